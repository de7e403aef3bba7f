;; SPDX-License-Identifier: 0BSD
;;; game.scm — @NAME@, a Downstroke game.
;;;
;;;   downstroke game.scm            plays the input script below headless
;;;                                  and prints what happened
;;;   downstroke --window game.scm   plays it: arrows (or A/D) run, Z or Space
;;;                                  jumps, Escape quits
;;;   downstroke test                runs tests/*-test.scm
;;;
;;; The level is maps/level.tmx: open it in Tiled, draw ground, move the
;;; coins (objects of class coin in the layer "things"), save, run again.

;;; Files are found beside this one, wherever it is run from.
(define here (dirname (or (current-filename) "./game.scm")))
(define (game-file name) (string-append here "/" name))

(define level (load-tilemap (game-file "maps/level.tmx")))

;;; Pictures: the tiles of maps/tiles.tsx, by gid (its tile id + 1).
(define player-standing 7)
(define player-running 8)
(define player-jumping 9)
(define coin-picture 10)

(load-sound 'jump (game-file "sounds/jump.wav"))
(load-sound 'coin (game-file "sounds/coin.wav"))

(define run-speed 3)                    ; px per frame

;;; ------------------------------------------------------------ the level's things
(define (objects-of-class class)
  (filter (lambda (o) (eq? (entity-ref o #:type) class)) (tilemap-objects level)))

(define (make-player spawn)
  ;; Solid, so that sensors notice it; category player, so that the coins
  ;; can name it as the one thing they collide with.
  (list #:id 'player #:x (entity-ref spawn #:x) #:y (entity-ref spawn #:y)
        #:width 12 #:height 16 #:vx 0 #:vy 0 #:gravity? #t #:solid? #t
        #:category 'player #:coins 0 #:sprite player-standing))

(define (make-coin object)
  ;; A sensor: it moves nothing, and the frame reports the player entering it.
  (list #:id (string->symbol (entity-ref object #:name)) #:kind 'coin
        #:x (entity-ref object #:x) #:y (entity-ref object #:y) #:width 8 #:height 8
        #:sensor? #t #:collides-with '(player) #:sprite coin-picture))

(define (start-entities)
  ;; The player first: the game finds it there every frame.
  (cons (make-player (car (objects-of-class 'player)))
        (map make-coin (objects-of-class 'coin))))

;;; ------------------------------------------------------------ every frame
(define (coins-entered scene)
  ;; The ids of the coins the player touches this frame.
  (filter-map (lambda (pair)
                (cond ((eq? (car pair) 'player) (cdr pair))
                      ((eq? (cdr pair) 'player) (car pair))
                      (else #f)))
              (scene-contacts scene)))

(define (steer player input)
  ;; Run while Left or Right is held; jump when 'a is pressed on the ground.
  (let* ((speed (cond ((input-held? input 'left) (- run-speed))
                      ((input-held? input 'right) run-speed)
                      (else 0)))
         (on-ground? (entity-ref player #:on-ground? #f))
         (jump? (and on-ground? (input-pressed? input 'a)))
         (player (entity-set player #:vx speed)))
    (when jump? (play-sound 'jump))
    (let* ((player (if jump? (entity-set player #:ay (- *jump-force*)) player))
           ;; Facing the way it last ran: #:flip-x? mirrors the picture.
           (player (if (zero? speed) player (entity-set player #:flip-x? (negative? speed)))))
      (entity-set player #:sprite (cond ((not on-ground?) player-jumping)
                                        ((zero? speed) player-standing)
                                        (else player-running))))))

(define (update game dt)
  ;; Physics has run: the player stands where it landed, and the contacts
  ;; name the coins it touched.
  (let* ((scene (game-scene game))
         (player (car (scene-entities scene)))
         (taken (coins-entered scene))
         (player (entity-set (steer player (game-input game))
                             #:coins (+ (entity-ref player #:coins) (length taken)))))
    (for-each (lambda (coin) (play-sound 'coin)) taken)
    (game-scene-set! game (update-scene scene entities:
                                        (cons player
                                              (remove (lambda (e) (memq (entity-ref e #:id) taken))
                                                      (cdr (scene-entities scene))))))))

(define (render game)
  ;; The score, in screen pixels, over the level.
  (draw-label (format #f "COINS ~a" (entity-ref (player-of game) #:coins)) 4 4 'yellow))

(define (player-of game) (car (scene-entities (game-scene game))))

;;; ------------------------------------------------------------ the game
;;; What a headless run plays: (frame . actions held from that frame on).
(define input-script
  '((0 . ())
    (10 . (right))               ; run right, through the first coin
    (76 . (right a))             ; jump onto the low platform: the second
    (77 . (right))
    (110 . (right a))            ; from its end up to the high one: the third
    (111 . (right))
    (200 . ())))                 ; the fourth was on the ground beyond: stop

(define (new-game)
  "A fresh game, at its first frame."
  (make-game title: "@NAME@" width: 320 height: 240
             scene: (make-scene entities: (start-entities) tilemap: level camera-target: 'player)
             update: update render: render input-script: input-script))

;; Run once: saving this file while the game runs (downstroke --window
;; watches it) reads the definitions above again into the running game.
(once
 (when (main-script? "game.scm")
   ;; In a window: until the player quits; headless: 300 frames (5 s).
   (let ((game (game-run! (new-game) frames: (if (eq? (display-mode) 'window) #f 300))))
     (format #t "frame ~a: ~a coins, the player at (~a, ~a)~%"
             (game-frame game) (entity-ref (player-of game) #:coins)
             (entity-ref (player-of game) #:x) (entity-ref (player-of game) #:y)))))
