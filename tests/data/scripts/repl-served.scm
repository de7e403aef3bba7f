;; SPDX-License-Identifier: MIT
;;; A game for tests/scheme/repl-server-test.scm to drive from the REPL: a
;;; box nothing moves, paced frames. It ends when an update hook exits, or
;;; with status 3 after 3000 frames (48 s), so a failed test cannot leave it.
(define game
  (make-game frame-delay: 16
             scene: (make-scene entities: (list '(#:id box #:x 0 #:y 0 #:width 8 #:height 8)))
             update: (lambda (game dt) #t)))
(display "ready\n") (force-output)
(game-run! game frames: 3000)
(display "timeout\n")
(exit 3)
