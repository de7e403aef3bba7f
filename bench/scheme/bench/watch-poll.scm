;; SPDX-License-Identifier: MIT
;;; What poll-watched-files! costs a frame when nothing changes
;;; (docs/repl.org, "What watching costs"): one game watching 10 files.
;;;   downstroke bench/scheme/bench/watch-poll.scm N MODE
;;; MODE between: N polls, none of which looks (the next look is far off);
;;;      look:    N polls, each looking at the 10 files (a stat each);
;;;      none:    N turns of an empty loop, for the loop's own cost.
;;; Prints the ns a call; under valgrind --tool=cachegrind, the instructions
;;; of N calls less those of 0 give a call's.
(use-modules (downstroke) (downstroke live))

(define n (string->number (cadr (command-line))))
(define mode (string->symbol (caddr (command-line))))
(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-watch-poll-XXXXXX")))
(define files (map (lambda (i) (format #f "~a/f~a.txt" dir i)) (iota 10)))
(for-each (lambda (f) (call-with-output-file f (lambda (p) (display "x" p)))) files)

(define game (make-game))
(for-each (lambda (f) (watch-file! game f (lambda (path) #t))) files)
(watch-poll-interval (if (eq? mode 'look) 0 1000000))
(poll-watched-files! game)   ; the first look, which sets the next

(define (polls k) (when (> k 0) (poll-watched-files! game) (polls (- k 1))))
(define (turns k) (when (> k 0) (turns (- k 1))))
(define t0 (get-internal-real-time))
(if (eq? mode 'none) (turns n) (polls n))
(define t1 (get-internal-real-time))
(format #t "~a ~a: ~,1f ns a call~%" mode n
        (/ (* 1e9 (/ (- t1 t0) internal-time-units-per-second)) (max n 1)))
(for-each delete-file files)
(rmdir dir)
