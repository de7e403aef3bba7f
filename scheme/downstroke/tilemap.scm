;;; (downstroke tilemap) — Tiled maps and in-memory grids.
(define-module (downstroke tilemap)
  #:use-module (downstroke native)
  #:re-export (make-tilemap tilemap? tilemap-width tilemap-height
               tilemap-tile-width tilemap-tile-height tilemap-cell-solid?
               tilemap-solid-extent
               tilemap-objects tilemap-gid)
  #:export (load-tilemap))

(define* (load-tilemap path #:key (solid-gids '()))
  "Load a Tiled .tmx map (and its .tsx tilesets). SOLID-GIDS marks more gids
solid, for maps whose tilesets carry no collision metadata."
  (%load-tilemap path solid-gids))
