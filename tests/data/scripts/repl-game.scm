;; SPDX-License-Identifier: MIT
;;; A game for tests/scheme/repl-server-test.scm: a box at x 0 that nothing
;;; moves. It exits 0 as soon as the box has been moved to x ≥ 500 (from the
;;; REPL), or 3 after 1000 frames (16 s of paced frames).
(use-modules (ice-9 format))
(define game
  (make-game frame-delay: 16 history: 120
             scene: (make-scene entities: (list '(#:id box #:x 0 #:y 0 #:width 8 #:height 8)))
             update: (lambda (game dt)
                       (let ((box (car (scene-entities (game-scene game)))))
                         (when (>= (entity-ref box #:x 0) 500)
                           (format #t "moved: x=~a at frame ~a~%" (entity-ref box #:x) (game-frame game))
                           (force-output)
                           (exit 0))))))
(format #t "ready~%") (force-output)
(game-run! game frames: 1000)
(format #t "timeout~%")
(exit 3)
