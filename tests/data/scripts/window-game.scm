;; SPDX-License-Identifier: MIT
;;; The window test's game (tests/scheme/window-test.scm runs it under Xvfb
;;; with `downstroke --window --scale 2'): a 64 × 48 picture with a 6 × 6
;;; box that walks right one pixel a frame while 'right is held (the test
;;; holds the Right arrow with xdotool) until it reaches x = 20. It says
;;; "ready" once the window shows the first frame, "arrived" when the box
;;; is there, and "quit" when 'quit ends the game (the test presses Escape).
;;; A left click (bound to 'click) says "click X Y" with the pointer's place
;;; in the picture, and the pointer is marked by a yellow pixel while it is
;;; over the picture.
(use-modules (ice-9 format))

(define said '())
(define (say-once! what)
  (unless (memq what said)
    (set! said (cons what said))
    (format #t "~a~%" what)
    (force-output)))

(define (update game dt)
  (let* ((scene (game-scene game))
         (box (car (scene-entities scene)))
         (x (entity-ref box #:x)))
    (when (and (input-held? (game-input game) 'right) (< x 20))
      (game-scene-set! game (update-scene scene entities: (list (entity-set box #:x (+ x 1))))))
    (when (>= x 20) (say-once! 'arrived))
    (when (input-pressed? (game-input game) 'click)
      (let ((m (input-mouse (game-input game))))
        (format #t "click ~a ~a ~a~%" (car m) (cadr m) (caddr m))
        (force-output)))))

(define game
  (make-game title: "window-test" width: 64 height: 48
             scene: (make-scene entities: (list (list #:id 'box #:x 4 #:y 20 #:width 6 #:height 6 #:solid? #t
                                                        #:color '(80 220 100))))
             update: update
             input-map: (append (default-input-map) '((click "mouse:left")))
             render: (lambda (game)
                       (draw-rect 0 0 64 4 'red fill?: #t space: 'screen)
                       (let ((m (input-mouse (game-input game))))
                         (when m (draw-rect (car m) (cadr m) 1 1 '(255 255 0) fill?: #t space: 'screen)))
                       (when (> (game-frame game) 1) (say-once! 'ready)))))

(game-run! game frames: 6000)  ; 100 s at most: the test ends it long before
(say-once! 'quit)
