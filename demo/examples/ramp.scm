;; SPDX-License-Identifier: 0BSD
;;; ramp.scm — one idea: a ramp.
;;;
;;; The hill in maps/platformer.tmx (x 704 to 832) is made of tiles with a
;;; collision shape drawn in Tiled: a slope whose floor is the line under
;;; it. A body running into it is lifted onto the highest point under its
;;; feet, so it climbs without jumping: 1 px up for 2 across on the gentle
;;; ramp (half pixels: y becomes a flonum), 1 for 1 on the steep one.
;;;
;;;   downstroke demo/examples/ramp.scm            headless: up the hill, stop on top
;;;   downstroke --window demo/examples/ramp.scm   Left/Right run
(define here (dirname (or (current-filename) "./ramp.scm")))
(define level (load-tilemap (string-append here "/../maps/platformer.tmx")))

(define hero-picture 5)                 ; sprites.tsx's first tile
(define run-speed 3)                    ; px per frame

(define hero
  ;; On the ground (top y 176), 64 px before the foot of the hill.
  (list #:id 'hero #:x 640 #:y 160 #:width 12 #:height 16 #:vx 0 #:vy 0
        #:gravity? #t #:solid? #t #:sprite hero-picture))

(define (update game dt)
  (let* ((input (game-input game))
         (scene (game-scene game))
         (speed (cond ((input-held? input 'left) (- run-speed))
                      ((input-held? input 'right) run-speed)
                      (else 0))))
    (game-scene-set! game (update-scene scene entities:
                                        (list (entity-set (car (scene-entities scene)) #:vx speed))))))

(define (render game)
  (let ((hero (car (scene-entities (game-scene game)))))
    (draw-label (format #f "Y ~a" (entity-ref hero #:y)) 4 4 'white)))

(define (new-game)
  "A fresh game: the hero runs right from frame 5 to 45, onto the hill's top."
  (make-game title: "ramp" width: 320 height: 240
             scene: (make-scene entities: (list hero) tilemap: level camera-target: 'hero)
             update: update render: render
             input-script: '((0 . ()) (5 . (right)) (45 . ()))))

(when (main-script? "ramp.scm")
  (let* ((game (game-run! (new-game) frames: (if (eq? (display-mode) 'window) #f 60)))
         (hero (car (scene-entities (game-scene game)))))
    (format #t "frame ~a: the hero at (~a, ~a), on the ground: ~a~%" (game-frame game)
            (entity-ref hero #:x) (entity-ref hero #:y) (entity-ref hero #:on-ground? #f))))
