;; SPDX-License-Identifier: MIT
;;; (downstroke arity) — refusing a hook that cannot take its arguments.
;;;
;;; A hook of the wrong shape, update: (lambda (game) …), would otherwise
;;; fail only when the first frame calls it, with Guile's "Wrong number of
;;; arguments" naming an anonymous procedure. Checked where it is given, the
;;; error names the hook, what it must take, and where the procedure was
;;; written.
(define-module (downstroke arity)
  #:use-module (srfi srfi-1)
  ;; Loaded only for a hook that may not fit: (system vm program) brings
  ;; the VM's debugging modules, which a game that runs need not carry
  ;; (docs/engine.org, "Memory against time").
  #:autoload (system vm program) (program? program-arguments-alists program-source)
  #:export (check-hook))

;; One clause's (required …) (optional …) (rest . name-or-#f) alist.
(define (clause-takes? clause n)
  (let ((required (length (or (assq-ref clause 'required) '())))
        (optional (length (or (assq-ref clause 'optional) '()))))
    (and (<= required n) (or (assq-ref clause 'rest) (<= n (+ required optional))))))

(define (takes? proc n)
  ;; Only a certain mismatch is refused. The minimum arity is exact for a
  ;; procedure of one clause; of a case-lambda it is the fewest arguments
  ;; any clause requires, so a count beyond it asks the clauses: a compiled
  ;; procedure lists each, an interpreted one with optional or rest
  ;; arguments only a rest argument (taking it, unchecked).
  (let ((arity (procedure-minimum-arity proc)))
    (cond ((not arity) #t)
          ((< n (car arity)) #f)
          ((or (caddr arity) (<= n (+ (car arity) (cadr arity)))) #t)
          ((program? proc)
           (let ((clauses (program-arguments-alists proc)))
             (or (not clauses) (any (lambda (clause) (clause-takes? clause n)) clauses))))
          (else #f))))

;; The evaluator's own file: an interpreted procedure's source is the
;; evaluator's closure there, not where its author wrote it.
(define evaluator-file
  (delay (let ((source (program-source (primitive-eval '(lambda () #f)) 0)))
           (and source (cadr source)))))

(define (authored-source proc)
  ;; (file line . column), line counted from 0, or #f when unknown.
  (let ((source (and (program? proc) (program-source proc 0))))
    (and source (cadr source) (not (equal? (cadr source) (force evaluator-file)))
         (cdr source))))

(define (count-text n)
  (if (= n 1) "1 argument" (format #f "~a arguments" n)))

;; A clause's arguments as its author wrote them: "(game [dt] . rest)".
(define (clause-text clause)
  (let ((words (append (map symbol->string (assq-ref clause 'required))
                       (map (lambda (o) (format #f "[~a]" o)) (assq-ref clause 'optional))
                       (if (assq-ref clause 'rest)
                           (list "." (symbol->string (assq-ref clause 'rest)))
                           '()))))
    (if (null? words) "no arguments" (string-append "(" (string-join words " ") ")"))))

(define (takes-text proc source)
  ;; Its own argument names when they are the author's (compiled), else how
  ;; many it takes.
  (let ((clauses (and source (program-arguments-alists proc)))
        (arity (procedure-minimum-arity proc)))
    (cond ((and clauses (pair? clauses)) (string-join (map clause-text clauses) " or "))
          ((not arity) "arguments of its own")
          ((caddr arity) (format #f "at least ~a" (count-text (car arity))))
          ((zero? (cadr arity))
           (if (zero? (car arity)) "no arguments" (count-text (car arity))))
          (else (format #f "~a to ~a" (car arity) (count-text (+ (car arity) (cadr arity))))))))

(define (check-hook who what proc arguments)
  "Refuse PROC, given to WHO as WHAT (\"update\"), unless it can be called
with ARGUMENTS, a list of names such as (game dt): a wrong-type-arg error
naming WHAT, ARGUMENTS, what PROC takes and, when known, where it was
written (file:line:column)."
  (unless (takes? proc (length arguments))
    (let* ((source (authored-source proc))
           (name (procedure-name proc)))
      (scm-error 'wrong-type-arg who "~A: expected a procedure of ~A, got ~A~A"
                 (list what
                       (if (null? arguments) "no arguments" (format #f "~a" arguments))
                       (if name
                           (format #f "~a, a procedure of ~a" name (takes-text proc source))
                           (format #f "a procedure of ~a" (takes-text proc source)))
                       (if source
                           (format #f ", at ~a:~a:~a" (car source) (+ 1 (cadr source)) (cddr source))
                           ""))
                 #f))))
