;; SPDX-License-Identifier: MIT
;;; Pause (game-paused-set!): paused ticks step nothing — not the physics,
;;; not the frame counter, not the history — but read input, call the
;;; paused: hook and render:, and unpausing goes on where the game stood.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke))

(load "support.scm")

(test-begin "pause")

(define faller '(#:x 0 #:y 0 #:width 8 #:height 8 #:gravity? #t))
(define (y-of game) (entity-ref (car (scene-entities (game-scene game))) #:y))

(define (toggle! game)
  (when (input-pressed? (game-input game) 'pause)
    (game-paused-set! game (not (game-paused? game)))))

;;; P goes down in tick 3 (update: pauses after frame 3's physics) and again
;;; in tick 6 (paused: goes on): ticks 4, 5 and 6 are paused, at frame 4.
(define seen '())      ; (frame y scene) in each paused tick, newest first
(define rendered 0)
(define (pausing-game script)
  (make-game input-map: '((pause "P") (quit "Escape"))
             history: 20
             scene: (make-scene entities: (list faller))
             input-script: script
             update: (lambda (game dt) (toggle! game))
             paused: (lambda (game dt)
                       (set! seen (cons (list (game-frame game) (y-of game) (game-scene game)) seen))
                       (toggle! game))
             render: (lambda (game) (set! rendered (+ rendered 1)))))
(define script '((0) (3 pause) (4) (6 pause) (7)))
(define game (pausing-game script))
(game-run! game frames: 10)

(test-equal "three paused ticks, all at frame 4, the body where frame 3 left it"
  '((4 10) (4 10) (4 10))
  (map (lambda (s) (list-head s 2)) (reverse seen)))
(test-assert "… and the very same scene in each"
  (every (lambda (s) (eq? (caddr s) (caddr (car seen)))) seen))
(test-equal "the run ends at frame 10, after 13 ticks, rendered in each" '(10 13) (list (game-frame game) rendered))
(test-equal "unpausing does not catch up: the body is where 10 unpaused frames put it"
  (let ((plain (make-game scene: (make-scene entities: (list faller)))))
    (game-run! plain frames: 10)
    (y-of plain))
  (y-of game))
(test-equal "55 px: 1 + 2 + … + 10" 55 (y-of game))
(test-equal "the history holds frames, not paused ticks" '(9 8 7 6 5 4 3 2 1 0)
  (map car (game-history game)))
(test-equal "the input log has one entry a tick, paused ones too"
  '(() () () (pause) () () (pause) () () () () () ())
  (game-input-log game))

;;; The recording replays as played: the same pauses at the same frames.
(set! seen '())
(define replay (pausing-game (input-log->script (game-input-log game))))
(game-run! replay frames: 10)
(test-equal "a recording with pauses replays them" '((4 10) (4 10) (4 10) 55 10)
  (append (map (lambda (s) (list-head s 2)) (reverse seen)) (list (y-of replay) (game-frame replay))))

;;; A rewind goes back to the input clock the frame had when it stepped.
(game-rewind! game 7)
(test-equal "a rewind to before the pause" '(3 6) (list (game-frame game) (y-of game)))
(set! seen '())
(game-run! game frames: 10)
(test-equal "… replays the pause from the script, and ends where the first run did"
  '((4 10) (4 10) (4 10) 55 10)
  (append (map (lambda (s) (list-head s 2)) (reverse seen)) (list (y-of game) (game-frame game))))

(define input-clock (@@ (downstroke engine) input-clock))
(test-equal "a rewind to after the pause keeps its three ticks: frame 7 at tick 10" '(7 10)
  (begin (game-rewind! game 3) (list (game-frame game) (input-clock game))))
(test-equal "a rewind to the paused frame itself: its pause came before its step" '(4 7)
  (begin (game-rewind! game 3) (list (game-frame game) (input-clock game))))
(game-run! game frames: 10)
(test-equal "… and the game plays on to the same end" '(10 13 55) (list (game-frame game) (input-clock game) (y-of game)))

;;; Paused for good: headless runs still end (at most FRAMES paused ticks).
(define ticks 0)
(define stuck (make-game input-map: '((pause "P"))
                         scene: (make-scene entities: (list faller))
                         update: (lambda (game dt) (game-paused-set! game #t))
                         paused: (lambda (game dt) (set! ticks (+ ticks 1)))))
(game-run! stuck frames: 5)
(test-equal "paused for good after frame 0: the run ends after 5 paused ticks" '(1 5 1)
  (list (game-frame stuck) ticks (y-of stuck)))
(test-assert (game-paused? stuck))
(game-paused-set! stuck #f)
(game-run! stuck frames: 5)
(test-equal "unpaused from outside, it steps one frame and pauses again" '(2 9 3)
  (list (game-frame stuck) ticks (y-of stuck)))

(test-equal "In procedure game-paused-set!: game: expected a game (make-game), got 1\n"
  (error-text (lambda () (game-paused-set! 1 #t))))
(test-assert (mentions? (error-text (lambda () (make-game paused: (lambda (game) #t)))) "make-game" "paused"))

(test-end "pause")
