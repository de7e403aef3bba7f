;; SPDX-License-Identifier: MIT
;;; (downstroke costs) — what a frame cost, step by step, and how often the
;;; collector runs. docs/engine.org, "What a frame costs: engine-stats" and
;;; "Memory against time: the collector".
(define-module (downstroke costs)
  #:use-module (downstroke native)
  #:use-module ((downstroke game) #:select (game-display))
  #:export (engine-stats gc-space-divisor set-gc-space-divisor!))

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
