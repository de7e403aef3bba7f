;; SPDX-License-Identifier: MIT
;;; (bench driver) — the Scheme side of downstroke-bench: builds a scene from
;;; the entity plists the C++ side made, and runs the timed frame loop.
;;;
;;; The loop is Scheme: each frame is (STEP scene dt) bracketed by
;;; (get-internal-real-time) (nanoseconds in Guile 3.0) and by the GC's
;;; 'heap-total-allocated counter; the bounce update of the platformer and
;;; bullets scenes runs after the bracket, untimed and uncounted.
;;; (gc-stats) itself allocates a little: bracket-overhead measures how much
;;; an empty bracket counts, and the C++ side subtracts it. With SPLIT?, each
;;; timed frame's (%frame-stats) is read after the bracket and summed: where
;;; the frame went (decode, the steps, encode, collection).
(define-module (bench driver)
  #:use-module (srfi srfi-1)
  #:use-module (downstroke world)
  #:use-module (downstroke tilemap)
  #:use-module ((downstroke native) #:select (%frame-stats %gc-clock))
  #:export (make-bench-scene bench-scene-entities grid-tilemap run-frames))

(define (make-bench-scene entities tilemap)
  (make-scene #:entities entities #:tilemap tilemap))

(define (bench-scene-entities scene) (scene-entities scene))

(define* (grid-tilemap cols rows tile-w tile-h cells #:optional (shapes '()))
  "A tilemap of COLS × ROWS cells from a vector of gids (1 = solid), SHAPES
giving gids their collision polygons, as make-tilemap takes them."
  (make-tilemap cols rows tile-w tile-h cells '(1) '() shapes))

(define (allocated) (assq-ref (gc-stats) 'heap-total-allocated))
;; Wall-clock time spent collecting, in ns. Not (gc-stats)'s gc-time-taken:
;; that is process CPU time, which adds up both marking threads on a 2-core
;; machine (about 1.8× the pause there; docs/benchmarks.org).
(define (gc-time) (cdr (%gc-clock)))

;;; The bounce update: an entity with #:rvx / #:rvy (the velocity it wants)
;;; whose #:vx (#:vy) a collision set to 0 turns round on that axis.
(define (plist-ref e key)
  (let loop ((p e))
    (cond ((null? p) #f)
          ((eq? (car p) key) (cadr p))
          (else (loop (cddr p))))))

(define (plist-set e key value)
  (let loop ((p e) (acc '()))
    (cond ((null? p) (reverse! (cons* value key acc)))
          ((eq? (car p) key) (append-reverse! acc (cons* key value (cddr p))))
          (else (loop (cddr p) (cons* (cadr p) (car p) acc))))))

(define (turn e vkey rkey)
  (let ((want (plist-ref e rkey)))
    (if (and want (not (eqv? want 0)) (eqv? (plist-ref e vkey) 0))
        (plist-set (plist-set e rkey (- want)) vkey (- want))
        e)))

(define (bounce e) (turn (turn e #:vx #:rvx) #:vy #:rvy))

(define (map-keeping proc lst)
  (let loop ((p lst) (acc '()) (changed? #f))
    (if (null? p)
        (if changed? (reverse! acc) lst)
        (let ((v (proc (car p))))
          (loop (cdr p) (cons v acc) (or changed? (not (eq? v (car p)))))))))

(define (bounce-scene scene)
  (let* ((es (scene-entities scene))
         (turned (map-keeping bounce es)))
    (if (eq? turned es) scene (update-scene scene #:entities turned))))

(define (bracket-overhead)
  "Bytes the allocation bracket itself counts (two gc-stats calls), averaged."
  (let loop ((i 0) (bytes 0))
    (if (< i 1000)
        (let* ((a0 (allocated))
               (t0 (get-internal-real-time))
               (t1 (get-internal-real-time))
               (a1 (allocated)))
          (loop (+ i 1) (+ bytes (- a1 a0) (* 0 (- t1 t0)))))
        (/ bytes 1000.))))

;; The frame's split as a vector: #(decode-ms steps-ms encode-ms collect-ms
;; collections bytes rewritten), from the rows of (%frame-stats).
(define (frame-split)
  (let ((rows (%frame-stats)))
    (define (row name) (assq name rows))
    (define (ms r) (list-ref r 3))
    (vector (ms (row 'decode))
            (fold (lambda (r sum)
                    (if (memq (car r) '(decode encode collect)) sum (+ sum (ms r))))
                  0 rows)
            (ms (row 'encode))
            (ms (row 'collect))
            (cadr (row 'collect))
            (caddr (row 'collect))
            (cadr (row 'encode)))))

(define (vector-add! sums v)
  (do ((i 0 (+ i 1))) ((= i (vector-length v)))
    (vector-set! sums i (+ (vector-ref sums i) (vector-ref v i)))))

(define* (run-frames step scene dt warmup frames bounce? max-frame-ns budget-ns #:optional split?)
  "Step SCENE WARMUP frames, then up to FRAMES timed frames. Stops at once
after a frame slower than MAX-FRAME-NS, and once all frames so far add up to
BUDGET-NS with at least 3 timed. Returns (times bytes overhead scene
too-slow-ns spent-ns gc-ns split): TIMES a vector of each timed frame's
nanoseconds, BYTES the bytes allocated inside the timed brackets, OVERHEAD
what one bracket counts by itself, TOO-SLOW-NS the offending frame's time or
#f, GC-NS the collection time inside the timed frames, SPLIT (with SPLIT?,
else #f) the timed frames' (frame-split) summed."
  (define (after s) (if bounce? (bounce-scene s) s))
  (let ((times (make-vector frames 0))
        (overhead (bracket-overhead))
        (split (and split? (make-vector 7 0))))
    (gc)
    (let loop ((i 0) (scene scene) (bytes 0) (spent 0) (gc-ns 0))
      (let ((timed (max 0 (- i warmup))))
        (if (>= i (+ warmup frames))
            (list times bytes overhead scene #f spent gc-ns split)
            (let* ((g0 (gc-time))
                   (a0 (allocated))
                   (t0 (get-internal-real-time))
                   (next (step scene dt))
                   (t1 (get-internal-real-time))
                   (a1 (allocated))
                   (g1 (gc-time))
                   (ns (- t1 t0))
                   (timed? (>= i warmup))
                   (timed (if timed? (+ timed 1) timed))
                   (bytes (if timed? (+ bytes (- a1 a0)) bytes))
                   (gc-ns (if timed? (+ gc-ns (- g1 g0)) gc-ns))
                   (spent (+ spent ns)))
              (when timed?
                (vector-set! times (- i warmup) ns)
                (when split (vector-add! split (frame-split))))
              (cond ((> ns max-frame-ns)
                     (list (vector-head times timed) bytes overhead next ns spent gc-ns split))
                    ((and (> spent budget-ns) (>= timed 3))
                     (list (vector-head times timed) bytes overhead next #f spent gc-ns split))
                    (else (loop (+ i 1) (after next) bytes spent gc-ns)))))))))

(define (vector-head v k)
  (let ((out (make-vector k)))
    (vector-move-left! v 0 k out 0)
    out))
