;; SPDX-License-Identifier: MIT
;;; (downstroke history) — bounded records of a running game, for looking
;;; back from a REPL or a test: a ring holding a value for each of the last
;;; N frames, and a log that keeps its newest items. Both stay in constant
;;; memory however long the game runs.
(define-module (downstroke history)
  #:use-module (srfi srfi-9)
  #:export (make-frame-ring frame-ring? frame-ring-set! frame-ring-ref
            make-bounded-log bounded-log-push bounded-log-items bounded-log-newest
            list->bounded-log))

(define (check-size who what n)
  (unless (and (exact-integer? n) (positive? n))
    (scm-error 'wrong-type-arg who "~a: expected a positive exact integer, got ~S"
               (list what n) (list n))))

(define (check-frame who frame)
  (unless (exact-integer? frame)
    (scm-error 'wrong-type-arg who "frame: expected an exact integer, got ~S"
               (list frame) (list frame))))

;;; ------------------------------------------------------------ frame ring
(define-record-type <frame-ring>
  (%make-frame-ring slots)
  frame-ring?
  (slots frame-ring-slots))                ; frame mod size → (frame . value)

(define (make-frame-ring size)
  "A ring that keeps one value for each of the last SIZE frames."
  (check-size 'make-frame-ring "size" size)
  (%make-frame-ring (make-vector size #f)))

(define (ring-slot ring frame)
  (modulo frame (vector-length (frame-ring-slots ring))))

(define (frame-ring-set! ring frame value)
  "Keeps VALUE as FRAME's, in place of what the frame SIZE before it kept."
  (check-frame 'frame-ring-set! frame)
  (vector-set! (frame-ring-slots ring) (ring-slot ring frame) (cons frame value)))

(define (frame-ring-ref ring frame)
  "FRAME's value, or #f when the ring holds nothing for FRAME (never kept,
or overwritten by a later frame)."
  (check-frame 'frame-ring-ref frame)
  (let ((slot (vector-ref (frame-ring-slots ring) (ring-slot ring frame))))
    (and slot (eqv? (car slot) frame) (cdr slot))))

;;; ------------------------------------------------------------ bounded log
;;; A newest-first list kept with its length, (count . items), cut back to its
;;; newest KEEP items once it holds twice that: one copy per KEEP additions,
;;; so adding stays O(1) on average and memory stays bounded. A log is a
;;; value; adding returns a new one. The engine keeps its scene history and
;;; its sound log this way.

(define (make-bounded-log)
  "An empty bounded log."
  '(0))

(define (bounded-log-push log item keep)
  "LOG with ITEM as its newest item; once that makes twice KEEP items, only
the newest KEEP are kept."
  (check-size 'bounded-log-push "keep" keep)
  (let ((count (+ (car log) 1)) (items (cons item (cdr log))))
    (if (> count (* 2 keep)) (cons keep (list-head items keep)) (cons count items))))

(define (bounded-log-items log)
  "Every item LOG holds (between KEEP and twice KEEP once it is full), newest
first."
  (cdr log))

(define (bounded-log-newest log n)
  "The newest N items (all of them when there are fewer), newest first."
  (if (> (car log) n) (list-head (cdr log) n) (cdr log)))

(define (list->bounded-log items)
  "A bounded log holding ITEMS, a proper list, newest first."
  (unless (list? items)
    (scm-error 'wrong-type-arg 'list->bounded-log "items: expected a proper list, got ~S"
               (list items) (list items)))
  (cons (length items) items))
