;; SPDX-License-Identifier: MIT
;;; Runs one SRFI-64 test file under the downstroke host and exits non-zero
;;; when anything failed: Guile 3.0.8's SRFI-64 alone exits 0 regardless.
;;; Usage: downstroke tests/scheme/run-suite.scm FILE.scm
(use-modules (srfi srfi-64) (ice-9 format))

(define passed 0)
(define failed 0)

(define (counting-runner)
  (let ((runner (test-runner-simple)))
    (test-runner-on-test-end! runner
      (lambda (r)
        (case (test-result-kind r)
          ((pass xfail) (set! passed (+ passed 1)))
          ((fail xpass)
           (set! failed (+ failed 1))
           (format (current-error-port) "FAIL ~a: ~a~%  expected: ~s~%  actual:   ~s~%  ~a:~a~%"
                   (test-runner-group-path r) (test-runner-test-name r)
                   (test-result-ref r 'expected-value) (test-result-ref r 'actual-value)
                   (test-result-ref r 'source-file) (test-result-ref r 'source-line)))
          (else #t))))
    ;; The simple runner writes a .log file per suite into the working
    ;; directory; we report ourselves instead.
    (test-runner-on-group-begin! runner (lambda (r name count) #t))
    (test-runner-on-group-end! runner (lambda (r) #t))
    (test-runner-on-final! runner (lambda (r) #t))
    runner))

(test-runner-factory counting-runner)

(define file (cadr (program-arguments)))
(catch #t
  (lambda () (load (canonicalize-path file)))
  (lambda (key . args)
    (set! failed (+ failed 1))
    (format (current-error-port) "ERROR while running ~a: ~s ~s~%" file key args)))
(format #t "~a: ~a passed, ~a failed~%" (basename file) passed failed)
(format #t "~a passed, ~a failed~%" passed failed)
(exit (if (and (zero? failed) (positive? passed)) 0 1))
