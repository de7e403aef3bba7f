;; SPDX-License-Identifier: MIT
;;; (downstroke documentation) — what each export of (downstroke) is, in words.
;;;
;;; Most exports carry their own docstring. Those that cannot — variables,
;;; parameters, macros of define-record-type (the accessors and predicates) —
;;; are described in `export-notes' below. Loading this module attaches each
;;; note where the REPL looks: procedure-documentation finds an accessor's,
;;; object-documentation a parameter's, and every note is the
;;; 'documentation object property of its exported variable.
(define-module (downstroke documentation)
  #:use-module (srfi srfi-1)
  ;; Only the reference generator asks for argument lists: a game need not
  ;; load (ice-9 session) at start-up.
  #:autoload (ice-9 session) (procedure-arguments)
  #:export (user-modules module-summary export-names export-kind export-documentation
            export-signature undocumented-exports))

;; The modules (downstroke) re-exports, in the order the reference lists
;; them, each with what it holds. Not (downstroke reference) (a second physics
;; for checking this one), (downstroke native) (its machinery) nor the host's
;; own modules.
(define module-summaries
  '(((downstroke entity) . "Entities, which are keyword lists, and defining your own steps.")
    ((downstroke world) . "Scenes (an entity list with a map and a camera) and the camera.")
    ((downstroke physics) . "The physics: each step on its own, and step-scene for a whole frame.")
    ((downstroke query) . "What is where: entities in a box or at a point, overlapping pairs, rays, the tile at a point.")
    ((downstroke contacts) . "Which pairs began or stopped touching between two frames.")
    ((downstroke tilemap) . "Tiled maps loaded from files or made in memory, and changing their tiles.")
    ((downstroke tween) . "Tweens: an entity's numbers driven from start to end over time.")
    ((downstroke engine) . "The game: making one, its frame loop, input, sounds, rewinding, frame hooks.")
    ((downstroke render) . "Drawing, sounds and how the host shows frames (headless, a window, captures).")
    ((downstroke hash) . "A fingerprint of a scene's physical state, for checking that two runs are the same.")
    ((downstroke scene-file) . "A whole scene in one readable file: saving a game, loading it, carrying a scene in a bug report.")
    ((downstroke history) . "Bounded records of a running game: a ring of the last frames, and a log of the newest items.")
    ((downstroke live) . "Live editing: files a running game watches, and maps reloaded when theirs change on disk.")))

(define user-modules (map car module-summaries))

(define (module-summary module-name)
  "What MODULE-NAME, one of user-modules, holds: one sentence."
  (assoc-ref module-summaries module-name))

(define export-notes
  '(;; (downstroke world)
    (scene? . "Whether OBJ is a scene (made by make-scene or update-scene).")
    (scene-entities . "The list of SCENE's entities, each a keyword list.")
    (scene-tilemap . "SCENE's tilemap, or #f when it has none.")
    (scene-camera . "SCENE's camera (see make-camera), or #f when it has none.")
    (scene-camera-target . "The #:id (or #:tag) of the entity SCENE's camera follows, or #f.")
    (camera? . "Whether OBJ is a camera (made by make-camera).")
    (camera-x . "The world x that CAMERA puts at the screen's left edge.")
    (camera-y . "The world y that CAMERA puts at the screen's top edge.")
    ;; (downstroke physics)
    (*gravity* . "What apply-gravity adds to a #:gravity? entity's #:vy every frame, in px per frame, unless the scene sets its own (make-scene gravity:) or the entity a #:gravity-scale: 1.")
    (*jump-force* . "The usual jump speed, in px per frame: set #:ay to (- *jump-force*) to jump. 15.")
    (*on-solid-tolerance* . "How far below its feet (px) detect-on-solid looks for ground: 4.")
    (collision-mode . "A parameter: 'swept (the default: a fast body cannot pass through a thin wall) or 'discrete (each body moves its whole step, then is pushed out). step-scene and the steps read it.")
    (push-rule . "A parameter: 'clipped (the default: push-apart never leaves a body in a solid cell; a push is cut at the cell and a body inside one is put out) or 'seed (the seed's rule: pushes ignore the map). step-scene reads it.")
    (resting-contacts? . "A parameter, #f by default: when true, a still body resting exactly on a tile or on a still solid body skips gravity and holds up what lands on it, so stacks stay put.")
    ;; (downstroke tween)
    (easing-names . "The names ease and make-tween's #:ease take: linear, and quad, cubic, quart, sine, expo, back, elastic and bounce each as -in, -out and -in-out.")
    (tween? . "Whether OBJ is a tween (made by make-tween).")
    (tween-props . "The keys TWEEN drives, as a list of (key start . end).")
    (tween-duration . "How long one run of TWEEN lasts, in ms.")
    (tween-delay . "How long TWEEN waits before it starts, in ms.")
    (tween-ease . "TWEEN's easing: a name from easing-names, or a procedure of t in [0, 1].")
    (tween-repeat . "How many more times TWEEN runs after the first: 0 once, -1 forever.")
    (tween-yoyo? . "Whether TWEEN runs back from end to start on every other repeat.")
    (tween-on-complete . "The procedure TWEEN calls with the entity when it ends, or #f.")
    (tween-elapsed . "How long TWEEN has run, in ms, its delay included.")
    ;; (downstroke engine)
    (game? . "Whether OBJ is a game (made by make-game).")
    (game-title . "GAME's title (a window shows it).")
    (game-width . "The width of GAME's picture, in pixels.")
    (game-height . "The height of GAME's picture, in pixels.")
    (game-frame-delay . "How long each of GAME's frames lasts, in ms: the dt every step gets.")
    (game-frame . "How many frames GAME has run.")
    (game-scene . "GAME's current scene.")
    (game-scene-set! . "Make SCENE GAME's current scene, from the next step on.")
    (game-update . "GAME's own per-frame procedure (game dt), or #f.")
    (game-update-set! . "Replace GAME's per-frame procedure by PROC, a procedure (game dt) or #f.")
    (game-engine-update . "What GAME runs before its update each frame: default-engine-update, #f, or your procedure (game dt).")
    (game-engine-update-set! . "Replace what GAME runs before its update each frame (a procedure (game dt), or #f for nothing).")
    (game-collision-mode . "'swept or 'discrete: the collision mode GAME's physics runs in (see collision-mode).")
    (game-push-rule . "'clipped or 'seed: the push rule GAME's physics runs in (see push-rule).")
    (game-substeps . "How many sub-frames GAME splits each physics frame into (1: none).")
    (game-resting-contacts? . "Whether GAME's physics keeps stacks at rest (see resting-contacts?).")
    (game-resting-contacts-set! . "Turn GAME's resting contacts on (#t) or off (#f) from the next frame on.")
    (game-input . "The input of GAME's current frame: ask it with input-held?, input-pressed? and input-released?.")
    (game-debug-draw? . "Whether GAME is drawn with the debug overlay (see game-debug-draw-set!).")
    (strict-games . "A parameter, #f by default: when true, a game made without strict?: is strict, so an entity key that is a slip of an engine key (#:sensr? for #:sensor?) is an error instead of a warning. `downstroke test' sets it while the tests run.")
    (frame-pacing . "A parameter, #f by default: when true, game-run! waits so that each frame lasts its frame delay in real time, as a game someone watches must; when #f it runs as fast as it can. The host sets it for a window or a REPL server.")
    (hook-error-reporter . "A parameter, #f by default: a procedure given the text of each error raised by a frame hook or a frame, which then pauses the game instead of ending the run. The host sets it when it serves a REPL.")
    (hook-time-limit . "A parameter, #f by default: a procedure (what thunk) each hook call runs through — engine-update:, update:, render: and frame hooks, WHAT naming it. The host sets one that interrupts a hook with an error past --repl-timeout when it serves a REPL.")
    ;; (downstroke render)
    (display-mode . "A parameter: how game-run! shows frames, 'headless (the default), 'window or 'capture. The host sets it from --window and --capture.")
    (capture-directory . "A parameter: the directory game-run! writes each frame to as a PNG in 'capture mode, or #f.")
    (window-scale . "A parameter: the window's whole scale factor (the host's --scale), 0 to fit the screen.")
    (window-fullscreen . "A parameter: whether the window opens fullscreen (the host's --fullscreen).")
    (record-file . "A parameter: the file a windowed game's input is written to when it ends (the host's --record), or #f.")
    (frame-log-file . "A parameter: a file the window loop writes each presented frame's time, step and alpha to (the host's --frame-log), or #f.")
    (debug-draw-default . "A parameter, #f by default: whether every game starts with the debug overlay on (the host's --debug).")
    (current-display . "A parameter: what the running game draws into (its window or off-screen picture), or #f outside game-run!; draw-rect and the other draw- procedures draw there.")
    ;; (downstroke engine)
    (game-paused? . "Whether GAME is paused (game-paused-set!): its ticks then read input and call the paused: hook and render:, and step nothing.")
    (once . "(once FORM …) evaluates the FORMs when the script first runs, and not when reload-script! (or --watch) evaluates the script again: load-sound, add-frame-hook!, whatever must happen once a game. Its value is the last FORM's, unspecified in a reload. A definition that keeps its first value is written (define-once NAME VALUE).")
    ;; (downstroke history)
    (frame-ring? . "Whether OBJ is a frame ring (made by make-frame-ring).")
    ;; (downstroke live)
    (watch-default . "A parameter, #f by default: whether games made from now on watch their maps' files (game-watch-maps!), and games run from now on their script (game-watch-script!). The host sets it from --watch, which is on by default with --window, --repl-server and --repl-port (--no-watch turns it off).")
    (watch-poll-interval . "A parameter, 1 by default: the least time, in seconds, between two looks (a stat of each) at a game's watched files (watch-file!); the frames between look at none. 0 looks in every frame, as tests do.")))

(define (export-names module-name)
  "The names MODULE-NAME (a list such as (downstroke world)) exports, sorted."
  (sort (module-map (lambda (name variable) name) (resolve-interface module-name))
        (lambda (a b) (string<? (symbol->string a) (symbol->string b)))))

;; A define-record-type accessor is a macro that stands for its procedure
;; when named rather than called: the procedure is what it documents.
(define (export-value module-name name)
  (let ((value (module-ref (resolve-interface module-name) name)))
    (if (macro? value)
        (or (false-if-exception (eval name (resolve-module module-name))) value)
        value)))

(define (export-kind module-name name)
  "What NAME of MODULE-NAME is: 'procedure, 'parameter, 'macro or 'variable."
  (let ((value (export-value module-name name)))
    (cond ((parameter? value) 'parameter)
          ((procedure? value) 'procedure)
          ((macro? value) 'macro)
          (else 'variable))))

(define (own-docstring value)
  (cond ((parameter? value) #f)
        ((procedure? value) (procedure-documentation value))
        ((and (macro? value) (procedure? (macro-transformer value)))
         (procedure-documentation (macro-transformer value)))
        (else #f)))

(define (export-documentation module-name name)
  "NAME's documentation (a string) as MODULE-NAME exports it, or #f when it
has none."
  (or (own-docstring (export-value module-name name))
      (assq-ref export-notes name)))

;; A docstring that starts "(NAME args …)" shows how to call NAME.
(define (leading-call doc name)
  (and (string-prefix? (string-append "(" (symbol->string name) " ") doc)
       (let loop ((i 0) (depth 0))
         (and (< i (string-length doc))
              (let ((depth (case (string-ref doc i)
                             ((#\() (+ depth 1))
                             ((#\)) (- depth 1))
                             (else depth))))
                (if (zero? depth)
                    (substring doc 0 (+ i 1))
                    (loop (+ i 1) depth)))))))

;; A record accessor's argument is named after its record: (game-title game).
(define (record-argument name argument)
  (if (memq argument '(s val))
      (if (eq? argument 's)
          (car (string-split (symbol->string name) #\-))
          "value")
      argument))

(define (argument-list name arguments)
  (define (words items) (map (lambda (x) (format #f "~a" (record-argument name x))) items))
  (let ((required (or (assq-ref arguments 'required) '()))
        (optional (or (assq-ref arguments 'optional) '()))
        (keyword (or (assq-ref arguments 'keyword) '()))
        (rest (assq-ref arguments 'rest)))
    (string-append
     "(" (string-join
          (append (list (symbol->string name))
                  (words required)
                  (map (lambda (x) (format #f "[~a]" x)) optional)
                  (map (lambda (k) (format #f "[#:~a]" (keyword->symbol (car k)))) keyword)
                  (if rest (list (format #f ". ~a" rest)) '()))
          " ")
     ")")))

(define (export-signature module-name name)
  "How to use NAME of MODULE-NAME, as a string: a call such as
\"(entity-ref entity key [default])\", \"(collision-mode)\" for a parameter,
or the name alone for a variable."
  (let ((value (export-value module-name name))
        (doc (or (export-documentation module-name name) "")))
    (cond ((leading-call doc name))
          ((parameter? value) (format #f "(~a)" name))
          ((procedure? value)
           (let ((arguments (procedure-arguments value)))
             (if arguments (argument-list name arguments) (format #f "(~a …)" name))))
          ((macro? value) (format #f "(~a …)" name))
          (else (symbol->string name)))))

(define (undocumented-exports)
  "The names, each as (module-name . name), of the exports of the user
modules that have no documentation: '() when every one is documented."
  (append-map (lambda (module-name)
                (filter-map (lambda (name)
                              (and (not (export-documentation module-name name))
                                   (cons module-name name)))
                            (export-names module-name)))
              user-modules))

(for-each
 (lambda (module-name)
   (for-each
    (lambda (name)
      (let ((note (assq-ref export-notes name))
            (value (export-value module-name name)))
        (when note
          (cond ((parameter? value) (set-object-property! value 'documentation note))
                ((procedure? value) (set-procedure-property! value 'documentation note)))
          (set-object-property! (module-variable (resolve-interface module-name) name)
                                'documentation note))))
    (export-names module-name)))
 user-modules)
