;;; Top-down: four-way movement in a walled room (demo/maps/topdown.tmx).
;;;
;;; No gravity: the player has #:gravity? #f, so the default engine-update's
;;; acceleration, gravity and ground steps pass it by; 'up 'down 'left 'right
;;; set #:vx / #:vy and the tile collisions stop it at the walls. The player
;;; and the coins come from the map's object layer; walking over a coin
;;; (aabb-overlap?) collects it.
;;;
;;; Run: build/bin/downstroke demo/topdown.scm
;;; Headless: it plays the built-in input script for `demo-frames' frames and
;;; prints a line every 20 frames plus one per event.
(use-modules (ice-9 format) (srfi srfi-1))

(define demo-dir
  (cond ((current-filename) => dirname)
        ((getenv "DS_DEMO_DIR"))
        (else "demo")))

(define room (load-tilemap (string-append demo-dir "/maps/topdown.tmx")))

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

(define coins0 (map object->entity (objects-of-type 'coin)))

;;; ------------------------------------------------------------ bookkeeping
;;; Both records are bounded (see (downstroke history)), so that a game left
;;; running (a soak test, a REPL session) stays in constant memory: a ring of
;;; the last 1000 frames, and between 500 and 1000 of the newest events.
(define trace? (main-script? "topdown.scm"))
(define events (make-bounded-log))      ; of (frame . what), newest first; 500 kept
(define history (make-frame-ring 1000)) ; each frame's entities

(define (note! game what)
  (set! events (bounded-log-push events (cons (game-frame game) what) 500))
  (when trace? (format #t "frame ~3d: ~a~%" (game-frame game) what)))

(define (remember! frame entities) (frame-ring-set! history frame entities))

(define (entities-at frame)
  "The entities as they were at the end of FRAME, or #f when FRAME is not
one of the last 1000."
  (frame-ring-ref history frame))

(define (player-at frame)
  (let ((entities (entities-at frame))) (and entities (car entities))))

;;; ------------------------------------------------------------ the game
(define (overlaps? a b)
  (aabb-overlap? (entity-ref a #:x 0) (entity-ref a #:y 0) (entity-ref a #:width 0) (entity-ref a #:height 0)
                 (entity-ref b #:x 0) (entity-ref b #:y 0) (entity-ref b #:width 0) (entity-ref b #:height 0)))

(define (axis-intent input minus plus speed)
  (+ (if (input-held? input minus) (- speed) 0) (if (input-held? input plus) speed 0)))

(define last-intent '(0 . 0))           ; the (vx . vy) the player asked for last frame
(define blocked '(#f . #f))             ; whether a wall stops it on x, on y

(define (report-walls! game player)
  ;; A velocity we asked for that physics zeroed: the player is against a
  ;; wall. Reported when that starts.
  (let* ((vx (entity-ref player #:vx 0)) (vy (entity-ref player #:vy 0))
         (bx? (and (not (zero? (car last-intent))) (zero? vx)))
         (by? (and (not (zero? (cdr last-intent))) (zero? vy))))
    (when (and bx? (not (car blocked)))
      (note! game (list 'wall (if (positive? (car last-intent)) 'right 'left)
                        'x (entity-ref player #:x))))
    (when (and by? (not (cdr blocked)))
      (note! game (list 'wall (if (positive? (cdr last-intent)) 'down 'up)
                        'y (entity-ref player #:y))))
    (set! blocked (cons bx? by?))))

(define (update game dt)
  (let* ((input (game-input game))
         (scene (game-scene game))
         (player (car (scene-entities scene)))
         (coins (cdr (scene-entities scene)))
         (speed (entity-ref player #:speed 3))
         (vx (axis-intent input 'left 'right speed))
         (vy (axis-intent input 'up 'down speed))
         (taken (filter (lambda (c) (overlaps? player c)) coins)))
    (report-walls! game player)
    (for-each (lambda (c)
                (play-sound 'coin)
                (note! game (list 'coin (entity-ref c #:id))))
              taken)
    (set! last-intent (cons vx vy))
    (let* ((player (entity-set player #:score (fold + (entity-ref player #:score 0)
                                                     (map (lambda (c) (entity-ref c #:value 1)) taken))))
           (player (entity-set (entity-set player #:vx vx) #:vy vy)))
      (game-scene-set! game (update-scene scene entities:
                                          (cons player (remove (lambda (c) (memq c taken)) coins)))))))

(define (render game)
  (let ((frame (game-frame game))
        (entities (scene-entities (game-scene game))))
    (remember! frame entities)
    (when (and trace? (zero? (modulo frame 20)))
      (let ((p (car entities)))
        (format #t "frame ~3d: player (~a, ~a) v (~a, ~a)  score ~a  coins left ~a~%"
                frame (entity-ref p #:x) (entity-ref p #:y) (entity-ref p #:vx) (entity-ref p #:vy)
                (entity-ref p #:score) (length (cdr entities)))))))

;;; Built-in input: right to the inner wall, down to the bottom wall, left,
;;; up, then diagonally across the room and over to the last coin.
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
             scene: (make-scene entities: (cons player0 coins0) tilemap: room camera-target: 'player)
             update: update render: render
             input-script: input-script))

(define (run! frames)
  "Run the game up to frame FRAMES (it counts from where it stopped)."
  (game-run! game frames: frames))

(when (main-script? "topdown.scm")
  (run! (script-number-argument 0 demo-frames))
  (format #t "score: ~a, sounds: ~s~%" (entity-ref (car (scene-entities (game-scene game))) #:score)
          (game-sounds game)))
