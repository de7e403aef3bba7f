;; SPDX-License-Identifier: MIT
;;; Drawing through the game API: frames captured off-screen (no display) and
;;; read back pixel by pixel against colours computed here from the test
;;; sheet's definition (tests/data/maps/render/make_render_maps.py), the
;;; draw-* procedures, the overlay, `downstroke --capture', input maps and
;;; logs, and sounds.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke) (ice-9 ftw) (ice-9 rdelim)
             (rnrs bytevectors) (ice-9 binary-ports) (ice-9 popen) (ice-9 textual-ports))

(load "support.scm")

(define data (getenv "DS_TEST_DATA"))
(define render-map (string-append data "/maps/render/render.tmx"))
(define host (readlink "/proc/self/exe"))
(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-render-XXXXXX")))

;; The sheet: tile t's pixel (u, v), as make_render_maps.py paints it.
(define (sheet t u v) (list (+ 40 (* 50 t)) (+ 20 (* 25 u)) (+ 10 (* 30 v)) 255))
;; Where Tiled puts source pixel (x, y) of an 8 × 8 tile under the flips:
;; diagonal swaps the axes first, then horizontal and vertical mirror.
(define (forward x y h? v? d?)
  (let* ((xy (if d? (cons y x) (cons x y)))
         (x (if h? (- 7 (car xy)) (car xy)))
         (y (if v? (- 7 (cdr xy)) (cdr xy))))
    (cons x y)))
(define background '(24 28 40 255))

(define (tile-drawn? game left top t h? v? d?)
  ;; Every pixel of tile T, turned, at (LEFT, TOP) of the last frame.
  (every (lambda (y)
           (every (lambda (x)
                    (let ((p (forward x y h? v? d?)))
                      (equal? (sheet t x y) (game-pixel game (+ left (car p)) (+ top (cdr p))))))
                  (iota 8)))
         (iota 8)))

(define (capture-of game)
  (let ((file (string-append dir "/frame.png")))
    (game-capture game file)
    file))

(define (png-size file)
  ;; Width and height from the IHDR chunk (big-endian, bytes 16–23).
  (let ((bv (call-with-input-file file get-bytevector-all #:binary #t)))
    (list (bytevector-u32-ref bv 16 (endianness big)) (bytevector-u32-ref bv 20 (endianness big)))))

(test-begin "render")

(test-assert "this build has the renderer" (renderer-available?))

;;; ---------------------------------------------------------------- the map
(define level (load-tilemap render-map))
(define (map-game . scene-args)
  (make-game width: 48 height: 32 scene: (apply make-scene tilemap: level scene-args)))

(define g (map-game))
(define first-capture (capture-of g))
(test-equal "a capture is exactly the game's width × height" '(48 32) (png-size first-capture))
(test-assert "tile 1 (gid 2) unflipped at cell (0, 0)" (tile-drawn? g 0 0 1 #f #f #f))
(test-assert "horizontal flip at cell (1, 0)" (tile-drawn? g 8 0 1 #t #f #f))
(test-assert "vertical flip at cell (2, 0)" (tile-drawn? g 16 0 1 #f #t #f))
(test-assert "diagonal flip at cell (3, 0)" (tile-drawn? g 24 0 1 #f #f #t))
(test-assert "horizontal and vertical at cell (4, 0)" (tile-drawn? g 32 0 1 #t #t #f))
(test-assert "diagonal and horizontal at cell (5, 0)" (tile-drawn? g 40 0 1 #t #f #t))
(test-assert "gid 3 at cell (0, 1)" (tile-drawn? g 0 8 2 #f #f #f))
(test-assert "the floor, gid 1, along row 3" (every (lambda (c) (tile-drawn? g (* 8 c) 24 0 #f #f #f)) (iota 6)))
(test-equal "an empty cell shows the background" background (game-pixel g 12 12))

(define moved (map-game camera: (make-camera x: 5 y: 3)))
(capture-of moved)
(test-assert "the camera shifts the map: cell (5, 1)'s gid 4 moves by (−5, −3)"
  (tile-drawn? moved (- 40 5) (- 8 3) 3 #f #f #f))
(test-equal "… and pixel (0, 0) shows world pixel (5, 3), in cell (0, 0)'s gid 2" (sheet 1 5 3) (game-pixel moved 0 0))

;;; ---------------------------------------------------------------- sprites and physics
;;; A box with a sprite falls onto the floor (row 3, y 24): wherever physics
;;; put it, its picture is there.
(define faller (make-game width: 48 height: 32
                          scene: (make-scene tilemap: level
                                             entities: (list (list #:id 'box #:x 20 #:y 8 #:width 8 #:height 8
                                                                   #:gravity? #t #:sprite 4)))))
(game-run! faller frames: 12)
(define box (car (scene-entities (game-scene faller))))
(capture-of faller)
(test-assert "the sprite is drawn where physics left the entity"
  (tile-drawn? faller (inexact->exact (floor (entity-ref box #:x)))
               (inexact->exact (floor (entity-ref box #:y))) 3 #f #f #f))
(test-equal "… resting on the floor" 16 (entity-ref box #:y))
(define flipped (make-game width: 48 height: 32
                           scene: (make-scene entities: (list '(#:x 0 #:y 0 #:width 8 #:height 8 #:sprite 2 #:flip-x? #t))
                                              tilemap: level)))
(capture-of flipped)
(test-assert "#:flip-x? mirrors the sprite" (tile-drawn? flipped 0 0 1 #t #f #f))

(define render-row (assq 'render (engine-stats faller)))
(test-assert "engine-stats: the render row counts what was drawn" (> (cadr render-row) 0))
(test-assert "… and its time" (>= (cadddr render-row) 0))

;;; ---------------------------------------------------------------- boxes and the overlay
(define solid-green '(80 220 100 255))
(define immovable-blue '(80 150 255 255))
(define velocity-yellow '(255 240 120 255))
(define boxes (make-game width: 48 height: 32
                         scene: (make-scene entities: (list '(#:x 2 #:y 2 #:width 10 #:height 10 #:solid? #t #:vx 2)
                                                            '(#:x 30 #:y 2 #:width 10 #:height 10 #:solid? #t #:immovable? #t)))))
(capture-of boxes)
(test-equal "an entity without a sprite or #:color draws nothing" background (game-pixel boxes 2 2))
(test-equal "… nor inside" background (game-pixel boxes 33 5))
(game-debug-draw-set! boxes #t)
(capture-of boxes)
(test-equal "the overlay outlines it in its role's colour: solid" solid-green (game-pixel boxes 2 2))
(test-equal "… immovable" immovable-blue (game-pixel boxes 30 2))
(game-debug-draw-set! boxes #f)
(define coloured (make-game width: 16 height: 8
                            scene: (make-scene entities: (list '(#:x 1 #:y 1 #:width 3 #:height 2 #:color (200 40 60))
                                                               '(#:x 8 #:y 0 #:width 2 #:height 2 #:color (0 100 200 128))))))
(capture-of coloured)
(test-equal "#:color fills the entity's box: every pixel of it, and none beside"
  '((200 40 60 255) (200 40 60 255) (200 40 60 255) (24 28 40 255) (24 28 40 255) (24 28 40 255))
  (map (lambda (xy) (game-pixel coloured (car xy) (cdr xy))) '((1 . 1) (3 . 2) (2 . 1) (4 . 1) (1 . 3) (0 . 1))))
;; Alpha 128 blends: c × 128/255 + background × 127/255, rounded.
(test-equal "… blended by its alpha"
  (append (map (lambda (c b) (inexact->exact (round (/ (+ (* c 128) (* b 127)) 255)))) '(0 100 200) '(24 28 40)) '(255))
  (game-pixel coloured 8 0))
(define named (make-game width: 8 height: 8
                         scene: (make-scene entities: (list '(#:x 0 #:y 0 #:width 2 #:height 2 #:color red)
                                                            '(#:x 4 #:y 0 #:width 2 #:height 2 #:color gray)))))
(capture-of named)
(test-equal "#:color takes the drawing procedures' colour names: red, gray"
  '((230 60 60 255) (150 150 150 255))
  (list (game-pixel named 1 1) (game-pixel named 5 1)))
(test-assert "a bad #:color is named by game-draw with its value, and the names it could be"
  (mentions? (error-text (lambda () (game-capture (make-game width: 8 height: 8
                                                             scene: (make-scene entities: (list '(#:x 0 #:y 0 #:width 1 #:height 1 #:color redd))))
                                                  (string-append dir "/x.png"))))
             "game-draw" "#:color" "redd" "white black red green blue yellow cyan magenta orange grey gray"))
(game-debug-draw-set! boxes #t)
(test-assert "game-debug-draw? follows the setter" (game-debug-draw? boxes))
(capture-of boxes)
;; Centre (7, 7); velocity (2, 0) drawn 4 frames long: to (15, 7).
(test-equal "the overlay draws the velocity" velocity-yellow (game-pixel boxes 15 7))
(game-debug-draw-set! boxes #f)

;;; Pushed pairs: two overlapping solid boxes are pushed apart in a frame;
;;; the overlay joins their centres in red.
(define pushed (make-game width: 48 height: 32
                          scene: (make-scene entities: (list '(#:id a #:x 10 #:y 10 #:width 8 #:height 8 #:solid? #t)
                                                             '(#:id b #:x 14 #:y 10 #:width 8 #:height 8 #:solid? #t)))))
(game-debug-draw-set! pushed #t)
(game-run! pushed frames: 1)
(capture-of pushed)
(define a1 (first (scene-entities (game-scene pushed))))
(define b1 (second (scene-entities (game-scene pushed))))
(test-equal "the pair was pushed apart" '(8 16) (list (entity-ref a1 #:x) (entity-ref b1 #:x)))
(test-equal "… and the overlay joins their centres" '(255 70 70 255) (game-pixel pushed 16 14))

;;; Trails: with history:, the overlay draws where each entity has been.
(define trail-game (make-game width: 48 height: 32 history: 30
                              scene: (make-scene entities: (list '(#:id m #:x 0 #:y 20 #:width 2 #:height 2 #:vx 1)))))
(game-run! trail-game frames: 20)
(game-debug-draw-set! trail-game #t)
(capture-of trail-game)
(test-equal "a trail runs through the old centres" '(120 230 255 255) (game-pixel trail-game 5 21))

;;; ---------------------------------------------------------------- draw-*
(define hud (make-game width: 32 height: 32
                       scene: (make-scene camera: (make-camera x: 10 y: 10))
                       render: (lambda (game)
                                 (draw-rect 12 12 4 4 '(255 0 0) fill?: #t)
                                 (draw-rect 0 0 2 2 'blue fill?: #t space: 'screen)
                                 (draw-line 0 31 31 31 '(0 255 0 255) space: 'screen)
                                 (draw-sprite 3 20 0 space: 'screen)
                                 (draw-text "A" 0 10 'white space: 'screen))))
(game-run! hud frames: 1)
(capture-of hud)
(test-equal "draw-rect in world space moves with the camera" '(255 0 0 255) (game-pixel hud 2 2))
(test-equal "… in screen space it does not" '(80 150 255 255) (game-pixel hud 0 0))
(test-equal "draw-line, both ends included" '((0 255 0 255) (0 255 0 255))
  (list (game-pixel hud 0 31) (game-pixel hud 31 31)))
(test-equal "draw-sprite without a map draws nothing" background (game-pixel hud 20 0))
(test-equal "draw-text: the top of A" '(255 255 255 255) (game-pixel hud 1 10))
(define sprite-hud (make-game width: 16 height: 16 scene: (make-scene tilemap: level)
                              render: (lambda (game) (draw-sprite 4 8 8 space: 'screen flip-x?: #t))))
(game-run! sprite-hud frames: 1)
(capture-of sprite-hud)
(test-assert "draw-sprite draws a gid of the scene's map, flipped" (tile-drawn? sprite-hud 8 8 3 #t #f #f))

(define labelled (make-game width: 32 height: 16 render: (lambda (game) (draw-label "A" 4 4 'yellow))))
(game-run! labelled frames: 1)
(capture-of labelled)
(test-equal "draw-label: its plate blends (22 17 31) at alpha 150 over the background"
  '(23 22 35 255) (game-pixel labelled 2 2))
(test-equal "… the text in its colour (A's top row)" '(250 220 70 255) (game-pixel labelled 5 4))
(test-equal "… nothing past the plate" background (game-pixel labelled 14 4))
(test-equal "text-width: 6 px a letter of the longest line" '(42 12 84) (list (text-width "SCORE 3") (text-width "AB\nC") (text-width "SCORE 3" #:scale 2)))

(test-assert "draw-rect outside a game's drawing names itself"
  (mentions? (error-text (lambda () (draw-rect 0 0 1 1))) "draw-rect" "render:"))
(define (error-in-render proc)
  (let ((game (make-game width: 8 height: 8 render: (lambda (game) (proc)))))
    (error-text (lambda () (game-run! game frames: 1)))))
(test-assert "a bad colour is named"
  (mentions? (error-in-render (lambda () (draw-rect 0 0 1 1 '(300 0 0)))) "draw-rect" "color" "(300 0 0)"))
(test-assert "an unknown colour name is named"
  (mentions? (error-in-render (lambda () (draw-line 0 0 1 1 'mauve))) "draw-line" "mauve"))
(test-assert "a bad space is named"
  (mentions? (error-in-render (lambda () (draw-text "x" 0 0 'white space: 'hud))) "draw-text" "space" "hud"))
(test-assert "NaN coordinates are refused"
  (mentions? (error-in-render (lambda () (draw-rect +nan.0 0 1 1))) "draw-rect" "x" "+nan.0"))
(test-assert "a bad sprite gid is named"
  (mentions? (error-in-render (lambda () (draw-sprite -1 0 0))) "draw-sprite" "gid" "-1"))

;;; ---------------------------------------------------------------- sprites that act like sprites
;; The game is 96 px wide and the map 48: from x 48 on, only the background
;; is under the entities. Expected pixels come from the sheet's definition:
;; tile T's pixel (u, v) is (sheet T u v).
(define (sprite-game . entities)
  (let ((game (make-game width: 96 height: 32 scene: (make-scene tilemap: level entities: entities))))
    (capture-of game)
    game))
(define (pixels game left top w h)
  (append-map (lambda (y) (map (lambda (x) (game-pixel game (+ left x) (+ top y))) (iota w))) (iota h)))
(define (all-background? game left top w h)
  (every (lambda (p) (equal? p background)) (pixels game left top w h)))

(test-assert "an entity with a sprite is drawn …"
  (tile-drawn? (sprite-game '(#:x 48 #:y 0 #:width 8 #:height 8 #:sprite 2)) 48 0 1 #f #f #f))
(define hidden-game (sprite-game '(#:x 48 #:y 0 #:width 8 #:height 8 #:sprite 2 #:visible? #f)
                                 '(#:x 56 #:y 0 #:width 8 #:height 8)
                                 '(#:x 64 #:y 0 #:width 8 #:height 8 #:sprite 2)))
(test-assert "… and #:visible? #f hides it" (all-background? hidden-game 48 0 8 8))
(test-equal "engine-stats counts the hidden one and the one with nothing to draw as not drawn" 2
  (caddr (assq 'render (engine-stats hidden-game))))
(define offset-game (sprite-game '(#:x 48 #:y 0 #:width 8 #:height 8 #:sprite 2 #:sprite-offset (5 . 3))))
(test-assert "#:sprite-offset (5 . 3) moves the picture by exactly 5 right and 3 down" (tile-drawn? offset-game 53 3 1 #f #f #f))
(test-assert "… leaving no pixel where it stood" (all-background? offset-game 48 0 5 3))
(test-equal "… and the body where it was" '(48 0)
  (let ((e (car (scene-entities (game-scene offset-game))))) (list (entity-ref e #:x) (entity-ref e #:y))))
;; Unscaled, the sprite would cover (60..67, 8..15); scaled 2 it keeps its
;; bottom-centre (64, 16): 16 × 16 px from (56, 0), each sheet pixel 2 × 2.
(test-equal "#:sprite-scale 2 doubles the picture about its bottom-centre"
  (append-map (lambda (y) (map (lambda (x) (sheet 1 (quotient x 2) (quotient y 2))) (iota 16))) (iota 16))
  (pixels (sprite-game '(#:x 60 #:y 8 #:width 8 #:height 8 #:sprite 2 #:sprite-scale 2)) 56 0 16 16))
(test-equal "#:sprite-scale (2 . 1) doubles only its width"
  (append-map (lambda (y) (map (lambda (x) (sheet 1 (quotient x 2) y)) (iota 16))) (iota 8))
  (pixels (sprite-game '(#:x 60 #:y 0 #:width 8 #:height 8 #:sprite 2 #:sprite-scale (2 . 1))) 56 0 16 8))
;; Turned 90° clockwise (y down) about its centre (52, 20): the offset (a, b)
;; from the centre goes to (−b, a), so pixel (u, v) lands on (48 + 7 − v, 16 + u).
(test-equal "#:rotation 90 turns the picture clockwise about its centre"
  (append-map (lambda (y) (map (lambda (x) (sheet 1 y (- 7 x))) (iota 8))) (iota 8))
  (pixels (sprite-game '(#:x 48 #:y 16 #:width 8 #:height 8 #:sprite 2 #:rotation 90)) 48 16 8 8))

;; Two enemies play the same animation, gid 2 then gid 3, 100 ms each, one
;; from frame 0 and one from frame 7: at 16 ms a frame, frame 10 is 160 ms
;; into the first's (gid 3) and 48 ms into the second's (gid 2).
(define walk '((2 . 100) (3 . 100)))
(define animated
  (make-game width: 96 height: 32 history: 30
             scene: (make-scene tilemap: level
                                entities: (list (entity-animate '(#:x 48 #:y 0 #:width 8 #:height 8) walk 0)
                                                (entity-animate '(#:x 64 #:y 0 #:width 8 #:height 8) walk 7)))))
(define (animation-tiles game)
  (capture-of game)
  (map (lambda (x) (find (lambda (t) (tile-drawn? game x 0 t #f #f #f)) '(1 2))) '(48 64)))
(game-run! animated frames: 10)
(define at-10 (animation-tiles animated))
(test-equal "two entities with one animation and different starts show different frames (tiles 2 and 1 at frame 10)"
  '(2 1) at-10)
(game-run! animated frames: 15)   ; on to frame 15
(test-equal "… each moves on by its own clock (frame 15: 240 and 128 ms in)" '(1 2) (animation-tiles animated))
(game-rewind! animated 5)
(test-equal "… and rewound to frame 10 they show frame 10's pictures again" at-10 (animation-tiles animated))
(test-equal "… drawn twice, the same" at-10 (animation-tiles animated))
(test-equal "an animation starting later than the frame drawn shows its first picture" '(1)
  (let ((g (make-game width: 96 height: 32
                      scene: (make-scene tilemap: level entities: (list (entity-animate '(#:x 48 #:y 0 #:width 8 #:height 8) walk 50))))))
    (list-head (animation-tiles g) 1)))
(test-equal "entity-animate sets both keys" '((4 . 10) 3)
  (let ((e (entity-animate '(#:x 0) '((4 . 10)) 3))) (list (car (entity-ref e #:animation)) (entity-ref e #:animation-start))))

;; A gid whose tile has a Tiled animation plays it from #:animation-start.
(define animated-sheet (string-append dir "/animated.tmx"))
(call-with-output-file animated-sheet
  (lambda (port)
    (format port "<map orientation=\"orthogonal\" width=\"1\" height=\"1\" tilewidth=\"8\" tileheight=\"8\">
 <tileset firstgid=\"1\" name=\"sheet\" tilewidth=\"8\" tileheight=\"8\" tilecount=\"4\" columns=\"2\">
  <image source=\"~a/maps/render/sheet.png\" width=\"16\" height=\"16\"/>
  <tile id=\"0\"><animation><frame tileid=\"1\" duration=\"100\"/><frame tileid=\"2\" duration=\"100\"/></animation></tile>
 </tileset>
 <layer name=\"ground\" width=\"1\" height=\"1\"><data encoding=\"csv\">0</data></layer>
</map>" data)))
(define tiled-animated
  (make-game width: 32 height: 8
             scene: (make-scene tilemap: (load-tilemap animated-sheet)
                                entities: (list (entity-animate '(#:x 0 #:y 0 #:width 8 #:height 8) 1 0)
                                                (entity-animate '(#:x 16 #:y 0 #:width 8 #:height 8) 1 7)))))
(game-run! tiled-animated frames: 10)
(capture-of tiled-animated)
(test-assert "#:animation as a gid plays its tile's Tiled animation by the entity's clock: tile 2 at 160 ms …"
  (tile-drawn? tiled-animated 0 0 2 #f #f #f))
(test-assert "… tile 1 at 48 ms" (tile-drawn? tiled-animated 16 0 1 #f #f #f))

(define (look-error . entity)
  (error-text (lambda () (game-capture (make-game width: 8 height: 8 scene: (make-scene tilemap: level entities: (list entity)))
                                       (string-append dir "/x.png")))))
(test-equal "a bad #:sprite-offset is named by game-draw with its value"
  "In procedure game-draw: #:sprite-offset: expected (dx . dy) of finite reals, in px, got (1 . +nan.0)\n"
  (look-error #:x 0 #:y 0 #:width 1 #:height 1 #:sprite 2 #:sprite-offset '(1 . +nan.0)))
(test-equal "a #:sprite-scale of 0 is refused"
  "In procedure game-draw: #:sprite-scale: expected a real > 0 and at most 64, or a pair (sx . sy) of them, got 0\n"
  (look-error #:x 0 #:y 0 #:width 1 #:height 1 #:sprite 2 #:sprite-scale 0))
(test-equal "… and one past 64"
  "In procedure game-draw: #:sprite-scale: expected a real > 0 and at most 64, or a pair (sx . sy) of them, got (1 . 65)\n"
  (look-error #:x 0 #:y 0 #:width 1 #:height 1 #:sprite 2 #:sprite-scale '(1 . 65)))
(test-equal "a bad #:rotation is named"
  "In procedure game-draw: #:rotation: expected a finite real number of degrees, got left\n"
  (look-error #:x 0 #:y 0 #:width 1 #:height 1 #:sprite 2 #:rotation 'left))
(test-equal "a bad #:animation frame is named"
  "In procedure game-draw: #:animation: expected a frame (gid . ms): a gid and an exact integer of ms ≥ 0, got (3 . -5)\n"
  (look-error #:x 0 #:y 0 #:width 1 #:height 1 #:animation '((2 . 10) (3 . -5))))
(test-equal "an empty #:animation is refused"
  "In procedure game-draw: #:animation: expected a gid or a list of 1 to 256 (gid . ms), got ()\n"
  (look-error #:x 0 #:y 0 #:width 1 #:height 1 #:animation '()))
(test-assert "… and one of 257 frames"
  (mentions? (look-error #:x 0 #:y 0 #:width 1 #:height 1 #:animation (make-list 257 '(2 . 10)))
             "game-draw" "#:animation" "a list of 1 to 256 (gid . ms)"))
(test-equal "a bad #:animation-start is named"
  "In procedure game-draw: #:animation-start: expected a frame number: an exact integer from -9007199254740992 to 9007199254740992, got 1.5\n"
  (look-error #:x 0 #:y 0 #:width 1 #:height 1 #:animation 2 #:animation-start 1.5))
(test-assert "entity-animate names a bad frame"
  (mentions? (error-text (lambda () (entity-animate '(#:x 0) 2 'now))) "entity-animate" "frame" "now"))

;;; ---------------------------------------------------------------- entities between layers
;; The platformer's map names its object layer "spawns" in the property
;; entity-layer; its layer "front" (grass at cell (6, 10)) comes after it, so
;; in that cell each pixel is the grass's where the grass is opaque and the
;; entity's box where it is clear.
(define platformer-map (load-tilemap "demo/maps/platformer.tmx"))
(define (grass-cell-pixels entities)
  (let ((game (make-game width: 160 height: 200
                         scene: (make-scene tilemap: platformer-map entities: entities))))
    (game-capture game (string-append dir "/grass.png"))
    (append-map (lambda (y) (map (lambda (x) (game-pixel game (+ 96 x) (+ 160 y))) (iota 16))) (iota 16))))
(define without-box (grass-cell-pixels '()))
(define with-box (grass-cell-pixels (list '(#:x 96 #:y 160 #:width 16 #:height 16 #:solid? #t #:color (255 0 255)))))
(define kept (count equal? without-box with-box))
;; A box drawn on top would change all 256 pixels (its colour covers each).
(test-assert "an entity in the entity-layer is drawn under the layers after it: the grass stays in front, the box shows where it is clear"
  (< 0 kept 256))
(define bad-layer-map (string-append dir "/bad-entity-layer.tmx"))
(call-with-output-file bad-layer-map
  (lambda (port)
    (display "<map orientation=\"orthogonal\" width=\"1\" height=\"1\" tilewidth=\"8\" tileheight=\"8\">
 <properties><property name=\"entity-layer\" value=\"actors\"/></properties>
 <objectgroup name=\"spawns\"/>
</map>" port)))
(test-assert "an entity-layer naming no object layer is an error naming the value and the map"
  (mentions? (error-text (lambda () (game-capture (make-game width: 8 height: 8
                                                             scene: (make-scene tilemap: (load-tilemap bad-layer-map)))
                                                  (string-append dir "/bad.png"))))
             "entity-layer" "\"actors\"" "bad-entity-layer.tmx"))

;;; ---------------------------------------------------------------- the background
(define (background-of . args)
  (let ((game (apply make-game width: 8 height: 8 args)))
    (game-capture game (string-append dir "/bg.png"))
    (game-pixel game 4 4)))
(test-equal "with no map and no background: the engine's" background (background-of))
(test-equal "make-game's background: is the clear colour" '(10 20 30 255) (background-of background: '(10 20 30)))
(test-equal "… drawn opaque whatever its alpha" '(10 20 30 255) (background-of background: '(10 20 30 7)))
(test-assert "a bad background: is named by make-game with its value"
  (mentions? (error-text (lambda () (make-game background: 'sky))) "make-game" "background" "sky"))

;;; ---------------------------------------------------------------- entities and maps that cannot be drawn
(test-assert "a bad #:sprite is named by key and value"
  (mentions? (error-text (lambda () (game-capture (make-game width: 8 height: 8
                                                             scene: (make-scene entities: (list '(#:x 0 #:y 0 #:width 1 #:height 1 #:sprite "hero"))))
                                                  (string-append dir "/x.png"))))
             "#:sprite" "\"hero\""))
;; Drawing walks every entity natively too (issue 19): a cycle is refused.
(define (ring . xs) (let ((l (list-copy xs))) (set-cdr! (last-pair l) l) l))
(define (drawing-error scene)
  (error-text (lambda () (game-capture (make-game width: 8 height: 8 scene: scene) (string-append dir "/ring.png")))))
(test-equal "a circular plist is refused by game-draw"
  "In procedure game-draw: entity 0: expected a keyword plist, got a circular or improper list\n"
  (drawing-error (make-scene entities: (list (ring #:x 1 #:y 2)))))
(test-equal "a circular entity list is refused by game-draw"
  "In procedure game-draw: entities: expected a proper list, got ((#:x 0) . #0#)\n"
  (drawing-error ((@@ (downstroke world) %scene-with-entities) (make-scene) (ring '(#:x 0)))))
(test-equal "two circular #:id values are refused by game-draw"
  "In procedure game-draw: entity key #:id: expected an id of at most 1024 pairs and vector slots (never a circular list), got (a . #0#)\n"
  (drawing-error (make-scene entities: (list (list #:x 0 #:id (ring 'a)) (list #:x 4 #:id (ring 'a))))))
(define no-image (load-tilemap (string-append data "/maps/render/no-image.tmx")))
(test-assert "a map whose image is missing loads (physics needs no images)" (tilemap? no-image))
(test-assert "… and drawing it names the missing file"
  (mentions? (error-text (lambda () (game-capture (make-game width: 8 height: 8 scene: (make-scene tilemap: no-image))
                                                  (string-append dir "/y.png"))))
             "absent.png"))
(test-assert "game-capture to a folder that does not exist names the file"
  (mentions? (error-text (lambda () (game-capture g "/nonexistent-dir/z.png"))) "game-capture" "/nonexistent-dir/z.png"))
(test-assert "make-game refuses a width of 0"
  (mentions? (error-text (lambda () (make-game width: 0))) "make-game" "width" "0"))

;;; ---------------------------------------------------------------- --capture
(define capture-dir (string-append dir "/frames"))
(define status (status:exit-val (system* host "--capture" capture-dir
                                         (string-append data "/scripts/capture-game.scm") "4")))
(test-equal "downstroke --capture runs the script" 0 status)
(test-equal "… writing one PNG per frame, named by frame number"
  '("000000.png" "000001.png" "000002.png" "000003.png")
  (sort (filter (lambda (f) (string-suffix? ".png" f)) (scandir capture-dir)) string<?))
(test-equal "… each the game's size, unscaled" '(48 32) (png-size (string-append capture-dir "/000003.png")))
;; Only regular files are written, and every write is checked (issue 45):
;; a FIFO blocked the game for ever, a full disk lost the picture silently.
(define fifo (string-append dir "/pipe"))
(mknod fifo 'fifo #o600 0)
(for-each
 (lambda (target)
   (test-equal (string-append "game-capture refuses " target ", not a regular file, without waiting")
     (format #f "In procedure game-capture: cannot write '~a': not a regular file\n" target)
     (error-text (lambda () (game-capture g target)))))
 (list fifo "/dev/full" dir))
(delete-file fifo)
;; A full disk without root: a file size limit of 0 makes every write fail
;; (EFBIG; SIGXFSZ ignored, as a shell passes it on), and the output goes
;; through a pipe, which the limit leaves alone.
(define full-dir (string-append dir "/full"))
(define full-run
  (let* ((p (open-pipe* OPEN_READ "/bin/sh" "-c"
                        (string-append "trap '' XFSZ; ulimit -f 0; exec '" host "' --no-auto-compile --capture '"
                                       full-dir "' '" data "/scripts/capture-game.scm' 4 2>&1")))
         (text (get-string-all p)))
    (list (status:exit-val (close-pipe p)) text (scandir full-dir (lambda (f) (string-suffix? ".png" f))))))
(test-equal "--capture onto a full disk ends at the first frame, naming it, with status 1 and no empty frame"
  (list 1 (format #f "In procedure game-capture: cannot write '~a/000000.png': File too large
(the whole backtrace: DOWNSTROKE_BACKTRACE=full)\n" full-dir) '())
  full-run)
(test-equal "--window and --capture together are refused" 2
  (status:exit-val (system* host "--window" "--capture" capture-dir "x.scm")))
(test-equal "--help exits 0" 0 (status:exit-val (system* host "--help")))

;;; ---------------------------------------------------------------- input
(test-assert "the default input map binds every action games use"
  (lset<= eq? '(left right up down a b start select quit) (map car (default-input-map))))
(test-assert "an input map naming no key is refused, naming it"
  (mentions? (error-text (lambda () (make-game input-map: '((jump "NoSuchKey"))))) "make-game" "NoSuchKey"))
(test-assert "a malformed input map is refused"
  (mentions? (error-text (lambda () (make-game input-map: '(("jump" "Z"))))) "make-game" "input-map"))
(test-assert "an input map of keys and pads is accepted"
  (game? (make-game input-map: '((jump "Space" "pad:a") (left "Left" "pad:leftx-")))))

;;; The input log of a run replays it: the same scene, frame for frame.
(define (walker script)
  (make-game scene: (make-scene entities: (list '(#:id w #:x 0 #:y 0 #:width 4 #:height 4 #:vx 0)))
             input-script: script
             update: (lambda (game dt)
                       (let* ((s (game-scene game)) (e (car (scene-entities s)))
                              (in (game-input game)))
                         (game-scene-set! game (update-scene s entities:
                                                             (list (entity-set e #:vx (cond ((input-held? in 'right) 2)
                                                                                            ((input-held? in 'left) -1)
                                                                                            (else 0))))))))))
(define played (walker '((0 . ()) (3 . (right)) (7 . (left right)) (9 . (left)) (12 . ()))))
(game-run! played frames: 15)
(define log (game-input-log played))
(test-equal "the input log has one entry per frame" 15 (length log))
(test-equal "… holding what was held" '(() () () (right) (right)) (list-head log 5))
(define replayed (walker (input-log->script log)))
(game-run! replayed frames: 15)
(test-equal "replaying the log gives the same scene" (scene-entities (game-scene played))
  (scene-entities (game-scene replayed)))

;;; ---------------------------------------------------------------- sounds
(define tone (string-append data "/sounds/tone.ogg"))
(load-sound 'jump (string-append demo-dir "/sounds/jump.wav"))
(load-sound 'tone tone)
(define noisy (make-game update: (lambda (game dt) (when (= (game-frame game) 2) (play-sound 'jump)))))
(game-run! noisy frames: 4)
(test-equal "headless, a loaded sound is recorded with its frame" '((2 . jump)) (game-sounds noisy))
(test-assert "opening the real audio device (as a window does) keeps the sounds loaded before"
  (begin ((@ (downstroke native) %open-audio!) #t)
         ((@ (downstroke native) %play-sound) 'jump)))
;; A window on a machine without a sound card: the engine's one line is all
;; of stderr (issue 46), not alsa-lib's eight "ALSA lib …" lines before it.
;; ALSA is made to find no device on any machine: SDL is sent to it (not to
;; a PulseAudio or PipeWire server) and its configuration, an empty file,
;; defines no PCM at all.
(define no-sound-card-stderr
  (let ((empty-conf (string-append dir "/empty-asound.conf")))
    (call-with-output-file empty-conf (lambda (port) #t))
    (let* ((p (open-pipe* OPEN_READ "/bin/sh" "-c"
                          (string-append "SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=alsa ALSA_CONFIG_PATH='" empty-conf
                                         "' exec '" host "' --no-auto-compile --window '" data
                                         "/scripts/capture-game.scm' 2 2>&1 >/dev/null")))
           (text (get-string-all p)))
      (list (status:exit-val (close-pipe p)) text))))
(test-equal "a window with no sound card prints one line, and no ALSA lib lines"
  '(0 "downstroke: no audio device (ALSA: Couldn't open audio device: No such file or directory); sound is off\n")
  no-sound-card-stderr)
(test-assert "a missing sound file is named"
  (mentions? (error-text (lambda () (load-sound 'x (string-append dir "/none.wav")))) "load-sound" "none.wav"))
(test-assert "a directory is not a sound"
  (mentions? (error-text (lambda () (load-sound 'x dir))) "load-sound" dir))
(test-assert "a sound's name must be a symbol"
  (mentions? (error-text (lambda () (load-sound "x" tone))) "load-sound" "name"))

;;; ---------------------------------------------------------------- music and volume
(load-music 'theme tone)
(load-music 'loop (string-append demo-dir "/sounds/jump.wav"))
(define tuneful
  (make-game update: (lambda (game dt)
                       (case (game-frame game)
                         ((1) (play-music 'theme))
                         ((3) (play-music 'loop loop?: #f fade-in: 250) (music-volume-set! 1/2))
                         ((5) (sound-volume-set! 0.25) (stop-music fade-out: 1000))))))
(game-run! tuneful frames: 7)
(test-equal "headless, music events are recorded with their frames"
  '((1 play theme #t 0) (3 play loop #f 250) (3 music-volume 1/2) (5 sound-volume 0.25) (5 stop 1000))
  (game-music tuneful))
(test-equal "play-music of a name never loaded is #f (and still recorded)" #f (play-music 'nothing))
(test-assert "opening the real audio device keeps the music loaded before"
  (begin ((@ (downstroke native) %open-audio!) #t)
         ((@ (downstroke native) %play-music) 'theme #t 0)))
((@ (downstroke native) %stop-music) 0)
(test-assert "a missing music file is named"
  (mentions? (error-text (lambda () (load-music 'x (string-append dir "/none.ogg")))) "load-music" "none.ogg"))
(test-assert "a broken OGG header is named"
  (let ((stub (string-append dir "/stub.ogg")))
    (call-with-output-file stub (lambda (port) (display "OggS\x00\x02" port)))
    (mentions? (error-text (lambda () (load-music 'x stub))) "load-music" "stub.ogg")))
(define (open-fds)
  ;; The file descriptors open, the folder read to list them left out.
  (let ((listed (filter-map string->number (scandir "/proc/self/fd"))))
    (filter (lambda (fd) (false-if-exception (fstat fd))) listed)))
(define fds-before-music (open-fds))
(for-each (lambda (i) (load-music (string->symbol (format #f "tune-~a" i)) tone)) (iota 300))
(test-equal "300 music names loaded hold no file open: the file is read whole and closed"
  fds-before-music (open-fds))
(test-equal "at the limit of open files, loading music says so, naming the file"
  (format #f "In procedure load-music: music ~a: Too many open files\n" tone)
  ;; The limit is on a descriptor's number: set to the lowest free one, no
  ;; file can be opened.
  (let ((limits (call-with-values (lambda () (getrlimit 'nofile)) cons))
        (lowest-free (let ((open (open-fds))) (find (lambda (n) (not (memv n open))) (iota 100000)))))
    (dynamic-wind
      (lambda () (setrlimit 'nofile lowest-free (cdr limits)))
      (lambda () (error-text (lambda () (load-music 'one-too-many tone))))
      (lambda () (setrlimit 'nofile (car limits) (cdr limits))))))
(test-assert "a volume outside 0–1 is refused"
  (mentions? (error-text (lambda () (music-volume-set! 1.5))) "music-volume-set!" "1.5"))
(test-assert "… NaN too"
  (mentions? (error-text (lambda () (sound-volume-set! +nan.0))) "sound-volume-set!" "+nan.0"))
(test-assert "a fade is a number of ms"
  (mentions? (error-text (lambda () (stop-music fade-out: 'slow))) "stop-music" "fade-out" "slow"))
(test-assert "a music name must be a symbol"
  (mentions? (error-text (lambda () (play-music "theme"))) "play-music" "name"))

;;; ---------------------------------------------------------------- drawing between steps
(define between-game (make-game width: 32 height: 8))
(define (draw-between previous alpha)
  ((@ (downstroke native) %display-draw!) ((@@ (downstroke engine) game-display) between-game) #f 0 0
   (list '(#:x 10 #:y 0 #:width 4 #:height 4 #:color (170 170 170))) #f '() 0
   (and previous (list previous alpha 0 0))))
(draw-between (list '(#:x 2 #:y 0 #:width 4 #:height 4 #:color (170 170 170))) 0.5)
(test-equal "between steps, a box is drawn α of the way: x 6 at α 0.5 from 2 to 10"
  '((170 170 170) (24 28 40) (24 28 40))
  (map (lambda (x) (list-head ((@ (downstroke native) %display-pixel) ((@@ (downstroke engine) game-display) between-game) x 0) 3)) '(6 5 10)))
(draw-between #f 0)
(test-equal "without the step before, where it is" '(170 170 170)
  (list-head ((@ (downstroke native) %display-pixel) ((@@ (downstroke engine) game-display) between-game) 10 0) 3))
(test-assert "an alpha outside 0–1 is refused"
  (mentions? (error-text (lambda () (draw-between (list '(#:x 2 #:y 0 #:width 4 #:height 4)) 2))) "alpha" "2"))

(test-end "render")
