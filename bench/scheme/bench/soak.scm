;; SPDX-License-Identifier: MIT
;;; (bench soak) — runs a demo (demo/*.scm) headless for many frames and
;;; samples the memory it holds: `downstroke-bench soak' (10^6 frames) and
;;; tests/scheme/stress-test.scm (10^4 frames) share it, so both measure the
;;; same thing.
;;;
;;; A demo runs in a fresh module, as tests/scheme/demos-test.scm loads it,
;;; with its built-in input script replayed from the start every
;;; `demo-frames' frames: a long run keeps jumping, firing and walking
;;; instead of idling once the script's last key frame is reached.
(define-module (bench soak)
  #:use-module (system base compile)
  #:use-module (system vm loader)
  #:use-module (downstroke)
  #:export (demo-names load-demo memory-sample soak-demo))

(define demo-names '("platformer" "topdown" "sandbox" "shmup" "tweens"))

(define (temporary-go-file)
  (let ((port (mkstemp! (string-copy (string-append (or (getenv "TMPDIR") "/tmp")
                                                    "/downstroke-soak-XXXXXX")))))
    (let ((name (port-filename port)))
      (close-port port)
      name)))

(define (load-demo file)
  "A fresh module using (downstroke), with FILE compiled and run in it. The
demo is compiled here, whatever the process's auto-compilation setting: the
bench runs with it off, and an interpreted demo would measure the
interpreter. Demos are read with postfix keywords (`title: \"x\"')."
  (read-set! keywords 'postfix)
  (let ((m (make-fresh-user-module))
        (go (temporary-go-file)))
    (module-use! m (resolve-interface '(downstroke)))
    (dynamic-wind
      (lambda () #t)
      (lambda ()
        (compile-file file #:output-file go #:env m)
        (let ((thunk (load-thunk-from-file go)))
          (save-module-excursion
           (lambda ()
             (set-current-module m)
             (thunk)))))
      (lambda () (when (file-exists? go) (delete-file go))))
    m))

(define (resident-bytes page-size)
  ;; /proc/self/statm: size resident shared … in pages.
  (call-with-input-file "/proc/self/statm"
    (lambda (port) (read port) (* page-size (read port)))))

(define* (memory-sample #:key (page-size 4096))
  "(heap-bytes . resident-bytes) after a full collection: Guile's heap size
from (gc-stats) and the process's resident set size from /proc/self/statm.
Two collections: the first may leave objects a finalizer still needed."
  (gc)
  (gc)
  (cons (assq-ref (gc-stats) 'heap-size) (resident-bytes page-size)))

;; Not sampled: heap-size − heap-free-size, which looks like "bytes in use"
;; but counts every block holding one live object as used, so a long-lived
;; list consed a pair at a time (the sound log) inflates it by MiBs while
;; the heap, whose free slots are reused, does not grow at all.

(define set-script! (@@ (downstroke engine) game-input-script-set!))

(define (shifted script offset)
  (map (lambda (key) (cons (+ (car key) offset) (cdr key))) script))

(define (run-looping! m to)
  "Run demo module M up to frame TO, replaying its input script (if it has
one) every `demo-frames' frames."
  (let* ((game (module-ref m 'game))
         (run! (module-ref m 'run!))
         (period (module-ref m 'demo-frames))
         (script (and (module-defined? m 'input-script) (module-ref m 'input-script))))
    (if (not (pair? script))
        (run! to)
        (let loop ()
          (let ((frame (game-frame game)))
            (when (< frame to)
              (when (zero? (modulo frame period))
                (set-script! game (shifted script frame)))
              (run! (min to (* period (+ 1 (quotient frame period)))))
              (loop)))))))

(define* (soak-demo file frames #:key (warmup 2000) (page-size 4096))
  "Load the demo FILE, run it WARMUP frames, sample the memory, run it on to
FRAMES frames in all, sampling halfway and at the end. An alist: frames,
warmup, seconds (the frames' time, warm-up included), heap-start heap-mid
heap-end rss-start rss-mid rss-end (bytes), events and sounds (how many the
demo's event list and the game's sound log hold at the end)."
  (let* ((m (load-demo file))
         (game (module-ref m 'game))
         (warmup (min warmup frames))
         (halfway (max warmup (quotient frames 2)))
         (running 0))
    ;; The sample in the middle tells a collector that grew its heap once
    ;; (a step of about a third of it) from a leak, which keeps growing.
    (define (run-to! frame)
      (let ((t0 (get-internal-real-time)))
        (run-looping! m frame)
        (set! running (+ running (- (get-internal-real-time) t0)))
        (memory-sample #:page-size page-size)))
    (let* ((start (run-to! warmup))
           (mid (run-to! halfway))
           (end (run-to! frames)))
      `((frames . ,(game-frame game))
        (warmup . ,warmup)
        (seconds . ,(exact->inexact (/ running internal-time-units-per-second)))
        (heap-start . ,(car start)) (heap-mid . ,(car mid)) (heap-end . ,(car end))
        (rss-start . ,(cdr start)) (rss-mid . ,(cdr mid)) (rss-end . ,(cdr end))
        (events . ,(length ((module-ref (resolve-interface '(demo events)) 'events-items) (module-ref m 'events))))
        (sounds . ,(length (game-sounds game)))))))
