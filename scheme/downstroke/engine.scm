;;; (downstroke engine) — the game record and its frame loop.
(define-module (downstroke engine)
  #:use-module (downstroke error-text)
  #:use-module (srfi srfi-1)
  #:use-module (srfi srfi-9)
  #:use-module ((system vm vm) #:select (call-with-stack-overflow-handler))
  #:use-module (downstroke entity)
  #:use-module (downstroke world)
  #:use-module (downstroke physics)
  #:use-module (downstroke tilemap)
  #:use-module (downstroke history)
  #:use-module (downstroke render)
  #:use-module (downstroke arity)
  #:use-module (downstroke tool-files)
  #:use-module ((downstroke native)
                #:select (%frame-stats %gc-space-divisor %set-gc-space-divisor! %make-display
                          %display-draw! %display-stats %display-save-png %display-pixel
                          %display-set-background!
                          %display-clear-commands! %display-set-input-map! %display-poll!
                          %display-open-window! %display-close-window! %open-audio!
                          %display-set-fullscreen! %display-fullscreen? %display-refresh-rate %display-vsync?
                          %play-sound %play-music %stop-music %set-volume!
                          %note-pushed-pairs! %max-substeps %take-key-slips))
  #:export (make-game game? game-title game-width game-height game-frame-delay
            game-scene game-scene-set! game-input game-frame game-sounds
            game-collision-mode game-collision-mode-set!
            game-substeps game-substeps-set! game-resting-contacts? game-resting-contacts-set!
            game-update game-update-set! game-engine-update game-engine-update-set!
            input-pressed? input-held? input-released? play-sound
            play-music stop-music music-volume-set! sound-volume-set! game-music
            input-mouse mouse-world-position game-fullscreen-set! game-fullscreen?
            default-engine-update camera-follow! game-run!
            game-history game-rewind! add-frame-hook! remove-frame-hook!
            game-paused? game-paused-set!
            strict-games frame-pacing hook-error-reporter hook-time-limit main-script? script-number-argument engine-stats
            gc-space-divisor set-gc-space-divisor!
            game-debug-draw? game-debug-draw-set! game-capture game-pixel game-input-log))

;;; What a game's input map binds, for its input to check queries against
;;; and complete scripted clicks with. BOUND holds each action some key,
;;; button or mouse input names: a query of any other action is a
;;; misspelling or a missing binding, as no player can hold it, and is
;;; warned about once per game (WARNED). CLICKS is ((action button …) …),
;;; in the map's order: the actions a mouse button holds, so a scripted
;;; click holds them as a real one does (scripted-held!).
(define-record-type <bindings>
  (make-bindings bound warned clicks)
  bindings?
  (bound bindings-bound)      ; hashq: action → #t
  (warned bindings-warned)    ; hashq: action → #t, once warned about
  (clicks bindings-clicks))

;; The button a mouse input's name holds, as input-mouse lists it: names
;; are read in any case, as the renderer reads them (parse_binding).
(define mouse-button-names '(("mouse:left" . left) ("mouse:middle" . middle) ("mouse:right" . right)))

(define (map-bindings map)
  ;; MAP is as %display-set-input-map! accepted it; a build without the
  ;; renderer checks nothing, so what is not (action name …) is passed over.
  (let ((bound (make-hash-table)))
    (let loop ((entries (if (list? map) map '())) (clicks '()))
      (if (null? entries)
          (make-bindings bound (make-hash-table) (reverse clicks))
          (let* ((entry (car entries))
                 (names (if (and (list? entry) (pair? entry) (symbol? (car entry)))
                            (filter string? (cdr entry))
                            '()))
                 (buttons (filter-map (lambda (name) (assoc-ref mouse-button-names (string-downcase name)))
                                      names)))
            (unless (null? names) (hashq-set! bound (car entry) #t))
            (loop (cdr entries)
                  (if (null? buttons) clicks (cons (cons (car entry) buttons) clicks))))))))

(define (warn-unbound! bindings who action)
  (hashq-set! (bindings-warned bindings) action #t)
  (let ((bound (sort (hash-map->list (lambda (action _) (symbol->string action)) (bindings-bound bindings))
                     string<?)))
    (format (current-warning-port)
            "~a: warning: no key, button or mouse input in the game's input map holds the action '~a, so only an input script can; the map binds ~a~%"
            who action (if (null? bound) "none" (string-join bound " ")))))

;;; Input: what is held this frame, and what was held the frame before,
;;; with the game's bindings (#f when they are not known: no renderer and
;;; no input-map:).
(define-record-type <input>
  (make-input held previous bindings)
  input?
  (held input-held-list)
  (previous input-previous-list)
  (bindings input-bindings))

(define (check-action who input action)
  ;; A query of a bound action costs one hash lookup; the rest is the rare
  ;; path: a wrong argument, no known map, or an action to warn about once
  ;; per game.
  (let ((bindings (and (input? input) (input-bindings input))))
    (unless (and bindings (hashq-ref (bindings-bound bindings) action))
      (check-unbound-action who input action))))

(define (check-unbound-action who input action)
  (unless (input? input)
    (scm-error 'wrong-type-arg who "input: expected a game's input (game-input), got ~S" (list input) #f))
  (unless (symbol? action)
    (scm-error 'wrong-type-arg who "action: expected a symbol, got ~S" (list action) #f))
  (let ((bindings (input-bindings input)))
    (when (and bindings (not (hashq-ref (bindings-warned bindings) action)))
      (warn-unbound! bindings who action))))

(define (input-held? input action)
  "Whether ACTION (a symbol) is held this frame. Asking for an action that
no key, button or mouse input of the game's input map holds prints a
warning naming it and the actions the map binds, once per action and game:
no player could hold it, only an input script."
  (check-action "input-held?" input action)
  (and (memq action (input-held-list input)) #t))
(define (input-pressed? input action)
  "Whether ACTION went down this frame (held now, not the frame before);
an action the input map does not bind is warned about as by input-held?."
  (check-action "input-pressed?" input action)
  (and (memq action (input-held-list input)) (not (memq action (input-previous-list input))) #t))
(define (input-released? input action)
  "Whether ACTION went up this frame (held the frame before, not now); an
action the input map does not bind is warned about as by input-held?."
  (check-action "input-released?" input action)
  (and (memq action (input-previous-list input)) (not (memq action (input-held-list input))) #t))

;;; The pointer rides in the held list as one element (mouse x y buttons),
;;; so the input log records it and a script replays it as it does keys.
(define (mouse-element held) (find (lambda (x) (and (pair? x) (eq? (car x) 'mouse))) held))

(define (input-mouse input)
  "Where the pointer is in this frame, as (x y buttons): x and y in the game
picture's own pixels (the window's scale and bars taken out), buttons the
list of those held (left middle right). #f when the pointer is not over the
picture (or there is no window, and the input script holds no mouse)."
  (let ((m (mouse-element (input-held-list input))))
    (and m (cdr m))))

(define-record-type <game>
  (%make-game title width height frame-delay scene update render engine-update
              collision-mode substeps resting-contacts
              input input-script script-cursor frame sounds music history-size history
              display debug-draw input-log stack-limit pause-when-unfocused interpolate
              strict slips-warned bindings paused paused-update paused-ticks pause-marks)
  game?
  (title game-title)
  (width game-width)
  (height game-height)
  (frame-delay game-frame-delay)
  (scene game-scene %game-scene-set!)
  (update game-update %game-update-set!)
  (render game-render)
  (engine-update game-engine-update %game-engine-update-set!)
  (collision-mode game-collision-mode %game-collision-mode-set!)
  (substeps game-substeps %game-substeps-set!)
  (resting-contacts game-resting-contacts? game-resting-contacts-set!)
  (input game-input game-input-set!)
  (input-script game-input-script game-input-script-set!)
  (script-cursor game-script-cursor game-script-cursor-set!)  ; where the replay is (scripted-held!), or #f
  (frame game-frame game-frame-set!)
  (sounds game-sound-log game-sound-log-set!)  ; (count . ((frame . name) …)), newest first
  (music game-music-log game-music-log-set!)   ; a bounded log of (frame . event), newest first
  (history-size game-history-size)
  (history game-history-log game-history-log-set!)  ; a bounded log of (frame . scene)
  (display game-display)            ; the renderer's, or #f in a build without it
  (debug-draw game-debug-draw? %game-debug-draw-set!)
  (input-log %game-input-log %game-input-log-set!)  ; an <input-log>: (frame . held) at each change
  (stack-limit game-stack-limit)    ; bytes of Scheme stack each hook may use
  (pause-when-unfocused game-pause-when-unfocused?)
  (interpolate game-interpolate?)
  (strict game-strict?)             ; a misspelt entity key is an error, not a warning
  (slips-warned game-slips-warned)  ; the misspelt keys warned of, a hash table: once each
  (bindings game-bindings)          ; a <bindings> of its input map, or #f when it is not known
  (paused game-paused? %game-paused-set!)      ; game-paused-set!: ticks run the paused: hook, not a frame
  (paused-update game-paused-update)          ; (game dt) called in each paused tick, or #f
  ;; Ticks spent paused so far: the input clock (input-clock) counts them.
  (paused-ticks game-paused-ticks game-paused-ticks-set!)
  ;; A bounded log of (frame . the ticks paused before the pause at that
  ;; frame), newest first: where a rewind finds the input clock of its frame.
  (pause-marks game-pause-marks game-pause-marks-set!))

(define (default-engine-update game dt)
  "One physics pass over the game's scene (step-scene), with the game's
collision mode, substeps and resting contacts."
  (let ((scene (game-scene game)))
    (when scene
      (parameterize ((collision-mode (game-collision-mode game))
                     (resting-contacts? (game-resting-contacts? game)))
        (game-scene-set! game (step-scene scene dt #:substeps (game-substeps game)))))))

;;; Refused where they are passed, not frames later inside the loop, where
;;; the error would name struct-vtable or camera-follow!.
(define (check-game who game)
  (unless (game? game)
    (scm-error 'wrong-type-arg who "game: expected a game (make-game), got ~S" (list game) #f)))

(define (check-scene-or-false who scene)
  (unless (or (not scene) (scene? scene))
    (scm-error 'wrong-type-arg who "scene: expected a scene (make-scene) or #f, got ~S" (list scene) #f)))

(define (check-procedure-or-false who what proc)
  (unless (or (not proc) (procedure? proc))
    (scm-error 'wrong-type-arg who "~A: expected a procedure or #f, got ~S" (list what proc) #f)))

;; The arguments the frame loop calls each of a game's hooks with
;; (step-game!): one home, for the checks and the messages.
(define hook-arguments '((engine-update game dt) (update game dt) (render game) (paused game dt)))

(define (check-hook-or-false who what proc)
  (check-procedure-or-false who what proc)
  (when proc (check-hook who what proc (assq-ref hook-arguments what))))

(define (mouse-entry? x)
  ;; (mouse x y buttons): the pointer in picture pixels and the buttons held.
  (and (pair? x) (eq? (car x) 'mouse) (list? x) (= (length x) 4)
       ;; A pointer at infinity or NaN has no pixel: camera arithmetic on it
       ;; gives NaN positions to the game's code.
       (real? (cadr x)) (real? (caddr x)) (finite? (cadr x)) (finite? (caddr x))
       (list? (cadddr x)) (every (lambda (b) (memq b '(left middle right))) (cadddr x))))

(define (input-script-entry? entry)
  (and (pair? entry) (exact-integer? (car entry)) (>= (car entry) 0)
       (list? (cdr entry))
       (every (lambda (x) (or (symbol? x) (mouse-entry? x))) (cdr entry))
       (<= (count pair? (cdr entry)) 1)))

(define (check-input-script who script)
  ;; A replay walks it (scripted-held!): a circular script would hang the game.
  (unless (list? script)
    (scm-error 'wrong-type-arg who "input-script: expected a list of (frame . actions), got ~S"
               (list script) #f))
  (let ((bad (find (negate input-script-entry?) script)))
    (when bad
      (scm-error 'wrong-type-arg who
                 "input-script: expected (frame . actions), a frame ≥ 0 and a list of symbols and at most one (mouse x y buttons), got ~S"
                 (list bad) #f)))
  ;; Entries are key frames, replayed in order: one for an earlier frame
  ;; than the entry before it would be held from that entry's frame on, not
  ;; its own, and of two for one frame only the later would count. Both are
  ;; refused, naming the two frames; entries are counted from 0.
  (let loop ((s script) (i 0) (before #f))
    (when (pair? s)
      (let ((frame (caar s)))
        (when (and before (<= frame before))
          (scm-error 'wrong-type-arg who
                     "input-script: entry ~a is for frame ~a, after an entry for frame ~a: frames must increase"
                     (list i frame before) #f))
        (loop (cdr s) (+ i 1) frame)))))

(define (game-scene-set! game scene)
  "Make SCENE (a scene, or #f for none) GAME's scene from now on."
  (check-game "game-scene-set!" game)
  (check-scene-or-false "game-scene-set!" scene)
  (%game-scene-set! game scene))

(define (game-update-set! game update)
  "Make UPDATE, (lambda (game dt) …) or #f, GAME's update from the next frame on."
  (check-game "game-update-set!" game)
  (check-hook-or-false "game-update-set!" 'update update)
  (%game-update-set! game update))

(define (game-engine-update-set! game engine-update)
  "Make ENGINE-UPDATE, (lambda (game dt) …) or #f, run first in GAME's frames."
  (check-game "game-engine-update-set!" game)
  (check-hook-or-false "game-engine-update-set!" 'engine-update engine-update)
  (%game-engine-update-set! game engine-update))

;; Checked where it is given, not first in a frame, where the error would
;; name the collision-mode parameter and come frames after the typo.
(define collision-modes '(swept discrete))

(define (check-collision-mode who mode)
  (unless (memq mode collision-modes)
    (scm-error 'wrong-type-arg who "collision-mode: expected one of ~S, got ~S"
               (list collision-modes mode) #f)))

(define (game-collision-mode-set! game mode)
  "Make MODE ('swept or 'discrete) GAME's collision mode from the next frame on."
  (check-game "game-collision-mode-set!" game)
  (check-collision-mode "game-collision-mode-set!" mode)
  (%game-collision-mode-set! game mode))

(define (check-substeps who k)
  (unless (and (exact-integer? k) (<= 1 k %max-substeps))
    (scm-error 'wrong-type-arg who "substeps: expected an exact integer from 1 to ~S, got ~S"
               (list %max-substeps k) #f)))

(define (game-substeps-set! game k)
  "Split GAME's physics frames into K sub-frames from the next frame on."
  (check-substeps "game-substeps-set!" k)
  (%game-substeps-set! game k))

(define* (make-game #:key (title "Downstroke") (width 640) (height 480)
                    (frame-delay 16) (scene #f) (update #f) (render #f)
                    (engine-update default-engine-update)
                    (collision-mode 'swept) (substeps 1) (resting-contacts? #f)
                    (input-script '()) (history 0) (input-map #f) (background #f)
                    (stack-limit default-stack-limit) (pause-when-unfocused? #f) (interpolate? #t)
                    (strict? (strict-games)) (paused #f))
  "A game. ENGINE-UPDATE runs before UPDATE every frame: the default steps
physics, #f disables it, a procedure (game dt) replaces it. SUBSTEPS k splits
each physics frame into k sub-frames; RESTING-CONTACTS? keeps stacks at
rest (both off by default). HISTORY keeps the scenes of
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
                            collision-mode substeps (and resting-contacts? #t)
                            (make-input '() '() bindings) input-script #f 0 (make-bounded-log) (make-bounded-log)
                            history (make-bounded-log)
                            display #f empty-input-log stack-limit (and pause-when-unfocused? #t)
                            (and interpolate? #t) (and strict? #t) (make-hash-table) bindings
                            #f paused 0 (make-bounded-log))))
      (when (debug-draw-default) (game-debug-draw-set! game #t))
      ;; Slips decoded before this game was made (a step-scene of its own)
      ;; are not this game's.
      (%take-key-slips)
      game)))

;;; ---------------------------------------------------------------- time travel
;;; Scenes are values, so keeping the past costs one pointer per frame.

;;; The history and the sound log run for as long as the game does: both are
;;; bounded logs (downstroke history).

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

;;; ---------------------------------------------------------------- pause
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

;;; ---------------------------------------------------------------- costs

(define (engine-stats game)
  "What the last physics frame cost, step by step: a list of
(step processed skipped ms) — decode (reading the entities), each step of the
frame in order (tweens acceleration gravity speed-limits velocity-x
tile-collisions-x velocity-y tile-collisions-y on-solid entity-collisions
groups), and encode
(writing back what changed). PROCESSED counts the entities a step applied
to; SKIPPED those it left alone (skip-pipelines, no #:gravity?, no speed on
a tile step's axis, not solid, not in a group); for encode, the entities
handed back as new plists and those handed back as they were. Then
(collect collections bytes ms): the collections that ran during the frame,
the bytes it allocated (Boehm's count, exact to a few KB) and the time the
collections took, which the decode and encode times leave out. It is the
last step-scene run on this thread, which for a running game is its own
last frame. A last row (render drawn culled ms) says what drawing the last
frame cost: tiles, sprites, boxes and commands drawn, entities not drawn
(outside the view, hidden, or with neither a picture nor a #:color), and
time (zeros until a frame is drawn, and always in a build without the
renderer)."
  (let ((display (game-display game)))
    (append (%frame-stats) (list (if display (%display-stats display) '(render 0 0 0.0))))))

;;; Memory against time: how often the collector runs. A frame of a big scene
;;; allocates fresh plist heads, and each collection marks the whole live
;;; scene, so collecting less often is faster at the price of a larger heap.
(define (gc-space-divisor)
  "The collector's free-space divisor: it collects after allocating about
twice the live heap divided by this (1 = least often). Downstroke starts it
at 1 (Boehm's own default is 3) unless the GC_FREE_SPACE_DIVISOR environment
variable is set."
  (%gc-space-divisor))

(define (set-gc-space-divisor! n)
  "Sets the free-space divisor to N, an exact integer from 1 to 1000: larger
means a smaller heap and more time collecting. Affects the whole process."
  (%set-gc-space-divisor! n))

;;; ---------------------------------------------------------------- scripts

(define (main-script? name)
  "Whether the script the host was started with is named NAME (its base
name): a file can define a game for others to load and run it only when it
is the program itself."
  (let ((args (program-arguments)))
    (and (pair? args) (string? (car args)) (string=? (basename (car args)) name))))

(define (script-number-argument n default)
  "The script's Nth argument (from 0) as a number, or DEFAULT: e.g. how many
frames to run, as in `downstroke demo/sandbox.scm 3600'."
  (let* ((args (program-arguments))
         (arg (and (> (length args) (+ n 1)) (list-ref args (+ n 1))))
         (v (and arg (string->number arg))))
    (or v default)))

;;; ---------------------------------------------------------------- frame hooks
;;; Procedures of no arguments called once at the start of every frame on the
;;; game's thread: the host polls its REPL server from here.

(define frame-hooks '())
(define (add-frame-hook! proc)
  "Call PROC, a procedure of no arguments, at the start of every frame of
every game run from now on, after the hooks added before it."
  (unless (procedure? proc)
    (scm-error 'wrong-type-arg "add-frame-hook!" "proc: expected a procedure of no arguments, got ~S"
               (list proc) #f))
  (check-hook "add-frame-hook!" "proc" proc '())
  (set! frame-hooks (append frame-hooks (list proc))))
(define (remove-frame-hook! proc)
  "Stop calling PROC (the very procedure add-frame-hook! was given) each frame."
  (set! frame-hooks (delete proc frame-hooks eq?)))

;; #t: game-run! keeps to wall-clock time (frame-delay ms per frame), as a
;; game someone is watching or poking from a REPL must; #f: as fast as it can.
(define frame-pacing (make-parameter #f))

(define (wait-until deadline)
  ;; usleep takes an exact count of µs: a deadline off a flonum frame-delay
  ;; is rounded to one.
  (let ((now (get-internal-real-time)))
    (when (< now deadline)
      (usleep (round (/ (* (- (inexact->exact deadline) now) 1000000) internal-time-units-per-second))))))

(define (step-ticks game)
  ;; One step in internal time units, exact (a flonum frame-delay taken as
  ;; the exact number it is): the loops' deadlines and counts of steps due
  ;; are then exact integers, as usleep and the step loop need.
  (* (inexact->exact (game-frame-delay game)) (/ internal-time-units-per-second 1000)))

;; A game that runs for hours must not keep every sound it ever played.
(define *sounds-kept* 4096)

(define (game-sounds game)
  "The sounds played lately, as (frame . name), oldest first: at least the
newest 4096 (older ones are dropped, so a long run stays in bounded memory)."
  (reverse (bounded-log-items (game-sound-log game))))

(define (play-sound game-or-name . rest)
  "Play a sound: (play-sound 'jump) in the running game, (play-sound game
'jump) naming it. It is recorded with the frame it was played in (see
game-sounds) and, when a window is open and load-sound loaded it, heard."
  (let ((game (if (game? game-or-name) game-or-name (current-game)))
        (name (if (game? game-or-name) (car rest) game-or-name)))
    (when game
      (game-sound-log-set! game (bounded-log-push (game-sound-log game)
                                                  (cons (game-frame game) name) *sounds-kept*)))
    ;; Heard only with a window open; a sound never loaded is only recorded.
    (when (and (symbol? name) (renderer-available?)) (%play-sound name))))

(define (game-music game)
  "The music events lately, oldest first, as (frame . event): (play NAME
LOOP? FADE-IN-MS), (stop FADE-OUT-MS), (music-volume V) and (sound-volume
V). Recorded headless as in a window, so a test sees what a player would
hear; at least the newest 4096 are kept."
  (reverse (bounded-log-items (game-music-log game))))

(define (note-music! event)
  (let ((game (current-game)))
    (when game
      (game-music-log-set! game (bounded-log-push (game-music-log game)
                                                  (cons (game-frame game) event) *sounds-kept*)))))

;; A fade longer than ten minutes is a typo (seconds for milliseconds, say).
(define *max-fade-ms* 600000)

(define (check-fade who what ms)
  (unless (and (real? ms) (not (nan? ms)) (<= 0 ms *max-fade-ms*))
    (scm-error 'wrong-type-arg who "~A: expected a number of ms from 0 to ~A, got ~S"
               (list what *max-fade-ms* ms) #f)))

(define (check-volume who v)
  (unless (and (real? v) (not (nan? v)) (<= 0 v 1))
    (scm-error 'wrong-type-arg who "volume: expected a number from 0 to 1, got ~S" (list v) #f)))

(define* (play-music name #:key (loop? #t) (fade-in 0))
  "Play the music NAME (load-music), in place of any playing: looping unless
LOOP? is #f, fading in over FADE-IN ms. Recorded in game-music; heard when
a window is open. #f when no music of that name was loaded."
  (unless (symbol? name)
    (scm-error 'wrong-type-arg "play-music" "name: expected a symbol, got ~S" (list name) #f))
  (check-fade "play-music" "fade-in" fade-in)
  (note-music! (list 'play name (and loop? #t) fade-in))
  (and (renderer-available?) (%play-music name (and loop? #t) fade-in)))

(define* (stop-music #:key (fade-out 0))
  "Stop the music, fading out over FADE-OUT ms."
  (check-fade "stop-music" "fade-out" fade-out)
  (note-music! (list 'stop fade-out))
  (when (renderer-available?) (%stop-music fade-out)))

(define (music-volume-set! v)
  "The music's volume, from 0 (silent) to 1 (as recorded, the default)."
  (check-volume "music-volume-set!" v)
  (note-music! (list 'music-volume v))
  (when (renderer-available?) (%set-volume! 'music v)))

(define (sound-volume-set! v)
  "Every sound's volume, from 0 (silent) to 1 (as recorded, the default)."
  (check-volume "sound-volume-set!" v)
  (note-music! (list 'sound-volume v))
  (when (renderer-available?) (%set-volume! 'sound v)))

(define current-game (make-parameter #f))

(define (mouse-world-position game)
  "Where the pointer is in GAME's world this frame, as (x y): input-mouse's
point through the scene's camera. #f when the pointer is not over the
picture."
  (check-game "mouse-world-position" game)
  (let ((m (input-mouse (game-input game)))
        (scene (game-scene game)))
    (and m (let ((camera (and scene (scene-camera scene))))
             (if camera
                 (list (+ (car m) (camera-x camera)) (+ (cadr m) (camera-y camera)))
                 (list (car m) (cadr m)))))))

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

(define (entity-tagged entities target)
  (find (lambda (e) (or (equal? (entity-ref e #:id) target)
                        (equal? (entity-ref e #:tag) target)))
        entities))

(define (check-target-number target key v)
  ;; Checked before the arithmetic, whose error would name Guile's + or /.
  (unless (and (real? v) (let ((d (exact->inexact v))) (not (or (nan? d) (inf? d)))))
    (scm-error 'wrong-type-arg "camera-follow!"
               "the camera target ~S: ~S: expected a finite number within a double's range, got ~S"
               (list target key v) #f)))

(define (camera-follow! game)
  "Centre the scene's camera on its camera-target entity, keeping the view
inside the level: never left of or above the origin, and — when the scene
has a tilemap — never past the map's right or bottom edge."
  (check-game "camera-follow!" game)
  (let* ((scene (game-scene game))
         (target (and scene (scene-camera-target scene)))
         (e (and target (entity-tagged (scene-entities scene) target))))
    (when e
      (for-each (lambda (key) (check-target-number target key (entity-ref e key 0)))
                '(#:x #:y #:width #:height))
      (let* ((camera (scene-camera scene))
             (tm (scene-tilemap scene))
             (limit (lambda (cells tile view)
                      (and tm (max 0 (- (* (cells tm) (tile tm)) view)))))
             (clamp (lambda (v hi) (max 0 (if hi (min v hi) v)))))
        (camera-x-set! camera
                       (clamp (- (+ (entity-ref e #:x 0) (/ (entity-ref e #:width 0) 2))
                                 (/ (game-width game) 2))
                              (limit tilemap-width tilemap-tile-width (game-width game))))
        (camera-y-set! camera
                       (clamp (- (+ (entity-ref e #:y 0) (/ (entity-ref e #:height 0) 2))
                                 (/ (game-height game) 2))
                              (limit tilemap-height tilemap-tile-height (game-height game))))))))

;;; Replaying: a cursor into the script, kept from frame to frame, so a
;;; replay walks its script once. Walking it from its head every frame made
;;; a replay quadratic: 10^5 key frames took 27 s (docs/limits.org,
;;; "Recordings").
(define-record-type <script-cursor>
  (make-script-cursor script ahead held since)
  script-cursor?
  (script cursor-script)                  ; the script it walks
  (ahead cursor-ahead cursor-ahead-set!)  ; the entries not passed yet
  (held cursor-held cursor-held-set!)     ; the actions of the last entry passed; () before the first
  (since cursor-since cursor-since-set!)) ; that entry's frame; -1 before the first

(define (scripted-held! game frame)
  ;; The actions of the last script entry at or before FRAME: entries are
  ;; key frames, in increasing order (check-input-script). The cursor holds
  ;; for any frame from its last key frame on; an earlier frame (a rewind)
  ;; or another script (play input:) starts a walk from the head.
  (let* ((script (game-input-script game))
         (kept (game-script-cursor game))
         (cursor (if (and kept (eq? (cursor-script kept) script) (>= frame (cursor-since kept)))
                     kept
                     (let ((fresh (make-script-cursor script script '() -1)))
                       (game-script-cursor-set! game fresh)
                       fresh))))
    (let pass ()
      (let ((ahead (cursor-ahead cursor)))
        (when (and (pair? ahead) (<= (caar ahead) frame))
          (cursor-held-set! cursor (with-clicked-actions (cdar ahead) (game-bindings game)))
          (cursor-since-set! cursor (caar ahead))
          (cursor-ahead-set! cursor (cdr ahead))
          (pass))))
    (cursor-held cursor)))

;;; A scripted click holds what the input map binds to its buttons, as a
;;; real click in a window does: HELD's actions, then those it lacks in the
;;; map's order, then its pointer. A recording made in a window holds them
;;; already and comes back as it is (eq?), so it replays frame for frame.
(define (with-clicked-actions held bindings)
  (let* ((pointer (mouse-element held))
         (buttons (if pointer (cadddr pointer) '()))
         (clicked (if (and bindings (pair? buttons))
                      (fold (lambda (click acc)
                              (if (and (any (lambda (b) (memq b buttons)) (cdr click))
                                       (not (memq (car click) held))
                                       (not (memq (car click) acc)))
                                  (cons (car click) acc)
                                  acc))
                            '() (bindings-clicks bindings))
                      '())))
    (if (null? clicked)
        held
        (append (remove pair? held) (reverse clicked) (list pointer)))))

;;; Recording input, to replay a run exactly (a bug report, a determinism test).

;;; The input log: each change of the actions held, as (frame . held) from
;;; that frame on, newest first. Every change is kept, from frame 0 on, up
;;; to a bound; a log that reaches it stops there and says so, and a
;;; recording of it replays up to that frame and quits. (It used to keep the
;;; newest 65536 changes, cut from 131072: a long session was then recorded
;;; from its middle and replayed as if that were frame 0.)
(define-record-type <input-log>
  (make-input-log count changes full-at)
  input-log?
  (count input-log-count)        ; how many changes it holds
  (changes input-log-changes)    ; (frame . held) at each change, newest first
  (full-at input-log-full-at))   ; the first frame it did not record, once at the bound; else #f

(define empty-input-log (make-input-log 0 '() #f))

;; The bound is for memory: a change of a key or two keeps about 70 bytes,
;; one with the pointer (its (mouse x y buttons) entry) about 150. Moving
;; the pointer changes the input every frame, so 2^21 changes are 9.7 hours
;; of it at 60 frames a second, in about 320 MB; keys alone change a few
;; times a second, days of play. (Figures: docs/limits.org, "Recordings".)
(define *max-input-changes* (expt 2 21))

(define (forget-from log frame)
  ;; A rewind replays from an earlier frame: forget what was recorded from
  ;; it on (and that the log was full, if it filled there or later).
  (let ((changes (input-log-changes log)) (full-at (input-log-full-at log)))
    (if (or (and (pair? changes) (>= (caar changes) frame)) (and full-at (>= full-at frame)))
        (let forget ((changes changes) (count (input-log-count log)))
          (if (and (pair? changes) (>= (caar changes) frame))
              (forget (cdr changes) (- count 1))
              (make-input-log count changes #f)))
        log)))

(define (record-input! game frame held)
  (let* ((log (forget-from (%game-input-log game) frame))
         (changes (input-log-changes log)))
    (%game-input-log-set!
     game
     (cond ((and (pair? changes) (lset= equal? (cdar changes) held)) log)
           ((input-log-full-at log) log)
           ((< (input-log-count log) *max-input-changes*)
            (make-input-log (+ (input-log-count log) 1) (cons (cons frame held) changes) #f))
           (else
            (format (current-error-port)
                    "downstroke: the input log holds ~a changes, its bound: the input from frame ~a on is not recorded, and a recording (record-input, --record) replays frames 0 to ~a and quits~%"
                    *max-input-changes* frame (- frame 1))
            (make-input-log (input-log-count log) changes frame))))))

(define (game-input-log game)
  "The actions held in each frame played so far, one list per frame, from
frame 0 on (and one per tick the game was paused, game-paused-set!): give it
to input-log->script to replay a played session headless, frame for frame. A log that reached its bound (2^21 changes of
input) ends at the frame before the first it did not record."
  (let* ((log (%game-input-log game))
         (end (if (input-log-full-at log) (min (input-log-full-at log) (input-clock game)) (input-clock game))))
    (let loop ((changes (input-log-changes log)) (frame end) (acc '()))
      ;; CHANGES is newest first: each (start . held) holds from START on.
      (if (null? changes)
          acc
          (let* ((start (caar changes)) (n (max 0 (- frame start))))
            (loop (cdr changes) (min frame start) (append (make-list n (cdar changes)) acc)))))))

(define (recorded-script game)
  ;; input-log->script of game-input-log, straight from the changes, in
  ;; time and memory proportional to their number (game-input-log takes a
  ;; pair a frame played). Changes at or after the game's frame were undone
  ;; by a rewind. A full log's script ends in quit at the first frame it did
  ;; not record, so its replay stops where the recording did.
  (let* ((log (%game-input-log game))
         (full-at (input-log-full-at log))
         (end (if full-at (min full-at (input-clock game)) (input-clock game)))
         (kept (drop-while (lambda (c) (>= (car c) end)) (input-log-changes log))))
    (reverse (if (and full-at (< full-at (input-clock game))) (cons (list full-at 'quit) kept) kept))))

(define (input-held-actions input)
  "The list of actions held in INPUT's frame: what an input log records."
  (input-held-list input))

(define (input-log->script log)
  "The input script that replays LOG, a list of the actions held in each
frame from frame 0 on: a key frame (frame . actions) for frame 0 and for
every frame whose set of held actions differs from the frame before."
  (let loop ((log log) (frame 0) (previous #f) (acc '()))
    (cond ((null? log) (reverse acc))
          ((and previous (lset= equal? previous (car log))) (loop (cdr log) (+ frame 1) previous acc))
          (else (loop (cdr log) (+ frame 1) (car log) (cons (cons frame (car log)) acc))))))

(define (record-input game file)
  "Write GAME's input so far to FILE as an input script (input-log->script
of game-input-log), which read-input-script reads back: a session played in
a window replays headless, frame for frame. `downstroke --window --record
FILE' writes it when the game ends. Every change of input is kept up to
2^21; a session with more is written up to the frame the bound was reached,
where the script quits, and record-input says so on the error port."
  (check-game "record-input" game)
  (unless (string? file)
    (scm-error 'wrong-type-arg "record-input" "file: expected a string, got ~S" (list file) #f))
  (let* ((script (recorded-script game))
         (full-at (input-log-full-at (%game-input-log game)))
         (cut (and full-at (< full-at (input-clock game)) full-at)))  ; where the script quits
    (call-with-output-file/whole "record-input" file
      (lambda (port)
        (format port ";;; The input of ~s, ~a frames, as an input script (record-input).~%" (game-title game)
                (input-clock game))
        (when cut
          (format port ";;; Frames 0 to ~a only: the input log reached its bound of ~a changes, and the script quits at frame ~a.~%"
                  (- cut 1) *max-input-changes* cut))
        ;; An entry a line: Guile's write of the whole list takes time
        ;; quadratic in its length (0.9 s for 25 000 entries, 3.2 s for
        ;; 50 000, 8.5 to 12 s for 10^5).
        (display "(" port)
        (let write-entries ((entries script) (first? #t))
          (when (pair? entries)
            (unless first? (display "\n " port))
            (write (car entries) port)
            (write-entries (cdr entries) #f)))
        (display ")\n" port)))
    (when cut
      (format (current-error-port)
              "downstroke: record-input: ~s holds frames 0 to ~a of ~a: the input log reached its bound of ~a changes, and the script quits at frame ~a~%"
              file (- cut 1) (input-clock game) *max-input-changes* cut))
    script))

;; The largest input script read-input-script reads: a recording at the
;; input log's bound, 2^21 changes, each a line of at most about 120 bytes
;; (a frame number, a few actions, the pointer with its buttons), is 252 MB.
(define max-input-script-bytes (* 256 1024 1024))

(define (error-args->text key args)
  ;; What a caught error says, as Guile prints it (for a read error, with
  ;; the file, line and column); KEY alone when its arguments are not the
  ;; usual (who message message-args …).
  (or (and (= (length args) 4) (string? (cadr args)) (list? (caddr args))
           (false-if-exception (apply format #f (cadr args) (caddr args))))
      (object->string key)))

(define (skip-blanks-and-comments port)
  ;; Past white space and ; comments, to where a datum would start.
  (let ((c (peek-char port)))
    (cond ((eof-object? c))
          ((char-whitespace? c) (read-char port) (skip-blanks-and-comments port))
          ((char=? c #\;)
           (let to-line-end ()
             (let ((c (read-char port)))
               (unless (or (eof-object? c) (char=? c #\newline)) (to-line-end))))
           (skip-blanks-and-comments port)))))

(define (read-one-datum file port)
  ;; PORT's one datum (the eof object for none), refusing text after it: it
  ;; would be silently ignored, and is more likely a script pasted twice or
  ;; cut than anything meant.
  (let ((datum (read port)))
    (skip-blanks-and-comments port)
    (let* ((line (+ 1 (port-line port))) (column (+ 1 (port-column port)))
           (more (read port)))  ; past a #| |# or #; comment: the end, or more
      (unless (eof-object? more)
        (scm-error 'misc-error "read-input-script"
                   "~A:~A:~A: text after the input script (a file holds one list of (frame . actions))"
                   (list file line column) #f)))
    datum))

(define (read-input-script file)
  "The input script record-input wrote to FILE, checked as make-game checks
one. FILE must be a regular file (not a FIFO or a device) of at most 256
MiB. A file that cannot be read, or holds text after the script, is refused
with an error naming it, and for text that does not read, the line and
column and what is wrong."
  (unless (string? file)
    (scm-error 'wrong-type-arg "read-input-script" "file: expected a string, got ~S" (list file) #f))
  (check-input-file "read-input-script" file)
  (let ((size (stat:size (stat file))))
    (when (> size max-input-script-bytes)
      (scm-error 'misc-error "read-input-script" "~s: ~a bytes, more than an input script may hold (~a)"
                 (list file size max-input-script-bytes) #f)))
  (let ((script (catch #t
                  (lambda () (call-with-input-file file (lambda (port) (read-one-datum file port))))
                  (lambda (key . args)
                    (if (and (eq? key 'misc-error) (pair? args) (equal? (car args) "read-input-script"))
                        (apply throw key args)
                        (scm-error 'misc-error "read-input-script" "cannot read an input script from ~S: ~a"
                                   (list file (error-args->text key args)) #f))))))
    (let ((script (if (eof-object? script) '() script)))  ; an empty file: no input
      (check-input-script "read-input-script" script)
      script)))

(export input-held-actions input-log->script record-input read-input-script)

;;; ---------------------------------------------------------------- drawing

(define (game-debug-draw-set! game on?)
  "Show (#t) or hide (#f) the debug overlay when GAME is drawn: every box
coloured by role (solid, immovable, ghost, plain, resting), velocities,
on-ground marks, the pairs pushed apart in the last frame and, with
history:, each entity's trail over the remembered frames. F1 toggles it in a
window."
  (%game-debug-draw-set! game (and on? #t))
  (when (renderer-available?) (%note-pushed-pairs! (and on? #t))))

(define (trail-scenes game)
  ;; The remembered frames' entities, oldest first, for the overlay's trails.
  (if (game-debug-draw? game)
      (filter-map (lambda (e) (and (cdr e) (scene-entities (cdr e)))) (reverse (game-history game)))
      '()))

(define* (draw-game! game #:optional (between #f))
  ;; One frame into the game's display (and its window, when one is open);
  ;; BETWEEN, (previous-entities alpha camera-x camera-y), draws it between
  ;; the step before and this one.
  (let ((display (game-display game))
        (scene (game-scene game)))
    (unless display
      (scm-error 'misc-error "game-capture" "this build has no renderer (SDL2)" '() #f))
    (%display-draw! display
                    (and scene (scene-tilemap scene))
                    (if scene (camera-x (scene-camera scene)) 0)
                    (if scene (camera-y (scene-camera scene)) 0)
                    (if scene (scene-entities scene) '())
                    (game-debug-draw? game)
                    (trail-scenes game)
                    ;; The game's clock, for animated tiles, and a frame's
                    ;; ms, for each entity's #:animation-start.
                    (* (game-frame game) (game-frame-delay game))
                    between
                    (game-frame-delay game))))

(define (game-capture game file)
  "Draw GAME's current frame — its map, entities, what its render: procedure
drew last, and the overlay when on — and write it to FILE as a PNG of
exactly the game's width × height. Works in any mode, headless included."
  (unless (string? file)
    (scm-error 'wrong-type-arg "game-capture" "file: expected a string, got ~S" (list file) #f))
  (draw-game! game)
  (%display-save-png (game-display game) file))

(define (game-pixel game x y)
  "The colour (r g b a) at pixel (X, Y) of the frame GAME drew last (by
game-capture, a capture run or a window)."
  (unless (game-display game)
    (scm-error 'misc-error "game-pixel" "this build has no renderer (SDL2)" '() #f))
  (%display-pixel (game-display game) x y))

;;; ---------------------------------------------------------------- the loop

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

(define (check-frames frames)
  (unless (or (not frames) (and (real? frames) (not (nan? frames))))
    (scm-error 'wrong-type-arg "game-run!"
               "frames: expected #f or a frame count, got ~S" (list frames) #f)))

;;; ---------------------------------------------------------------- endless runs
;;; Headless, nobody closes a window: a game-run! that nothing ends runs
;;; until the process is killed, and a test or a CI job hangs without a word.

;; The most frames one headless game-run! runs, counted from the frame it
;; starts at, or #f: the host's --frames N. In a window the player ends it.
;; This and game-served? are the host's, not a game's: not exported.
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

(define (run-frame-hooks! game)
  (for-each (lambda (hook)
              ;; A hook that bounds its own calls (the REPL server's poll) is
              ;; left to do so.
              (let ((bounded (if (procedure-property hook 'own-stack-limit)
                                 hook
                                 (lambda () (call-bounded game "frame hook" hook)))))
                (if (hook-error-reporter)
                    (call-reporting (lambda ()
                                      (format #f "a frame hook (now removed) raised an error in frame ~a"
                                              (game-frame game)))
                                    bounded (lambda () (remove-frame-hook! hook)))
                    (bounded))))
            frame-hooks))

;;; ---------------------------------------------------------------- hook errors
;;; In a game served to a REPL an error in a hook must not end the session
;;; its author is working in. The host then sets hook-error-reporter (a
;;; procedure taking the report's text); a failing frame hook is removed,
;;; and a failing frame leaves the game paused on it, as it started, until
;;; a hook or the scene is replaced (from the REPL), when it runs again.

(define hook-error-reporter (make-parameter #f))

;; A served game's hooks are also bounded in time: the host sets this to a
;; procedure (WHAT THUNK) that runs the hook WHAT ("update:" …) and
;; interrupts it with an error past the REPL's limit, so an endless hook
;; pauses the game instead of freezing it and the REPL.
(define hook-time-limit (make-parameter #f))

;; game → what it failed with: its hooks and scene then (see game-levers)
(define paused-on (make-object-property))

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

(define (step-or-pause! game dt held)
  ;; #t when the frame ran.
  (cond ((not (hook-error-reporter)) (step-game! game dt held) #t)
        ((and (paused-on game) (every eq? (paused-on game) (game-levers game))) #f)
        (else (set! (paused-on game) #f) (step-reporting! game dt held))))

(define (step-reporting! game dt held)
  (let ((frame (game-frame game)) (scene (game-scene game))
        (input (game-input game)) (history (game-history-log game))
        (paused-ticks (game-paused-ticks game)) (marks (game-pause-marks game)))
    (call-reporting (lambda ()
                      (format #f "a hook raised an error in frame ~a; the game is paused on it until \
a hook (game-update-set! ...) or the scene (game-scene-set! ...) is replaced" frame))
                    (lambda () (step-game! game dt held) #t)
                    (lambda ()
                      (game-scene-set! game scene)
                      (game-input-set! game input)
                      (game-history-log-set! game history)
                      (game-frame-set! game frame)
                      (game-paused-ticks-set! game paused-ticks)
                      (game-pause-marks-set! game marks)
                      (set! (paused-on game) (game-levers game))
                      #f))))

(define (step-game! game dt held)
  (if (game-paused? game) (pause-tick! game dt held) (step-frame! game dt held)))

(define (render-tick! game)
  (let ((render (game-render game))
        (display (game-display game)))
    (when display (%display-clear-commands! display))
    (when render (call-bounded game "render:" (lambda () (render game))))))

(define (pause-tick! game dt held)
  ;; A paused tick: input, the paused: hook, render; nothing steps.
  (record-input! game (input-clock game) held)
  (game-input-set! game (make-input held (input-held-list (game-input game)) (game-bindings game)))
  ;; Counted before the hook, which may rewind the game (and so set the count).
  (note-paused-tick! game)
  (let ((hook (game-paused-update game)))
    (when hook (call-bounded game "paused:" (lambda () (hook game dt)))))
  (render-tick! game)
  (report-key-slips! game))

(define (step-frame! game dt held)
  ;; One fixed step: input, engine-update, update, camera, render.
  (let ((frame (game-frame game)))
    (remember-scene! game)
    (record-input! game (input-clock game) held)
    (game-input-set! game (make-input held (input-held-list (game-input game)) (game-bindings game)))
    (let ((engine (game-engine-update game)))
      (when engine (call-bounded game "engine-update:" (lambda () (engine game dt)))))
    (let ((update (game-update game)))
      (when update (call-bounded game "update:" (lambda () (update game dt)))))
    (camera-follow! game)
    (render-tick! game)
    (report-key-slips! game)
    ;; unless the frame rewound the game, the next frame is frame + 1
    (when (= (game-frame game) frame) (game-frame-set! game (+ frame 1)))))

;;; ---------------------------------------------------------------- misspelt keys
;;; An entity key the engine does not read but that is a slip of one it does
;;; (#:sensr? for #:sensor?) turns a behaviour off without a word. Decoding
;;; notices it (bindings/key_slips.hpp: which keys are slips, and why it
;;; costs nothing measurable); here each is said once per game, or refused.

;; #t: games made without strict?: are strict. `downstroke test' sets it, so
;; a test suite does not pass on a game with a misspelt key.
(define strict-games (make-parameter #f))

(define (slip-text key suggestion index id)
  (format #f "entity key ~s is not one the engine reads (entity ~a of the list~a): did you mean ~s?"
          key index (if id (format #f ", #:id ~s" id) "") suggestion))

(define (report-key-slips! game)
  ;; The slips decoded in this frame, on this thread: one native call that
  ;; gives () in a game without any.
  (for-each (lambda (slip)
              (let ((key (car slip)) (warned (game-slips-warned game)))
                (unless (hashq-ref warned key)
                  (hashq-set! warned key #t)
                  (if (game-strict? game)
                      (scm-error 'misc-error "game-run!" "~a (make-game strict?: #t makes this an error)"
                                 (list (apply slip-text slip)) #f)
                      (format (current-warning-port) "game-run!: warning: ~a~%" (apply slip-text slip))))))
            (%take-key-slips)))

(define (frame-file dir frame)
  (string-append dir "/" (string-pad (number->string frame) 6 #\0) ".png"))

(define (run-headless! game frames capture-dir)
  (let ((dt (game-frame-delay game))
        (tick (step-ticks game))
        (start (get-internal-real-time))
        ;; Paused ticks do not bring the frame counter to FRAMES: a run makes
        ;; at most as many as the frames it was asked for, so a game paused
        ;; for good still ends.
        (pause-budget (and frames (finite? frames) (max 0 (- frames (game-frame game))))))
    (let loop ((ticks 0) (paused 0))
      (run-frame-hooks! game)
      (let* ((frame (game-frame game))
             (held (scripted-held! game (input-clock game)))
             (paused? (game-paused? game)))
        (when (and (or (not frames) (< frame frames)) (not (memq 'quit held))
                   (not (and paused? pause-budget (>= paused pause-budget))))
          (when (and (step-or-pause! game dt held) capture-dir (not paused?))
            (draw-game! game)
            (%display-save-png (game-display game) (frame-file capture-dir frame)))
          (when (frame-pacing) (wait-until (+ start (round (* (+ ticks 1) tick)))))
          (loop (+ ticks 1) (if paused? (+ paused 1) paused)))))))

;; A display frame that finds more than this many fixed steps due runs only
;; these and drops the rest of the backlog: a stall (a breakpoint, a slow
;; REPL expression, a dragged window) is then a hiccup, never a spiral of
;; ever longer catch-up frames.
(define *max-catch-up-steps* 5)

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
  ;; Real time at a fixed timestep ("Fix Your Timestep!"): time accumulates,
  ;; and each fixed step of frame-delay ms consumes it. The window presents
  ;; at the display's refresh rate, not the step's: each entity and the
  ;; camera are drawn between the last two steps, α of the way (the share of
  ;; a step the clock holds), so motion is smooth at 60, 75, 120 or 144 Hz.
  (let* ((display (game-display game))
         (dt (game-frame-delay game))
         (tick (step-ticks game)))
    (when (window-fullscreen) (%display-set-fullscreen! display #t))
    (%display-open-window! display (game-title game) (window-scale))
    (%open-audio! #t)
    (let ((present (round (/ internal-time-units-per-second (%display-refresh-rate display))))
          (log (open-frame-log))
          (start (get-internal-real-time)))
      (define saved start)   ; when the --record file was last written
      (when log
        (format log "# ~a Hz, ~a~%" (%display-refresh-rate display)
                (if (%display-vsync? display) "presented on vsync" "paced by the loop (no vsync)")))
      (dynamic-wind
        (lambda () #t)
        (lambda ()
          (let loop ((last start) (owed tick) (before #f) (next-present start) (dropped 0))
            (run-frame-hooks! game)
            (let* ((polled (%display-poll! display))
                   (mouse (list-ref polled 3))
                   (held (if mouse (append (car polled) (list (cons 'mouse mouse))) (car polled)))
                   ;; Unfocused and told to pause: no step, and no time owed.
                   (paused? (and (game-pause-when-unfocused? game) (not (list-ref polled 4)))))
              (when (odd? (caddr polled))
                (game-debug-draw-set! game (not (game-debug-draw? game))))
              (unless (or (cadr polled) (memq 'quit held)
                          (and frames (>= (game-frame game) frames)))
                (let* ((now (get-internal-real-time))
                       (owed (if paused? 0 (+ owed (- now last))))
                       (due (floor (/ owed tick)))
                       (steps (min due *max-catch-up-steps*))
                       (before
                        (let step ((k 0) (before before))
                          (if (and (< k steps) (not (and frames (>= (game-frame game) frames))))
                              (let ((then (state-of game)))
                                (step-or-pause! game dt held)
                                (step (+ k 1) then))
                              before)))
                       (dropped (+ dropped (- due steps)))  ; steps a stall's backlog lost
                       (owed (if (> due steps) 0 (- owed (* steps tick))))
                       (alpha (min 1 (max 0 (exact->inexact (/ owed tick))))))
                  (draw-game! game (and (game-interpolate? game) before
                                        (list (car before) alpha (cadr before) (caddr before))))
                  (when (and (record-file) (not (input-log-full-at (%game-input-log game)))
                             (> (- now saved) (* record-interval-seconds internal-time-units-per-second)))
                    ;; A write that fails (the disk full, the folder
                    ;; gone) is said and the game plays on: the write as
                    ;; it ends tries again.
                    (catch 'misc-error
                      (lambda () (record-input game (record-file)))
                      (lambda (key who fmt args . _)
                        (format (current-error-port) "downstroke: --record: ~a~%" (apply format #f fmt args))))
                    (set! saved now))
                  (when log
                    (format log "~a ~a ~a ~a~%"
                            ;; The frame's clock: the time its steps and α were taken at.
                            (/ (round (/ (* 1000000 (- now start)) internal-time-units-per-second)) 1000.)
                            (game-frame game) (/ (round (* 10000 alpha)) 10000.) dropped))
                  ;; The next present is one refresh on; a loop that fell
                  ;; behind presents at once and starts counting afresh.
                  (let* ((next (+ next-present present))
                         (next (if (< next (get-internal-real-time)) (get-internal-real-time) next)))
                    (wait-until next)
                    (loop now owed before next dropped)))))))
        (lambda ()
          (when log (close-port log))
          (when (record-file) (record-input game (record-file)))
          (%display-close-window! display))))))

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
hooks, or from a REPL served into it) is an error."
  (check-game "game-run!" game)
  (check-frames frames)
  ;; One frame loop at a time: game-run! from a hook or a REPL evaluation of
  ;; a running game would nest a loop in its frame, and again in that one's.
  (when (current-game)
    (scm-error 'misc-error "game-run!"
               "a game is already running (~A): game-run! cannot start a game from inside a running game's hooks or REPL; run games one after another"
               (list (if (eq? (current-game) game) "this one" (game-title (current-game)))) #f))
  (parameterize ((current-game game)
                 (current-display (game-display game)))
    (case (display-mode)
      ((window) (run-window! game frames))
      ((capture) (warn-if-endless! game frames)
                 (run-headless! game (headless-end game frames) (capture-directory)))
      (else (warn-if-endless! game frames)
            (run-headless! game (headless-end game frames) #f)))
    game))
