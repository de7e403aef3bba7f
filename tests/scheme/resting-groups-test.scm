;; SPDX-License-Identifier: MIT
;;; Resting groups on the Scheme path (settle.hpp's RestingGroups): the
;;; native step-scene lets colliders at rest that push each other sleep as
;;; a group, as the World path does, and a run with them asleep equals,
;;; entity for entity (equal?) and frame for frame, the reference
;;; step-scene, which never sleeps. An asleep entity comes back eq? to the
;;; one it was handed.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke entity) (downstroke world) (downstroke tilemap)
             (downstroke physics)
             ((downstroke reference) #:select ((step-scene . reference-step-scene))))

(load "support.scm")

(test-begin "resting-groups")

;;; 20 × 8 cells of 16 px, walled, the floor's top at y = 112 (the core's
;;; tests/core/resting_groups_test.cpp arena).
(define arena
  (let* ((cols 20) (rows 8) (v (make-vector (* cols rows) 0)))
    (do ((c 0 (+ c 1))) ((= c cols))
      (vector-set! v c 1)
      (vector-set! v (+ c (* cols (- rows 1))) 1))
    (do ((r 0 (+ r 1))) ((= r rows))
      (vector-set! v (* cols r) 1)
      (vector-set! v (+ (- cols 1) (* cols r)) 1))
    (make-tilemap cols rows 16 16 v '(1))))
(define floor-top 112)

;;; A stack of eight 8×8 solid gravity boxes standing on the floor at x.
(define (stack name x)
  (map (lambda (k)
         (list #:id (string->symbol (format #f "~a~a" name k)) #:x x #:y (- floor-top (* 8 (+ k 1)))
               #:width 8 #:height 8 #:solid? #t #:gravity? #t))
       (iota 8)))

;;; The bodies the last native frame stepped: velocity-x applies to every
;;; one it visits.
(define (stepped)
  (second (assq 'velocity-x ((@@ (downstroke physics) %frame-stats)))))

;;; Steps `entities` FRAMES frames both ways under resting contacts, with
;;; SUBSTEPS sub-frames, after (EDIT frame entities) each frame; checks each
;;; frame that both give equal entities, and that every entity the native
;;; frame did not step is eq? to its input. Returns the native frames'
;;; stepped counts (summed over sub-frames), frame by frame, or #f at the
;;; first difference (reported).
(define* (run entities frames #:key (substeps 1) (edit (lambda (frame es) es)))
  (define (scene es) (make-scene #:entities es #:tilemap arena))
  (parameterize ((resting-contacts? #t))
    (let loop ((native entities) (reference entities) (frame 1) (counts '()))
      (if (> frame frames)
          (reverse counts)
          (let* ((native (edit frame native))
                 (reference (edit frame reference))
                 (n (scene-entities (step-scene (scene native) 16 #:substeps substeps)))
                 (count (stepped))
                 (r (scene-entities (reference-step-scene (scene reference) 16 #:substeps substeps)))
                 (kept (count-eq native n)))
            (cond
             ((not (equal? n r))
              (format #t "frame ~a: native ~s~%  reference ~s~%" frame n r)
              #f)
             ((< kept (- (length entities) (/ count substeps)))
              (format #t "frame ~a: ~a stepped, but only ~a of ~a eq? to their input~%"
                      frame count kept (length entities))
              #f)
             (else (loop n r (+ frame 1) (cons count counts)))))))))
(define (count-eq before after) (count eq? before after))

;;; Frame 1 steps the stack and leaves it as it was; frame 2 finds it
;;; handed back as left and unchanged again, and forms the group; from
;;; frame 3 it sleeps.
(let ((counts (run (stack 'a 32) 120)))
  (test-assert "a resting stack: every frame equal to the reference's" counts)
  (test-equal "… stepped in frames 1 and 2 only, then asleep" (append '(8 8) (make-list 118 0))
    (and counts counts)))

;;; The core's case too: frames 1-2 step all 17; the stacks then sleep while
;;; the box falls alone; from frame 6 its extent reaches the first stack,
;;; which wakes (8 + 1), the far one staying asleep; from frame 10 the box
;;; and its stack have rested a frame and sleep as one group.
(let ((counts (run (append (stack 'a 32) (stack 'b 200)
                           (list (list #:id 'drop #:x 32 #:y 16 #:width 8 #:height 8 #:solid? #t #:gravity? #t)))
                   120)))
  (test-assert "a box dropped on one of two stacks: every frame equal to the reference's" counts)
  (test-equal "… the stacks asleep while it falls, its stack woken where it lands, then all asleep"
    (append '(17 17) (make-list 3 1) (make-list 4 9) (make-list 111 0))
    counts))

;;; With sub-frames: a shot thrown down onto the first stack reaches it in
;;; the fourth sub-frame, and the frame runs again from its start with the
;;; stack awake (the core's case: all 17 bodies in frames 1-2, then none;
;;; the shot and its stack from the throw until they have rested a frame).
(let ((counts (run (append (stack 'a 32) (stack 'b 200)
                           (list (list #:id 'shot #:x 32 #:y 16 #:width 8 #:height 8 #:solid? #t)))
                   60 #:substeps 4
                   #:edit (lambda (frame es)
                            (if (= frame 6)
                                (append (list-head es 16) (list (entity-set (list-ref es 16) #:vy 24)))
                                es)))))
  (test-assert "sub-frames, a group reached in a later one: every frame equal to the reference's" counts)
  (test-equal "… the frame run again once, the other stack asleep throughout"
    (append (make-list 2 (* 4 17)) (make-list 3 0) (make-list 3 (* 4 9)) (make-list 52 0))
    counts))

;;; A box sliding along the floor into a sleeping stack wakes it and pushes
;;; its boxes, whose plists lack #:vx and #:vy: the keys a woken entity
;;; gains come in the order stepping every body gives them.
(let ((counts (run (append (stack 'a 32)
                           (list (list #:id 'slider #:x 120 #:y (- floor-top 8) #:width 8 #:height 8
                                       #:solid? #t #:gravity? #t #:vx -3)))
                   120)))
  (test-assert "a box sliding into a stack: every frame equal to the reference's" counts)
  (test-assert "… which slept before it came and wakes when it does"
    (and counts (= 1 (list-ref counts 3)) (< 1 (apply max (list-tail counts 3))))))

;;; An asleep entity is handed back as the very same object.
(parameterize ((resting-contacts? #t))
  (let* ((s0 (make-scene #:entities (stack 'a 32) #:tilemap arena))
         (s3 (step-scene (step-scene (step-scene s0 16) 16) 16))
         (s4 (step-scene s3 16)))
    (test-equal "an asleep stack's entities come back eq?" (make-list 8 #t)
      (map eq? (scene-entities s3) (scene-entities s4)))
    (test-eq "… and the list itself" (scene-entities s3) (scene-entities s4))
    ;; Every entity in a resting group and the very list handed back: the
    ;; frame steps nobody, so it is skipped before decoding.
    (let ((decode (lambda () (assq 'decode ((@@ (downstroke physics) %frame-stats))))))
      (test-equal "… a frame of only asleep groups is not even decoded" '(decode 0 8)
        (list-head (decode) 3))
      (let* ((s5 (step-scene s4 16))
             (late (entity-set (car (scene-entities s5)) #:vy 0.0))
             (s6 (step-scene (update-scene s5 #:entities (cons late (cdr (scene-entities s5)))) 16)))
        (test-eq "… nor the next" (scene-entities s4) (scene-entities s5))
        (test-equal "… but one written entity decodes the frame again" '(decode 8 0)
          (list-head (decode) 3))
        (test-equal "… which steps as the reference does"
          (scene-entities (reference-step-scene (update-scene s5 #:entities (cons late (cdr (scene-entities s5)))) 16))
          (scene-entities s6))))))

(test-end "resting-groups")
