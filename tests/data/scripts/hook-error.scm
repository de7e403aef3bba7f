;; SPDX-License-Identifier: MIT
;;; A game whose update hook fails in frame 3, for tests/scheme/repl-server-test.scm:
;;; without a REPL server the error ends the script (status 1).
(define game
  (make-game frame-delay: 16 scene: (make-scene entities: '())
             update: (lambda (game dt)
                       (when (= (game-frame game) 3) (error "update failed in frame" 3)))))
(game-run! game frames: 10)
(display "not reached\n")
