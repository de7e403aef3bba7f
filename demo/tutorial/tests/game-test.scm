;; SPDX-License-Identifier: 0BSD
;;; The tutorial's tests (docs/tutorial.org, where they are made from).
(use-modules (downstroke testing))
(load "../game.scm")

(define tests-dir (dirname (current-filename)))
(define (player game) (car (scene-entities (game-scene game))))

(define level-1-run
  '((0 . ()) (10 . (right))
    (38 . (right a)) (39 . (right))      ; jump: a coin in the air, then onto the plank
    (70 . ())                            ; wait there for the walker to come back
    (152 . (right))                      ; off the plank's end, onto its head
    (258 . (right a)) (259 . (right))))  ; over to the second one, and on to the door

(test-begin "tutorial")

(test-group "level 1, played through"
  (let ((game (play (new-game) frames: 345 input: level-1-run)))
    (test-equal "it is in level 2" "level2.tmx" (entity-ref (player game) #:level))
    (test-equal "with the two coins it picked up" 2 (entity-ref (player game) #:coins))
    (test-equal "what it did, frame by frame"
      '((38 . jump) (41 . coin) (61 . coin) (168 . stomp) (258 . jump) (287 . stomp) (339 . door))
      (game-sounds game))

    (test-assert "and level 2 looks as it did"
      (check-frame game (string-append tests-dir "/level2.png")))))

(test-group "running into a walker"
  (let ((game (play (new-game) frames: 100 input: '((0 . ()) (10 . (right))))))
    (test-equal "hurts once" '((89 . hurt)) (game-sounds game))
    (test-equal "and starts the level again" 45 (entity-ref (player game) #:x))))

(test-group "the last door"
  (let* ((game (new-game))
         (scene (level-scene "level2.tmx" 4))
         (near-door (entity-set (car (scene-entities scene)) #:x 760)))
    (game-scene-set! game (update-scene scene entities: (cons near-door (cdr (scene-entities scene)))))
    (play game frames: 30 input: '((0 . (right))))
    (test-assert "wins" (entity-ref (player game) #:won?))
    (test-equal "and the player stops there" 0 (entity-ref (player game) #:vx))))

(test-group "pause"
  (let ((paused (play (new-game) frames: 30
                      input: '((0 . ()) (10 . (right)) (20 . (right pause)) (21 . (right))
                               (25 . (right pause)) (26 . (right)))))
        (never (play (new-game) frames: 30 input: '((0 . ()) (10 . (right))))))
    (test-equal "30 frames in 35 ticks, not paused at the end" '(30 35 #f)
      (list (game-frame paused) (length (game-input-log paused)) (game-paused? paused)))
    (test-equal "where a game never paused is" (entity-ref (player never) #:x) (entity-ref (player paused) #:x))))

(test-end "tutorial")
