;; SPDX-License-Identifier: MIT
(use-modules (srfi srfi-64) (downstroke) (srfi srfi-1) (rnrs bytevectors)
             ((downstroke reference) #:select ((step-scene . reference-step-scene))))

(load "support.scm")

(define data (or (getenv "DS_TEST_DATA") "tests/data"))
(define (map-file name) (string-append data "/maps/" name))

;;; The solidity of every cell, row by row.
(define (solid-grid m)
  (map (lambda (r) (map (lambda (c) (tilemap-cell-solid? m c r)) (iota (tilemap-width m))))
       (iota (tilemap-height m))))
(define (object-named m name)
  (find (lambda (o) (equal? (entity-ref o #:name) name)) (tilemap-objects m)))

(test-begin "tilemap")

;;; ---------------------------------------------------------------- demo/maps/level1.tmx
(define level1 (load-tilemap "demo/maps/level1.tmx"))
(test-assert (tilemap? level1))
(test-equal 30 (tilemap-width level1))
(test-equal 15 (tilemap-height level1))
(test-equal 16 (tilemap-tile-width level1))
(test-equal 16 (tilemap-tile-height level1))
;; tiles.tsx: gid 1 and 2 have solid=true, gid 3 a collision objectgroup, gid 4 nothing.
(test-equal "gid 2 (wall), top-left" #t (tilemap-cell-solid? level1 0 0))
(test-equal "empty cell" #f (tilemap-cell-solid? level1 1 0))
(test-equal "gid 2, right column" #t (tilemap-cell-solid? level1 29 5))
(test-equal "gid 1 (ground)" #t (tilemap-cell-solid? level1 1 13))
(test-equal "gid 1, last row" #t (tilemap-cell-solid? level1 28 14))
(test-equal "gid 3 (collision objectgroup)" #t (tilemap-cell-solid? level1 15 7))
(test-equal "gid 3, other platform" #t (tilemap-cell-solid? level1 9 9))
(test-equal "gid 3 row ends" #f (tilemap-cell-solid? level1 10 9))
(test-equal "gid 4 (no metadata)" #f (tilemap-cell-solid? level1 3 12))
(test-equal "gid 4 again" #f (tilemap-cell-solid? level1 25 12))
(test-equal "gid 2 in the middle" #t (tilemap-cell-solid? level1 12 12))
(test-equal "outside: left" #f (tilemap-cell-solid? level1 -1 0))
(test-equal "outside: right" #f (tilemap-cell-solid? level1 30 0))
(test-equal "outside: below" #f (tilemap-cell-solid? level1 1 15))
(test-equal "outside: above" #f (tilemap-cell-solid? level1 0 -1))
(test-equal "solid cells counted" (+ 15 15 28 28 7 5 2)
  ;; two wall columns, two ground rows (28 inner cells each), 7 + 5 platform
  ;; cells, and the two gid-2 cells at (12, 12) and (13, 12).
  (count identity (concatenate (solid-grid level1))))
(test-equal 2 (length (tilemap-objects level1)))
(let ((player (object-named level1 "player")))
  (test-equal 'player (entity-ref player #:type))
  (test-assert (symbol? (entity-ref player #:type)))
  (test-equal "player" (entity-ref player #:name))
  (test-equal 48 (entity-ref player #:x))
  (test-equal 160 (entity-ref player #:y))
  (test-equal 12 (entity-ref player #:width))
  (test-equal 14 (entity-ref player #:height))
  (test-equal "int property" 3 (entity-ref player #:speed))
  (test-assert "an object is a well-formed entity" (entity-ref (entity-set player #:vx 1) #:vx)))
(let ((door (object-named level1 "exit")))
  (test-equal 'door (entity-ref door #:type))
  (test-equal '(440 176 16 32) (map (lambda (k) (entity-ref door k)) '(#:x #:y #:width #:height))))
(test-equal "objects in document order" '("player" "exit")
  (map (lambda (o) (entity-ref o #:name)) (tilemap-objects level1)))
;; solid-gids: gid 4 has no metadata; a script marks it solid.
(define level1-4 (load-tilemap "demo/maps/level1.tmx" solid-gids: '(4)))
(test-equal "solid-gids: gid 4 now solid" #t (tilemap-cell-solid? level1-4 3 12))
(test-equal "solid-gids: metadata still counts" #t (tilemap-cell-solid? level1-4 0 0))
(test-equal "solid-gids: empty cells stay empty" #f (tilemap-cell-solid? level1-4 1 0))
(test-equal "prefix keyword form" #t
  (tilemap-cell-solid? (load-tilemap "demo/maps/level1.tmx" #:solid-gids '(4)) 25 12))
(test-equal "the first load is unaffected" #f (tilemap-cell-solid? level1 3 12))
;; A loaded map drives the physics.
(test-equal "level1 floor stops a falling box: row 13 top at 208 → y = 208 − 16"
  '(#:x 32 #:y 192 #:width 16 #:height 16 #:vy 0)
  (resolve-tile-collisions-y '(#:x 32 #:y 200 #:width 16 #:height 16 #:vy 5)
                             (make-scene tilemap: level1) 16))

;;; ---------------------------------------------------------------- every encoding
;; The 6×4 level in every encoding. terrain.tsx: gid 1 solid, 2 collision,
;; 3 collides, 4 a non-empty collision objectgroup (all solid); 5 solid=false,
;; 6 an empty objectgroup, 7 a ladder (not solid). Flip bits are masked:
;; 2147483649 = gid 1, 1073741828 = gid 4, 1610612739 = gid 3, 4026531841 = gid 1.
(define encodings '("level_csv.tmx" "level_base64.tmx" "level_zlib.tmx" "level_gzip.tmx"
                    "level_zstd.tmx" "level_zstd_stream.tmx" "level_xml.tmx"))
(define csv (load-tilemap (map-file "level_csv.tmx")))
(test-equal '(6 4 16 16) (list (tilemap-width csv) (tilemap-height csv)
                               (tilemap-tile-width csv) (tilemap-tile-height csv)))
(define (cells m cs) (map (lambda (c) (tilemap-cell-solid? m (car c) (cdr c))) cs))
(for-each
 (lambda (name)
   (let ((m (load-tilemap (map-file name))))
     (test-equal (string-append name ": size") '(6 4) (list (tilemap-width m) (tilemap-height m)))
     (test-equal (string-append name ": solid cells")
       '(#t #t #t #t #t #t #t #t)
       (cells m '((0 . 2) (5 . 2) (0 . 3) (1 . 3) (2 . 3) (3 . 3) (4 . 3) (5 . 3))))
     (test-equal (string-append name ": non-solid cells")
       '(#f #f #f #f #f #f #f)
       (cells m '((0 . 0) (2 . 0) (1 . 1) (4 . 1) (1 . 2) (3 . 0) (3 . 1))))
     (test-equal (string-append name ": same as CSV") (solid-grid csv) (solid-grid m))
     (test-equal (string-append name ": raw gid keeps the flip bits") 2147483656 (tilemap-gid m 0 5 0))
     (test-equal (string-append name ": raw gid 4026531841") 4026531841 (tilemap-gid m 0 5 3))
     (test-equal (string-append name ": empty cell gid") 0 (tilemap-gid m 0 0 0))))
 encodings)
(test-equal "solid-gids on a loaded level: gid 7 (ladder)" #t
  (tilemap-cell-solid? (load-tilemap (map-file "level_csv.tmx") solid-gids: '(7)) 2 0))

;;; ---------------------------------------------------------------- several tilesets
;; firstgids 13 (deco, embedded), 1 (terrain.tsx), 9 (props, embedded), listed
;; out of order. gid 9 = props 0 (solid), 10 = props 1 (nothing), 11 = props 2
;; (polygon collision), 12 = props 3 (collides=false), 13 = deco 0 (image),
;; 18 = deco 5 (bush, solid).
(define multi (load-tilemap (map-file "tilesets.tmx")))
(test-equal '(6 2) (list (tilemap-width multi) (tilemap-height multi)))
(test-equal "row 0: gids 1 9 10 11 12" '(#t #t #f #t #f)
  (cells multi '((0 . 0) (2 . 0) (3 . 0) (4 . 0) (5 . 0))))
(test-equal "row 1: 9 (flipped) 11 (flipped) 13 18 _ 0" '(#t #t #f #t #f)
  (cells multi '((0 . 1) (1 . 1) (2 . 1) (3 . 1) (5 . 1))))

;;; ---------------------------------------------------------------- layers and objects
;; 4×3 map of 16×8 tiles. background: (0,0) gid 5 (solid=false), (1,0) gid 1.
;; "walls" has solid=true: its cells (0,1) gid 6 and (3,1) gid 7 are solid.
;; "decor" has collision=false: its gids 1 2 3 on row 2 add no solidity.
;; "hidden": (3,2) gid 3 (collides) is solid.
(define layers (load-tilemap (map-file "layers.tmx")))
(test-equal '(4 3 16 8) (list (tilemap-width layers) (tilemap-height layers)
                              (tilemap-tile-width layers) (tilemap-tile-height layers)))
(test-equal "row 0" '(#f #t #f #f) (list-ref (solid-grid layers) 0))
(test-equal "row 1: a solid layer" '(#t #f #f #t) (list-ref (solid-grid layers) 1))
(test-equal "row 2: a collision=false layer adds nothing; the hidden layer's gid 3 does"
  '(#f #f #f #t) (list-ref (solid-grid layers) 2))
(test-equal "objects of every object layer" 6 (length (tilemap-objects layers)))
(let ((start (object-named layers "start")))
  (test-equal 'spawn (entity-ref start #:type))
  (test-equal '(8 16) (list (entity-ref start #:x) (entity-ref start #:y))))
(let ((p (object-named layers "player")))
  (test-equal 'player (entity-ref p #:type))
  (test-equal '(16 32 16 16) (map (lambda (k) (entity-ref p k)) '(#:x #:y #:width #:height)))
  (test-equal "int" 3 (entity-ref p #:speed))
  (test-equal "float" 15.5 (entity-ref p #:jump))
  (test-equal "bool false" #f (entity-ref p #:can_fly 'absent))
  (test-equal "string" "Hero" (entity-ref p #:label))
  (test-equal "multi-line string" "first line\nsecond line" (entity-ref p #:bio)))
(let ((slime (object-named layers "slime")))
  (test-equal "type from class" 'enemy (entity-ref slime #:type))
  (test-equal "fractional x" 40.5 (entity-ref slime #:x))
  (test-equal '(12 10) (list (entity-ref slime #:width) (entity-ref slime #:height))))
(test-equal "negative fractional y" -4.25 (entity-ref (object-named layers "both") #:y))
(test-assert "every object is a keyword plist"
  (every (lambda (o) (and (even? (length o)) (keyword? (car o)))) (tilemap-objects layers)))

;;; ---------------------------------------------------------------- infinite maps
;; Chunks: ground (-4,-2) 4×2: row -2 all gid 1; (0,0) 4×2: "2,0,0,3 / 2,2,2,2".
;; overhang (zlib) chunk (4,-4) 4×2: row -4 = 0,0,4,4.
(define inf (load-tilemap (map-file "infinite.tmx")))
(test-equal "negative chunk" '(#t #t #t #t) (cells inf '((-4 . -2) (-3 . -2) (-2 . -2) (-1 . -2))))
(test-equal "gid 5 in the negative chunk" #f (tilemap-cell-solid? inf -2 -1))
(test-equal "chunk at the origin" '(#t #f #f #t #t #t #t #t)
  (cells inf '((0 . 0) (1 . 0) (2 . 0) (3 . 0) (0 . 1) (1 . 1) (2 . 1) (3 . 1))))
(test-equal "zlib chunk: gid 4" '(#f #f #t #t) (cells inf '((4 . -4) (5 . -4) (6 . -4) (7 . -4))))
(test-equal "between chunks" #f (tilemap-cell-solid? inf 5 0))
(test-equal "far away" #f (tilemap-cell-solid? inf 100 100))
;; Columns -4 … 7 and rows -4 … 1 can hold solid cells.
(test-equal "solid extent of an infinite map" '(-4 -4 12 6) (tilemap-solid-extent inf))
(test-assert (mentions? (error-text (lambda () (tilemap-solid-extent 'map))) "tilemap-solid-extent"))

;;; ---------------------------------------------------------------- make-tilemap
(define mv (make-tilemap 3 2 8 8 #(0 1 0 2 0 3) '(1 2)))
(test-assert (tilemap? mv))
(test-equal '(3 2 8 8) (list (tilemap-width mv) (tilemap-height mv) (tilemap-tile-width mv) (tilemap-tile-height mv)))
(test-equal "vector cells" '((#f #t #f) (#t #f #f)) (solid-grid mv))
(test-equal "solid extent of a made map" '(0 0 3 2) (tilemap-solid-extent mv))
;; Issue 51: a map with no tile layers has no solid block (not one of
;; 0 × 0 cells at the origin); the native step and the reference both take
;; it as a map where nothing is solid.
(define objects-only (load-tilemap (map-file "scheme/objects_only.tmx")))
(test-equal "no tile layers: no solid extent" #f (tilemap-solid-extent objects-only))
(let* ((body '(#:x 8 #:y 8 #:vx 3 #:vy 2 #:width 4 #:height 4 #:gravity? #t))
       (scene (make-scene #:entities (list body) #:tilemap objects-only))
       (moved (lambda (step) (car (scene-entities (step scene 16))))))
  (test-equal "… a body crosses it untouched, natively and in the reference"
    '((11 11) (11 11))  ; x 8 + vx 3; y 8 + vy 2 + the default gravity's 1
    (map (lambda (step) (let ((e (moved step))) (list (entity-ref e #:x) (entity-ref e #:y))))
         (list step-scene reference-step-scene))))
(define ml (make-tilemap 3 2 8 8 '(0 1 0 2 0 3) '(1 2)))
(test-equal "list cells" '((#f #t #f) (#t #f #f)) (solid-grid ml))
(test-equal "no solid gids: nothing solid" '((#f #f #f) (#f #f #f))
  (solid-grid (make-tilemap 3 2 8 8 #(0 1 0 2 0 3) '())))
(test-equal "gid 3 marked" '((#f #f #f) (#f #f #t)) (solid-grid (make-tilemap 3 2 8 8 #(0 1 0 2 0 3) '(3))))
(test-equal "no objects" '() (tilemap-objects mv))
(test-equal "made maps drive the physics: 8 px tiles; box [2, 10) → columns 0..1 → x = 8·1 − 8 = 0"
  '(#:x 0 #:y 0 #:width 8 #:height 8 #:vx 0)
  (resolve-tile-collisions-x '(#:x 2 #:y 0 #:width 8 #:height 8 #:vx 2) (make-scene tilemap: mv) 16))
(test-equal #f (tilemap? 'map))
(test-equal #f (tilemap? #(0 1)))

;;; ---------------------------------------------------------------- what else a map holds
;; tests/data/maps/scheme/features.tmx: every kind of property, layer, object
;; and tileset field the accessors report (the file says what each is).
(define features (load-tilemap (map-file "scheme/features.tmx")))
(define (scheme-file name) (string-append data "/maps/scheme/" name))
(test-equal "map properties: every Tiled type; a class is a plist, a list a list"
  '(#:title "Cave" #:gravity 0.25 #:scale 2 #:lives 3 #:dark #t #:fog "#80ff0000"
    #:music "../music/cave.ogg" #:boss 8 #:difficulty "hard"
    #:spawn (#:at (#:x 4 #:y 1.5) #:count 2) #:waves (1 "two" #f (0.5 ()) (#:x 7)))
  (tilemap-properties features))
(test-equal "a map without properties" '() (tilemap-properties level1))
(test-equal "a map made in memory has no properties, layers, tilesets or warnings" '(() () () ())
  (list (tilemap-properties mv) (tilemap-layers mv) (tilemap-tilesets mv) (tilemap-warnings mv)))

(define feature-objects (tilemap-objects features))
(define (feature-object name) (object-named features name))
(test-equal "a custom property spelled like a built-in key is prefixed, again while taken"
  '(#:type crate #:name "box" #:id 1 #:x 0 #:y 0 #:width 16 #:height 16 #:layer "things"
    #:property-name "Boxy" #:property-property-name "p" #:property-gid 7 #:weight 2.5)
  (feature-object "box"))
(test-equal "ellipse"
  '(#:type #f #:name "ring" #:id 2 #:x 16 #:y 0 #:width 8 #:height 8 #:layer "things" #:shape ellipse)
  (feature-object "ring"))
(test-equal "point"
  '(#:type #f #:name "spot" #:id 3 #:x 4 #:y 4 #:width 0 #:height 0 #:layer "things" #:shape point)
  (feature-object "spot"))
(test-equal "polygon: relative points, rotation"
  '(#:type #f #:name "tri" #:id 4 #:x 10 #:y 20 #:width 0 #:height 0 #:layer "things"
    #:shape polygon #:points ((0 . 0) (8 . 0) (4 . -6.5)) #:rotation 45)
  (feature-object "tri"))
(test-equal "polyline, hidden"
  '(#:type #f #:name "path" #:id 5 #:x 0 #:y 30 #:width 0 #:height 0 #:layer "things"
    #:shape polyline #:points ((0 . 0) (10 . 5)) #:visible? #f)
  (feature-object "path"))
(test-equal "text: its text and every attribute"
  '(#:type #f #:name "sign" #:id 6 #:x 0 #:y 24 #:width 48 #:height 16 #:layer "things" #:shape text
    #:text (#:text "Hello" #:font-family "serif" #:pixel-size 12 #:wrap? #t #:bold? #t #:italic? #f
            #:underline? #f #:strikeout? #f #:kerning? #t #:color "#ff336699" #:halign center
            #:valign bottom))
  (feature-object "sign"))
(test-equal "tile object: gid without the flip bits, and the flips"
  '(#:type #f #:name "barrel" #:id 7 #:x 32 #:y 32 #:width 24 #:height 32 #:layer "things"
    #:shape tile #:gid 9 #:flips (horizontal))
  (feature-object "barrel"))
(test-equal "template: its type, name, size and properties, the instance's position and its own hp"
  `(#:type enemy #:name "enemy" #:id 8 #:x 48 #:y 16 #:width 12 #:height 10 #:layer "things"
    #:template ,(scheme-file "tpl/enemy.tx") #:hp 5 #:speed 1.5)
  (feature-object "enemy"))
(test-equal "capsule (Tiled 1.12): its shape and box"
  '(#:type #f #:name "pill" #:id 9 #:x 40 #:y 0 #:width 8 #:height 20 #:layer "things" #:shape capsule)
  (feature-object "pill"))
(test-equal "objects in document order" '("box" "ring" "spot" "tri" "path" "sign" "barrel" "enemy" "pill")
  (map (lambda (o) (entity-ref o #:name)) feature-objects))

;; Element i, or () when there are fewer: a missing layer fails its own test only.
(define (nth l i) (if (> (length l) i) (list-ref l i) '()))
(define (head l n) (if (>= (length l) n) (list-head l n) l))
(define feature-layers (tilemap-layers features))
(test-equal "layers in file order, groups nested" '((tile "ground") (group "fore") (object "things"))
  (map (lambda (l) (list (entity-ref l #:kind) (entity-ref l #:name))) feature-layers))
(test-equal "a tile layer"
  '(#:kind tile #:name "ground" #:id 1 #:type #f #:visible? #t #:opacity 1 #:offset-x 0 #:offset-y 0
    #:parallax-x 1 #:parallax-y 1 #:tint #f #:properties () #:layer 0)
  (nth feature-layers 0))
(let ((group (nth feature-layers 1)))
  (test-equal "a group: its own attributes"
    '(#:kind group #:name "fore" #:id 2 #:type #f #:visible? #t #:opacity 0.5 #:offset-x 4 #:offset-y -2
      #:parallax-x 1 #:parallax-y 1 #:tint #f #:properties (#:depth 2))
    (head group 24))
  (test-equal "a hidden, tinted tile layer in the group: its own values, its number"
    '(#:kind tile #:name "deco" #:id 3 #:type #f #:visible? #f #:opacity 0.5 #:offset-x 0 #:offset-y 0
      #:parallax-x 0.5 #:parallax-y 1 #:tint "#ff00ff00" #:properties () #:layer 1)
    (nth (entity-ref group #:layers '()) 0))
  (test-equal "an image layer: the path resolved against the map's folder"
    `(#:kind image #:name "sky" #:id 4 #:type #f #:visible? #t #:opacity 1 #:offset-x 1.5 #:offset-y 0
      #:parallax-x 1 #:parallax-y 1 #:tint #f #:properties () #:image ,(scheme-file "art/sky.png")
      #:image-width 320 #:image-height 240 #:repeat-x? #t #:repeat-y? #f)
    (nth (entity-ref group #:layers '()) 1)))
(test-equal "the #:layer of a tile layer is the one tilemap-gid reads" '(2 2)
  (list (tilemap-gid features 1 3 0) (tilemap-gid features 0 1 0)))
(test-equal "an object layer holds its objects" feature-objects (entity-ref (nth feature-layers 2) #:objects #f))
(test-equal "an object layer's other keys"
  '(#:kind object #:name "things" #:id 5 #:type #f #:visible? #t #:opacity 1 #:offset-x 0 #:offset-y 0
    #:parallax-x 1 #:parallax-y 1 #:tint #f #:properties ())
  (head (nth feature-layers 2) 24))

(define feature-tilesets (tilemap-tilesets features))
(test-equal "an external tileset: its image resolved against the .tsx's folder; animation frames"
  `(#:first-gid 1 #:name "anim" #:type terrain #:source "tsx/anim.tsx" #:tile-width 16 #:tile-height 16
    #:tile-count 8 #:columns 4 #:margin 2 #:spacing 1 #:image ,(scheme-file "tsx/../art/tiles.png")
    #:image-width 70 #:image-height 36 #:tile-offset (0 . 4) #:properties (#:kind "rock")
    #:tiles ((#:id 0 #:type #f #:properties (#:solid #t))
             (#:id 1 #:type water #:properties () #:animation ((1 . 100) (2 . 150)))))
  (first feature-tilesets))
(test-equal "a sparse image collection: no image of its own, one per tile"
  `(#:first-gid 9 #:name "props" #:type #f #:source #f #:tile-width 32 #:tile-height 32 #:tile-count 2
    #:columns 0 #:margin 0 #:spacing 0 #:image #f #:tile-offset (0 . 0) #:properties ()
    #:tiles ((#:id 0 #:type #f #:properties () #:image ,(scheme-file "props/barrel.png")
              #:image-width 24 #:image-height 32)
             (#:id 5 #:type lamp #:properties () #:image ,(scheme-file "props/lamp.png")
              #:image-width 8 #:image-height 32)))
  (second feature-tilesets))
(test-equal "a sparse image collection's tile 5 (gid 14) loads" 14 (tilemap-gid features 0 2 1))
(test-equal "collision shapes are reported"
  '(#:id 2 #:type platform #:properties () #:collision? #t)
  (third (entity-ref (first (tilemap-tilesets level1)) #:tiles)))
(test-equal "no warnings for a map Tiled has nothing to say about" '() (tilemap-warnings features))

;; features.tmj is the same map in Tiled's JSON format (naming the same .tsx
;; tileset and .tx template): every accessor gives the same values.
(define features-json (load-tilemap (map-file "scheme/features.tmj")))
(for-each
 (lambda (accessor name)
   (test-equal (string-append "JSON twin: " name) (accessor features) (accessor features-json)))
 (list tilemap-properties tilemap-objects tilemap-layers tilemap-tilesets tilemap-warnings
       tilemap-width tilemap-height tilemap-tile-width tilemap-tile-height)
 '("properties" "objects" "layers" "tilesets" "warnings" "width" "height" "tile width" "tile height"))
(test-equal "JSON twin: the same gids" 
  (map (lambda (c) (tilemap-gid features 0 c 1)) (iota 4))
  (map (lambda (c) (tilemap-gid features-json 0 c 1)) (iota 4)))
(test-assert "JSON twin: not an empty map" (pair? (tilemap-objects features-json)))

;; game.tiled-project defines Spawn (at: Point, count 1, label "wave") and
;; Point (x 0, y 0, z 9): the members features.tmx leaves out are filled in.
(define project (scheme-file "game.tiled-project"))
(for-each
 (lambda (name)
   (test-equal (string-append name " with a project: the class's defaults filled in, nested too")
     '(#:at (#:x 4 #:y 1.5 #:z 9) #:count 2 #:label "wave")
     (entity-ref (tilemap-properties (load-tilemap (map-file (string-append "scheme/" name)) #:project project))
                 #:spawn)))
 '("features.tmx" "features.tmj"))
(test-assert "a missing project file: an error naming it"
  (mentions? (error-text (lambda () (load-tilemap (map-file "scheme/features.tmx")
                                                  #:project (scheme-file "none.tiled-project"))))
             "load-tilemap" "none.tiled-project" "cannot open project file"))

;;; ---------------------------------------------------------------- text in any encoding
;; latin1.tmx declares ISO-8859-1: its bytes E9 (é) and FC (ü) come back as
;; those characters. stray_byte.tmx has a byte FF in UTF-8 text on line 5.
(define (chars . codes) (list->string (map integer->char codes)))
(define latin1 (load-tilemap (map-file "scheme/latin1.tmx")))
(test-equal "ISO-8859-1 text: a property" (list #:title (chars 67 97 102 233)) (tilemap-properties latin1))
(test-equal "ISO-8859-1 text: a layer name" (chars 103 114 252 110) (entity-ref (car (tilemap-layers latin1)) #:name))
(test-equal "ISO-8859-1 text: an object name" (chars 77 252 108 108 101 114)
  (entity-ref (car (tilemap-objects latin1)) #:name))
(test-equal "a stray byte: an error naming the file, line and byte, not a decoding-error"
  (list 'misc-error (string-append "In procedure load-tilemap: " (map-file "scheme/stray_byte.tmx")
                                   ":5: byte 0xFF is not valid UTF-8\n"))
  (catch #t
    (lambda () (load-tilemap (map-file "scheme/stray_byte.tmx")))
    (lambda (key . args)
      (list key (call-with-output-string (lambda (port) (print-exception port #f key args)))))))

;;; ---------------------------------------------------------------- gids beyond every tileset
;; beyond.tmx: gid 7 at (1, 0) of layer "ground", beyond its 2-tile tileset.
(define beyond-output (open-output-string))
(define beyond
  (parameterize ((current-warning-port beyond-output))
    (load-tilemap (map-file "scheme/beyond.tmx"))))
(test-equal "loaded, the gid beyond as a non-solid cell" '(#t #f #t)
  (map (lambda (c) (tilemap-cell-solid? beyond c 0)) '(0 1 2)))
(test-equal "one warning, naming the map and line, the layer and the cell"
  (list (string-append (map-file "scheme/beyond.tmx")
                       ":14: gid 7 at cell (1, 0) of layer 'ground' is beyond every tileset; "
                       "loaded as a missing, non-solid tile"))
  (tilemap-warnings beyond))
(test-equal "the cell keeps its gid (drawn as a missing tile)" 7 (tilemap-gid beyond 0 1 0))
(test-equal "each warning is one line on the warning port"
  (string-append "load-tilemap: warning: " (car (tilemap-warnings beyond)) "\n")
  (get-output-string beyond-output))
(test-assert "#:strict? #t refuses it, naming the file, layer and cell"
  (mentions? (error-text (lambda () (load-tilemap (map-file "scheme/beyond.tmx") #:strict? #t)))
             "load-tilemap" "beyond.tmx" "ground" "beyond every tileset"))
(test-equal "#:strict? #f is the default" '() 
  (tilemap-warnings (load-tilemap "demo/maps/level1.tmx" #:strict? #t)))

;; A tileset file of {} (issue 45) loaded without a word; its gids were
;; silently missing.
(define nothing-output (open-output-string))
(define nothing-problem
  "tileset file 'says_nothing.tsj' says nothing (no tile size, no image, no tiles): its gids are missing, non-solid tiles")
(test-equal "a tileset file that says nothing is a warning naming the map and the file"
  (list (string-append (map-file "scheme/says_nothing.tmj") ": " nothing-problem))
  (tilemap-warnings (parameterize ((current-warning-port nothing-output))
                      (load-tilemap (map-file "scheme/says_nothing.tmj")))))
(test-equal "… on the warning port"
  (string-append "load-tilemap: warning: " (map-file "scheme/says_nothing.tmj") ": " nothing-problem "\n")
  (get-output-string nothing-output))
(test-equal "… and #:strict? #t refuses the map"
  (string-append "In procedure load-tilemap: " (map-file "scheme/says_nothing.tmj") ": " nothing-problem "\n")
  (error-text (lambda () (load-tilemap (map-file "scheme/says_nothing.tmj") #:strict? #t))))

;; A tileset whose picture is missing (issue 46): found when the map loads,
;; headless too, not only when a window first draws a tile of it.
(define no-image-output (open-output-string))
(define no-image-problem
  (string-append "tileset 'gone' (no-image.tsx): image '" (map-file "render/absent.png")
                 "' cannot be opened: No such file or directory"))
(test-equal "a missing tileset picture is a warning naming the map, the tileset and the file"
  (list (string-append (map-file "render/no-image.tmx") ": " no-image-problem "; its tiles cannot be drawn"))
  (tilemap-warnings (parameterize ((current-warning-port no-image-output))
                      (load-tilemap (map-file "render/no-image.tmx")))))
(test-equal "… on the warning port"
  (string-append "load-tilemap: warning: " (map-file "render/no-image.tmx") ": " no-image-problem
                 "; its tiles cannot be drawn\n")
  (get-output-string no-image-output))
(test-equal "… and #:strict? #t refuses the map"
  (string-append "In procedure load-tilemap: " (map-file "render/no-image.tmx") ": " no-image-problem "\n")
  (error-text (lambda () (load-tilemap (map-file "render/no-image.tmx") #:strict? #t))))

;;; ---------------------------------------------------------------- errors
(test-assert "missing file: the message names the file"
  (mentions? (error-text (lambda () (load-tilemap (map-file "no-such-map.tmx")))) "load-tilemap" "no-such-map.tmx"))
;; Issue 51: a native message arrives whole, however long, and a
;; character of several bytes is never cut in two.
(define long-path  ; 400 bytes: "missing/", 55 × "éé/é" (7 bytes each), "abc.tmx"
  (string-append "missing/" (string-concatenate (make-list 55 "éé/é")) "abc.tmx"))
(test-equal "the long path's length in bytes" 400 (bytevector-length (string->utf8 long-path)))
(test-equal "a 400-byte path with multibyte characters: the whole message"
  (string-append "In procedure load-tilemap: " long-path ": cannot open map: No such file or directory\n")
  (error-text (lambda () (load-tilemap long-path))))
(test-assert "malformed XML: file and line"
  (mentions? (error-text (lambda () (load-tilemap (map-file "bad/malformed.tmx")))) "malformed.tmx" ":5"))
(for-each
 (lambda (name)
   (test-assert (string-append name ": an error naming the file")
     (mentions? (error-text (lambda () (load-tilemap (map-file (string-append "bad/" name))))) name)))
 '("short_csv.tmx" "bad_encoding.tmx" "bad_compression.tmx" "missing_tsx.tmx" "empty.tmx"
   "no_map.tmx" "corrupt_zlib.tmx" "corrupt_gzip.tmx" "corrupt_zstd.tmx" "truncated_base64.tmx"
   "short_xml.tmx" "malformed_tsx.tmx" "isometric.tmx"))
(test-assert "a missing tileset names it"
  (mentions? (error-text (lambda () (load-tilemap (map-file "bad/missing_tsx.tmx")))) "missing.tsx"))
(test-assert "load-tilemap with a number"
  (mentions? (error-text (lambda () (load-tilemap 42))) "load-tilemap" "42"))
(test-error "solid-gids not a list" (load-tilemap "demo/maps/level1.tmx" solid-gids: 'four))
(test-error "solid-gids with a negative gid" (load-tilemap "demo/maps/level1.tmx" solid-gids: '(-1)))
(test-error "solid-gids with a string" (load-tilemap "demo/maps/level1.tmx" solid-gids: '("4")))
(test-assert "make-tilemap: wrong number of cells"
  (error-text (lambda () (make-tilemap 3 2 8 8 #(0 1 0 2 0) '()))))
(test-assert "make-tilemap: width 0"
  (mentions? (error-text (lambda () (make-tilemap 0 2 8 8 #() '()))) "make-tilemap" "width"))
(test-assert "make-tilemap: tile width a string"
  (mentions? (error-text (lambda () (make-tilemap 1 1 "8" 8 #(0) '()))) "make-tilemap" "tile-width"))
(test-assert "make-tilemap: a cell that is not a gid"
  (mentions? (error-text (lambda () (make-tilemap 2 1 8 8 #(0 a) '()))) "make-tilemap" "cells"))
(test-assert "make-tilemap: a negative cell in a list"
  (error-text (lambda () (make-tilemap 2 1 8 8 '(0 -1) '()))))
(test-assert "make-tilemap: cells neither vector nor list"
  (error-text (lambda () (make-tilemap 2 1 8 8 "00" '()))))
(test-assert "make-tilemap: solid-gids not a list"
  (error-text (lambda () (make-tilemap 2 1 8 8 #(0 0) 1))))
(test-error "make-tilemap: too few arguments" (make-tilemap 2 1 8 8 #(0 0)))
(test-assert "tilemap-cell-solid? on a non-tilemap"
  (mentions? (error-text (lambda () (tilemap-cell-solid? 'level 0 0))) "tilemap-cell-solid?" "level"))
(test-assert "tilemap-cell-solid? with a flonum index"
  (error-text (lambda () (tilemap-cell-solid? mv 1.5 0))))
(test-assert "the refusal names the index, col or row"
  (and (mentions? (error-text (lambda () (tilemap-cell-solid? mv 1.5 0))) "col: " "1.5")
       (mentions? (error-text (lambda () (tilemap-gid mv 0 0 'r))) "tilemap-gid" "row: " "r")))
(test-assert "tilemap-width on a non-tilemap"
  (mentions? (error-text (lambda () (tilemap-width "map"))) "tilemap-width"))
(test-assert "tilemap-objects on a non-tilemap" (error-text (lambda () (tilemap-objects #f))))

(for-each
 (lambda (proc name)
   (test-assert (string-append name " on a non-tilemap names itself and the value")
     (mentions? (error-text (lambda () (proc 'level))) name "level")))
 (list tilemap-properties tilemap-layers tilemap-tilesets tilemap-warnings tilemap-objects)
 '("tilemap-properties" "tilemap-layers" "tilemap-tilesets" "tilemap-warnings" "tilemap-objects"))
(test-assert "load-tilemap: strict? not a boolean"
  (mentions? (error-text (lambda () (load-tilemap "demo/maps/level1.tmx" #:strict? 'yes))) "load-tilemap" "strict?" "yes"))
(test-assert "load-tilemap: project not a file name"
  (mentions? (error-text (lambda () (load-tilemap "demo/maps/level1.tmx" #:project 42))) "load-tilemap" "project" "42"))

;;; Shapes (semantics §12): make-tilemap's shapes, tilemap-cell-shape,
;;; tilemap-steepest-ramp, and the queries by shape.
(define (shaped . shapes) (make-tilemap 2 1 16 16 #(1 2) '(1) '() shapes))
(define ramp45 '(2 . (polygon (0 . 16) (16 . 16) (16 . 0))))
(test-equal "tilemap-cell-shape: whole, shaped, empty"
  (list 'solid #(0 0 16 16 floor 0 16 16 0 #f) #f)
  (let ((m (shaped ramp45))) (list (tilemap-cell-shape m 0 0) (tilemap-cell-shape m 1 0) (tilemap-cell-shape m 5 5))))
(test-equal "a one-way ramp" #(0 8 16 16 box 0 0 0 0 #t)
  (tilemap-cell-shape (make-tilemap 1 1 16 16 #(2) '() '(2) '((2 . (rect 0 8 16 8)))) 0 0))
(test-equal "tilemap-steepest-ramp: 1.0, and 0.0 without ramps" '(1.0 0.0)
  (list (tilemap-steepest-ramp (shaped ramp45)) (tilemap-steepest-ramp (shaped))))
(test-equal "tilemap-solid-at? by shape: above the slope, under it" '(#f #t)
  (let ((m (shaped ramp45))) (list (tilemap-solid-at? m 20 4) (tilemap-solid-at? m 28 12))))
;; A convex polygon cut by several slants on one side (§12): a house, 8 px
;; walls under a 45° roof peaking at (8, 0); in cell (1, 0) of this map its
;; roof is y = 24 − x up to (24, 0), then x − 24.
(define house '(2 . (polygon (0 . 16) (0 . 8) (8 . 0) (16 . 8) (16 . 16))))
(define house-map (make-tilemap 3 2 16 16 #(0 2 0 1 1 1) '(1) '() (list house)))
(test-equal "tilemap-cell-shape: a polygon cut by two slants has their list in an 11th slot"
  '(#(0 0 16 16 floor 0 8 8 0 #f ((8 0 16 8))) #(0 0 16 16 ceiling 0 8 8 16 #f ((8 16 16 8))) 1.0)
  (list (tilemap-cell-shape house-map 1 0)
        (tilemap-cell-shape (make-tilemap 1 1 16 16 #(#x40000002) '() '() (list house)) 0 0)
        (tilemap-steepest-ramp house-map)))
(test-equal "tilemap-solid-at? by a roof: at the peak, beside it above the slope" '(#t #f #t)
  (list (tilemap-solid-at? house-map 24 0) (tilemap-solid-at? house-map 19 4) (tilemap-solid-at? house-map 19 6)))
;; Falling 8 × 8 bodies land on the roof where it is highest under them:
;; over [20, 28) the peak (feet 0), over [14, 22) the left slope at 22 (2),
;; over [27, 35) the right slope at 27 (3); natively and in the reference.
(for-each
 (lambda (step name)
   (let ((landed (map (lambda (x)
                        (let loop ((s (make-scene #:entities (list (list #:x x #:y -40 #:width 8 #:height 8 #:gravity? #t))
                                                  #:tilemap house-map))
                                   (i 0))
                          (if (= i 30)
                              (let ((e (car (scene-entities s))))
                                (list (entity-ref e #:y) (entity-ref e #:on-ground?)))
                              (loop (step s 16) (+ i 1)))))
                      '(20 14 27))))
     (test-equal (string-append name ": bodies land on a roof's peak and slopes")
       '((-8 #t) (-6 #t) (-5 #t)) landed)))
 (list step-scene reference-step-scene) '("native" "reference"))
;; A convex polygon slanted on its top and its underside (§12): a diamond,
;; in cell (1, 0) its top y = 24 − x up to (24, 0), then x − 24, its
;; underside y = x − 8 down to (24, 16), then 40 − x, its sides meeting at
;; (16, 8) and (32, 8).
(define diamond '(2 . (polygon (8 . 0) (16 . 8) (8 . 16) (0 . 8))))
(define diamond-map (make-tilemap 3 2 16 16 #(0 2 0 0 0 0) '() '() (list diamond)))
(test-equal "tilemap-cell-shape: a polygon slanted on both sides is a floor shape with its underside in a 12th slot"
  '#(0 0 16 16 floor 0 8 8 0 #f ((8 0 16 8)) ((0 8 8 16) (8 16 16 8)))
  (tilemap-cell-shape diamond-map 1 0))
(test-equal "tilemap-solid-at? by a diamond: its top vertex, above its top, below its underside, its inside"
  '(#t #f #f #t)
  (list (tilemap-solid-at? diamond-map 24 0) (tilemap-solid-at? diamond-map 19 4)
        (tilemap-solid-at? diamond-map 19 12) (tilemap-solid-at? diamond-map 19 8)))
;; Natively and in the reference: 8 × 8 bodies falling onto it land where
;; its top is highest under them (over [20, 28) the vertex, over [14, 22)
;; 2, over [27, 35) 3); rising into it, they stop where its underside is
;; lowest (16, then 14, then 13); an 8 × 16 body walking right at y 0 stops
;; against its side vertex (16, 8).
(define (run-diamond step entity frames)
  (let loop ((s (make-scene #:entities (list entity) #:tilemap diamond-map)) (i 0))
    (if (= i frames)
        (let ((e (car (scene-entities s)))) (list (entity-ref e #:x) (entity-ref e #:y)))
        (loop (step s 16) (+ i 1)))))
(for-each
 (lambda (step name)
   (test-equal (string-append name ": bodies land on a diamond's top, bump its underside, stop at its side")
     '((20 -8) (14 -6) (27 -5) (20 16) (14 14) (27 13) (8 0))
     (append
      (map (lambda (x) (run-diamond step (list #:x x #:y -40 #:width 8 #:height 8 #:gravity? #t) 30)) '(20 14 27))
      (map (lambda (x) (run-diamond step (list #:x x #:y 40 #:width 8 #:height 8 #:vy -2) 30)) '(20 14 27))
      (list (run-diamond step (list #:x 0 #:y 0 #:width 8 #:height 16 #:vx 2) 10)))))
 (list step-scene reference-step-scene) '("native" "reference"))
(test-equal "make-tilemap: a polygon that is not convex"
  "In procedure make-tilemap: shapes: the shape of gid 1: the collision polygon is not convex\n"
  (error-text (lambda () (make-tilemap 1 1 16 16 #(1) '() '()
                                       '((1 . (polygon (0 . 16) (16 . 16) (16 . 0) (8 . 8) (0 . 8))))))))
(test-equal "make-tilemap: a polygon of 2 points"
  "In procedure make-tilemap: shapes: the shape of gid 1: a collision polygon of 2 points (3 at least make a shape)\n"
  (error-text (lambda () (make-tilemap 1 1 16 16 #(1) '() '() '((1 . (polygon (0 . 0) (1 . 1))))))))
(test-equal "make-tilemap: a polygon of more points than a shape may have (a million: refused at once)"
  "In procedure make-tilemap: shapes: the shape of gid 1: a collision polygon of 1000000 points, more than the 256 a shape may have\n"
  (error-text (lambda () (make-tilemap 1 1 16 16 #(1) '() '()
                                       `((1 . (polygon ,@(map (lambda (i) (cons (modulo i 17) 16)) (iota 1000000)))))))))
(test-equal "make-tilemap: a point more than a tile outside the tile"
  "In procedure make-tilemap: shapes: the shape of gid 1: collision point (33, 16) lies more than a tile outside the 16x16 tile\n"
  (error-text (lambda () (make-tilemap 1 1 16 16 #(1) '() '() '((1 . (polygon (0 . 16) (33 . 16) (33 . 0))))))))
(test-equal "make-tilemap: a polygon reaching past the tile is its part inside"
  #(0 5 16 16 floor 0 16 24 0 #f)
  (tilemap-cell-shape (make-tilemap 1 1 16 16 #(1) '() '() '((1 . (polygon (0 . 16) (24 . 16) (24 . 0))))) 0 0))
(test-equal "make-tilemap: a rectangle with no area"
  "In procedure make-tilemap: shapes: the shape of gid 1: a collision rectangle of (16, 0) px has no area\n"
  (error-text (lambda () (make-tilemap 1 1 16 16 #(1) '() '() '((1 . (rect 0 4 16 0)))))))
(test-equal "make-tilemap: NaN in a shape"
  "In procedure make-tilemap: shapes: expected (gid . (rect x y w h)) or (gid . (polygon (x . y) ...)) with finite numbers, got (1 polygon (0 . 0) (1 . +nan.0) (4 . 4))\n"
  (error-text (lambda () (make-tilemap 1 1 16 16 #(1) '() '() '((1 . (polygon (0 . 0) (1 . +nan.0) (4 . 4))))))))
(test-equal "make-tilemap: shapes not a list"
  "In procedure make-tilemap: shapes: expected a list of (gid . shape), got oops\n"
  (error-text (lambda () (make-tilemap 1 1 16 16 #(1) '() '() 'oops))))
(test-equal "make-tilemap: a circular list of shapes"
  #t
  (let ((l (list ramp45 ramp45))) (set-cdr! (cdr l) l)
    (mentions? (error-text (lambda () (make-tilemap 1 1 16 16 #(1) '() '() l))) "make-tilemap" "shapes")))
(test-equal "tilemap-cell-shape: not a map, not a cell"
  '("In procedure tilemap-cell-shape: expected a tilemap, got map\n"
    "In procedure tilemap-cell-shape: col: expected an exact integer cell index, got 0.5\n")
  (list (error-text (lambda () (tilemap-cell-shape 'map 0 0)))
        (error-text (lambda () (tilemap-cell-shape (shaped) 0.5 0)))))

(test-end "tilemap")
