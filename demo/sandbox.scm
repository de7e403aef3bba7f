;; SPDX-License-Identifier: 0BSD
;;; Physics sandbox on demo/maps/sandbox.tmx, with the default engine-update.
;;;
;;; - boxes (#:gravity? #t #:solid? #t) fall onto immovable platforms (solid
;;;   entities with #:immovable? #t), onto a ledge of the map, and one onto
;;;   another box;
;;; - a raft: three planks and a mast sharing #:group-id 'raft; the first
;;;   plank is the #:group-origin? and moves with #:vx, the others follow at
;;;   their #:group-local-x / #:group-local-y (sync-groups); the update hook
;;;   turns the raft round at the ends of its run;
;;; - bots with their own logic: they walk the floor and turn round when a
;;;   wall stopped them, i.e. when the tile collision left their #:vx at 0;
;;; - two balls with #:bounce: one (bounce 1) bounces between the floor and
;;;   the walls for ever, to the same height every time; the other (0.6)
;;;   bounces lower and lower and comes to rest. They collide with no
;;;   category (#:collides-with '()), only with the map: they pass the
;;;   crates, the bots and each other.
;;; update: only runs that per-entity logic, through scene-map-entities.
;;;
;;; Keys (in a window): Left/Right or A/D move the dropper along the top,
;;; Z or Space drops a crate from it, a left click drops one where you
;;; click, Return puts everything back, Escape quits.
;;;
;;; Run: build/bin/downstroke demo/sandbox.scm
;;; Headless: it runs `demo-frames' frames (no input needed) and prints a line
;;; every 20 frames plus one per event.
;;; In a window (downstroke --window demo/sandbox.scm) it runs until the
;;; player quits.
(use-modules (ice-9 format) (srfi srfi-1))
;;; The demos' shared looks and sounds: (demo looks), in demo/lib.
(add-to-load-path (canonicalize-path (string-append (dirname (current-filename)) "/lib")))
(use-modules (demo looks) (demo events))

(define arena (load-tilemap (demo-file "maps/sandbox.tmx")))

;;; ------------------------------------------------------------ looks
(load-demo-music!)
(define walker-picture (sprite 3))
(define walker-step-picture (sprite 4))
(define crate-picture (sprite 9))
(define flag-picture (sprite 11))
(define platform-picture (sprite 12))   ; a 16×8 piece, in the bottom half of its 16×16 frame
(define ball-picture (sprite 13))

;;; ------------------------------------------------------------ entities
(define (platform id x y w)
  ;; Drawn as a row of platform pieces (see draw-platforms!).
  (list #:id id #:kind 'platform #:x x #:y y #:width w #:height 8 #:solid? #t #:immovable? #t
        #:sprite platform-picture))

(define (box id x y)
  (list #:id id #:kind 'box #:x x #:y y #:width 12 #:height 12 #:vx 0 #:vy 0
        #:gravity? #t #:solid? #t #:on-ground? #f #:sprite crate-picture))

(define (bot id x vx)
  ;; Standing on the floor (its top at y 208).
  (dress-bot (list #:id id #:kind 'bot #:x x #:y (- 208 14) #:width 12 #:height 14 #:vx vx #:vy 0
                   #:speed (abs vx) #:gravity? #t #:solid? #t #:on-ground? #t)))

(define (dress-bot e)
  "The bot E with its picture: a two-frame walk, mirrored (#:flip-x?) while
it walks left."
  (entity-set (entity-set e #:flip-x? (negative? (entity-ref e #:vx 0)))
              #:sprite (if (even? (quotient (entity-ref e #:x) 6)) walker-picture walker-step-picture)))

(define (ball id x y vx bounce)
  (list #:id id #:kind 'ball #:x x #:y y #:width 8 #:height 8 #:vx vx #:vy 0
        #:gravity? #t #:solid? #t #:bounce bounce #:category 'ball #:collides-with '()
        #:sprite ball-picture))

(define raft-speed 1)
(define raft-min-x 256)
(define raft-max-x 352)

(define (plank id local-x origin?)
  (append (list #:id id #:kind 'raft #:x (+ raft-min-x local-x) #:y 160 #:width 16 #:height 8
                #:solid? #t #:immovable? #t #:group-id 'raft #:sprite platform-picture)
          (if origin?
              (list #:group-origin? #t #:vx raft-speed)
              (list #:group-local-x local-x #:group-local-y 0))))

(define raft0
  (list (plank 'raft-0 0 #t)
        (plank 'raft-1 16 #f)
        (plank 'raft-2 32 #f)
        ;; The mast: not solid, carried along all the same; a flag flies on it.
        (list #:id 'mast #:kind 'raft #:x (+ raft-min-x 22) #:y 140 #:width 4 #:height 20
              #:group-id 'raft #:group-local-x 22 #:group-local-y -20 #:sprite flag-picture)))

;;; Order matters for stacks: resolve-entity-collisions makes one pass over
;;; the pairs in list order, and in the pair (lower, upper) the earlier body
;;; moves by the larger half of the overlap. Listing box-5 before box-2 (which
;;; it lands on) makes the lower box stay put on ledge-a; the other way round
;;; box-2 would be pushed back 1 px into the ledge every frame after the pair
;;; (ledge-a, box-2) had set it right.
(define entities0
  (append
   (list (platform 'ledge-a 48 128 64)       ; immovable platforms
         (platform 'ledge-b 288 64 64)
         (box 'box-1 60 16)                  ; → rests on ledge-a
         (box 'box-5 94 20)                  ; → lands on box-2 (listed first: see below)
         (box 'box-2 92 40)                  ; → rests on ledge-a
         (box 'box-3 300 20)                 ; → rests on ledge-b
         (box 'box-4 400 16)                 ; → rests on the map's ledge (row 7)
         (bot 'bot-1 100 -2)                 ; patrols between the west wall and the stub
         (bot 'bot-2 300 2))                 ; patrols between the stub and the east wall
   raft0
   ;; ball-1 falls 153 px (1 + 2 + … + 17) to the floor (its top y 208),
   ;; hits it at 18 px a frame and rises back to y 47, for ever, off the
   ;; west wall and the stub too; ball-2 lands on the map's ledge, rolls off
   ;; it, and bounces lower and lower to rest on the floor.
   (list (ball 'ball-1 40 47 2 1)
         (ball 'ball-2 420 40 -1 0.6))))

;;; ------------------------------------------------------------ what happened
(define trace? (main-script? "sandbox.scm"))   ; headless as the host's script: print as it goes

;;; What happened: (demo events).
(define events (make-events trace?))

(define (note-at! frame what) (note-event! events frame what))

(define (note! game what) (note-at! (game-frame game) what))

;;; ------------------------------------------------------------ the logic
(define (bot-logic game)
  (lambda (e)
    (if (eq? (entity-ref e #:kind) 'bot)
        (let ((vx (entity-ref e #:vx 0)) (speed (entity-ref e #:speed 1))
              (dir (entity-ref e #:dir (if (negative? (entity-ref e #:vx 0)) -1 1))))
          (if (zero? vx)
              ;; A wall zeroed #:vx: walk the other way.
              (begin
                (note! game (list 'turned (entity-ref e #:id) 'at (entity-ref e #:x)))
                (dress-bot (entity-set (entity-set e #:dir (- dir)) #:vx (* (- dir) speed))))
              ;; Keep the patrol speed (a push from another body may change it).
              (let ((dir (if (negative? vx) -1 1)))
                (dress-bot (entity-set (entity-set e #:dir dir) #:vx (* dir speed))))))
        e)))

(define (raft-logic game)
  (lambda (e)
    (if (entity-ref e #:group-origin? #f)
        (let ((x (entity-ref e #:x)) (vx (entity-ref e #:vx 0)))
          (cond ((and (positive? vx) (>= x raft-max-x))
                 (note! game (list 'raft-turned 'at x))
                 (entity-set e #:vx (- raft-speed)))
                ((and (negative? vx) (<= x raft-min-x))
                 (note! game (list 'raft-turned 'at x))
                 (entity-set e #:vx raft-speed))
                (else e)))
        e)))

;;; What the game remembers besides its entities is the scene's data, so a
;;; rewind gives it back: the ids of the boxes that came to rest, where the
;;; dropper is and how many crates it has dropped.
(define data0 (list #:landed '() #:dropper-x 234 #:dropped 0))

(define (data-ref game key) (entity-ref (scene-data (game-scene game)) key))

(define (data-set scene key value)
  "SCENE with KEY of its data set to VALUE."
  (update-scene scene data: (entity-set (scene-data scene) key value)))

(define (watch-boxes! game)
  (game-scene-set!
   game
   (data-set (game-scene game) #:landed
             (fold (lambda (e landed)
                     ;; At rest: supported, and not falling any more.
                     (if (and (eq? (entity-ref e #:kind) 'box) (entity-ref e #:on-ground? #f)
                              (zero? (entity-ref e #:vy 0)) (not (memq (entity-ref e #:id) landed)))
                         (begin
                           (note! game (list 'landed (entity-ref e #:id) 'y (entity-ref e #:y)))
                           (cons (entity-ref e #:id) landed))
                         landed))
                   (data-ref game #:landed)
                   (scene-entities (game-scene game))))))

;;; The player's part (in a window; headless runs hold nothing): a dropper
;;; that moves along the top and drops crates, and a reset.
;;; The dropper's x (its crate's left edge) is in the scene's data.
(define dropper-y 18)
(define dropper-speed 3)
(define max-dropped 24)                 ; beyond that the oldest dropped crate goes

(define (drop-crate scene x y)
  "SCENE with a crate at (X, Y), unless something is in the way."
  (let* ((entities (scene-entities scene))
         (free? (not (any (lambda (e) (aabb-overlap? x y 12 12
                                                     (entity-ref e #:x 0) (entity-ref e #:y 0)
                                                     (entity-ref e #:width 0) (entity-ref e #:height 0)))
                          entities))))
    (if (not free?)
        scene
        (let* ((old (filter (lambda (e) (entity-ref e #:dropped? #f)) entities))
               (entities (if (>= (length old) max-dropped) (delete (car old) entities eq?) entities))
               (dropped (+ (entity-ref (scene-data scene) #:dropped) 1)))
          (data-set (update-scene scene entities:
                                  (append entities
                                          (list (append (box (string->symbol (format #f "crate-~a" dropped)) x y)
                                                        (list #:dropped? #t)))))
                    #:dropped dropped)))))

(define (player-input! game)
  (let ((input (game-input game)) (scene (game-scene game)))
    (cond ((input-pressed? input 'start)
           (game-scene-set! game (data-set (update-scene scene entities: entities0) #:landed '())))
          (else
           (game-scene-set! game (data-set scene #:dropper-x
                                           (max 16 (min (- 464 12)
                                                        (+ (data-ref game #:dropper-x)
                                                           (if (input-held? input 'left) (- dropper-speed) 0)
                                                           (if (input-held? input 'right) dropper-speed 0))))))
           (when (input-pressed? input 'a)
             (game-scene-set! game (drop-crate (game-scene game) (data-ref game #:dropper-x) dropper-y)))
           ;; A click drops a crate centred on the pointer, inside the walls.
           (let ((m (mouse-world-position game)))
             (when (and m (input-pressed? input 'click))
               (let ((x (max 16 (min (- 464 12) (- (car m) 6))))
                     (y (max 16 (min (- 208 12) (- (cadr m) 6))))
                     (scene (game-scene game)))
                 (game-scene-set! game (drop-crate scene x y)))))))))

(define (update game dt)
  (theme-from-the-start game)
  ;; The default engine-update has moved everything; now the game's own logic.
  (watch-boxes! game)
  (game-scene-set! game (scene-map-entities (game-scene game) (bot-logic game) (raft-logic game)))
  (player-input! game))

(define (draw-platforms! entities)
  ;; An immovable platform is wider than one piece: a row of them along it
  ;; (each 16×8 piece sits in the bottom half of its frame).
  (for-each (lambda (e)
              (when (eq? (entity-ref e #:kind) 'platform)
                (let ((x (entity-ref e #:x)) (y (entity-ref e #:y)))
                  (for-each (lambda (k) (draw-sprite platform-picture (+ x (* 16 k)) (- y 8)))
                            (iota (quotient (entity-ref e #:width) 16))))))
            entities))

(define (draw! game)
  ;; The crates, bots and raft are drawn by the engine from their #:sprite.
  (let* ((entities (scene-entities (game-scene game)))
         (boxes (filter (lambda (e) (eq? (entity-ref e #:kind) 'box)) entities))
         (at-rest (count (lambda (e) (memq (entity-ref e #:id) (data-ref game #:landed))) boxes))
         (dropper-x (data-ref game #:dropper-x))
         (hint "ARROWS MOVE  Z OR CLICK: A CRATE  RETURN RESET"))
    (draw-platforms! entities)
    ;; The dropper: where the next crate appears, and an arrow down.
    (draw-rect dropper-x dropper-y 12 12 '(250 220 70 200))
    (draw-line (+ dropper-x 6) (+ dropper-y 3) (+ dropper-x 6) (+ dropper-y 8) '(250 220 70 200))
    (draw-line (+ dropper-x 4) (+ dropper-y 6) (+ dropper-x 6) (+ dropper-y 8) '(250 220 70 200))
    (draw-line (+ dropper-x 8) (+ dropper-y 6) (+ dropper-x 6) (+ dropper-y 8) '(250 220 70 200))
    (draw-label (format #f "CRATES ~a   LANDED ~a" (length boxes) at-rest) 4 4 'white)
    (draw-label hint (- (game-width game) 4 (text-width hint)) 4 'white)))

(define (render game)
  ;; Draws the platforms, the dropper and the HUD (when the game has a
  ;; display) and, headless, prints a line every 20 frames.
  (when (current-display) (draw! game))
  (let ((frame (game-frame game))
        (entities (scene-entities (game-scene game))))
    (when (and trace? (zero? (modulo frame 20)))
      (format #t "frame ~3d:" frame)
      (for-each (lambda (e)
                  (unless (eq? (entity-ref e #:kind) 'platform)
                    (format #t " ~a(~a,~a)~a" (entity-ref e #:id) (entity-ref e #:x) (entity-ref e #:y)
                            (if (entity-ref e #:on-ground? #f) "*" ""))))
                entities)
      (newline))))

(define demo-frames 300)

(define game
  (make-game title: "Downstroke — sandbox" width: 480 height: 240 frame-delay: 16
             input-map: (append (default-input-map) '((click "mouse:left")))
             scene: (make-scene entities: entities0 tilemap: arena data: data0)
             update: update render: render
             input-script: '()))

(define (run! frames)
  "Run the game up to frame FRAMES (it counts from where it stopped)."
  (game-run! game frames: frames))

(when (main-script? "sandbox.scm")
  ;; Headless or capturing: the demo's frames; in a window: until the player quits.
  (run! (script-number-argument 0 (if (eq? (display-mode) 'window) #f demo-frames)))
  (format #t "(* marks #:on-ground?)~%"))
