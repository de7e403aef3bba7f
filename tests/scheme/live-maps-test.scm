;; SPDX-License-Identifier: MIT
;;; Maps reloaded under a running headless game (game-watch-maps!,
;;; reload-map!): the next frame's scene, the entities, the history, the
;;; game's tile edits, and a map saved broken.
(use-modules (srfi srfi-64) (downstroke) (downstroke live) (srfi srfi-1))

(load "support.scm")

(test-begin "live-maps")

(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-live-maps-XXXXXX")))
(define (in-dir name) (string-append dir "/" name))
(define (write-file path text)
  (call-with-output-file path (lambda (port) (display text port))))
(define (save path text)
  ;; As Tiled saves: a new file renamed over the old one.
  (write-file (string-append path ".new") text)
  (rename-file (string-append path ".new") path))
(define (warnings-of thunk)
  (let ((port (open-output-string)))
    (parameterize ((current-warning-port port)) (thunk))
    (get-output-string port)))

;; Every poll looks (the default waits a second between looks).
(watch-poll-interval 0)

;;; A 4 × 3 map of 16 px cells whose tileset, in a file of its own, makes
;;; gid 1 solid; the picture is a 64 × 32 PNG of the test data.
(copy-file (string-append (dirname (current-filename)) "/../data/maps/images/terrain.png") (in-dir "terrain.png"))
(define (tileset-text solid-id)
  (string-append "<?xml version=\"1.0\" encoding=\"UTF-8\"?>
<tileset version=\"1.10\" name=\"t\" tilewidth=\"16\" tileheight=\"16\" tilecount=\"8\" columns=\"4\">
 <image source=\"terrain.png\" width=\"64\" height=\"32\"/>
 <tile id=\"" (number->string solid-id) "\"><properties><property name=\"solid\" type=\"bool\" value=\"true\"/></properties></tile>
</tileset>
"))
(define (map-text width rows)
  ;; ROWS: a list of strings of comma-separated gids, one for each row.
  (string-append "<?xml version=\"1.0\" encoding=\"UTF-8\"?>
<map version=\"1.10\" orientation=\"orthogonal\" renderorder=\"right-down\" width=\"" (number->string width)
                 "\" height=\"" (number->string (length rows)) "\" tilewidth=\"16\" tileheight=\"16\" infinite=\"0\">
 <tileset firstgid=\"1\" source=\"t.tsx\"/>
 <layer id=\"1\" name=\"ground\" width=\"" (number->string width) "\" height=\"" (number->string (length rows)) "\">
  <data encoding=\"csv\">
" (string-join rows ",\n") "
  </data>
 </layer>
</map>
"))
(define map-file (in-dir "level.tmx"))
(define tileset-file (in-dir "t.tsx"))
(write-file tileset-file (tileset-text 0))
(write-file map-file (map-text 4 '("0,0,0,0" "0,0,0,0" "1,1,1,1")))

(define (gids tm)
  ;; Layer 0's gids, row by row.
  (map (lambda (row) (map (lambda (col) (tilemap-gid tm 0 col row)) (iota (tilemap-width tm))))
       (iota (tilemap-height tm))))
(define (scene-gids game) (gids (scene-tilemap (game-scene game))))

;; A box resting on the floor at column 3; the game sets its #:score in
;; frame 2 and puts a tile at (2, 1) in frame 3.
(define (make-level-game)
  (make-game history: 20
             scene: (make-scene entities: (list (list #:id 'box #:x 48 #:y 16 #:width 16 #:height 16
                                                      #:gravity? #t #:score 0))
                                tilemap: (load-tilemap map-file))
             update: (lambda (game dt)
                       (case (game-frame game)
                         ((2) (game-scene-set! game
                                (update-scene (game-scene game)
                                              #:entities (map (lambda (e) (entity-set e #:score 7))
                                                              (scene-entities (game-scene game))))))
                         ((3) (let ((s (game-scene game)))
                                (game-scene-set! game (update-scene s #:tilemap (tilemap-set-tile (scene-tilemap s) 2 1 1)))))))))
(define (box game) (car (scene-entities (game-scene game))))

(define game (make-level-game))
(test-equal "a new game does not watch its maps" #f (game-watching-maps? game))
(game-watch-maps! game #t)
(test-equal "game-watch-maps! #t: it does" #t (game-watching-maps? game))
(game-run! game frames: 5)
(test-equal "before the save: the map as loaded, with the game's edit at (2, 1)"
  '((0 0 0 0) (0 0 1 0) (1 1 1 1)) (scene-gids game))

(save map-file (map-text 4 '("2,0,0,0" "0,0,0,0" "0,1,1,1")))
(game-run! game frames: 6)
(test-equal "saved under the running game: the next frame's scene has the new map, the edit re-applied"
  '((2 0 0 0) (0 0 1 0) (0 1 1 1)) (scene-gids game))
(test-equal "its entities kept their state: the box still rests, its score kept" '(16 #t 7)
  (map (lambda (k) (entity-ref (box game) k)) '(#:y #:on-ground? #:score)))
(test-equal "the history keeps the map each scene had: frame 4 started on the old one, frame 5 on the new"
  '(((0 0 0 0) (0 0 1 0) (1 1 1 1)) ((2 0 0 0) (0 0 1 0) (0 1 1 1)))
  (map (lambda (f) (gids (scene-tilemap (assv-ref (game-history game) f)))) '(4 5)))
(test-equal "rewound past the reload: the old map, and stepping on keeps it" '(4 6 (1 1 1 1))
  (let ((frame (game-rewind! game 2)))
    (game-run! game frames: 6)
    (list frame (game-frame game) (list-ref (scene-gids game) 2))))

;;; A tileset changed: the map is read again with it.
(test-equal "the tileset saved: gid 2 is now the solid one" '(#f #t)
  (begin
    (save tileset-file (tileset-text 1))
    (game-run! game frames: 7)
    (let ((tm (scene-tilemap (game-scene game))))
      (list (tilemap-cell-solid? tm 1 2) (tilemap-cell-solid? tm 0 0)))))

;;; A map saved broken: the game runs on with the map it had, the error said.
(define before-broken (scene-tilemap (game-scene game)))
(define broken-report
  (warnings-of (lambda ()
                 (save map-file "<?xml version=\"1.0\"?><map width=\"4\"")
                 (game-run! game frames: 9))))
(test-equal "a broken save: the game ran on, on the map it had" '(9 #t)
  (list (game-frame game) (eq? before-broken (scene-tilemap (game-scene game)))))
(test-assert "the error is on the warning port, naming the file"
  (mentions? broken-report
             (string-append "downstroke: reload-map!: the map " map-file
                            " did not load; the game runs on with the map it had:\n")
             "In procedure load-tilemap: "))
(test-assert "and is shown over the game's picture until a reload succeeds"
  (string? ((@@ (downstroke live) live-error) ((@@ (downstroke game) game-live) game))))
(test-equal "the next good save is reloaded, and the error is gone" '(((3 0 0 0) (0 0 1 0) (1 1 1 1)) #f)
  (begin
    (save map-file (map-text 4 '("3,0,0,0" "0,0,0,0" "1,1,1,1")))
    (game-run! game frames: 10)
    (list (scene-gids game) ((@@ (downstroke live) live-error) ((@@ (downstroke game) game-live) game)))))

;;; A tile edit whose cell the new map no longer has is dropped, said.
(define narrowed-report
  (warnings-of (lambda ()
                 (save map-file (map-text 2 '("0,0" "0,0" "1,1")))
                 (game-run! game frames: 11))))
(test-equal "the map saved two columns narrower: the edit at (2, 1) is gone with its cell"
  '((0 0) (0 0) (1 1)) (scene-gids game))
(test-equal "dropped with a warning naming the layer and the cell"
  "reload-map!: warning: the game's edit of tile layer 0, cell (2, 1) (gid 1) is dropped: cell (2, 1) is outside tile layer 0\n"
  narrowed-report)

;;; By hand, and not watching.
(test-equal "game-watch-maps! #f: a save is not seen" '(#f ((0 0) (0 0) (1 1)))
  (begin
    (game-watch-maps! game #f)
    (save map-file (map-text 4 '("1,0,0,0" "0,0,0,0" "1,1,1,1")))
    (game-run! game frames: 12)
    (list (game-watching-maps? game) (scene-gids game))))
(test-equal "reload-map! reads it now" '(#t ((1 0 0 0) (0 0 0 0) (1 1 1 1)))
  (let ((result (reload-map! game)))
    (list result (scene-gids game))))
(test-equal "reload-map! without a game, outside game-run!: refused by name"
  "In procedure reload-map!: game: expected a game (make-game), got #f\n"
  (error-text (lambda () (reload-map!))))
(test-equal "reload-map! in a game's hook reloads that game's map" #t
  (let* ((seen #f)
         (g (make-game scene: (make-scene tilemap: (load-tilemap map-file))
                       update: (lambda (game dt) (set! seen (reload-map!))))))
    (game-run! g frames: 1)
    seen))
(test-equal "reload-map! of a scene with no map from a file: #f" #f
  (reload-map! (make-game scene: (make-scene tilemap: (make-tilemap 2 2 16 16 '(0 0 0 0) '())))))
(test-equal "game-watch-maps!: not a game"
  "In procedure game-watch-maps!: game: expected a game (make-game), got 1\n"
  (error-text (lambda () (game-watch-maps! 1 #t))))

;;; New games watch their maps when watch-default is true (the host's --watch).
(test-equal "watch-default" '(#t #f)
  (list (parameterize ((watch-default #t)) (game-watching-maps? (make-game)))
        (game-watching-maps? (make-game))))

(system* "rm" "-rf" dir)
(test-end "live-maps")
