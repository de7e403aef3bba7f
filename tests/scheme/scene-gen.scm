;; SPDX-License-Identifier: MIT
;;; Random scenes for the differential suite (differential-test.scm).
;;;
;;; (generate-scene SEED)       a scene: entities and (in ~3/4 of the scenes) a tilemap
;;; (generate-scene-parts SEED) the entity list and the tilemap spec (see below), as two values
;;; (scene-dt SEED FRAME)       the dt (ms) of FRAME of scene SEED: 16, 16.666 or 20
;;; (tilemap-spec->tilemap S)   a tilemap from a spec (#f → #f)
;;; (sparse-tilemap cols rows tw th '((index . gid) ...))
;;;                             a tilemap from its non-empty cells; reproducers print this
;;; (tile-edits SEED FRAME TILEMAP ENTITIES)
;;;                             the cells to change before FRAME, as ((col row gid) ...)
;;; (edit-tilemap TILEMAP EDITS) a tilemap with those edits made
;;;
;;; Everything is a pure function of the seed: the generator has its own PRNG
;;; (xoshiro128**, seeded by splitmix64) on exact integers, so a seed names the
;;; same scene on every machine and Guile version. A tilemap spec is
;;; (cols rows tw th cells) with CELLS a vector of gids (1 solid, 0 empty, 2 not
;;; solid). In maps whose cols + rows is odd, gid 2 is a one-way platform
;;; (semantics §9): decided by the spec, not drawn, so every seed keeps the
;;; scene it had before one-way cells existed.
;;;
;;; What a scene holds (weights are approximate):
;;; - 1–4 entities (45%), 5–16 (37%), 17–40 (12%), 41–100 (5%), 101–200 (1%).
;;; - Roles: bodies (gravity, jumping ay −15, walking), crates (solid), platforms
;;;   (solid, often immovable, sometimes moving), projectiles (fast, skipping
;;;   gravity), decorations (no physics keys), chaos (any key, any value).
;;;   Half are placed on, beside or overlapping an earlier entity; most of the
;;;   rest inside the map or just above its bottom row.
;;; - Each key is dropped with p 1/8 (#:x and #:y stay), 1 entity in 20 keeps
;;;   about half its keys; 60% shuffled; 30% get 1–3 unknown keys (#:name "foo",
;;;   #:hp 3, #:tag 'enemy, …); 1 in 20 repeats a key later with another value.
;;; - Numbers: exact integers (55%), flonums, n + 0.5, n + 0.001·k, n ± 1e-9,
;;;   n + 1/2 (exact), -0.0 / 0.0; 1 coordinate in 60 huge (±1e7, ±2^40, ±1e15,
;;;   2^53 + 1, −2^62, 2^64). Sizes mostly 1–64, sometimes 0, negative or huge.
;;;   Velocities 0 (35%), −20…20 (50%), ±50…300 (8%), oddities (1/3, 600, …).
;;; - Flags #t / #f or truthy non-booleans ('yes, 0, "no", (x)). Skip lists:
;;;   each of the nine symbols with p 1/4, sometimes an unknown one.
;;; - #:id (40%): symbols, 1–3, strings (fresh copies: equal?, not eq?), #f;
;;;   1 in 10 reuses an id already given. Groups (40% of scenes with ≥ 2
;;;   entities): 1–3 of squad, g2, "team", 42, (band 1); 0, 1 or 2 origins
;;;   (#t or 'yes), 1–5 members with local offsets (sometimes none).
;;; - Tweens (1 entity in 12): 0–3 distinct props of #:x #:y #:vx #:width #:hp,
;;;   duration 0–400 (exact or flonum), delay 0–100, any easing name or a
;;;   procedure, repeat 0/1/2/−1, yoyo 30%, on-complete #f (70%) or returning a
;;;   modified entity, a non-entity, '() or a chained tween.
;;; - Tilemaps (75%): 1–40 × 1–40 cells of 8/16/32 px (sometimes 16×8, 8×16,
;;;   32×16, 16×32): arenas (floor, walls, platforms, holes), noise of random
;;;   density, empty, nearly full, or pillars; gid 2 sprinkled, never solid.
;;; - Ramps and part-tile boxes (semantics §12), in about 2 tilemaps in 5 (decided
;;;   by a stream of their own, so the other scenes are the ones they were): on
;;;   top of the floors and platforms, under ceilings and sprinkled anywhere,
;;;   gids 3–12 (shape-gids: 45°, 1:2 and 2:1 ramp pieces, a half-height box, a
;;;   4 px ledge, a small triangle, a one-way ramp), each with random flip bits
;;;   (horizontal, vertical: a ceiling ramp, diagonal), some drawn past their
;;;   tile (gids 13–16) and some convex polygons with several slants (gids
;;;   17–21: a house, a peak, a three-slant roof, ones reaching past the
;;;   tile), a third of those slanted on both sides (gids 22–25: a diamond,
;;;   a hexagon on its side, a diamond reaching past every side, a lopsided
;;;   one; each its own stream); tile edits on such maps may put ramps too.
;;; - Push-apart against the map (semantics §4), in about 1 map in 3 (its own
;;;   stream, map-pushers): boxes spawned inside solid and shaped cells, a
;;;   squeezed stack landing on a floor, two boxes pushed into a wall.
;;; - Categories, sensors and bounce (semantics §13) in about 2 scenes in 3
;;;   (collision-roles: its own stream).
;;; - Gravity and speed limits (semantics §14), each from a stream of its own:
;;;   a scene gravity other than 1 in about 1 scene in 3 (scene-gravity-for),
;;;   and #:gravity-scale, #:max-vx, #:max-vy, #:drag and the 'speed-limits
;;;   skip on entities of about 1 scene in 2 (speed-knobs).
;;; - dt: 16, 16.666 or 20 for the whole scene, or varying by frame (10%).
;;;
;;; Set `scene-gen-invalid?' to #t to put a wrongly typed value (a string
;;; velocity, +nan.0, a non-list skip list, ...) into about 1 scene in 30.
(use-modules (srfi srfi-1) (downstroke))

(define scene-gen-invalid? #f)

;;; ---------------------------------------------------------------- PRNG
;;; xoshiro128** on exact integers (every intermediate fits a fixnum), seeded
;;; through splitmix64.
(define %mask64 #xFFFFFFFFFFFFFFFF)
(define %mask32 #xFFFFFFFF)

(define (splitmix64 state)                 ; (values output next-state)
  (let* ((state (logand (+ state #x9E3779B97F4A7C15) %mask64))
         (z (logand (* (logxor state (ash state -30)) #xBF58476D1CE4E5B9) %mask64))
         (z (logand (* (logxor z (ash z -27)) #x94D049BB133111EB) %mask64)))
    (values (logxor z (ash z -31)) state)))

(define-syntax-rule (rotl32 x k)
  (logior (logand (ash x k) %mask32) (ash x (- k 32))))

;;; A procedure returning the next 32-bit draw of the stream named by SEED and SALT.
(define (make-rng seed salt)
  (call-with-values (lambda () (splitmix64 (logand (+ seed (* salt #xD1B54A32D192ED03)) %mask64)))
    (lambda (a state)
      (call-with-values (lambda () (splitmix64 state))
        (lambda (b state)
          (let ((s0 (logand a %mask32)) (s1 (ash a -32))
                (s2 (logand b %mask32)) (s3 (logior 1 (ash b -32))))
            (lambda ()
              (let ((result (logand (* 9 (rotl32 (logand (* s1 5) %mask32) 7)) %mask32))
                    (t (logand (ash s1 9) %mask32)))
                (set! s2 (logxor s2 s0))
                (set! s3 (logxor s3 s1))
                (set! s1 (logxor s1 s2))
                (set! s0 (logxor s0 s3))
                (set! s2 (logxor s2 t))
                (set! s3 (rotl32 s3 11))
                result))))))))

(define (ri r n) (modulo (r) n))                         ; 0 … n−1
(define (rr r lo hi) (+ lo (ri r (+ 1 (- hi lo)))))      ; lo … hi
(define (chance r num den) (< (ri r den) num))           ; probability num/den
(define (pick r lst) (list-ref lst (ri r (length lst))))
;;; WEIGHTED: ((weight . value) ...)
(define (wpick r weighted)
  (let loop ((n (ri r (apply + (map car weighted)))) (w weighted))
    (if (< n (caar w)) (cdar w) (loop (- n (caar w)) (cdr w)))))
;;; (choose r (weight expr) ...): one EXPR, picked by weight; only it is evaluated.
(define-syntax choose
  (syntax-rules ()
    ((_ r (w e) ...)
     ((wpick r (list (cons w (lambda () e)) ...))))))
(define (shuffle r lst)
  (let ((v (list->vector lst)))
    (do ((i (- (vector-length v) 1) (- i 1))) ((< i 1) (vector->list v))
      (let* ((j (ri r (+ i 1))) (t (vector-ref v i)))
        (vector-set! v i (vector-ref v j))
        (vector-set! v j t)))))

;;; ---------------------------------------------------------------- numbers
;;; N (an exact integer) in one of the number forms physics must accept.
(define (num-form r n)
  (choose r
          (55 n)
          (12 (exact->inexact n))
          (12 (+ n 0.5))
          (7 (+ n (* 0.001 (ri r 1000))))
          (3 (+ n 1e-9))
          (2 (- n 1e-9))
          (2 (+ n 1/2))
          (4 (if (zero? n) -0.0 n))
          (3 (if (zero? n) 0.0 (- n 0.25)))))

(define huge-values
  (list 10000000 -10000000 1e7 -1e7 (expt 2 40) (- (expt 2 40)) 1e15 -1e15
        (+ (expt 2 53) 1) (- (expt 2 62)) (expt 2 64)))

;;; A coordinate near BASE (exact integer): mostly BASE itself in some form,
;;; rarely a huge value.
(define (coord r base)
  (if (chance r 1 60) (pick r huge-values) (num-form r base)))

(define (size r)
  (choose r
          (70 (num-form r (pick r '(16 16 16 8 12 24 32 4 48 64 1 2 3))))
          (10 (num-form r (rr r 1 40)))
          (4 (pick r '(0 0 0.0 -0.0)))
          (3 (num-form r (rr r -16 -1)))
          (3 (pick r '(100 250 640 1000.0)))
          (1 (pick r '(1e7 10000000 1e-9)))))

(define (velocity r)
  (choose r
          (35 0)
          (50 (num-form r (rr r -20 20)))
          (8 (num-form r (* (pick r '(1 -1)) (rr r 50 300))))
          (2 (pick r '(-15 15 1/3 -0.0 1e-9 600)))))

(define (flag r)
  (choose r (80 #t) (12 #f) (8 (pick r '(yes 1 0 "no" (x))))))

(define all-skips '(acceleration gravity velocity-x velocity-y tile-collisions-x
                    tile-collisions-y on-solid entity-collisions tweens))

(define (skip-list r)
  (let ((l (filter (lambda (s) (chance r 1 4)) all-skips)))
    (if (chance r 1 6) (append l (list (pick r '(fly swim jump)))) (shuffle r l))))

;;; ---------------------------------------------------------------- tilemaps
(define (tile-size r)
  (wpick r '((25 . (8 . 8)) (40 . (16 . 16)) (20 . (32 . 32))
             (5 . (16 . 8)) (4 . (8 . 16)) (3 . (32 . 16)) (3 . (16 . 32)))))

(define (make-cells r cols rows)
  (let ((v (make-vector (* cols rows) 0)))
    (define (set-cell! c row gid)
      (when (and (< -1 c cols) (< -1 row rows)) (vector-set! v (+ c (* cols row)) gid)))
    (define (hrun! row c0 len gid) (do ((c c0 (+ c 1))) ((>= c (+ c0 len))) (set-cell! c row gid)))
    (define (vrun! c r0 len gid) (do ((row r0 (+ row 1))) ((>= row (+ r0 len))) (set-cell! c row gid)))
    (define (sprinkle! num den gid)
      (do ((i 0 (+ i 1))) ((= i (vector-length v)))
        (when (chance r num den) (vector-set! v i gid))))
    (case (wpick r '((50 . arena) (18 . noise) (10 . empty) (5 . full) (17 . pillars)))
      ((arena)
       (sprinkle! 1 20 2)
       (let ((floors (wpick r '((70 . 1) (20 . 2) (10 . 0)))))
         (do ((k 0 (+ k 1))) ((= k floors)) (hrun! (- rows 1 k) 0 cols 1)))
       (when (chance r 7 10) (vrun! 0 0 rows 1) (vrun! (- cols 1) 0 rows 1))
       (do ((k (ri r (+ 1 (quotient rows 3))) (- k 1))) ((<= k 0))
         (hrun! (ri r rows) (ri r cols) (rr r 1 8) 1))
       (when (chance r 1 4)                           ; holes in the floor
         (do ((k (rr r 1 3) (- k 1))) ((<= k 0)) (hrun! (- rows 1) (ri r cols) (rr r 1 3) 0))))
      ((noise)
       (let ((d (pick r '(1 5 10 20 40 70))))
         (sprinkle! d 100 1)
         (sprinkle! 1 30 2)))
      ((empty) (when (chance r 1 2) (sprinkle! 1 10 2)))
      ((full) (vector-fill! v 1) (sprinkle! 1 5 0))
      ((pillars)
       (hrun! (- rows 1) 0 cols 1)
       (do ((c (rr r 0 3) (+ c (rr r 2 6)))) ((>= c cols))
         (let ((h (rr r 1 (max 1 (quotient rows 2)))))
           (vrun! c (- rows 1 h) h 1)))))
    v))

(define (make-tilemap-spec r)
  (let* ((dims (choose r (30 (cons (rr r 10 20) (rr r 8 15)))
                          (30 (cons (rr r 20 40) (rr r 10 30)))
                          (20 (cons (rr r 1 5) (rr r 1 5)))
                          (20 (cons (rr r 1 40) (rr r 1 40)))))
         (cols (car dims)) (rows (cdr dims))
         (ts (tile-size r)))
    (list cols rows (car ts) (cdr ts) (make-cells r cols rows))))

;;; ---------------------------------------------------------------- ramps (§12)
;;; The shapes of gids 3–25 in a TW × TH tile, as make-tilemap takes them.
(define (shape-gids tw th)
  (let ((hw (quotient tw 2)) (hh (quotient th 2)) (qw (quotient tw 4)) (qh (quotient th 4)))
    `((3 . (polygon (0 . ,th) (,tw . ,th) (,tw . 0)))                  ; a whole-tile ramp
      (4 . (polygon (0 . ,th) (,tw . ,th) (,tw . ,hh)))                ; 1:2, lower
      (5 . (polygon (0 . ,th) (,tw . ,th) (,tw . 0) (0 . ,hh)))        ; 1:2, upper
      (6 . (polygon (0 . ,th) (,tw . ,th) (,tw . 0) (,hw . 0)))        ; 2:1, lower
      (7 . (polygon (,hw . ,th) (,tw . ,th) (,tw . 0)))                ; 2:1, upper
      (8 . (rect 0 ,hh ,tw ,(- th hh)))                                ; half-height box
      (9 . (rect 0 0 ,tw ,(min 4 th)))                                 ; a ledge
      (10 . (polygon (1 . ,(- th 1)) (,hw . ,(- th 1)) (,hw . ,hh)))   ; a small triangle
      (11 . (polygon (0 . ,th) (,tw . ,th) (,tw . 0)))                 ; one-way ramp
      (12 . (polygon (0 . ,th) (,tw . ,th) (,tw . ,(- th 1))))         ; a very shallow ramp
      ;; Drawn past the tile (§12): each collides as its part inside.
      (13 . (polygon (0 . ,(+ th hh)) (,(+ tw hw) . ,(+ th hh)) (,(+ tw hw) . 0))) ; past right and bottom
      (14 . (polygon (0 . ,th) (,(+ tw hw) . ,th) (,(+ tw hw) . 0)))   ; past right: slant ends off whole px
      (15 . (rect ,(- hw) ,(- hh) ,tw ,th))                            ; a box past left and top
      (16 . (polygon (,(- hw) . ,(- hh)) (,tw . ,(- hh)) (,(- hw) . ,th))) ; a ceiling ramp past left and top
      ;; Convex polygons cut by several slants on one side (§12).
      (17 . (polygon (0 . ,th) (0 . ,hh) (,hw . 0) (,tw . ,hh) (,tw . ,th)))  ; a house
      (18 . (polygon (0 . ,th) (,hw . ,hh) (,tw . ,th)))                       ; a peak
      (19 . (polygon (0 . ,th) (,qw . ,hh) (,hw . ,qh) (,tw . ,th)))           ; three slants
      (20 . (polygon (0 . ,th) (0 . ,hh) (,hw . ,(- hh)) (,tw . ,hh) (,tw . ,th))) ; peaking above the tile
      (21 . (polygon (,(- hw) . ,th) (,hw . 0) (,(+ tw hw) . ,th)))         ; slopes past left and right
      ;; Convex polygons slanted on both their top and their underside (§12).
      (22 . (polygon (,hw . 0) (,tw . ,hh) (,hw . ,th) (0 . ,hh)))            ; a diamond
      (23 . (polygon (,qw . 0) (,(- tw qw) . 0) (,tw . ,hh) (,(- tw qw) . ,th) (,qw . ,th) (0 . ,hh))) ; a hexagon on its side
      (24 . (polygon (,hw . ,(- hh)) (,(+ tw hw) . ,hh) (,hw . ,(+ th hh)) (,(- hw) . ,hh))) ; past every side: an octagon
      (25 . (polygon (0 . ,hh) (,hw . 0) (,tw . ,qh) (,tw . ,(- th qh)) (,qw . ,th)))))) ; lopsided

(define ramp-one-way-gids '(11))

(define (flip-bits r)
  (+ (if (chance r 1 2) #x80000000 0) (if (chance r 1 5) #x40000000 0) (if (chance r 1 6) #x20000000 0)))

;;; A ramp cell's gid, or in about one in six (a draw from R2, a stream of
;;; its own, so the maps' other cells stay as they were) a shape drawn past
;;; its tile (gids 13–16) with the same flips.
(define (reaching r2 gid)
  (if (chance r2 1 6)
      (logior (logand gid #xE0000000) (pick r2 '(13 14 15 16)))
      gid))

(define (ramp-gid r)
  (+ (wpick r '((30 . 3) (12 . 4) (12 . 5) (6 . 6) (6 . 7) (8 . 8) (6 . 9) (5 . 10) (10 . 11) (5 . 12)))
     (flip-bits r)))

;;; A shape cell's gid, or in about one in six (a draw from R3, a stream of
;;; its own) a convex polygon cut by several slants (gids 17–21), a third
;;; of those (a draw from R4, its own too, so R3's cells stay as they were)
;;; slanted on both sides (gids 22–25), same flips.
(define (polygonal r3 r4 gid)
  (if (chance r3 1 6)
      (let ((one-sided (pick r3 '(17 18 19 20 21))))
        (logior (logand gid #xE0000000) (if (chance r4 1 3) (pick r4 '(22 23 24 25)) one-sided)))
      gid))

;;; In about 2 maps in 5, ramps: on the empty cells just above solid ones (on
;;; floors and platforms, and pieces of ramps two tiles long), under solid ones,
;;; and a few anywhere. A stream of its own, salted by the seed: the other maps
;;; and every draw of the scene stay as they were.
(define (add-ramps! seed cols rows cells)
  (let ((r (make-rng seed 7919)) (r2 (make-rng seed 7927)) (r3 (make-rng seed 7933)) (r4 (make-rng seed 7937)))
    (when (chance r 2 5)
      (let ((solid? (lambda (c row) (and (< -1 c cols) (< -1 row rows)
                                         (eqv? 1 (vector-ref cells (+ c (* cols row)))))))
            (density (pick r '(2 4 6 10))))
        (do ((row 0 (+ row 1))) ((= row rows))
          (do ((c 0 (+ c 1))) ((= c cols))
            (let ((i (+ c (* cols row))))
              (when (eqv? 0 (vector-ref cells i))
                (cond ((and (solid? c (+ row 1)) (chance r density 10))
                       (vector-set! cells i (polygonal r3 r4 (reaching r2 (ramp-gid r)))))
                      ((and (solid? c (- row 1)) (chance r 1 6))
                       (vector-set! cells i (logior #x40000000 (polygonal r3 r4 (reaching r2 (ramp-gid r))))))
                      ((chance r 1 40)
                       (vector-set! cells i (polygonal r3 r4 (reaching r2 (ramp-gid r))))))))))))))

(define (ramped? spec)
  (and spec (let ((v (list-ref spec 4)))
              (let loop ((i 0)) (and (< i (vector-length v))
                                     (or (> (logand (vector-ref v i) #x0FFFFFFF) 2) (loop (+ i 1))))))))

(define (one-way-gids cols rows)
  (append (if (odd? (+ cols rows)) '(2) '()) ramp-one-way-gids))

(define (make-map cols rows tw th cells)
  (make-tilemap cols rows tw th cells '(1) (one-way-gids cols rows) (shape-gids tw th)))

(define (tilemap-spec->tilemap spec)
  (and spec (apply make-map spec)))

(define (sparse-tilemap cols rows tw th cells)
  (let ((v (make-vector (* cols rows) 0)))
    (for-each (lambda (c) (vector-set! v (car c) (cdr c))) cells)
    (make-map cols rows tw th v)))

;;; The non-empty cells of a spec's vector, as ((index . gid) ...).
(define (spec-cells spec)
  (let ((v (list-ref spec 4)))
    (let loop ((i (- (vector-length v) 1)) (acc '()))
      (cond ((< i 0) acc)
            ((eqv? 0 (vector-ref v i)) (loop (- i 1) acc))
            (else (loop (- i 1) (cons (cons i (vector-ref v i)) acc)))))))

;;; ---------------------------------------------------------------- tweens
(define (make-on-complete r)
  (choose r
          (70 #f)
          (12 (lambda (e) (entity-set e #:done #t)))
          (6 (lambda (e) 'not-an-entity))
          (3 (lambda (e) 42))
          (2 (lambda (e) '()))
          (2 (lambda (e) (entity-set (entity-set e #:hp 0) #:tag 'finished)))
          (5 (lambda (e)                                  ; chaining
               (entity-set e #:tween (make-tween e #:props '((#:x . 0)) #:duration 48))))))

(define (add-tween r entity)
  (let* ((keys (take (shuffle r '(#:x #:y #:vx #:width #:hp)) (wpick r '((10 . 0) (50 . 1) (30 . 2) (10 . 3)))))
         (props (map (lambda (k) (cons k (num-form r (rr r -100 500)))) keys))
         (duration (choose r (10 0) (70 (rr r 1 400)) (20 (exact->inexact (rr r 1 400)))))
         (delay (choose r (60 0) (30 (rr r 1 100)) (10 (* 0.5 (rr r 1 200)))))
         (ease (choose r (85 (pick r easing-names))
                          (10 (lambda (t) (* t t)))
                          (5 (lambda (t) (- 1 t)))))
         (repeat (choose r (55 0) (20 1) (10 2) (15 (if (zero? duration) 0 -1))))
         (yoyo? (chance r 3 10))
         (on-complete (make-on-complete r)))
    (catch #t
      (lambda ()
        (entity-set entity #:tween
                    (make-tween entity #:props props #:duration duration #:delay delay
                                #:ease ease #:repeat repeat #:yoyo? yoyo? #:on-complete on-complete)))
      (lambda _ entity))))                     ; e.g. a start value that is not a number

;;; ---------------------------------------------------------------- entities
(define unknown-pairs
  (list (cons #:name "foo") (cons #:hp 3) (cons #:tag 'enemy) (cons #:color '(1 2 3))
        (cons #:facing 'left) (cons #:speed 2.5) (cons #:hp 10.0) (cons #:name "crate")))

(define id-pool '(player e1 e2 e3 box 1 2 3 "hero" "crate" #f))
(define group-pool '(squad g2 "team" 42 (band 1)))

;;; A fresh copy of strings and lists, so that equal? ids are not eq?.
(define (fresh v) (cond ((string? v) (string-copy v)) ((pair? v) (list-copy v)) (else v)))

;;; The alist of an entity playing ROLE with its top-left at (X, Y) (exact
;;; integers); width and height are chosen here. Returns (alist w h).
(define (role-alist r role x y)
  (define (box w h . more)
    (append (list (cons #:x (coord r x)) (cons #:y (coord r y))
                  (cons #:width (if (chance r 1 10) (size r) w))
                  (cons #:height (if (chance r 1 10) (size r) h)))
            more))
  (case role
    ((body)                                   ; something falling, walking, jumping
     (box (num-form r (pick r '(8 12 16 16 24 32))) (num-form r (pick r '(8 16 16 24 32)))
          (cons #:gravity? (flag r)) (cons #:vx (velocity r)) (cons #:vy (velocity r))
          (cons #:on-ground? (pick r '(#t #f)))
          (cons #:solid? (pick r '(#t #f)))
          (cons #:ay (choose r (60 0) (30 -15) (10 (num-form r (rr r -20 5)))))))
    ((crate)
     (box 16 16 (cons #:solid? #t) (cons #:gravity? (flag r)) (cons #:vx (velocity r))
          (cons #:vy (velocity r))))
    ((platform)
     (box (num-form r (pick r '(32 48 64 128))) (num-form r (pick r '(8 16)))
          (cons #:solid? #t) (cons #:immovable? (flag r))
          (cons #:vx (choose r (70 0) (30 (velocity r))))
          (cons #:vy (choose r (80 0) (20 (velocity r))))))
    ((projectile)
     (box (num-form r 4) (num-form r 4) (cons #:vx (num-form r (* (pick r '(1 -1)) (rr r 20 300))))
          (cons #:vy (velocity r)) (cons #:solid? (pick r '(#t #f)))
          (cons #:skip-pipelines (pick r '((gravity) (on-solid entity-collisions) ())))))
    ((decoration)
     (list (cons #:x (coord r x)) (cons #:y (coord r y)) (pick r unknown-pairs)))
    (else                                     ; chaos: any key, any value
     (list (cons #:x (coord r x)) (cons #:y (coord r y)) (cons #:width (size r))
           (cons #:height (size r)) (cons #:vx (velocity r)) (cons #:vy (velocity r))
           (cons #:ay (velocity r)) (cons #:gravity? (flag r)) (cons #:on-ground? (flag r))
           (cons #:solid? (flag r)) (cons #:immovable? (flag r)) (cons #:drop-through? (flag r))
           (cons #:skip-pipelines (skip-list r))
           (cons #:group-local-x (velocity r)) (cons #:group-local-y (velocity r))))))

;;; Drop some keys, add unknown ones, shuffle, maybe duplicate a key.
(define (finish-alist r alist)
  (let* ((kept (filter (lambda (p) (or (memq (car p) '(#:x #:y)) (not (chance r 1 8)))) alist))
         (kept (if (chance r 1 20) (filter (lambda (p) (chance r 1 2)) kept) kept))
         (extra (if (chance r 3 10)
                    (map (lambda (i) (let ((p (pick r unknown-pairs))) (cons (car p) (fresh (cdr p)))))
                         (iota (rr r 1 3)))
                    '()))
         (all (delete-duplicates (append kept extra) (lambda (a b) (eq? (car a) (car b)))))
         (ordered (if (chance r 6 10) (shuffle r all) all)))
    (if (and (pair? ordered) (chance r 1 20))
        ;; A second occurrence of a key, later in the list: the first one wins.
        (let* ((i (ri r (length ordered)))
               (dup (car (list-ref ordered i)))
               (val (cond ((memq dup '(#:x #:y #:vx #:vy #:ay #:width #:height)) (velocity r))
                          ((eq? dup #:skip-pipelines) (skip-list r))
                          (else (pick r '(#t #f 7 bogus))))))
          (append ordered (list (cons dup val))))
        ordered)))

(define (alist->plist alist) (append-map (lambda (p) (list (car p) (cdr p))) alist))

(define (add-skips r alist)
  (if (chance r 3 20) (cons (cons #:skip-pipelines (skip-list r)) alist) alist))

(define (add-id r alist used-ids)
  (if (chance r 2 5)
      (let ((id (if (and (pair? used-ids) (chance r 1 10)) (pick r used-ids) (pick r id-pool))))
        (cons (cons #:id (fresh id)) alist))
      alist))

(define (entity-count r)
  (choose r (45 (rr r 1 4)) (37 (rr r 5 16)) (12 (rr r 17 40))
            (5 (rr r 41 100)) (1 (rr r 101 200))))

;;; Group members: ((group-id origin? local-x local-y) ...), one per entity slot
;;; that belongs to a group.
(define (make-groups r n)
  (if (or (< n 2) (chance r 6 10))
      '()
      (append-map
       (lambda (g)
         (let ((origins (wpick r '((20 . 0) (70 . 1) (10 . 2))))
               (members (rr r 1 5)))
           (append (map (lambda (i) (list g (wpick r '((80 . #t) (20 . yes))) 0 0)) (iota origins))
                   (map (lambda (i) (list g #f (velocity r) (velocity r))) (iota members)))))
       (take (shuffle r group-pool) (rr r 1 3)))))

(define (invalid-pair r)
  (pick r (list (cons #:vx "fast") (cons #:x +nan.0) (cons #:width 'wide)
                (cons #:skip-pipelines 'gravity) (cons #:y 1+2i) (cons #:x +inf.0)
                (cons #:vy +nan.0) (cons #:skip-pipelines '(gravity "tweens")))))

;;; Solid immovable bodies exactly 8 px high are one-way ledges (semantics
;;; §9). Decided from what was drawn, never drawn itself, so every seed keeps
;;; the scene it had before one-way bodies existed, bar the flag.
(define (one-way-ledge e)
  (if (and (eq? #t (entity-ref e #:solid? #f)) (entity-ref e #:immovable? #f)
           (eqv? 8 (entity-ref e #:height #f)))
      (append e (list #:one-way? #t))
      e))

;;; A moving immovable platform (the platform role's widths, a speed or a
;;; tween) carries its riders (semantics §11). Decided from what was drawn,
;;; as one-way-ledge is, so no scene's draws move.
(define (carrier-platform e)
  (define (moving? v) (and (real? v) (not (zero? v))))
  (if (and (eq? #t (entity-ref e #:solid? #f)) (entity-ref e #:immovable? #f)
           (memv (entity-ref e #:width #f) '(32 48 64 128))
           (or (moving? (entity-ref e #:vx 0)) (moving? (entity-ref e #:vy 0)) (entity-ref e #:tween #f)))
      (append e (list #:carries? #t))
      e))

;;; Every third entity, from a place the seed decides, reports contacts
;;; (semantics §10), bar every fourth seed's scene, which has none; every
;;; other one of those asks for the sides ('sides). Decided from the seed
;;; and the position, never drawn, so every seed keeps the scene it had
;;; before contact reports existed, bar the flag.
(define (contact-reporter seed)
  (lambda (e i)
    (if (and (not (zero? (modulo seed 4))) (zero? (modulo (+ seed i) 3)))
        (append e (list #:contacts? (if (odd? (quotient (+ seed i) 3)) 'sides #t)))
        e)))

;;; Categories, sensors and bounce (semantics §13), in about 2 scenes in 3,
;;; drawn from a stream of their own (salt 104729), so every seed keeps the
;;; scene it had before they existed, bar these keys: an entity gets a
;;; #:category (1 in 3), a #:collides-with list (1 in 4, '() included), is
;;; a sensor (1 in 10) and bounces (1 in 5: 1, 1.0, 1/2, 0.5, 0.25 or 0.75).
(define category-pool '(default player enemy bullet wall))

(define (collision-roles seed entities)
  (let ((r (make-rng seed 104729)))
    (define (role e)
      (let* ((e (if (chance r 1 3) (append e (list #:category (pick r category-pool))) e))
             (e (if (chance r 1 4)
                    (append e (list #:collides-with
                                    (let loop ((cs category-pool) (acc '()))   ; drawn in order
                                      (cond ((null? cs) (reverse acc))
                                            ((chance r 1 2) (loop (cdr cs) (cons (car cs) acc)))
                                            (else (loop (cdr cs) acc))))))
                    e))
             (e (if (chance r 1 10) (append e (list #:sensor? #t)) e)))
        (if (chance r 1 5) (append e (list #:bounce (pick r '(1 1.0 1/2 0.5 0.25 0.75)))) e)))
    (if (chance r 1 3)
        entities
        (let loop ((es entities) (acc '()))        ; one entity after the other
          (if (null? es) (reverse acc) (loop (cdr es) (cons (role (car es)) acc)))))))

;;; Gravity and speed limits (semantics §14), from streams of their own
;;; (salts 130363 and 130399), so every seed keeps the scene it had before
;;; they existed, bar these keys and its gravity. In about 1 scene in 2 an
;;; entity gets a #:gravity-scale (1 in 4), a #:max-vx and a #:max-vy (1 in
;;; 5 each), a #:drag (1 in 5; 0 included) and, with none of its own, a skip
;;; list of 'speed-limits (1 in 12).
(define (speed-knobs seed entities)
  (let ((r (make-rng seed 130363)))
    (define (knobs e)
      (let* ((e (if (chance r 1 4) (append e (list #:gravity-scale (pick r '(0 -1 1/2 0.5 2 1.0 3 -0.25)))) e))
             (e (if (chance r 1 5) (append e (list #:max-vx (pick r '(0 1 3 4.5 8 1/2 0.0)))) e))
             (e (if (chance r 1 5) (append e (list #:max-vy (pick r '(0 1 3 4.5 8 1/2 2.0)))) e))
             (e (if (chance r 1 5) (append e (list #:drag (pick r '(1 0.25 1/3 2 0 0.5)))) e)))
        (if (and (chance r 1 12) (not (memq #:skip-pipelines e)))
            (append e (list #:skip-pipelines '(speed-limits)))
            e)))
    (if (chance r 1 2)
        entities
        (map knobs entities))))

(define (scene-gravity-for seed)
  "The gravity of scene SEED: 1, the default, in about 2 scenes in 3."
  (let ((r (make-rng seed 130399)))
    (if (chance r 2 3) 1 (pick r '(1/2 2 0 -1 0.5 1.0 1/6 3)))))

;;; ---------------------------------------------------------------- push-apart against the map (§4)
;;; In about 1 map in 3, bodies that make push-apart meet the map (the
;;; 'clipped push rule): 1–3 boxes spawned overlapping a solid or shaped
;;; cell, to be put out; a stack of 3–5 boxes squeezed together on a floor
;;; cell, the upper ones falling, so that landing pushes the lowest into it;
;;; and two boxes overlapping beside a wall, the outer one moving towards
;;; it. Appended after the scene's own entities, from a stream of their own:
;;; every other draw of the scene stays as it was.
(define (map-pushers seed spec)
  (let ((r (make-rng seed 104729)))
    (if (not (and spec (chance r 1 3)))
        '()
        (apply
         (lambda (cols rows tw th cells)
           (define (gid c row) (if (and (< -1 c cols) (< -1 row rows)) (vector-ref cells (+ c (* row cols))) 0))
           (define (blocks? g) (or (eqv? g 1) (>= (logand g #x1FFFFFFF) 3)))
           (define (box x y w h . more)
             (append (list #:x x #:y y #:width w #:height h #:solid? #t) more))
           (let* ((cells-where (lambda (ok?) (filter (lambda (i) (ok? (modulo i cols) (quotient i cols)))
                                                     (iota (* cols rows)))))
                  (blocked (cells-where (lambda (c row) (blocks? (gid c row)))))
                  (floors (cells-where (lambda (c row) (and (eqv? (gid c row) 1) (eqv? (gid c (- row 1)) 0)))))
                  (walls (cells-where (lambda (c row) (and (eqv? (gid c row) 1) (eqv? (gid (- c 1) row) 0)))))
                  (at (lambda (i) (values (* tw (modulo i cols)) (* th (quotient i cols)))))
                  (spawned
                   (if (null? blocked)
                       '()
                       (map (lambda (k)
                              (let-values (((x y) (at (pick r blocked))))
                                (box (+ x (rr r -6 (- tw 2))) (+ y (rr r -6 (- th 2)))
                                     (pick r '(4 8 12 16)) (pick r '(4 8 12 16))
                                     #:gravity? (chance r 1 2) #:vx (rr r -3 3))))
                            (iota (rr r 1 3)))))
                  (stack
                   (if (null? floors)
                       '()
                       (let-values (((x top) (at (pick r floors))))
                         (let ((size (pick r '(8 16))) (squeeze (rr r 1 6)) (dx (rr r -4 4)))
                           (map (lambda (k)
                                  (box (+ x dx) (- top size (* k (- size squeeze))) size size
                                       #:gravity? #t #:vy (if (= k 0) 0 (rr r 0 12))))
                                (iota (rr r 3 5)))))))
                  (pair
                   (if (null? walls)
                       '()
                       (let-values (((x y) (at (pick r walls))))
                         (let ((size (pick r '(8 16))) (squeeze (rr r 1 6)))
                           (list (box (- x size (rr r -2 2)) y size size)
                                 (box (- x size size (- squeeze)) y size size #:vx (rr r 2 12))))))))
             (append spawned stack pair)))
         spec))))

(define (generate-scene-parts seed)
  (let* ((r (make-rng seed 0))
         (spec (and (chance r 3 4) (make-tilemap-spec r)))
         (spec (begin (when spec (add-ramps! seed (car spec) (cadr spec) (list-ref spec 4))) spec))
         (world-w (if spec (* (list-ref spec 0) (list-ref spec 2)) 600))
         (world-h (if spec (* (list-ref spec 1) (list-ref spec 3)) 400))
         (th (if spec (list-ref spec 3) 16))
         (n (entity-count r))
         (group-slots (let ((g (make-groups r n))) (if (> (length g) n) (take g n) g)))
         (slots (shuffle r (append group-slots (make-list (- n (length group-slots)) #f)))))
    (let loop ((slots slots) (boxes '()) (ids '()) (acc '()))
      (if (null? slots)
          (let ((entities (map (contact-reporter seed)
                               (speed-knobs seed
                                            (collision-roles seed (map (compose carrier-platform one-way-ledge) (reverse acc))))
                               (iota (length acc)))))
            (values (append
                     (if (and scene-gen-invalid? (chance r 1 30))
                         (let* ((i (ri r (length entities))) (p (invalid-pair r)))
                           (append (take entities i)
                                   (list (entity-set (list-ref entities i) (car p) (cdr p)))
                                   (drop entities (+ i 1))))
                         entities)
                     (map-pushers seed spec))
                    spec))
          (let* ((role (wpick r '((40 . body) (15 . crate) (12 . platform) (8 . projectile)
                                  (8 . decoration) (17 . chaos))))
                 ;; Near an earlier entity (on it, beside it, overlapping it) or anywhere.
                 (near (and (pair? boxes) (chance r 1 2) (pick r boxes)))
                 (x (if near
                        (+ (car near) (rr r -24 24))
                        (choose r (75 (rr r 0 (max 0 (- world-w 16))))
                                  (25 (rr r (- (min 200 world-w)) (+ world-w 16))))))
                 ;; Inside the map, just above its bottom row (a floor, usually), or anywhere.
                 (y (if near
                        (- (cdr near) (wpick r '((50 . 16) (30 . 17) (20 . 8))) (rr r -4 4))
                        (choose r (45 (rr r 0 (max 0 (- world-h th th))))
                                  (30 (- world-h th (pick r '(16 16 8 32)) (rr r -2 40)))
                                  (25 (rr r -200 600)))))
                 (alist (role-alist r role x y))
                 (alist (add-skips r alist))
                 (alist (add-id r alist ids))
                 (group (car slots))
                 (alist (if group
                            (apply (lambda (g origin? lx ly)
                                     (append alist
                                             (list (cons #:group-id (fresh g)))
                                             (if origin? (list (cons #:group-origin? origin?))
                                                 (if (chance r 1 5) (list (cons #:group-origin? #f)) '()))
                                             (if (or origin? (chance r 1 10)) '()
                                                 (list (cons #:group-local-x lx) (cons #:group-local-y ly)))))
                                   group)
                            alist))
                 (entity (alist->plist (finish-alist r alist)))
                 (entity (if (chance r 1 12) (add-tween r entity) entity))
                 (id (entity-ref entity #:id)))
            (loop (cdr slots) (cons (cons x y) boxes) (if id (cons id ids) ids)
                  (cons entity acc)))))))

;;; ---------------------------------------------------------------- tile edits
;;; The cells to change in TILEMAP before FRAME of scene SEED, as ((col row
;;; gid) …): on frames 4, 10, 16, … 1–3 edits, each at the cell under the
;;; feet of one of ENTITIES (the frame's input; where a body rests, an edit
;;; matters most) or, one time in three, anywhere in the map. A solid cell
;;; is cleared (gid 0) or, one time in four, made one-way (gid 2); any other
;;; becomes solid (gid 1) or one-way. Drawn from a stream of their own
;;; (negative salts: the scene and its dt use 0, 1, 2 + frame), so every
;;; seed keeps the scene it had before edits existed.
(define edit-period 6)

(define (tile-edits seed frame tilemap entities)
  (if (not (and tilemap (= 4 (modulo frame edit-period))))
      '()
      (let* ((r (make-rng seed (- -1 frame)))
             (cols (tilemap-width tilemap)) (rows (tilemap-height tilemap))
             (tw (tilemap-tile-width tilemap)) (th (tilemap-tile-height tilemap)))
        (define (feet e)                  ; (col . row) under e's feet, or #f
          (false-if-exception
           (let ((x (entity-ref e #:x)) (y (entity-ref e #:y))
                 (w (entity-ref e #:width 0)) (h (entity-ref e #:height 0)))
             (and (real? x) (real? y) (real? w) (real? h)
                  (let ((c (inexact->exact (floor (/ (+ x (/ w 2)) tw))))
                        (row (inexact->exact (floor (/ (+ y h) th)))))
                    (and (< -1 c cols) (< -1 row rows) (cons c row)))))))
        (define (cell)
          (or (and (pair? entities) (not (chance r 1 3)) (feet (pick r entities)))
              (cons (ri r cols) (ri r rows))))
        (let loop ((k (rr r 1 3)) (acc '()))
          (if (= k 0)
              (reverse acc)
              (let* ((c (cell))
                     (gid (if (tilemap-cell-solid? tilemap (car c) (cdr c))
                              (if (chance r 1 4) 2 0)
                              (if (chance r 1 3) 2 1)))
                     ;; On a map with shapes, one edit in three puts a ramp.
                     (gid (if (and (> (tilemap-steepest-ramp tilemap) 0) (chance r 1 3)) (ramp-gid r) gid)))
                (loop (- k 1) (cons (list (car c) (cdr c) gid) acc))))))))

;;; TILEMAP with EDITS ((col row gid) …) applied.
(define (edit-tilemap tilemap edits)
  (fold (lambda (e m) (apply tilemap-set-tile m e)) tilemap edits))

(define (generate-scene seed)
  (call-with-values (lambda () (generate-scene-parts seed))
    (lambda (entities spec)
      (make-scene #:entities entities #:tilemap (tilemap-spec->tilemap spec)
                  #:gravity (scene-gravity-for seed)))))

(define (scene-dt seed frame)
  (let* ((r (make-rng seed 1))
         (per-scene (wpick r '((40 . 16) (30 . 16.666) (20 . 20) (10 . vary)))))
    (if (eq? per-scene 'vary)
        (let ((rf (make-rng seed (+ 2 frame)))) (pick rf '(16 16.666 20)))
        per-scene)))
