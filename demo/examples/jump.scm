;; SPDX-License-Identifier: 0BSD
;;; jump.scm — one idea: a jump is game logic, not physics.
;;;
;;; Pressed on the ground, 'a sets the body's #:ay to (- *jump-force*); the
;;; next frame's physics turns that into speed upwards, and gravity slows it
;;; and brings it back down. The highest point reached (the smallest y) is
;;; kept in the scene's data, so a rewind or a test sees it too.
;;;
;;;   downstroke demo/examples/jump.scm            headless: one jump, the apex
;;;   downstroke --window demo/examples/jump.scm   Z or Space jumps
(define here (dirname (or (current-filename) "./jump.scm")))
(define level (load-tilemap (string-append here "/../maps/platformer.tmx")))

(define hero-picture 5)                 ; sprites.tsx's first tile

(define hero
  ;; Standing on the ground (its top is y 176; the hero is 16 high).
  (list #:id 'hero #:x 40 #:y 160 #:width 12 #:height 16 #:vx 0 #:vy 0
        #:gravity? #t #:solid? #t #:sprite hero-picture))

(define (update game dt)
  ;; Physics has run: #:on-ground? says whether the hero stands this frame.
  (let* ((scene (game-scene game))
         (hero (car (scene-entities scene)))
         (jump? (and (input-pressed? (game-input game) 'a) (entity-ref hero #:on-ground? #f)))
         (hero (if jump? (entity-set hero #:ay (- *jump-force*)) hero)))
    (game-scene-set! game (update-scene scene entities: (list hero)
                                        data: (min (scene-data scene) (entity-ref hero #:y))))))

(define (render game)
  (let ((text (format #f "HIGHEST Y ~a" (scene-data (game-scene game)))))
    ;; Right-aligned: text-width measures it in the built-in font.
    (draw-label text (- (game-width game) 4 (text-width text)) 4 'yellow)))

(define (new-game)
  "A fresh game, at its first frame: the hero on the ground, jumping at frame 20."
  (make-game title: "jump" width: 320 height: 240
             scene: (make-scene entities: (list hero) tilemap: level camera-target: 'hero
                                data: (entity-ref hero #:y))   ; the smallest y so far
             update: update render: render
             input-script: '((0 . ()) (20 . (a)) (21 . ()))))

(when (main-script? "jump.scm")
  (let ((game (game-run! (new-game) frames: (if (eq? (display-mode) 'window) #f 60))))
    (format #t "frame ~a: the apex was y ~a, ~a px above where it stood~%"
            (game-frame game) (scene-data (game-scene game))
            (- (entity-ref hero #:y) (scene-data (game-scene game))))))
