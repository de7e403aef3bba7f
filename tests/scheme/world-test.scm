;; SPDX-License-Identifier: MIT
(use-modules (srfi srfi-64) (downstroke) (srfi srfi-1))

(load "support.scm")

(define (grid-map cols rows solid)
  (let ((v (make-vector (* cols rows) 0)))
    (for-each (lambda (c) (vector-set! v (+ (car c) (* cols (cdr c))) 1)) solid)
    (make-tilemap cols rows 16 16 v '(1))))

(test-begin "world")

;;; ---------------------------------------------------------------- camera
(let ((c (make-camera)))
  (test-assert (camera? c))
  (test-equal 0 (camera-x c))
  (test-equal 0 (camera-y c))
  (camera-x-set! c 12)
  (camera-y-set! c 7.5)
  (test-equal 12 (camera-x c))
  (test-equal 7.5 (camera-y c)))
(let ((c (make-camera x: 5 y: 6)))
  (test-equal '(5 6) (list (camera-x c) (camera-y c))))
(let ((c (make-camera #:y 9)))
  (test-equal '(0 9) (list (camera-x c) (camera-y c))))
(test-equal #f (camera? 'camera))
;; A camera holds finite real coordinates; anything else is refused by name.
(test-equal "In procedure make-camera: camera x: expected a finite number, got +nan.0\n"
  (error-text (lambda () (make-camera x: +nan.0))))
(test-assert (mentions? (error-text (lambda () (make-camera y: "3"))) "make-camera" "camera y" "\"3\""))
(test-assert (mentions? (error-text (lambda () (make-camera y: -inf.0))) "camera y" "-inf.0"))
(let ((c (make-camera x: 4 y: 1/2)))
  (test-assert (mentions? (error-text (lambda () (camera-x-set! c +inf.0))) "camera-x-set!" "camera x"))
  (test-assert (mentions? (error-text (lambda () (camera-y-set! c 'up))) "camera-y-set!" "camera y" "up"))
  (test-equal '(4 1/2) (list (camera-x c) (camera-y c))))  ; refused writes leave it as it was

;;; ---------------------------------------------------------------- make-scene and accessors
(let ((s (make-scene)))
  (test-assert (scene? s))
  (test-equal '() (scene-entities s))
  (test-equal #f (scene-tilemap s))
  (test-assert (camera? (scene-camera s)))
  (test-equal 0 (camera-x (scene-camera s)))
  (test-equal #f (scene-camera-target s)))
(define tm (grid-map 4 4 '((0 . 3))))
(define cam (make-camera x: 1 y: 2))
(define ents (list '(#:id a #:x 1) '(#:id b #:x 2)))
(define s1 (make-scene entities: ents tilemap: tm camera: cam camera-target: 'a))
(test-eq (scene-entities s1) ents)
(test-eq tm (scene-tilemap s1))
(test-eq cam (scene-camera s1))
(test-equal 'a (scene-camera-target s1))
(test-assert (not (scene? ents)))
(test-error "entities: must be a list" (make-scene entities: 'nope))

;;; ---------------------------------------------------------------- update-scene
(define s2 (update-scene s1 entities: '((#:id c))))
(test-equal '((#:id c)) (scene-entities s2))
(test-eq "tilemap kept" tm (scene-tilemap s2))
(test-eq "camera kept (the same mutable record)" cam (scene-camera s2))
(test-equal "camera target kept" 'a (scene-camera-target s2))
(test-eq "the original is not modified" ents (scene-entities s1))
(test-assert "a new scene" (not (eq? s1 s2)))
(define s3 (update-scene s1 tilemap: #f camera-target: 'b))
(test-equal #f (scene-tilemap s3))
(test-equal 'b (scene-camera-target s3))
(test-eq ents (scene-entities s3))
(test-eq tm (scene-tilemap s1))
(let ((c2 (make-camera)))
  (test-eq c2 (scene-camera (update-scene s1 camera: c2))))
(test-error "update-scene refuses a non-list" (update-scene s1 entities: 5))
;; The camera is shared and mutable: a change through one scene shows in the other.
(camera-x-set! (scene-camera s2) 99)
(test-equal 99 (camera-x (scene-camera s1)))

;;; ---------------------------------------------------------------- scene-map-entities
(define (add-x n) (lambda (e) (entity-set e #:x (+ (entity-ref e #:x 0) n))))
(define (double-x e) (entity-set e #:x (* 2 (entity-ref e #:x 0))))
;; (5 + 1)·2 = 12, not 5·2 + 1 = 11: steps in the order given.
(test-equal "steps applied in order" '((#:x 12) (#:x 4))
  (scene-entities (scene-map-entities (make-scene entities: '((#:x 5) (#:x 1))) (add-x 1) double-x)))
(test-equal "the other order" '((#:x 11) (#:x 3))
  (scene-entities (scene-map-entities (make-scene entities: '((#:x 5) (#:x 1))) double-x (add-x 1))))
;; Each step runs over every entity before the next step starts.
(let* ((log '())
       (tracer (lambda (tag) (lambda (e) (set! log (cons (list tag (entity-ref e #:id)) log)) e))))
  (scene-map-entities (make-scene entities: '((#:id 1) (#:id 2))) (tracer 'a) (tracer 'b))
  (test-equal "one step after another" '((a 1) (a 2) (b 1) (b 2)) (reverse log)))
(let* ((l (list '(#:x 1) '(#:x 2)))
       (s (make-scene entities: l)))
  (test-eq "identity steps: the same entity list" l
    (scene-entities (scene-map-entities s identity (lambda (e) e))))
  (test-eq "no steps: the same list" l (scene-entities (scene-map-entities s)))
  (test-eq "physics steps that change nothing: the same list" l
    (scene-entities (scene-map-entities s (lambda (e) (apply-gravity e s 16))
                                          (lambda (e) (apply-velocity-y e s 16))))))
(let* ((a '(#:x 1 #:vx 0)) (b '(#:x 2 #:vx 3))
       (s (make-scene entities: (list a b)))
       (r (scene-entities (scene-map-entities s (lambda (e) (apply-velocity-x e s 16))))))
  (test-eq "unchanged elements are the same objects" a (car r))
  (test-equal '(#:x 5 #:vx 3) (cadr r))
  (test-equal "the scene is not modified" (list a b) (scene-entities s)))
(let ((s (make-scene entities: '((#:x 1)) tilemap: tm camera: cam)))
  (let ((r (scene-map-entities s (add-x 1))))
    (test-eq "tilemap carried" tm (scene-tilemap r))
    (test-eq "camera carried" cam (scene-camera r))))

;;; ---------------------------------------------------------------- scene-transform-entities
(let* ((l (list '(#:id 1) '(#:id 2)))
       (s (make-scene entities: l tilemap: tm))
       (r (scene-transform-entities s reverse)))
  (test-equal '((#:id 2) (#:id 1)) (scene-entities r))
  (test-eq l (scene-entities s))
  (test-eq tm (scene-tilemap r)))
(let* ((s (make-scene entities: (list '(#:x 0 #:y 0 #:width 10 #:height 10 #:solid? #t)
                                      '(#:x 7 #:y 0 #:width 10 #:height 10 #:solid? #t))))
       (r (scene-transform-entities s resolve-entity-collisions)))
  (test-equal '((#:x -2 #:y 0 #:width 10 #:height 10 #:solid? #t #:vx -1)
                (#:x 8 #:y 0 #:width 10 #:height 10 #:solid? #t #:vx 1))
    (scene-entities r))
  (test-equal 0 (entity-ref (car (scene-entities s)) #:x)))
(test-equal "filtering" '((#:keep #t))
  (scene-entities (scene-transform-entities (make-scene entities: '((#:keep #t) (#:keep #f)))
                                            (lambda (l) (filter (lambda (e) (entity-ref e #:keep)) l)))))

;;; ---------------------------------------------------------------- step-scene = the composition
;; semantics §5: the per-entity steps, each applied to every entity with the scene
;; as it was at the start of the frame, then the two bulk steps.
(define (composed-frame scene dt)
  (let ((per-entity (list step-tweens apply-acceleration apply-gravity apply-velocity-x
                          resolve-tile-collisions-x apply-velocity-y resolve-tile-collisions-y
                          detect-on-solid)))
    (update-scene scene
                  entities: (sync-groups
                             (resolve-entity-collisions
                              (map (lambda (e)
                                     (fold (lambda (step e) (step e scene dt)) e per-entity))
                                   (scene-entities scene)))))))

;; The entity lists of N frames, stepping with STEP.
(define (run step scene n dt)
  (let loop ((i 0) (s scene) (acc '()))
    (if (= i n)
        (reverse acc)
        (let ((next (step s dt)))
          (loop (+ i 1) next (cons (scene-entities next) acc))))))

;; #f when both runs agree, else the first frame that differs and what differs.
(define (first-difference composed native)
  (let loop ((i 1) (a composed) (b native))
    (cond ((and (null? a) (null? b)) #f)
          ((equal? (car a) (car b)) (loop (+ i 1) (cdr a) (cdr b)))
          (else (list 'frame i
                      'composition (lset-difference equal? (car a) (car b))
                      'step-scene (lset-difference equal? (car b) (car a)))))))

(define (same-as-composition? name scene)
  (let ((native (run step-scene scene 30 16))
        (composed (run composed-frame scene 30 16)))
    (test-equal (string-append name ": 30 frames equal the composition") #f
      (first-difference composed native))
    native))

;; 1: a floor (row 10, y 160) and a wall (column 15, x 240); a runner that
;; reaches the wall, a crate landing on an immovable platform, two boxes
;; meeting, a group riding a moving origin.
(define level
  (grid-map 20 12 (append (map (lambda (c) (cons c 10)) (iota 20))
                          (map (lambda (r) (cons 15 r)) (iota 10)))))
(define scene-a
  (make-scene
   tilemap: level
   entities: (list '(#:id runner #:x 16 #:y 100 #:width 16 #:height 16 #:gravity? #t #:vx 8 #:ay -5)
                   '(#:id crate #:x 100 #:y 0 #:width 16 #:height 16 #:gravity? #t #:solid? #t)
                   '(#:id plat #:x 96 #:y 120 #:width 48 #:height 8 #:solid? #t #:immovable? #t)
                   '(#:id b1 #:x 150 #:y 144 #:width 16 #:height 16 #:solid? #t #:gravity? #t #:vx 2 #:vy 0)
                   '(#:id b2 #:x 180 #:y 144 #:width 16 #:height 16 #:solid? #t #:gravity? #t #:vx -2 #:vy 0)
                   '(#:id boat #:x 0 #:y 50 #:vx 2 #:group-id g #:group-origin? #t)
                   '(#:id flag #:group-id g #:group-local-x 4 #:group-local-y -8 #:name "flag"))))
(define frames-a (same-as-composition? "platformer" scene-a))
;; Spot checks from docs/semantics.org, independent of the composition.
;; Runner: x = 16 + 8k until its box [x, x+16) meets the wall at 240:
;; k = 26 gives 224 (touching); k = 27 would give 232 → snapped to 240 − 16 = 224, vx 0.
(let ((runner (lambda (k) (car (list-ref frames-a (- k 1))))))
  (test-equal 224 (entity-ref (runner 26) #:x))
  (test-equal 8 (entity-ref (runner 26) #:vx))
  (test-equal 224 (entity-ref (runner 27) #:x))
  (test-equal 0 (entity-ref (runner 27) #:vx))
  ;; y: frame 1: vy = 0 − 5 + 1 = −4, y 96; then vy −3 … : y = 100 + Σ(−5 + k).
  (test-equal '(96 -4 0) (map (lambda (k) (entity-ref (runner 1) k)) '(#:y #:vy #:ay)))
  (test-equal '(93 -3) (map (lambda (k) (entity-ref (runner 2) k)) '(#:y #:vy))))
;; The flag follows the boat: boat x = 2k, flag x = 2k + 4, y = 50 − 8 = 42 (k = 10).
(test-equal '(24 42) (let ((flag (list-ref (list-ref frames-a 9) 6)))
                       (list (entity-ref flag #:x) (entity-ref flag #:y))))
;; Crate: y_k = k(k+1)/2 until it overlaps the platform's top at 120:
;; k = 7: y 28; … k = 13: y 91 (feet 107); k = 14: y 105 (feet 121 > 120) →
;; landing (centre 113 < 124): y = 120 − 16 = 104, vy 0.
(let ((crate (lambda (k) (cadr (list-ref frames-a (- k 1))))))
  (test-equal '(91 13) (list (entity-ref (crate 13) #:y) (entity-ref (crate 13) #:vy)))
  (test-equal '(104 0) (list (entity-ref (crate 14) #:y) (entity-ref (crate 14) #:vy))))

;; 2: no tilemap; boxes falling on an immovable floor entity and on each other,
;; flonums included.
(define scene-b
  (make-scene
   entities: (list '(#:id floor #:x 0 #:y 200 #:width 300 #:height 20 #:solid? #t #:immovable? #t)
                   '(#:id low #:x 50 #:y 150 #:width 20 #:height 20 #:gravity? #t #:solid? #t)
                   '(#:id high #:x 55 #:y 100 #:width 20 #:height 20 #:gravity? #t #:solid? #t)
                   '(#:id float #:x 150.5 #:y 20.25 #:width 10 #:height 10 #:gravity? #t #:solid? #t #:vx 0.5)
                   '(#:id ghost #:x 52 #:y 0 #:width 20 #:height 20 #:gravity? #t #:solid? #t
                     #:skip-pipelines (entity-collisions)))))
(same-as-composition? "stacking" scene-b)

;; 3: tweens with skip-pipelines, repeating tweens, on-complete, groups.
(define knock-base '(#:id enemy #:x 100 #:y 144 #:width 16 #:height 16 #:gravity? #t #:vx -5
                     #:skip-pipelines (acceleration gravity velocity-x velocity-y)))
(define bob-base '(#:id bob #:x 200 #:y 40 #:group-id h #:group-origin? #t))
(define scene-c
  (make-scene
   tilemap: level
   entities: (list (entity-set knock-base #:tween
                               (make-tween knock-base props: '((#:x . 40)) duration: 160
                                           ease: 'quad-out
                                           on-complete: (lambda (e) (entity-set e #:stunned #t))))
                   (entity-set bob-base #:tween
                               (make-tween bob-base props: '((#:y . 80) (#:x . 190)) duration: 100
                                           repeat: -1 yoyo?: #t))
                   '(#:id rider #:group-id h #:group-local-x 0 #:group-local-y -10)
                   '(#:id faller #:x 40 #:y 0 #:width 16 #:height 16 #:gravity? #t #:solid? #t))))
(define frames-c (same-as-composition? "tweens" scene-c))
(test-equal "on-complete ran once (the key is there at the end)" #t
  (entity-ref (car (last frames-c)) #:stunned))

;; A resting scene comes back itself.
(define resting
  (make-scene tilemap: level
              entities: (list '(#:id box #:x 32 #:y 144 #:width 16 #:height 16 #:gravity? #t #:vy 0 #:on-ground? #t)
                              '(#:id sign #:x 60 #:y 10 #:width 8 #:height 8)
                              '(#:id wall #:x 0 #:y 0 #:width 10 #:height 10 #:solid? #t #:immovable? #t))))
(test-eq "a resting scene: step-scene returns the scene itself" resting (step-scene resting 16))
(let ((s (make-scene)))
  (test-eq "an empty scene: itself" s (step-scene s 16)))
(let* ((s (make-scene entities: (list '(#:x 1 #:vx 1) '(#:id still #:x 5))))
       (r (step-scene s 16)))
  (test-eq "unchanged entities are the same objects" (cadr (scene-entities s)) (cadr (scene-entities r)))
  (test-equal '(#:x 2 #:vx 1) (car (scene-entities r)))
  (test-eq "tilemap carried" #f (scene-tilemap r))
  (test-eq "camera carried" (scene-camera s) (scene-camera r)))
;; step-scene respects collision-mode: a box crossing a 1-tile wall in one frame.
(let ((s (make-scene tilemap: (grid-map 20 3 '((5 . 0) (5 . 1) (5 . 2)))
                     entities: '((#:x 0 #:y 16 #:width 16 #:height 16 #:vx 160)))))
  (test-equal "swept" 64 (entity-ref (car (scene-entities (step-scene s 16))) #:x))
  (test-equal "discrete" 160 (entity-ref (car (scene-entities (parameterize ((collision-mode 'discrete))
                                                               (step-scene s 16))))
                                         #:x)))

;; Per-entity steps see the frame-start scene, so the order of the list does
;; not matter. A platform moving down (vy 3) under a falling body:
;; body vy 3 → 4, y 84 → 88; detect-on-solid vs the platform at its
;; frame-start y 100: feet 104, |104 − 100| = 4, |4 − 3| = 1 → on the ground.
;; Platform → 103; overlap 1, the body's centre is above → y = 103 − 16 = 87, vy 0.
(define elevator '(#:id el #:x 0 #:y 100 #:width 64 #:height 16 #:solid? #t #:immovable? #t #:vy 3))
(define passenger '(#:id pa #:x 10 #:y 84 #:width 16 #:height 16 #:gravity? #t #:solid? #t #:vy 3))
(define forward (scene-entities (step-scene (make-scene entities: (list elevator passenger)) 16)))
(define backward (scene-entities (step-scene (make-scene entities: (list passenger elevator)) 16)))
(test-equal "moving platform: the passenger"
  '(#:id pa #:x 10 #:y 87 #:width 16 #:height 16 #:gravity? #t #:solid? #t #:vy 0 #:on-ground? #t)
  (cadr forward))
(test-equal "moving platform: the platform" 103 (entity-ref (car forward) #:y))
(test-equal "order of the list does not matter" forward (reverse backward))
;; The native frame step excludes the entity's own slot: a 3 px tall solid
;; body falling alone is never "supported" by its own frame-start self.
(test-equal "own slot excluded" #f
  (entity-ref (car (scene-entities (step-scene (make-scene entities: '((#:x 0 #:y 0 #:width 8 #:height 3
                                                                       #:solid? #t #:gravity? #t)))
                                               16)))
              #:on-ground?))
(test-error "step-scene: dt must be a number" (step-scene (make-scene entities: '((#:x 0 #:vx 1))) "16"))
(test-error "step-scene: a malformed entity" (step-scene (make-scene entities: '((#:x 0 #:vx))) 16))

;; Equivalence with the composition also covers the keys a frame writes. A body
;; resting on the floor without a #:vy key: apply-gravity appends #:vy 1 and
;; resolve-tile-collisions-y sets it to 0, so the composition ends with
;; #:vy 0 appended; step-scene must give the same (equal?) plist.
(define keyless
  (make-scene tilemap: level
              entities: '((#:id box #:x 32 #:y 144 #:width 16 #:height 16 #:gravity? #t #:on-ground? #t))))
(test-equal "composition: #:vy 0 appended"
  '((#:id box #:x 32 #:y 144 #:width 16 #:height 16 #:gravity? #t #:on-ground? #t #:vy 0))
  (scene-entities (composed-frame keyless 16)))
(test-equal "step-scene: equal to the composition (#:vy 0 appended)"
  (scene-entities (composed-frame keyless 16))
  (scene-entities (step-scene keyless 16)))
;; Keys absent at the start are appended in the order the steps write them:
;; apply-gravity (#:vy), then apply-velocity-x (#:x), then apply-velocity-y (#:y).
(define keyless-mover
  (make-scene entities: '((#:id m #:width 4 #:height 4 #:gravity? #t #:vx 1))))
(test-equal "composition: appended in step order"
  '((#:id m #:width 4 #:height 4 #:gravity? #t #:vx 1 #:vy 1 #:x 1 #:y 1))
  (scene-entities (composed-frame keyless-mover 16)))
(test-equal "step-scene: same key order as the composition"
  (scene-entities (composed-frame keyless-mover 16))
  (scene-entities (step-scene keyless-mover 16)))

;; The reference hands a scene back as itself too when a frame changed a
;; value and put it back (found by the differential tests): gravity writes
;; #:vy 1, the landing writes #:vy 0 again.
(let ((resting (make-scene entities: (list '(#:x 0 #:y 32 #:width 16 #:height 16 #:gravity? #t
                                             #:vy 0 #:on-ground? #t))
                           tilemap: (grid-map 1 4 '((0 . 3))))))
  (test-eq "native: a resting scene comes back as itself" resting (step-scene resting 16))
  (test-eq "reference: the same" resting ((@ (downstroke reference) step-scene) resting 16)))

;; A value a double cannot hold exactly (−33/2 is read as −16.5): moved to
;; −15.5 and pushed back to −16.5 by the wall in one frame, it is written as
;; the flonum −16.5, as the composition writes it.
(define lossy-pair
  (make-scene entities: '((#:x -33/2 #:y 0 #:width 16 #:height 16 #:vx 1 #:solid? #t)
                          (#:x -0.5 #:y 0 #:width 16 #:height 16 #:solid? #t #:immovable? #t))))
(test-eqv "composition: the fraction is replaced by the flonum"
  -16.5 (entity-ref (car (scene-entities (composed-frame lossy-pair 16))) #:x))
(test-equal "step-scene: equal to the composition (lossy value restored)"
  (scene-entities (composed-frame lossy-pair 16))
  (scene-entities (step-scene lossy-pair 16)))
(test-eqv -16.5 (entity-ref (car (scene-entities (step-scene lossy-pair 16))) #:x))

;; semantics §5: every per-entity step — detect-on-solid included — receives the
;; scene as it was at the start of the frame, i.e. before this frame's tweens.
;; A platform tweened from y 100 to 150 (t = 0.2 per 20 ms frame: 110.0 after
;; one frame) under a resting body: the body's detect-on-solid sees the
;; platform at 100: feet 84 + 1 + 16 = 101, |101 − 100| = 1 ≤ 4, |1 − 0| ≤ 4
;; → #:on-ground? stays #t. (The bodies no longer overlap: no push.)
(define lift-base '(#:id lift #:x 0 #:y 100 #:width 64 #:height 16 #:solid? #t #:immovable? #t))
(define lift-scene
  (make-scene entities: (list (entity-set lift-base #:tween (make-tween lift-base props: '((#:y . 150))
                                                                        duration: 100))
                              '(#:id rider #:x 10 #:y 84 #:width 16 #:height 16 #:gravity? #t
                                #:on-ground? #t))))
(test-equal "composition: supported by the platform's frame-start position" #t
  (entity-ref (cadr (scene-entities (composed-frame lift-scene 20))) #:on-ground?))
(test-equal "step-scene: same (detect-on-solid must see the frame-start scene)" #t
  (entity-ref (cadr (scene-entities (step-scene lift-scene 20))) #:on-ground?))

;;; ---------------------------------------------------------------- a scene at rest
;;; Handed back the very list it returned, with every entity settled, under
;;; the same map and options, step-scene knows the frame is a no-op and does
;;; not even decode: the scene comes back as itself and every step reports
;;; all entities skipped. Any other input takes the full path.
(define shelf (make-tilemap 4 4 16 16 (append (make-list 12 0) (make-list 4 1)) '(1)))
(define resting-boxes
  (map (lambda (i) (list #:x (* 16 i) #:y 40 #:width 8 #:height 8 #:gravity? #t)) (iota 4)))
(define settled
  (let loop ((i 0) (s (make-scene #:entities resting-boxes #:tilemap shelf)))
    (if (= i 3) s (loop (+ i 1) (step-scene s 16)))))
(define (noop-stats) (engine-stats (make-game)))
(test-eq "a settled scene comes back as itself" settled (step-scene settled 16))
(test-equal "… and no step processed anything"
  '((decode 0 4) (tweens 0 4) (acceleration 0 4) (gravity 0 4) (speed-limits 0 4) (velocity-x 0 4)
    (tile-collisions-x 0 4) (velocity-y 0 4) (tile-collisions-y 0 4) (on-solid 0 4)
    (entity-collisions 0 4) (groups 0 4) (encode 0 4)
    (collect 0 0)                       ; not a pair allocated, no collection
    (render 0 0))
  (map (lambda (row) (list-head row 3)) (noop-stats)))
(resolve-entity-collisions (list '(#:x 0 #:y 0 #:width 8 #:height 8 #:solid? #t)))
(step-scene settled 16)
(test-equal "… its figures count the scene's entities, whatever ran in between"
  '(decode 0 4) (list-head (car (noop-stats)) 3))
(test-equal "the same list on another map is stepped: without the floor they fall"
  '(41 41 41 41)
  (map (lambda (e) (entity-ref e #:y))
       (scene-entities (step-scene (update-scene settled #:tilemap (make-tilemap 4 4 16 16 (make-list 16 0) '(1)))
                                   16))))
(test-equal "… and with other options: two sub-frames make y a flonum" '(40.0 40.0 40.0 40.0)
  (map (lambda (e) (entity-ref e #:y)) (scene-entities (step-scene settled 16 #:substeps 2))))
(test-eq "a new list with the same entities takes the full path, and is unchanged"
  (car (scene-entities settled))
  (car (scene-entities (step-scene (update-scene settled #:entities (list-copy (scene-entities settled))) 16))))
;;; Settled marks belong to the map (and options) they were made under: a
;;; list that shrinks while stepped on another map and then grows back
;;; brings back entities that settled on the old map; on this one they fall.
(step-scene settled 16)
(step-scene settled 16)
(define bare-map (make-tilemap 4 4 16 16 (make-list 16 0) '(1)))
(step-scene (update-scene settled #:entities (list (car (scene-entities settled))) #:tilemap bare-map) 16)
(test-equal "a list that shrank on another map grows back: every entity falls" '(41 41 41 41)
  (map (lambda (e) (entity-ref e #:y))
       (scene-entities (step-scene (update-scene settled #:tilemap bare-map) 16))))

;;; ---------------------------------------------------------------- gravity (semantics §14)
(test-equal "a scene's gravity is 1 unless it says" 1 (scene-gravity (make-scene)))
(test-equal "make-scene gravity: keeps the value, exact" 1/6 (scene-gravity (make-scene #:gravity 1/6)))
(test-equal "update-scene keeps it, and can change it" '(-2 0.5)
  (let ((s (make-scene #:gravity -2)))
    (list (scene-gravity (update-scene s #:entities '())) (scene-gravity (update-scene s #:gravity 0.5)))))
(test-equal "a frame keeps it" 3
  (scene-gravity (step-scene (make-scene #:gravity 3 #:entities '((#:x 0 #:y 0 #:gravity? #t))) 16)))
(test-equal "the scene's gravity pulls: 3, 6, 9 px/frame" '(3 9 18)
  (let loop ((s (make-scene #:gravity 3 #:entities '((#:x 0 #:y 0 #:width 8 #:height 8 #:gravity? #t))))
             (i 0) (acc '()))
    (if (= i 3)
        (reverse acc)
        (let ((s (step-scene s 16)))
          (loop s (+ i 1) (cons (entity-ref (car (scene-entities s)) #:y) acc))))))
(for-each
 (lambda (bad)
   (test-equal (format #f "make-scene gravity: ~s is refused by name" bad)
     (format #f "In procedure make-scene: gravity: expected a finite real number, got ~s\n" bad)
     (error-text (lambda () (make-scene #:gravity bad)))))
 '(+nan.0 +inf.0 "1" 1+2i))
(test-assert "update-scene too"
  (mentions? (error-text (lambda () (update-scene (make-scene) #:gravity 'moon))) "update-scene" "gravity" "moon"))
(let ((es '((#:x 0 #:y 0 #:vy 2))))
  (test-equal "scene-hash: the default gravity adds nothing" (scene-hash (make-scene #:entities es))
    (scene-hash (make-scene #:entities es #:gravity 1)))
  (test-assert "scene-hash: another gravity hashes differently"
    (not (= (scene-hash (make-scene #:entities es)) (scene-hash (make-scene #:entities es #:gravity 1.0)))))
  (test-equal "scene-hash: the reference agrees"
    (map (lambda (g) (scene-hash (make-scene #:entities es #:gravity g))) '(1 1.0 1/6 -2))
    (map (lambda (g) ((@ (downstroke reference-hash) scene-hash) (make-scene #:entities es #:gravity g)))
         '(1 1.0 1/6 -2))))

(test-end "world")
