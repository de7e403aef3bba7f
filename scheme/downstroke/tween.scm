;; SPDX-License-Identifier: MIT
;;; (downstroke tween) — properties driven from start to end over time.
(define-module (downstroke tween)
  #:use-module (srfi srfi-1)
  #:use-module (srfi srfi-9)
  #:use-module (downstroke native)
  #:use-module (downstroke entity)
  #:use-module (downstroke read-only)
  #:export (make-tween tween? tween-props tween-duration tween-delay tween-ease
            tween-repeat tween-yoyo? tween-on-complete tween-elapsed
            tween-with-elapsed ease easing-names))

;; Field order matters: the native stepper reads the record by position
;; (TweenField in bindings/tween_procs.cpp), and %register-tween-type! refuses
;; a record whose field names and order are not the ones it reads.
(define-record-type <tween>
  (%make-tween props duration delay ease ease-index repeat yoyo? on-complete elapsed)
  tween?
  (props tween-props)            ; ((key start . end) ...)
  (duration tween-duration)      ; ms per cycle
  (delay tween-delay)            ; ms before the first cycle
  (ease tween-ease)              ; a name or a procedure of t
  (ease-index tween-ease-index)  ; the native curve, #f for a procedure
  (repeat tween-repeat)          ; extra cycles, -1 forever
  (yoyo? tween-yoyo?)
  (on-complete tween-on-complete)
  (elapsed tween-elapsed))

(%register-tween-type! <tween>)

(define (tween-with-elapsed tween elapsed)
  "A copy of TWEEN that has run for ELAPSED ms."
  (unless (tween? tween) (bad "tween-with-elapsed" "tween: expected a tween (make-tween)" tween))
  ;; The stepper adds dt to it in doubles: NaN, ±inf (or an exact number
  ;; that is one as a double) would never reach the end, and time before
  ;; the start is the delay's to give.
  (unless (and (real? elapsed) (finite-real? (exact->inexact elapsed)) (>= elapsed 0))
    (bad "tween-with-elapsed" "elapsed: expected a number of ms from 0 to 1.8e308 (a double's range)" elapsed))
  (%make-tween (tween-props tween) (tween-duration tween) (tween-delay tween)
               (tween-ease tween) (tween-ease-index tween) (tween-repeat tween)
               (tween-yoyo? tween) (tween-on-complete tween) elapsed))

;; Read-only: the stepper knows its curves by number (%ease-index), not from
;; this list, so a set! would only make the list wrong.
(define-read-only easing-names built-in-easings
  "easing-names is read-only: it lists the easings the engine has built in; \
an easing of your own is a procedure of t in [0, 1], given as make-tween's #:ease")
(define built-in-easings
  (cons 'linear
        (append-map (lambda (family)
                      (map (lambda (variant) (symbol-append family '- variant))
                           '(in out in-out)))
                    '(quad cubic quart sine expo back elastic bounce))))

(define (bad who what value)
  (scm-error 'wrong-type-arg who (string-append what ", got ~S") (list value) #f))

(define (finite-real? x) (and (real? x) (not (nan? x)) (not (inf? x))))

(define (ease name t)
  "The easing curve NAME (e.g. 'quad-in-out) at T in [0, 1]."
  (let ((index (%ease-index name)))
    (unless index (bad "ease" "expected an easing name" name))
    (%ease index t)))

(define* (make-tween entity #:key (props '()) (duration 0) (delay 0) (ease 'linear)
                     (on-complete #f) (repeat 0) (yoyo? #f))
  "A tween of ENTITY's PROPS, an alist of (key . target). Store it under
#:tween; step-tweens advances it by dt and removes it at the end, then calls
ON-COMPLETE with the entity (its result replaces the entity when it is one)."
  (unless (and (list? props) (<= (length props) %max-tween-props))
    (bad "make-tween"
         (format #f "props: expected an alist of at most ~a (key . target)" %max-tween-props)
         props))
  (for-each (lambda (p)
              (unless (and (pair? p) (keyword? (car p)) (finite-real? (cdr p)))
                (bad "make-tween" "props: expected (keyword . finite number)" p)))
            props)
  ;; One value per key: a key twice would need a rule for which one wins.
  (let loop ((keys (map car props)))
    (unless (null? keys)
      (when (memq (car keys) (cdr keys))
        (bad "make-tween" "props: duplicate key" (car keys)))
      (when (eq? (car keys) #:tween)
        (bad "make-tween" "props: a tween cannot drive its own key" (car keys)))
      (loop (cdr keys))))
  (unless (and (finite-real? duration) (>= duration 0))
    (bad "make-tween" "duration: expected a number of ms ≥ 0" duration))
  (unless (and (finite-real? delay) (>= delay 0))
    (bad "make-tween" "delay: expected a number of ms ≥ 0" delay))
  (unless (and (exact-integer? repeat) (<= -1 repeat %max-tween-repeat))
    (bad "make-tween"
         (format #f "repeat: expected an exact integer from -1 to ~a" %max-tween-repeat)
         repeat))
  (when (and (= repeat -1) (zero? duration))
    (bad "make-tween" "repeat: a tween repeating forever needs a duration > 0" repeat))
  (unless (or (procedure? ease) (%ease-index ease))
    (bad "make-tween" "ease: expected an easing name or a procedure" ease))
  (unless (or (not on-complete) (procedure? on-complete))
    (bad "make-tween" "on-complete: expected a procedure or #f" on-complete))
  (let ((props (map (lambda (p)
                      (let ((start (entity-ref entity (car p) 0)))
                        (unless (finite-real? start)
                          (bad "make-tween" "start value: expected a finite number" start))
                        (cons* (car p) start (cdr p))))
                    props)))
    (%make-tween props duration delay ease (and (symbol? ease) (%ease-index ease))
                 repeat yoyo? on-complete 0)))
