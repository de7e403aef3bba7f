;; SPDX-License-Identifier: 0BSD
;;; plank.scm — one idea: a one-way plank.
;;;
;;; The plank's tiles (row 8 of maps/platformer.tmx, x 992 to 1088) have the
;;; tileset property one-way: a body passes up through them from below and
;;; lands on them from above. Holding Down sets #:drop-through?, which lets
;;; the body fall through the plank it stands on.
;;;
;;;   downstroke demo/examples/plank.scm            headless: up through, land, drop
;;;   downstroke --window demo/examples/plank.scm   Z or Space jumps, Down drops
(define here (dirname (or (current-filename) "./plank.scm")))
(define level (load-tilemap (string-append here "/../maps/platformer.tmx")))

(define hero-picture 5)                 ; sprites.tsx's first tile

(define hero
  ;; On the ground (top y 176) under the plank (top y 128).
  (list #:id 'hero #:x 1020 #:y 160 #:width 12 #:height 16 #:vx 0 #:vy 0
        #:gravity? #t #:solid? #t #:sprite hero-picture))

(define (update game dt)
  (let* ((input (game-input game))
         (scene (game-scene game))
         (hero (car (scene-entities scene)))
         (jump? (and (input-pressed? input 'a) (entity-ref hero #:on-ground? #f)))
         (hero (entity-set hero #:drop-through? (input-held? input 'down)))
         (hero (if jump? (entity-set hero #:ay (- *jump-force*)) hero)))
    (game-scene-set! game (update-scene scene entities: (list hero)))))

(define (render game)
  (draw-label "Z JUMPS UP THROUGH, DOWN DROPS" 4 4 'white))

(define (new-game)
  "A fresh game: the hero jumps at frame 10 and holds Down from frame 60."
  (make-game title: "plank" width: 320 height: 240
             scene: (make-scene entities: (list hero) tilemap: level camera-target: 'hero)
             update: update render: render
             input-script: '((0 . ()) (10 . (a)) (11 . ()) (60 . (down)) (61 . ()))))

(when (main-script? "plank.scm")
  (let ((game (game-run! (new-game) frames: (if (eq? (display-mode) 'window) #f 90))))
    (format #t "frame ~a: the hero at y ~a~%" (game-frame game)
            (entity-ref (car (scene-entities (game-scene game))) #:y))))
