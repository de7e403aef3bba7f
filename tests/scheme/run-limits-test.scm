;; SPDX-License-Identifier: MIT
;;; What a script can do to a running game (issue 35): re-entering game-run!,
;;; runaway recursion in a hook, and sizes past the bounds. Each case asserts
;;; the exact error text.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke) (ice-9 popen) (ice-9 textual-ports) (ice-9 rdelim))

(load "support.scm")

(test-begin "run-limits")

;;; ---------------------------------------------------------------- re-entry
(define inner-error #f)
(define outer
  (make-game title: "outer"
             update: (lambda (game dt)
                       (unless inner-error
                         (set! inner-error (error-text (lambda () (game-run! game frames: 10))))))))
(game-run! outer frames: 3)
(test-equal "game-run! on the running game, from its update:, is refused naming game-run!"
  "In procedure game-run!: a game is already running (this one): game-run! cannot start a game from inside a running game's hooks or REPL; run games one after another\n"
  inner-error)
(test-equal "… and the outer game ran on" 3 (game-frame outer))

(define other-error #f)
(define host
  (make-game title: "host"
             update: (lambda (game dt)
                       (unless other-error
                         (set! other-error (error-text (lambda () (game-run! (make-game) frames: 1))))))))
(game-run! host frames: 1)
(test-equal "… and so is starting another game from inside one, naming the running one"
  "In procedure game-run!: a game is already running (host): game-run! cannot start a game from inside a running game's hooks or REPL; run games one after another\n"
  other-error)

(define first-game (make-game))
(define second-game (make-game))
(game-run! first-game frames: 5)
(game-run! second-game frames: 7)
(game-run! first-game frames: 8)
(test-equal "two games run one after the other, and the first again after"
  '(8 7) (list (game-frame first-game) (game-frame second-game)))

;;; ---------------------------------------------------------------- the stack
(define host (readlink "/proc/self/exe"))
(define runaway (string-append (getenv "DS_TEST_DATA") "/scripts/runaway.scm"))
(define (run-host . argv)
  ;; (exit status . everything printed, error port included).
  (let* ((cmd (string-append (string-join (map (lambda (a) (string-append "'" a "'")) (cons host argv)) " ")
                             " 2>&1"))
         (p (open-pipe* OPEN_READ "/bin/sh" "-c" cmd))
         (text (get-string-all p)))
    (cons (status:exit-val (close-pipe p)) text)))

;; In a child process (the host on runaway.scm): the recursion in update:
;; ends in a stack-overflow error naming the hook; the child reports how
;; long it took and its peak memory.
(define caught (string-split (cdr (run-host runaway "caught")) #\newline))
(test-equal "a runaway recursion in update: ends in stack-overflow" "stack-overflow" (car caught))
(test-equal "… naming the hook and the limit"
  "In procedure update:: the hook used up its 64 MiB of Scheme stack (make-game stack-limit:): a recursion that never ends?"
  (cadr caught))
(define took-ms (string->number (caddr caught)))
(test-assert (format #f "… within a few seconds (took ~a ms)" took-ms) (< took-ms 5000))
(define peak-and-start (map string->number (string-split (cadddr caught) #\space)))
(define grew-mb (quotient (- (car peak-and-start) (cadr peak-and-start)) 1024))
(test-assert (format #f "… with the process's peak memory less than 300 MB above the game's own (grew ~a MB)" grew-mb)
  (< grew-mb 300))

(define uncaught (run-host runaway))
(test-equal "unserved and uncaught, it ends the script with status 1" 1 (car uncaught))
(test-assert "… and a short message, not the million frames (at most 30 lines)"
  (<= (length (string-split (cdr uncaught) #\newline)) 30))
(test-assert "… that names the hook and says what happened"
  (mentions? (cdr uncaught) "update:" "used up its 64 MiB of Scheme stack" "more frames left out"))

(define small-limit-error
  (error-text (lambda ()
                (game-run! (make-game stack-limit: (* 2 1024 1024)
                                      update: (lambda (game dt) (let down ((n 0)) (+ 1 (down n)))))
                           frames: 1))))
(test-equal "stack-limit: sets the bound, in bytes"
  "In procedure update:: the hook used up its 2 MiB of Scheme stack (make-game stack-limit:): a recursion that never ends?\n"
  small-limit-error)
(define hook-error #f)
(define (deep-hook) (let down ((n 0)) (+ 1 (down n))))
(add-frame-hook! deep-hook)
(set! hook-error (error-text (lambda () (game-run! (make-game stack-limit: (* 2 1024 1024)) frames: 1))))
(remove-frame-hook! deep-hook)
(test-equal "a frame hook is bounded and named too"
  "In procedure frame hook: the hook used up its 2 MiB of Scheme stack (make-game stack-limit:): a recursion that never ends?\n"
  hook-error)
(test-equal "a recursion deep but finite within the limit runs"
  100000
  (let ((depth #f))
    (game-run! (make-game update: (lambda (game dt) (set! depth (let down ((n 100000)) (if (= n 0) 0 (+ 1 (down (- n 1))))))))
               frames: 1)
    depth))
(test-equal "make-game refuses a stack-limit below 1 MiB, naming it and the value"
  "In procedure make-game: stack-limit: expected an exact integer of bytes from 1048576 (1 MiB) to 4294967296 (4 GiB), got 1000\n"
  (error-text (lambda () (make-game stack-limit: 1000))))
(test-equal "… and one that is not an integer"
  "In procedure make-game: stack-limit: expected an exact integer of bytes from 1048576 (1 MiB) to 4294967296 (4 GiB), got +nan.0\n"
  (error-text (lambda () (make-game stack-limit: +nan.0))))

;;; ---------------------------------------------------------------- sizes from scripts
;; A render: that queues drawings without end is stopped at the frame's bound
;; (a build without the renderer queues none).
(when (renderer-available?)
  (let* ((queued 0)
         (draw-flood
          (error-text (lambda ()
                        (game-run! (make-game width: 64 height: 64
                                              render: (lambda (game)
                                                        (let loop ((i 0))
                                                          (when (< i 10000000)
                                                            (draw-rect 0 0 1 1 '(255 0 0))
                                                            (set! queued (+ i 1))
                                                            (loop (+ i 1))))))
                                   frames: 1)))))
    (test-equal "a render: queuing 10^7 drawings is stopped at 262144, naming the procedure"
      "In procedure draw-rect: more than 262144 drawings queued in one frame: a render: loop that never ends?\n"
      draw-flood)
    (test-equal "… after queuing exactly the bound" 262144 queued)))

;; history: 10^9 is allowed: the ring grows only as frames are recorded.
(define long-memory (make-game history: 1000000000))
(game-run! long-memory frames: 12)
(test-equal "history: 10^9 keeps only the frames run (12 scenes after 12 frames)"
  12 (length (game-history long-memory)))

;; 10^6 entities: allowed, and stepped natively in one frame.
(define million
  (make-scene entities: (map (lambda (i) (list #:x (* 2 i) #:y 0 #:width 1 #:height 1 #:vx 1)) (iota 1000000))))
(define stepped (step-scene million 16))
(test-equal "10^6 entities step (allowed): all of them, each moved"
  '(1000000 1 1999999)
  (let ((es (scene-entities stepped)))
    (list (length es) (entity-ref (car es) #:x) (entity-ref (last es) #:x))))

;; An entity plist of 10^5 keys: allowed; the steps read past the unknown keys.
(define wide (append (append-map (lambda (i) (list (symbol->keyword (string->symbol (format #f "k~a" i))) i))
                                 (iota 100000))
                     '(#:x 5 #:y 0 #:width 1 #:height 1 #:vx 2)))
(test-equal "an entity of 10^5 keys (allowed): entity-ref finds the last, a step moves it"
  '(99999 7)
  (list (entity-ref wide #:k99999) (entity-ref (car (scene-entities (step-scene (make-scene entities: (list wide)) 16))) #:x)))

;; The largest game: 2^26 pixels (256 MiB a frame); its capture works.
(test-equal "make-game refuses more than 2^26 pixels, naming both sizes"
  "In procedure make-game: width × height: expected at most 67108864 pixels (256 MiB a frame), got 16384 × 16384\n"
  (error-text (lambda () (make-game width: 16384 height: 16384))))
(when (renderer-available?)
  (let ((file (string-append (or (getenv "TMPDIR") "/tmp") "/ds-largest-" (number->string (getpid)) ".png"))
        (largest (make-game width: 16384 height: 4096)))
    (game-capture largest file)
    (test-equal "the largest game, 16384 × 4096, is captured whole" '(24 28 40 255) (game-pixel largest 16383 4095))
    (delete-file file)))

(test-end "run-limits")
