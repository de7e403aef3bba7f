;; SPDX-License-Identifier: 0BSD
;;; Tweens: entities driven by make-tween, stored under #:tween and advanced by
;;; step-tweens inside the default engine-update (dt = 16 ms a frame).
;;;
;;; - slider    x 20 → 220, linear, 320 ms; its on-complete chains a second
;;;             tween back to 20 (cubic-in-out)
;;; - bouncer   y 0 → 160, bounce-out, 640 ms
;;; - pulse     width 16 → 32, sine-in-out, 160 ms, yoyo?, repeat 3: four
;;;             legs, back to 16
;;; - repeater  y 40 → 80, linear, 160 ms, repeat 2 (no yoyo): ends at 80
;;; - looper    x 100 → 140, quad-in-out, 320 ms, yoyo?, repeat -1: forever
;;; - delayed   x 200 → 260, back-out, 320 ms after a 160 ms delay
;;; - fader     #:alpha 0 → 1 with an easing procedure (sqrt)
;;; - walker    walks right with #:vx 2 into the spikes; a hit knocks it back
;;;             with a tween on #:x (quad-out, 240 ms) and
;;;             #:skip-pipelines '(velocity-x) so its #:vx is ignored while the
;;;             tween runs; the tween's on-complete lifts the skip again.
;;;
;;; The scene's map, demo/maps/tweens.tmx, has no tiles at all: it is there
;;; for its tilesets, which the entities' #:sprite gids refer to (and with no
;;; solid cell the engine's tile collisions find nothing, as without a map).
;;;
;;; Keys (in a window): Return plays the tweens again from the start, Escape
;;; quits. Nothing else: it is a show.
;;;
;;; Run: build/bin/downstroke demo/tweens.scm
;;; Headless: it runs `demo-frames' frames (no input needed) and prints a line
;;; every 20 frames plus one per event.
;;; In a window (downstroke --window demo/tweens.scm) it runs until the
;;; player quits.
(use-modules (ice-9 format) (srfi srfi-1))
;;; The demos' shared looks and sounds: (demo looks), in demo/lib.
(add-to-load-path (canonicalize-path (string-append (dirname (current-filename)) "/lib")))
(use-modules (demo looks) (demo events))

;;; ------------------------------------------------------------ looks and sounds
(define backdrop (load-tilemap (demo-file "maps/tweens.tmx")))
(define walker-picture (sprite 3))
(define walker-step-picture (sprite 4))
(define coin-picture (sprite 10))
(define ball-picture (sprite 13))
(define spikes-picture (sprite 14))
(define burst-picture (sprite 15))

(load-demo-sounds! 'hit)
(load-demo-music!)

;;; ------------------------------------------------------------ what happened
(define trace? (main-script? "tweens.scm"))   ; headless as the host's script: print as it goes

;;; What happened: (demo events).
(define events (make-events trace?))

(define (note-at! frame what) (note-event! events frame what))

(define (note! what)
  ;; `game' is defined below; on-complete procedures run inside it.
  (note-at! (game-frame game) what))

;;; ------------------------------------------------------------ entities
(define (tweened entity . args)
  "ENTITY with a tween made from ARGS (make-tween's keywords) under #:tween."
  (entity-set entity #:tween (apply make-tween entity args)))

(define (slider-back entity)
  ;; on-complete: chain the way back.
  (note! '(slider arrived))
  (tweened entity props: '((#:x . 20)) duration: 320 ease: 'cubic-in-out
           on-complete: (lambda (e) (note! '(slider back)) e)))

(define knockback-distance 48)
(define knockback-ms 240)

(define (knockback-over entity)
  ;; on-complete of the knockback: #:vx counts again.
  (note! (list 'recovered 'at (entity-ref entity #:x)))
  (entity-set entity #:skip-pipelines '()))

(define (knock-back entity)
  (entity-set (tweened entity props: `((#:x . ,(- (entity-ref entity #:x) knockback-distance)))
                       duration: knockback-ms ease: 'quad-out on-complete: knockback-over)
              #:skip-pipelines '(velocity-x)))

(define entities0
  (list
   (tweened `(#:id slider #:x 20 #:y 20 #:width 8 #:height 8 #:sprite ,ball-picture)
            props: '((#:x . 220)) duration: 320 ease: 'linear on-complete: slider-back)
   (tweened `(#:id bouncer #:x 60 #:y 0 #:width 8 #:height 8 #:sprite ,ball-picture)
            props: '((#:y . 160)) duration: 640 ease: 'bounce-out
            on-complete: (lambda (e) (note! '(bouncer landed)) e))
   (tweened `(#:id pulse #:x 100 #:y 60 #:width 16 #:height 16 #:sprite ,burst-picture)
            props: '((#:width . 32) (#:height . 32)) duration: 160 ease: 'sine-in-out
            yoyo?: #t repeat: 3 on-complete: (lambda (e) (note! '(pulse done)) e))
   (tweened `(#:id repeater #:x 140 #:y 40 #:width 8 #:height 8 #:sprite ,coin-picture)
            props: '((#:y . 80)) duration: 160 ease: 'linear repeat: 2
            on-complete: (lambda (e) (note! '(repeater done)) e))
   (tweened `(#:id looper #:x 100 #:y 120 #:width 8 #:height 8 #:sprite ,ball-picture)
            props: '((#:x . 140)) duration: 320 ease: 'quad-in-out yoyo?: #t repeat: -1)
   (tweened `(#:id delayed #:x 200 #:y 120 #:width 8 #:height 8 #:sprite ,ball-picture)
            props: '((#:x . 260)) duration: 320 delay: 160 ease: 'back-out)
   ;; The renderer has no per-sprite opacity: render fades the coin in by
   ;; covering it with the background at 1 - #:alpha.
   (tweened `(#:id fader #:x 240 #:y 20 #:width 8 #:height 8 #:alpha 0 #:sprite ,coin-picture)
            props: '((#:alpha . 1)) duration: 400 ease: sqrt)
   `(#:id walker #:x 40 #:y 200 #:width 12 #:height 12 #:vx 2 #:sprite ,walker-picture)
   `(#:id spikes #:x 120 #:y 196 #:width 8 #:height 16 #:sprite ,spikes-picture)))

;;; ------------------------------------------------------------ the game
(define (overlaps? a b)
  (aabb-overlap? (entity-ref a #:x 0) (entity-ref a #:y 0) (entity-ref a #:width 0) (entity-ref a #:height 0)
                 (entity-ref b #:x 0) (entity-ref b #:y 0) (entity-ref b #:width 0) (entity-ref b #:height 0)))

(define (dress-walker e)
  ;; A two-frame walk by where it is, so it steps as it goes, either way.
  (entity-set e #:sprite (if (even? (quotient (inexact->exact (floor (entity-ref e #:x))) 6))
                             walker-picture
                             walker-step-picture)))

(define (update game dt)
  (theme-from-the-start game)
  (if (input-pressed? (game-input game) 'start)
      ;; Return in a window: every tween from the start again.
      (game-scene-set! game (update-scene (game-scene game) entities: entities0))
      (play! game dt)))

(define (play! game dt)
  ;; The engine has stepped the tweens and moved the walker; knock it back
  ;; when it touches the spikes (and is not being knocked back already).
  (let* ((scene (game-scene game))
         (entities (scene-entities scene))
         (spikes (find (lambda (e) (eq? (entity-ref e #:id) 'spikes)) entities)))
    (game-scene-set!
     game
     (update-scene scene entities:
                   (map (lambda (e)
                          (if (and (eq? (entity-ref e #:id) 'walker) (not (entity-ref e #:tween))
                                   (overlaps? e spikes))
                              (begin
                                (play-sound 'hit)
                                (note! (list 'hit 'at (entity-ref e #:x)))
                                (dress-walker (knock-back e)))
                              (if (eq? (entity-ref e #:id) 'walker) (dress-walker e) e)))
                        entities)))))

(define (show x)
  (if (inexact? x) (format #f "~,2f" x) (format #f "~a" x)))

;;; What each one shows, written by where it moves (capitals read best in
;;; the 5×7 font).
(define labels
  '((20 31 "SLIDER: LINEAR, CUBIC BACK")
    (186 38 "FADER: SQRT")
    (152 58 "REPEATER: X3")
    (100 96 "PULSE: SINE YOYO")
    (72 161 "BOUNCER: BOUNCE-OUT")
    (6 121 "LOOPER: FOREVER")
    (200 131 "DELAYED: BACK-OUT")
    (4 222 "WALKER: SPIKES KNOCK IT BACK (QUAD-OUT)")))

(define label-color '(120 124 160))
(define background '(24 28 40))         ; the renderer's clear colour

(define (draw! game)
  ;; The entities are drawn by the engine from their #:sprite; the floor,
  ;; labels, the pulse's box, the fader's fade and the HUD here.
  (let* ((entities (scene-entities (game-scene game)))
         (get (lambda (id) (find (lambda (e) (eq? (entity-ref e #:id) id)) entities)))
         (pulse (get 'pulse))
         (fader (get 'fader))
         (hits (count (lambda (e) (eq? (cadr e) 'hit)) (events-items events))))
    (draw-rect 0 212 320 2 '(98 58 42) fill?: #t)            ; the walker's floor
    (draw-rect 0 214 320 26 '(56 34 32) fill?: #t)
    (for-each (lambda (l) (draw-text (caddr l) (car l) (cadr l) label-color)) labels)
    (draw-rect (entity-ref pulse #:x) (entity-ref pulse #:y)
               (entity-ref pulse #:width) (entity-ref pulse #:height) '(255 150 40))
    ;; The coin's 16×16 picture, centred on its 8×8 box and bottom-aligned,
    ;; under the background at 1 - alpha.
    (let ((cover (inexact->exact (round (* 255 (- 1 (entity-ref fader #:alpha 1)))))))
      (when (> cover 0)
        (draw-rect (- (entity-ref fader #:x) 4) (- (entity-ref fader #:y) 8) 16 16
                   (append background (list cover)) fill?: #t)))
    (draw-label "TWEENS" 4 4 'white)
    (let ((text (format #f "HITS ~a   RETURN: AGAIN" hits)))
      (draw-label text (- (game-width game) 4 (text-width text)) 4 'white))))

(define (render game)
  ;; Draws the scenery and HUD (when the game has a display) and, headless,
  ;; prints a line every 20 frames.
  (when (current-display) (draw! game))
  (let ((frame (game-frame game))
        (entities (scene-entities (game-scene game))))
    (when (and trace? (zero? (modulo frame 20)))
      (let ((get (lambda (id key) (show (entity-ref (find (lambda (e) (eq? (entity-ref e #:id) id)) entities) key)))))
        (format #t "frame ~3d: slider x ~a  bouncer y ~a  pulse w ~a  repeater y ~a  looper x ~a  delayed x ~a  fader ~a  walker x ~a~%"
                frame (get 'slider #:x) (get 'bouncer #:y) (get 'pulse #:width) (get 'repeater #:y)
                (get 'looper #:x) (get 'delayed #:x) (get 'fader #:alpha) (get 'walker #:x))))))

(define demo-frames 120)

(define game
  (make-game title: "Downstroke — tweens" width: 320 height: 240 frame-delay: 16
             scene: (make-scene entities: entities0 tilemap: backdrop)
             update: update render: render
             input-script: '()))

(define (run! frames)
  "Run the game up to frame FRAMES (it counts from where it stopped)."
  (game-run! game frames: frames))

(when (main-script? "tweens.scm")
  ;; Headless or capturing: the demo's frames; in a window: until the player quits.
  (run! (script-number-argument 0 (if (eq? (display-mode) 'window) #f demo-frames)))
  (format #t "sounds: ~s~%" (game-sounds game)))
