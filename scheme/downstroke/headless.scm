;; SPDX-License-Identifier: MIT
;;; (downstroke headless) — the headless and capture back ends of the loop:
;;; input from the game's input script, one step a turn on a clock that each
;;; turn moves on by exactly a step (so a run is as deterministic as the
;;; physics), kept to wall-clock time only under frame-pacing; a capture
;;; draws each frame stepped into a PNG. And the bound on runs that nothing
;;; ends. docs/render.org, "Three ways to run a game", and docs/engine.org,
;;; "Runs that end".
(define-module (downstroke headless)
  #:use-module ((srfi srfi-1) #:select (any))
  #:use-module (downstroke native)
  #:use-module (downstroke game)
  #:use-module ((downstroke pause) #:select (input-clock))
  #:use-module ((downstroke recording) #:select (scripted-held!))
  #:use-module ((downstroke frame) #:select (step-game!))
  #:use-module ((downstroke frame-hooks) #:select (run-frame-hooks! frame-pacing))
  #:use-module ((downstroke hook-errors) #:select (step-or-pause!))
  #:use-module ((downstroke live) #:select (poll-watched-files!))
  #:use-module ((downstroke drawing) #:select (draw-game!))
  #:use-module (downstroke loop)
  #:export (run-headless! warn-if-endless! headless-end headless-frame-limit game-served?))

;;; Headless, nobody closes a window: a game-run! that nothing ends runs
;;; until the process is killed, and a test or a CI job hangs without a word.

;; The most frames one headless game-run! runs, counted from the frame it
;; starts at, or #f: the host's --frames N. In a window the player ends it.
;; This and game-served? are the host's, not a game's: (downstroke) does
;; not export them.
(define headless-frame-limit (make-parameter #f))

;; #t while a REPL is served into the game (the host's --repl-server and
;; --repl-port): its author ends it from there, so running on is asked for.
(define game-served? (make-parameter #f))

(define (script-quits? script)
  ;; An input script ends a run when one of its entries holds quit.
  (any (lambda (entry) (memq 'quit (cdr entry))) script))

(define (warn-if-endless! game frames)
  (unless (or (and frames (finite? frames)) (headless-frame-limit) (game-served?)
              (script-quits? (game-input-script game)))
    (format (current-warning-port)
            "game-run!: warning: ~s runs headless until quit, and nothing quits it (no frames:, no quit in its input script): pass frames: N, or run it with downstroke --frames N~%"
            (game-title game))))

(define (headless-end game frames)
  ;; The frame a headless run stops at: FRAMES, or sooner under the host's limit.
  (let ((limit (headless-frame-limit)))
    (if limit
        (let ((cap (+ (game-frame game) limit)))
          (if (and frames (< frames cap)) frames cap))
        frames)))

(define (frame-file dir frame)
  (string-append dir "/" (string-pad (number->string frame) 6 #\0) ".png"))

(define (run-headless! game frames capture-dir)
  (let* ((dt (game-frame-delay game))
         (tick (step-ticks dt))
         ;; The loop's clock: where the last turn's wait moved it, a step a
         ;; turn. Under frame-pacing each wait also sleeps until the same
         ;; time on the real clock, counted from the run's start.
         (now 0)
         (real-start (real-clock))
         ;; Paused ticks do not bring the frame counter to FRAMES: a run makes
         ;; at most as many as the frames it was asked for, so a game paused
         ;; for good still ends.
         (pause-budget (and frames (finite? frames) (max 0 (- frames (game-frame game)))))
         (paused 0))
    (run-fixed-step!
     #:clock (lambda () now)
     #:sleep-until (lambda (t)
                     (set! now t)
                     (when (frame-pacing) (wait-until (+ real-start (round t)))))
     #:tick tick #:period tick
     #:poll (lambda ()
              (run-frame-hooks! game)
              (poll-watched-files! game)
              (let ((held (scripted-held! game (input-clock game))))
                (and (or (not frames) (< (game-frame game) frames)) (not (memq 'quit held))
                     (not (and (game-paused? game) pause-budget (>= paused pause-budget)))
                     (cons held #t))))
     #:step (lambda (held)
              (let ((frame (game-frame game)) (paused? (game-paused? game)))
                (when (and (step-or-pause! game (lambda () (step-game! game dt held)))
                           capture-dir (not paused?))
                  (draw-game! game)
                  (%display-save-png (game-display game) (frame-file capture-dir frame)))
                (when paused? (set! paused (+ paused 1)))))
     ;; One step a turn, and the poll before it checked the end.
     #:finished? (lambda () #f)
     #:present (lambda (elapsed alpha dropped) #t))))
