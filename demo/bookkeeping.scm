;;; What every demo keeps of itself, for its trace, its tests and a REPL
;;; looking back: included by each demo after it defines `demo-script' (its
;;; file name). Both records are bounded (see (downstroke history)), so a
;;; demo left running (a soak test, a REPL session) stays in constant memory:
;;; a ring of the last 1000 frames, and between 500 and 1000 of the newest
;;; events.
(define trace? (main-script? demo-script))
(define events (make-bounded-log))      ; of (frame . what), newest first; 500 kept
(define history (make-frame-ring 1000)) ; what each frame ended with

(define (note-at! frame what)
  "Record WHAT as happening in FRAME (and print it when tracing)."
  (set! events (bounded-log-push events (cons frame what) 500))
  (when trace? (format #t "frame ~3d: ~a~%" frame what)))

(define (remember! frame value) (frame-ring-set! history frame value))

(define (entities-at frame)
  "What FRAME ended with (its entities, or the player), or #f when FRAME is
not one of the last 1000."
  (frame-ring-ref history frame))

(define (entity-at frame id)
  "The entity with #:id ID as FRAME ended, or #f."
  (let ((entities (entities-at frame)))
    (and entities (find (lambda (e) (eq? (entity-ref e #:id) id)) entities))))

(define (event-frames what)
  "The frames WHAT happened in, oldest first."
  (filter-map (lambda (e) (and (eq? (cdr e) what) (car e))) (reverse (bounded-log-items events))))
