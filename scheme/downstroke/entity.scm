;;; (downstroke entity) — entities are keyword plists.
(define-module (downstroke entity)
  #:use-module (srfi srfi-1)
  #:export (entity-ref
            entity-set
            entity-skips-pipeline?
            define-pipeline))

(define (malformed who entity)
  (scm-error 'wrong-type-arg (symbol->string who)
             "malformed entity (expected a keyword plist): ~S" (list entity) #f))

(define (check-key who key)
  (unless (keyword? key)
    (scm-error 'wrong-type-arg (symbol->string who)
               "expected a keyword, got ~S" (list key) #f)))

(define* (entity-ref entity key #:optional (default #f))
  "The value of KEY in ENTITY, or DEFAULT (#f unless given) when absent."
  (check-key 'entity-ref key)
  (let loop ((p entity))
    (cond ((null? p) default)
          ((and (pair? p) (keyword? (car p)) (pair? (cdr p)))
           (if (eq? (car p) key) (cadr p) (loop (cddr p))))
          (else (malformed 'entity-ref entity)))))

(define (entity-set entity key value)
  "A new entity with KEY set to VALUE: replaced where KEY stands, appended
at the end when absent. ENTITY itself is not changed; the part after KEY is
shared."
  (check-key 'entity-set key)
  (let loop ((p entity) (acc '()))
    (cond ((null? p) (append-reverse! acc (list key value)))
          ((and (pair? p) (keyword? (car p)) (pair? (cdr p)))
           (if (eq? (car p) key)
               (append-reverse! acc (cons key (cons value (cddr p))))
               (loop (cddr p) (cons* (cadr p) (car p) acc))))
          (else (malformed 'entity-set entity)))))

(define (entity-skips-pipeline? entity step)
  "Whether STEP (a symbol) is listed in ENTITY's #:skip-pipelines."
  (let ((skips (entity-ref entity #:skip-pipelines '())))
    (unless (and (list? skips) (every symbol? skips))
      (scm-error 'wrong-type-arg "entity-skips-pipeline?"
                 "entity key #:skip-pipelines: expected a list of symbols, got ~S"
                 (list skips) #f))
    (and (memq step skips) #t)))

(eval-when (expand load eval)
  ;; `guard:' reads as the keyword #:guard with postfix keywords, and as a
  ;; plain symbol when keywords are not read at all.
  (define (guard-marker? datum)
    (or (eq? datum #:guard) (eq? datum 'guard:))))

(define-syntax define-pipeline
  (lambda (stx)
    "(define-pipeline (name skip-symbol) (entity scene dt) [guard: expr] body ...)
defines a step that returns ENTITY unchanged when it skips SKIP-SYMBOL or
the guard is false."
    (syntax-case stx ()
      ((_ (name skip) (entity scene dt) marker guard body0 body ...)
       (guard-marker? (syntax->datum #'marker))
       #'(define (name entity scene dt)
           (if (or (entity-skips-pipeline? entity 'skip) (not guard))
               entity
               (let () body0 body ...))))
      ((_ (name skip) (entity scene dt) body0 body ...)
       #'(define (name entity scene dt)
           (if (entity-skips-pipeline? entity 'skip)
               entity
               (let () body0 body ...)))))))
