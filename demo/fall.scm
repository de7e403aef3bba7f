;;; Headless: a player and a few crates fall onto demo/maps/level1.tmx; the
;;; player walks right and jumps once. Prints a short trace.
;;; Run: build/bin/downstroke demo/fall.scm
(use-modules (ice-9 format))

(define here (dirname (current-filename)))
(define level (load-tilemap (string-append here "/maps/level1.tmx")))

(define (crate id x y)
  (list #:id id #:x x #:y y #:width 12 #:height 12 #:gravity? #t #:solid? #t))

(define player
  (list #:id 'player #:x 48 #:y 100 #:width 12 #:height 14 #:gravity? #t))

(define (update game dt)
  (let* ((input (game-input game))
         (scene (game-scene game))
         (player (car (scene-entities scene)))
         (jump? (and (input-pressed? input 'a) (entity-ref player #:on-ground? #f)))
         (player (entity-set player #:vx (if (input-held? input 'right) 3 0))))
    (when jump? (play-sound 'jump))
    (game-scene-set! game
                     (update-scene scene
                                   entities: (cons (if jump? (entity-set player #:ay (- *jump-force*)) player)
                                                   (cdr (scene-entities scene)))))))

(define (trace game)
  (let ((frame (game-frame game)))
    (when (zero? (modulo frame 10))
      (format #t "frame ~3d:" frame)
      (for-each (lambda (e)
                  (format #t "  ~a(~a, ~a)~a" (entity-ref e #:id) (entity-ref e #:x)
                          (entity-ref e #:y) (if (entity-ref e #:on-ground? #f) "*" "")))
                (scene-entities (game-scene game)))
      (newline))))

(define game
  (make-game title: "fall" frame-delay: 16
             scene: (make-scene entities: (list player (crate 'a 100 0) (crate 'b 104 -40)
                                                (crate 'c 250 20))
                                tilemap: level camera-target: 'player)
             update: update render: trace
             input-script: '((0 . ()) (20 . (right)) (40 . (right a)) (41 . (right)) (70 . ()))))

(game-run! game frames: 90)
(format #t "sounds: ~s~%" (game-sounds game))
(format #t "camera: (~a, ~a)   (* marks #:on-ground?)~%"
        (camera-x (scene-camera (game-scene game))) (camera-y (scene-camera (game-scene game))))
