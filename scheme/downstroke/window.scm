;; SPDX-License-Identifier: MIT
;;; (downstroke window) — the window back end of the loop: real time, input
;;; from the keyboard, controllers and mouse, each presented frame drawn
;;; between the last two steps; and the window's own settings.
;;; docs/render.org, "Three ways to run a game" and "The window: resizing,
;;; fullscreen, focus".
(define-module (downstroke window)
  #:use-module (downstroke native)
  #:use-module (downstroke world)
  #:use-module ((downstroke render) #:select (window-fullscreen window-scale frame-log-file record-file))
  #:use-module (downstroke game)
  #:use-module ((downstroke recording) #:select (record-input input-log-full-at))
  #:use-module ((downstroke frame) #:select (step-game!))
  #:use-module ((downstroke frame-hooks) #:select (run-frame-hooks!))
  #:use-module ((downstroke hook-errors) #:select (step-or-pause!))
  #:use-module ((downstroke live) #:select (poll-watched-files!))
  #:use-module ((downstroke drawing) #:select (draw-game! game-debug-draw-set!))
  #:use-module (downstroke loop)
  #:export (run-window! game-fullscreen-set! game-fullscreen?))

(define (game-fullscreen-set! game on?)
  "Show GAME fullscreen (ON? true) or in its window, now if its window is
open, else when it opens (F11 and Alt+Return toggle it too)."
  (check-game "game-fullscreen-set!" game)
  (let ((display (game-display game)))
    (if display (%display-set-fullscreen! display (and on? #t)) #f)))

(define (game-fullscreen? game)
  "Whether GAME is (or, before its window opens, will be) fullscreen."
  (check-game "game-fullscreen?" game)
  (let ((display (game-display game)))
    (and display (%display-fullscreen? display))))

;; What the step before left, for drawing between it and this one:
;; (entities camera-x camera-y).
(define (state-of game)
  (let ((scene (game-scene game)))
    (and scene (list (scene-entities scene) (camera-x (scene-camera scene)) (camera-y (scene-camera scene))))))

(define (open-frame-log)
  (let ((file (frame-log-file)))
    (and file (open-output-file file))))

;; --record writes the recording this often while the game runs, not only
;; as it ends, so that a crash or a kill keeps what was played but these
;; last seconds. Each write is of the whole log (renamed into place, never
;; half a file), in time that grows with it: so not more often.
(define record-interval-seconds 5)

(define (run-window! game frames)
  ;; The window presents at the display's refresh rate, not the step's:
  ;; each entity and the camera are drawn between the last two steps, α of
  ;; the way (the share of a step the clock holds), so motion is smooth at
  ;; 60, 75, 120 or 144 Hz.
  (let* ((display (game-display game))
         (dt (game-frame-delay game))
         (tick (step-ticks dt))
         (done? (lambda () (and frames (>= (game-frame game) frames)))))
    (when (window-fullscreen) (%display-set-fullscreen! display #t))
    (%display-open-window! display (game-title game) (window-scale))
    (%open-audio! #t)
    (let ((present (round (/ internal-time-units-per-second (%display-refresh-rate display))))
          (log (open-frame-log))
          (saved 0)      ; when the --record file was last written, since the start
          (before #f))   ; the state the last step started from (state-of)
      (when log
        (format log "# ~a Hz, ~a~%" (%display-refresh-rate display)
                (if (%display-vsync? display) "presented on vsync" "paced by the loop (no vsync)")))
      (dynamic-wind
        (lambda () #t)
        (lambda ()
          (run-fixed-step!
           #:clock real-clock #:sleep-until wait-until #:tick tick #:period present
           #:pause-when-unfocused? (game-pause-when-unfocused? game)
           #:poll (lambda ()
                    (run-frame-hooks! game)
                    (poll-watched-files! game)
                    (let* ((polled (%display-poll! display))
                           (mouse (list-ref polled 3))
                           (held (if mouse (append (car polled) (list (cons 'mouse mouse))) (car polled))))
                      (when (odd? (caddr polled))
                        (game-debug-draw-set! game (not (game-debug-draw? game))))
                      (and (not (or (cadr polled) (memq 'quit held) (done?)))
                           (cons held (list-ref polled 4)))))
           #:step (lambda (held)
                    (let ((then (state-of game)))
                      (step-or-pause! game (lambda () (step-game! game dt held)))
                      (set! before then)))
           #:finished? done?
           #:present
           (lambda (elapsed alpha dropped)
             (draw-game! game (and (game-interpolate? game) before
                                   (list (car before) alpha (cadr before) (caddr before))))
             (when (and (record-file) (not (input-log-full-at (%game-input-log game)))
                        (> (- elapsed saved) (* record-interval-seconds internal-time-units-per-second)))
               ;; A write that fails (the disk full, the folder gone) is
               ;; said and the game plays on: the write as it ends tries
               ;; again.
               (catch 'misc-error
                 (lambda () (record-input game (record-file)))
                 (lambda (key who fmt args . _)
                   (format (current-error-port) "downstroke: --record: ~a~%" (apply format #f fmt args))))
               (set! saved elapsed))
             (when log
               (format log "~a ~a ~a ~a~%"
                       ;; The frame's clock: the time its steps and α were taken at.
                       (/ (round (/ (* 1000000 elapsed) internal-time-units-per-second)) 1000.)
                       (game-frame game) (/ (round (* 10000 alpha)) 10000.) dropped)))))
        (lambda ()
          (when log (close-port log))
          (when (record-file) (record-input game (record-file)))
          (%display-close-window! display))))))
