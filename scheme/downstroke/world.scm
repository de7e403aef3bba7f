;; SPDX-License-Identifier: MIT
;;; (downstroke world) — scenes (immutable) and the camera (mutable).
(define-module (downstroke world)
  #:use-module (srfi srfi-9)
  #:use-module (rnrs bytevectors)
  #:use-module (downstroke native)
  #:export (make-scene scene? update-scene
            scene-entities scene-tilemap scene-camera scene-camera-target
            scene-contacts scene-contact-sides scene-gravity scene-data
            scene-map-entities scene-transform-entities
            make-camera camera? camera-x camera-y camera-x-set! camera-y-set!))

(define-record-type <camera>
  (%make-camera x y)
  camera?
  (x camera-x %camera-x-set!)
  (y camera-y %camera-y-set!))

(define (check-coordinate who axis v)
  ;; A NaN or infinite camera would draw nothing and follow nothing, silently.
  (unless (and (real? v) (not (nan? v)) (not (inf? v)))
    (scm-error 'wrong-type-arg who "camera ~A: expected a finite number, got ~S"
               (list axis v) #f))
  ;; An exact number past a double's range is finite, but no camera drawn
  ;; in doubles can stand there: say the range.
  (when (inf? (exact->inexact v))
    (scm-error 'out-of-range who
               "camera ~A: expected a number between -1.8e308 and 1.8e308 (a double's range), got ~S"
               (list axis v) #f)))

(define* (make-camera #:key (x 0) (y 0))
  "A camera at (X, Y), the world point drawn at the screen's top-left.
X and Y must be finite real numbers."
  (check-coordinate "make-camera" 'x x)
  (check-coordinate "make-camera" 'y y)
  (%make-camera x y))

(define (camera-x-set! camera x)
  "Move CAMERA so that world x X is at the screen's left edge."
  (check-coordinate "camera-x-set!" 'x x)
  (%camera-x-set! camera x))

(define (camera-y-set! camera y)
  "Move CAMERA so that world y Y is at the screen's top edge."
  (check-coordinate "camera-y-set!" 'y y)
  (%camera-y-set! camera y))

(define-record-type <scene>
  (%make-scene* entities tilemap camera camera-target contacts gravity data)
  scene?
  (entities scene-entities)
  (tilemap scene-tilemap)
  (camera scene-camera)
  (camera-target scene-camera-target)
  ;; The pairs the last step-scene pushed apart with a #:contacts? entity
  ;; (semantics §10), a report of the frame that made the scene: '() for
  ;; none, else (pairs . sides), SIDES a bytevector of the first bodies'
  ;; sides (0 left, 1 right, 2 up, 3 down), pair for pair — one allocation
  ;; a frame, named only when scene-contact-sides asks.
  (contacts %scene-contacts)
  ;; px/frame² (semantics §14); the seed's *gravity*, 1, by default.
  (gravity %scene-gravity)
  ;; The game's own state (score, lives, flags): any Scheme value, carried
  ;; by every scene made from this one, so a rewind restores it.
  (data %scene-data))

(define (scene-data scene)
  "The game's own value SCENE holds (make-scene data:, update-scene data:),
#f unless one was given. Every scene made from SCENE (update-scene,
step-scene, scene-map-entities, a frame of the game) keeps it, so a rewound
game has the data it had in that frame."
  (unless (scene? scene)
    (scm-error 'wrong-type-arg "scene-data" "expected a scene, got ~S" (list scene) #f))
  (%scene-data scene))

;; The seed's *gravity*: a scene that sets none falls as the seed's does.
(define default-gravity 1)

(define (scene-gravity scene)
  "SCENE's gravity in px per frame², what apply-gravity adds to a #:gravity?
entity's #:vy each frame (times its #:gravity-scale): 1 unless make-scene or
update-scene gave another (gravity:)."
  (unless (scene? scene)
    (scm-error 'wrong-type-arg "scene-gravity" "expected a scene, got ~S" (list scene) #f))
  (%scene-gravity scene))

(define (check-gravity who g)
  ;; Refused here, not frames later inside step-scene.
  (unless (and (real? g) (not (nan? g)) (not (inf? g)) (not (inf? (exact->inexact g))))
    (scm-error 'wrong-type-arg who "gravity: expected a finite real number, got ~S" (list g) #f)))

(define (scene-contacts scene)
  "The pairs (name-a . name-b) the step-scene that made SCENE pushed apart
where at least one of the two has #:contacts? #t, in the order resolved
(names: #:id, else the position in the list); '() for a scene no frame
made. update-scene keeps them."
  (unless (scene? scene)
    (scm-error 'wrong-type-arg "scene-contacts" "expected a scene, got ~S" (list scene) #f))
  (let ((report (%scene-contacts scene)))
    (if (null? report) '() (car report))))

(define side-names #(left right up down))

(define (scene-contact-sides scene)
  "The pairs of (scene-contacts SCENE) with the side each first body met the
second on: ((name-a name-b . side-of-a) …), in the same order. The side is
left, right, up or down: the axis and direction push-apart moved the pair
on, or for a pair nothing moved (a sensor's, two immovable bodies) the
axis its overlap began on last, from the bodies' speeds (with no relative
speed, the narrower overlap's). B met A on the opposite side; a landing
body's side is down."
  (unless (scene? scene)
    (scm-error 'wrong-type-arg "scene-contact-sides" "expected a scene, got ~S" (list scene) #f))
  (let ((report (%scene-contacts scene)))
    (if (null? report)
        '()
        (let ((sides (cdr report)))
          (let loop ((pairs (car report)) (k 0) (acc '()))
            (if (null? pairs)
                (reverse! acc)
                (loop (cdr pairs) (+ k 1)
                      (cons (cons* (caar pairs) (cdar pairs)
                                   (vector-ref side-names (bytevector-u8-ref sides k)))
                            acc))))))))

(define (check-scene who scene)
  (unless (scene? scene)
    (scm-error 'wrong-type-arg who "scene: expected a scene (make-scene), got ~S" (list scene) #f)))

(define (checked-scene scene)
  ;; For update-scene's defaults, which read SCENE before its body can check it.
  (check-scene "update-scene" scene)
  scene)

(define (check-entities who entities)
  (unless (list? entities)
    (scm-error 'wrong-type-arg who "entities: expected a list, got ~S" (list entities) #f)))

;; Refused when the scene is made, not frames later inside a step or a draw.
(define (check-scene-parts who tilemap camera)
  (unless (or (not tilemap) (tilemap? tilemap))
    (scm-error 'wrong-type-arg who "tilemap: expected a tilemap or #f, got ~S" (list tilemap) #f))
  (unless (camera? camera)
    (scm-error 'wrong-type-arg who "camera: expected a camera (make-camera), got ~S" (list camera) #f)))

(define* (make-scene #:key (entities '()) (tilemap #f) (camera (make-camera))
                     (camera-target #f) (gravity default-gravity) (data #f))
  "A scene: the entity list, an optional tilemap, a camera, optionally the
#:id (or #:tag) of the entity the camera follows, its GRAVITY in px per
frame², any finite real number (1, the seed's, by default; 1/6 for the
moon), and DATA, any value the game keeps with the scene (score, lives,
flags; #f by default)."
  (check-entities "make-scene" entities)
  (check-scene-parts "make-scene" tilemap camera)
  (check-gravity "make-scene" gravity)
  (%make-scene* entities tilemap camera camera-target '() gravity data))

(define* (update-scene scene #:key (entities (scene-entities (checked-scene scene)))
                       (tilemap (scene-tilemap (checked-scene scene)))
                       (camera (scene-camera (checked-scene scene)))
                       (camera-target (scene-camera-target (checked-scene scene)))
                       (gravity (%scene-gravity (checked-scene scene)))
                       (data (%scene-data (checked-scene scene))))
  "A copy of SCENE with the given fields replaced."
  (check-scene "update-scene" scene)
  (check-entities "update-scene" entities)
  (check-scene-parts "update-scene" tilemap camera)
  (check-gravity "update-scene" gravity)
  (%make-scene* entities tilemap camera camera-target (%scene-contacts scene) gravity data))

(define (%scene-with-entities scene entities)
  "SCENE with ENTITIES, a list the caller vouches for (no O(n) list? check):
for the native steps, whose result is always a proper list."
  (%make-scene* entities (scene-tilemap scene) (scene-camera scene)
                (scene-camera-target scene) (%scene-contacts scene) (%scene-gravity scene) (%scene-data scene)))

(define (%scene-after-frame scene entities contacts)
  "SCENE after a frame: its ENTITIES and its CONTACTS (a step-scene's report:
'(), or (pairs . side-bytevector))."
  (%make-scene* entities (scene-tilemap scene) (scene-camera scene)
                (scene-camera-target scene) contacts (%scene-gravity scene) (%scene-data scene)))

(define (map-keeping proc lst)
  ;; Like map, but returns LST itself when PROC returned every element as is.
  (let loop ((p lst) (acc '()) (changed? #f))
    (if (null? p)
        (if changed? (reverse! acc) lst)
        (let ((v (proc (car p))))
          (loop (cdr p) (cons v acc) (or changed? (not (eq? v (car p)))))))))

(define (scene-map-entities scene . steps)
  "Apply each of STEPS to every entity, one step after another."
  (update-scene scene
                #:entities (let loop ((entities (scene-entities scene)) (steps steps))
                             (if (null? steps)
                                 entities
                                 (loop (map-keeping (car steps) entities) (cdr steps))))))

(define (scene-transform-entities scene proc)
  "SCENE with its entity list replaced by (PROC entities)."
  (update-scene scene #:entities (proc (scene-entities scene))))
