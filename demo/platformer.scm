;; SPDX-License-Identifier: 0BSD
;;; Platformer: a side-scroller on demo/maps/platformer.tmx.
;;;
;;; The player (spawned from the map's object layer) falls in, lands, runs
;;; with 'left / 'right held, and jumps when 'a is pressed while
;;; #:on-ground? — the jump is game logic: #:ay set to (- *jump-force*), which
;;; the next frame's apply-acceleration consumes. Physics is the default
;;; engine-update; the camera follows the player (camera-target: 'player).
;;; Reaching the goal object of the map plays 'goal, and coins on the way
;;; are picked up: the goal and the coins are sensors that collide only with
;;; the player (category player), so the frame itself reports when the
;;; player enters them (scene-contacts) and they never push it.
;;;
;;; Beyond the first pit: a one-way plank (tiles with the tileset property
;;; one-way) that the player jumps up through and lands on, and drops down
;;; from with Down held (#:drop-through?); blocks that break when the
;;; player's head hits them from below (the player has #:contacts? #t, so its
;;; #:blocked holds up; tilemap-set-tile, and the scene takes the new map);
;;; and a lift (the map's "lift" object: an immovable solid
;;; with #:carries? #t, moving by #:vx and turned at the ends of its run by
;;; the game) that carries the player over a pit too wide to jump (its
;;; #:standing-on names the lift). In that pit a walker paces: fall on it
;;; and it is stomped (the player has #:contacts? 'sides, so each entry of
;;; its #:touching says which side met the other: down is a stomp), and the
;;; player bounces off; touch it any other way and the run starts again.
;;; The scripted run rides over it.
;;;
;;; What the run remembers from frame to frame is the scene's data
;;; (scene-data): the coins picked up, when the run started and reached the
;;; goal, and what the player did last frame. So a rewind (game-rewind!,
;;; history: 600) gives all of it back as it was at the frame it goes to,
;;; with the coins themselves.
;;;
;;; Keys (in a window): Left/Right or A/D run, Z or Space jumps, Down or S
;;; drops through a plank, P pauses and goes on (the paused: hook), Return
;;; starts again, Escape quits.
;;;
;;; Run: build/bin/downstroke demo/platformer.scm
;;; Headless: it plays the built-in input script below for `demo-frames'
;;; frames and prints a line every 20 frames plus one per event.
;;; In a window (downstroke --window demo/platformer.scm) it runs until the
;;; player quits.
;;; Loaded from elsewhere (tests/scheme/demos-test.scm) it only defines
;;; `game', `run!', `events' and friends.
(use-modules (ice-9 format) (srfi srfi-1))
;;; The demos' shared looks and sounds: (demo looks), in demo/lib.
(add-to-load-path (canonicalize-path (string-append (dirname (current-filename)) "/lib")))
(use-modules (demo looks) (demo events))

(define level (load-tilemap (demo-file "maps/platformer.tmx")))

;;; ------------------------------------------------------------ looks and sounds
(define player-standing (sprite 0))
(define player-running (sprite 1))
(define player-jumping (sprite 2))
(define walker-picture (sprite 3))
(define goal-flag (sprite 11))
(define coin-picture (sprite 10))
(define lift-piece (sprite 12))         ; a 16×8 piece, in the bottom half of its 16×16 frame
(define breakable-gid 22)               ; level-tiles.tsx's tile 1 (make_maps.py)

(load-demo-sounds! 'jump 'goal 'boom 'coin)
(load-demo-music!)

(define (map-object name)
  (or (find (lambda (o) (equal? (entity-ref o #:name) name)) (tilemap-objects level))
      (error "platformer.tmx has no object named" name)))

(define *run-speed* 3)
(define goal (map-object "goal"))

(define player0
  (let ((spawn (map-object "player")))
    (list #:id 'player #:x (entity-ref spawn #:x) #:y (entity-ref spawn #:y)
          #:width (entity-ref spawn #:width) #:height (entity-ref spawn #:height)
          #:vx 0 #:vy 0 #:gravity? #t #:on-ground? #f
          ;; Solid so that the lift's push-apart and carrying take it along,
          ;; and the sensors notice it; the contact report tells the game
          ;; what it hit and stands on, and on which side it met the walker.
          #:solid? #t #:contacts? 'sides #:category 'player)))

;;; The goal and the coins notice the player and nothing else.
(define goal0
  (list #:id 'goal #:x (entity-ref goal #:x) #:y (entity-ref goal #:y)
        #:width (entity-ref goal #:width) #:height (entity-ref goal #:height)
        #:sensor? #t #:collides-with '(player)))

(define (coin k x y)
  (list #:id (string->symbol (format #f "coin-~a" k)) #:kind 'coin #:x x #:y y #:width 8 #:height 8
        #:sensor? #t #:collides-with '(player) #:sprite coin-picture))

;;; On the ground, the two platforms and the hill's top; the last hangs over
;;; the lift's run, out of the scripted run's reach.
(define coins0 (list (coin 1 100 164) (coin 2 200 116) (coin 3 300 68) (coin 4 750 132) (coin 5 1300 100)))

(define lift0
  (let ((spawn (map-object "lift")))
    (list #:id 'lift #:x (entity-ref spawn #:x) #:y (entity-ref spawn #:y)
          #:width (entity-ref spawn #:width) #:height (entity-ref spawn #:height)
          #:vx (entity-ref spawn #:speed) #:vy 0
          #:solid? #t #:immovable? #t #:carries? #t)))

(define lift-from-x (entity-ref lift0 #:x))

;;; The walker paces the floor of the pit under the lift's run (row 14's
;;; top, y 224), turning where a wall stops it (its #:blocked).
(define walker0
  (list #:id 'walker #:x 1320 #:y 210 #:width 12 #:height 14 #:vx -1 #:vy 0
        #:gravity? #t #:solid? #t #:contacts? #t #:sprite walker-picture))
(define *walker-speed* 1)
(define *stomp-bounce* 8)               ; px/frame up off a stomped walker
(define lift-to-x (entity-ref (map-object "lift") #:to-x))

;;; ------------------------------------------------------------ what happened
(define trace? (main-script? "platformer.scm"))   ; headless as the host's script: print as it goes

;;; What happened: (demo events).
(define events (make-events trace?))

(define (note-at! frame what) (note-event! events frame what))

(define (note! game what) (note-at! (game-frame game) what))

;;; ------------------------------------------------------------ the game
(define (fresh-run start-frame)
  "The scene's data for a run that starts at START-FRAME: a plist."
  (list #:coins 0                       ; picked up so far
        #:start-frame start-frame       ; the frame the run (re)started at
        #:goal-frame #f                 ; the frame the goal was reached at, once it is
        ;; Last frame's: whether the player stood, was pushing against a
        ;; wall, the #:vx it asked for and the #:id of what it stood on.
        #:was-on-ground? #f #:was-blocked? #f #:last-wanted 0 #:was-standing-on #f))

(define (run-ref game key)
  "KEY of the run GAME's scene holds (fresh-run)."
  (entity-ref (scene-data (game-scene game)) key))

(define (dress player wanted on-ground? frame)
  "PLAYER with its picture: facing the way it last ran (#:flip-x? mirrors the
right-facing sprite), the jump frame in the air, a two-frame run cycle while
running on the ground."
  (let ((left? (cond ((negative? wanted) #t)
                     ((positive? wanted) #f)
                     (else (entity-ref player #:flip-x? #f)))))
    (entity-set (entity-set player #:flip-x? left?)
                #:sprite (cond ((not on-ground?) player-jumping)
                               ((zero? wanted) player-standing)
                               ((even? (quotient frame 6)) player-running)
                               (else player-standing)))))

(define (restart! game)
  ;; Return in a window: the player back at the spawn point, the clock at 0.
  (game-scene-set! game (update-scene (game-scene game) entities: (start-entities) tilemap: level
                                      data: (fresh-run (+ (game-frame game) 1)))))

(define (start-entities) (cons* (dress player0 0 #f 0) lift0 goal0 (append coins0 (list walker0))))

(define (walker-sides player)
  "The sides of PLAYER that met the walker this frame (its #:touching
entries (name . side), #:contacts? 'sides)."
  (filter-map (lambda (entry) (and (pair? entry) (eq? (car entry) 'walker) (cdr entry)))
              (entity-ref player #:touching '())))

(define (steer-walker walker)
  ;; Turned by a wall it ran into this frame (the tile step stopped it).
  (let ((blocked (entity-ref walker #:blocked '())))
    (cond ((memq 'left blocked) (entity-set walker #:vx *walker-speed*))
          ((memq 'right blocked) (entity-set walker #:vx (- *walker-speed*)))
          (else walker))))

(define (entered scene)
  "The names of the sensors the player entered this frame: the scene's
contacts name it with each sensor it overlaps, the sensor first or last
as they stand in the list."
  (filter-map (lambda (pair)
                (cond ((eq? (car pair) 'player) (cdr pair))
                      ((eq? (cdr pair) 'player) (car pair))
                      (else #f)))
              (scene-contacts scene)))

(define (steer-lift lift)
  ;; Back and forth between the ends of its run: physics moved it this frame,
  ;; so the speed set here is the next frame's.
  (let ((x (entity-ref lift #:x)) (speed (abs (entity-ref lift #:vx))))
    (cond ((>= x lift-to-x) (entity-set lift #:vx (- speed)))
          ((<= x lift-from-x) (entity-set lift #:vx speed))
          (else lift))))

(define (cell-index v)
  "A cell index from a coordinate over a tile size: an exact integer even
when the coordinate is a flonum, as a y is after a 1:2 ramp walked at an
odd speed (its half pixels are flonums)."
  (inexact->exact (floor v)))

(define (cells-above-head player tiles)
  "The (col . row) cells of the row just above PLAYER's head that its box
spans, on the map TILES."
  (let* ((tw (tilemap-tile-width tiles)) (th (tilemap-tile-height tiles))
         (x (entity-ref player #:x)) (w (entity-ref player #:width))
         (row (cell-index (/ (- (entity-ref player #:y) 1) th)))
         (first (cell-index (/ x tw))))
    (map (lambda (col) (cons col row))
         (iota (- (inexact->exact (ceiling (/ (+ x w) tw))) first) first))))

(define (break-blocks tiles cells)
  "(map . count): the map TILES with each breakable block among CELLS
removed, and how many there were."
  (fold (lambda (cell acc)
          (let ((m (car acc)) (col (car cell)) (row (cdr cell)))
            (if (and (< -1 col (tilemap-width m)) (< -1 row (tilemap-height m))
                     (= (tilemap-gid m 0 col row) breakable-gid))
                (cons (tilemap-set-tile m col row 0) (+ (cdr acc) 1))
                acc)))
        (cons tiles 0) cells))

(define (update game dt)
  (theme-from-the-start game)
  (let ((sides (walker-sides (car (scene-entities (game-scene game))))))
    (cond ((input-pressed? (game-input game) 'start) (restart! game))
          ;; Paused after this frame: the next ticks call paused-update.
          ((input-pressed? (game-input game) 'pause) (game-paused-set! game #t) (note! game 'paused))
          ;; Met on any side but its feet: the walker got the player.
          ((any (lambda (side) (not (eq? side 'down))) sides)
           (note! game 'hurt)
           (restart! game))
          (else (play! game dt)))))

(define (paused-update game dt)
  ;; Nothing steps while paused: only P, to go on from the frame it stood at.
  (when (input-pressed? (game-input game) 'pause)
    (game-paused-set! game #f)
    (note! game 'resumed)))

(define (entity-find entities id)
  (find (lambda (e) (eq? (entity-ref e #:id) id)) entities))

(define (coin-name? name) (string-prefix? "coin-" (symbol->string name)))

(define (play! game dt)
  ;; Physics has already run this frame: #:on-ground? and #:x are resolved,
  ;; and the sensors the player overlaps are in the scene's contacts.
  (let* ((input (game-input game))
         (scene (game-scene game))
         (run (scene-data scene))
         (player (car (scene-entities scene)))
         (lift (entity-find (scene-entities scene) 'lift))
         (touched (entered scene))
         (picked (filter coin-name? touched))
         ;; Landed on the walker: its down side met it.
         (stomp? (memq 'down (walker-sides player)))
         (on-ground? (entity-ref player #:on-ground? #f))
         (wanted (cond ((input-held? input 'left) (- *run-speed*))
                       ((input-held? input 'right) *run-speed*)
                       (else 0)))
         ;; The contact report (#:contacts? #t): the sides a tile stopped the
         ;; player on this frame, and the entity it stands on.
         (blocked (entity-ref player #:blocked '()))
         (standing-on (entity-ref player #:standing-on #f))
         ;; Pushing against a wall: running, and stopped along x.
         (blocked? (and (not (zero? (entity-ref run #:last-wanted))) (or (memq 'left blocked) (memq 'right blocked)) #t))
         (jump? (and (input-pressed? input 'a) on-ground?))
         (head-hit? (memq 'up blocked))
         (goal? (memq 'goal touched))
         (broken (if head-hit?
                     (break-blocks (scene-tilemap scene) (cells-above-head player (scene-tilemap scene)))
                     (cons (scene-tilemap scene) 0))))
    (when (positive? (cdr broken))
      (play-sound 'boom)
      (note! game 'broke))
    (when (and on-ground? (not (entity-ref run #:was-on-ground?))) (note! game 'landed))
    (when (and blocked? (not (entity-ref run #:was-blocked?))) (note! game 'bumped))
    (when (and (eq? standing-on 'lift) (not (eq? (entity-ref run #:was-standing-on) 'lift)))
      (note! game 'boarded))
    (for-each (lambda (name)
                (play-sound 'coin)
                (note! game (list 'coin name)))
              picked)
    (when stomp?
      (play-sound 'boom)
      (note! game 'stomped))
    (when (and goal? (not (entity-ref run #:goal-frame)))
      (play-sound 'goal)
      (note! game 'goal))
    (when jump?
      (play-sound 'jump)
      (note! game 'jumped))
    (let* ((player (entity-set player #:vx wanted))
           (player (if jump? (entity-set player #:ay (- *jump-force*)) player))
           (player (if stomp? (entity-set player #:vy (- *stomp-bounce*)) player))
           (player (if (or (input-held? input 'down) (entity-ref player #:drop-through? #f))
                       (entity-set player #:drop-through? (input-held? input 'down))
                       player))
           (player (dress player wanted on-ground? (game-frame game))))
      (game-scene-set! game (update-scene scene entities:
                                          (cons* player (steer-lift lift)
                                                 (filter-map
                                                  (lambda (e)
                                                    (let ((id (entity-ref e #:id)))
                                                      (cond ((memq id picked) #f)
                                                            ((eq? id 'walker) (and (not stomp?) (steer-walker e)))
                                                            (else e))))
                                                  (cddr (scene-entities scene))))
                                          tilemap: (car broken)
                                          data: (let* ((run (entity-set run #:coins (+ (entity-ref run #:coins)
                                                                                       (length picked))))
                                                       (run (if (and goal? (not (entity-ref run #:goal-frame)))
                                                                (entity-set run #:goal-frame (game-frame game))
                                                                run))
                                                       (run (entity-set run #:was-on-ground? on-ground?))
                                                       (run (entity-set run #:was-blocked? blocked?))
                                                       (run (entity-set run #:last-wanted wanted)))
                                                  (entity-set run #:was-standing-on standing-on)))))))

(define (draw! game)
  ;; The goal flag (a map object, not an entity) and the HUD; the player is
  ;; drawn by the engine from its #:sprite.
  (let* ((frame (game-frame game))
         (start-frame (run-ref game #:start-frame))
         (goal-frame (run-ref game #:goal-frame))
         (seconds (/ (* (game-frame-delay game) (- (or goal-frame frame) start-frame)) 1000.)))
    (draw-sprite goal-flag (entity-ref goal #:x)
                 (- (+ (entity-ref goal #:y) (entity-ref goal #:height)) 16))
    (let ((lift (entity-find (scene-entities (game-scene game)) 'lift)))
      (for-each (lambda (k) (draw-sprite lift-piece (+ (entity-ref lift #:x) (* 16 k)) (- (entity-ref lift #:y) 8)))
                (iota (quotient (entity-ref lift #:width) 16))))
    (draw-label (format #f "TIME ~,1f" seconds) 4 4 'white)
    (let ((text (format #f "COINS ~a" (run-ref game #:coins))))
      (draw-label text (- (game-width game) 4 (text-width text)) 4 'yellow))
    (cond (goal-frame
           (draw-label "GOAL!" (centred-x "GOAL!" (game-width game) scale: 3) 70 'yellow scale: 3)
           (draw-label "RETURN: PLAY AGAIN" (centred-x "RETURN: PLAY AGAIN" (game-width game)) 100 'white))
          ((game-paused? game)
           (draw-label "PAUSED" (centred-x "PAUSED" (game-width game) scale: 3) 70 'white scale: 3)
           (draw-label "P: GO ON" (centred-x "P: GO ON" (game-width game)) 100 'white))
          ((< (- frame start-frame) 240)   ; the first 4 s: how to play, over the ground
           (draw-label "ARROWS RUN  Z JUMP  DOWN DROPS  GET TO THE FLAG" (centred-x "ARROWS RUN  Z JUMP  DOWN DROPS  GET TO THE FLAG" (game-width game)) (- (game-height game) 12) 'white)))))

(define (render game)
  ;; Runs after camera-follow! (which keeps the view inside the map).
  ;; Draws the goal and the HUD (when the game has a display) and,
  ;; headless, prints a line every 20 frames (not again while
  ;; the game stands paused on it).
  (when (current-display) (draw! game))
  (let ((frame (game-frame game))
        (player (car (scene-entities (game-scene game))))
        (camera (scene-camera (game-scene game))))
    (when (and trace? (zero? (modulo frame 20)) (not (game-paused? game)))
      (format #t "frame ~3d: player (~a, ~a) v (~a, ~a)~a  camera (~a, ~a)~%"
              frame (entity-ref player #:x) (entity-ref player #:y)
              (entity-ref player #:vx) (entity-ref player #:vy)
              (if (entity-ref player #:on-ground? #f) " on-ground" "")
              (camera-x camera) (camera-y camera)))))

;;; The built-in input: key frames (frame . actions held from then on).
(define input-script
  '((0 . ())
    (25 . (right))               ; run right
    (50 . (right a))             ; jump onto the first platform (row 8, y 128)
    (51 . (right))
    (60 . (right a))             ; pressing 'a in the air does nothing
    (61 . (right))
    (78 . ())                    ; stand on it
    (85 . (right a))             ; jump to the second platform (row 5, y 80)
    (86 . (right))
    (112 . ())
    (120 . (right))              ; run off its end, drop to the ground, into the pit
    (220 . (right a))            ; in the pit, pressed against its wall: jump out
    (221 . (right))              ; over the grass, under the plank
    (372 . (right a))            ; jump up through the one-way plank
    (373 . (right))
    (395 . ())                   ; landed on it: stand
    (410 . (down))               ; drop through it
    (411 . ())
    (425 . (right))              ; on to the blocks
    (453 . (right a))            ; jump: the head breaks the block above
    (454 . (right))
    (480 . ())                   ; wait at the second pit's edge for the lift
    (573 . (right))              ; step on as it leaves the near end (frame 575)
    (583 . ())                   ; ride it over
    (636 . (right))))            ; walk off near the far end, on to the goal and the east wall

(define demo-frames 720)

(define game
  (make-game title: "Downstroke — platformer" width: 320 height: 240 frame-delay: 16
             scene: (make-scene entities: (start-entities) tilemap: level camera-target: 'player
                                data: (fresh-run 0))
             update: update render: render paused: paused-update
             ;; The default keys, and P for pause.
             input-map: (append (default-input-map) '((pause "P")))
             history: 600                         ; 10 s to rewind
             input-script: input-script))

(define (run! frames)
  "Run the game up to frame FRAMES (it counts from where it stopped)."
  (game-run! game frames: frames))

(when (main-script? "platformer.scm")
  ;; Headless or capturing: the scripted demo; in a window: until the player quits.
  (run! (script-number-argument 0 (if (eq? (display-mode) 'window) #f demo-frames)))
  (format #t "sounds: ~s~%" (game-sounds game))
  (format #t "camera: (~a, ~a)~%" (camera-x (scene-camera (game-scene game)))
          (camera-y (scene-camera (game-scene game)))))
