;; SPDX-License-Identifier: 0BSD
;;; game.scm — the tutorial's game (docs/tutorial.org): two levels drawn in
;;; Tiled, enemies placed as objects, one-way planks, a door to the next
;;; level, a HUD and sounds. Made from docs/tutorial.org: edit it there.
(define here (dirname (or (current-filename) "./game.scm")))
(define (game-file name) (string-append here "/" name))

;;; Pictures: the tiles of maps/tiles.tsx, by gid (its tile id + 1).
(define player-standing 7)
(define player-running 8)
(define player-jumping 9)
(define coin-picture 10)
(define walker-picture 11)
(define walker-stepping 12)
;; A walker's feet: each picture for 128 ms (8 frames of 16 ms), in turn.
(define walker-walk (list (cons walker-picture 128) (cons walker-stepping 128)))

(for-each (lambda (name)
            (load-sound name (game-file (string-append "sounds/" (symbol->string name) ".wav"))))
          '(jump coin stomp hurt door))

(define run-speed 3)                    ; px per frame
(define stomp-bounce 8)                 ; px per frame up, off an enemy's head
(define first-level "level1.tmx")

(define (load-level file)
  (load-tilemap (game-file (string-append "maps/" file))))

(define (objects-of-class level class)
  (filter (lambda (o) (eq? (entity-ref o #:type) class)) (tilemap-objects level)))

(define (level-title level)
  (entity-ref (tilemap-properties level) #:title))

(define (make-player spawn file coins)
  ;; The player carries the game's state: the level it is in, its coins,
  ;; and the coins it had when it entered the level (what a hurt takes
  ;; it back to).
  (list #:id 'player #:x (entity-ref spawn #:x) #:y (entity-ref spawn #:y)
        #:width 12 #:height 16 #:vx 0 #:vy 0 #:gravity? #t #:solid? #t
        #:category 'player #:sprite player-standing
        #:level file #:coins coins #:coins-at-start coins #:won? #f))

(define (make-coin object)
  ;; A sensor: it moves nothing, and the frame reports the player entering it.
  (list #:id (string->symbol (entity-ref object #:name)) #:kind 'coin
        #:x (entity-ref object #:x) #:y (entity-ref object #:y) #:width 8 #:height 8
        #:sensor? #t #:collides-with '(player) #:sprite coin-picture))

(define (make-enemy object place)
  ;; It turns at walls and at the ends of its patrol, the object's own
  ;; property `patrol' px either way of where it starts. PLACE, its place
  ;; among the level's walkers, sets its step 5 frames after the one before.
  (let ((x (entity-ref object #:x)) (patrol (entity-ref object #:patrol 32)))
    (list #:id (string->symbol (entity-ref object #:name)) #:kind 'enemy
          #:x x #:y (entity-ref object #:y) #:width 12 #:height 14
          #:vx -1 #:vy 0 #:gravity? #t #:contacts? #t
          #:sensor? #t #:collides-with '(player)
          #:from (- x patrol) #:to (+ x patrol)
          #:animation walker-walk #:animation-start (* -5 place))))

(define (make-door object)
  ;; Its property `to' names the next level's map; the last door has none.
  (list #:id 'door #:kind 'door
        #:x (entity-ref object #:x) #:y (entity-ref object #:y)
        #:width (entity-ref object #:width) #:height (entity-ref object #:height)
        #:sensor? #t #:collides-with '(player) #:to (entity-ref object #:to #f)))

(define (level-scene file coins)
  "The scene of the level in maps/FILE, the player entering it with COINS."
  (let ((level (load-level file)))
    (make-scene entities: (cons (make-player (car (objects-of-class level 'player)) file coins)
                                (append (map make-coin (objects-of-class level 'coin))
                                        (let ((walkers (objects-of-class level 'enemy)))
                                          (map make-enemy walkers (iota (length walkers))))
                                        (map make-door (objects-of-class level 'door))))
                tilemap: level camera-target: 'player)))

(define (steer player input)
  (let* ((speed (cond ((input-held? input 'left) (- run-speed))
                      ((input-held? input 'right) run-speed)
                      (else 0)))
         (on-ground? (entity-ref player #:on-ground? #f))
         (jump? (and on-ground? (input-pressed? input 'a)))
         (player (entity-set player #:vx speed))
         (player (entity-set player #:drop-through? (and on-ground? (input-held? input 'down))))
         (player (if jump? (entity-set player #:ay (- *jump-force*)) player))
         ;; Facing the way it last ran: #:flip-x? mirrors the picture.
         (player (if (zero? speed) player (entity-set player #:flip-x? (negative? speed)))))
    (when jump? (play-sound 'jump))
    (entity-set player #:sprite (cond ((not on-ground?) player-jumping)
                                      ((zero? speed) player-standing)
                                      (else player-running)))))

(define (patrol enemy)
  (let* ((vx (entity-ref enemy #:vx))
         (blocked (entity-ref enemy #:blocked '()))
         (x (entity-ref enemy #:x))
         (vx (cond ((or (memq 'left blocked) (< x (entity-ref enemy #:from))) (abs vx))
                   ((or (memq 'right blocked) (> x (entity-ref enemy #:to))) (- (abs vx)))
                   (else vx))))
    (entity-set (entity-set enemy #:vx vx) #:flip-x? (negative? vx))))

(define (touched-by-player scene)
  "What the player touched this frame: (entity . side), SIDE the player's."
  (let ((sides (filter-map (lambda (contact)
                             (and (eq? (car contact) 'player) (cons (cadr contact) (cddr contact))))
                           (scene-contact-sides scene))))
    (filter-map (lambda (e)
                  (let ((hit (assq (entity-ref e #:id) sides)))
                    (and hit (cons e (cdr hit)))))
                (scene-entities scene))))

(define (of-kind kind entities)
  (filter (lambda (e) (eq? (entity-ref e #:kind #f) kind)) entities))

(define (update game dt)
  (let* ((scene (game-scene game))
         (player (car (scene-entities scene)))
         (hits (touched-by-player scene))
         (touched (map car hits))
         (door (find (lambda (e) (eq? (entity-ref e #:kind #f) 'door)) touched))
         (stomped (of-kind 'enemy (filter-map (lambda (hit) (and (eq? (cdr hit) 'down) (car hit))) hits))))
    (cond ((input-pressed? (game-input game) 'pause)
           (game-paused-set! game #t))
          ((entity-ref player #:won? #f)
           (game-scene-set! game (update-scene scene entities:
                                               (cons (entity-set player #:vx 0) (cdr (scene-entities scene))))))
          ((and door (entity-ref door #:to))
           (play-sound 'door)
           (game-scene-set! game (level-scene (entity-ref door #:to) (entity-ref player #:coins))))
          (door
           (play-sound 'door)
           (game-scene-set! game (update-scene scene entities:
                                               (cons (entity-set (entity-set player #:won? #t) #:vx 0)
                                                     (cdr (scene-entities scene))))))
          ((< (length stomped) (length (of-kind 'enemy touched)))
           (play-sound 'hurt)
           (game-scene-set! game (level-scene (entity-ref player #:level)
                                              (entity-ref player #:coins-at-start))))
          (else (play! game scene player touched stomped)))))

(define (play! game scene player touched stomped)
  (let* ((coins (of-kind 'coin touched))
         (gone (map (lambda (e) (entity-ref e #:id)) (append coins stomped)))
         (player (entity-set player #:coins (+ (entity-ref player #:coins) (length coins))))
         (player (steer player (game-input game)))
         (player (if (pair? stomped) (entity-set player #:vy (- stomp-bounce)) player)))
    (for-each (lambda (c) (play-sound 'coin)) coins)
    (for-each (lambda (e) (play-sound 'stomp)) stomped)
    (game-scene-set! game
      (update-scene scene entities:
                    (cons player
                          (filter-map (lambda (e)
                                        (cond ((memq (entity-ref e #:id) gone) #f)
                                              ((eq? (entity-ref e #:kind #f) 'enemy) (patrol e))
                                              (else e)))
                                      (cdr (scene-entities scene))))))))

(define (player-of game) (car (scene-entities (game-scene game))))

(define (render game)
  (let* ((player (player-of game))
         (title (level-title (scene-tilemap (game-scene game))))
         (width (game-width game)))
    (draw-label (format #f "COINS ~a" (entity-ref player #:coins)) 4 4 'yellow)
    (draw-label title (- width 4 (text-width title)) 4 'white)
    (when (entity-ref player #:won? #f)
      (draw-label "YOU WIN!" (quotient (- width (text-width "YOU WIN!" #:scale 3)) 2) 90 'yellow #:scale 3))
    (when (game-paused? game)
      (draw-label "PAUSED" (quotient (- width (text-width "PAUSED" #:scale 2)) 2) 100 'white #:scale 2))))

(define input-script
  '((0 . ())
    (10 . (right))))

(define (paused game dt)
  ;; Called instead of update while the game is paused: nothing steps, the
  ;; window shows the game as it stood, and P goes on from there.
  (when (input-pressed? (game-input game) 'pause)
    (game-paused-set! game #f)))

(define (new-game)
  "A fresh game, at its first frame, in the first level."
  (make-game title: "Downstroke tutorial" width: 320 height: 240
             scene: (level-scene first-level 0)
             input-map: (append (default-input-map) '((pause "P")))
             update: update render: render paused: paused input-script: input-script))

;; once: a save of game.scm while it plays (next section) reads the
;; definitions above again into the running game, but does not run this.
(once
 (when (main-script? "game.scm")
   (let ((game (game-run! (new-game) frames: (if (eq? (display-mode) 'window) #f 600))))
     (format #t "frame ~a: ~a, ~a coins~a~%" (game-frame game)
             (entity-ref (player-of game) #:level) (entity-ref (player-of game) #:coins)
             (if (entity-ref (player-of game) #:won? #f) ", won" "")))))
