;; SPDX-License-Identifier: MIT
;;; The demos (demo/*.scm), each loaded into a fresh module and run headless
;;; with its built-in input script, then checked with exact values; and their
;;; maps (demo/maps/*.tmx, written by demo/maps/make_maps.py). The demos keep
;;; no record of their frames: the test watches them through a frame hook.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke) (downstroke testing))

(load "support.scm")   ; demo-dir

(define (load-demo name)
  (load-in-fresh-module (string-append demo-dir "/" name)))

(define seen (make-weak-key-hash-table)) ; demo module → (frame → its entities)

(define (watch! m thunk)
  "Call THUNK, which runs the game of demo module M, with a frame hook that
records what each frame ended with: the hook runs at the start of a frame
(and once more after the last), so it sees the one before ended. A frame
played again (a rewind, a paused tick) is recorded again."
  (let* ((game (module-ref m 'game))
         (frames (or (hashq-ref seen m) (let ((t (make-hash-table))) (hashq-set! seen m t) t)))
         (hook (lambda () (hashv-set! frames (- (game-frame game) 1) (scene-entities (game-scene game))))))
    (add-frame-hook! hook)
    (dynamic-wind (lambda () #t) thunk (lambda () (remove-frame-hook! hook)))))

(define (run! m frames)
  "Run demo module M's game up to frame FRAMES, watched."
  (watch! m (lambda () ((module-ref m 'run!) frames))))

(define (entities-at m frame)
  "What FRAME of demo module M's game ended with, or #f when it did not run."
  (hashv-ref (or (hashq-ref seen m) (make-hash-table)) frame #f))

(define (entity-at m frame id)
  "The entity with #:id ID as FRAME ended, or #f."
  (let ((entities (entities-at m frame)))
    (and entities (find (lambda (e) (eq? (entity-ref e #:id) id)) entities))))

(define (player-at m frame)
  "The first entity (the player) as FRAME ended, or #f."
  (let ((entities (entities-at m frame))) (and entities (car entities))))

(define (run-demo name . frames)
  "demo/NAME loaded and run for FRAMES frames (its own `demo-frames' if none)."
  (let ((m (load-demo name)))
    (run! m (if (pair? frames) (car frames) (module-ref m 'demo-frames)))
    m))

(define (ref m name) (module-ref m name))
(define (game-of m) (ref m 'game))
(define (entities-of m) (scene-entities (game-scene (game-of m))))
(define (events-items-of m)
  ;; The demo's log, (demo events), newest first: the module is found once a demo put demo/lib on the load path.
  ((module-ref (resolve-interface '(demo events)) 'events-items) (ref m 'events)))
(define (events-of m) (reverse (events-items-of m)))
(define (pick e . keys) (map (lambda (k) (entity-ref e k)) keys))
(define (by-id id entities) (find (lambda (e) (eq? (entity-ref e #:id) id)) entities))
(define (range a b) (iota (- b a) a))   ; a .. b-1

(test-begin "demos")

;;; ================================================================ the maps
(define (tilemap name) (load-tilemap (string-append demo-dir "/maps/" name ".tmx")))
(define (solid-cells? m cells) (every (lambda (c) (tilemap-cell-solid? m (car c) (cdr c))) cells))
(define (empty-cells? m cells) (not (any (lambda (c) (tilemap-cell-solid? m (car c) (cdr c))) cells)))
(define (row-cells cols row) (map (lambda (c) (cons c row)) cols))
(define (col-cells col rows) (map (lambda (r) (cons col r)) rows))

(test-group "maps"
  (let ((m (tilemap "platformer")))
    (test-equal "platformer: 100×15 of 16 px" '(100 15 16 16)
      (list (tilemap-width m) (tilemap-height m) (tilemap-tile-width m) (tilemap-tile-height m)))
    (test-equal "platformer: the hill's ramps (columns 44-51), turned by flip bits"
      '(#(0 8 16 16 floor 0 16 16 8 #f) #(0 0 16 16 floor 0 8 16 0 #f) #(0 0 16 16 floor 0 16 16 0 #f)
        #(0 0 16 16 floor 0 0 16 16 #f) #(0 0 16 16 floor 0 0 16 8 #f) #(0 8 16 16 floor 0 8 16 16 #f))
      (map (lambda (cell) (tilemap-cell-shape m (car cell) (cdr cell)))
           '((44 . 10) (45 . 10) (46 . 9) (49 . 9) (50 . 10) (51 . 10))))
    (test-assert "platformer: ground rows 11-14 left of the pit"
      (solid-cells? m (append-map (lambda (r) (row-cells (range 1 30) r)) '(11 12 13 14))))
    (test-assert "platformer: the pit (columns 30-35, rows 11-12) is open"
      (empty-cells? m (append (row-cells (range 30 36) 11) (row-cells (range 30 36) 12))))
    (test-assert "platformer: the pit has a floor (row 13)" (solid-cells? m (row-cells (range 30 36) 13)))
    (test-assert "platformer: the pit wall (column 36, rows 8-12)" (solid-cells? m (col-cells 36 (range 8 13))))
    (test-assert "platformer: above the pit wall is open" (empty-cells? m (col-cells 36 (range 0 8))))
    (test-assert "platformer: platforms at row 8 (10-13) and row 5 (16-19)"
      (solid-cells? m (append (row-cells (range 10 14) 8) (row-cells (range 16 20) 5))))
    (test-assert "platformer: nothing beside the platforms"
      (empty-cells? m (list '(9 . 8) '(14 . 8) '(15 . 5) '(20 . 5) '(12 . 7) '(12 . 9))))
    (test-assert "platformer: end walls" (solid-cells? m (append (col-cells 0 (range 0 15)) (col-cells 99 (range 0 15)))))
    (test-assert "platformer: the ground goes on under the old east wall (column 59)"
      (and (empty-cells? m (col-cells 59 (range 1 11))) (solid-cells? m (col-cells 59 (range 11 15)))))
    (test-equal "platformer: the plank (row 8, columns 62-67) is one-way, gid 21, not solid"
      '((#t #t #t #t #t #t) (21 21 21 21 21 21) #f (#f #f))
      (list (map (lambda (c) (tilemap-cell-one-way? m c 8)) (range 62 68))
            (map (lambda (c) (tilemap-gid m 0 c 8)) (range 62 68))
            (any (lambda (c) (tilemap-cell-solid? m c 8)) (range 62 68))
            (list (tilemap-cell-one-way? m 61 8) (tilemap-cell-one-way? m 68 8))))
    (test-equal "platformer: the breakable blocks (row 8, columns 71-73) are solid, gid 22"
      '((22 22 22) #t) (list (map (lambda (c) (tilemap-gid m 0 c 8)) (range 71 74))
                             (solid-cells? m (row-cells (range 71 74) 8))))
    (test-assert "platformer: the second pit (columns 78-89, rows 11-13) is open, with a floor (row 14)"
      (and (empty-cells? m (append-map (lambda (r) (row-cells (range 78 90) r)) '(11 12 13)))
           (solid-cells? m (row-cells (range 78 90) 14))
           (solid-cells? m (col-cells 77 (range 11 15))) (solid-cells? m (col-cells 90 (range 11 15)))))
    (test-equal "platformer: grass is tile 4 and not solid" '(4 #f 4 #f)
      (list (tilemap-gid m 0 3 10) (tilemap-cell-solid? m 3 10)
            (tilemap-gid m 0 52 10) (tilemap-cell-solid? m 52 10)))
    (test-equal "platformer: objects" '((player 40 100 12 16) (goal 1520 144 16 32) (lift 1248 176 48 8))
      (map (lambda (o) (pick o #:type #:x #:y #:width #:height)) (tilemap-objects m)))
    (test-equal "platformer: the lift's run and speed" '(1392 2)
      (pick (third (tilemap-objects m)) #:to-x #:speed)))
  (let ((m (tilemap "topdown")))
    (test-equal "topdown: 20×15 (base64)" '(20 15) (list (tilemap-width m) (tilemap-height m)))
    (test-assert "topdown: border walls"
      (solid-cells? m (append (row-cells (range 0 20) 0) (row-cells (range 0 20) 14)
                              (col-cells 0 (range 0 15)) (col-cells 19 (range 0 15)))))
    (test-assert "topdown: inner wall, column 10, rows 1-8" (solid-cells? m (col-cells 10 (range 1 9))))
    (test-assert "topdown: the gap under the inner wall" (empty-cells? m (col-cells 10 (range 9 14))))
    (test-assert "topdown: the block (columns 4-6, rows 10-11)"
      (solid-cells? m (append (row-cells '(4 5 6) 10) (row-cells '(4 5 6) 11))))
    (test-equal "topdown: grass tiles are not solid" '(4 #f 4 #f)
      (list (tilemap-gid m 0 5 5) (tilemap-cell-solid? m 5 5) (tilemap-gid m 0 12 11) (tilemap-cell-solid? m 12 11)))
    (test-equal "topdown: a player and five coins" '(player coin coin coin coin coin)
      (map (lambda (o) (entity-ref o #:type)) (tilemap-objects m))))
  (let ((m (tilemap "sandbox")))
    (test-equal "sandbox: 30×15 (base64+zlib)" '(30 15) (list (tilemap-width m) (tilemap-height m)))
    (test-assert "sandbox: floor rows 13-14" (solid-cells? m (append (row-cells (range 0 30) 13) (row-cells (range 0 30) 14))))
    (test-assert "sandbox: stub wall (column 15, rows 11-12)" (solid-cells? m (col-cells 15 '(11 12))))
    (test-assert "sandbox: the ledge (row 7, columns 24-27)" (solid-cells? m (row-cells (range 24 28) 7)))
    (test-assert "sandbox: open around the ledge" (empty-cells? m (list '(23 . 7) '(28 . 7) '(25 . 6) '(25 . 8))))
    (test-equal "sandbox: grass not solid" '(4 #f) (list (tilemap-gid m 0 5 12) (tilemap-cell-solid? m 5 12)))
    (test-equal "sandbox: no objects" '() (tilemap-objects m)))
  ;; Maps loaded only for their tilesets (the entities' #:sprite gids): not
  ;; one tile, so they add no collision.
  (for-each
   (lambda (name)
     (let ((m (tilemap name)))
       (test-equal (string-append name ": 20×15 of 16 px, the screen's size") '(20 15 16 16)
         (list (tilemap-width m) (tilemap-height m) (tilemap-tile-width m) (tilemap-tile-height m)))
       (test-assert (string-append name ": no tile in any cell, so none solid")
         (every (lambda (row)
                  (every (lambda (col) (and (= 0 (tilemap-gid m 0 col row)) (not (tilemap-cell-solid? m col row))))
                         (range 0 20)))
                (range 0 15)))
       (test-equal (string-append name ": no objects") '() (tilemap-objects m))))
   '("shmup" "tweens")))

;;; Loading does not run a demo: each runs itself only as the host's script.
(let ((m (load-demo "platformer.scm")))
  (test-equal "loading a demo does not run it" 0 (game-frame (game-of m)))
  (test-equal "the demo found its maps next to itself, through (demo looks)"
    (string-append demo-dir "/maps/platformer.tmx") ((ref m 'demo-file) "maps/platformer.tmx")))

;;; ================================================================ platformer
;;; Ground top: row 11, y 176; the player is 12×16, so standing y = 160.
(define platformer (load-demo "platformer.scm"))
(define (p-at k) (player-at platformer k))
(run! platformer 200)
(define camera-at-200 (let ((c (scene-camera (game-scene (game-of platformer))))) (cons (camera-x c) (camera-y c))))
(run! platformer (ref platformer 'demo-frames))

(test-group "platformer"
  ;; Spawned at y 100, falling: after frame k, y = 100 + (k+1)(k+2)/2.
  (test-equal "falling: y after frames 0, 4, 9" '(101 115 155) (map (lambda (k) (entity-ref (p-at k) #:y)) '(0 4 9)))
  (test-equal "not on the ground while falling" #f (entity-ref (p-at 9) #:on-ground?))
  (test-equal "landed at frame 10: y 160, vy 0, on-ground" '(160 0 #t) (pick (p-at 10) #:y #:vy #:on-ground?))
  (test-equal "events" '((10 . landed) (42 coin coin-1) (50 . jumped) (75 coin coin-2) (76 . landed) (85 . jumped)
                         (111 . landed) (123 coin coin-3)
                         (147 . landed) (194 . landed) (215 . bumped) (220 . jumped) (247 . landed)
                         (287 coin coin-4)
                         (372 . jumped) (398 . landed) (420 . landed) (453 . jumped) (455 . broke)
                         (461 . landed) (576 . boarded) (675 . goal) (696 . bumped))
    (events-of platformer))
  (test-equal "sounds: a jump for each press of 'a on the ground (not the one in the air at 60), a boom for the block"
    '((42 . coin) (50 . jump) (75 . coin) (85 . jump) (123 . coin) (220 . jump) (287 . coin) (372 . jump)
      (453 . jump) (455 . boom) (675 . goal))
    (game-sounds (game-of platformer)))
  (test-equal "the theme plays from the first frame, looping" '((0 play theme #t 0)) (game-music (game-of platformer)))
  ;; The coins and the goal are sensors: entered when the frame pairs them
  ;; with the player; coin-1 (8×8 at 100, 164) meets the 12 px player at x 91.
  (test-equal "coin-1 is there until frame 41, gone at 42; coin-5, out of reach, stays"
    '(#t #f #t) (list (and (by-id 'coin-1 (entities-at platformer 41)) #t)
                      (and (by-id 'coin-1 (entities-at platformer 42)) #t)
                      (and (by-id 'coin-5 (entities-at platformer 700)) #t)))
  (test-equal "the sensors never moved the player: x 91 at frame 42, as it runs 3 px a frame from 25"
    91 (entity-ref (p-at 42) #:x))
  ;; Jump pressed at frame 50 (on the ground): the next frame's vy = -15 + 1.
  (test-equal "frame 50: on the ground before the jump" '(160 #t) (pick (p-at 50) #:y #:on-ground?))
  (test-equal "frame 51: y 146, vy -14, in the air" '(146 -14 #f) (pick (p-at 51) #:y #:vy #:on-ground?))
  (test-equal "the jump's apex: 160 - (14+13+...+1) = 55"
    55 (apply min (map (lambda (k) (entity-ref (p-at k) #:y)) (range 51 76))))
  (test-assert "y went up every frame until the apex"
    (every (lambda (k) (< (entity-ref (p-at (+ k 1)) #:y) (entity-ref (p-at k) #:y))) (range 50 64)))
  (test-equal "landed on the first platform (top y 128): y 112" '(112 0 #t) (pick (p-at 76) #:y #:vy #:on-ground?))
  (test-equal "landed on the second platform (top y 80): y 64" '(64 #t) (pick (p-at 111) #:y #:on-ground?))
  (test-equal "in the pit (floor top y 208): y 192" '(192 #t) (pick (p-at 194) #:y #:on-ground?))
  (test-equal "stopped by the pit wall at x = 36·16 - 12 = 564"
    '(564 564 564 564 564 564) (map (lambda (k) (entity-ref (p-at k) #:x)) (range 215 221)))
  (test-equal "pinned to the wall while rising, over it once the feet clear y 128"
    '((564 108) (567 102)) (map (lambda (k) (pick (p-at k) #:x #:y)) '(228 229)))
  (test-equal "landed beyond the wall" '(160 #t) (pick (p-at 247) #:y #:on-ground?))
  ;; The hill (columns 44-51): up a 1:2 ramp from x 704 (y 176 to 160) and a
  ;; 45° one (to 144), a flat top, down a 45° and a 1:2 ramp to x 832. The
  ;; 12 px player stands on the highest point under its feet: running at 3
  ;; px/frame, y moves by 1.5 on the 1:2 ramps (half pixels, flonums) and by
  ;; 3 on the 45° ones.
  (test-equal "up the 1:2 ramp: half pixels, as flonums" '((693 159.5) (696 158.0) (699 156.5))
    (map (lambda (k) (pick (p-at k) #:x #:y)) '(271 272 273)))
  (test-equal "up the 45° ramp: 3 px a frame" '((729 139.0) (732 136.0))
    (map (lambda (k) (pick (p-at k) #:x #:y)) '(283 284)))
  (test-equal "on the hill's top (y 144): y 128" '(750 128.0 #t) (pick (p-at 290) #:x #:y #:on-ground?))
  (test-equal "down the far side to the ground" '((795 139.0) (831 159.5) (834 160.0))
    (map (lambda (k) (pick (p-at k) #:x #:y)) '(305 317 318)))
  (test-assert "on the ground every frame over the hill, at a steady 3 px/frame"
    (every (lambda (k) (and (entity-ref (p-at k) #:on-ground?)
                            (= 3 (- (entity-ref (p-at k) #:x) (entity-ref (p-at (- k 1)) #:x)))))
           (range 248 372)))
  ;; The one-way plank: row 8 (top y 128), columns 62-67 (x 992-1088).
  (test-equal "jumped up through the plank: rising past its top, no stop"
    '((1005 121.0 -12) (1011 100.0 -10) (1038 55.0 -1))
    (map (lambda (k) (pick (p-at k) #:x #:y #:vy)) '(375 377 386)))
  (test-equal "landed on the plank from above: y 128 - 16 = 112" '(1065 112.0 0 #t)
    (pick (p-at 398) #:x #:y #:vy #:on-ground?))
  (test-equal "standing on it until Down is held (frame 410)" '((112.0 #t) (112.0 #t #t))
    (list (pick (p-at 409) #:y #:on-ground?) (pick (p-at 410) #:y #:on-ground? #:drop-through?)))
  (test-equal "dropped through it, back on the ground at frame 420"
    '((113.0 1 #f) (157.0 9 #f) (160.0 0 #t))
    (map (lambda (k) (pick (p-at k) #:y #:vy #:on-ground?)) '(411 419 420)))
  ;; The blocks: row 8 (bottom y 144), columns 71-73 (x 1136-1184).
  (test-equal "the head hit the middle block: stopped at y 144, vy 0, blocked up" '(1155 144.0 0 (up))
    (pick (p-at 455) #:x #:y #:vy #:blocked))
  (test-equal "that block is gone from the scene's map; its neighbours and the level are not"
    '((22 0 22) (22 22 22) (#t #f #t))
    (let ((now (scene-tilemap (game-scene (game-of platformer)))) (level (ref platformer 'level)))
      (list (map (lambda (c) (tilemap-gid now 0 c 8)) '(71 72 73))
            (map (lambda (c) (tilemap-gid level 0 c 8)) '(71 72 73))
            (map (lambda (c) (tilemap-cell-solid? now c 8)) '(71 72 73)))))
  ;; The lift: 48×8 at y 176, x 1248 to 1392 and back at 2 px a frame.
  (define (l-x k) (entity-ref (entity-at platformer k 'lift) #:x))
  (test-equal "the lift runs 1248 → 1392 → 1248" '(1250 1392 1390 1248 1250)
    (map l-x '(0 71 72 143 144)))
  (test-equal "stepped on as it left the near end" '((1236 1248) (1249 1254))
    (map (lambda (k) (list (entity-ref (p-at k) #:x) (l-x k))) '(575 578)))
  (test-equal "the contact report names the lift: stood on and pushed against, no tile below; met on its down side"
    '(() lift ((lift . down)))
    (pick (p-at 600) #:blocked #:standing-on #:touching))
  (test-equal "and on the ground, nothing" '((down) #f ())
    (pick (p-at 560) #:blocked #:standing-on #:touching))
  (test-assert "standing still on it, carried: 10 px from its left end every frame from 584 to 635"
    (every (lambda (k) (and (= (- (entity-ref (p-at k) #:x) (l-x k)) 10)
                            (equal? (pick (p-at k) #:y #:vx #:on-ground?) '(160 0 #t))))
           (range 584 636)))
  (test-equal "walking on it: 3 + 2 px a frame, then 3 - 2 as it turns back, then off on the far side"
    '(1385 1390 1434 1435 1439 1442)
    (map (lambda (k) (entity-ref (p-at k) #:x)) '(637 638 648 649 651 652)))
  (test-equal "stopped by the east wall at x = 99·16 - 12 = 1572" '(1572 1572)
    (map (lambda (k) (entity-ref (p-at k) #:x)) '(701 719)))
  (test-equal "running: x grows by 3 a frame" '(520 523 526)
    (map (lambda (k) (entity-ref (p-at k) #:x)) '(200 201 202)))
  ;; camera-follow! centres the player (320×240 view) and keeps the view
  ;; inside the level (960×240).
  (test-equal "camera followed: x = 517 + 6 - 160 at frame 199, y clamped to 0" '(363 . 0) camera-at-200)
  (test-equal "camera at the end: clamped to 1600 - 320" '(1280 . 0)
    (let ((c (scene-camera (game-scene (game-of platformer))))) (cons (camera-x c) (camera-y c))))
  (test-assert "x stays an exact integer all the way"
    (every (lambda (k) (exact? (entity-ref (p-at k) #:x))) (range 0 720)))
  ;; A flonum stays a flonum (semantics §1): y is exact until the 1:2 ramp's
  ;; first half pixel, at frame 271, and a flonum until the lift carries the
  ;; player (frame 579: push-apart puts it on the lift's exact top).
  (test-equal "y stays exact up to the 1:2 ramp" 271
    (find (lambda (k) (inexact? (entity-ref (p-at k) #:y))) (range 0 720)))
  (test-assert "y is a flonum from then on, until the lift"
    (every (lambda (k) (inexact? (entity-ref (p-at k) #:y))) (range 271 579)))
  (test-assert "exact again from the lift on"
    (every (lambda (k) (exact? (entity-ref (p-at k) #:y))) (range 579 720))))

;;; The coins picked up are in the scene's data: coin-3 is picked up at
;;; frame 123, so the scene frame 120 started from holds 2, and a rewind to
;;; it gives 2 back; playing on picks coin-3 up again, at the same frame.
(define rewound (load-demo "platformer.scm"))
(run! rewound 130)
(define (coins-of m) (entity-ref (scene-data (game-scene (game-of m))) #:coins))
(define (last-wanted-of m) (entity-ref (scene-data (game-scene (game-of m))) #:last-wanted))
(test-group "platformer: the coins in the scene data"
  (test-equal "the whole demo picks up four" 4 (coins-of platformer))
  (test-equal "three by frame 130, running right (the #:vx asked for last frame)" '(3 3)
    (list (coins-of rewound) (last-wanted-of rewound)))
  (test-equal "a rewind of 10 frames: frame 120, two coins, coin-3 back in the scene, and the rest of the run's memory: it stood still before frame 120" '(120 2 #t 0)
    (list (game-rewind! (game-of rewound) 10) (coins-of rewound)
          (and (by-id 'coin-3 (entities-of rewound)) #t) (last-wanted-of rewound)))
  (run! rewound 130)
  (test-equal "played on: coin-3 again at frame 123, three coins" '(3 (123 coin coin-3))
    (list (coins-of rewound) (last (filter (lambda (e) (equal? (cdr e) '(coin coin-3))) (events-of rewound))))))

;;; P pressed in tick 5 pauses after frame 5; ticks 6 to 9 step nothing
;;; (P is pressed again in tick 9, in the paused: hook), and the game goes on
;;; from frame 6: it still lands at frame 10, four ticks later.
(define paused (load-demo "platformer.scm"))
(watch! paused (lambda () (play (game-of paused) frames: 12 input: '((0) (5 pause) (6) (9 pause) (10)))))
(test-group "platformer: pause"
  (test-equal "paused after frame 5, resumed at frame 6, landed at frame 10"
    '((5 . paused) (6 . resumed) (10 . landed)) (events-of paused))
  (test-equal "the fall is that of a game never paused: frames 5 to 10"
    '(121 128 136 145 155 160) (map (lambda (k) (entity-ref (player-at paused k) #:y)) (iota 6 5)))
  (test-equal "twelve frames in sixteen ticks, not paused" '(12 16 #f)
    (list (game-frame (game-of paused)) (length (game-input-log (game-of paused))) (game-paused? (game-of paused)))))

;;; The walker in the pit under the lift, out of the scripted run's way: the
;;; player put above it or beside it at frame 0 (the script holds nothing
;;; until frame 25).
(define (platformer-with-player-at x y frames)
  (let* ((m (load-demo "platformer.scm")) (g (game-of m)) (s (game-scene g)) (es (scene-entities s)))
    (game-scene-set! g (update-scene s entities: (cons (entity-set (entity-set (car es) #:x x) #:y y) (cdr es))))
    (run! m frames)
    m))
(test-group "platformer: the walker"
  (let* ((m (platformer-with-player-at 1316 150 14))
         (p (lambda (k) (player-at m k)))
         (walker (lambda (k) (entity-at m k 'walker))))
    (test-equal "falling on it: frame 8 the player's #:touching says its down side met it"
      '((() 1312) (((walker . down)) #f))
      (map (lambda (k) (list (entity-ref (p k) #:touching) (and (walker k) (entity-ref (walker k) #:x)))) '(7 8)))
    (test-equal "… a stomp: the walker is gone, the player bounces off at 8 px a frame, a boom"
      '((8 . stomped) -8 ((8 . boom)))
      (list (assq 8 (events-of m)) (entity-ref (p 8) #:vy) (game-sounds (game-of m)))))
  (let* ((m (platformer-with-player-at 1290 208 19)))
    (test-equal "standing in its way: it walks into the player's right side at frame 18, and the run starts again"
      '(((0 . landed) (18 . hurt)) (40 100) (1320 210))
      (list (events-of m) (pick (player-at m 18) #:x #:y)
            (pick (entity-at m 18 'walker) #:x #:y)))))

;;; ================================================================ top-down
(define topdown (run-demo "topdown.scm"))
(define (t-at k) (player-at topdown k))
(define (t-xy k) (pick (t-at k) #:x #:y))

(test-group "topdown"
  (test-equal "no gravity: y unchanged while going right" '((40 40) (43 40) (100 40))
    (map t-xy '(0 1 20)))
  (test-equal "right: stopped by the inner wall at x = 10·16 - 12 = 148" '((148 40) (148 40))
    (map t-xy '(37 49)))
;; 'down is held from frame 50: update sets vy then, physics moves from 51.
  (test-equal "down: y grows by 3, stopped at y = 14·16 - 12 = 212" '((148 40) (148 43) (148 70) (148 212) (148 212))
    (map t-xy '(50 51 60 108 119)))
  (test-equal "left: stopped at x = 16" '((145 212) (16 212)) (map t-xy '(121 174)))
  (test-equal "up: stopped at y = 16" '((16 209) (16 16)) (map t-xy '(176 249)))
  (test-equal "diagonal, then right under the inner wall to x = 19·16 - 12 = 292" '((19 19) (292 148))
    (map t-xy '(251 349)))
  (test-equal "up to the top wall in the east room" '(292 16) (t-xy 419))
  (test-equal "wall events, each when the wall first stops the player"
    '((37 wall right x 148) (108 wall down y 212) (165 wall left x 16) (241 wall up y 16)
      (343 wall right x 292) (395 wall up y 16))
    (filter (lambda (e) (eq? (cadr e) 'wall)) (events-of topdown)))
  (test-equal "coins collected, in order"
    '((17 coin coin1) (73 coin coin2) (147 coin coin3) (210 coin coin4) (325 coin coin5))
    (filter (lambda (e) (eq? (cadr e) 'coin)) (events-of topdown)))
  (test-equal "score: four coins of 10 and one of 50" 90 (entity-ref (car (entities-of topdown)) #:score))
  (test-equal "no coins left: the player and the guard remain" '(player guard)
    (map (lambda (e) (entity-ref e #:id)) (entities-of topdown)))
  ;; It walks 2 px a frame from x = 100 and looks 8 px past its front edge:
  ;; the east wall (x = 304) is seen from x = 286, the west one (x = 16) from 22.
  (test-equal "the guard turns where a ray finds a wall ahead"
    '((92 turn guard x 286) (224 turn guard x 22) (356 turn guard x 286))
    (filter (lambda (e) (eq? (cadr e) 'turn)) (events-of topdown)))
  (test-equal "a 'coin sound for each" '(17 73 147 210 325) (map car (game-sounds (game-of topdown))))
  (test-equal "the coins glint out of phase: each starts its animation 9 frames before the next"
    '(0 -9 -18 -27 -36) (map (lambda (c) (entity-ref c #:animation-start)) (ref topdown 'coins0)))
  (test-equal "the guard walks by its #:animation, not a #:sprite set each frame" '(#f #t)
    (let ((g (by-id 'guard (entities-of topdown)))) (list (entity-ref g #:sprite) (pair? (entity-ref g #:animation)))))
  (test-assert "walked over the grass at cell (5, 5) (not solid)"
    (any (lambda (k) (let ((x (entity-ref (t-at k) #:x)) (y (entity-ref (t-at k) #:y)))
                       (aabb-overlap? x y 12 12 80 80 16 16)))
         (range 250 300))))

;;; ================================================================ sandbox
(define sandbox (run-demo "sandbox.scm"))
(define (s-at k id) (entity-at sandbox k id))
(define sandbox-last (- (ref sandbox 'demo-frames) 1))

(test-group "sandbox"
  ;; Boxes are 12×12: resting y = surface top - 12.
  (test-equal "boxes at rest at the end: (y on-ground?)"
    '((116 #t) (116 #t) (104 #t) (52 #t) (100 #t))
    (map (lambda (id) (pick (s-at sandbox-last id) #:y #:on-ground?)) '(box-1 box-2 box-5 box-3 box-4)))
  (test-equal "single boxes have stopped: vy 0" '(0 0 0)
    (map (lambda (id) (entity-ref (s-at sandbox-last id) #:vy)) '(box-1 box-3 box-4)))
  (test-assert "the stack box-5 on box-2 stays put from frame 15 on"
    (every (lambda (k) (equal? '(116 104) (list (entity-ref (s-at k 'box-2) #:y) (entity-ref (s-at k 'box-5) #:y))))
           (range 15 300)))
  (test-equal "boxes keep their x (nothing pushed them sideways)" '(60 92 94 300 400)
    (map (lambda (id) (entity-ref (s-at sandbox-last id) #:x)) '(box-1 box-2 box-5 box-3 box-4)))
  (test-equal "landings" '((8 landed box-3 y 52) (12 landed box-4 y 100) (14 landed box-1 y 116)
                           (15 landed box-5 y 104) (15 landed box-2 y 116))
    (filter (lambda (e) (eq? (cadr e) 'landed)) (events-of sandbox)))
  (test-equal "immovable platforms did not move" '((48 128) (288 64))
    (map (lambda (id) (pick (s-at sandbox-last id) #:x #:y)) '(ledge-a ledge-b)))
  ;; The raft: every frame, each member sits at origin + its local offset.
  (test-assert "raft members keep their offsets to the origin, every frame"
    (every (lambda (k)
             (let ((ox (entity-ref (s-at k 'raft-0) #:x)) (oy (entity-ref (s-at k 'raft-0) #:y)))
               (every (lambda (m)
                        (let ((e (s-at k (car m))))
                          (and (= (entity-ref e #:x) (+ ox (cadr m))) (= (entity-ref e #:y) (+ oy (caddr m))))))
                      '((raft-1 16 0) (raft-2 32 0) (mast 22 -20)))))
           (range 0 300)))
  (test-equal "the raft moves: origin x at frames 0, 50, 95, 96, 191, 192"
    '(257 307 352 351 256 257) (map (lambda (k) (entity-ref (s-at k 'raft-0) #:x)) '(0 50 95 96 191 192)))
  (test-equal "raft turns" '((95 raft-turned at 352) (191 raft-turned at 256) (287 raft-turned at 352))
    (filter (lambda (e) (eq? (cadr e) 'raft-turned)) (events-of sandbox)))
  ;; Bots: 12 wide; west wall's face x 16, stub (column 15) 240..256, east wall x 464.
  (test-equal "bots turned at the walls: x 16, 464-12, 240-12, 256"
    '((42 turned bot-1 at 16) (76 turned bot-2 at 452) (149 turned bot-1 at 228)
      (175 turned bot-2 at 256) (256 turned bot-1 at 16) (274 turned bot-2 at 452))
    (filter (lambda (e) (eq? (cadr e) 'turned)) (events-of sandbox)))
  ;; x 98 - 2k reaches 16 at frame 41; at 42 the wall zeroes vx and the bot turns.
  (test-equal "bot-1: walking left, stopped, walking right" '((18 -2) (16 -2) (16 2) (18 2))
    (map (lambda (k) (pick (s-at k 'bot-1) #:x #:vx)) '(40 41 42 43)))
  ;; ball-1 (bounce 1) falls 153 px = 1 + … + 17 from y 47 to the floor
  ;; (rest y 200): it hits at 18 px a frame and rises back to y 47, where it
  ;; is at frames 34, 70, … ball-2 (bounce 0.6) ends at rest on the floor.
  (test-equal "ball-1 rises back to y 47 every 36 frames, exactly (until it comes down on the stub's top)"
    '(47 47 47 47 47 47) (map (lambda (k) (entity-ref (s-at k 'ball-1) #:y)) '(34 70 106 142 178 214)))
  (test-equal "… and touches the floor (y 200) between" '(200 200) (map (lambda (k) (entity-ref (s-at k 'ball-1) #:y)) '(16 52)))
  (test-equal "ball-2 has come to rest on the floor" '(200.0 0 #t)
    (pick (s-at 299 'ball-2) #:y #:vy #:on-ground?))
  (test-assert "bots stay on the floor (y 194, on-ground)"
    (every (lambda (k) (every (lambda (id) (equal? '(194 #t) (pick (s-at k id) #:y #:on-ground?))) '(bot-1 bot-2)))
           (range 0 300))))

;;; ================================================================ shmup
(define shmup (run-demo "shmup.scm"))
(define (sh-at k) (entities-at shmup k))
(define (kind k entities) (filter (lambda (e) (eq? (entity-ref e #:kind) k)) entities))

(test-group "shmup"
  (test-equal "bullets are sensors in the category bullet that collide only with enemies"
    '(#t bullet (enemy)) (pick (by-id 'bullet-1 (sh-at 5)) #:sensor? #:category #:collides-with))
  (test-equal "enemies collide only with bullets" '(enemy (bullet))
    (pick (car (kind 'enemy (sh-at 0))) #:category #:collides-with))
  (test-equal "ten enemies at the start" 10 (length (kind 'enemy (sh-at 0))))
  (test-equal "five hit, five left" 5 (length (kind 'enemy (entities-of shmup))))
  (test-equal "hits" '((23 hit enemy-1-2 by bullet-1) (55 hit enemy-1-1 by bullet-3) (63 hit enemy-0-1 by bullet-4)
                       (177 hit enemy-0-2 by bullet-6) (195 hit enemy-1-3 by bullet-7))
    (filter (lambda (e) (eq? (cadr e) 'hit)) (events-of shmup)))
  (test-equal "score: 3 × 100 (row 1) + 2 × 200 (row 0)" 700 (entity-ref (car (entities-of shmup)) #:score))
  (test-equal "seven shots, fired on the presses" '(0 10 30 36 80 150 172)
    (filter-map (lambda (s) (and (eq? (cdr s) 'shot) (car s))) (game-sounds (game-of shmup))))
  (test-equal "a 'boom for each hit" '(23 55 63 177 195)
    (filter-map (lambda (s) (and (eq? (cdr s) 'boom) (car s))) (game-sounds (game-of shmup))))
  ;; bullet-1: fired at frame 0 at (159, 210), 6 px up a frame; enemy-1-2
  ;; (16×12 at y 64) starts at x 136 and moves 1 px a frame.
  (test-equal "frame 22: bullet-1 at (159, 78), enemy-1-2 at (159, 64): not touching yet"
    '((159 78) (159 64))
    (list (pick (by-id 'bullet-1 (sh-at 22)) #:x #:y) (pick (by-id 'enemy-1-2 (sh-at 22)) #:x #:y)))
  (test-assert "one step on they overlap" (aabb-overlap? 159 72 2 6 160 64 16 12))
  (test-equal "frame 23: both gone" '(#f #f) (list (by-id 'bullet-1 (sh-at 23)) (by-id 'enemy-1-2 (sh-at 23))))
  ;; bullet-2: fired at frame 10 at y 210, so y = 210 - 6(k - 10); dropped
  ;; once its bottom is above the screen (y + 6 ≤ 0).
  (test-equal "a miss flies off the top: bullet-2 at y 0 at frame 45, gone at 46" '(0 #f)
    (list (entity-ref (by-id 'bullet-2 (sh-at 45)) #:y) (by-id 'bullet-2 (sh-at 46))))
  (test-equal "no bullets left at the end" '() (kind 'bullet (entities-of shmup)))
  ;; The ship moves by thrust 2 against #:drag 1 up to #:max-vx 3 (physics.org,
  ;; apply-speed-limits): right held from frame 120, released at 170.
  (let ((ship-x (lambda (k) (entity-ref (by-id 'ship (sh-at k)) #:x))))
    (test-equal "the ship speeds up 1, 2, 3, 3 px a frame and no faster" '(1 2 3 3)
      (map (lambda (k) (- (ship-x (+ k 1)) (ship-x k))) '(120 121 122 150)))
    (test-equal "released, its drag stops it: it glides 2, 1, then stands" '(2 1 0 0)
      (map (lambda (k) (- (ship-x (+ k 1)) (ship-x k))) '(170 171 172 173))))
  ;; The right-hand enemies (x 233 + k, 16 wide) reach 312 - 8 at frame 63.
  (test-equal "the formation turns at the edges: first enemy x at 0, 63, 64, 65"
    '(41 104 103 102)
    (map (lambda (k) (entity-ref (car (kind 'enemy (sh-at k))) #:x)) '(0 63 64 65))))

;;; ================================================================ tweens
(define tweens (run-demo "tweens.scm" 120))
(define (tw k id key) (entity-ref (entity-at tweens k id) key))
(define (tween-value start end name elapsed duration)
  (+ start (* (- end start) (ease name (/ elapsed duration)))))
(define (near? a b) (< (abs (- a b)) 1e-9))

(test-group "tweens"
  ;; dt 16 ms: after frame k a tween made before frame 0 has run 16(k+1) ms.
  (test-equal "slider (linear 20 → 220, 320 ms): frame 9 is halfway" 120.0 (tw 9 'slider #:x))
  (test-equal "slider: the target itself at the end (frame 19)" 220 (tw 19 'slider #:x))
  (test-equal "slider: chained back (cubic-in-out) — halfway at 29, home at 39" '(120.0 20)
    (list (tw 29 'slider #:x) (tw 39 'slider #:x)))
  (test-equal "bouncer (bounce-out, 640 ms): frame 19 = 160 · ease(1/2) = 122.5" 122.5 (tw 19 'bouncer #:y))
  (test-equal "bouncer: 160 at frame 39" 160 (tw 39 'bouncer #:y))
  (test-assert "pulse (sine-in-out, yoyo, repeat 3): frames 0..8"
    (every (lambda (k) (near? (tw k 'pulse #:width) (tween-value 16 32 'sine-in-out (* 16 (+ k 1)) 160)))
           (range 0 9)))
  (test-equal "pulse: the legs end at 32, 16, 32, then 16 exactly" '(32.0 16.0 32.0 16)
    (map (lambda (k) (tw k 'pulse #:width)) '(9 19 29 39)))
  (test-equal "pulse: yoyo — frame 10 mirrors frame 8" (tw 8 'pulse #:width) (tw 10 'pulse #:width))
  (test-equal "pulse: back to its start, tween gone" '(16 16 #f)
    (list (tw 40 'pulse #:width) (tw 40 'pulse #:height) (tw 40 'pulse #:tween)))
  ;; Without yoyo the cycle boundary belongs to the next cycle: at 160 ms the
  ;; value is the start again (40.0), not 80.
  (test-equal "repeater (linear, repeat 2): 60 at 4, 76 at 8, restarts: 40 at 9, 44 at 10; 80 at 29 for good"
    '(60.0 76.0 40.0 44.0 80 80) (map (lambda (k) (tw k 'repeater #:y)) '(4 8 9 10 29 60)))
  (test-equal "looper (repeat -1, yoyo): 140 at 19, 100 at 39 and 79; still running"
    '(140.0 100.0 100.0 #t) (list (tw 19 'looper #:x) (tw 39 'looper #:x) (tw 79 'looper #:x)
                                  (and (tw 119 'looper #:tween) #t)))
  (test-assert "looper stays within [100, 140]"
    (every (lambda (k) (<= 100 (tw k 'looper #:x) 140)) (range 0 120)))
  (test-assert "delayed (160 ms delay): x 200 until frame 9"
    (every (lambda (k) (= 200 (tw k 'delayed #:x))) (range 0 10)))
  (test-assert "delayed: back-out overshoots 260" (> (tw 20 'delayed #:x) 260))
  (test-equal "delayed: 260 at frame 29" 260 (tw 29 'delayed #:x))
  (test-assert "fader (ease sqrt): alpha = sqrt(t)"
    (every (lambda (k) (near? (tw k 'fader #:alpha) (sqrt (/ (* 16 (+ k 1)) 400)))) (range 0 24)))
  (test-equal "fader: 1 at frame 24" 1 (tw 24 'fader #:alpha))
  (test-equal "on-complete ran once each, at the ends"
    '((19 slider arrived) (29 repeater done) (39 slider back) (39 bouncer landed) (39 pulse done))
    (filter (lambda (e) (memq (cadr e) '(slider bouncer repeater pulse))) (events-of tweens)))
  ;; Knockback: walker at x 40 with vx 2 reaches the spikes (x 120) at frame
  ;; 34 (x 110, box 110..122); knocked back to 62 over 240 ms (15 frames).
  (test-equal "walker walks: x at frames 0, 33" '(42 108) (list (tw 0 'walker #:x) (tw 33 'walker #:x)))
  (test-equal "hits" '((34 hit at 110) (72 hit at 110) (110 hit at 110))
    (filter (lambda (e) (eq? (cadr e) 'hit)) (events-of tweens)))
  (test-equal "the knockback skips velocity-x" '(velocity-x) (tw 35 'walker #:skip-pipelines))
  (test-assert "during the knockback x is the tween's (quad-out), vx 2 ignored"
    (every (lambda (k)
             (and (near? (tw (+ 34 k) 'walker #:x) (tween-value 110 62 'quad-out (* 16 k) 240))
                  (= 2 (tw (+ 34 k) 'walker #:vx))))
           (range 1 15)))
  (test-assert "x only went back (left) while the tween ran"
    (every (lambda (k) (< (tw (+ k 1) 'walker #:x) (tw k 'walker #:x))) (range 34 48)))
  (test-equal "recovered at 62 (on-complete, frame 49); the skip is lifted"
    '((49 recovered at 62) (87 recovered at 62))
    (filter (lambda (e) (eq? (cadr e) 'recovered)) (events-of tweens)))
  ;; on-complete ran inside step-tweens, before this frame's apply-velocity-x.
  (test-equal "frame 49: 62 + vx 2, no tween, no skips; walking again after"
    '(64 #f () 66) (list (tw 49 'walker #:x) (tw 49 'walker #:tween) (tw 49 'walker #:skip-pipelines)
                         (tw 50 'walker #:x)))
  (test-equal "a 'hit sound per knockback" '((34 . hit) (72 . hit) (110 . hit)) (game-sounds (game-of tweens))))

;;; ================================================================ reproducible
;;; The same demo and script, loaded twice into fresh modules: equal scenes,
;;; events and sounds.
(define (comparable entities)
  ;; ENTITIES with each tween record as a list of its fields, procedures
  ;; (an on-complete, an easing procedure) replaced by their names.
  (define (named p) (if (procedure? p) (procedure-name p) p))
  (map (lambda (e)
         (let ((t (entity-ref e #:tween)))
           (if (tween? t)
               (entity-set e #:tween (list (tween-props t) (tween-duration t) (tween-delay t)
                                           (named (tween-ease t)) (tween-repeat t) (tween-yoyo? t)
                                           (named (tween-on-complete t)) (tween-elapsed t)))
               e)))
       entities))

(define (same-run? name frames)
  (let ((a (run-demo name frames)) (b (run-demo name frames)))
    (and (equal? (entities-of a) (entities-of b))
         (equal? (events-items-of a) (events-items-of b))
         (equal? (game-sounds (game-of a)) (game-sounds (game-of b))))))

(test-group "reproducible"
  (test-assert "platformer.scm" (same-run? "platformer.scm" 360))
  (test-assert "topdown.scm" (same-run? "topdown.scm" 420))
  (test-assert "sandbox.scm" (same-run? "sandbox.scm" 300))
  (test-assert "shmup.scm" (same-run? "shmup.scm" 240))
  ;; At frame 140 the only tween in flight is the looper's (pure data); a
  ;; knockback tween would hold an on-complete procedure, a different object
  ;; in each module (procedures compare with eq?).
  (test-assert "tweens.scm" (same-run? "tweens.scm" 140))
  (test-assert "tweens.scm mid-knockback (frame 120), tweens compared field by field"
    (equal? (comparable (entities-of (run-demo "tweens.scm" 120)))
            (comparable (entities-of (run-demo "tweens.scm" 120)))))
  (test-assert "a run is also reproducible against the first one"
    (equal? (entities-of shmup) (entities-of (run-demo "shmup.scm" 240)))))

;;; ---------------------------------------------------------------- fall
;;; The small headless script runs its 90 frames when loaded; the player
;;; jumps once, on frame 40, and the jump's sound is logged.
(let ((fall (load-demo "fall.scm")))
  (test-equal "fall: one jump sound, on frame 40" '((40 . jump)) (game-sounds (game-of fall)))
  (test-equal "fall: 90 frames ran" 90 (game-frame (game-of fall))))

(test-end "demos")
