;; SPDX-License-Identifier: 0BSD
;;; Shmup: who hits whom is decided by categories (physics.org, "Who
;;; collides with whom").
;;;
;;; Everything moves by its velocity in the engine's frame. The ship is
;;; steered by thrust ('left / 'right held add to its #:vx); its #:drag
;;; slows it to a stop when nothing is held and its #:max-vx is its top
;;; speed (physics.org, "apply-speed-limits"): it speeds up 1, 2, 3 px a
;;; frame and glides 2, 1 after a release, in exact integers.
;;; Pressing 'a fires a bullet. A bullet is a sensor in the category bullet
;;; that collides only with enemies; an enemy, in the category enemy,
;;; collides only with bullets. So the frame itself finds each bullet that
;;; overlaps an enemy (the scene's contacts), nothing is pushed, and bullets
;;; pass through the ship and each other. The update hook removes both and
;;; scores the enemy's #:points.
;;;
;;; The scene's map, demo/maps/shmup.tmx, has no tiles at all: it is there
;;; for its tilesets, which the entities' #:sprite gids refer to. The stars
;;; are drawn by render.
;;;
;;; Keys (in a window): Left/Right or A/D steer, Z or Space fires (one shot
;;; a press), Return starts a new game, Escape quits.
;;;
;;; Run: build/bin/downstroke demo/shmup.scm
;;; Headless: it plays the built-in input script for `demo-frames' frames and
;;; prints a line every 20 frames plus one per event.
;;; In a window (downstroke --window demo/shmup.scm) it runs until the
;;; player quits.
(use-modules (ice-9 format) (srfi srfi-1))
;;; The demos' shared looks and sounds: (demo looks), in demo/lib.
(add-to-load-path (canonicalize-path (string-append (dirname (current-filename)) "/lib")))
(use-modules (demo looks) (demo events))

;;; ------------------------------------------------------------ looks and sounds
;;; No solid tile, no camera-target: the map changes nothing but what gids mean.
(define backdrop (load-tilemap (demo-file "maps/shmup.tmx")))
(define ship-picture (sprite 5))
(define enemy-picture (sprite 6))
(define enemy-flap-picture (sprite 7))
(define bullet-picture (sprite 8))
(define explosion-picture (sprite 15))

(load-demo-sounds! 'shot 'boom)
(load-demo-music!)

(define screen-width 320)
(define screen-height 240)
(define ship-thrust 2)                  ; px/frame² while a direction is held
(define bullet-speed 6)

(define ship0
  (list #:id 'ship #:kind 'ship #:x 154 #:y 216 #:width 12 #:height 12 #:score 0
        #:vx 0 #:drag 1 #:max-vx 3
        #:category 'ship #:sprite ship-picture))

;;; Enemies are solid, so bullets sense them, and immovable, so nothing a
;;; bullet does moves them; they collide only with bullets.
(define (enemy row col)
  (list #:id (string->symbol (format #f "enemy-~a-~a" row col)) #:kind 'enemy
        #:x (+ 40 (* 48 col)) #:y (+ 40 (* 24 row)) #:width 16 #:height 12
        #:vx 1 #:vy 0 #:points (if (= row 0) 200 100) #:sprite enemy-picture
        #:solid? #t #:immovable? #t #:category 'enemy #:collides-with '(bullet)))

(define enemies0
  (append-map (lambda (row) (map (lambda (col) (enemy row col)) (iota 5))) (iota 2)))

;;; ------------------------------------------------------------ what happened
(define trace? (main-script? "shmup.scm"))   ; headless as the host's script: print as it goes

;;; What happened: (demo events).
(define events (make-events trace?))

(define (note-at! frame what) (note-event! events frame what))

(define (note! game what) (note-at! (game-frame game) what))

(define (kind-of k) (lambda (e) (eq? (entity-ref e #:kind) k)))

;;; ------------------------------------------------------------ the game
(define (steer-ship input ship)
  ;; The frame has moved the ship: kept on the screen (stopped at an edge),
  ;; it takes this frame's thrust, which the next frame's drag and top speed
  ;; temper.
  (let* ((x (entity-ref ship #:x))
         (right-edge (- screen-width (entity-ref ship #:width)))
         (kept (max 0 (min x right-edge)))
         (vx (if (= kept x) (entity-ref ship #:vx) 0))
         (thrust (+ (if (input-held? input 'left) (- ship-thrust) 0)
                    (if (input-held? input 'right) ship-thrust 0))))
    (entity-set (entity-set ship #:x kept) #:vx (+ vx thrust))))

(define (bullet-from ship k)
  "The K-th bullet fired, from SHIP."
  (list #:id (string->symbol (format #f "bullet-~a" k)) #:kind 'bullet
        #:x (+ (entity-ref ship #:x) 5) #:y (- (entity-ref ship #:y) 6) #:width 2 #:height 6
        #:vx 0 #:vy (- bullet-speed) #:sprite bullet-picture
        #:sensor? #t #:category 'bullet #:collides-with '(enemy)))

(define (turn-formation enemies)
  ;; The formation turns round as one when any of it reaches a screen edge.
  (if (any (lambda (e) (let ((x (entity-ref e #:x)) (vx (entity-ref e #:vx)))
                         (or (and (negative? vx) (<= x 8))
                             (and (positive? vx) (>= (+ x (entity-ref e #:width)) (- screen-width 8))))))
           enemies)
      (map (lambda (e) (entity-set e #:vx (- (entity-ref e #:vx)))) enemies)
      enemies))

;;; What the game remembers besides its entities is the scene's data, so a
;;; rewind gives it back: the bullets fired so far (across restarts, so
;;; each bullet's #:id is new) and the explosions. Explosions are only
;;; drawn: (x y until-frame) of each enemy shot down, newest first, kept out
;;; of the entities so they touch nothing.
(define data0 (list #:shots 0 #:explosions '()))
(define explosion-frames 12)

(define (explosions-of game) (entity-ref (scene-data (game-scene game)) #:explosions))

(define (flap enemies frame)
  ;; The formation beats its wings together, every 8 frames.
  (let ((picture (if (even? (quotient frame 8)) enemy-picture enemy-flap-picture)))
    (map (lambda (e) (entity-set e #:sprite picture)) enemies)))

(define (restart! game)
  ;; Return in a window: a new game, the ship and the whole formation back.
  (let ((scene (game-scene game)))
    (game-scene-set! game (update-scene scene entities: (cons ship0 enemies0)
                                        data: (entity-set (scene-data scene) #:explosions '())))))

(define (update game dt)
  (theme-from-the-start game)
  ;; An explosion whose time is up is gone.
  (let ((scene (game-scene game)))
    (game-scene-set! game (update-scene scene data: (entity-set (scene-data scene) #:explosions
                                                                (filter (lambda (x) (> (caddr x) (game-frame game)))
                                                                        (explosions-of game))))))
  (if (input-pressed? (game-input game) 'start)
      (restart! game)
      (play! game dt)))

(define (by-id entities)
  (lambda (id) (find (lambda (e) (eq? (entity-ref e #:id) id)) entities)))

(define (play! game dt)
  ;; The engine's frame has moved everything by its velocity and found the
  ;; (enemy . bullet) pairs that overlap: the scene's contacts.
  (let* ((input (game-input game))
         (scene (game-scene game))
         (entities (scene-entities scene))
         (named (by-id entities))
         (ship (steer-ship input (find (kind-of 'ship) entities)))
         (fire? (input-pressed? input 'a))
         (shots (+ (entity-ref (scene-data scene) #:shots) (if fire? 1 0)))
         (new-bullets (if fire? (list (bullet-from ship shots)) '()))
         ;; A new bullet starts where it was fired; the frame moves it next.
         (bullets (append (filter (kind-of 'bullet) entities) new-bullets))
         (enemies (flap (turn-formation (filter (kind-of 'enemy) entities)) (game-frame game))))
    (when fire?
      (play-sound 'shot)
      (note! game (list 'fired (entity-ref (car new-bullets) #:id) 'x (entity-ref (car new-bullets) #:x))))
    ;; Each enemy is taken by the first bullet it met that no other enemy
    ;; took: the pairs come in list order, enemies before bullets.
    (let loop ((pairs (map (lambda (p) (cons (named (cdr p)) (named (car p)))) (scene-contacts scene)))
               (spent '()) (hit '()) (score (entity-ref ship #:score))
               (explosions (explosions-of game)))
      (cond
       ((null? pairs)
        (let ((kept (remove (lambda (b) (or (memq b spent) (<= (+ (entity-ref b #:y) (entity-ref b #:height)) 0)))
                            bullets)))
          (game-scene-set! game (update-scene scene data: (list #:shots shots #:explosions explosions)
                                              entities:
                                              (cons (entity-set ship #:score score)
                                                    (append (remove (lambda (e) (memq (entity-ref e #:id) hit))
                                                                    enemies)
                                                            kept))))))
       ((or (memq (caar pairs) spent) (memq (entity-ref (cdar pairs) #:id) hit))
        (loop (cdr pairs) spent hit score explosions))
       (else
        (let ((bullet (caar pairs)) (enemy (cdar pairs)))
          (play-sound 'boom)
          (note! game (list 'hit (entity-ref enemy #:id) 'by (entity-ref bullet #:id)))
          (loop (cdr pairs) (cons bullet spent) (cons (entity-ref enemy #:id) hit)
                (+ score (entity-ref enemy #:points))
                (cons (list (entity-ref enemy #:x) (entity-ref enemy #:y) (+ (game-frame game) explosion-frames))
                      explosions))))))))


;;; Stars: fixed columns, drifting down at three speeds (half, one and one
;;; and a half pixels a frame), the faster the brighter.
(define star-count 48)
(define star-colors '#((70 78 110) (120 130 165) (210 215 235)))

(define (behind-sprite? x y entities)
  ;; Whether (X, Y) is inside an entity's 16×16 picture (centred on its box,
  ;; bottom-aligned): a star is drawn over the sprites, so it skips those.
  (any (lambda (e)
         (let ((left (+ (entity-ref e #:x) (quotient (- (entity-ref e #:width) 16) 2)))
               (top (- (+ (entity-ref e #:y) (entity-ref e #:height)) 16)))
           (and (<= left x (+ left 15)) (<= top y (+ top 15)))))
       entities))

(define (draw-stars! frame entities)
  (for-each (lambda (i)
              (let* ((speed (modulo i 3))
                     (x (modulo (+ 13 (* i 97)) screen-width))
                     (y (modulo (+ (* i 61) (quotient (* frame (+ speed 1)) 2)) screen-height)))
                (unless (behind-sprite? x y entities)
                  (draw-rect x y 1 1 (vector-ref star-colors speed) fill?: #t))))
            (iota star-count)))

(define (draw! game)
  ;; The ship, the enemies and the bullets are drawn by the engine from
  ;; their #:sprite; the stars, the explosions and the HUD here.
  (let* ((frame (game-frame game))
         (entities (scene-entities (game-scene game)))
         (ship (find (kind-of 'ship) entities))
         (left (count (kind-of 'enemy) entities)))
    (draw-stars! frame entities)
    (for-each (lambda (x) (draw-sprite explosion-picture (car x) (- (cadr x) 4))) (explosions-of game))
    (draw-label (format #f "SCORE ~a" (entity-ref ship #:score)) 4 4 'white)
    (let ((enemies (format #f "ENEMIES ~a" left)))
      (draw-label enemies (- screen-width 4 (text-width enemies)) 4 'green))
    (cond ((zero? left)
           (draw-label "WAVE CLEARED!" (centred-x "WAVE CLEARED!" screen-width scale: 2) 90 'yellow scale: 2)
           (draw-label "RETURN: PLAY AGAIN" (centred-x "RETURN: PLAY AGAIN" screen-width) 116 'white))
          ((< frame 240)                ; the first 4 s: how to play
           (draw-label "ARROWS MOVE   Z FIRE" (centred-x "ARROWS MOVE   Z FIRE" screen-width) 4 'white)))))

(define (render game)
  ;; Draws the stars, explosions and HUD (when the game has a display),
  ;; and, headless, prints a line every 20 frames.
  (when (current-display) (draw! game))
  (let ((frame (game-frame game))
        (entities (scene-entities (game-scene game))))
    (when (and trace? (zero? (modulo frame 20)))
      (let ((ship (find (kind-of 'ship) entities)))
        (format #t "frame ~3d: ship x ~a  enemies ~a (first at ~a)  bullets ~a  score ~a~%"
                frame (entity-ref ship #:x) (count (kind-of 'enemy) entities)
                (let ((e (find (kind-of 'enemy) entities))) (and e (entity-ref e #:x)))
                (count (kind-of 'bullet) entities) (entity-ref ship #:score))))))

;;; Built-in input: a press needs a release first. Seven shots: five hits
;;; (rows 1 and 0 of column 2, 1, then 1 again...) and two misses that fly
;;; through gaps of the formation and off the top of the screen.
(define input-script
  '((0 . (a)) (1 . ())           ; hits enemy-1-2
    (10 . (a)) (11 . ())         ; misses: through a gap
    (30 . (a)) (31 . ())         ; hits enemy-1-1
    (36 . (a)) (37 . ())         ; passes where enemy-1-1 was, hits enemy-0-1
    (60 . (left))
    (80 . (left a)) (81 . (left)) ; misses
    (100 . ())
    (120 . (right))
    (150 . (right a)) (151 . (right)) ; hits enemy-0-2
    (170 . ())
    (172 . (a)) (173 . ())))     ; hits enemy-1-3

(define demo-frames 240)

(define game
  (make-game title: "Downstroke — shmup" width: screen-width height: screen-height frame-delay: 16
             scene: (make-scene entities: (cons ship0 enemies0) tilemap: backdrop data: data0)
             update: update render: render
             input-script: input-script))

(define (run! frames)
  "Run the game up to frame FRAMES (it counts from where it stopped)."
  (game-run! game frames: frames))

(when (main-script? "shmup.scm")
  ;; Headless or capturing: the scripted demo; in a window: until the player quits.
  (run! (script-number-argument 0 (if (eq? (display-mode) 'window) #f demo-frames)))
  (format #t "score: ~a, shots: ~a, sounds: ~s~%"
          (entity-ref (car (scene-entities (game-scene game))) #:score)
          (entity-ref (scene-data (game-scene game)) #:shots) (game-sounds game)))
