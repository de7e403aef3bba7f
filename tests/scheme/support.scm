;;; Helpers shared by the SRFI-64 suites; each suite (load "support.scm").
(use-modules (srfi srfi-1))

;;; The printed error (procedure, message, irritants) raised by THUNK, or #f.
(define (error-text thunk)
  (catch #t
    (lambda () (thunk) #f)
    (lambda (key . args)
      (call-with-output-string
       (lambda (port) (print-exception port #f key args))))))

;;; Whether TEXT contains every one of PARTS.
(define (mentions? text . parts)
  (and (string? text) (every (lambda (p) (string-contains text p)) parts) #t))
