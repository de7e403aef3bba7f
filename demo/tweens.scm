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
;;; Run: build/bin/downstroke demo/tweens.scm
;;; Headless: it runs `demo-frames' frames (no input needed) and prints a line
;;; every 20 frames plus one per event.
(use-modules (ice-9 format) (srfi srfi-1))

;;; ------------------------------------------------------------ bookkeeping
;;; Both records are bounded (see (downstroke history)), so that a game left
;;; running (a soak test, a REPL session) stays in constant memory: a ring of
;;; the last 1000 frames, and between 500 and 1000 of the newest events.
(define trace? (main-script? "tweens.scm"))
(define events (make-bounded-log))      ; of (frame . what), newest first; 500 kept
(define history (make-frame-ring 1000)) ; each frame's entities

(define (note! what)
  ;; `game' is defined below; on-complete procedures run inside it.
  (let ((frame (game-frame game)))
    (set! events (bounded-log-push events (cons frame what) 500))
    (when trace? (format #t "frame ~3d: ~a~%" frame what))))

(define (remember! frame entities) (frame-ring-set! history frame entities))

(define (entities-at frame)
  "The entities as they were at the end of FRAME, or #f when FRAME is not
one of the last 1000."
  (frame-ring-ref history frame))

(define (entity-at frame id)
  (let ((entities (entities-at frame)))
    (and entities (find (lambda (e) (eq? (entity-ref e #:id) id)) entities))))

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
   (tweened '(#:id slider #:x 20 #:y 20 #:width 8 #:height 8)
            props: '((#:x . 220)) duration: 320 ease: 'linear on-complete: slider-back)
   (tweened '(#:id bouncer #:x 60 #:y 0 #:width 8 #:height 8)
            props: '((#:y . 160)) duration: 640 ease: 'bounce-out
            on-complete: (lambda (e) (note! '(bouncer landed)) e))
   (tweened '(#:id pulse #:x 100 #:y 60 #:width 16 #:height 16)
            props: '((#:width . 32) (#:height . 32)) duration: 160 ease: 'sine-in-out
            yoyo?: #t repeat: 3 on-complete: (lambda (e) (note! '(pulse done)) e))
   (tweened '(#:id repeater #:x 140 #:y 40 #:width 8 #:height 8)
            props: '((#:y . 80)) duration: 160 ease: 'linear repeat: 2
            on-complete: (lambda (e) (note! '(repeater done)) e))
   (tweened '(#:id looper #:x 100 #:y 120 #:width 8 #:height 8)
            props: '((#:x . 140)) duration: 320 ease: 'quad-in-out yoyo?: #t repeat: -1)
   (tweened '(#:id delayed #:x 200 #:y 120 #:width 8 #:height 8)
            props: '((#:x . 260)) duration: 320 delay: 160 ease: 'back-out)
   (tweened '(#:id fader #:x 240 #:y 20 #:width 8 #:height 8 #:alpha 0)
            props: '((#:alpha . 1)) duration: 400 ease: sqrt)
   '(#:id walker #:x 40 #:y 200 #:width 12 #:height 12 #:vx 2)
   '(#:id spikes #:x 120 #:y 196 #:width 8 #:height 16)))

;;; ------------------------------------------------------------ the game
(define (overlaps? a b)
  (aabb-overlap? (entity-ref a #:x 0) (entity-ref a #:y 0) (entity-ref a #:width 0) (entity-ref a #:height 0)
                 (entity-ref b #:x 0) (entity-ref b #:y 0) (entity-ref b #:width 0) (entity-ref b #:height 0)))

(define (update game dt)
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
                                (knock-back e))
                              e))
                        entities)))))

(define (show x)
  (if (inexact? x) (format #f "~,2f" x) (format #f "~a" x)))

(define (render game)
  (let ((frame (game-frame game))
        (entities (scene-entities (game-scene game))))
    (remember! frame entities)
    (when (and trace? (zero? (modulo frame 20)))
      (let ((get (lambda (id key) (show (entity-ref (find (lambda (e) (eq? (entity-ref e #:id) id)) entities) key)))))
        (format #t "frame ~3d: slider x ~a  bouncer y ~a  pulse w ~a  repeater y ~a  looper x ~a  delayed x ~a  fader ~a  walker x ~a~%"
                frame (get 'slider #:x) (get 'bouncer #:y) (get 'pulse #:width) (get 'repeater #:y)
                (get 'looper #:x) (get 'delayed #:x) (get 'fader #:alpha) (get 'walker #:x))))))

(define demo-frames 120)

(define game
  (make-game title: "Downstroke — tweens" width: 320 height: 240 frame-delay: 16
             scene: (make-scene entities: entities0)
             update: update render: render
             input-script: '()))

(define (run! frames)
  "Run the game up to frame FRAMES (it counts from where it stopped)."
  (game-run! game frames: frames))

(when (main-script? "tweens.scm")
  (run! (script-number-argument 0 demo-frames))
  (format #t "sounds: ~s~%" (game-sounds game)))
