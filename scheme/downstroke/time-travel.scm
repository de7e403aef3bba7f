;; SPDX-License-Identifier: MIT
;;; (downstroke time-travel) — the scenes of past frames, and going back
;;; to one. docs/engine.org, "Time travel: history and game-rewind!".
(define-module (downstroke time-travel)
  #:use-module ((srfi srfi-1) #:select (filter))
  #:use-module (downstroke history)
  #:use-module (downstroke game)
  #:use-module ((downstroke pause) #:select (rewind-input-clock!))
  #:export (remember-scene! game-history game-rewind!))

;;; Scenes are values, so keeping the past costs one pointer per frame.

;;; The history runs for as long as the game does: it is a bounded log
;;; (downstroke history).

(define (remember-scene! game)
  "Record the scene as it is at the start of the coming frame."
  (let ((n (game-history-size game)))
    (when (> n 0)
      (game-history-log-set! game (bounded-log-push (game-history-log game)
                                                    (cons (game-frame game) (game-scene game)) n)))))

(define (game-history game)
  "The remembered (frame . scene) pairs, newest first: the scene each frame
started from."
  (bounded-log-newest (game-history-log game) (game-history-size game)))

(define (game-rewind! game k)
  "Go back K frames: the scene becomes the one frame (current − K) started
from, and the game continues from that frame (its input script included).
Returns that frame's number."
  (check-game "game-rewind!" game)
  ;; Checked before (- frame k), whose error would name Guile's -.
  (unless (and (exact-integer? k) (> k 0))
    (scm-error 'wrong-type-arg "game-rewind!" "k: expected an exact integer of frames > 0, got ~S"
               (list k) #f))
  (let* ((target (- (game-frame game) k))
         (past (game-history game))
         (entry (assv target past)))
    (unless entry
      (scm-error 'out-of-range "game-rewind!"
                 "cannot go back ~S frames: ~S remembered (make-game history: N)"
                 (list k (length past)) #f))
    (game-scene-set! game (cdr entry))
    (game-frame-set! game target)
    (rewind-input-clock! game target)
    ;; Forget the future we left: the next frames record it anew.
    (game-history-log-set! game (list->bounded-log (filter (lambda (e) (< (car e) target)) past)))
    target))
