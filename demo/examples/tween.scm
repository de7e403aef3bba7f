;; SPDX-License-Identifier: 0BSD
;;; tween.scm — one idea: a tween.
;;;
;;; make-tween moves an entity's keys to targets over a time, by an easing
;;; curve; stored under #:tween, it is advanced by the engine each frame
;;; (16 ms here) and removed at its end, when its on-complete runs. Here a
;;; block glides across and back (yoyo), twice over, easing in and out, and
;;; turns yellow when it is done.
;;;
;;;   downstroke demo/examples/tween.scm            headless: the block's x as it goes
;;;   downstroke --window demo/examples/tween.scm   Return starts it again
(define block
  (list #:id 'block #:x 40 #:y 112 #:width 16 #:height 16 #:color '(120 180 255)))

(define (done block)
  ;; on-complete: what it returns replaces the entity.
  (entity-set block #:color 'yellow))

(define (glide block)
  "BLOCK with a fresh tween: to x 264 in 480 ms and back, twice."
  (entity-set block #:tween (make-tween block props: '((#:x . 264)) duration: 480
                                        ease: 'quad-in-out yoyo?: #t repeat: 3
                                        on-complete: done)))

(define (update game dt)
  (when (input-pressed? (game-input game) 'start)
    (game-scene-set! game (update-scene (game-scene game) entities: (list (glide block))))))

(define (render game)
  (let ((x (entity-ref (car (scene-entities (game-scene game))) #:x)))
    (draw-label (format #f "X ~,1f" x) 4 4 'white)))

(define (new-game)
  "A fresh game, the block gliding from its first frame."
  (make-game title: "tween" width: 320 height: 240 frame-delay: 16
             scene: (make-scene entities: (list (glide block)))
             update: update render: render))

(when (main-script? "tween.scm")
  (let ((game (new-game)))
    (if (eq? (display-mode) 'window)
        (game-run! game)
        (for-each (lambda (frame)
                    (game-run! game frames: frame)
                    (format #t "after frame ~a: x ~a~%" (- frame 1)
                            (entity-ref (car (scene-entities (game-scene game))) #:x)))
                  '(15 30 60 121)))))
