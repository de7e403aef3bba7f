;; SPDX-License-Identifier: MIT
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke))

(load "support.scm")

(test-begin "history")

;;; ------------------------------------------------------------ frame ring
(let ((ring (make-frame-ring 3)))
  (test-assert (frame-ring? ring))
  (test-equal #f (frame-ring? '(1 2 3)))
  (test-equal #f (frame-ring-ref ring 0))          ; nothing kept yet
  (for-each (lambda (k) (frame-ring-set! ring k (* 10 k))) '(0 1 2 3 4))
  ;; frames 3 and 4 took the slots of 0 and 1; 2 is still there
  (test-equal '(#f #f 20 30 40) (map (lambda (k) (frame-ring-ref ring k)) '(0 1 2 3 4)))
  (test-equal #f (frame-ring-ref ring 7))           ; 7's slot holds frame 4
  (test-equal #f (frame-ring-ref ring -2))          ; a negative frame's slot holds frame 4
  (frame-ring-set! ring 4 'again)                   ; a frame may be kept again
  (test-equal 'again (frame-ring-ref ring 4)))

(test-equal "In procedure make-frame-ring: size: expected a positive exact integer, got 0\n"
  (error-text (lambda () (make-frame-ring 0))))
(test-assert (mentions? (error-text (lambda () (make-frame-ring 2.0))) "make-frame-ring" "2.0"))
(test-equal "In procedure frame-ring-ref: frame: expected an exact integer, got +nan.0\n"
  (error-text (lambda () (frame-ring-ref (make-frame-ring 2) +nan.0))))
(test-assert (mentions? (error-text (lambda () (frame-ring-set! (make-frame-ring 2) "1" 'x)))
                        "frame-ring-set!" "\"1\""))

;;; ------------------------------------------------------------ bounded log
(define (push-all log items keep)
  (fold (lambda (item log) (bounded-log-push log item keep)) log items))

(let* ((empty (make-bounded-log))
       (four (push-all empty '(a b c d) 2)))
  (test-equal '() (bounded-log-items empty))
  ;; up to twice KEEP, nothing is dropped; newest first
  (test-equal '(d c b a) (bounded-log-items four))
  (test-equal '(d c) (bounded-log-newest four 2))
  (test-equal '(d c b a) (bounded-log-newest four 9))
  ;; the fifth is one too many: cut back to the newest two
  (let ((five (bounded-log-push four 'e 2)))
    (test-equal '(e d) (bounded-log-items five))
    (test-equal '(d c b a) (bounded-log-items four))   ; a log is a value
    (test-equal '(g f e d) (bounded-log-items (push-all five '(f g) 2)))
    (test-equal '(h g) (bounded-log-items (push-all five '(f g h) 2)))))

;; a log made from a list, newest first, goes on as any other
(let ((log (list->bounded-log '(c b a))))
  (test-equal '(c b a) (bounded-log-items log))
  (test-equal '(c b) (bounded-log-newest log 2))
  (test-equal '(e d) (bounded-log-items (push-all log '(d e) 2)))
  (test-equal '() (bounded-log-items (list->bounded-log '()))))
(test-equal "In procedure list->bounded-log: items: expected a proper list, got (a . b)\n"
  (error-text (lambda () (list->bounded-log '(a . b)))))

(test-equal "In procedure bounded-log-push: keep: expected a positive exact integer, got 0\n"
  (error-text (lambda () (bounded-log-push (make-bounded-log) 'a 0))))
(test-assert (mentions? (error-text (lambda () (bounded-log-push (make-bounded-log) 'a 'many)))
                        "bounded-log-push" "many"))

(test-end "history")
