;;; Physics sandbox on demo/maps/sandbox.tmx, with the default engine-update.
;;;
;;; - boxes (#:gravity? #t #:solid? #t) fall onto immovable platforms (solid
;;;   entities with #:immovable? #t), onto a ledge of the map, and one onto
;;;   another box;
;;; - a raft: three planks and a mast sharing #:group-id 'raft; the first
;;;   plank is the #:group-origin? and moves with #:vx, the others follow at
;;;   their #:group-local-x / #:group-local-y (sync-groups); the update hook
;;;   turns the raft round at the ends of its run;
;;; - bots with their own logic: they walk the floor and turn round when a
;;;   wall stopped them, i.e. when the tile collision left their #:vx at 0.
;;; update: only runs that per-entity logic, through scene-map-entities.
;;;
;;; Run: build/bin/downstroke demo/sandbox.scm
;;; Headless: it runs `demo-frames' frames (no input needed) and prints a line
;;; every 20 frames plus one per event.
(use-modules (ice-9 format) (srfi srfi-1))

(define demo-dir
  (cond ((current-filename) => dirname)
        ((getenv "DS_DEMO_DIR"))
        (else "demo")))

(define arena (load-tilemap (string-append demo-dir "/maps/sandbox.tmx")))

;;; ------------------------------------------------------------ entities
(define (platform id x y w)
  (list #:id id #:kind 'platform #:x x #:y y #:width w #:height 8 #:solid? #t #:immovable? #t))

(define (box id x y)
  (list #:id id #:kind 'box #:x x #:y y #:width 12 #:height 12 #:vx 0 #:vy 0
        #:gravity? #t #:solid? #t #:on-ground? #f))

(define (bot id x vx)
  ;; Standing on the floor (its top at y 208).
  (list #:id id #:kind 'bot #:x x #:y (- 208 14) #:width 12 #:height 14 #:vx vx #:vy 0
        #:speed (abs vx) #:gravity? #t #:solid? #t #:on-ground? #t))

(define raft-speed 1)
(define raft-min-x 256)
(define raft-max-x 352)

(define (plank id local-x origin?)
  (append (list #:id id #:kind 'raft #:x (+ raft-min-x local-x) #:y 160 #:width 16 #:height 8
                #:solid? #t #:immovable? #t #:group-id 'raft)
          (if origin?
              (list #:group-origin? #t #:vx raft-speed)
              (list #:group-local-x local-x #:group-local-y 0))))

(define raft0
  (list (plank 'raft-0 0 #t)
        (plank 'raft-1 16 #f)
        (plank 'raft-2 32 #f)
        ;; The mast: not solid, carried along all the same.
        (list #:id 'mast #:kind 'raft #:x (+ raft-min-x 22) #:y 140 #:width 4 #:height 20
              #:group-id 'raft #:group-local-x 22 #:group-local-y -20)))

;;; Order matters for stacks: resolve-entity-collisions makes one pass over
;;; the pairs in list order, and in the pair (lower, upper) the earlier body
;;; moves by the larger half of the overlap. Listing box-5 before box-2 (which
;;; it lands on) makes the lower box stay put on ledge-a; the other way round
;;; box-2 would be pushed back 1 px into the ledge every frame after the pair
;;; (ledge-a, box-2) had set it right.
(define entities0
  (append
   (list (platform 'ledge-a 48 128 64)       ; immovable platforms
         (platform 'ledge-b 288 64 64)
         (box 'box-1 60 16)                  ; → rests on ledge-a
         (box 'box-5 94 20)                  ; → lands on box-2 (listed first: see below)
         (box 'box-2 92 40)                  ; → rests on ledge-a
         (box 'box-3 300 20)                 ; → rests on ledge-b
         (box 'box-4 400 16)                 ; → rests on the map's ledge (row 7)
         (bot 'bot-1 100 -2)                 ; patrols between the west wall and the stub
         (bot 'bot-2 300 2))                 ; patrols between the stub and the east wall
   raft0))

;;; ------------------------------------------------------------ bookkeeping
;;; Both records are bounded (see (downstroke history)), so that a game left
;;; running (a soak test, a REPL session) stays in constant memory: a ring of
;;; the last 1000 frames, and between 500 and 1000 of the newest events.
(define trace? (main-script? "sandbox.scm"))
(define events (make-bounded-log))      ; of (frame . what), newest first; 500 kept
(define history (make-frame-ring 1000)) ; each frame's entities

(define (note! game what)
  (set! events (bounded-log-push events (cons (game-frame game) what) 500))
  (when trace? (format #t "frame ~3d: ~a~%" (game-frame game) what)))

(define (remember! frame entities) (frame-ring-set! history frame entities))

(define (entities-at frame)
  "The entities as they were at the end of FRAME, or #f when FRAME is not
one of the last 1000."
  (frame-ring-ref history frame))

(define (entity-at frame id)
  (let ((entities (entities-at frame)))
    (and entities (find (lambda (e) (eq? (entity-ref e #:id) id)) entities))))

;;; ------------------------------------------------------------ the logic
(define (bot-logic game)
  (lambda (e)
    (if (eq? (entity-ref e #:kind) 'bot)
        (let ((vx (entity-ref e #:vx 0)) (speed (entity-ref e #:speed 1))
              (dir (entity-ref e #:dir (if (negative? (entity-ref e #:vx 0)) -1 1))))
          (if (zero? vx)
              ;; A wall zeroed #:vx: walk the other way.
              (begin
                (note! game (list 'turned (entity-ref e #:id) 'at (entity-ref e #:x)))
                (entity-set (entity-set e #:dir (- dir)) #:vx (* (- dir) speed)))
              ;; Keep the patrol speed (a push from another body may change it).
              (let ((dir (if (negative? vx) -1 1)))
                (entity-set (entity-set e #:dir dir) #:vx (* dir speed)))))
        e)))

(define (raft-logic game)
  (lambda (e)
    (if (entity-ref e #:group-origin? #f)
        (let ((x (entity-ref e #:x)) (vx (entity-ref e #:vx 0)))
          (cond ((and (positive? vx) (>= x raft-max-x))
                 (note! game (list 'raft-turned 'at x))
                 (entity-set e #:vx (- raft-speed)))
                ((and (negative? vx) (<= x raft-min-x))
                 (note! game (list 'raft-turned 'at x))
                 (entity-set e #:vx raft-speed))
                (else e)))
        e)))

(define landed '())                     ; ids of the boxes that came to rest

(define (watch-boxes! game)
  (for-each (lambda (e)
              ;; At rest: supported, and not falling any more.
              (when (and (eq? (entity-ref e #:kind) 'box) (entity-ref e #:on-ground? #f)
                         (zero? (entity-ref e #:vy 0)) (not (memq (entity-ref e #:id) landed)))
                (set! landed (cons (entity-ref e #:id) landed))
                (note! game (list 'landed (entity-ref e #:id) 'y (entity-ref e #:y)))))
            (scene-entities (game-scene game))))

(define (update game dt)
  ;; The default engine-update has moved everything; now the game's own logic.
  (watch-boxes! game)
  (game-scene-set! game (scene-map-entities (game-scene game) (bot-logic game) (raft-logic game))))

(define (render game)
  (let ((frame (game-frame game))
        (entities (scene-entities (game-scene game))))
    (remember! frame entities)
    (when (and trace? (zero? (modulo frame 20)))
      (format #t "frame ~3d:" frame)
      (for-each (lambda (e)
                  (unless (eq? (entity-ref e #:kind) 'platform)
                    (format #t " ~a(~a,~a)~a" (entity-ref e #:id) (entity-ref e #:x) (entity-ref e #:y)
                            (if (entity-ref e #:on-ground? #f) "*" ""))))
                entities)
      (newline))))

(define demo-frames 300)

(define game
  (make-game title: "Downstroke — sandbox" width: 480 height: 240 frame-delay: 16
             scene: (make-scene entities: entities0 tilemap: arena)
             update: update render: render
             input-script: '()))

(define (run! frames)
  "Run the game up to frame FRAMES (it counts from where it stopped)."
  (game-run! game frames: frames))

(when (main-script? "sandbox.scm")
  (run! (script-number-argument 0 demo-frames))
  (format #t "(* marks #:on-ground?)~%"))
