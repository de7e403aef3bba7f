;; SPDX-License-Identifier: MIT
;;; (downstroke query) — what is where: entities in a box or at a point,
;;; overlapping pairs between two groups, rays against tiles and entities,
;;; and world-point tile queries. All native (src/query.*); results are the
;;; scene's own entity objects, in list order.
(define-module (downstroke query)
  #:use-module (downstroke native)
  #:use-module (downstroke world)
  #:re-export (tilemap-solid-cells tilemap-solid-at? tilemap-gid-at)
  #:export (scene-query-rect scene-query-point scene-pairs scene-raycast
            scene-select))

;; WHERE chooses entities: #f (all of them), a procedure of an entity, or a
;; (key . value) pair matching entities whose KEY is equal? to VALUE.
(define (check-where who where)
  (unless (or (not where) (procedure? where)
              (and (pair? where) (keyword? (car where))))
    (scm-error 'wrong-type-arg who
               "where: expected #f, a procedure of an entity or a (keyword . value) pair, got ~S"
               (list where) #f)))

(define (entities-of who scene)
  (unless (scene? scene)
    (scm-error 'wrong-type-arg who "expected a scene, got ~S" (list scene) #f))
  (scene-entities scene))

(define (by-category who entities category collides-with)
  "ENTITIES kept by the category filter (semantics §13): those a body of
CATEGORY that collides with the categories COLLIDES-WITH would meet (each
#f: not asked). Native; ENTITIES itself when nothing is asked."
  (if (or category collides-with)
      (%category-filter who entities category collides-with)
      entities))

(define (choose who entities where)
  (check-where who where)
  (cond ((not where) entities)
        ((procedure? where) (filter where entities))
        (else (%select entities (car where) (cdr where)))))

(define* (scene-select scene where)
  "The entities of SCENE that WHERE chooses (a procedure of an entity, or a
(key . value) pair compared with equal?), in list order."
  (choose 'scene-select (entities-of 'scene-select scene) where))

(define* (scene-query-rect scene x y w h #:optional where #:key category collides-with)
  "The entities of SCENE whose boxes overlap the rectangle [X, X+W) × [Y, Y+H)
(strictly, as aabb-overlap?), in list order, optionally only those WHERE
chooses and those a body of CATEGORY that collides with COLLIDES-WITH (a
list of categories) would meet."
  (let ((found (%query-rect (by-category 'scene-query-rect (entities-of 'scene-query-rect scene)
                                         category collides-with)
                            x y w h)))
    (choose 'scene-query-rect found where)))

(define* (scene-query-point scene x y #:optional where #:key category collides-with)
  "The entities of SCENE whose boxes hold the point (X, Y) (a box holds its
top and left edges, not its bottom and right ones), in list order,
optionally only those WHERE chooses and the category filter keeps (see
scene-query-rect)."
  (let ((found (%query-point (by-category 'scene-query-point (entities-of 'scene-query-point scene)
                                          category collides-with)
                             x y)))
    (choose 'scene-query-point found where)))

(define* (scene-pairs scene where-a where-b #:key category collides-with)
  "Every overlapping pair (a . b) with a chosen by WHERE-A and b by WHERE-B
(see scene-select), by a's then b's list order. An entity never pairs with
itself, and two entities both chosen by both sides are paired once. The
category filter (see scene-query-rect) chooses on both sides."
  (let ((entities (by-category 'scene-pairs (entities-of 'scene-pairs scene) category collides-with)))
    (check-where 'scene-pairs where-a)
    (check-where 'scene-pairs where-b)
    (if (and (pair? where-a) (pair? where-b))
        (%pairs-by-key entities (car where-a) (cdr where-a) (car where-b) (cdr where-b))
        (%pairs (choose 'scene-pairs entities where-a)
                (choose 'scene-pairs entities where-b)))))

(define* (scene-raycast scene x0 y0 x1 y1 #:optional where #:key all? category collides-with)
  "Cast the segment from (X0, Y0) towards (X1, Y1) (the end not included)
against the scene's solid tiles and its entities (those WHERE chooses, or
all). Returns #f or the first hit, a plist of #:x #:y (where it enters, on
the entered edge), #:distance from the start, #:normal-x #:normal-y (the
face entered: -1, 0 or 1 each) and #:entity or #:col #:row; with ALL?, the
list of every hit, nearest first (at equal distances entities, in list
order, before tiles). A box or tile holding the start point is not hit.
The category filter (see scene-query-rect) chooses the entities it can hit."
  (let ((entities (choose 'scene-raycast
                          (by-category 'scene-raycast (entities-of 'scene-raycast scene) category collides-with)
                          where)))
    (%raycast entities (scene-tilemap scene) x0 y0 x1 y1 all?)))
