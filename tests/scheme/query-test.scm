;; SPDX-License-Identifier: MIT
(use-modules (srfi srfi-64) (downstroke) (srfi srfi-1))

(load "support.scm")

(test-begin "query")

(define (box x y w h . more) (append (list #:x x #:y y #:width w #:height h) more))
(define a (box 0 0 10 10 #:kind 'enemy))
(define b (box 5 5 10 10 #:kind 'bullet))
(define c (box 40 0 10 10 #:kind 'enemy))
;; 6 × 3 cells of 16 px, the cell (4, 1) solid.
(define grid (make-tilemap 6 3 16 16 '(0 0 0 0 0 0  0 0 0 0 1 0  0 0 0 0 0 0) '(1)))
(define scene (make-scene entities: (list a b c) tilemap: grid))

(define (error-of thunk)
  (catch #t (lambda () (thunk) 'no-error)
    (lambda (key who fmt args . _) (list key who (apply format #f fmt args)))))

;;; ---------------------------------------------------------------- rectangles and points
(test-assert "the entity objects themselves, in list order"
  (let ((found (scene-query-rect scene 6 6 1 1)))
    (and (= 2 (length found)) (eq? a (first found)) (eq? b (second found)))))
(test-equal "touching edges do not overlap" '() (scene-query-rect scene 10 10 5 5 '(#:kind . enemy)))
(test-equal "a point on a left edge is inside, on a right edge outside" (list b)
  (scene-query-point scene 10 5))
(test-equal "filtered by a (key . value) pair" (list b) (scene-query-point scene 7 7 '(#:kind . bullet)))
(test-equal "filtered by a predicate" (list a)
  (scene-query-point scene 7 7 (lambda (e) (eq? 'enemy (entity-ref e #:kind)))))
(test-equal "scene-select" (list a c) (scene-select scene '(#:kind . enemy)))

;;; ---------------------------------------------------------------- pairs
(test-equal "bullets × enemies" (list (cons b a)) (scene-pairs scene '(#:kind . bullet) '(#:kind . enemy)))
(test-equal "everything × everything: each pair once, nobody with itself" (list (cons a b))
  (scene-pairs scene #f #f))
(let* ((p (box 0 0 10 10 #:kind 'enemy)) (q (box 5 5 10 10 #:kind 'enemy)) (r (box 8 0 4 4 #:kind 'enemy))
       (s (make-scene entities: (list p q r))))
  (test-equal "one group against itself, by key: each pair once, by list order"
    (list (cons p q) (cons p r))
    (scene-pairs s '(#:kind . enemy) '(#:kind . enemy)))
  (test-equal "the same through predicates"
    (scene-pairs s '(#:kind . enemy) '(#:kind . enemy))
    (scene-pairs s (lambda (e) #t) (lambda (e) #t))))

;; Random scenes against the plain double loop over aabb-overlap?.
(define (random-scene seed n)
  (let ((state (seed->random-state seed)))
    (map (lambda (i)
           (box (random 300 state) (random 300 state) (+ 1 (random 30 state)) (+ 1 (random 30 state))
                #:kind (if (even? (random 2 state)) 'bullet 'enemy)))
         (iota n))))
(define (brute-pairs as bs)
  (append-map (lambda (p)
                (filter-map (lambda (q)
                              (and (not (eq? p q))
                                   (aabb-overlap? (entity-ref p #:x) (entity-ref p #:y) (entity-ref p #:width)
                                                  (entity-ref p #:height) (entity-ref q #:x) (entity-ref q #:y)
                                                  (entity-ref q #:width) (entity-ref q #:height))
                                   (cons p q)))
                            bs))
              as))
(test-assert "pairs equal brute force on random scenes"
  (every (lambda (seed)
           (let* ((es (random-scene seed 200)) (s (make-scene entities: es))
                  (kind (lambda (k) (filter (lambda (e) (eq? k (entity-ref e #:kind))) es))))
             (equal? (scene-pairs s '(#:kind . bullet) '(#:kind . enemy))
                     (brute-pairs (kind 'bullet) (kind 'enemy)))))
         (iota 10)))

;;; ---------------------------------------------------------------- rays
(test-equal "a ray stops at the wall's edge"
  '(#:x 64.0 #:y 20.0 #:distance 44.0 #:normal-x -1 #:normal-y 0 #:col 4 #:row 1)
  (scene-raycast scene 20 20 90 20))
(test-equal "the end is not included" #f (scene-raycast scene 20 20 64 20))
(test-equal "an entity holding the start is not hit; all hits, nearest first"
  (list (list #:x 5.0 #:y 5.0 #:distance 5.0 #:normal-x -1 #:normal-y 0 #:entity b)
        (list #:x 40.0 #:y 5.0 #:distance 40.0 #:normal-x -1 #:normal-y 0 #:entity c))
  (scene-raycast scene 0 5 100 5 #:all? #t))
(test-equal "entities chosen by where; tiles are always there"
  '(#:x 64.0 #:y 17.0 #:distance 64.0 #:normal-x -1 #:normal-y 0 #:col 4 #:row 1)
  (scene-raycast scene 0 17 100 17 '(#:kind . nobody)))
(test-equal "up into a cell from below"
  '(#:x 70.0 #:y 32.0 #:distance 8.0 #:normal-x 0 #:normal-y 1 #:col 4 #:row 1)
  (scene-raycast scene 70 40 70 0))

;; The cells any segment enters, against trying every cell as a box.
(define (enter-time p d lo hi)  ; the span of t with p + t·d in [lo, hi)
  (cond ((> d 0) (cons (/ (- lo p) d) (/ (- hi p) d)))
        ((< d 0) (cons (/ (- hi p) d) (/ (- lo p) d)))
        ((and (<= lo p) (< p hi)) (cons -inf.0 +inf.0))
        (else (cons +inf.0 -inf.0))))
(define (brute-first-cell tm x0 y0 x1 y1)
  (let ((dx (- x1 x0)) (dy (- y1 y0)) (best #f))
    (do ((row 0 (+ row 1))) ((= row (tilemap-height tm)) best)
      (do ((col 0 (+ col 1))) ((= col (tilemap-width tm)))
        (when (tilemap-cell-solid? tm col row)
          (let* ((lx (* 1.0 col 16)) (ly (* 1.0 row 16))
                 (sx (enter-time x0 dx lx (+ lx 16))) (sy (enter-time y0 dy ly (+ ly 16)))
                 (t (max (car sx) (car sy) 0.0)))
            (when (and (not (and (<= lx x0) (< x0 (+ lx 16)) (<= ly y0) (< y0 (+ ly 16))))
                       (< t (min (cdr sx) (cdr sy) 1.0))
                       (or (not best) (< t (car best))))
              (set! best (list t col row)))))))))
(define walls
  (make-tilemap 12 12 16 16
                (map (lambda (i) (if (zero? (modulo (* i 7) 5)) 1 0)) (iota 144)) '(1)))
(test-assert "the first cell hit equals brute force for random segments"
  (let ((state (seed->random-state 3)) (s (make-scene tilemap: walls)))
    (every (lambda (_)
             (let* ((x0 (- (random 220.0 state) 10)) (y0 (- (random 220.0 state) 10))
                    (x1 (- (random 220.0 state) 10)) (y1 (- (random 220.0 state) 10))
                    (hit (scene-raycast s x0 y0 x1 y1))
                    (want (brute-first-cell walls x0 y0 x1 y1)))
               (if want
                   (and hit (= (second want) (entity-ref hit #:col)) (= (third want) (entity-ref hit #:row)))
                   (not hit))))
           (iota 500))))

;;; ---------------------------------------------------------------- tiles
(test-equal "solid cells a box covers" '((4 . 1)) (tilemap-solid-cells grid 60 10 20 20))
(test-equal "a box ending on a cell's edge does not cover it" '() (tilemap-solid-cells grid 48 16 16 16))
(test-equal '(#t #f) (list (tilemap-solid-at? grid 64 16) (tilemap-solid-at? grid 63.9 16)))
(test-equal "the gid at a world point" '(1 0) (list (tilemap-gid-at grid 64 16) (tilemap-gid-at grid 0 0)))

;;; ---------------------------------------------------------------- bad input
(test-equal "a ray of zero length"
  '(out-of-range "scene-raycast" "a ray of zero length, from (1, 1) to itself")
  (error-of (lambda () (scene-raycast scene 1 1 1 1))))
(test-equal "NaN"
  '(wrong-type-arg "scene-query-rect" "height: expected a finite real number, got +nan.0")
  (error-of (lambda () (scene-query-rect scene 1 1 1 +nan.0))))
(test-equal "a where that is neither"
  '(wrong-type-arg scene-pairs "where: expected #f, a procedure of an entity or a (keyword . value) pair, got kind")
  (error-of (lambda () (scene-pairs scene 'kind #f))))
(test-equal "not a scene"
  '(wrong-type-arg scene-query-point "expected a scene, got (1 2)")
  (error-of (lambda () (scene-query-point '(1 2) 0 0))))
(test-equal "a circular plist in a group"
  'wrong-type-arg
  (car (error-of (lambda ()
                   (let ((e (list #:x 1 #:y 2)))
                     (set-cdr! (cdddr e) e)
                     (scene-query-point (make-scene entities: (list e)) 0 0))))))
(test-equal "a wrong-typed #:x names the key"
  'wrong-type-arg
  (car (error-of (lambda () (scene-query-point (make-scene entities: (list (box "a" 0 1 1))) 0 0)))))

;;; ---------------------------------------------------------------- the category filter (semantics §13)
(define hero (box 0 0 10 10 #:id 'hero #:category 'player))
(define imp (box 2 2 10 10 #:id 'imp #:category 'enemy #:collides-with '(player wall bullet)))
(define shot (box 4 4 10 10 #:id 'shot #:category 'bullet #:collides-with '(enemy)))
(define crate (box 6 6 10 10 #:id 'crate))
(define crowd (make-scene entities: (list hero imp shot crate) tilemap: grid))
(define (ids es) (map (lambda (e) (if (pair? e) (entity-ref e #:id) e)) es))
(test-equal "collides-with: keeps the entities in those categories" '(imp crate)
  (ids (scene-query-rect crowd 0 0 20 20 collides-with: '(enemy default))))
(test-equal "category: keeps those whose #:collides-with names it (or that name none)" '(hero imp crate)
  (ids (scene-query-rect crowd 0 0 20 20 category: 'player)))
(test-equal "both: what a body of that category and mask would meet" '(imp)
  (ids (scene-query-point crowd 7 7 category: 'bullet collides-with: '(enemy))))
(test-equal "… alongside where" '(hero)
  (ids (scene-query-point crowd 7 7 '(#:id . hero) collides-with: '(player enemy))))
(test-equal "scene-pairs: the filter chooses on both sides" '((hero . imp))
  (map (lambda (p) (cons (entity-ref (car p) #:id) (entity-ref (cdr p) #:id)))
       (scene-pairs crowd '(#:id . hero) #f collides-with: '(player enemy))))
(test-equal "scene-raycast: a ray that hits only enemies passes the player and the crate" 'imp
  (entity-ref (entity-ref (scene-raycast crowd -5 8 50 8 collides-with: '(enemy)) #:entity) #:id))
(test-equal "without the filter, the first entity on the ray" 'hero
  (entity-ref (entity-ref (scene-raycast crowd -5 8 50 8) #:entity) #:id))
(test-eq "no filter asked: the query sees every entity" 4 (length (scene-query-rect crowd 0 0 20 20)))
(test-equal "a category that is not a symbol"
  '(wrong-type-arg "scene-query-rect" "category: expected a category symbol or #f, got 3")
  (error-of (lambda () (scene-query-rect crowd 0 0 1 1 category: 3))))
(test-equal "a collides-with that is not a list of symbols"
  '(wrong-type-arg "scene-raycast" "collides-with: expected a list of category symbols or #f, got (enemy \"x\")")
  (error-of (lambda () (scene-raycast crowd 0 0 1 1 collides-with: '(enemy "x")))))
(test-equal "… nor circular" 'wrong-type-arg
  (car (error-of (lambda () (scene-query-point crowd 0 0 collides-with: (let ((l (list 'a))) (set-cdr! l l) l))))))
(test-equal "an entity's bad #:category is named" 'wrong-type-arg
  (car (error-of (lambda () (scene-query-point (make-scene entities: (list (box 0 0 1 1 #:category 5))) 0 0
                                               category: 'player)))))

(test-end "query")
