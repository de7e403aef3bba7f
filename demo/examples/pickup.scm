;; SPDX-License-Identifier: 0BSD
;;; pickup.scm — one idea: a sensor pickup.
;;;
;;; The coin is a sensor: it pushes nothing, and the frame reports each body
;;; that overlaps it in the scene's contacts. It collides only with the
;;; category hero, so nothing else can take it. The game removes the coin
;;; it finds in a contact and counts it on the hero (#:coins).
;;;
;;;   downstroke demo/examples/pickup.scm            headless: run right, take the coin
;;;   downstroke --window demo/examples/pickup.scm   Left/Right run
(use-modules (srfi srfi-1))

(define here (dirname (or (current-filename) "./pickup.scm")))
(define level (load-tilemap (string-append here "/../maps/platformer.tmx")))

(define hero-picture 5)                 ; sprites.tsx's first tile
(define coin-picture 15)                ; sprites.tsx's tile 10
(define run-speed 3)                    ; px per frame

(load-sound 'coin (string-append here "/../sounds/coin.wav"))

(define hero
  (list #:id 'hero #:x 40 #:y 160 #:width 12 #:height 16 #:vx 0 #:vy 0
        #:gravity? #t #:solid? #t #:category 'hero #:coins 0 #:sprite hero-picture))

(define coin
  ;; 8×8, floating at the height of the hero's head, in its way (higher than
  ;; the grass in front, which the map draws over the entities).
  (list #:id 'coin #:x 100 #:y 158 #:width 8 #:height 8
        #:sensor? #t #:collides-with '(hero) #:sprite coin-picture))

(define (taken scene)
  ;; The ids the hero is paired with in this frame's contacts.
  (filter-map (lambda (pair)
                (cond ((eq? (car pair) 'hero) (cdr pair))
                      ((eq? (cdr pair) 'hero) (car pair))
                      (else #f)))
              (scene-contacts scene)))

(define (update game dt)
  (let* ((input (game-input game))
         (scene (game-scene game))
         (gone (taken scene))
         (hero (car (scene-entities scene)))
         (hero (entity-set hero #:coins (+ (entity-ref hero #:coins) (length gone))))
         (hero (entity-set hero #:vx (cond ((input-held? input 'left) (- run-speed))
                                           ((input-held? input 'right) run-speed)
                                           (else 0)))))
    (unless (null? gone) (play-sound 'coin))
    (game-scene-set! game (update-scene scene entities:
                                        (cons hero (remove (lambda (e) (memq (entity-ref e #:id) gone))
                                                           (cdr (scene-entities scene))))))))

(define (render game)
  (draw-label (format #f "COINS ~a" (entity-ref (car (scene-entities (game-scene game))) #:coins))
              4 4 'yellow))

(define (new-game)
  "A fresh game: the hero runs right from frame 5 to 40, through the coin."
  (make-game title: "pickup" width: 320 height: 240
             scene: (make-scene entities: (list hero coin) tilemap: level camera-target: 'hero)
             update: update render: render
             input-script: '((0 . ()) (5 . (right)) (40 . ()))))

(when (main-script? "pickup.scm")
  (let ((game (game-run! (new-game) frames: (if (eq? (display-mode) 'window) #f 60))))
    (format #t "frame ~a: ~a coin, the sound at ~s~%" (game-frame game)
            (entity-ref (car (scene-entities (game-scene game))) #:coins) (game-sounds game))))
