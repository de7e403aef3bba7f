;; SPDX-License-Identifier: MIT
;;; Every Scheme example of the seed document (docs: Physics System), run as
;;; written — postfix keywords included — followed by the numbers the SPEC
;;; implies.
(use-modules (srfi srfi-64) (downstroke) (srfi srfi-1) (srfi srfi-11))

;;; A COLS×ROWS map of 16 px tiles; the cells in SOLID ((col . row) …) are solid.
(define (grid-map cols rows solid)
  (let ((v (make-vector (* cols rows) 0)))
    (for-each (lambda (c) (vector-set! v (+ (car c) (* cols (cdr c))) 1)) solid)
    (make-tilemap cols rows 16 16 v '(1))))
(define (floor-rows cols rows . floor)
  (grid-map cols rows (append-map (lambda (r) (map (lambda (c) (cons c r)) (iota cols))) floor)))

;;; A render hook recording the first entity after each frame; and a lookup.
(define (recorder)
  (let ((frames '()))
    (values (lambda (game) (set! frames (cons (car (scene-entities (game-scene game))) frames)))
            (lambda (k) (list-ref (reverse frames) k)))))
(define (pick e . keys) (map (lambda (k) (entity-ref e k)) keys))

;;; The examples run under the seed's own push rule (semantics §4): the
;;; parameter for step-scene, and every game the examples make.
(push-rule 'seed)
(define (make-game . args)
  (let ((game (apply (@ (downstroke engine) make-game) args)))
    (game-push-rule-set! game 'seed)
    game))

(test-begin "seed-examples")
(test-equal "the examples run under the seed's push rule" '(seed seed)
  (list (push-rule) (game-push-rule (make-game))))

;;; ================================================================ Platformer
;;; A 40×10 map, floor at row 8 (top y = 128). The player stands on it.
(define platform-map (floor-rows 40 10 8))
(define player0 '(#:id player #:x 32 #:y 112 #:width 16 #:height 16 #:gravity? #t #:vy 0 #:on-ground? #t))

(define (platformer-game script)
  (let-values (((render frame) (recorder)))
    (values
     (make-game
      title: "platformer"
      scene: (make-scene tilemap: platform-map entities: (list player0))
      input-script: script
      render: render
      ;; Omit engine-update: or use default — physics runs automatically before this hook.
      update: (lambda (game dt)
                (let* ((input (game-input game))
                       (scene (game-scene game))
                       (player (car (scene-entities scene)))
                       (jump? (and (input-pressed? input 'a)
                                   (entity-ref player #:on-ground? #f)))
                       (player (entity-set player #:vx
                                           (cond ((input-held? input 'left) -3)
                                                 ((input-held? input 'right) 3)
                                                 (else 0)))))
                  (when jump? (play-sound 'jump))
                  (let ((player (if jump?
                                    (entity-set player #:ay (- *jump-force*))
                                    player)))
                    (game-scene-set! game
                                     (update-scene scene entities: (list player)))))))
     frame)))

;; Walking: hold right from frame 0. Frame 0's physics sees no #:vx yet; from
;; frame 1 on x grows by 3: after frame k, x = 32 + 3k. Ten frames: x = 59.
(let-values (((game frame) (platformer-game '((0 . (right))))))
  (game-run! game frames: 10)
  (test-equal "walk: x per frame" '(32 35 38 41 44 47 50 53 56 59)
    (map (lambda (k) (entity-ref (frame k) #:x)) (iota 10)))
  (test-assert "walk: x exact" (exact? (entity-ref (frame 9) #:x)))
  (test-equal "walk: still on the ground, vy 0, y 112" '(112 0 #t 3)
    (pick (frame 9) #:y #:vy #:on-ground? #:vx))
  (test-equal "walk: no sound" '() (game-sounds game)))
;; Right for 10 frames, left for 5, then nothing: Σ vx over frames 0..18 =
;; 10·3 − 5·3 = 15 → x = 47 after 20 frames, vx 0.
(let-values (((game frame) (platformer-game '((0 . (right)) (10 . (left)) (15 . ())))))
  (game-run! game frames: 20)
  (test-equal "right then left: x 47, vx 0" '(47 0) (pick (frame 19) #:x #:vx))
  (test-equal "turning: x at frames 10..15" '(62 59 56 53 50 47)
    (map (lambda (k) (entity-ref (frame k) #:x)) (iota 6 10))))

;; Jumping: press a at frame 2 (on the ground) → play-sound, #:ay −15. Next
;; frame: vy = 0 − 15 + 1 = −14, y = 112 − 14 = 98, then vy rises by 1 a frame:
;; k frames after the jump, vy = k − 15 and y = 112 + k(k+1)/2 − 15k.
;; Pressing a again at frame 6 (in the air) does nothing. At k = 29 (frame 31)
;; y = 112 + 435 − 435 = 112 with vy 14: the box [112, 128) only touches the
;; floor, so no snap, but the floor row is under its feet: on the ground.
;; k = 30: vy 15, y 127 → snapped to 112, vy 0. A new press at frame 35 jumps again.
(let-values (((game frame)
              (platformer-game '((0 . ()) (2 . (a)) (3 . ()) (6 . (a)) (7 . ()) (35 . (a)) (36 . ())))))
  (game-run! game frames: 37)
  (test-equal "frame 2: ay set by update" '(112 0 -15 #t) (pick (frame 2) #:y #:vy #:ay #:on-ground?))
  (test-equal "frame 3: ay consumed" '(98 -14 0 #f) (pick (frame 3) #:y #:vy #:ay #:on-ground?))
  (test-equal "frames 3..8: y" '(98 85 73 62 52 43) (map (lambda (k) (entity-ref (frame k) #:y)) (iota 6 3)))
  (test-equal "frames 3..8: vy (no second jump at frame 6)" '(-14 -13 -12 -11 -10 -9)
    (map (lambda (k) (entity-ref (frame k) #:vy)) (iota 6 3)))
  (test-equal "apex: frames 16 and 17" '((7 -1) (7 0)) (list (pick (frame 16) #:y #:vy) (pick (frame 17) #:y #:vy)))
  ;; k = 28: y = 112 + 406 − 420 = 98, vy 13.
  (test-equal "frame 30: falling" '(98 13 #f) (pick (frame 30) #:y #:vy #:on-ground?))
  (test-equal "frame 31: back at 112, touching" '(112 14 #t) (pick (frame 31) #:y #:vy #:on-ground?))
  (test-equal "frame 32: landed" '(112 0 #t) (pick (frame 32) #:y #:vy #:on-ground?))
  (test-equal "frame 34: resting" '(112 0 #t) (pick (frame 34) #:y #:vy #:on-ground?))
  (test-equal "frame 36: the second jump" '(98 -14) (pick (frame 36) #:y #:vy))
  (test-equal "x never moved" 32 (entity-ref (frame 36) #:x))
  (test-equal "play-sound 'jump recorded for each jump" '((2 . jump) (35 . jump)) (game-sounds game)))

;;; ================================================================ Top-down
;;; No gravity: #:gravity? #f. Right+down for 5 frames, left for 5, up for 5.
(define (top-down-game x script)
  (let-values (((render frame) (recorder)))
    (let ((cams '()))
      (values
       (make-game
        title: "top-down"
        scene: (make-scene entities: (list (list #:id 'player #:x x #:y 100 #:width 16 #:height 16
                                                 #:gravity? #f)))
        input-script: script
        render: (lambda (game)
                  (render game)
                  (set! cams (cons (camera-x (scene-camera (game-scene game))) cams)))
        update: (lambda (game dt)
                  (let* ((input (game-input game))
                         (scene (game-scene game))
                         (player (car (scene-entities scene)))
                         (dx (+ (if (input-held? input 'left) -3 0)
                                (if (input-held? input 'right) 3 0)))
                         (dy (+ (if (input-held? input 'up) -3 0)
                                (if (input-held? input 'down) 3 0)))
                         (player (entity-set (entity-set player #:vx dx) #:vy dy)))
                    ;; Camera follow still runs after update: in game-run!
                    (camera-x-set! (scene-camera scene)
                                   (max 0 (- (entity-ref player #:x 0) 300)))
                    (game-scene-set! game
                                     (update-scene scene entities: (list player))))))
       frame
       (lambda (k) (list-ref (reverse cams) k))))))
;; Frame k's physics applies the velocity update k − 1 set:
;; x: 400, +3 ×5 (frames 1..5) → 415, −3 ×5 (6..10) → 400.
;; y: 100, +3 ×5 → 115, 0 ×5, −3 ×5 (11..15) → 100.
(let-values (((game frame cam) (top-down-game 400 '((0 . (right down)) (5 . (left)) (10 . (up)) (15 . ())))))
  (game-run! game frames: 20)
  (test-equal "top-down: x per frame"
    '(400 403 406 409 412 415 412 409 406 403 400 400 400 400 400 400 400 400 400 400)
    (map (lambda (k) (entity-ref (frame k) #:x)) (iota 20)))
  (test-equal "top-down: y per frame (no gravity while dy = 0)"
    '(100 103 106 109 112 115 115 115 115 115 115 112 109 106 103 100 100 100 100 100)
    (map (lambda (k) (entity-ref (frame k) #:y)) (iota 20)))
  (test-equal "top-down: camera x = max(0, x − 300), set by update"
    '(100 103 106 109 112 115 112 109 106 103 100 100)
    (map cam (iota 12)))
  (test-equal "top-down: the final entity"
    '(#:id player #:x 400 #:y 100 #:width 16 #:height 16 #:gravity? #f #:vx 0 #:vy 0)
    (frame 19))
  (test-equal "top-down: no sound" '() (game-sounds game)))
(let-values (((game frame cam) (top-down-game 100 '((0 . (left up))))))
  (game-run! game frames: 4)
  (test-equal "top-down: camera clamped at 0" '(0 0 0 0) (map cam (iota 4)))
  (test-equal "top-down: diagonal" '(91 91) (pick (frame 3) #:x #:y)))

;;; ================================================================ Physics sandbox
(define (my-engine-update game dt)
  (let ((scene (game-scene game)))
    (when scene
      (game-scene-set! game
        (scene-transform-entities
          (scene-map-entities scene
            (lambda (e) (apply-gravity e scene dt))
            (lambda (e) (apply-velocity-x e scene dt))
            (lambda (e) (resolve-tile-collisions-x e scene dt))
            (lambda (e) (apply-velocity-y e scene dt))
            (lambda (e) (resolve-tile-collisions-y e scene dt))
            (lambda (e) (detect-on-solid e scene dt)))
          resolve-entity-collisions)))))

;; Floor rows 8 and 9 (top y 128). b rests on the floor; a falls onto b; c
;; falls alone. Frame n = the n-th engine pass.
;;  a: y = 80 + n(n+1)/2 until frame 6 (y 101, overlapping b [112, 128) by 5):
;;     push along y, a up ⌈5/2⌉ = 3 → 98 (vy −1), b down 2 → 114 (vy +1).
;;  7: a vy 0, y 98; b vy 2 → 116 → floor → 112, vy 0; overlap 2: a 97, b 113.
;;  8: a 97; b → 112; overlap 1: a −1 → 96 (vy −1), b +0 → 112 (vy +1).
;;  9: a vy 0, y 96; b 112 vy 0; touching: nothing.
;; 10: a vy 1 → 97; overlap 1 → a 96 vy −1, b 112 vy 1 — and so on: a rests at
;; 96 on b, b at 112 on the floor, vy alternating (0, 0) / (−1, +1).
;;  a is on the ground from frame 7: its feet at b's frame-start top, |vy − b.vy| ≤ 4.
;;  c: y = n(n+1)/2; frame 15: 120 → floor → 112, vy 0, on the ground.
(define sandbox-log '())
(define sandbox
  (make-game
   title: "sandbox"
   engine-update: my-engine-update
   scene: (make-scene
           tilemap: (floor-rows 10 10 8 9)
           entities: (list '(#:id a #:x 32 #:y 80 #:width 16 #:height 16 #:gravity? #t #:solid? #t)
                           '(#:id b #:x 32 #:y 112 #:width 16 #:height 16 #:gravity? #t #:solid? #t)
                           '(#:id c #:x 96 #:y 0 #:width 16 #:height 16 #:gravity? #t #:solid? #t)))
   render: (lambda (game) (set! sandbox-log (cons (scene-entities (game-scene game)) sandbox-log)))))
(game-run! sandbox frames: 31)
(define (box n id)                       ; entity ID after the n-th pass
  (find (lambda (e) (eq? (entity-ref e #:id) id)) (list-ref (reverse sandbox-log) (- n 1))))
(test-equal "a falls: frames 1..5" '(81 83 86 90 95) (map (lambda (n) (entity-ref (box n 'a) #:y)) (iota 5 1)))
(test-equal "b: on the floor at frame 1" '(112 0 #t) (pick (box 1 'b) #:y #:vy #:on-ground?))
(test-equal "a not supported at frame 5 (|vy 5 − 0| > 4)" #f (entity-ref (box 5 'a) #:on-ground?))
(test-equal "frame 6: pushed apart 3/2" '((98 -1) (114 1)) (list (pick (box 6 'a) #:y #:vy) (pick (box 6 'b) #:y #:vy)))
(test-equal "frame 7" '((97 -1 #t) (113 1)) (list (pick (box 7 'a) #:y #:vy #:on-ground?) (pick (box 7 'b) #:y #:vy)))
(test-equal "frame 8" '((96 -1) (112 1)) (list (pick (box 8 'a) #:y #:vy) (pick (box 8 'b) #:y #:vy)))
(test-equal "frame 9" '((96 0) (112 0)) (list (pick (box 9 'a) #:y #:vy) (pick (box 9 'b) #:y #:vy)))
(test-equal "frame 10" '((96 -1) (112 1)) (list (pick (box 10 'a) #:y #:vy) (pick (box 10 'b) #:y #:vy)))
(test-equal "frame 30: a rests on b, b on the floor" '((32 96 -1 #t) (32 112 1 #t))
  (list (pick (box 30 'a) #:x #:y #:vy #:on-ground?) (pick (box 30 'b) #:x #:y #:vy #:on-ground?)))
(test-equal "frame 31" '((96 0 #t) (112 0 #t))
  (list (pick (box 31 'a) #:y #:vy #:on-ground?) (pick (box 31 'b) #:y #:vy #:on-ground?)))
(test-equal "a's y from frame 8 on" (make-list 24 96) (map (lambda (n) (entity-ref (box n 'a) #:y)) (iota 24 8)))
(test-equal "c: frames 14, 15, 31" '((105 14 #f) (112 0 #t) (112 0 #t))
  (map (lambda (n) (pick (box n 'c) #:y #:vy #:on-ground?)) '(14 15 31)))

;;; ================================================================ Jumping (common pattern)
(define jump-game
  (make-game
   scene: (make-scene tilemap: platform-map entities: (list player0))
   input-script: '((1 . (a)) (2 . ()) (3 . (a)) (4 . ()))
   update: (lambda (game dt)
             (let* ((input (game-input game))
                    (scene (game-scene game))
                    (player (car (scene-entities scene))))
               (game-scene-set!
                game
                (update-scene
                 scene
                 entities:
                 (list
                  ;; In update: (after physics, #:on-ground? is current)
                  (let ((jump? (and (input-pressed? input 'a)
                                    (entity-ref player #:on-ground? #f))))
                    (if jump?
                        (entity-set player #:ay (- *jump-force*))
                        player)))))))))
(game-run! jump-game frames: 5)
;; Frame 1: on the ground, a pressed → #:ay −15. Frame 2: vy −14, y 98.
;; Frame 3: pressed in the air → nothing; vy −13, y 85. Frame 4: vy −12, y 73.
(test-equal "jumping: after 5 frames" '(73 -12 0 #f) (pick (car (scene-entities (game-scene jump-game)))
                                                         #:y #:vy #:ay #:on-ground?))

;;; ================================================================ Knockback
(define enemy '(#:id enemy #:x 100 #:y 112 #:width 16 #:height 16 #:gravity? #t #:vy 0 #:on-ground? #t))
(define knocked
  (entity-set enemy #:vx -5) ;; Push left
  )
(test-equal "knockback: #:vx appended" '(#:id enemy #:x 100 #:y 112 #:width 16 #:height 16 #:gravity? #t
                                         #:vy 0 #:on-ground? #t #:vx -5)
  knocked)
;; Through the default pipeline: x −5 a frame; gravity resumes each frame and
;; the floor holds: y 112, vy 0. Three frames: x = 85.
(define knock-scene
  (let loop ((i 0) (s (make-scene tilemap: platform-map entities: (list knocked))))
    (if (= i 3) s (loop (+ i 1) (step-scene s 16)))))
(test-equal "knockback: 3 frames later" '(85 112 -5 0 #t)
  (pick (car (scene-entities knock-scene)) #:x #:y #:vx #:vy #:on-ground?))

;;; ================================================================ aabb-overlap? (player / enemy)
(define damage 0)
(define (do-damage!) (set! damage (+ damage 1)))
(define (check player enemy)
  ;; Example: check if player overlaps enemy
  (if (aabb-overlap? (entity-ref player #:x 0) (entity-ref player #:y 0)
                     (entity-ref player #:width 0) (entity-ref player #:height 0)
                     (entity-ref enemy #:x 0) (entity-ref enemy #:y 0)
                     (entity-ref enemy #:width 0) (entity-ref enemy #:height 0))
      (do-damage!)))
(check '(#:x 0 #:y 0 #:width 16 #:height 16) '(#:x 10 #:y 10 #:width 16 #:height 16))
(test-equal "overlapping: damage" 1 damage)
(check '(#:x 0 #:y 0 #:width 16 #:height 16) '(#:x 16 #:y 0 #:width 16 #:height 16))
(test-equal "touching: no damage" 1 damage)
(check '(#:x 0 #:y 0 #:width 16 #:height 16) '(#:x 5 #:y 5))
;; The enemy's missing size reads 0: a point at (5, 5) strictly inside.
(test-equal "a point inside: damage (strict formula)" 2 damage)

;;; ================================================================ Trigger zones
;; The player walks right at 4 px/frame from x 60 through a 20 px zone at
;; x [100, 120). After frame k's physics, x = 64 + 4k; the boxes overlap while
;; 84 < x < 120: frames 6 (88) … 13 (116). Touching (84, 120) does not count.
(define entered '())
(define trigger-game
  (make-game
   scene: (make-scene entities: (list '(#:id player #:x 60 #:y 50 #:width 16 #:height 16 #:vx 4)
                                      '(#:id zone #:x 100 #:y 0 #:width 20 #:height 200)))
   update: (lambda (game dt)
             (let* ((scene (game-scene game))
                    (player (car (scene-entities scene)))
                    (trigger (cadr (scene-entities scene)))
                    (on-trigger-enter! (lambda (p) (set! entered (cons (list (game-frame game) (entity-ref p #:x))
                                                                      entered)))))
               ;; In update:
               (if (aabb-overlap? (entity-ref trigger #:x 0) (entity-ref trigger #:y 0)
                                  (entity-ref trigger #:width 0) (entity-ref trigger #:height 0)
                                  (entity-ref player #:x 0) (entity-ref player #:y 0)
                                  (entity-ref player #:width 0) (entity-ref player #:height 0))
                   (on-trigger-enter! player))))))
(game-run! trigger-game frames: 16)
(test-equal "trigger: frames and x inside the zone"
  '((6 88) (7 92) (8 96) (9 100) (10 104) (11 108) (12 112) (13 116))
  (reverse entered))
(test-equal "the zone is not solid: nothing pushed it" '(#:id zone #:x 100 #:y 0 #:width 20 #:height 200)
  (cadr (scene-entities (game-scene trigger-game))))

;;; ================================================================ resolve-entity-collisions on a scene
(define crowd (make-scene entities: (list '(#:x 0 #:y 0 #:width 10 #:height 10 #:solid? #t)
                                          '(#:x 7 #:y 0 #:width 10 #:height 10 #:solid? #t))))
(define pushed (scene-transform-entities crowd resolve-entity-collisions))
;; Overlap 3 along x: the first moves −⌈3/2⌉ = −2, the second +1; vx −1 / +1.
(test-equal "scene-transform-entities + resolve-entity-collisions"
  '((#:x -2 #:y 0 #:width 10 #:height 10 #:solid? #t #:vx -1)
    (#:x 8 #:y 0 #:width 10 #:height 10 #:solid? #t #:vx 1))
  (scene-entities pushed))
(test-equal "the original scene is not modified"
  '((#:x 0 #:y 0 #:width 10 #:height 10 #:solid? #t) (#:x 7 #:y 0 #:width 10 #:height 10 #:solid? #t))
  (scene-entities crowd))

;;; ================================================================ The signatures, as documented
(define scene (make-scene tilemap: platform-map
                          entities: '((#:id rock #:x 40 #:y 112 #:width 16 #:height 16 #:solid? #t))))
(define dt 16)
(define entity '(#:id me #:x 10 #:y 109 #:width 16 #:height 16 #:vx 2 #:vy 2 #:ay -3 #:gravity? #t))
(test-equal "(apply-acceleration entity scene dt)" '(-1 0)
  (pick (apply-acceleration entity scene dt) #:vy #:ay))
(test-equal "(apply-gravity entity scene dt)" 3 (entity-ref (apply-gravity entity scene dt) #:vy))
(test-equal "(apply-velocity-x entity scene dt)" 12 (entity-ref (apply-velocity-x entity scene dt) #:x))
(test-equal "(apply-velocity-y entity scene dt)" 111 (entity-ref (apply-velocity-y entity scene dt) #:y))
;; Tiles only: the box [10, 26) × [109, 125) spans rows 6..7, none solid → unchanged.
(test-eq "(resolve-tile-collisions-x entity scene dt)" entity (resolve-tile-collisions-x entity scene dt))
;; y 111 → [111, 127) rows 6..7: no floor yet; y 120 → rows 7..8 → 112.
(test-equal "(resolve-tile-collisions-y entity scene dt)" '(112 0)
  (pick (resolve-tile-collisions-y (entity-set entity #:y 120) scene dt) #:y #:vy))
;; Feet at 125: row 7 — no tile; the rock [40, 56) does not overlap [10, 26).
(test-equal "(detect-on-solid entity scene dt): not yet" #f
  (entity-ref (detect-on-solid entity scene dt) #:on-ground?))
;; At x 30, y 96 (feet 112 on the rock's top; |vy 2 − 0| ≤ 4): supported.
(test-equal "(detect-on-solid entity scene dt): on the rock" #t
  (entity-ref (detect-on-solid (entity-set (entity-set entity #:x 30) #:y 96) scene dt) #:on-ground?))

(test-end "seed-examples")
