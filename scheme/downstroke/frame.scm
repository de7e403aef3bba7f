;; SPDX-License-Identifier: MIT
;;; (downstroke frame) — one fixed step of a game: input, engine-update,
;;; update, camera, render; or, paused, a tick that steps nothing.
;;; docs/engine.org, "The frame".
(define-module (downstroke frame)
  #:use-module ((srfi srfi-1) #:select (find))
  #:use-module (downstroke native)
  #:use-module (downstroke entity)
  #:use-module (downstroke world)
  #:use-module (downstroke physics)
  #:use-module ((downstroke tilemap) #:select (tilemap-width tilemap-height tilemap-tile-width tilemap-tile-height))
  #:use-module (downstroke game)
  #:use-module (downstroke input)
  #:use-module (downstroke pause)
  #:use-module ((downstroke time-travel) #:select (remember-scene!))
  #:use-module ((downstroke recording) #:select (record-input!))
  #:use-module ((downstroke misspelt-keys) #:select (report-key-slips!))
  #:use-module ((downstroke hook-errors) #:select (call-bounded))
  #:export (default-engine-update camera-follow! step-game!))

(define (default-engine-update game dt)
  "One physics pass over the game's scene (step-scene), with the game's
collision mode, push rule, substeps and resting contacts."
  (let ((scene (game-scene game)))
    (when scene
      (parameterize ((collision-mode (game-collision-mode game))
                     (push-rule (game-push-rule game))
                     (resting-contacts? (game-resting-contacts? game)))
        (game-scene-set! game (step-scene scene dt #:substeps (game-substeps game)))))))

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

(define (step-game! game dt held)
  (if (game-paused? game) (pause-tick! game dt held) (step-frame! game dt held)))

(define (render-tick! game)
  (let ((render (game-render game))
        (display (game-display game)))
    (when display (%display-clear-commands! display))
    (when render (call-bounded game "render:" (lambda () (render game))))
    ;; Over what the game drew: a map reload's error, while it stands.
    (draw-reload-error! game)))

(define draw-reload-error! (@@ (downstroke live) draw-reload-error!))

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
