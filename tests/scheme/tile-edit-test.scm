(use-modules (srfi srfi-64) (downstroke) (srfi srfi-1)
             ((downstroke reference) #:select ((step-scene . reference-step-scene))))

(load "support.scm")

(test-begin "tile-edit")

;; 4 × 4 cells of 16 px: a floor of gid 1 (solid) in row 3; gid 2 is one-way.
(define floor-map (make-tilemap 4 4 16 16 '(0 0 0 0  0 0 0 0  0 0 0 0  1 1 1 1) '(1) '(2)))
(define box (list #:x 16 #:y 32 #:width 16 #:height 16 #:gravity? #t))
(define (run step s n) (if (= n 0) s (run step (step s 16) (- n 1))))
(define (first-entity s) (car (scene-entities s)))

(define broken (tilemap-set-tile floor-map 1 3 0))
(test-equal "the new map has the cell cleared, the old one keeps it" '(#f #t)
  (list (tilemap-cell-solid? broken 1 3) (tilemap-cell-solid? floor-map 1 3)))
(test-equal "the gid too" '(0 1) (list (tilemap-gid broken 0 1 3) (tilemap-gid floor-map 0 1 3)))
(test-equal "a one-way gid makes a one-way cell" '(#t #f)
  (let ((m (tilemap-set-tile floor-map 2 1 2)))
    (list (tilemap-cell-one-way? m 2 1) (tilemap-cell-solid? m 2 1))))

;; A body at rest for 30 frames (long enough for every settled-body shortcut
;; to be taken), then the tile under it removed: it falls on the next frame,
;; through step-scene and through the reference alike.
(for-each
 (lambda (step name)
   (let* ((rest (run step (make-scene entities: (list box) tilemap: floor-map) 30))
          (after (run step (update-scene rest #:tilemap broken) 3)))
     (test-equal (string-append name ": at rest on the floor") '(32 #t)
       (list (entity-ref (first-entity rest) #:y) (entity-ref (first-entity rest) #:on-ground?)))
     (test-equal (string-append name ": falls once the tile is gone, 1 + 2 + 3 px") '(38 3 #f)
       (map (lambda (k) (entity-ref (first-entity after) k)) '(#:y #:vy #:on-ground?)))
     (test-equal (string-append name ": the old scene still stands on the old map") 32
       (entity-ref (first-entity (run step rest 5)) #:y))))
 (list step-scene reference-step-scene) '("native" "reference"))

;; Putting a tile back under a falling body stops it.
(test-equal "a tile put in the way stops the fall" 32
  (let* ((s (make-scene entities: (list (list #:x 16 #:y 20 #:width 16 #:height 16 #:gravity? #t))
                        tilemap: broken))
         (s (run step-scene s 2))
         (s (update-scene s #:tilemap (tilemap-set-tile broken 1 3 1))))
    (entity-ref (first-entity (run step-scene s 10)) #:y)))

(define (error-of thunk)
  (catch #t (lambda () (thunk) 'no-error)
    (lambda (key who fmt args . _) (list key who (apply format #f fmt args)))))
(test-equal "a cell outside the layer"
  '(out-of-range "tilemap-set-tile" "cell (9, 0) is outside tile layer 0")
  (error-of (lambda () (tilemap-set-tile floor-map 9 0 1))))
(test-equal "a layer that is not there"
  '(out-of-range "tilemap-set-tile" "no tile layer 3")
  (error-of (lambda () (tilemap-set-tile floor-map 0 0 1 3))))
(test-equal "a gid of no tileset"
  '(out-of-range "tilemap-set-tile" "gid 999 belongs to none of the map's tilesets")
  (error-of (lambda () (tilemap-set-tile (load-tilemap "demo/maps/level1.tmx") 0 0 999))))
(test-equal "a gid that is not one"
  '(wrong-type-arg "tilemap-set-tile" "gid: expected an exact integer from 0 to 4294967295, got -1")
  (error-of (lambda () (tilemap-set-tile floor-map 0 0 -1))))

(test-end "tile-edit")
