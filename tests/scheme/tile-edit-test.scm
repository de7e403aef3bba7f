;; SPDX-License-Identifier: MIT
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

;; A falling body lands on a tile put in its way, on the reference side too.
(for-each
 (lambda (step name)
   (let* ((s (make-scene entities: (list (list #:x 16 #:y 20 #:width 16 #:height 16 #:gravity? #t))
                         tilemap: broken))
          (s (run step s 2))
          (s (update-scene s #:tilemap (tilemap-set-tile broken 1 3 1)))
          (e (first-entity (run step s 10))))
     (test-equal (string-append name ": a falling body lands on the new tile") '(32 0 #t)
       (map (lambda (k) (entity-ref e k)) '(#:y #:vy #:on-ground?)))))
 (list step-scene reference-step-scene) '("native" "reference"))

;; Edits on a map larger than one storage chunk (100 × 100 cells): each map
;; of the chain keeps exactly its own cells, gid and solidity alike.
(define wide (make-tilemap 100 100 8 8 (make-vector 10000 0) '(1) '(2)))
(define wide-1 (tilemap-set-tile wide 5 5 1))
(define wide-2 (tilemap-set-tile wide-1 99 99 2))
(define wide-3 (tilemap-set-tile wide-2 5 5 0))
(test-equal "a chain of edits: every map keeps its cells"
  '((0 0 #f #f) (1 0 #t #f) (1 2 #t #f) (0 2 #f #f))
  (map (lambda (m) (list (tilemap-gid m 0 5 5) (tilemap-gid m 0 99 99)
                         (tilemap-cell-solid? m 5 5) (tilemap-cell-solid? m 99 99)))
       (list wide wide-1 wide-2 wide-3)))
(test-equal "the one-way cell is only in the maps made after it" '(#f #f #t #t)
  (map (lambda (m) (tilemap-cell-one-way? m 99 99)) (list wide wide-1 wide-2 wide-3)))

;; A game that breaks the floor under its box at frame 5: rewinding to
;; before the edit brings the old map back, and the box rests again.
(let* ((game (make-game history: 10 scene: (make-scene entities: (list box) tilemap: floor-map)
                        update: (lambda (game dt)
                                  (when (= (game-frame game) 5)
                                    (game-scene-set! game (update-scene (game-scene game)
                                                                        #:tilemap broken))))))
       (y (lambda () (entity-ref (first-entity (game-scene game)) #:y))))
  (game-run! game frames: 9)
  (test-equal "the box falls once the game breaks the floor (frames 6–8: 1 + 2 + 3 px)" '(#f 38)
    (list (tilemap-cell-solid? (scene-tilemap (game-scene game)) 1 3) (y)))
  (game-rewind! game 6)
  (test-equal "rewound to before the edit: the old map and the box at rest" '(#t #t 32)
    (list (eq? floor-map (scene-tilemap (game-scene game)))
          (tilemap-cell-solid? (scene-tilemap (game-scene game)) 1 3) (y))))

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

(test-equal "a cell left of the layer"
  '(out-of-range "tilemap-set-tile" "cell (-1, 0) is outside tile layer 0")
  (error-of (lambda () (tilemap-set-tile floor-map -1 0 1))))
(test-equal "a cell below the layer"
  '(out-of-range "tilemap-set-tile" "cell (0, 4) is outside tile layer 0")
  (error-of (lambda () (tilemap-set-tile floor-map 0 4 1))))
(test-equal "not a map"
  '(wrong-type-arg "tilemap-set-tile" "tm: expected a tilemap, got (1 2)")
  (error-of (lambda () (tilemap-set-tile '(1 2) 0 0 1))))
(test-equal "a column that is not an exact integer"
  '(wrong-type-arg "tilemap-set-tile" "col: expected an exact integer cell index, got 1.5")
  (error-of (lambda () (tilemap-set-tile floor-map 1.5 0 1))))
(test-equal "a row that is not a number"
  '(wrong-type-arg "tilemap-set-tile" "row: expected an exact integer cell index, got \"3\"")
  (error-of (lambda () (tilemap-set-tile floor-map 0 "3" 1))))
(test-equal "a gid past 32 bits"
  '(wrong-type-arg "tilemap-set-tile" "gid: expected an exact integer from 0 to 4294967295, got 4294967296")
  (error-of (lambda () (tilemap-set-tile floor-map 0 0 (expt 2 32)))))
(test-equal "a gid that is a symbol"
  '(wrong-type-arg "tilemap-set-tile" "gid: expected an exact integer from 0 to 4294967295, got solid")
  (error-of (lambda () (tilemap-set-tile floor-map 0 0 'solid))))
(test-equal "a layer that is not a number"
  '(wrong-type-arg "tilemap-set-tile" "layer: expected a tile layer number (an exact integer from 0), got top")
  (error-of (lambda () (tilemap-set-tile floor-map 0 0 1 'top))))
(test-equal "a negative layer"
  '(wrong-type-arg "tilemap-set-tile" "layer: expected a tile layer number (an exact integer from 0), got -1")
  (error-of (lambda () (tilemap-set-tile floor-map 0 0 1 -1))))
(test-equal "a refused edit leaves the map as it was" '(1 #t)
  (begin (error-of (lambda () (tilemap-set-tile floor-map 1 3 0 7)))
         (list (tilemap-gid floor-map 0 1 3) (tilemap-cell-solid? floor-map 1 3))))

(test-end "tile-edit")
