;; SPDX-License-Identifier: 0BSD
;;; Top-down: four-way movement in a walled room (demo/maps/topdown.tmx).
;;;
;;; No gravity: the player has #:gravity? #f, so the default engine-update's
;;; acceleration, gravity and ground steps pass it by; 'up 'down 'left 'right
;;; set #:vx / #:vy and the tile collisions stop it at the walls. The player
;;; and the coins come from the map's object layer; walking over a coin
;;; (found with scene-query-rect) collects it. A guard patrols the bottom of
;;; the room and turns where a ray (scene-raycast) finds a wall just ahead;
;;; it is not solid and does the player no harm. The guard's walk and the
;;; coins' glints are #:animation lists, out of phase by #:animation-start.
;;;
;;; Keys (in a window): the arrows or WASD walk (diagonals too), Return
;;; starts again, Escape quits.
;;;
;;; Run: build/bin/downstroke demo/topdown.scm
;;; Headless: it plays the built-in input script for `demo-frames' frames and
;;; prints a line every 20 frames plus one per event.
;;; In a window (downstroke --window demo/topdown.scm) it runs until the
;;; player quits.
(use-modules (ice-9 format) (srfi srfi-1))
;;; The demos' shared looks and sounds: (demo looks), in demo/lib.
(add-to-load-path (canonicalize-path (string-append (dirname (current-filename)) "/lib")))
(use-modules (demo looks) (demo events))

(define room (load-tilemap (demo-file "maps/topdown.tmx")))

;;; ------------------------------------------------------------ looks and sounds
(define player-standing (sprite 0))
(define player-walking (sprite 1))
(define coin-picture (sprite 10))
;;; Animations, as (gid . ms) lists the renderer plays by the game's clock
;;; from each entity's #:animation-start: a guard's two-step walk, and a
;;; coin's glint (the picture mirrored for a moment, its highlight jumping
;;; across). Each coin starts its glint at its own frame, so they glint one
;;; after another, not all together.
(define guard-walk (list (cons (sprite 3) 128) (cons (sprite 4) 128)))
(define coin-glint (list (cons coin-picture 600) (cons (logior coin-picture #x80000000) 120)))
(define coin-phase 9)                   ; frames between two coins' glints: 5 coins × 9 = the 45-frame cycle

(load-demo-sounds! 'coin)
(load-demo-music!)

;;; Map objects → entities. Object ids are Tiled's numbers; the game names
;;; entities by symbols instead.
(define (object->entity o)
  (append (list #:id (string->symbol (entity-ref o #:name)) #:type (entity-ref o #:type)
                #:x (entity-ref o #:x) #:y (entity-ref o #:y)
                #:width (entity-ref o #:width) #:height (entity-ref o #:height))
          (if (entity-ref o #:value) (list #:value (entity-ref o #:value)) '())))

(define (objects-of-type type)
  (filter (lambda (o) (eq? (entity-ref o #:type) type)) (tilemap-objects room)))

(define player0
  (let ((spawn (car (objects-of-type 'player))))
    (append (object->entity spawn)
            (list #:speed (entity-ref spawn #:speed 3) #:vx 0 #:vy 0 #:gravity? #f #:score 0))))

(define coins0
  (map (lambda (o i) (entity-animate (object->entity o) coin-glint (- (* i coin-phase))))
       (objects-of-type 'coin) (iota (length (objects-of-type 'coin)))))

;;; The guard walks along rows 12–13, between the block and the bottom wall.
(define guard0
  (list #:id 'guard #:type 'guard #:x 100 #:y 196 #:width 12 #:height 12 #:vx 2 #:vy 0
        #:gravity? #f #:animation guard-walk))

(define (entities-of-type scene type)
  (filter (lambda (e) (eq? (entity-ref e #:type) type)) (scene-entities scene)))

;;; ------------------------------------------------------------ what happened
(define trace? (main-script? "topdown.scm"))   ; headless as the host's script: print as it goes

;;; What happened: (demo events).
(define events (make-events trace?))

(define (note-at! frame what) (note-event! events frame what))

(define (note! game what) (note-at! (game-frame game) what))

;;; ------------------------------------------------------------ the game
(define (axis-intent input minus plus speed)
  (+ (if (input-held? input minus) (- speed) 0) (if (input-held? input plus) speed 0)))

(define (fresh-run start-frame)
  "The scene's data for a run that starts at START-FRAME: what the run
remembers from frame to frame, so a rewind gives it back too."
  (list #:start-frame start-frame       ; the frame the run (re)started at
        #:last-intent '(0 . 0)          ; the (vx . vy) the player asked for last frame
        #:blocked '(#f . #f)))          ; whether a wall stopped it on x, on y last frame

(define (report-walls! game player run)
  "Whether a wall stops PLAYER on x, on y, as a pair: a velocity asked for
last frame (RUN's #:last-intent) that physics zeroed. Reported when that
starts."
  (let* ((vx (entity-ref player #:vx 0)) (vy (entity-ref player #:vy 0))
         (last-intent (entity-ref run #:last-intent))
         (blocked (entity-ref run #:blocked))
         (bx? (and (not (zero? (car last-intent))) (zero? vx)))
         (by? (and (not (zero? (cdr last-intent))) (zero? vy))))
    (when (and bx? (not (car blocked)))
      (note! game (list 'wall (if (positive? (car last-intent)) 'right 'left)
                        'x (entity-ref player #:x))))
    (when (and by? (not (cdr blocked)))
      (note! game (list 'wall (if (positive? (cdr last-intent)) 'down 'up)
                        'y (entity-ref player #:y))))
    (cons bx? by?)))

(define (dress player vx vy frame)
  "PLAYER with its picture: facing the way it last walked sideways
(#:flip-x? mirrors the right-facing sprite), a two-frame walk while moving."
  (let ((left? (cond ((negative? vx) #t)
                     ((positive? vx) #f)
                     (else (entity-ref player #:flip-x? #f)))))
    (entity-set (entity-set player #:flip-x? left?)
                #:sprite (if (and (or (not (zero? vx)) (not (zero? vy))) (even? (quotient frame 6)))
                             player-walking
                             player-standing))))

(define (restart! game)
  ;; Return in a window: the player back at its spawn point, every coin back.
  (game-scene-set! game (update-scene (game-scene game)
                                      entities: (cons (dress player0 0 0 0) (append coins0 (list guard0)))
                                      data: (fresh-run (+ (game-frame game) 1)))))

(define (update game dt)
  (theme-from-the-start game)
  (if (input-pressed? (game-input game) 'start)
      (restart! game)
      (play! game dt)))

(define (play! game dt)
  (let* ((input (game-input game))
         (scene (game-scene game))
         (player (car (scene-entities scene)))
         (coins (entities-of-type scene 'coin))
         (speed (entity-ref player #:speed 3))
         (vx (axis-intent input 'left 'right speed))
         (vy (axis-intent input 'up 'down speed))
         (taken (scene-query-rect scene (entity-ref player #:x) (entity-ref player #:y)
                                  (entity-ref player #:width) (entity-ref player #:height)
                                  '(#:type . coin)))
         ;; Walls first, then coins: the order the events are noted in.
         (blocked (report-walls! game player (scene-data scene))))
    (for-each (lambda (c)
                (play-sound 'coin)
                (note! game (list 'coin (entity-ref c #:id))))
              taken)
    (let* ((player (entity-set player #:score (fold + (entity-ref player #:score 0)
                                                     (map (lambda (c) (entity-ref c #:value 1)) taken))))
           (player (entity-set (entity-set player #:vx vx) #:vy vy))
           (player (dress player vx vy (game-frame game))))
      (game-scene-set! game (update-scene scene
                                          data: (list #:start-frame (entity-ref (scene-data scene) #:start-frame)
                                                      #:last-intent (cons vx vy) #:blocked blocked)
                                          entities:
                                          (cons player (append (remove (lambda (c) (memq c taken)) coins)
                                                               (map (lambda (g) (patrol game scene g))
                                                                    (entities-of-type scene 'guard)))))))))

(define guard-sight 8)                  ; px past its front edge a guard looks for a wall

(define (patrol game scene guard)
  ;; A ray from the middle of the guard's front edge, against the walls only
  ;; (no entity is chosen), finds a wall within guard-sight: turn round.
  (let* ((vx (entity-ref guard #:vx)) (x (entity-ref guard #:x)) (w (entity-ref guard #:width))
         (front (if (positive? vx) (+ x w) x))
         (eye-y (+ (entity-ref guard #:y) (quotient (entity-ref guard #:height) 2)))
         (wall (scene-raycast scene front eye-y (+ front (if (positive? vx) guard-sight (- guard-sight))) eye-y
                              (lambda (e) #f)))
         (vx (if wall (- vx) vx)))
    (when wall (note! game (list 'turn (entity-ref guard #:id) 'x x)))
    (entity-set (entity-set guard #:vx vx) #:flip-x? (negative? vx))))


(define (draw-hud! game)
  ;; The entities are drawn by the engine: the player from its #:sprite, the
  ;; coins and the guard from their #:animation.
  (let* ((entities (scene-entities (game-scene game)))
         (left (length (entities-of-type (game-scene game) 'coin)))
         (total (length coins0))
         (width (game-width game)))
    (draw-label (format #f "SCORE ~a" (entity-ref (car entities) #:score 0)) 4 4 'white)
    (let ((coins (format #f "COINS ~a/~a" (- total left) total)))
      (draw-label coins (- width 4 (text-width coins)) 4 'yellow))
    (cond ((zero? left)
           (draw-label "ALL COINS!" (centred-x "ALL COINS!" width scale: 3) 90 'yellow scale: 3)
           (draw-label "RETURN: PLAY AGAIN" (centred-x "RETURN: PLAY AGAIN" width) 120 'white))
          ((< (- (game-frame game) (entity-ref (scene-data (game-scene game)) #:start-frame)) 240)   ; the first 4 s: how to play
           (draw-label "ARROWS WALK - PICK UP EVERY COIN" (centred-x "ARROWS WALK - PICK UP EVERY COIN" width) (- (game-height game) 12) 'white)))))

(define (render game)
  ;; Draws the HUD (when the game has a display) and, headless, prints a
  ;; line every 20 frames.
  (when (current-display) (draw-hud! game))
  (let ((frame (game-frame game))
        (entities (scene-entities (game-scene game))))
    (when (and trace? (zero? (modulo frame 20)))
      (let ((p (car entities)))
        (format #t "frame ~3d: player (~a, ~a) v (~a, ~a)  score ~a  coins left ~a~%"
                frame (entity-ref p #:x) (entity-ref p #:y) (entity-ref p #:vx) (entity-ref p #:vy)
                (entity-ref p #:score) (length (entities-of-type (game-scene game) 'coin)))))))

;;; Built-in input: right to the inner wall, down to the bottom wall, left,
;;; up, then diagonally into the room, right under the inner wall to the
;;; east wall, and up.
(define input-script
  '((0 . (right))
    (45 . ())
    (50 . (down))
    (115 . ())
    (120 . (left))
    (170 . ())
    (175 . (up))
    (245 . ())
    (250 . (down right))
    (294 . (right))
    (350 . (up))
    (400 . ())))

(define demo-frames 420)

(define game
  (make-game title: "Downstroke — top-down" width: 320 height: 240 frame-delay: 16
             scene: (make-scene entities: (cons player0 (append coins0 (list guard0))) tilemap: room
                                camera-target: 'player data: (fresh-run 0))
             update: update render: render
             input-script: input-script))

(define (run! frames)
  "Run the game up to frame FRAMES (it counts from where it stopped)."
  (game-run! game frames: frames))

(when (main-script? "topdown.scm")
  ;; Headless or capturing: the scripted demo; in a window: until the player quits.
  (run! (script-number-argument 0 (if (eq? (display-mode) 'window) #f demo-frames)))
  (format #t "score: ~a, sounds: ~s~%" (entity-ref (car (scene-entities (game-scene game))) #:score)
          (game-sounds game)))
