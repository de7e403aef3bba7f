;; SPDX-License-Identifier: MIT
;;; Maps reloaded under a running headless game (game-watch-maps!,
;;; reload-map!): the next frame's scene, the entities, the history, the
;;; game's tile edits, and a map saved broken.
(use-modules (srfi srfi-64) (downstroke) (downstroke live) (srfi srfi-1)
             (ice-9 popen) (ice-9 rdelim) (ice-9 textual-ports))

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
;; A pixel past the map's 64 px, where the first line of an error is drawn.
(define (pixel-over-the-error game)
  (game-capture game (in-dir "frame.png"))
  (game-pixel game 300 6))
(define plain-pixel (and (renderer-available?) (pixel-over-the-error game)))
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
(when (renderer-available?)
  (test-assert "drawn over the game's picture: the label's plate darkens the background"
    (not (equal? plain-pixel (pixel-over-the-error game)))))
(test-equal "the next good save is reloaded, and the error is gone" '(((3 0 0 0) (0 0 1 0) (1 1 1 1)) #f)
  (begin
    (save map-file (map-text 4 '("3,0,0,0" "0,0,0,0" "1,1,1,1")))
    (game-run! game frames: 10)
    (list (scene-gids game) ((@@ (downstroke live) live-error) ((@@ (downstroke game) game-live) game)))))
(when (renderer-available?)
  (test-equal "… from the picture too" plain-pixel (pixel-over-the-error game)))

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

;;; What a map remembers to watch: every file it was read from, each once.
(test-equal "a map with templates: the map, a tileset file, the tilesets' pictures, the templates of its objects and of a tile's shape"
  '(#t ("templates.tmx" "terrain.tsx" "terrain.png" "shapes.png" "spawn.tx" "crate.tx" "self.tx"))
  (let* ((tm (load-tilemap (string-append (dirname (current-filename)) "/../data/maps/features/templates.tmx")))
         (files (cdr ((@@ (downstroke tilemap) %tilemap-origin) tm))))
    (list (every (lambda (f) (and (absolute-file-name? f) (file-exists? f))) files)
          (map basename files))))

(test-equal "a map with an image layer: its picture too"
  '("platformer.tmx" "demo-tiles.tsx" "tiles.png" "sprites.tsx" "sprites.png" "level-tiles.tsx" "level-tiles.png" "backdrop.png")
  (map basename (cdr ((@@ (downstroke tilemap) %tilemap-origin)
                      (load-tilemap (string-append demo-dir "/maps/platformer.tmx"))))))

;;; The watched files follow the scene's map.
(define (watched-paths game)
  (map (@@ (downstroke live) watched-path)
       ((@@ (downstroke live) live-files) ((@@ (downstroke game) game-live) game))))
(test-equal "the files watched are the current map's: the map, its tileset and its picture"
  (list map-file tileset-file (in-dir "terrain.png"))
  (let ((g (make-game scene: (make-scene tilemap: (load-tilemap map-file)))))
    (game-watch-maps! g #t)
    (watched-paths g)))
(test-equal "a scene with a map made in memory: none, from the next look; a save then changes nothing" '(() #t)
  (let ((g (make-game scene: (make-scene tilemap: (load-tilemap map-file))))
        (in-memory (make-tilemap 2 2 16 16 '(0 0 0 0) '())))
    (game-watch-maps! g #t)
    (game-scene-set! g (make-scene tilemap: in-memory))
    (poll-watched-files! g)
    (save map-file (map-text 4 '("1,1,1,1" "0,0,0,0" "1,1,1,1")))
    (poll-watched-files! g)
    (list (watched-paths g) (eq? in-memory (scene-tilemap (game-scene g))))))

;;; New games watch their maps when watch-default is true (the host's --watch).
(test-equal "watch-default" '(#t #f)
  (list (parameterize ((watch-default #t)) (game-watching-maps? (make-game)))
        (game-watching-maps? (make-game))))

;;; ---------------------------------------------------------------- the host
(define host (readlink "/proc/self/exe"))
(define (run-host . argv)
  ;; (exit status, stdout, stderr) of the host run with ARGV.
  (let* ((err (in-dir "stderr"))
         (cmd (string-append (string-join (map (lambda (a) (string-append "'" a "'")) (cons host argv)) " ")
                             " 2>'" err "'"))
         (p (open-pipe* OPEN_READ "/bin/sh" "-c" cmd))
         (out (get-string-all p))
         (status (status:exit-val (close-pipe p))))
    (list status out (call-with-input-file err get-string-all))))
(define watching-script (in-dir "watching.scm"))
(write-file watching-script "(display (game-watching-maps? (make-game)))\n")
(test-equal "headless, games do not watch their maps by default" '(0 "#f" "")
  (run-host "--no-auto-compile" watching-script))
(test-equal "--watch: they do" '(0 "#t" "") (run-host "--no-auto-compile" "--watch" watching-script))
(when (renderer-available?)
  (test-equal "--window: they do" '(0 "#t" "") (run-host "--no-auto-compile" "--window" watching-script))
  (test-equal "--window --no-watch: they do not" '(0 "#f" "")
    (run-host "--no-auto-compile" "--window" "--no-watch" watching-script)))
(test-equal "--watch and --no-watch together are refused" '(2 "" "downstroke: --watch and --no-watch exclude each other\n")
  (run-host "--watch" "--no-watch" watching-script))

;;; A game served to a REPL watches its map by default, and reloads it as
;;; a game in a window does.
(define served-script (in-dir "served.scm"))
(write-file served-script
            (string-append "(watch-poll-interval 0)
(define game (make-game scene: (make-scene tilemap: (load-tilemap " (object->string map-file) "))))
(format #t \"~a~%\" (game-watching-maps? game)) (force-output)
(game-run! game frames: 3000)
(exit 3)
"))
(define (connect-when-ready path tries)
  (let ((s (socket PF_UNIX SOCK_STREAM 0)))
    (catch 'system-error
      (lambda () (connect s AF_UNIX path) s)
      (lambda args
        (close-port s)
        (if (zero? tries) (apply throw args) (begin (usleep 50000) (connect-when-ready path (- tries 1))))))))
(define prompt "scheme@(guile-user)> ")
(define (read-until port marker)
  ;; What PORT sends up to and including MARKER (or its end).
  (let loop ((acc ""))
    (if (string-suffix? marker acc)
        acc
        (let ((ch (read-char port)))
          (if (eof-object? ch) acc (loop (string-append acc (string ch))))))))
(define (value c text)
  ;; The value TEXT evaluates to in the served game, from its "$N = VALUE".
  (display text c) (newline c) (force-output c)
  (let* ((r (read-until c prompt)) (at (string-contains r " = ")))
    (and at (read (open-input-string (substring r (+ at 3)))))))
(save map-file (map-text 4 '("0,0,0,0" "0,0,0,0" "1,1,1,1")))
(define socket-path (in-dir "repl.sock"))
(define served (open-pipe* OPEN_READ host "--no-auto-compile" "--repl-server" socket-path served-script))
(test-equal "served: the game watches its map" "#t" (read-line served))
(define client (connect-when-ready socket-path 100))
(read-until client prompt)
(define gid-at-0-0 "(tilemap-gid (scene-tilemap (game-scene game)) 0 0 0)")
(test-equal "the map as loaded" 0 (value client gid-at-0-0))
(save map-file (map-text 4 '("2,0,0,0" "0,0,0,0" "1,1,1,1")))
(test-equal "saved: the served game's scene has the new map within a few frames" 2
  ;; Asked again, at most 100 times 20 ms apart, until the save is seen.
  (let wait ((tries 100))
    (let ((gid (value client gid-at-0-0)))
      (if (or (eqv? gid 2) (zero? tries)) gid (begin (usleep 20000) (wait (- tries 1)))))))
(save map-file (map-text 4 '("3,0,0,0" "0,0,0,0" "1,1,1,1")))
(test-equal "(reload-map!) by hand in the REPL reads it at once" '(#t 3)
  (list (value client "(reload-map!)") (value client gid-at-0-0)))
(display "(game-update-set! game (lambda (g dt) (exit 0)))\n" client)
(force-output client)
(test-equal "the served game ends when asked" 0 (status:exit-val (close-pipe served)))
(close-port client)

(system* "rm" "-rf" dir)
(test-end "live-maps")
