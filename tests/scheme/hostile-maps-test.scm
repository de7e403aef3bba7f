;; SPDX-License-Identifier: MIT
;;; load-tilemap and make-tilemap against maps built to exhaust, hang or
;;; confuse the loader (issue 19): each is an error naming the procedure, the
;;; file and the value, and the suite finishing shows the time is bounded.
;;; The maps are tests/data/maps/hostile (make_hostile_maps.py); the FIFO is
;;; made here, in a temporary directory.
(use-modules (srfi srfi-64) (downstroke))

(load "support.scm")

;;; Relative to the project root (ctest's working directory), so that the
;;; messages compared below stay short of the 256 bytes a native error holds
;;; wherever the checkout is.
(define data "tests/data")
(define (hostile name) (string-append data "/maps/hostile/" name))
(define (map-file name) (string-append data "/maps/" name))

;;; The key and the printed message of THUNK's error, or 'no-error.
(define (failure thunk)
  (catch #t
    (lambda () (thunk) 'no-error)
    (lambda (key . args)
      (list key (call-with-output-string (lambda (port) (print-exception port #f key args)))))))

(define (load-failure path . options)
  (failure (lambda () (apply load-tilemap path options))))

(define (in-load-tilemap path line message)
  (list 'misc-error
        (string-append "In procedure load-tilemap: " path ":" (number->string line) ": " message "\n")))

(define limit "more than the loader's limit of 67108864 cells (max-cells)")

(test-begin "hostile-maps")

;;; ---------------------------------------------------------------- the audit's cases
(test-equal "64 layers of 4096² zstd (4 GB decoded): refused at the fifth, before decoding"
  (in-load-tilemap (hostile "zstd_bomb.tmx") 16
                   (string-append "layer 'layer4' (16777216 cells) brings the map's tile layers to " limit))
  (load-failure (hostile "zstd_bomb.tmx")))
(test-equal "a tileset that is /dev/zero"
  (in-load-tilemap (hostile "tileset_zero.tmx") 3
                   "cannot open tileset '/dev/zero': is not a regular file (a character device)")
  (load-failure (hostile "tileset_zero.tmx")))
(test-equal "a tileset that is /dev/urandom"
  (in-load-tilemap (hostile "tileset_urandom.tmx") 3
                   "cannot open tileset '/dev/urandom': is not a regular file (a character device)")
  (load-failure (hostile "tileset_urandom.tmx")))
(test-equal "a tile object upside down (it corrupted the heap)"
  (in-load-tilemap (hostile "object_negative_height.tmx") 8 "<object> attribute height='-50' is negative")
  (load-failure (hostile "object_negative_height.tmx")))
(test-equal "a collision polygon of 6000 points (it took 39 s)"
  (in-load-tilemap (hostile "polygon_bomb.tmx") 3
                   "tileset 't', tile 0: a collision shape of 6000 points, more than the 256 a shape may have")
  (load-failure (hostile "polygon_bomb.tmx")))
(let* ((dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-hostile-XXXXXX")))
       (fifo (string-append dir "/pipe.tsx"))
       (tmx (string-append dir "/pipe.tmx")))
  (mknod fifo 'fifo #o600 0)
  (call-with-output-file tmx
    (lambda (port)
      (display (string-append
                "<?xml version=\"1.0\"?>\n<map orientation=\"orthogonal\" width=\"1\" height=\"1\" "
                "tilewidth=\"16\" tileheight=\"16\">\n <tileset firstgid=\"1\" source=\"pipe.tsx\"/>\n"
                " <layer name=\"l\"><data encoding=\"csv\">0</data></layer>\n</map>\n")
               port)))
  (test-equal "a tileset that is a FIFO: no wait for a writer"
    (in-load-tilemap tmx 3 (string-append "cannot open tileset '" fifo "': is not a regular file (a FIFO)"))
    (load-failure tmx))
  (test-equal "a map that is a FIFO"
    (list 'misc-error (string-append "In procedure load-tilemap: " fifo
                                     ": cannot open map: is not a regular file (a FIFO)\n"))
    (load-failure fifo))
  (delete-file fifo)
  (delete-file tmx)
  (rmdir dir))
(test-equal "a 0x0 map with a 6x4 layer"
  (in-load-tilemap (hostile "zero_size.tmx") 2 "map size 0x0 is not positive")
  (load-failure (hostile "zero_size.tmx")))
(test-equal "a layer wider than its map"
  (in-load-tilemap (hostile "layer_wider.tmx") 4 "layer 'ground' is 6x2 cells but the map is 2x2")
  (load-failure (hostile "layer_wider.tmx")))
(test-equal "tilewidth 2^31-1, which make-tilemap refuses too"
  (in-load-tilemap (hostile "huge_tilewidth.tmx") 2
                   "tile size 2147483647x16 is larger than the limit of 16777216 px")
  (load-failure (hostile "huge_tilewidth.tmx")))
(test-equal "make-tilemap refuses the same tile width"
  '(wrong-type-arg "In procedure make-tilemap: tile-width: expected an exact integer from 1 to 16777216, got 2147483647\n")
  (failure (lambda () (make-tilemap 1 1 2147483647 16 #(0) '()))))
(test-equal "a stream that runs past its layer stops at the layer's 16 bytes"
  (in-load-tilemap (hostile "zstd_overlong.tmx") 5
                   "layer 'ground': decompressed zstd data is larger than the 16 bytes the layer size allows")
  (load-failure (hostile "zstd_overlong.tmx")))
(test-equal "groups nested 40 deep"
  (in-load-tilemap (hostile "deep_groups.tmx") 35 "<group> nested more than 32 deep")
  (load-failure (hostile "deep_groups.tmx")))

;;; ---------------------------------------------------------------- max-cells: and max-bytes:
(test-equal "max-cells: 48 holds layers.tmx's four 4x3 layers" 3
  (tilemap-height (load-tilemap (map-file "layers.tmx") max-cells: 48)))
(test-equal "max-cells: 47 refuses the fourth"
  (in-load-tilemap (map-file "layers.tmx") 46
                   "layer 'hidden' (12 cells) brings the map's tile layers to more than the loader's limit of 47 cells (max-cells)")
  (load-failure (map-file "layers.tmx") #:max-cells 47))
(test-equal "max-cells: #f keeps the default" 6
  (tilemap-width (load-tilemap (map-file "level_csv.tmx") max-cells: #f)))
(test-equal "max-bytes: too small for the map"
  (list 'misc-error
        (string-append "In procedure load-tilemap: " (map-file "level_csv.tmx")
                       ": cannot open map: is " (number->string (stat:size (stat (map-file "level_csv.tmx"))))
                       " bytes, more than the 100 bytes max-bytes allows\n"))
  (load-failure (map-file "level_csv.tmx") #:max-bytes 100))
(test-equal "max-cells: 0"
  '(wrong-type-arg "In procedure load-tilemap: max-cells: expected a positive exact integer or #f, got 0\n")
  (load-failure (map-file "level_csv.tmx") #:max-cells 0))
(test-equal "max-bytes: a string"
  '(wrong-type-arg "In procedure load-tilemap: max-bytes: expected a positive exact integer or #f, got \"1\"\n")
  (load-failure (map-file "level_csv.tmx") #:max-bytes "1"))
(test-equal "make-tilemap: more cells than the limit, refused before the cells are read"
  '(out-of-range "In procedure make-tilemap: map size 16384x8192 is more than the max-cells limit of 67108864 cells\n")
  (failure (lambda () (make-tilemap 16384 8192 8 8 #() '()))))

(test-end "hostile-maps")
