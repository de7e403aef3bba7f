;; SPDX-License-Identifier: MIT
;;; A served game whose script fails after its game loop: for
;;; tests/scheme/repl-server-test.scm to see that an error that ends the
;;; script still removes the REPL socket.
(define game (make-game frame-delay: 16 update: (lambda (game dt) #t)))
(display "ready\n") (force-output)
(game-run! game frames: 3)
(error "the script failed after its game")
