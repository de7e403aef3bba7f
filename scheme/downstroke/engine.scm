;; SPDX-License-Identifier: MIT
;;; (downstroke engine) — a game: make-game fills in the record, and
;;; game-run! runs it through the loop kernel on the back end the host chose
;;; (headless, capture or window). Each concern of a running game is a
;;; module of its own, re-exported here as the engine's interface:
;;;   (downstroke game)        the record, its checks and setters
;;;   (downstroke loop)        the fixed-step kernel
;;;   (downstroke headless)    headless and capture runs; runs that end
;;;   (downstroke window)      runs in a window
;;;   (downstroke frame)       one step: engine-update, update, camera, render
;;;   (downstroke hook-errors) a hook's bounds, and its errors in a served game
;;;   (downstroke frame-hooks) procedures called every frame
;;;   (downstroke input)       actions held, the pointer, input scripts checked
;;;   (downstroke recording)   replaying and recording input
;;;   (downstroke pause)       pausing, and the input clock
;;;   (downstroke time-travel) history and game-rewind!
;;;   (downstroke sound)       sounds and music
;;;   (downstroke drawing)     the overlay, captures, pixels
;;;   (downstroke costs)       engine-stats and the collector
;;;   (downstroke misspelt-keys) slips of engine keys
;;;   (downstroke script-arguments) what the script was started with
;;;   (downstroke script-reload) the script evaluated again in the running game
;;; docs/engine.org, "make-game" and "A complete game".
(define-module (downstroke engine)
  #:use-module (downstroke native)
  #:use-module (downstroke render)
  #:use-module (downstroke history)
  #:use-module (downstroke game)
  #:use-module (downstroke input)
  #:use-module (downstroke recording)
  #:use-module (downstroke pause)
  #:use-module (downstroke time-travel)
  #:use-module (downstroke sound)
  #:use-module (downstroke costs)
  #:use-module (downstroke script-arguments)
  #:use-module ((downstroke script-reload) #:select (reload-script! game-watch-script! once script-reloading? arm-script-watch!))
  #:use-module (downstroke hook-errors)
  #:use-module ((downstroke live) #:select (game-watch-maps! watch-default))
  #:use-module (downstroke frame-hooks)
  #:use-module (downstroke drawing)
  #:use-module (downstroke misspelt-keys)
  #:use-module (downstroke frame)
  #:use-module (downstroke headless)
  #:use-module (downstroke window)
  #:export (make-game game-run!)
  #:re-export (game? game-title game-width game-height game-frame-delay
               game-scene game-scene-set! game-input game-frame game-sounds
               game-collision-mode game-collision-mode-set! game-push-rule game-push-rule-set!
               game-substeps game-substeps-set! game-resting-contacts? game-resting-contacts-set!
               game-update game-update-set! game-engine-update game-engine-update-set!
               input-pressed? input-held? input-released? play-sound
               play-music stop-music music-volume-set! sound-volume-set! game-music
               input-mouse mouse-world-position game-fullscreen-set! game-fullscreen?
               default-engine-update camera-follow!
               game-history game-rewind! add-frame-hook! remove-frame-hook!
               game-paused? game-paused-set!
               strict-games frame-pacing hook-error-reporter hook-time-limit main-script? script-number-argument engine-stats
               gc-space-divisor set-gc-space-divisor!
               game-debug-draw? game-debug-draw-set! game-capture game-pixel game-input-log
               input-held-actions input-log->script record-input read-input-script
               reload-script! game-watch-script! once))


;; A hook's Scheme stack, in bytes. Guile grows its stack on demand without
;; bound, so a recursion that never ends used to take about a minute and
;; 8 GB before it failed; 64 MiB is over a million frames of ordinary
;; recursion, and is reached in about a second.
(define default-stack-limit (* 64 1024 1024))
(define max-game-pixels (expt 2 26))          ; the renderer's kMaxCanvasPixels
(define min-stack-limit (* 1024 1024))        ; below this the engine's own calls may not fit
(define max-stack-limit (* 4 1024 1024 1024)) ; past this the bound no longer bounds memory
;; A step longer than a minute is a typo (seconds written for ms), and a
;; paced loop sleeps a step at a time: a REPL served into the game answers
;; only between two steps.
(define max-frame-delay 60000)

(define* (make-game #:key (title "Downstroke") (width 640) (height 480)
                    (frame-delay 16) (scene #f) (update #f) (render #f)
                    (engine-update default-engine-update)
                    (collision-mode 'swept) (push-rule 'clipped) (substeps 1) (resting-contacts? #f)
                    (input-script '()) (history 0) (input-map #f) (background #f)
                    (stack-limit default-stack-limit) (pause-when-unfocused? #f) (interpolate? #t)
                    (strict? (strict-games)) (paused #f))
  "A game. ENGINE-UPDATE runs before UPDATE every frame: the default steps
physics, #f disables it, a procedure (game dt) replaces it. SUBSTEPS k splits
each physics frame into k sub-frames; RESTING-CONTACTS? keeps stacks at
rest (both off by default). PUSH-RULE 'clipped (the default) keeps
push-apart from leaving a body in a solid cell; 'seed is the seed's rule
(see push-rule). HISTORY keeps the scenes of
that many past frames for game-rewind!. WIDTH × HEIGHT is the picture in
pixels (a window shows it scaled up). INPUT-MAP binds keys, controller and
mouse inputs to actions in a window, as ((action name …) …) — see
default-input-map, which is used when it is #f; a click in the
INPUT-SCRIPT, (mouse x y (left)), holds the actions bound to \"mouse:left\"
as a real one does (middle and right likewise). BACKGROUND, (r g b), is the
colour a frame is cleared to; #f uses the map's backgroundcolor, else the
engine's (24 28 40). STACK-LIMIT is the Scheme stack, in bytes, each hook
(engine-update, update, render, a frame hook) may use: past it the hook
raises stack-overflow naming itself (64 MiB by default).
PAUSE-WHEN-UNFOCUSED? stops the game's steps while its window has lost the
keyboard focus; it resumes where it stopped, with no burst of catch-up
steps. INTERPOLATE? (in a window) draws each entity and the camera between
their last two steps, at the fraction of a step the clock has run, so
motion is smooth at any refresh rate; physics is not touched, and headless
runs and captures draw the stepped state. STRICT? makes an entity key that
is a slip of an engine key (#:sensr? for #:sensor?) an error instead of a
warning; it defaults to (strict-games), which `downstroke test' sets.
PAUSED, (lambda (game dt) …) or #f, is called instead of ENGINE-UPDATE and
UPDATE in each tick while the game is paused (game-paused-set!): input and
RENDER go on, nothing steps."
  (unless (and (exact-integer? history) (>= history 0))
    (scm-error 'wrong-type-arg "make-game" "history: expected a count of frames ≥ 0, got ~S"
               (list history) #f))
  (for-each (lambda (name v)
              (unless (and (exact-integer? v) (<= 1 v 16384))
                (scm-error 'wrong-type-arg "make-game" "~A: expected an exact integer from 1 to 16384 (pixels), got ~S"
                           (list name v) #f)))
            '(width height) (list width height))
  ;; A frame is width × height × 4 bytes, drawn and captured whole: bounded
  ;; as the renderer's canvas is (kMaxCanvasPixels, 256 MiB).
  (unless (<= (* width height) max-game-pixels)
    (scm-error 'wrong-type-arg "make-game"
               "width × height: expected at most ~a pixels (256 MiB a frame), got ~a × ~a"
               (list max-game-pixels width height) #f))
  (check-substeps "make-game" substeps)
  (check-collision-mode "make-game" collision-mode)
  (check-push-rule "make-game" push-rule)
  (unless (and (exact-integer? stack-limit) (<= min-stack-limit stack-limit max-stack-limit))
    (scm-error 'wrong-type-arg "make-game"
               "stack-limit: expected an exact integer of bytes from ~a (1 MiB) to ~a (4 GiB), got ~S"
               (list min-stack-limit max-stack-limit stack-limit) #f))
  ;; dt is frame-delay ms, and the window's clock divides by it: a frame
  ;; takes some time, and time runs forwards.
  (unless (and (real? frame-delay) (not (nan? frame-delay)) (< 0 frame-delay) (<= frame-delay max-frame-delay))
    (scm-error 'wrong-type-arg "make-game" "frame-delay: expected a number of ms > 0 and at most ~a (a minute), got ~S"
               (list max-frame-delay frame-delay) #f))
  (check-input-script "make-game" input-script)
  (check-scene-or-false "make-game" scene)
  (for-each (lambda (what proc) (check-hook-or-false "make-game" what proc))
            '(update render engine-update paused) (list update render engine-update paused))
  (let ((display (and (renderer-available?) (%make-display width height)))
        ;; Without the renderer, no input-map: means no map is known (its
        ;; default-input-map is ()): queries are not checked against it.
        (bindings (and (or input-map (renderer-available?))
                       (map-bindings (or input-map (default-input-map))))))
    (when display
      (%display-set-input-map! display (or input-map (default-input-map)))
      (%display-set-background! display background))
    (let ((game (%make-game title width height frame-delay scene update render engine-update
                            collision-mode push-rule substeps (and resting-contacts? #t)
                            (make-input '() '() bindings) input-script #f 0 (make-bounded-log) (make-bounded-log)
                            history (make-bounded-log)
                            display #f empty-input-log stack-limit (and pause-when-unfocused? #t)
                            (and interpolate? #t) (and strict? #t) (make-hash-table) bindings
                            #f paused 0 (make-bounded-log) #f)))
      (when (debug-draw-default) (game-debug-draw-set! game #t))
      (when (watch-default) (game-watch-maps! game #t))
      ;; Slips decoded before this game was made (a step-scene of its own)
      ;; are not this game's.
      (%take-key-slips)
      game)))

(define (check-frames frames)
  (unless (or (not frames) (and (real? frames) (not (nan? frames))))
    (scm-error 'wrong-type-arg "game-run!"
               "frames: expected #f or a frame count, got ~S" (list frames) #f)))

(define* (game-run! game #:key (frames #f))
  "Run GAME at a fixed timestep (dt = frame-delay ms): input, then
engine-update, update, camera follow, render — until the game's frame
counter reaches FRAMES (so a second call with the same FRAMES runs nothing
more), or until the 'quit action is held. FRAMES is #f (run until quit) or
a real number, +inf.0 meaning the same as #f. Headless, a run that nothing
ends (no FRAMES, no quit in its input script) is warned of as it starts, on
the warning port; `downstroke --frames N' ends each headless run after N
frames at most.

How frames are shown is the host's choice: headless by default (input from
input-script:, nothing drawn, as deterministic as the physics); in a window
with `downstroke --window' (real time, keyboard and controllers, sound;
closing the window quits); or drawn off-screen into PNG files with
`downstroke --capture DIR'.

Games run one after another: game-run! while a game is running (from its
hooks, or from a REPL served into it) is an error. While the script is
evaluated again (reload-script!), game-run! runs nothing and returns the
running game (GAME when none runs): the game goes on where it was."
  (check-game "game-run!" game)
  (check-frames frames)
  (if (script-reloading?)
      (or (current-game) game)
      (run-game! game frames)))

(define (run-game! game frames)
  ;; One frame loop at a time: game-run! from a hook or a REPL evaluation of
  ;; a running game would nest a loop in its frame, and again in that one's.
  (when (current-game)
    (scm-error 'misc-error "game-run!"
               "a game is already running (~A): game-run! cannot start a game from inside a running game's hooks or REPL; run games one after another"
               (list (if (eq? (current-game) game) "this one" (game-title (current-game)))) #f))
  (arm-script-watch! game)
  (parameterize ((current-game game)
                 (current-display (game-display game)))
    (case (display-mode)
      ((window) (run-window! game frames))
      ((capture) (warn-if-endless! game frames)
                 (run-headless! game (headless-end game frames) (capture-directory)))
      (else (warn-if-endless! game frames)
            (run-headless! game (headless-end game frames) #f)))
    game))
