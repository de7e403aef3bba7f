;; SPDX-License-Identifier: MIT
;;; (downstroke tilemap) — Tiled maps and in-memory grids.
(define-module (downstroke tilemap)
  #:use-module ((downstroke native) #:hide (tilemap-set-tile))
  #:use-module ((downstroke native) #:select ((tilemap-set-tile . %tilemap-set-tile)))
  #:re-export (make-tilemap tilemap? tilemap-width tilemap-height
               tilemap-tile-width tilemap-tile-height tilemap-cell-solid?
               tilemap-cell-one-way?
               tilemap-solid-extent tilemap-cell-shape tilemap-steepest-ramp
               tilemap-objects tilemap-gid
               tilemap-properties tilemap-layers tilemap-tilesets
               tilemap-warnings)
  #:export (load-tilemap tilemap-set-tile))

;; A loaded map → the arguments it was loaded with, (path solid-gids
;; max-cells max-bytes strict? project), kept by its edits (tilemap-set-tile):
;; what scene-save writes to name it. Weak: a map no one holds is dropped.
(define %tilemap-source (make-object-property))

;; A loaded map → (loaded . files): the map as load-tilemap returned it (#f
;; for the map itself, which a weak table's value must not hold), before
;; the game's edits, and the absolute names of the files it was read from.
;; Kept by its edits, as the source is: (downstroke live) watches the files,
;; and re-applies the edits (the cells that differ from LOADED) to the map
;; read again.
(define %tilemap-origin (make-object-property))

;; PATH against the current folder; (downstroke live) names files so too.
(define (absolute path)
  (if (absolute-file-name? path) path (string-append (getcwd) "/" path)))

(define (read-files tm project)
  ;; The map's files, its project's too, each once, in the order read.
  (let loop ((files (append (%tilemap-files tm) (if (string? project) (list project) '())))
             (seen '()))
    (cond ((null? files) (reverse seen))
          ((member (absolute (car files)) seen) (loop (cdr files) seen))
          (else (loop (cdr files) (cons (absolute (car files)) seen))))))

(define* (load-tilemap path #:key (solid-gids '()) (max-cells #f) (max-bytes #f)
                       (strict? #f) (project #f))
  "Load a Tiled map (.tmx or .tmj) and the tilesets (.tsx, .tsj) and
templates (.tx, .tj) it names. SOLID-GIDS marks more gids solid, for maps
whose tilesets carry no collision metadata. MAX-CELLS bounds the cells of all
its tile layers together (default 67108864, 64 M), MAX-BYTES the bytes read
for the map and every file it names together (default 67108864, 64 MiB); #f
keeps the default. Only regular files are read. A gid beyond every tileset
loads as an empty, non-solid cell with a warning on (current-warning-port),
kept in (tilemap-warnings map), and so does a picture it names (a tileset's,
a tile's, an image layer's) that cannot be opened; STRICT? #t makes each an
error instead.
PROJECT names a Tiled project file (.tiled-project) whose class types fill in
the members a class property leaves at their defaults. The map remembers the
files it was read from, so that a game watching its maps (game-watch-maps!)
reloads it when one of them changes."
  (let ((tm (%load-tilemap path solid-gids max-cells max-bytes strict? project)))
    (set! (%tilemap-source tm) (list path solid-gids max-cells max-bytes strict? project))
    (set! (%tilemap-origin tm) (cons #f (read-files tm project)))
    (for-each (lambda (warning)
                (display "load-tilemap: warning: " (current-warning-port))
                (display warning (current-warning-port))
                (newline (current-warning-port)))
              (tilemap-warnings tm))
    tm))

(define (tilemap-set-tile tm col row gid . layer)
  "(tilemap-set-tile tm col row gid [layer]): a new map whose cell (col, row)
of tile layer number layer (0) holds gid (0 clears it), solidity and all; tm
is unchanged."
  (let ((edited (apply %tilemap-set-tile tm col row gid layer))
        (source (%tilemap-source tm))
        (origin (%tilemap-origin tm)))
    (when source (set! (%tilemap-source edited) source))
    (when origin (set! (%tilemap-origin edited) (cons (or (car origin) tm) (cdr origin))))
    edited))
