;; SPDX-License-Identifier: 0BSD
;;; The game's tests: `downstroke test' runs every tests/*-test.scm.
;;; A game is a pure function of its input, so each test plays a fresh game
;;; headless with an input script and checks exact values.
(use-modules (downstroke testing))
(load "../game.scm")

(define (player game) (car (scene-entities (game-scene game))))

(test-begin "game")

(test-group "the built-in run"
  (let ((game (play (new-game) frames: 300)))
    (test-equal "it picks up all four coins" 4 (entity-ref (player game) #:coins))
    (test-equal "and no coin is left" '() (cdr (scene-entities (game-scene game))))
    (test-equal "each coin rang" 4 (length (filter (lambda (s) (eq? (cdr s) 'coin)) (game-sounds game))))))

(test-group "standing still"
  (let ((game (play (new-game) frames: 60 input: '((0 . ())))))
    (test-equal "the player lands on the ground and stays" 208 (entity-ref (player game) #:y))
    (test-assert "on the ground" (entity-ref (player game) #:on-ground?))))

(test-group "a jump"
  ;; Pressed at frame 5, once: up and back down.
  (let ((game (play (new-game) frames: 40 input: '((0 . ()) (5 . (a)) (6 . ())))))
    (test-equal "it played the jump sound" '(jump) (map cdr (game-sounds game)))
    (test-equal "and landed where it rose" 208 (entity-ref (player game) #:y))))

(test-end "game")
