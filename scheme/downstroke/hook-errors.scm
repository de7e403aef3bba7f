;; SPDX-License-Identifier: MIT
;;; (downstroke hook-errors) — the bounds on a game's hooks (stack, and time
;;; when the host sets one) and, in a game served to a REPL, what an error
;;; in a hook does. docs/engine.org, "The frame".
(define-module (downstroke hook-errors)
  #:use-module ((srfi srfi-1) #:select (every))
  #:use-module ((system vm vm) #:select (call-with-stack-overflow-handler))
  #:use-module (downstroke error-text)
  #:use-module (downstroke game)
  #:export (call-bounded call-reporting hook-error-reporter hook-time-limit step-or-pause! retry-failed-frame!))

(define (call-bounded game what thunk)
  ;; (THUNK) with at most the game's stack-limit of stack: past it, a
  ;; stack-overflow error naming WHAT (the hook) instead of growing on.
  ;; And within the host's time limit, when it sets one: around the stack
  ;; bound, since an overflow leaves the frames under it without running
  ;; their dynamic-wind exits (the limit's would stay armed).
  (define (bounded)
    (call-with-stack-overflow-handler
     (quotient (game-stack-limit game) 8)  ; in words of 8 bytes
     thunk
     (lambda ()
       (scm-error 'stack-overflow what
                  "the hook used up its ~a MiB of Scheme stack (make-game stack-limit:): a recursion that never ends?"
                  (list (quotient (game-stack-limit game) (* 1024 1024))) #f))))
  (let ((limit (hook-time-limit)))
    (if limit (limit what bounded) (bounded))))

;;; In a game served to a REPL an error in a hook must not end the session
;;; its author is working in. The host then sets hook-error-reporter (a
;;; procedure taking the report's text); a failing frame hook is removed,
;;; and a failing frame leaves the game paused on it, as it started, until
;;; a hook or the scene is replaced (from the REPL), or the script is
;;; reloaded, when it runs again.

(define hook-error-reporter (make-parameter #f))

;; A served game's hooks are also bounded in time: the host sets this to a
;; procedure (WHAT THUNK) that runs the hook WHAT ("update:" …) and
;; interrupts it with an error past the REPL's limit, so an endless hook
;; pauses the game instead of freezing it and the REPL.
(define hook-time-limit (make-parameter #f))

;; game → what it failed with: its hooks and scene then (see game-levers)
(define paused-on (make-object-property))

(define (retry-failed-frame! game)
  ;; GAME, paused on a failing frame, runs it again at its next tick: its
  ;; code has changed in a way the levers do not show (a reload of the
  ;; script, script-reload.scm, redefining a procedure a hook calls by name).
  (set! (paused-on game) #f))

(define (game-levers game)
  (list (game-engine-update game) (game-update game) (game-render game) (game-scene game)
        (game-paused-update game)))

(define (call-reporting what thunk on-error)
  ;; (system repl debug) is named with @, so it loads at the first failure:
  ;; loaded with the engine, it and the VM's debugging modules it brings were
  ;; 0.8 MB of live data that every collection of every game marked, about
  ;; 1.5 ms a collection (docs/engine.org).
  ;; THUNK's value; or, if it raises an error, (on-error) once (WHAT) — a
  ;; line saying what failed —, the backtrace and the error are reported.
  ;; (exit) is no error.
  (let ((frames #f))
    (catch #t
      (lambda () (start-stack 'hook (thunk)))
      (lambda (key . args)
        (when (eq? key 'quit) (apply throw key args))
        ((hook-error-reporter)
         (call-with-output-string
          (lambda (port)
            (format port "downstroke: ~a:~%" (what))
            (display (frames-text frames) port)
            (print-error port key args))))
        (on-error))
      (lambda (key . args)
        ;; The frames from the hook on, as Guile's REPL narrows them: the
        ;; game loop's around it are always the same.
        ;; A stack overflow's frames are the runaway recursion, a million
        ;; of the same: its report is the error alone.
        (unless (memq key '(quit stack-overflow))
          (let ((tag (cdr (fluid-ref %stacks))))
            (set! frames ((@ (system repl debug) narrow-stack->vector) (make-stack #t) 3 tag 0 1))))))))

(define (frames-text frames)
  ;; FRAMES printed, or "" — also when Guile cannot print them: those of a
  ;; hook interrupted by a signal (hook-time-limit) fail in frame-local-ref.
  (if frames
      (catch #t
        (lambda ()
          (call-with-output-string
           (lambda (port) ((@ (system repl debug) print-frames) frames port))))
        (lambda _ ""))
      ""))

(define (step-or-pause! game step!)
  ;; (STEP!) steps GAME one tick; #t when it ran.
  (cond ((not (hook-error-reporter)) (step!) #t)
        ((and (paused-on game) (every eq? (paused-on game) (game-levers game))) #f)
        (else (set! (paused-on game) #f) (step-reporting! game step!))))

(define (step-reporting! game step!)
  (let ((frame (game-frame game)) (scene (game-scene game))
        (input (game-input game)) (history (game-history-log game))
        (paused-ticks (game-paused-ticks game)) (marks (game-pause-marks game)))
    (call-reporting (lambda ()
                      (format #f "a hook raised an error in frame ~a; the game is paused on it until \
a hook (game-update-set! ...) or the scene (game-scene-set! ...) is replaced" frame))
                    (lambda () (step!) #t)
                    (lambda ()
                      (game-scene-set! game scene)
                      (game-input-set! game input)
                      (game-history-log-set! game history)
                      (game-frame-set! game frame)
                      (game-paused-ticks-set! game paused-ticks)
                      (game-pause-marks-set! game marks)
                      (set! (paused-on game) (game-levers game))
                      #f))))
