;; SPDX-License-Identifier: MIT
;;; (downstroke physics) — the physics steps, all native.
(define-module (downstroke physics)
  #:use-module (downstroke native)
  #:use-module (downstroke world)
  #:use-module (downstroke read-only)
  #:re-export (resolve-entity-collisions sync-groups aabb-overlap?)
  #:export (*gravity* *jump-force* *on-solid-tolerance* collision-mode
            push-rule resting-contacts?
            step-tweens apply-acceleration apply-gravity apply-speed-limits apply-velocity-x
            apply-velocity-y apply-velocity resolve-tile-collisions-x
            resolve-tile-collisions-y detect-on-solid carry-riders step-scene))

;; The rules' numbers, from the core (src/constants.hpp): one home for each.
;; Read-only, for the core never reads a Scheme variable: a set! would change
;; nothing but the game's own idea of the number.
(define-read-only *gravity* %gravity
  (format #f "*gravity* is read-only: it is the default gravity, ~a px/frame², \
added to each #:gravity? entity's #:vy every frame; for a stronger or weaker \
fall, give the scene its own (make-scene gravity: 1/6) or an entity its \
#:gravity-scale" %gravity))
(define-read-only *jump-force* %jump-force
  (format #f "*jump-force* is read-only: it is the usual jump speed, ~a px/frame, \
which the engine itself never reads; jump at another speed by setting #:ay \
to your own number, e.g. (entity-set player #:ay -18)" %jump-force))
(define-read-only *on-solid-tolerance* %on-solid-tolerance
  (format #f "*on-solid-tolerance* is read-only: detect-on-solid always looks ~a px \
below the feet for ground, a fixed rule of the engine" %on-solid-tolerance))

(define collision-mode
  (make-parameter 'swept
                  (lambda (mode)
                    (unless (memq mode '(swept discrete))
                      (scm-error 'wrong-type-arg "collision-mode"
                                 "expected 'swept or 'discrete, got ~S" (list mode) #f))
                    mode)))

(define push-rule
  ;; Beyond the seed, and the default: push-apart never leaves a body in a
  ;; solid cell ('clipped, docs/semantics.org §4); 'seed is the seed's rule,
  ;; whose pushes ignore the map.
  (make-parameter 'clipped
                  (lambda (rule)
                    (unless (memq rule '(clipped seed))
                      (scm-error 'wrong-type-arg "push-rule"
                                 "expected 'clipped or 'seed, got ~S" (list rule) #f))
                    rule)))

(define resting-contacts?
  ;; Beyond the seed, off by default: a still body resting exactly on a tile
  ;; or on a still solid body skips gravity and holds up what lands on it,
  ;; so stacks stay put (docs/physics.org, "Resting contacts").
  (make-parameter #f (lambda (on?) (and on? #t))))

(define (tilemap-of scene) (and scene (scene-tilemap scene)))
(define (entities-of scene) (if scene (scene-entities scene) '()))

(define (step-tweens entity scene dt)
  "Advance ENTITY's #:tween by DT ms."
  (%step-tweens entity dt))
(define (apply-acceleration entity scene dt)
  "ENTITY with its #:ay added to #:vy and #:ay set to 0 (only a #:gravity?
entity; any other comes back as it is)."
  (%apply-acceleration entity))
(define (apply-gravity entity scene dt)
  "ENTITY with SCENE's gravity (scene-gravity; *gravity* when SCENE is #f)
times its #:gravity-scale (1 when absent) added to its #:vy (only a
#:gravity? entity)."
  (if scene (%apply-gravity entity (scene-gravity scene)) (%apply-gravity entity)))
(define (apply-speed-limits entity scene dt)
  "ENTITY with its #:drag taken off the size of #:vx and #:vy (never past
0), then #:vx and #:vy clamped to #:max-vx and #:max-vy; an entity with none
of these keys comes back as it is, whether or not it has #:gravity?."
  (%apply-speed-limits entity))
(define (apply-velocity-x entity scene dt) "ENTITY moved by its #:vx along x." (%apply-velocity-x entity))
(define (apply-velocity-y entity scene dt) "ENTITY moved by its #:vy along y." (%apply-velocity-y entity))
(define (apply-velocity entity scene dt)
  "ENTITY moved by #:vx along x and #:vy along y; #:skip-pipelines can skip
each axis on its own (velocity-x, velocity-y)."
  (%apply-velocity entity))
(define (resolve-tile-collisions-x entity scene dt)
  "ENTITY moved back along x out of the solid tiles of SCENE's map it ran
into, with #:vx 0 when it hit one."
  (%resolve-tile-collisions-x entity (tilemap-of scene) (collision-mode)))
(define (resolve-tile-collisions-y entity scene dt)
  "ENTITY moved back along y out of the solid tiles of SCENE's map it ran
into, with #:vy 0 when it hit one."
  (%resolve-tile-collisions-y entity (tilemap-of scene) (collision-mode)))
(define (detect-on-solid entity scene dt)
  "ENTITY with #:on-ground? set: whether a solid tile of SCENE's map or one
of its solid entities is right under it."
  (%detect-on-solid entity (tilemap-of scene) (entities-of scene)))

(define (carry-riders entities scene dt)
  "ENTITIES (this frame's entities, moved) with every rider of a moving
#:carries? platform moved by the platform's own movement since SCENE (the
scene the frame started from), resolved
against the solid tiles; a rider lifted into a solid cell gets #:crushed? #t
(and a crushable body with the key that is not crushed, #f)."
  (%carry-riders entities (tilemap-of scene) (entities-of scene) (collision-mode)))

(define* (step-scene scene dt #:key (substeps 1))
  "SCENE after one whole engine pass (the default-engine-update composition:
tweens, then motion, tiles, ground, carriers, push-apart and groups), done
all at once. With SUBSTEPS k > 1 (off by default), everything after the
tweens runs as k sub-frames of 1/k frame each: velocities and gravity
advance by a k-th, in flonums, and the motion converges to the continuous
one as k grows. Entities with #:contacts? #t get a contact report
(#:blocked, #:touching, #:standing-on; with #:contacts? 'sides each
#:touching entry is (name . side)) and the frame's pairs with them are
kept in the scene (scene-contacts, scene-contact-sides)."
  (unless (scene? scene)
    (scm-error 'wrong-type-arg "step-scene" "scene: expected a scene (make-scene), got ~S" (list scene) #f))
  (let* ((entities (scene-entities scene))
         (stepped (%step-entities entities (scene-tilemap scene) dt (collision-mode)
                                  substeps (resting-contacts?) (scene-gravity scene) (push-rule)))
         (old ((@@ (downstroke world) %scene-contacts) scene))
         (pairs (%frame-contacts stepped))
         (contacts (if (null? pairs) '() (cons pairs (%frame-contact-sides))))
         ;; '() and '() almost always: eq? first
         (contacts (if (or (eq? contacts old) (equal? contacts old)) old contacts)))
    (if (and (eq? stepped entities) (eq? contacts old))
        scene
        ((@@ (downstroke world) %scene-after-frame) scene stepped contacts))))
