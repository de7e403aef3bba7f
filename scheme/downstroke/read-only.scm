;; SPDX-License-Identifier: MIT
;;; (downstroke read-only) — exported constants that refuse set!.
;;;
;;; A constant exported as a plain variable can be assigned by a game:
;;; (set! *gravity* 2) changes that variable, and nothing else, for the
;;; engine reads its own number (src/constants.hpp). Each constant is
;;; instead an identifier macro that reads as its value and makes set! a
;;; syntax error saying why and what to do instead, raised where the form is
;;; expanded: compiling a script, interpreting it, or at the REPL.
(define-module (downstroke read-only)
  #:export (define-read-only))

(define-syntax define-read-only
  (syntax-rules ()
    "(define-read-only name value why): NAME reads as VALUE (an expression,
evaluated at each use); (set! NAME …) is a syntax error whose message is
WHY, a string evaluated once, where NAME is defined."
    ((_ name value why)
     (define-syntax name
       (let ((message why))
         (make-variable-transformer
          (lambda (form)
            (syntax-case form (set!)
              ((set! id e) (syntax-violation 'set! message form))
              ((head . arguments) #'(value . arguments))
              (id (identifier? #'id) #'value)))))))))
