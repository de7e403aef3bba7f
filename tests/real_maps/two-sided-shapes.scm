;; SPDX-License-Identifier: MIT
;;; Real maps' convex collision polygons slanted on both their top and their
;;; underside (issue 51, item 10; semantics §12) collide as drawn: loading the
;;; maps of ../shared/corpus that use the tilesets holding them gives no
;;; warning about those tiles. The corpus is other people's work, read where
;;; it lies and unpacked into the build tree, never copied into the project;
;;; without it the check skips (exit 77), saying why.
;;;
;;; downstroke two-sided-shapes.scm CORPUS-DIR WORK-DIR
(use-modules (downstroke) (ice-9 ftw) (ice-9 textual-ports) (srfi srfi-1))

;; The tiles, as (tileset . tile id), that warned "slanted edges both on
;; its top and on its underside" before such shapes collided as drawn.
(define two-sided-tiles
  '(("orthogonal_1" . 2) ("external-fantasy" . 93) ("external-fantasy" . 105)
    ("external-fantasy-tmj" . 93) ("external-fantasy-tmj" . 105)
    ("spritesheet_ground" . 24) ("Kenny RPG Urban Pack" . 251)
    ("kenney-tileset-64px-extruded" . 120)))
(define tileset-names (delete-duplicates (map car two-sided-tiles)))

(define (fail fmt . args)
  (apply format (current-error-port) fmt args)
  (newline (current-error-port))
  (exit 1))

(define corpus (cadr (command-line)))
(define work (caddr (command-line)))
(define archives '("tiled-maps.tar.zst" "tiled-maps-with-art.tar.zst"))

(unless (every (lambda (a) (file-exists? (string-append corpus "/" a))) archives)
  (format #t "skipped: the corpus (~a) is absent\n" corpus)
  (exit 77))

;; Each archive into a folder of its own, afresh.
(for-each
 (lambda (a)
   (let ((dir (string-append work "/" a)))
     (system* "rm" "-rf" dir)
     (system* "mkdir" "-p" dir)
     (unless (zero? (status:exit-val (system* "tar" "--zstd" "-xf" (string-append corpus "/" a) "-C" dir)))
       (fail "two-sided-shapes: cannot unpack ~a" a))))
 archives)

(define (map-file? f)
  (any (lambda (ext) (string-suffix? ext f)) '(".tmx" ".tmj" ".json")))

;; The maps naming one of the tilesets (or their files), by their text.
(define maps
  (let ((found '()))
    (ftw work (lambda (f stat flag)
                (when (and (eq? flag 'regular) (map-file? f)
                           (let ((text (call-with-input-file f get-string-all)))
                             (any (lambda (n) (string-contains text n)) (cons "tilesets/ground.tsx" tileset-names))))
                  (set! found (cons f found)))
                #t))
    (sort found string<?)))

(define (names-tile? warning tile)
  ;; "tileset 'NAME' ..., tile ID:" as the loader writes it.
  (and (string-contains warning (string-append "tileset '" (car tile) "'"))
       (string-contains warning (format #f ", tile ~a: " (cdr tile)))))

(define loaded 0)
(for-each
 (lambda (f)
   (let ((warnings (catch #t
                     (lambda ()
                       (let ((m (parameterize ((current-warning-port (%make-void-port "w"))) (load-tilemap f))))
                         (set! loaded (+ loaded 1))
                         (tilemap-warnings m)))
                     (lambda args '()))))  ; maps that do not load are other checks' business
     (for-each (lambda (w)
                 (when (or (string-contains w "both on its top and on its underside")
                           (any (lambda (t) (names-tile? w t)) two-sided-tiles))
                   (fail "two-sided-shapes: ~a" w)))
               warnings)))
 maps)
;; 10 of the maps that named these tilesets loaded when this check was
;; written; fewer means the search above no longer finds them.
(when (< loaded 10)
  (fail "two-sided-shapes: only ~a of ~a maps naming the tilesets loaded" loaded (length maps)))
(format #t "two-sided-shapes: ~a maps loaded, none warns about a two-sided shape\n" loaded)
