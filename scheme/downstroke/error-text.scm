;; SPDX-License-Identifier: MIT
;;; (downstroke error-text) — an error as the author reads it, wherever the
;;; engine prints one: a script's uncaught error, a failed check, a hook's
;;; error, the REPL's reply, a scene file's refusal.
;;;
;;; Scripts get R7RS/SRFI-34 `raise' (docs/engine.org), which may raise any
;;; value, not only an error condition. Uncaught, such a value reaches Guile
;;; as the key %exception with the value as its only argument, and Guile
;;; prints it as "Throw to key `%exception' with args `(42)'": here it
;;; reads as what the script did.
(define-module (downstroke error-text)
  #:use-module ((ice-9 exceptions) #:select (exception?))
  #:export (print-error error-text))

(define (raised-non-condition? key args)
  (and (eq? key '%exception) (pair? args) (null? (cdr args)) (not (exception? (car args)))))

(define (print-error port key args)
  "Write the error thrown as KEY with ARGS to PORT, as print-exception
does, but a raised value that is not an error condition as
\"uncaught raise of a non-condition: VALUE\"."
  (if (raised-non-condition? key args)
      (format port "uncaught raise of a non-condition: ~s~%" (car args))
      (print-exception port #f key args)))

(define (error-text key args)
  "The text print-error writes, as a string."
  (call-with-output-string (lambda (port) (print-error port key args))))
