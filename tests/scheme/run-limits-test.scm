;;; What a script can do to a running game (issue 35): re-entering game-run!,
;;; runaway recursion in a hook, and sizes past the bounds. Each case asserts
;;; the exact error text.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke))

(load "support.scm")

(test-begin "run-limits")

;;; ---------------------------------------------------------------- re-entry
(define inner-error #f)
(define outer
  (make-game title: "outer"
             update: (lambda (game dt)
                       (unless inner-error
                         (set! inner-error (error-text (lambda () (game-run! game frames: 10))))))))
(game-run! outer frames: 3)
(test-equal "game-run! on the running game, from its update:, is refused naming game-run!"
  "In procedure game-run!: a game is already running (this one): game-run! cannot start a game from inside a running game's hooks or REPL; run games one after another\n"
  inner-error)
(test-equal "… and the outer game ran on" 3 (game-frame outer))

(define other-error #f)
(define host
  (make-game title: "host"
             update: (lambda (game dt)
                       (unless other-error
                         (set! other-error (error-text (lambda () (game-run! (make-game) frames: 1))))))))
(game-run! host frames: 1)
(test-equal "… and so is starting another game from inside one, naming the running one"
  "In procedure game-run!: a game is already running (host): game-run! cannot start a game from inside a running game's hooks or REPL; run games one after another\n"
  other-error)

(define first-game (make-game))
(define second-game (make-game))
(game-run! first-game frames: 5)
(game-run! second-game frames: 7)
(game-run! first-game frames: 8)
(test-equal "two games run one after the other, and the first again after"
  '(8 7) (list (game-frame first-game) (game-frame second-game)))

(test-end "run-limits")
