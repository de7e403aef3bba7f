;; SPDX-License-Identifier: MIT
;;; (downstroke input) — what a game's player holds: the input map's
;;; bindings, each frame's held actions and the pointer, the queries on them
;;; (input-held? …), and the checks of an input script. Keys, buttons and the
;;; mouse of a window are read by the renderer (%display-poll!); a script's
;;; are replayed by (downstroke recording). docs/engine.org, "Input", and
;;; docs/render.org, "Input".
(define-module (downstroke input)
  #:use-module (srfi srfi-1)
  #:use-module (srfi srfi-9)
  #:use-module (downstroke world)
  #:use-module (downstroke game)
  #:use-module (downstroke native)
  #:export (default-input-map map-bindings bindings-clicks
            make-input input-held-list input-previous-list
            input-held? input-pressed? input-released?
            mouse-element input-mouse mouse-world-position
            check-input-script with-clicked-actions input-held-actions))

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

(define (input-held-actions input)
  "The list of actions held in INPUT's frame: what an input log records."
  (input-held-list input))

(define (default-input-map)
  "The keys and controller inputs bound to each action when make-game has no
input-map:, as ((action name …) …): arrows or WASD move, Z or Space is a,
X is b, Return is start, Backspace is select, Escape quits; a controller's
d-pad or left stick moves and its A, B, Start and Back buttons act. In a
build without the renderer there are no inputs: it is ()."
  (%default-input-map))
