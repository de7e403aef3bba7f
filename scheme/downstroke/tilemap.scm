;;; (downstroke tilemap) — Tiled maps and in-memory grids.
(define-module (downstroke tilemap)
  #:use-module (downstroke native)
  #:re-export (make-tilemap tilemap? tilemap-width tilemap-height
               tilemap-tile-width tilemap-tile-height tilemap-cell-solid?
               tilemap-cell-one-way? tilemap-set-tile
               tilemap-solid-extent
               tilemap-objects tilemap-gid)
  #:export (load-tilemap))

(define* (load-tilemap path #:key (solid-gids '()) (max-cells #f) (max-bytes #f))
  "Load a Tiled .tmx map (and its .tsx tilesets). SOLID-GIDS marks more gids
solid, for maps whose tilesets carry no collision metadata. MAX-CELLS bounds
the cells of all its tile layers together (default 67108864, 64 M), MAX-BYTES
the bytes read for the map and its tilesets together (default 67108864,
64 MiB); #f keeps the default. Only regular files are read."
  (%load-tilemap path solid-gids max-cells max-bytes))
