;; SPDX-License-Identifier: MIT
;;; scene-save and scene-load: a whole scene through one readable file,
;;; exactly, and a clear refusal of what cannot be written or read.
(use-modules (srfi srfi-64) (srfi srfi-1) (srfi srfi-11) (ice-9 textual-ports) (ice-9 ftw) (downstroke))

(load "support.scm")

(test-begin "scene-file")

(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-scene-file-XXXXXX")))
(define (in-dir name) (string-append dir "/" name))
(define (file-text file) (call-with-input-file file get-string-all))
(define (scandir* d) (scandir d (lambda (name) (not (member name '("." ".."))))))
(define (write-text file text) (call-with-output-file file (lambda (port) (display text port))))

;;; A level with two cells changed by the game, exact and inexact numbers,
;;; strings, chars and vectors in the entities, a camera at a half pixel.
(define level-file (string-append demo-dir "/maps/level1.tmx"))
(define level (load-tilemap level-file))
(define broken (tilemap-set-tile (tilemap-set-tile level 3 13 0) 4 2 7))
(define hero '(#:id hero #:x 1/3 #:y 2.5 #:width 12 #:height 14 #:vx -0.0 #:vy 0.1 #:gravity? #t
               #:name "say \"hi\"" #:bag #(1 #\a #t) #:big 123456789012345678901234567890))
(define coin '(#:type coin #:x 96 #:y 190 #:width 8 #:height 8))
(define scene (make-scene entities: (list hero coin) tilemap: broken
                          camera: (make-camera x: 12 y: 1/2) camera-target: 'hero
                          data: '(#:coins 3 #:flags (door-open) #:best 12.75)))
(define file (in-dir "level.scm"))
(test-equal "scene-save returns the file" file (scene-save scene file frame: 42))

(test-equal "the file: one datum, an entry a line"
  (string-append
   ";;; A Downstroke scene (scene-save); scene-load reads it back.\n"
   "(downstroke-scene\n"
   " (version 1)\n"
   " (frame 42)\n"
   " (tilemap (" (object->string level-file) " () #f #f #f #f))\n"
   " (tile-edits\n"
   "  (0 4 2 7)\n"
   "  (0 3 13 0))\n"
   " (camera 12 1/2)\n"
   " (camera-target hero)\n"
   " (gravity 1)\n"
   " (data (#:coins 3 #:flags (door-open) #:best 12.75))\n"
   " (entities\n"
   "  (#:id hero #:x 1/3 #:y 2.5 #:width 12 #:height 14 #:vx -0.0 #:vy 0.1 #:gravity? #t #:name \"say \\\"hi\\\"\" #:bag #(1 #\\a #t) #:big 123456789012345678901234567890)\n"
   "  (#:type coin #:x 96 #:y 190 #:width 8 #:height 8)))\n")
  (file-text file))

(let-values (((loaded frame) (scene-load file)))
  (test-equal "the frame" 42 frame)
  (test-equal "the entities, equal? (exact stays exact, -0.0 stays -0.0)" (scene-entities scene) (scene-entities loaded))
  (test-assert "… to the bit" (eqv? -0.0 (entity-ref (car (scene-entities loaded)) #:vx)))
  (test-equal "the data" '(#:coins 3 #:flags (door-open) #:best 12.75) (scene-data loaded))
  (test-equal "camera and target" '(12 1/2 hero)
    (list (camera-x (scene-camera loaded)) (camera-y (scene-camera loaded)) (scene-camera-target loaded)))
  (test-equal "the map, loaded again with the game's edits"
    (map (lambda (cell) (tilemap-gid broken 0 (car cell) (cdr cell))) '((3 . 13) (4 . 2) (5 . 13)))
    (map (lambda (cell) (tilemap-gid (scene-tilemap loaded) 0 (car cell) (cdr cell))) '((3 . 13) (4 . 2) (5 . 13))))
  (test-equal "… which the level did not have" '(0 7) (list (tilemap-gid broken 0 3 13) (tilemap-gid broken 0 4 2)))
  (test-assert "the level's cell (3, 13) was a tile" (> (tilemap-gid level 0 3 13) 0))
  (test-equal "the same scene-hash" (scene-hash scene) (scene-hash loaded))
  (test-equal "and the same next frames"
    (scene-entities (step-scene (step-scene scene 16) 16))
    (scene-entities (step-scene (step-scene loaded 16) 16))))
(test-equal "one value taken: the scene" '(#:coins 3 #:flags (door-open) #:best 12.75)
  (scene-data (scene-load file)))

;;; The scene's gravity goes with it, exact; a file without one (saved
;;; before scenes had a gravity) falls as the seed's, and a bad one is
;;; refused naming the file. (Files of their own folder: the checks below
;;; list this one's.)
(define gdir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-scene-gravity-XXXXXX")))
(define (in-gdir name) (string-append gdir "/" name))
(scene-save (make-scene entities: (list coin) gravity: 1/6) (in-gdir "moon.scm"))
(test-equal "a moon's gravity, exact" 1/6 (scene-gravity (scene-load (in-gdir "moon.scm"))))
(write-text (in-gdir "old.scm") "(downstroke-scene (version 1) (frame #f) (tilemap #f) (tile-edits) (camera 0 0) (camera-target #f) (data #f) (entities))")
(test-equal "no (gravity …): 1" 1 (scene-gravity (scene-load (in-gdir "old.scm"))))
(write-text (in-gdir "heavy.scm") "(downstroke-scene (version 1) (frame #f) (tilemap #f) (tile-edits) (camera 0 0) (camera-target #f) (gravity \"9.8\") (data #f) (entities))")
(test-assert "a gravity that is not a number is refused"
  (mentions? (error-text (lambda () (scene-load (in-gdir "heavy.scm"))))
             "heavy.scm" "(gravity …): expected a finite real number, got \"9.8\""))

;;; A scene without a map, a frame or data.
(scene-save (make-scene entities: (list coin)) (in-dir "bare.scm"))
(let-values (((loaded frame) (scene-load (in-dir "bare.scm"))))
  (test-equal '(#f #f #f ((#:type coin #:x 96 #:y 190 #:width 8 #:height 8)))
    (list frame (scene-tilemap loaded) (scene-data loaded) (scene-entities loaded))))

;;; ---------------------------------------------------------------- refused writes
(define tweened (list (append coin (list #:tween (make-tween coin props: '((#:x . 10)) duration: 100)))))
(test-assert "a tween is refused, naming the entity and key"
  (mentions? (error-text (lambda () (scene-save (make-scene entities: (list coin (car tweened))) file)))
             "In procedure scene-save: entity 1, #:tween, holds #<<tween> props: ((#:x 96 . 10))" "which is not plain data"))
(test-equal "a procedure in the data"
  "In procedure scene-save: data holds #<procedure car (_)>, which is not plain data (numbers, symbols, keywords, strings, chars, booleans, and lists and vectors of them)\n"
  (error-text (lambda () (scene-save (make-scene data: (list 1 car)) file))))
(test-equal "… and the file is left as it was, with no temporary beside it"
  (list (file-text file) '("bare.scm" "level.scm"))
  (list (file-text file) (sort (scandir* dir) string<?)))
(test-equal "a map made in memory has no file to name"
  "In procedure scene-save: tilemap: a 2 × 1 map made in memory (make-tilemap) has no file that a scene file could name; save a scene with a map from load-tilemap, or none\n"
  (error-text (lambda () (scene-save (make-scene tilemap: (make-tilemap 2 1 16 16 '(1 0) '(1))) file))))
(test-equal "In procedure scene-save: frame: expected #f or an exact integer ≥ 0, got 1.5\n"
  (error-text (lambda () (scene-save scene file frame: 1.5))))
(test-assert (mentions? (error-text (lambda () (scene-save scene (in-dir "no/such/dir.scm")))) "scene-save" "cannot write" "no/such/dir.scm"))

;;; ---------------------------------------------------------------- refused reads
(define (load-error text)
  (write-text (in-dir "bad.scm") text)
  (error-text (lambda () (scene-load (in-dir "bad.scm")))))
(define bad (object->string (in-dir "bad.scm")))
(define (scene-text entities)
  (string-append "(downstroke-scene (version 1) (frame 3) (tilemap #f) (tile-edits) (camera 0 0) (camera-target #f) (data #f) (entities " entities "))"))
(test-equal "… but #e in a string, or the char #\\\", is no prefix" '((#:name "#e1e9" #:c #\"))
  (begin (write-text (in-dir "ok.scm") (scene-text "(#:name \"#e1e9\" #:c #\\\")"))
         (scene-entities (scene-load (in-dir "ok.scm")))))
(for-each
 (lambda (case)
   (test-equal (car case)
     (string-append "In procedure scene-load: " bad ": " (cadr case) "\n")
     (load-error (caddr case))))
 ;; (name, what the refusal says after the file's name, the file's text)
 (list
  (list "read-eval is off"
   "not a scene file: it does not read as one Scheme datum (#. read expansion found and read-eval? is #f.)"
   "(downstroke-scene #.(system \"touch pwned\"))")
  (list "two datums"
   "not a scene file: more than one datum"
   "(downstroke-scene (version 1)) (more)")
  (list "not a scene"
   "not a scene file: expected (downstroke-scene (version 1) …)"
   "(hello world)")
  (list "a later version"
   "version 2, expected 1 (this engine's)"
   "(downstroke-scene (version 2))")
  (list "a missing part"
   "not a scene file: no (camera …)"
   "(downstroke-scene (version 1) (frame #f) (tilemap #f) (tile-edits) (camera-target #f) (data #f) (entities))")
  (list "an exactness prefix: a few bytes that read as a huge number"
   "not a scene file: it holds an exactness prefix (#e), which scene-save never writes and which can make a number of millions of digits from a few bytes"
   (scene-text "(#:x #e1e99999 #:name \"#e in a string is fine\")"))
  (list "an entity that is not a keyword list"
   "entity 1: expected a keyword list (#:key value …), got (#:x 1 #:y)"
   (scene-text "(#:x 0) (#:x 1 #:y)"))
  (list "a bytevector is not plain data"
   "not a scene file: the file holds #vu8(1 2), which is not plain data (numbers, symbols, keywords, strings, chars, booleans, and lists and vectors of them)"
   (scene-text "(#:x #vu8(1 2))"))
  (list "nesting past the bound"
   "not a scene file: the file: expected plain data nested at most 10000 deep (a cycle through a car or a vector?)"
   (scene-text (string-append "(#:x " (make-string 20000 #\() (make-string 20000 #\)) ")")))
  (list "a camera at NaN"
   "(camera x y): expected two numbers, got (+nan.0)"
   "(downstroke-scene (version 1) (frame #f) (tilemap #f) (tile-edits) (camera +nan.0) (camera-target #f) (data #f) (entities))")
  (list "a tile edit outside its map"
   "tile edit (0 999 0 1): expected (layer col row gid) of a cell of its map"
   (string-append "(downstroke-scene (version 1) (frame #f) (tilemap (" (object->string level-file)
                             " () #f #f #f #f)) (tile-edits (0 999 0 1)) (camera 0 0) (camera-target #f) (data #f) (entities))"))))
(test-equal "a directory"
  (string-append "In procedure scene-load: " (object->string dir) ": expected a regular file, got a directory\n")
  (error-text (lambda () (scene-load dir))))
(test-equal "a missing file"
  (string-append "In procedure scene-load: " (object->string (in-dir "none.scm")) ": cannot read it (No such file or directory)\n")
  (error-text (lambda () (scene-load (in-dir "none.scm")))))
;; Past the bound: a sparse file, refused by its size before a byte is read.
(let ((port (open-output-file (in-dir "huge.scm"))))
  (truncate-file port (+ 1 (* 8 1024 1024)))
  (close-port port))
(test-equal "a file past 8 MiB"
  (string-append "In procedure scene-load: " (object->string (in-dir "huge.scm")) ": 8388609 bytes, more than a scene file may hold (8388608)\n")
  (error-text (lambda () (scene-load (in-dir "huge.scm")))))
(test-equal "In procedure scene-load: file: expected a file name (a string), got 7\n"
  (error-text (lambda () (scene-load 7))))

(for-each (lambda (name) (delete-file (in-dir name))) (scandir* dir))
(rmdir dir)
(for-each (lambda (name) (delete-file (in-gdir name))) (scandir* gdir))
(rmdir gdir)

(test-end "scene-file")
