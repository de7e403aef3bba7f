;; SPDX-License-Identifier: MIT
;;; (downstroke pause) — pausing a game, and the input clock that keeps
;;; counting the ticks it spends paused. docs/engine.org, "Pause".
(define-module (downstroke pause)
  #:use-module (downstroke history)
  #:use-module (downstroke game)
  #:export (game-paused-set! input-clock note-paused-tick! rewind-input-clock!))

;;; A paused game ticks at its frame rate as it runs, but a tick steps
;;; nothing: it reads input, calls the paused: hook and render:, and the
;;; frame counter, the scene and the history stay as they were. Input is
;;; read and recorded by the input clock, which counts every tick, paused
;;; or not (frame + paused ticks): an input script can unpause a game, and
;;; a session with pauses is recorded and replays as it was played.

(define (game-paused-set! game on?)
  "Pause GAME (ON? true) or go on (#f) from its next tick. While paused, a
tick calls the paused: hook (make-game paused:) and render: with the tick's
input, and nothing steps: not engine-update: nor update: (so no physics, no
tweens), not the frame counter, not the history. Going on does not catch up:
the next tick steps the frame the game stood at."
  (check-game "game-paused-set!" game)
  (%game-paused-set! game (and on? #t)))

(define (input-clock game)
  ;; The tick the input of the coming tick is read and recorded at.
  (+ (game-frame game) (game-paused-ticks game)))

(define (note-paused-tick! game)
  ;; One more tick paused at the game's frame; the first at a frame leaves
  ;; a mark of the ticks paused before it. The marks are only for rewinds,
  ;; which go back at most history-size frames: that many marks (one a
  ;; frame at most) are all a rewind can need.
  (let ((ticks (game-paused-ticks game))
        (newest (bounded-log-newest (game-pause-marks game) 1))
        (frame (game-frame game)))
    (unless (and (pair? newest) (= (caar newest) frame))
      (game-pause-marks-set! game (bounded-log-push (game-pause-marks game) (cons frame ticks)
                                                    (+ (game-history-size game) 1))))
    (game-paused-ticks-set! game (+ ticks 1))))

(define (rewind-input-clock! game frame)
  ;; Back to the input clock FRAME had when it was stepped: the ticks paused
  ;; before the first pause after FRAME (a pause at FRAME came before its
  ;; step, and counts).
  (let loop ((marks (bounded-log-items (game-pause-marks game))) (later #f))
    (if (and (pair? marks) (> (caar marks) frame))
        (loop (cdr marks) (car marks))
        (when later
          (game-pause-marks-set! game (list->bounded-log marks))
          (game-paused-ticks-set! game (cdr later))))))
