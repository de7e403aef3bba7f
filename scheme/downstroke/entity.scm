;; SPDX-License-Identifier: MIT
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

(define (circular who entity)
  (scm-error 'wrong-type-arg (symbol->string who)
             "malformed entity (expected a keyword plist): circular list ~S" (list entity) #f))

;;; The walks below visit the plist key by key (P = x0, x1, … with
;;; x(i+1) = (cddr xi)) while SLOW trails at half speed (Floyd's tortoise and
;;; hare): SLOW is x(i/2) for even i. Only a circular plist brings the two
;;; together, within a few laps of its cycle, so a walk for a missing key ends.
(define-inlinable (lapped? odd? p slow)
  (and odd? (eq? (cddr p) (cddr slow))))
(define-inlinable (trail odd? slow)
  (if odd? (cddr slow) slow))

(define (check-key who key)
  (unless (keyword? key)
    (scm-error 'wrong-type-arg (symbol->string who)
               "expected a keyword, got ~S" (list key) #f)))

(define* (entity-ref entity key #:optional (default #f))
  "The value of KEY in ENTITY, or DEFAULT (#f unless given) when absent."
  (check-key 'entity-ref key)
  (let loop ((p entity) (slow entity) (odd? #f))
    (cond ((null? p) default)
          ((and (pair? p) (keyword? (car p)) (pair? (cdr p)))
           (cond ((eq? (car p) key) (cadr p))
                 ((lapped? odd? p slow) (circular 'entity-ref entity))
                 (else (loop (cddr p) (trail odd? slow) (not odd?)))))
          (else (malformed 'entity-ref entity)))))

(define (entity-set entity key value)
  "A new entity with KEY set to VALUE: replaced where KEY stands, appended
at the end when absent. ENTITY itself is not changed; the part after KEY is
shared."
  (check-key 'entity-set key)
  (let loop ((p entity) (acc '()) (slow entity) (odd? #f))
    (cond ((null? p) (append-reverse! acc (list key value)))
          ((and (pair? p) (keyword? (car p)) (pair? (cdr p)))
           (cond ((eq? (car p) key) (append-reverse! acc (cons key (cons value (cddr p)))))
                 ((lapped? odd? p slow) (circular 'entity-set entity))
                 (else (loop (cddr p) (cons* (cadr p) (car p) acc) (trail odd? slow) (not odd?)))))
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
    (define (names? . ids) (and-map identifier? ids))
    (syntax-case stx ()
      ((_ (name skip) (entity scene dt) marker guard body0 body ...)
       (and (guard-marker? (syntax->datum #'marker)) (names? #'name #'skip #'entity #'scene #'dt))
       #'(define (name entity scene dt)
           (if (or (entity-skips-pipeline? entity 'skip) (not guard))
               entity
               (let () body0 body ...))))
      ((_ (name skip) (entity scene dt) body0 body ...)
       (names? #'name #'skip #'entity #'scene #'dt)
       #'(define (name entity scene dt)
           (if (entity-skips-pipeline? entity 'skip)
               entity
               (let () body0 body ...))))
      (_ (syntax-violation 'define-pipeline
                           "expected (define-pipeline (name skip-symbol) (entity scene dt) [guard: expr] body ...), each name a symbol"
                           stx)))))
