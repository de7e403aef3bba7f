;; SPDX-License-Identifier: MIT
;;; (downstroke contacts) — contact events from the frames' reports
;;; (semantics §10): which pairs began or ended touching between two frames.
(define-module (downstroke contacts)
  #:use-module (srfi srfi-1)
  #:use-module (downstroke world)
  #:export (contacts-begun contacts-ended))

(define (pairs-of who x)
  ;; A scene's pairs (scene-contacts), or a list of pairs as it holds them.
  (cond ((scene? x) (scene-contacts x))
        ((and (list? x) (every pair? x)) x)
        (else (scm-error 'wrong-type-arg who
                         "expected a scene or a list of (name-a . name-b) pairs, got ~S"
                         (list x) #f))))

(define (same-pair? p q)
  ;; Either way round: (a . b) and (b . a) are one contact.
  (or (and (equal? (car p) (car q)) (equal? (cdr p) (cdr q)))
      (and (equal? (car p) (cdr q)) (equal? (cdr p) (car q)))))

(define (missing-from pairs others)
  (remove (lambda (p) (any (lambda (q) (same-pair? p q)) others)) pairs))

(define (contacts-begun before after)
  "The pairs of AFTER that BEFORE does not hold, in AFTER's order. Each
argument is a scene (its scene-contacts) or a list of (name-a . name-b)
pairs; a pair matches another either way round."
  (missing-from (pairs-of "contacts-begun" after) (pairs-of "contacts-begun" before)))

(define (contacts-ended before after)
  "The pairs of BEFORE that AFTER no longer holds, in BEFORE's order
(scenes or pair lists, as for contacts-begun)."
  (missing-from (pairs-of "contacts-ended" before) (pairs-of "contacts-ended" after)))
