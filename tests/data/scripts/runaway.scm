;; SPDX-License-Identifier: MIT
;;; A game whose update: hook recurses without end, for
;;; tests/scheme/run-limits-test.scm. With the argument "caught" it catches
;;; the error and prints, one per line: the error's key, its text, the ms it
;;; took, and the process's peak memory (VmHWM, kB) against its memory when
;;; the game started (VmRSS, kB). Without it, the error ends the script.
(use-modules (ice-9 rdelim))

(define (status-kb key)
  (call-with-input-file "/proc/self/status"
    (lambda (port)
      (let loop ((line (read-line port)))
        (cond ((eof-object? line) #f)
              ((string-prefix? key line) (string->number (car (string-tokenize (substring line (string-length key))))))
              (else (loop (read-line port))))))))

(define (down n) (+ 1 (down (+ n 1))))
(define game (make-game update: (lambda (game dt) (down 0))))
(define caught? (member "caught" (command-line)))

(if caught?
    (let ((rss (status-kb "VmRSS:")) (t0 (get-internal-real-time)))
      (catch #t
        (lambda () (game-run! game frames: 1))
        (lambda (key . args)
          (format #t "~a~%" key)
          (print-exception (current-output-port) #f key args)
          (format #t "~a~%" (quotient (- (get-internal-real-time) t0) 1000000))
          (format #t "~a ~a~%" (status-kb "VmHWM:") rss))))
    (game-run! game frames: 1))
