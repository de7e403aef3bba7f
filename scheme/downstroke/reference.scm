;; SPDX-License-Identifier: MIT
;;; (downstroke reference) — the physics rules of semantics §1–§6 and §9–§13 in plain Scheme.
;;;
;;; An executable specification: the same procedures as (downstroke physics),
;;; written for reading, not for speed, and sharing nothing with the native
;;; core but the tile queries of (downstroke tilemap). The differential tests
;;; step random scenes through both and demand equal? results, so every rule
;;; here is one the C++ core must follow to the bit.
(define-module (downstroke reference)
  #:use-module (srfi srfi-1)
  #:use-module (srfi srfi-11)
  #:use-module ((rnrs bytevectors) #:select (u8-list->bytevector))
  #:use-module (downstroke entity)
  #:use-module (downstroke world)
  #:use-module (downstroke tween)
  #:use-module ((downstroke physics) #:select (collision-mode push-rule resting-contacts?))
  #:use-module ((downstroke tilemap)
                #:select (tilemap-tile-width tilemap-tile-height
                          tilemap-cell-shape tilemap-steepest-ramp tilemap-solid-extent))
  #:re-export (collision-mode push-rule resting-contacts?)
  #:export (*gravity* *jump-force* *on-solid-tolerance*
            step-tweens apply-acceleration apply-gravity apply-speed-limits apply-velocity-x
            apply-velocity-y apply-velocity resolve-tile-collisions-x
            resolve-tile-collisions-y detect-on-solid resolve-entity-collisions
            sync-groups aabb-overlap? carry-riders step-scene))

(define *gravity* 1)
(define *jump-force* 15)
(define *on-solid-tolerance* 4)
;; How far into a one-way cell a body's feet may be for it to stand there
;; (semantics §9): less than the 1 px a first frame of falling takes it.
(define *one-way-footing* 1)
;; A stop rebounds (#:bounce, §13) only from a hit faster than this, in
;; px/frame: a body at rest on a floor hits it at exactly 1 every frame.
(define *bounce-rest-speed* 1)

;;; ---------------------------------------------------------------- numbers (§1)
;;; The core computes in double. A number is read as the nearest double,
;;; staying exact only when it is an exact integer; sums of exact integers
;;; stay exact (rounded like a double past 2^53); anything touching a flonum
;;; is computed on flonums, so IEEE rules (signed zeros) apply throughout.

(define (fl x) (exact->inexact x))

;; A number as the core reads it (§1).
(define (as-double x)
  (cond ((not (exact? x)) x)
        ((and (integer? x) (< (abs x) (expt 2 53))) x)
        ((integer? x) (let ((d (fl x))) (if (inf? d) d (inexact->exact d))))   ; ∞: put refuses it
        (else (fl x))))                 ; exact fractions are read as flonums

;; Sums and products as the core computes them (§1).
(define (num+ a b)
  (if (and (exact? a) (exact? b)) (as-double (+ a b)) (+ (fl a) (fl b))))
(define (num- a b)
  (if (and (exact? a) (exact? b)) (as-double (- a b)) (- (fl a) (fl b))))
(define (num* a b)
  (if (and (exact? a) (exact? b)) (as-double (* a b)) (* (fl a) (fl b))))

;;; ---------------------------------------------------------------- reading and writing entities (§2)

;;; Every step first checks its entities as a whole (semantics §2): a malformed
;;; plist, or a wrongly typed physics key (first occurrence), is an error
;;; naming the step, the key and the value.

(define number-keys
  '(#:x #:y #:width #:height #:vx #:vy #:ay #:group-local-x #:group-local-y #:gravity-scale))

;; The speed limits (§14): a finite real ≥ 0 each.
(define non-negative-keys '(#:max-vx #:max-vy #:drag))

(define (fail who message . args)
  (scm-error 'wrong-type-arg (symbol->string who) message args #f))

(define (check-finite who key v)
  ;; An exact number past a double's range is finite: its message says the
  ;; range, as the native decoder's does (bindings/scm_number.hpp).
  (when (or (nan? v) (inf? v)) (fail who "entity key ~S: expected a finite number, got ~S" key v))
  (when (inf? (exact->inexact v))
    (scm-error 'out-of-range (symbol->string who)
               "entity key ~S: expected a number between -1.8e308 and 1.8e308 (a double's range), got ~S"
               (list key v) #f)))

(define (check-value who key v)
  (cond ((memq key number-keys)
         (unless (real? v) (fail who "entity key ~S: expected a real number, got ~S" key v))
         (check-finite who key v))
        ((memq key '(#:skip-pipelines #:collides-with))
         (unless (and (list? v) (every symbol? v))
           (fail who "entity key ~S: expected a list of symbols, got ~S" key v)))
        ((eq? key #:category)
         (unless (symbol? v) (fail who "entity key ~S: expected a category symbol, got ~S" key v)))
        ((memq key non-negative-keys)
         (unless (real? v) (fail who "entity key ~S: expected a real number, got ~S" key v))
         (check-finite who key v)
         (unless (>= v 0)
           (scm-error 'out-of-range (symbol->string who)
                      "entity key ~S: expected a number ≥ 0, got ~S" (list key v) #f)))
        ;; A flag, with one symbol of its own (§10): another symbol is a slip
        ;; ('side, 'sidez) that would quietly give the plain report.
        ((eq? key #:contacts?)
         (when (and (symbol? v) (not (eq? v 'sides)))
           (fail who "entity key ~S: expected #t, #f or 'sides, got ~S" key v)))
        ((eq? key #:bounce)
         (unless (real? v) (fail who "entity key ~S: expected a real number, got ~S" key v))
         (check-finite who key v)
         (unless (<= 0 v 1)
           (scm-error 'out-of-range (symbol->string who)
                      "entity key ~S: expected a number from 0 to 1, got ~S" (list key v) #f)))))

;; A whole entity checked before a step reads it (§2).
(define (check who e)
  (let loop ((p e) (seen '()))
    (cond ((null? p) e)
          ((not (pair? p)) (fail who "malformed entity: expected a keyword plist, got ~S" e))
          ((not (keyword? (car p))) (fail who "malformed entity: ~S in key position of ~S" (car p) e))
          ((not (pair? (cdr p))) (fail who "malformed entity: key ~S has no value in ~S" (car p) e))
          ((memq (car p) seen) (loop (cddr p) seen))      ; first occurrence wins
          (else (check-value who (car p) (cadr p))
                (loop (cddr p) (cons (car p) seen))))))

(define (check-all who entities)
  (unless (list? entities) (fail who "expected a list of entities, got ~S" entities))
  (for-each (lambda (e) (check who e)) entities))

(define-syntax-rule (define-step (name e arg ...) doc body ...)
  ;; A per-entity step that checks its entity first.
  (define (name e arg ...)
    doc
    (check 'name e)
    body ...))

(define (num e key)
  "The number under KEY (0 when absent), as the core reads it (§1, §2)."
  (as-double (entity-ref e key 0)))

(define (flag e key) (and (entity-ref e key #f) #t))

;; Whether E skips STEP by #:skip-pipelines (§3).
(define (skips? e step) (entity-skips-pipeline? e step))

(define (put e key old new)
  "E with KEY set to NEW, unless NEW is the value OLD that was read: a step
writes a key only when its value or exactness changes. A result beyond the
range of a double (finite inputs near its limits) is an error."
  (when (and (real? new) (inf? new))
    (scm-error 'out-of-range #f "entity key ~S: the result ~S is beyond the range of a double"
               (list key new) #f))
  (if (eqv? old new) e (entity-set e key new)))

(define (entity-remove e key)
  "E without the first occurrence of KEY."
  (let loop ((p e) (acc '()))
    (cond ((null? p) e)
          ((eq? (car p) key) (append-reverse acc (cddr p)))
          (else (loop (cddr p) (cons* (cadr p) (car p) acc))))))

(define (same-or new old)
  "OLD when NEW holds the very same elements, so an unchanged list stays eq?."
  (if (every eq? new old) old new))

(define (map-keeping proc lst) (same-or (map proc lst) lst))

(define (keep-if-unchanged new old)
  "OLD when NEW holds the same keys and the same (eqv?) values in the same
order: a frame whose steps changed a value and put it back (gravity, then a
landing) hands the entity back as itself."
  (let loop ((a new) (b old))
    (cond ((and (null? a) (null? b)) old)
          ((or (null? a) (null? b)) new)
          ;; equal?: the contact report's lists (§10) are rebuilt when written
          ((and (eq? (car a) (car b)) (equal? (cadr a) (cadr b))) (loop (cddr a) (cddr b)))
          (else new))))

(define (scene-tiles scene) (and scene (scene-tilemap scene)))

;;; ---------------------------------------------------------------- contact reports (§10)
;;; Written only on entities with #:contacts? #t, each key by the step that
;;; owns it, and only when its value changes (equal?), so identity holds.

(define (contacts? e) (flag e #:contacts?))

(define sides '(left right up down))

(define (blocked-sides e)
  "The sides E's #:blocked names when it lists them in the order of SIDES,
each once; any other value names none."
  (let ((v (entity-ref e #:blocked '())))
    (let loop ((p v) (rest sides))
      (cond ((null? p) v)
            ((and (pair? p) (memq (car p) rest)) => (lambda (tail) (loop (cdr p) (cdr tail))))
            (else '())))))

(define absent (list 'absent))

(define (put-report e key value)
  "E with the report key KEY set to VALUE unless it holds it already: a
first write puts KEY in front (semantics §2), so E is shared whole."
  (let ((old (entity-ref e key absent)))
    (cond ((equal? value old) e)
          ((eq? old absent) (cons* key value e))
          (else (entity-set e key value)))))

(define (put-blocked e axis found gather?)
  "A tile step's part of #:blocked: its AXIS sides become FOUND (a later
sub-frame, GATHER?, adds FOUND to what the frame found already)."
  (if (not (contacts? e))
      e
      (let* ((old (blocked-sides e))
             (kept (if gather? old (remove (lambda (s) (memq s axis)) old))))
        (put-report e #:blocked (filter (lambda (s) (or (memq s kept) (memq s found))) sides)))))

(define (name-of e index)
  "An entity's name in a report: its #:id, or its position in the list."
  (or (entity-ref e #:id #f) index))

;;; ---------------------------------------------------------------- categories, sensors, bounce (§13)

(define (category-of e) (entity-ref e #:category 'default))

(define (accepts? e category)
  "E's #:collides-with names CATEGORY; without the key it names every one."
  (let ((names (entity-ref e #:collides-with #f)))
    (or (not names) (and (memq category names) #t))))

(define (meets? a b)
  "Each one's #:collides-with names the other's category."
  (and (accepts? a (category-of b)) (accepts? b (category-of a))))

(define (sensor? e) (flag e #:sensor?))
(define (senses? e) (and (sensor? e) (not (skips? e 'entity-collisions))))
(define (reports-pairs? e) (or (contacts? e) (sensor? e)))

(define (bounce-of e) (as-double (entity-ref e #:bounce 0)))

(define (pair-bounce a b)
  "The larger of two entities' bounces (on a tie, A's)."
  (let ((ba (bounce-of a)) (bb (bounce-of b)))
    (if (> bb ba) bb ba)))

(define (rebound v bounce)
  "The velocity a stop leaves: 0, or −v·bounce for a hit faster than
*bounce-rest-speed*; exact when both are."
  (cond ((or (zero? bounce) (not (> (abs (fl v)) *bounce-rest-speed*))) 0)
        ((and (exact? v) (exact? bounce)) (- (* v bounce)))
        (else (- (* (fl v) (fl bounce))))))

(define (stop-velocity e moved vel-key stopped? carried?)
  "MOVED (E after a tile step that zeroed VEL-KEY when STOPPED?) with the
stop's rebound; a carried move never rebounds."
  (if (and stopped? (not carried?))
      (put moved vel-key (num moved vel-key) (rebound (num e vel-key) (bounce-of e)))
      moved))

;;; ---------------------------------------------------------------- motion (§4)
;;; Each motion step has a sub-frame form taking H: #f for the seed's whole
;;; frame, else the flonum 1/k of a frame that make-game's substeps: k gives.

(define (share rate h)
  "A per-frame RATE over a sub-frame: the rate itself for a whole frame (H
#f), else rate·h computed in flonums."
  (if h (* (fl rate) h) rate))

(define (gravity-of scene)
  "SCENE's gravity as the core reads it (§14); *gravity* without a scene."
  (if scene (as-double (scene-gravity scene)) *gravity*))

(define (scale-of e) (as-double (entity-ref e #:gravity-scale 1)))

(define (pulled-down? e g)
  "Whether gravity G pulls E down (G × its scale > 0): only then can it rest."
  (let ((s (scale-of e)))
    (and (not (zero? g)) (not (zero? s)) (eq? (positive? g) (positive? s)))))

(define (gravity-step e h g)
  (if (or (not (flag e #:gravity?)) (skips? e 'gravity))
      e
      (let ((vy (num e #:vy)))
        (put e #:vy vy (num+ vy (share (num* g (scale-of e)) h))))))

;;; Speed limits (§14): drag, then the caps. A zero limit reads as exact 0.

(define (limit e key)
  "E's limit under KEY as the core reads it, or #f when absent."
  (let ((v (entity-ref e key #f)))
    (and v (if (zero? v) 0 (as-double v)))))

(define (toward-zero v d)
  "V moved toward 0 by D (> 0), never past it; a still V is left as it is."
  (cond ((> v d) (num- v d))
        ((< v (- d)) (num+ v d))
        ((zero? v) v)
        ((and (exact? v) (exact? d)) 0)
        (else 0.)))

(define (cap-speed v cap)
  "V with its size at most CAP (#f: no cap)."
  (cond ((not cap) v)
        ((> v cap) cap)
        ((< v (- cap)) (- cap))
        (else v)))

(define (speed-limits-step e h)
  (let ((drag (limit e #:drag)) (mx (limit e #:max-vx)) (my (limit e #:max-vy)))
    (if (or (skips? e 'speed-limits) (not (or (and drag (not (zero? drag))) mx my)))
        e
        (let* ((vx (num e #:vx)) (vy (num e #:vy))
               (d (and drag (not (zero? drag)) (share drag h)))
               (nx (cap-speed (if d (toward-zero vx d) vx) mx))
               (ny (cap-speed (if d (toward-zero vy d) vy) my)))
          (put (put e #:vx vx nx) #:vy vy ny)))))

(define (velocity-step e h pos-key vel-key skip)
  ;; In a sub-frame a still body's coordinate is left as it is (exact stays
  ;; exact); the whole frame adds even a zero, as the seed's step does.
  (let ((vel (num e vel-key)))
    (if (or (skips? e skip) (and h (zero? vel)))
        e
        (let ((pos (num e pos-key)))
          (put e pos-key pos (num+ pos (share vel h)))))))

(define-step (apply-acceleration e scene dt)
  "vy += ay, then ay = 0 (written only when it was non-zero) (§4)."
  (if (or (not (flag e #:gravity?)) (skips? e 'acceleration))
      e
      (let* ((vy (num e #:vy)) (ay (num e #:ay))
             (e (put e #:vy vy (num+ vy ay))))
        (if (zero? ay) e (put e #:ay ay 0)))))

(define-step (apply-gravity e scene dt)
  "vy += the scene's gravity × #:gravity-scale (§4, §14)."
  (gravity-step e #f (gravity-of scene)))

(define-step (apply-speed-limits e scene dt)
  "vx and vy toward 0 by #:drag, then clamped to #:max-vx and #:max-vy (§14)."
  (speed-limits-step e #f))

(define-step (apply-velocity-x e scene dt)
  "x += vx (§4)."
  (velocity-step e #f #:x #:vx 'velocity-x))

(define-step (apply-velocity-y e scene dt)
  "y += vy (§4)."
  (velocity-step e #f #:y #:vy 'velocity-y))

(define-step (apply-velocity e scene dt)
  "Both axes, each skippable on its own (§4)."
  (apply-velocity-y (apply-velocity-x e scene dt) scene dt))

;;; ---------------------------------------------------------------- tile cells (§4)

(define (cells-of pos size tile)
  "The cells ⌊pos/tile⌋ … ⌈(pos+size)/tile⌉−1 the span [pos, pos+size)
overlaps, as (first . last), or #f when size ≤ 0. Exact spans are divided
exactly; others in double."
  (cond ((not (> size 0)) #f)
        ((and (exact? pos) (exact? size))
         (cons (floor (/ pos tile)) (- (ceiling (/ (+ pos size) tile)) 1)))
        (else
         (cons (inexact->exact (floor (/ (fl pos) tile)))
               (- (inexact->exact (ceiling (/ (+ (fl pos) (fl size)) tile))) 1)))))

(define (cell-of pos tile)
  (if (exact? pos)
      (floor (/ pos tile))
      (inexact->exact (floor (/ (fl pos) tile)))))

(define (clip range first count)
  "The part of RANGE within [first, first+count): cells outside the map are
empty, so there is no need to look at them."
  (and range
       (let ((lo (max (car range) first))
             (hi (min (cdr range) (+ first count -1))))
         (and (<= lo hi) (cons lo hi)))))

(define (range->list range step)
  (if range
      (if (> step 0)
          (iota (+ (- (cdr range) (car range)) 1) (car range))
          (reverse (iota (+ (- (cdr range) (car range)) 1) (car range))))
      '()))

(define (candidate-cells pos vel size tile mode)
  "The cells to test along the moving axis. Discrete: the box as it is.
Swept: the box plus every cell its leading edge crossed, i.e. from where the
leading edge started (pos − vel, plus size when moving forward) to the box."
  (if (or (eq? mode 'discrete) (not (> size 0)))
      (cells-of pos size tile)
      (let ((start (num- pos vel)))
        (if (> vel 0)
            (let* ((lead-start (num+ start size))
                   (lo (if (< lead-start pos) lead-start pos)))
              (cells-of lo (num- (num+ pos size) lo) tile))
            (let* ((end (num+ pos size))
                   (hi (if (> start end) start end)))
              (cells-of pos (num- hi pos) tile))))))

(define (snap pos vel size tile cell)
  "Where the box stops against CELL: flush with its near side. The result is
exact when the position and size were."
  (let* ((exact (and (exact? pos) (exact? size)))
         (edge (* (if (> vel 0) cell (+ cell 1)) tile))
         (v (if (> vel 0) (num- edge size) edge)))
    (if exact v (fl v))))

;;; ---------------------------------------------------------------- shaped cells (§12)
;;; A cell as (tilemap-cell-shape tm col row) gives it: #f, 'solid, 'one-way,
;;; or a shape #(x0 y0 x1 y1 cut ax ay bx by one-way?) in tile px, CUT one of
;;; box floor ceiling, with an 11th slot listing further slants ((ax ay bx by)
;;; ...) for a convex polygon cut by several, and a 12th listing the
;;; underside's slants of a floor shape slanted below too (two-sided). The core computes every quantity of a shape in doubles
;;; in one order of operations (src/detail/placed_shape.hpp); these do the
;;; same on flonums, so both get the same bits. Whole cells keep §4's rules,
;;; so a map without shapes is stepped as before.

(define (cut-of s) (vector-ref s 4))
(define (one-way-shape? s) (vector-ref s 9))

(define (place s col row tm)
  "Shape S at cell (COL, ROW): #(s ox oy), the cell's corner in flonums."
  (vector s (* (fl col) (tilemap-tile-width tm)) (* (fl row) (tilemap-tile-height tm))))

(define (p-cut p) (cut-of (vector-ref p 0)))
(define (p-ref p i) (vector-ref (vector-ref p 0) i))
(define (p-left p) (+ (vector-ref p 1) (p-ref p 0)))
(define (p-right p) (+ (vector-ref p 1) (p-ref p 2)))
(define (p-box-top p) (+ (vector-ref p 2) (p-ref p 1)))
(define (p-box-bottom p) (+ (vector-ref p 2) (p-ref p 3)))

(define (shape-slants s)
  "S's slanted lines, left to right, each (ax ay bx by)."
  (cons (list (vector-ref s 5) (vector-ref s 6) (vector-ref s 7) (vector-ref s 8))
        (if (> (vector-length s) 10) (vector-ref s 10) '())))
(define (p-slants p) (shape-slants (vector-ref p 0)))
(define (shape-under s)
  "A two-sided shape's underside slants, left to right; '() for any other."
  (if (> (vector-length s) 11) (vector-ref s 11) '()))
(define (p-under p) (shape-under (vector-ref p 0)))
(define (two-sided? p) (pair? (p-under p)))

(define (p-line-of p l x)
  "Slant L's y at X: ((oy + ay)·dx + ((x − ox) − ax)·dy) / dx."
  (apply (lambda (ax ay bx by)
           (let ((ox (vector-ref p 1)) (oy (vector-ref p 2)) (dx (- bx ax)) (dy (- by ay)))
             (/ (+ (* (+ oy ay) dx) (* (- (- x ox) ax) dy)) dx)))
         l))

(define (p-line p x)
  "The y at X of the line bounding the solid: the lowest of a floor shape's
slants (greatest y), the highest of a ceiling shape's, the first of a tie."
  (let ((floor? (eq? (p-cut p) 'floor)))
    (let loop ((ls (cdr (p-slants p))) (v (p-line-of p (car (p-slants p)) x)))
      (if (null? ls)
          v
          (let ((w (p-line-of p (car ls) x)))
            (loop (cdr ls) (if (if floor? (< v w) (< w v)) w v)))))))

(define (p-under-line p x)
  "The y at X of the line bounding a two-sided shape from below: the highest
of its underside's slants, the first of a tie."
  (let loop ((ls (cdr (p-under p))) (v (p-line-of p (car (p-under p)) x)))
    (if (null? ls)
        v
        (let ((w (p-line-of p (car ls) x)))
          (loop (cdr ls) (if (< w v) w v))))))

(define (slants-apex s slants floor?)
  "Where (tile px) SLANTS, left to right, are highest (FLOOR?: a top) or
lowest: x1 when every slant climbs that way rightwards, x0 when none does,
else the right end of the last that does (within [x0, x1])."
  (let* ((n (length slants))
         (climbs? (lambda (l) (if floor? (< (list-ref l 3) (list-ref l 1))
                                  (> (list-ref l 3) (list-ref l 1)))))
         (last (let loop ((i 0) (ls slants) (last #f))
                 (if (null? ls) last (loop (+ i 1) (cdr ls) (if (climbs? (car ls)) i last))))))
    (cond ((not last) (vector-ref s 0))
          ((= last (- n 1)) (vector-ref s 2))
          (else (max (vector-ref s 0) (min (vector-ref s 2) (list-ref (list-ref slants last) 2)))))))
(define (shape-apex s)
  "Where (tile px) a floor shape's top is highest, a ceiling shape's bottom lowest."
  (slants-apex s (shape-slants s) (eq? (cut-of s) 'floor)))
(define (shape-under-apex s)
  "Where (tile px) a shape's bottom is lowest: a ceiling shape's apex, a
two-sided shape's underside's."
  (if (eq? (cut-of s) 'ceiling) (shape-apex s) (slants-apex s (shape-under s) #f)))
(define (p-apex p) (+ (vector-ref p 1) (shape-apex (vector-ref p 0))))
(define (p-under-apex p) (+ (vector-ref p 1) (shape-under-apex (vector-ref p 0))))

(define (clamp v lo hi) (cond ((< v lo) lo) ((< hi v) hi) (else v)))

(define (p-top p x)
  (if (eq? (p-cut p) 'floor) (clamp (p-line p x) (p-box-top p) (p-box-bottom p)) (p-box-top p)))
(define (p-bottom p x)
  (cond ((eq? (p-cut p) 'ceiling) (clamp (p-line p x) (p-box-top p) (p-box-bottom p)))
        ((two-sided? p) (clamp (p-under-line p x) (p-box-top p) (p-box-bottom p)))
        (else (p-box-bottom p))))
(define (p-slanted-below? p) (or (eq? (p-cut p) 'ceiling) (two-sided? p)))

(define (p-over p lo hi)
  "The part [a, b) of the span [LO, HI) over the shape, as (a . b), or #f."
  (let ((a (if (< lo (p-left p)) (p-left p) lo))
        (b (if (< (p-right p) hi) (p-right p) hi)))
    (and (< a b) (cons a b))))

(define (p-top-over p ab)
  "The highest top over [a, b): at the apex clamped to [a, b] (b as the
limit), the top falling away from the apex on either side; for a ramp, the
end its line rises towards."
  (p-top p (clamp (p-apex p) (car ab) (cdr ab))))
(define (p-bottom-over p ab)
  (p-bottom p (clamp (if (eq? (p-cut p) 'ceiling) (p-apex p) (p-under-apex p)) (car ab) (cdr ab))))
(define (p-surface p ab) (if (eq? (p-cut p) 'floor) (p-top-over p ab) (p-box-top p)))
(define (p-underside p ab) (if (p-slanted-below? p) (p-bottom-over p ab) (p-box-bottom p)))
(define (p-solid-over? p ab)
  (case (p-cut p)
    ((floor) (< (p-top-over p ab) (p-underside p ab)))
    ((ceiling) (> (p-bottom-over p ab) (p-box-top p)))
    (else #t)))

(define (p-overlaps? p lo hi top bottom)
  "Whether the box [LO, HI) × [TOP, BOTTOM) overlaps the shape's solid."
  (let ((ab (p-over p lo hi)))
    (and ab (p-solid-over? p ab)
         (case (p-cut p)
           ((floor) (and (< top (p-underside p ab)) (> bottom (p-top-over p ab))))
           ((ceiling) (and (> bottom (p-box-top p)) (< top (p-bottom-over p ab))))
           (else (and (< top (p-box-bottom p)) (> bottom (p-box-top p))))))))

(define (exact-if exact? v)
  "A written value: exact when its inputs were and it is an integer."
  (if (and exact? (integer? v)) (inexact->exact v) v))

(define (box-exact? e)
  (every (lambda (k) (exact? (num e k))) '(#:x #:y #:width #:height)))

(define (each-cell tm cols rows proc)
  "(PROC col row cell) for the cells of the ranges, rows outer; the first
true result, or #f."
  (let rows-loop ((rs (range->list (and cols rows) 1)))
    (and (pair? rs)
         (or (let cols-loop ((cs (range->list cols 1)))
               (and (pair? cs)
                    (or (proc (car cs) (car rs) (tilemap-cell-shape tm (car cs) (car rs)))
                        (cols-loop (cdr cs)))))
             (rows-loop (cdr rs))))))

(define (solid-extent tm)
  "TM's block of cells that can be solid, (first-col first-row cols rows);
an empty block when it has none (tilemap-solid-extent's #f), which every
clip below then leaves empty."
  (or (tilemap-solid-extent tm) '(0 0 0 0)))

(define (box-rows e tm)
  (apply (lambda (col0 row0 cols rows)
           (clip (cells-of (num e #:y) (num e #:height) (tilemap-tile-height tm)) row0 rows))
         (solid-extent tm)))
(define (box-cols e tm)
  (apply (lambda (col0 row0 cols rows)
           (clip (cells-of (num e #:x) (num e #:width) (tilemap-tile-width tm)) col0 cols))
         (solid-extent tm)))
(define (span-of e) (cons (fl (num e #:x)) (fl (num+ (num e #:x) (num e #:width)))))

(define (overlaps-solid? e tm)
  "Whether E's box overlaps a whole solid cell or a solid shape."
  (let ((span (span-of e)) (top (fl (num e #:y))) (bottom (fl (num+ (num e #:y) (num e #:height)))))
    (each-cell tm (box-cols e tm) (box-rows e tm)
               (lambda (c r cell)
                 (or (eq? cell 'solid)
                     (and (vector? cell) (not (one-way-shape? cell))
                          (p-overlaps? (place cell c r tm) (car span) (cdr span) top bottom)))))))

;;; resolve-tile-collisions-x: column by column from the side the body moves
;;; from, a wall (a whole solid cell, or a solid shape's near side) stops it;
;;; otherwise the column's ramps move it along y (§12).

(define (enters-side? p fwd? lead0 lead1 top bottom)
  (let ((side (if fwd? (p-left p) (p-right p))))
    (and (if fwd? (and (<= lead0 side) (< side lead1)) (and (< lead1 side) (<= side lead0)))
         (< top (p-bottom p side))
         (> bottom (p-top p side)))))

(define (enters-from-above? p fwd? lead0 feet)
  (let ((at (if fwd?
                (if (< (p-left p) lead0) lead0 (p-left p))
                (if (< lead0 (p-right p)) lead0 (p-right p)))))
    (<= feet (p-top p at))))

(define (wall-in-column e tm c fwd? lead0 lead1)
  "The nearest wall of column C at E's rows: (position . whole?), or #f."
  (let ((top (fl (num e #:y))) (bottom (fl (num+ (num e #:y) (num e #:height)))))
    (let loop ((rs (range->list (box-rows e tm) 1)) (found #f))
      (if (null? rs)
          found
          (let ((cell (tilemap-cell-shape tm c (car rs))))
            (cond ((eq? cell 'solid)
                   (cons (* (fl (if fwd? c (+ c 1))) (tilemap-tile-width tm)) #t))
                  ((and (vector? cell) (not (one-way-shape? cell))
                        (enters-side? (place cell c (car rs) tm) fwd? lead0 lead1 top bottom))
                   (let* ((p (place cell c (car rs) tm))
                          (side (if fwd? (p-left p) (p-right p))))
                     (loop (cdr rs)
                           (if (or (not found) (if fwd? (< side (car found)) (> side (car found))))
                               (cons side #f)
                               found))))
                  (else (loop (cdr rs) found))))))))

(define (climb-column e tm c fwd? lead0 sweep lifted)
  "E moved out of the ramps of column C that its box overlaps over SWEEP:
(values e lifted), LIFTED 1 once lifted, −1 once pushed down; E #f when
squeezed."
  (let ((limit (+ (list-ref (solid-extent tm) 3) 1)))
    (let loop ((e e) (lifted lifted) (guard 0))
      (if (> guard limit)
          (values #f lifted)
          (let* ((head (fl (num e #:y))) (feet (fl (num+ (num e #:y) (num e #:height))))
                 (up #f) (down #f) (new-feet feet) (new-head head))
            (for-each
             (lambda (r)
               (let ((cell (tilemap-cell-shape tm c r)))
                 (when (and (vector? cell) (not (eq? (cut-of cell) 'box)))
                   (let* ((p (place cell c r tm))
                          (ab (p-over p (car sweep) (cdr sweep))))
                     (when (and ab (p-solid-over? p ab))
                       (if (eq? (cut-of cell) 'floor)
                           (unless (and (one-way-shape? cell)
                                        (or (flag e #:drop-through?)
                                            (not (enters-from-above? p fwd? lead0 feet))))
                             (let ((t (p-top-over p ab)))
                               (when (and (< head (p-underside p ab)) (> feet t))
                                 (set! up #t)
                                 (when (< t new-feet) (set! new-feet t)))))
                           (unless (one-way-shape? cell)
                             (let ((u (p-bottom-over p ab)))
                               (when (and (> feet (p-box-top p)) (< head u))
                                 (set! down #t)
                                 (when (< new-head u) (set! new-head u)))))))))))
             (range->list (box-rows e tm) 1))
            (cond ((and (not up) (not down)) (values e lifted))
                  ((or (and up down) (and up (< lifted 0)) (and down (> lifted 0))) (values #f lifted))
                  (else
                   (let ((y (exact-if (box-exact? e)
                                      (if up (- new-feet (fl (num e #:height))) new-head))))
                     (loop (put e #:y (num e #:y) y) (if up 1 -1) (+ guard 1))))))))))

(define (shaped-x e tm h)
  "(values entity stopped?) for the x step (§4, §12)."
  (let* ((tw (tilemap-tile-width tm))
         (x (num e #:x)) (y (num e #:y)) (w (num e #:width))
         (vel (num e #:vx)) (move (share vel h)) (fwd? (> vel 0))
         (x-start (num- x move))
         (lead0 (fl (if fwd? (num+ x-start w) x-start)))
         (lead1 (fl (if fwd? (num+ x w) x)))
         (sweep (cond ((eq? (collision-mode) 'discrete) (cons (fl x) (fl (num+ x w))))
                      (fwd? (cons (fl x-start) (fl (num+ x w))))
                      (else (cons (fl x) (fl (num+ x-start w))))))
         (along (apply (lambda (col0 row0 cols rows)
                         (clip (candidate-cells x move w tw (collision-mode)) col0 cols))
                       (solid-extent tm))))
    (define (finish moved stopped? check?)
      ;; A move that leaves the box in a solid is not made at all.
      (let* ((back? (or (not moved) (and check? (overlaps-solid? moved tm))))
             (moved (if back? (put (put e #:x x x-start) #:y y y) moved))
             (stopped? (or stopped? back?)))
        (values (if stopped? (put moved #:vx vel 0) moved) stopped?)))
    (let loop ((cs (range->list along (if fwd? 1 -1))) (e e) (lifted 0))
      (if (null? cs)
          (finish e #f (not (zero? lifted)))
          (let ((wall (wall-in-column e tm (car cs) fwd? lead0 lead1)))
            (if wall
                (let* ((exact (and (exact? x) (exact? w)))
                       (v (if fwd? (- (car wall) (fl w)) (car wall))))
                  (finish (put e #:x x (if exact (inexact->exact v) v)) #t
                          (or (not (zero? lifted)) (not (cdr wall)))))
                (let-values (((climbed lifted) (climb-column e tm (car cs) fwd? lead0 sweep lifted)))
                  (if climbed
                      (loop (cdr cs) climbed lifted)
                      (finish #f #t #f)))))))))

(define (shaped-y e tm h)
  "(values entity stopped?) for the y step (§4, §9, §12)."
  (let* ((th (tilemap-tile-height tm))
         (y (num e #:y)) (hh (num e #:height))
         (vel (num e #:vy)) (move (share vel h)) (fwd? (> vel 0))
         (may-land? (and fwd? (not (flag e #:drop-through?))))
         (feet-before (fl (num+ (num- y move) hh))) (head-before (fl (num- y move)))
         (feet (fl (num+ y hh))) (head (fl y))
         (span (span-of e))
         (rows (apply (lambda (col0 row0 cols rows)
                        (clip (candidate-cells y move hh th (collision-mode)) row0 rows))
                      (solid-extent tm)))
         (cols (box-cols e tm)))
    (let loop ((rs (range->list (and cols rows) (if fwd? 1 -1))))
      (if (null? rs)
          (values e #f)
          (let* ((r (car rs))
                 (whole? (any (lambda (c)
                                (let ((cell (tilemap-cell-shape tm c r)))
                                  (or (eq? cell 'solid)
                                      (and may-land? (eq? cell 'one-way) (<= feet-before (* r th))))))
                              (range->list cols 1))))
            (if whole?
                (let ((e (put e #:y y (snap y vel hh th r))))
                  (values (put e #:vy vel 0) #t))
                (let ((stop (fold (lambda (c stop)
                                    (let ((cell (tilemap-cell-shape tm c r)))
                                      (if (and (vector? cell) (or (not (one-way-shape? cell)) may-land?))
                                          (let* ((p (place cell c r tm))
                                                 (ab (p-over p (car span) (cdr span))))
                                            (if (and ab (p-solid-over? p ab))
                                                (if fwd?
                                                    (let ((t (p-surface p ab)))
                                                      (if (and (<= feet-before t) (< t feet)
                                                               (or (not stop) (< t stop)))
                                                          t stop))
                                                    (let ((u (p-underside p ab)))
                                                      (if (and (>= head-before u) (> u head)
                                                               (or (not stop) (> u stop)))
                                                          u stop)))
                                                stop))
                                          stop)))
                                  #f (range->list cols 1))))
                  (if stop
                      (let ((e (put e #:y y (exact-if (box-exact? e) (if fwd? (- stop (fl hh)) stop)))))
                        (values (put e #:vy vel 0) #t))
                      (loop (cdr rs))))))))))

(define (snap-down e tm h)
  "A body that stood on the ground and walks on follows it down a ramp (§12):
(values entity snapped?)."
  (let* ((th (tilemap-tile-height tm))
         (reach (* (abs (fl (share (num e #:vx) h))) (tilemap-steepest-ramp tm)))
         (y (num e #:y)) (hh (num e #:height))
         (feet (fl (num+ y hh))) (lowest (+ feet reach))
         (span (span-of e))
         (drop? (flag e #:drop-through?)))
    (if (not (and (flag e #:gravity?) (flag e #:on-ground?) (> reach 0)))
        (values e #f)
        (let* ((rows (apply (lambda (col0 row0 cols rows)
                              (clip (cons (cell-of (num+ y hh) th) (cell-of lowest th)) row0 rows))
                            (solid-extent tm)))
               (cols (box-cols e tm))
               (ground
                (let loop ((rs (range->list (and cols rows) 1)))
                  (and (pair? rs)
                       (or (fold (lambda (c found)
                                   (let* ((r (car rs))
                                          (cell (tilemap-cell-shape tm c r))
                                          (top (cond ((or (eq? cell 'solid) (and (eq? cell 'one-way) (not drop?)))
                                                      (* (fl r) th))
                                                     ((and (vector? cell) (not (and (one-way-shape? cell) drop?)))
                                                      (let* ((p (place cell c r tm))
                                                             (ab (p-over p (car span) (cdr span))))
                                                        (and ab (p-solid-over? p ab) (p-surface p ab))))
                                                     (else #f))))
                                     (if (and top (<= feet top) (<= top lowest) (or (not found) (< top found)))
                                         top found)))
                                 #f (range->list cols 1))
                           (loop (cdr rs)))))))
          (if ground
              (let ((e (put e #:y y (exact-if (box-exact? e) (- ground (fl hh))))))
                (values (put e #:vy (num e #:vy) 0) #t))
              (values e #f))))))

(define-step (resolve-tile-collisions-x e scene dt)
  "Moving along x into solid cells (of the rows the box spans): snap flush
against the first one, vx = 0 (§4)."
  (tiles-x e scene #f #f))

(define* (tiles-x e scene h gather? #:optional carried?)
  (let ((tm (scene-tiles scene)))
    (cond ((skips? e 'tile-collisions-x) e)
          ((or (not tm) (zero? (num e #:vx))) (put-blocked e '(left right) '() gather?))
          (else
           (let-values (((moved stopped?) (shaped-x e tm h)))
             (put-blocked (stop-velocity e moved #:vx stopped? carried?) '(left right)
                          (if stopped? (list (if (> (num e #:vx) 0) 'right 'left)) '())
                          gather?))))))

(define-step (resolve-tile-collisions-y e scene dt)
  "The same along y, in the columns the box spans; vy = 0 (§4)."
  (tiles-y e scene #f #f))

(define* (tiles-y e scene h gather? #:optional carried?)
  (let ((tm (scene-tiles scene)))
    (cond
     ((skips? e 'tile-collisions-y) e)
     ((or (not tm) (zero? (num e #:vy))) (put-blocked e '(up down) '() gather?))
     (else
      (let*-values (((moved stopped?) (shaped-y e tm h))
                    ((moved) (stop-velocity e moved #:vy stopped? carried?))
                    ((moved stopped?) (if (or stopped? (not (> (num e #:vy) 0)) carried?)
                                          (values moved stopped?)
                                          (snap-down moved tm h))))
        (put-blocked moved '(up down)
                     (if stopped? (list (if (> (num e #:vy) 0) 'down 'up)) '())
                     gather?))))))

;;; ---------------------------------------------------------------- ground (§4)

(define (whole-cell-supports? e tm)
  "A solid cell in the row just under the box (row ⌊(y+h)/th⌋), in any of
the columns it spans; or a one-way cell there (§9), for a body not rising,
not dropping through, its feet less than *one-way-footing* into the cell."
  (and tm
       (apply (lambda (col0 row0 cols rows)
                (let* ((th (tilemap-tile-height tm))
                       (feet (num+ (num e #:y) (num e #:height)))
                       (row (cell-of feet th))
                       (on-top? (and (>= (num e #:vy) 0) (not (flag e #:drop-through?))
                                     (< (- feet (* row th)) *one-way-footing*)))
                       (span (clip (cells-of (num e #:x) (num e #:width) (tilemap-tile-width tm))
                                   col0 cols)))
                  (and (clip (cons row row) row0 rows)
                       (any (lambda (col) (let ((cell (tilemap-cell-shape tm col row)))
                                            (or (eq? cell 'solid) (and on-top? (eq? cell 'one-way)))))
                            (range->list span 1)))))
              (solid-extent tm))))

(define (shape-supports? e tm)
  "A shape in the row under the feet whose surface they are on or below,
above its underside; a one-way shape only within *one-way-footing* of its
surface, for a body not rising nor dropping through (§12)."
  (let* ((feet (num+ (num e #:y) (num e #:height)))
         (row (cell-of feet (tilemap-tile-height tm)))
         (f (fl feet))
         (span (span-of e))
         (may-stand? (and (>= (num e #:vy) 0) (not (flag e #:drop-through?)))))
    (any (lambda (c)
           (let ((cell (tilemap-cell-shape tm c row)))
             (and (vector? cell)
                  (or (not (one-way-shape? cell)) may-stand?)
                  (let* ((p (place cell c row tm))
                         (ab (p-over p (car span) (cdr span))))
                    (and ab (p-solid-over? p ab)
                         (let ((top (p-surface p ab)))
                           (and (<= top f) (< f (p-underside p ab))
                                (or (not (one-way-shape? cell)) (< (- f top) *one-way-footing*)))))))))
         (range->list (box-cols e tm) 1))))

(define (tile-supports? e tm)
  (and tm (or (whole-cell-supports? e tm) (shape-supports? e tm))))

(define (entity-supports? e o)
  "O holds E up: solid, not a sensor nor a ghost, overlapping horizontally,
its top within the tolerance of E's feet, moving at nearly E's vertical
speed, and their categories meet (§13)."
  (and (collides? o)
       (< (num e #:x) (num+ (num o #:x) (num o #:width)))
       (< (num o #:x) (num+ (num e #:x) (num e #:width)))
       (<= (abs (num- (num+ (num e #:y) (num e #:height)) (num o #:y))) *on-solid-tolerance*)
       (<= (abs (num- (num e #:vy) (num o #:vy))) *on-solid-tolerance*)
       (may-stand-on? e o)
       (meets? e o)))

(define (may-stand-on? e o)
  "A one-way O (§9) holds up only an E that is not rising nor dropping through."
  (or (not (flag o #:one-way?))
      (and (>= (num e #:vy) 0) (not (flag e #:drop-through?)))))

;;; Resting contacts (beyond the seed; the resting-contacts? parameter): a
;;; still body whose feet are exactly on a solid tile's top, or on the top of
;;; a still solid body overlapping it, skips gravity and holds up what comes
;;; down on it.

(define (rests-on-tile? e tm)
  (let ((feet (num+ (num e #:y) (num e #:height))))
    (and tm
         (integer? (/ (inexact->exact feet) (tilemap-tile-height tm)))   ; fmod = 0, exactly
         (whole-cell-supports? e tm))))   ; whole cells only (§12)

(define (rests-on? e o)
  (and (collides? o)
       (meets? e o)
       (zero? (num o #:vy))
       (= (num o #:y) (num+ (num e #:y) (num e #:height)))
       (< (num e #:x) (num+ (num o #:x) (num o #:width)))
       (< (num o #:x) (num+ (num e #:x) (num e #:width)))
       (may-stand-on? e o)))

(define (rests? e tm holders slot)
  "Whether E, about to take gravity, rests: still, and on a tile or on one of
HOLDERS ((index . entity) …) other than its own SLOT and its #:id."
  (and (flag e #:gravity?)
       (not (skips? e 'gravity))
       (zero? (num e #:vy))
       (or (rests-on-tile? e tm)
           (any (lambda (h) (and (not (= (car h) slot)) (not (same-id? e (cdr h)))
                                 (rests-on? e (cdr h))))
                holders))))

(define (same-id? e o)
  (let ((id (entity-ref e #:id #f)))
    (and id (equal? id (entity-ref o #:id #f)))))

(define (holders entities)
  "The entities that can hold another up (solid, not ghosts), each as
(index . entity) with its index in ENTITIES."
  (filter (lambda (slot) (collides? (cdr slot)))
          (map cons (iota (length entities)) entities)))

(define* (on-solid e tm holders itself? #:optional (name-at name-of))
  "#:on-ground? from the tiles and from HOLDERS ((index . entity) …),
leaving out those for which (ITSELF? index entity) holds and those sharing
E's #:id. A contact entity's holder is named by (NAME-AT entity index)."
  (if (or (not (flag e #:gravity?)) (skips? e 'on-solid))
      e
      (let* ((holds? (lambda (slot)
                       (let ((i (car slot)) (o (cdr slot)))
                         (and (not (itself? i o)) (not (same-id? e o))
                              (entity-supports? e o)))))
             (ground (or (tile-supports? e tm) (any holds? holders)))
             (e (put e #:on-ground? (flag e #:on-ground?) ground)))
        (if (contacts? e)
            ;; §10: the first holder in list order, tiles aside
            (let ((holder (find holds? holders)))
              (put-report e #:standing-on (and holder (name-at (cdr holder) (car holder)))))
            e))))

(define-step (detect-on-solid e scene dt)
  "Whether E stands on a solid tile or on a solid entity of SCENE (not
itself: not eq?, no equal #:id) (§4)."
  (let ((others (if scene (scene-entities scene) '())))
    (check-all 'detect-on-solid others)
    (on-solid e (scene-tiles scene) (holders others) (lambda (i o) (eq? o e)))))

;;; ---------------------------------------------------------------- push-apart against the map (§4)
;;; Under the push rule 'clipped (the default) push-apart never leaves a
;;; body in a solid cell: each push is cut at the first solid cell it would
;;; enter, and a body left in one is put out by the shortest way.

(define %walls
  ;; The tilemap whose solid cells cut pushes, while a frame's push-apart
  ;; runs under 'clipped; #f (the seed's rule) otherwise.
  (make-parameter #f))

(define (stops-push? cell down?)
  "A solid cell stops a push as a whole cell; a one-way cell only a move
down. A shaped cell stops it by its shape (shape-stop)."
  (or (eq? cell 'solid) (and down? (eq? cell 'one-way))))

(define (line-x p l y)
  "Where slant L of shape P is at height Y: ((y·dx − (oy + ay)·dx) / dy + ax) + ox."
  (apply (lambda (ax ay bx by)
           (let ((ox (vector-ref p 1)) (oy (vector-ref p 2)) (dx (fl (- bx ax))) (dy (fl (- by ay))))
             (+ (+ (/ (- (* y dx) (* (+ oy ay) dx)) dy) ax) ox)))
         l))

(define (corner-stop p slants floor? level apex fwd? lead reach)
  "Where a box moving along x from LEAD to REACH meets, with its corner at
height LEVEL, the SLANTS of one side of P (a top's when FLOOR?) that face
the move before APEX: the farthest of their lines at that height, as the
distance from LEAD; #f when none faces it or the box does not get there."
  (let ((lx (fold (lambda (l x)
                    (let ((rising (if fwd? (< (list-ref l 3) (list-ref l 1))
                                      (> (list-ref l 3) (list-ref l 1)))))
                      (if (eq? rising floor?)
                          (let ((xi (line-x p l level)))
                            (if (or (not x) (if fwd? (< x xi) (< xi x))) xi x))
                          x)))
                  #f slants)))
    (and lx
         (let ((at (if fwd?
                       (if (< lx (p-left p)) (p-left p) lx)
                       (if (< (p-right p) lx) (p-right p) lx))))
           (and (if fwd?
                    (and (<= lead at) (< at reach) (< at (p-right p)) (< at apex))
                    (and (< reach at) (<= at lead) (> at (p-left p)) (> at apex)))
                (- at lead))))))

(define (shape-stop b p x-axis? d)
  "How far (signed as D, a flonum) box B moves along an axis before it meets
the solid of placed shape P, or #f: along y the feet onto its surface (down)
or the head onto its underside (up); along x the leading face onto its near
side where the box spans solid there, else the box's corner onto the slants
facing the move before the apex (the feet for a floor, the head for a
ceiling), the farthest of their lines at that height; a two-sided shape's
feet onto its top's when no lower than the near side's top, head onto its
underside's when no higher than that side's bottom, the nearer. A one-way
shape stops only a move down."
  (let* ((fwd? (> d 0)) (d (fl d))
         (head (fl (y b))) (feet (fl (num+ (y b) (h b))))
         (lo (fl (x b))) (hi (fl (num+ (x b) (w b)))))
    (cond
     ((and (one-way-shape? (vector-ref p 0)) (or x-axis? (not fwd?))) #f)
     ((not x-axis?)
      (let ((ab (p-over p lo hi)))
        (and ab (p-solid-over? p ab)
             (let ((top (p-surface p ab)) (under (p-underside p ab)))
               (cond ((and fwd? (<= feet top) (< top (+ feet d))) (- top feet))
                     ((and (not fwd?) (>= head under) (> under (+ head d))) (- under head))
                     (else #f))))))
     (else
      (let* ((lead (if fwd? hi lo)) (reach (+ lead d))
             (side (if fwd? (p-left p) (p-right p)))
             (crossed (if fwd? (and (<= lead side) (< side reach)) (and (< reach side) (<= side lead)))))
        (cond
         ((and crossed (< head (p-bottom p side)) (> feet (p-top p side))) (- side lead))
         ((not (and (< head (p-box-bottom p)) (> feet (p-box-top p)))) #f)
         ((eq? (p-cut p) 'box) #f)
         ((not (two-sided? p))
          (let ((floor? (eq? (p-cut p) 'floor)))
            (corner-stop p (p-slants p) floor? (if floor? feet head) (p-apex p) fwd? lead reach)))
         (else
          (let ((by-feet (and (<= feet (p-top p side))
                              (corner-stop p (p-slants p) #t feet (p-apex p) fwd? lead reach)))
                (by-head (and (>= head (p-bottom p side))
                              (corner-stop p (p-under p) #f head (p-under-apex p) fwd? lead reach))))
            (if (and by-feet (or (not by-head) (<= (abs by-feet) (abs by-head))))
                by-feet
                by-head)))))))))


(define (clipped-push b x-axis? d tm)
  "How far of the push D (along x or y) box B goes before its leading face
meets the first solid cell it would enter in the rows (columns) it spans:
D when nothing stops it, else the distance to that cell's near face."
  (let* ((pos (vector-ref b (if x-axis? 0 1))) (size (vector-ref b (if x-axis? 2 3)))
         (tw (tilemap-tile-width tm)) (th (tilemap-tile-height tm))
         (tile (if x-axis? tw th)))
    (apply
     (lambda (col0 row0 cols rows)
       (let ((across (if x-axis? (clip (cells-of (y b) (h b) th) row0 rows)
                         (clip (cells-of (x b) (w b) tw) col0 cols))))
         (if (or (zero? d) (not (finite? d)) (not across) (not (> size 0)))
             d
             (let* ((now (cells-of pos size tile))
                    (fwd? (> d 0))
                    (reach (if fwd? (cells-of (num+ pos size) d tile) (cells-of (num+ pos d) (- d) tile)))
                    (entered (and reach (if fwd?
                                            (cons (max (car reach) (+ (cdr now) 1)) (cdr reach))
                                            (cons (car reach) (min (cdr reach) (- (car now) 1))))))
                    (entered (and entered (<= (car entered) (cdr entered))
                                  (if x-axis? (clip entered col0 cols) (clip entered row0 rows))))
                    (down? (and (not x-axis?) fwd?))
                    (exact (and (exact? pos) (exact? size))))
               (shaped-cut
                b x-axis? tm across
                (if x-axis? (clip (cells-between now reach) col0 cols) (clip (cells-between now reach) row0 rows))
                (let loop ((cs (range->list entered (if fwd? 1 -1))))
                  (cond ((null? cs) d)
                        ((any (lambda (k)
                                (stops-push? (if x-axis? (tilemap-cell-shape tm (car cs) k)
                                                 (tilemap-cell-shape tm k (car cs)))
                                             down?))
                              (range->list across 1))
                         (let ((face (* (if fwd? (car cs) (+ (car cs) 1)) tile)))
                           (if exact
                               (- face (if fwd? (+ pos size) pos))
                               (- (fl face) (fl (if fwd? (num+ pos size) pos))))))
                        (else (loop (cdr cs))))))))))
     (solid-extent tm))))

(define (cells-between a b)
  "The cells of ranges A and B and every one between."
  (cons (min (car a) (car b)) (max (cdr a) (cdr b))))

(define (shaped-cut b x-axis? tm across swept cut)
  "CUT, or a shorter stop at a shape in the cells SWEPT (along the axis) ×
ACROSS: the nearest, exact when B's box is and it is an integer."
  (let ((exact (box-exact-b? b)))
    (fold (lambda (c cut)
            (fold (lambda (k cut)
                    (let* ((col (if x-axis? c k)) (row (if x-axis? k c))
                           (cell (tilemap-cell-shape tm col row))
                           (stop (and (vector? cell) (shape-stop b (place cell col row tm) x-axis? cut))))
                      (if (and stop (< (abs stop) (abs (fl cut)))) (exact-if exact stop) cut)))
                  cut (range->list across 1)))
          cut (range->list swept 1))))

(define (box-exact-b? b) (every exact? (list (x b) (y b) (w b) (h b))))

(define (place-at! b x-axis? target)
  "Box B's position along an axis to TARGET: all the way under the seed's
rule or when nothing stops it, else as far as clipped-push lets it."
  (let* ((slot (if x-axis? 0 1)) (pos (vector-ref b slot)) (tm (%walls)))
    (if tm
        (let* ((d (num- target pos)) (cut (clipped-push b x-axis? d tm)))
          (vector-set! b slot (if (= cut d) target (num+ pos cut))))
        (vector-set! b slot target))))

(define (solid-shape-at tm col row)
  "The placed shape of a cell when it is a solid (not one-way) one, or #f."
  (let ((cell (tilemap-cell-shape tm col row)))
    (and (vector? cell) (not (one-way-shape? cell)) (place cell col row tm))))

(define (each-inside tm bx by bw bh proc)
  "(PROC col row p) for each cell a box overlaps that is a whole solid cell
(P #f) or a solid shape whose solid it overlaps (P the placed shape)."
  (apply (lambda (col0 row0 cols rows)
           (let ((cs (clip (cells-of bx bw (tilemap-tile-width tm)) col0 cols))
                 (rs (clip (cells-of by bh (tilemap-tile-height tm)) row0 rows))
                 (lo (fl bx)) (hi (fl (num+ bx bw))) (top (fl by)) (bottom (fl (num+ by bh))))
             (for-each
              (lambda (r)
                (for-each
                 (lambda (c)
                   (if (eq? (tilemap-cell-shape tm c r) 'solid)
                       (proc c r #f)
                       (let ((p (solid-shape-at tm c r)))
                         (when (and p (p-overlaps? p lo hi top bottom)) (proc c r p)))))
                 (range->list cs 1)))
              (range->list rs 1))))
         (solid-extent tm)))

(define (in-solid? tm bx by bw bh)
  "Whether a box overlaps a whole solid cell or the solid of a shape (not a
one-way one): what put-out counts as inside."
  (call/cc (lambda (k) (each-inside tm bx by bw bh (lambda (c r p) (k #t))) #f)))

(define (next-place tm b x-axis? fwd? at exact)
  "Box B's nearest position along an axis beyond AT that could be free: past
every solid it overlaps there — a whole cell by its far edge, a shape by
its surface (up), its underside (down), its box's side (along x)."
  (let* ((bx (if x-axis? at (x b))) (by (if x-axis? (y b) at))
         (size (if x-axis? (w b) (h b)))
         (tile (if x-axis? (tilemap-tile-width tm) (tilemap-tile-height tm)))
         (face #f)
         (ask! (lambda (f) (set! face (if (not face) f (if fwd? (if (< face f) f face) (if (< f face) f face)))))))
    (each-inside tm bx by (w b) (h b)
                 (lambda (c r p)
                   (if p
                       (let ((ab (p-over p (fl bx) (fl (num+ bx (w b))))))
                         (ask! (if x-axis?
                                   (if fwd? (p-right p) (p-left p))
                                   (if fwd? (p-underside p ab) (p-surface p ab)))))
                       (let ((along (if x-axis? c r)))
                         (ask! (fl (* (if fwd? (+ along 1) along) tile)))))))
    (exact-if exact (if fwd? face (- face (fl size))))))

(define (way-out tm b x-axis? fwd?)
  "Box B's position along an axis at the nearest place, one way, where it
overlaps no solid: from place to place (next-place); beyond the grid
nothing is solid."
  (let ((exact (box-exact-b? b)))
    (let loop ((at (if x-axis? (x b) (y b))))
      (if (if x-axis? (in-solid? tm at (y b) (w b) (h b)) (in-solid? tm (x b) at (w b) (h b)))
          (loop (next-place tm b x-axis? fwd? at exact))
          at))))

(define (put-out! b tm)
  "Box B, when it overlaps a whole solid cell or a solid shape, out of it by
the shortest of the four axis moves (ties: up, left, right, down); the
velocity on that axis becomes 0 when it pointed back in."
  (when (and (every (lambda (v) (finite? (fl v))) (list (x b) (y b) (w b) (h b)))
             (> (w b) 0) (> (h b) 0) (in-solid? tm (x b) (y b) (w b) (h b)))
    (let* ((up (way-out tm b #f #f)) (left (way-out tm b #t #f))
           (right (way-out tm b #t #t)) (down (way-out tm b #f #t))
           (far (lambda (to from) (abs (- (fl to) (fl from)))))
           (least (min (far up (y b)) (far left (x b)) (far right (x b)) (far down (y b)))))
      (cond ((= least (far up (y b))) (vector-set! b 1 up) (when (> (vector-ref b 5) 0) (vector-set! b 5 0)))
            ((= least (far left (x b))) (vector-set! b 0 left) (when (> (vector-ref b 4) 0) (vector-set! b 4 0)))
            ((= least (far right (x b))) (vector-set! b 0 right) (when (< (vector-ref b 4) 0) (vector-set! b 4 0)))
            (else (vector-set! b 1 down) (when (< (vector-ref b 5) 0) (vector-set! b 5 0)))))))

;;; ---------------------------------------------------------------- bulk steps (§4)
;;; A bulk step works on every entity's numbers and then writes each
;;; entity's changed keys once, in the order x y vx vy: a key changed by one
;;; pair and restored by a later one is not written.

(define (box e)
  (vector (num e #:x) (num e #:y) (num e #:width) (num e #:height)
          (num e #:vx) (num e #:vy)))

(define (write-box e before after)
  (fold (lambda (key i e) (put e key (vector-ref before i) (vector-ref after i)))
        e '(#:x #:y #:vx #:vy) '(0 1 4 5)))

(define (x b) (vector-ref b 0))
(define (y b) (vector-ref b 1))
(define (w b) (vector-ref b 2))
(define (h b) (vector-ref b 3))

(define (overlaps? a b)
  (and (< (x a) (num+ (x b) (w b))) (< (x b) (num+ (x a) (w a)))
       (< (y a) (num+ (y b) (h b))) (< (y b) (num+ (y a) (h a)))))

(define (overlap p1 s1 p2 s2)
  "How far [p1, p1+s1) and [p2, p2+s2) overlap, in double."
  (- (fl (min (num+ p1 s1) (num+ p2 s2))) (fl (max p1 p2))))

(define (centre2 p s) (+ (* 2 (fl p)) (fl s)))   ; twice the centre, in double

(define (stopped-by v into? bounce)
  "A velocity pushed off a fixed body: its rebound when it ran INTO? it."
  (if into? (rebound v bounce) 0))

(define (push-off-immovable! m s ox oy bounce)
  "Landing wins while M's centre is above S's; else the shallower axis.
Returns the side of M that met S (§10)."
  (cond ((< (centre2 (y m) (h m)) (centre2 (y s) (h s)))
         (place-at! m #f (num- (y s) (h m)))
         (vector-set! m 5 (stopped-by (vector-ref m 5) (> (vector-ref m 5) 0) bounce))
         'down)
        ((< ox oy)
         (let ((left? (< (centre2 (x m) (w m)) (centre2 (x s) (w s)))))
           (place-at! m #t (if left? (num- (x s) (w m)) (num+ (x s) (w s))))
           (vector-set! m 4 (stopped-by (vector-ref m 4)
                                        (if left? (> (vector-ref m 4) 0) (< (vector-ref m 4) 0))
                                        bounce))
           (if left? 'right 'left)))
        (else
         (place-at! m #f (num+ (y s) (h s)))
         (vector-set! m 5 (stopped-by (vector-ref m 5) (< (vector-ref m 5) 0) bounce))
         'up)))

(define (opposite side)
  "SIDE as the other body of the pair sees it."
  (case side ((left) 'right) ((right) 'left) ((up) 'down) (else 'up)))

(define (facing x-axis? a-negative)
  "The side of the body moved (or, unmoved, lying) the negative way along an
axis that faces the other."
  (if x-axis? (if a-negative 'right 'left) (if a-negative 'down 'up)))

(define (negative-of? a-pos a-size b-pos b-size)
  "A is on the negative side of B: B's centre is not smaller (a tie: A)."
  (not (< (centre2 b-pos b-size) (centre2 a-pos a-size))))

(define (entry-side a b)
  "The side of A that met B when nothing moved them (§10): the axis their
overlap began on last, from their relative speed (x when ox·|Δvy| <
oy·|Δvx|, in doubles), else (no relative speed, or a tie) the narrower
overlap's (x when ox < oy); facing B, a tie as push-apart breaks it."
  (let* ((ox (overlap (x a) (w a) (x b) (w b)))
         (oy (overlap (y a) (h a) (y b) (h b)))
         (x-later (* ox (abs (- (fl (vector-ref a 5)) (fl (vector-ref b 5))))))
         (y-later (* oy (abs (- (fl (vector-ref a 4)) (fl (vector-ref b 4))))))
         (along-x (if (= x-later y-later) (< ox oy) (< x-later y-later))))
    (if along-x
        (facing #t (negative-of? (x a) (w a) (x b) (w b)))
        (facing #f (negative-of? (y a) (h a) (y b) (h b))))))

(define (part neg pos bounce)
  "Two movable bodies' velocities after they were pushed apart, NEG the one
moved the negative way: the seed's −1 and +1; with bounce and closing
faster than *bounce-rest-speed*, equal masses parting at BOUNCE times their
closing speed about their mean (bounce 1: swapped)."
  (let ((closing (- (fl neg) (fl pos))))
    (cond ((or (zero? bounce) (not (> closing *bounce-rest-speed*))) (values -1 1))
          ((exact? bounce) (values pos neg))
          (else (let ((mean (/ (+ (fl neg) (fl pos)) 2))
                      (half (/ (* (fl bounce) closing) 2)))
                  (values (- mean half) (+ mean half)))))))

(define (push-apart! a b pos size vel o bounce)
  "Share the overlap O along one axis (POS SIZE VEL: vector slots). A, the
earlier in the list, moves negative unless B's centre is smaller, and takes
the larger half when everything is an exact integer. Returns whether A
moved the negative way."
  (let* ((exact (every exact? (list (vector-ref a pos) (vector-ref a size)
                                    (vector-ref b pos) (vector-ref b size))))
         (a-share (if exact (ceiling (/ (inexact->exact o) 2)) (/ o 2)))
         (b-share (if exact (- (inexact->exact o) a-share) (/ o 2)))
         (a-negative (negative-of? (vector-ref a pos) (vector-ref a size)
                                (vector-ref b pos) (vector-ref b size))))
    (let ((da (if a-negative (- a-share) a-share)) (db (if a-negative b-share (- b-share)))
          (tm (%walls)) (x-axis? (= pos 0)))
      (if (not tm)
          (begin
            (vector-set! a pos (num+ (vector-ref a pos) da))
            (vector-set! b pos (num+ (vector-ref b pos) db)))
          ;; §4: a's cut-off share goes to b (cut again); what b could not
          ;; take goes back to a when a was not cut; the rest is dropped.
          (let* ((ca (clipped-push a x-axis? da tm))
                 (_ (vector-set! a pos (num+ (vector-ref a pos) ca)))
                 (a-left (num- da ca))
                 (want-b (if (zero? a-left) db (num- db a-left)))
                 (cb (clipped-push b x-axis? want-b tm))
                 (_ (vector-set! b pos (num+ (vector-ref b pos) cb)))
                 (b-left (num- want-b cb)))
            (when (and (zero? a-left) (not (zero? b-left)))
              (vector-set! a pos (num+ (vector-ref a pos) (clipped-push a x-axis? (- b-left) tm)))))))
    (let-values (((neg pos) (if a-negative
                                (part (vector-ref a vel) (vector-ref b vel) bounce)
                                (part (vector-ref b vel) (vector-ref a vel) bounce))))
      (vector-set! a vel (if a-negative neg pos))
      (vector-set! b vel (if a-negative pos neg)))
    a-negative))

(define (above? upper lower)
  (< (centre2 (y upper) (h upper)) (centre2 (y lower) (h lower))))

(define (lands-from-above? em m o)
  "M (the box of entity EM) comes down on the one-way O: not rising, not
dropping through, its feet before the frame's move at or above O's top
before its own."
  (and (>= (vector-ref m 5) 0) (not (flag em #:drop-through?))
       (<= (num+ (num- (y m) (vector-ref m 5)) (h m)) (num- (y o) (vector-ref o 5)))))

(define (resolve-pair! ea a a-rests eb b b-rests)
  "A resting body (resting contacts) holds up one whose centre is above its
own, as an immovable body would. Returns the side of A that met B (§10):
as it was pushed, or where nothing moved, entry-side."
  (let ((a-fixed (flag ea #:immovable?)) (b-fixed (flag eb #:immovable?))
        (ox (overlap (x a) (w a) (x b) (w b)))
        (oy (overlap (y a) (h a) (y b) (h b)))
        (bounce (pair-bounce ea eb)))
    (cond ((or (flag ea #:one-way?) (flag eb #:one-way?))   ; §9: it lands, or they pass
           (let* ((a-one-way (flag ea #:one-way?))
                  (em (if a-one-way eb ea)) (m (if a-one-way b a)) (o (if a-one-way a b)))
             (cond ((and (not (and (flag ea #:one-way?) (flag eb #:one-way?)))
                         (not (flag em #:immovable?)) (lands-from-above? em m o))
                    (place-at! m #f (num- (y o) (h m)))
                    (vector-set! m 5 (rebound (vector-ref m 5) bounce))
                    (if a-one-way 'up 'down))
                   (else (entry-side a b)))))
          ((and a-fixed b-fixed) (entry-side a b))
          (a-fixed (opposite (push-off-immovable! b a ox oy bounce)))
          (b-fixed (push-off-immovable! a b ox oy bounce))
          ((and a-rests (above? b a)) (opposite (push-off-immovable! b a ox oy bounce)))
          ((and b-rests (above? a b)) (push-off-immovable! a b ox oy bounce))
          ((< ox oy) (facing #t (push-apart! a b 0 2 4 ox bounce)))
          (else (facing #f (push-apart! a b 1 3 5 oy bounce))))))

(define (resolve-entity-collisions entities)
  "One pass over the pairs (i, j), i < j, in list order, each seeing what
earlier pairs did: solid, non-ghost, strictly overlapping pairs are pushed
apart (semantics §4)."
  (check-all 'resolve-entity-collisions entities)
  (let-values (((result pairs) (push-apart entities (map (const #f) entities) '())))
    result))

(define (push-apart entities resting earlier)
  "The pass, RESTING holding each entity's resting flag. Returns the
entities and the pairs (i j . side-of-i) it resolved with a contact entity
(§10), after EARLIER (the frame's earlier sub-frames), each pair once with
the side it was first found on."
  (let* ((before (map box entities))
         (after (map vector-copy before))
         (takes-part (map (lambda (e) (or (collides? e) (senses? e))) entities))
         ;; (entity box rests? index)
         (members (filter-map (lambda (e b part r i) (and part (list e b r i)))
                              entities after takes-part resting (iota (length entities))))
         (pairs (reverse earlier)))
    (let outer ((rest members))
      (unless (null? rest)
        (let ((m (car rest)))
          (for-each (lambda (o)
                      ;; §13: categories that do not meet pass; a sensor and
                      ;; a body only meet (two sensors do not)
                      (when (and (overlaps? (cadr m) (cadr o)) (meets? (car m) (car o))
                                 (not (and (sensor? (car m)) (sensor? (car o)))))
                        (let ((side (if (or (sensor? (car m)) (sensor? (car o)))
                                        (entry-side (cadr m) (cadr o))
                                        (resolve-pair! (car m) (cadr m) (caddr m) (car o) (cadr o) (caddr o))))
                              (i (cadddr m)) (j (cadddr o)))
                          (when (and (or (reports-pairs? (car m)) (reports-pairs? (car o)))
                                     (not (pair-side pairs i j)))
                            (set! pairs (cons (cons* i j side) pairs))))))
                    (cdr rest)))
        (outer (cdr rest))))
    (let ((tm (%walls)))
      (when tm
        (for-each (lambda (m)
                    (let ((e (car m)))
                      (when (and (collides? e) (not (flag e #:immovable?))
                                 (not (skips? e 'tile-collisions-x)) (not (skips? e 'tile-collisions-y)))
                        (put-out! (cadr m) tm))))
                  members)))
    (let* ((pairs (reverse pairs))
           (moved (map write-box entities before after)))
      (values (same-or (write-touching moved pairs) entities) pairs))))

(define (pair-side pairs i j)
  "The side of I where PAIRS ((i j . side) …) pair it with J (either way
round), or #f."
  (any (lambda (p)
         (cond ((and (= (car p) i) (= (cadr p) j)) (cddr p))
               ((and (= (car p) j) (= (cadr p) i)) (opposite (cddr p)))
               (else #f)))
       pairs))

(define (write-touching entities pairs)
  "Each contact entity's #:touching: the names of those PAIRS paired it
with, in list order; with #:contacts? 'sides, each as (name . side)."
  (let ((names (map name-of entities (iota (length entities)))))
    (map (lambda (e i)
           (if (contacts? e)
               (let ((sides? (eq? (entity-ref e #:contacts?) 'sides)))
                 (put-report e #:touching
                             (filter-map (lambda (o j)
                                           (let ((side (pair-side pairs i j)))
                                             (and side (if sides? (cons o side) o))))
                                         names (iota (length entities)))))
               e))
         entities (iota (length entities)))))

(define (group-of e) (entity-ref e #:group-id #f))

(define (sync-groups entities)
  "Members follow their group's origin (the first #:group-origin? entity of
that #:group-id, compared with equal?): x = origin.x + #:group-local-x, and
likewise y."
  (check-all 'sync-groups entities)
  (let* ((slots (iota (length entities)))
         ;; (group-id slot . origin), first origin first: assoc finds it
         (origins (filter-map (lambda (e i)
                                (and (group-of e) (flag e #:group-origin?)
                                     (cons* (group-of e) i e)))
                              entities slots)))
    (same-or
     (map (lambda (e i)
            (let ((origin (and (group-of e) (assoc (group-of e) origins))))
              (if (or (not origin) (= (cadr origin) i))
                  e
                  (let* ((o (cddr origin))
                         (e (put e #:x (num e #:x) (num+ (num o #:x) (num e #:group-local-x)))))
                    (put e #:y (num e #:y) (num+ (num o #:y) (num e #:group-local-y)))))))
          entities slots)
     entities)))

(define (aabb-overlap? x1 y1 w1 h1 x2 y2 w2 h2)
  "Whether two boxes overlap; touching edges do not."
  (let ((r (lambda (v)
             (unless (and (real? v) (not (nan? v)) (not (inf? v)))
               (fail 'aabb-overlap? "expected a finite real number, got ~S" v))
             (as-double v))))
    (overlaps? (vector (r x1) (r y1) (r w1) (r h1)) (vector (r x2) (r y2) (r w2) (r h2)))))

;;; ---------------------------------------------------------------- carriers (§11)
;;; A moving carrier carries the bodies that stood on it when the (sub-)frame
;;; began; the bodies it pushes into solid cells, and the riders it lifts
;;; into them, are crushed.

(define (collides? e)
  (and (flag e #:solid?) (not (sensor? e)) (not (skips? e 'entity-collisions))))
(define (carrier? e) (and (flag e #:carries?) (flag e #:immovable?) (collides? e)))
(define (crushable? e) (and (not (flag e #:immovable?)) (collides? e)))
(define (may-ride? e) (and (crushable? e) (not (skips? e 'carry))))

(define (displacement now then)
  (cons (num- (num now #:x) (num then #:x)) (num- (num now #:y) (num then #:y))))
(define (moved? d) (not (and (zero? (car d)) (zero? (cdr d)))))

(define (rides? e c)
  "E stood on the carrier C: overlapping it horizontally, its feet within
the tolerance of C's top; on a one-way C, not rising nor dropping through.
Not their speeds: push-apart zeroes a rider's vy each frame, whatever C's."
  (and (< (num e #:x) (num+ (num c #:x) (num c #:width)))
       (< (num c #:x) (num+ (num e #:x) (num e #:width)))
       (meets? e c)
       (<= (abs (num- (num+ (num e #:y) (num e #:height)) (num c #:y))) *on-solid-tolerance*)
       (may-stand-on? e c)))

(define (crush e) (if (flag e #:crushed?) e (put-report e #:crushed? #t)))

(define (clear-crushed entities)
  "No body enters a frame crushed: #:crushed? #t becomes #f on crushable ones."
  (map-keeping (lambda (e) (if (and (crushable? e) (flag e #:crushed?)) (put e #:crushed? #t #f) e))
               entities))

(define (carry-along e scene d pos-key vel-key resolve)
  "E moved by D along one axis as that axis's tile step would move it with
velocity D, its own velocity untouched: (entity . stopped-by-a-cell?)."
  (if (zero? d)
      (cons e #f)
      ;; Both coordinates: a rider carried along x onto a ramp climbs it (§12).
      (let* ((pos (num e pos-key))
             (moved (resolve (entity-set (entity-set e pos-key (num+ pos d)) vel-key d) scene #f #f #t))
             (e (put e #:x (num e #:x) (num moved #:x))))
        (cons (put e #:y (num e #:y) (num moved #:y)) (zero? (num moved vel-key))))))

(define (carry-one e scene d)
  (let* ((e (car (carry-along e scene (car d) #:x #:vx tiles-x)))
         (stopped (carry-along e scene (cdr d) #:y #:vy tiles-y)))
    (if (and (cdr stopped) (< (cdr d) 0)) (crush (car stopped)) (car stopped))))

(define (carry-among entities start scene)
  "Each moving carrier of ENTITIES, in list order, carries the bodies that
stood on it in START (the same entities at the (sub-)frame start) and ride
no earlier carrier."
  (let* ((now (list->vector entities))
         (then (list->vector start))
         (slots (iota (vector-length now)))
         (ridden (make-vector (vector-length now) #f)))
    (for-each
     (lambda (c)
       (let ((d (displacement (vector-ref now c) (vector-ref then c))))
         (when (and (carrier? (vector-ref now c)) (moved? d))
           (for-each (lambda (r)
                       (when (and (not (vector-ref ridden r)) (may-ride? (vector-ref now r))
                                  (rides? (vector-ref then r) (vector-ref then c)))
                         (vector-set! ridden r #t)
                         (vector-set! now r (carry-one (vector-ref now r) scene d))))
                     slots))))
     slots)
    (same-or (vector->list now) entities)))

(define (in-way entities start)
  "The slots of the crushable entities a moving carrier (not one-way)
overlaps: the bodies push-apart is about to push out of its way."
  (let ((pushers (filter-map (lambda (e s) (and (carrier? e) (not (flag e #:one-way?))
                                                (moved? (displacement e s)) e))
                             entities start)))
    (filter-map (lambda (e i) (and (crushable? e)
                                   (any (lambda (p) (and (meets? e p) (overlaps? (box e) (box p)))) pushers)
                                   i))
                entities (iota (length entities)))))

(define (crush-in-way entities slots tm)
  "After push-apart: the pushed SLOTS now overlapping a solid cell are
crushed; under the push rule 'clipped (§4), where a wall cuts the push, so
are those still overlapping a carrier (not one-way)."
  (define carriers (filter (lambda (e) (and (carrier? e) (not (flag e #:one-way?)))) entities))
  (define (held? e)
    (and (eq? (push-rule) 'clipped)
         (any (lambda (c) (and (meets? e c) (overlaps? (box e) (box c)))) carriers)))
  (if (or (not tm) (null? slots))
      entities
      (same-or (map (lambda (e i) (if (and (memv i slots) (or (overlaps-solid? e tm) (held? e))) (crush e) e))
                    entities (iota (length entities)))
               entities)))

(define (carry-riders entities scene dt)
  "The carry step: SCENE is the frame-start scene (its entities are
ENTITIES before this frame's per-entity steps). Each moving #:carries?
platform moves its riders by its own displacement, resolved against the
solid tiles; a rider lifted into a solid cell gets #:crushed? #t (and a
crushable body with the key that is not crushed, #f)."
  (check-all 'carry-riders entities)
  (let ((start (if scene (scene-entities scene) '())))
    (check-all 'carry-riders start)
    (unless (= (length start) (length entities))
      (fail 'carry-riders "expected the scene to hold as many entities as the list (~S), got ~S"
            (length entities) (length start)))
    ;; Crushed again after being cleared: the entity itself, as on the native side.
    (same-or (map keep-if-unchanged (carry-among (clear-crushed entities) start scene) entities)
             entities)))

;;; ---------------------------------------------------------------- easing (§6)
;;; Penner's curves as easings.net writes them; the ends are pinned to 0 and 1.

(define pi (acos -1))

(define (bounce-out u)
  (let ((n1 7.5625) (d1 2.75))
    (cond ((< u (/ 1 d1)) (* n1 u u))
          ((< u (/ 2 d1)) (let ((u (- u (/ 1.5 d1)))) (+ (* n1 u u) 0.75)))
          ((< u (/ 2.5 d1)) (let ((u (- u (/ 2.25 d1)))) (+ (* n1 u u) 0.9375)))
          (else (let ((u (- u (/ 2.625 d1)))) (+ (* n1 u u) 0.984375))))))

(define (in-curve family t)
  (case family
    ((quad) (* t t))
    ((cubic) (* t t t))
    ((quart) (* t t t t))
    ((sine) (- 1 (cos (/ (* t pi) 2))))
    ((expo) (if (= t 0) 0. (expt 2. (- (* 10 t) 10))))
    ((back) (let* ((c1 1.70158) (c3 (+ c1 1)))
              (- (* c3 t t t) (* c1 t t))))
    ((elastic) (if (or (= t 0) (= t 1))
                   t
                   (* (- (expt 2. (- (* 10 t) 10)))
                      (sin (* (- (* t 10) 10.75) (/ (* 2 pi) 3))))))
    ((bounce) (- 1 (bounce-out (- 1 t))))))

(define (back-in-out t)
  (let ((c2 (* 1.70158 1.525)))
    (if (< t 0.5)
        (let ((u (* 2 t))) (/ (* u u (- (* (+ c2 1) 2 t) c2)) 2))
        (let ((u (- (* 2 t) 2))) (/ (+ (* u u (+ (* (+ c2 1) (- (* t 2) 2)) c2)) 2) 2)))))

(define (elastic-in-out t)
  (let ((c5 (/ (* 2 pi) 4.5)))
    (cond ((or (= t 0) (= t 1)) t)
          ((< t 0.5) (/ (- (* (expt 2. (- (* 20 t) 10)) (sin (* (- (* 20 t) 11.125) c5)))) 2))
          (else (+ (/ (* (expt 2. (+ (* -20 t) 10)) (sin (* (- (* 20 t) 11.125) c5))) 2) 1)))))

(define (ease-by-name name t)
  (let* ((s (symbol->string name))
         (variant (cond ((string-suffix? "-in-out" s) 'in-out)
                        ((string-suffix? "-out" s) 'out)
                        (else 'in)))
         (family (string->symbol (substring s 0 (string-index s #\-)))))
    (case variant
      ((in) (in-curve family t))
      ((out) (- 1 (in-curve family (- 1 t))))
      (else (case family
              ((back) (back-in-out t))
              ((elastic) (elastic-in-out t))
              (else (if (< t 0.5)
                        (/ (in-curve family (* 2 t)) 2)
                        (- 1 (/ (in-curve family (- 2 (* 2 t))) 2)))))))))

(define (eased ease t)
  "EASE (a name or a procedure) at T. Names pin the ends exactly; a
procedure is called as it is and must return a finite number."
  (cond ((procedure? ease)
         (let ((v (ease t)))
           (unless (and (real? v) (not (nan? v)) (not (inf? v)))
             (scm-error 'wrong-type-arg "step-tweens"
                        "tween easing ~S returned ~S, not a finite number" (list ease v) #f))
           (fl v)))
        ((not (> t 0)) 0.)
        ((>= t 1) 1.)
        ((eq? ease 'linear) t)
        (else (fl (ease-by-name ease t)))))

;;; ---------------------------------------------------------------- tweens (§6)

(define (tween-phase tw elapsed)
  "Where a tween stands after ELAPSED ms: #f during the delay, else
(finished? reversed? t) with t the progress through the current cycle."
  (let* ((duration (fl (tween-duration tw)))
         (delay (fl (tween-delay tw)))
         (repeat (tween-repeat tw))
         (forever (< repeat 0))
         (cycles (+ repeat 1))
         (run (- elapsed delay)))
    (cond ((< elapsed delay) #f)
          ((or (<= duration 0) (and (not forever) (>= run (* cycles duration))))
           ;; over: the last cycle's direction decides the final target
           (list #t (and (tween-yoyo? tw) (not forever) (odd? (- cycles 1))) 1.))
          (else
           (let ((cycle (floor (/ run duration))))
             (list #f
                   (and (tween-yoyo? tw) (odd? (inexact->exact cycle)))
                   (max 0. (min 1. (/ (- run (* cycle duration)) duration)))))))))

(define (tween-prop-value prop finished? reversed? e)
  "A property's value: start + (end − start)·e as a flonum, and at the end
the target itself (as the core reads it)."
  (let ((from (as-double (if reversed? (cddr prop) (cadr prop))))
        (to (as-double (if reversed? (cadr prop) (cddr prop)))))
    (if finished?
        to
        (+ (fl from) (* (- (fl to) (fl from)) e)))))

(define (advance-tween e tw dt)
  (let* ((elapsed (+ (fl (tween-elapsed tw)) (fl dt)))
         (phase (tween-phase tw elapsed)))
    (if (not phase)
        (entity-set e #:tween (tween-with-elapsed tw elapsed))
        (apply
         (lambda (finished? reversed? t)
           (let* ((k (eased (tween-ease tw) t))
                  (e (fold (lambda (prop e)
                             (entity-set e (car prop) (tween-prop-value prop finished? reversed? k)))
                           e (tween-props tw))))
             (if (not finished?)
                 (entity-set e #:tween (tween-with-elapsed tw elapsed))
                 (let ((e (entity-remove e #:tween))
                       (done (tween-on-complete tw)))
                   (if done
                       (let ((r (done e)))
                         (if (and (pair? r) (keyword? (car r))) r e))
                       e)))))
         phase))))

(define-step (step-tweens e scene dt)
  "Advance E's #:tween by DT ms: write its properties, drop it when it ends
and call its on-complete (§6)."
  (let ((tw (entity-ref e #:tween #f)))
    (cond ((or (not tw) (skips? e 'tweens)) e)
          ((not (tween? tw)) (fail 'step-tweens "entity key ~S: expected a tween (make-tween), got ~S" #:tween tw))
          (else (advance-tween e tw dt)))))

;;; ---------------------------------------------------------------- the frame (§5)

(define* (step-scene scene dt #:key (substeps 1))
  "One default-engine-update pass: tweens; then SUBSTEPS sub-frames (one, the
seed's frame, by default), each taking every entity through the per-entity
steps, all reading the scene as it was at the start of the sub-frame (the
first: of the frame, before the tweens), then the carriers, push-apart
and the crushing of what they pushed (§11), then groups (§5)."
  (unless (and (exact-integer? substeps) (<= 1 substeps 1024))
    (fail 'step-scene "substeps: expected an exact integer from 1 to ~S, got ~S" 1024 substeps))
  (let* ((start (scene-entities scene))
         (h (and (> substeps 1) (fl (/ 1 substeps))))
         (tweened (map-keeping (lambda (e) (step-tweens e scene dt)) start)))
    (let loop ((round 0) (es tweened) (pairs '()))
      (if (= round substeps)
          (let* ((result (same-or (map keep-if-unchanged es start) start))
                 (names (list->vector (map name-of result (iota (length result)))))
                 (contacts (if (null? pairs)
                               '()
                               (cons (map (lambda (p) (cons (vector-ref names (car p)) (vector-ref names (cadr p))))
                                          pairs)
                                     ;; the sides as the native report keeps them (world.scm)
                                     (u8-list->bytevector
                                      (map (lambda (p) (list-index (lambda (s) (eq? s (cddr p))) sides)) pairs)))))
                 (old ((@@ (downstroke world) %scene-contacts) scene))
                 (contacts (if (equal? contacts old) old contacts)))
            (if (and (eq? result start) (eq? contacts old))
                scene
                ((@@ (downstroke world) %scene-after-frame) scene result contacts)))
          (let-values (((es pairs) (sub-frame scene dt h round (if (= round 0) start es) es pairs)))
            (loop (+ round 1) es pairs))))))

(define (sub-frame scene dt h round supporting entities earlier)
  "One (sub-)frame of ENTITIES after the tweens; SUPPORTING is the scene
ground detection, resting and the carriers read (its holders, by slot)."
  (let* ((tm (scene-tilemap scene))
         (entities (if (= round 0) (clear-crushed entities) entities))
         (supporters (holders supporting))
         ;; Holders are named as the entities stepped now (after the tweens).
         (names (list->vector (map name-of entities (iota (length entities)))))
         (name-at (lambda (o i) (vector-ref names i)))
         (rest? (resting-contacts?))
         (g (gravity-of scene))
         (stepped
          (map (lambda (e slot)
                 (let* ((e (if (= round 0) (apply-acceleration e scene dt) e))
                        (rests (and rest? (pulled-down? e g) (rests? e tm supporters slot)))
                        (e (if rests e (gravity-step e h g)))
                        (e (speed-limits-step e h))
                        (e (velocity-step e h #:x #:vx 'velocity-x))
                        (e (tiles-x e scene h (> round 0)))
                        (e (velocity-step e h #:y #:vy 'velocity-y))
                        (e (tiles-y e scene h (> round 0)))
                        ;; not itself: its own slot of the supporting list
                        (e (on-solid e tm supporters (lambda (i o) (= i slot)) name-at)))
                   (cons e rests)))
               entities (iota (length entities))))
         (moved (same-or (map car stepped) entities))
         (carrying (any carrier? moved))
         (carried (if carrying (carry-among moved supporting scene) moved)))
    (let-values (((pushed pairs) (parameterize ((%walls (and tm (eq? (push-rule) 'clipped) tm)))
                                   (push-apart carried (map cdr stepped) earlier))))
      (values (sync-groups (if carrying (crush-in-way pushed (in-way carried supporting) tm) pushed))
              pairs))))
