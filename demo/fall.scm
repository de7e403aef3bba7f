;; SPDX-License-Identifier: 0BSD
;;; Headless: a player and a few crates fall onto demo/maps/level1.tmx; the
;;; player walks right and jumps once. Prints a short trace.
;;; Keys (in a window): Right/Left or D/A walk, Z or Space jumps, Escape quits.
;;; Run: build/bin/downstroke demo/fall.scm
;;; In a window (downstroke --window demo/fall.scm) it runs until the player
;;; quits; headless it runs its 90 frames.
(use-modules (ice-9 format))
;;; The demos' shared looks and sounds: (demo looks), in demo/lib.
(add-to-load-path (canonicalize-path (string-append (dirname (current-filename)) "/lib")))
(use-modules (demo looks))

(define level (load-tilemap (demo-file "maps/level1.tmx")))
(define player-standing (sprite 0))
(define player-running (sprite 1))
(define player-jumping (sprite 2))
(define crate-picture (sprite 9))

(load-demo-sounds! 'jump)

(define (crate id x y)
  (list #:id id #:x x #:y y #:width 12 #:height 12 #:gravity? #t #:solid? #t #:sprite crate-picture))

(define player
  (list #:id 'player #:x 48 #:y 100 #:width 12 #:height 14 #:gravity? #t #:sprite player-jumping))

(define (dress player vx frame)
  ;; Its picture: facing the way it last walked, the jump frame in the air.
  (let ((left? (cond ((negative? vx) #t) ((positive? vx) #f) (else (entity-ref player #:flip-x? #f)))))
    (entity-set (entity-set player #:flip-x? left?)
                #:sprite (cond ((not (entity-ref player #:on-ground? #f)) player-jumping)
                               ((and (not (zero? vx)) (even? (quotient frame 6))) player-running)
                               (else player-standing)))))

(define (update game dt)
  (let* ((input (game-input game))
         (scene (game-scene game))
         (player (car (scene-entities scene)))
         (jump? (and (input-pressed? input 'a) (entity-ref player #:on-ground? #f)))
         (vx (cond ((input-held? input 'right) 3) ((input-held? input 'left) -3) (else 0)))
         (player (dress (entity-set player #:vx vx) vx (game-frame game))))
    (when jump? (play-sound 'jump))
    (game-scene-set! game
                     (update-scene scene
                                   entities: (cons (if jump? (entity-set player #:ay (- *jump-force*)) player)
                                                   (cdr (scene-entities scene)))))))

(define (trace game)
  (when (current-display)                ; how to play, on a plate over the ground
    (draw-rect 18 226 123 11 '(22 17 31 150) fill?: #t space: 'screen)
    (draw-text "ARROWS WALK   Z JUMP" 20 228 'white space: 'screen))
  (let ((frame (game-frame game)))
    (when (zero? (modulo frame 10))
      (format #t "frame ~3d:" frame)
      (for-each (lambda (e)
                  (format #t "  ~a(~a, ~a)~a" (entity-ref e #:id) (entity-ref e #:x)
                          (entity-ref e #:y) (if (entity-ref e #:on-ground? #f) "*" "")))
                (scene-entities (game-scene game)))
      (newline))))

;;; The picture is the level's size (30×15 tiles of 16 px), so the camera
;;; never moves (it is clamped to the map) — as with the default 640×480.
(define game
  (make-game title: "fall" width: 480 height: 240 frame-delay: 16
             scene: (make-scene entities: (list player (crate 'a 100 0) (crate 'b 104 -40)
                                                (crate 'c 250 20))
                                tilemap: level camera-target: 'player)
             update: update render: trace
             input-script: '((0 . ()) (20 . (right)) (40 . (right a)) (41 . (right)) (70 . ()))))

(game-run! game frames: (if (eq? (display-mode) 'window) #f 90))
(format #t "sounds: ~s~%" (game-sounds game))
(format #t "camera: (~a, ~a)   (* marks #:on-ground?)~%"
        (camera-x (scene-camera (game-scene game))) (camera-y (scene-camera (game-scene game))))
