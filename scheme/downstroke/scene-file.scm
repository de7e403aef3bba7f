;; SPDX-License-Identifier: MIT
;;; (downstroke scene-file) — a whole scene in one readable file: a saved
;;; game, or a bug report that carries the scene it is about.
;;;
;;; The file is one Scheme datum, (downstroke-scene (version 1) (frame …)
;;; …), written with `write', so exact numbers stay exact and a flonum
;;; reads back to the bit. A map is named by the file and options it was
;;; loaded with, and the game's edits of it are listed cell by cell.
(define-module (downstroke scene-file)
  #:use-module (downstroke error-text)
  #:use-module (srfi srfi-1)
  #:use-module (downstroke world)
  #:use-module (downstroke tilemap)
  #:use-module ((downstroke plain-data) #:select (check-plain-data))
  #:export (scene-save scene-load))

(define tilemap-source (@@ (downstroke tilemap) %tilemap-source))
(define load-map (@@ (downstroke tilemap) %load-tilemap))

;; The format's version, first in every file: a later format can then read
;; this one, and this one refuses a later one by name.
(define scene-file-version 1)

;; A scene file larger than this is refused before it is read: Guile's
;; reader takes about 0.75 s a MiB here (a 14.2 MB file of 80 000 entities
;; loaded in 10.9 s), so a hostile file costs at most about 6 s, and 8 MiB
;; holds some 45 000 entities of 180 bytes (docs/limits.org, "Scene files").
(define max-scene-file-bytes (* 8 1024 1024))

;;; ---------------------------------------------------------------- writing

(define (tile-layer-count tm)
  ;; Tile layers are numbered in file order, groups flattened (tilemap-gid).
  (let count ((layers (tilemap-layers tm)))
    (fold (lambda (layer n)
            (case (and (pair? layer) (memq #:kind layer) (cadr (memq #:kind layer)))
              ((tile) (+ n 1))
              ((group) (+ n (count (cadr (memq #:layers layer)))))
              (else n)))
          0 layers)))

(define (tile-edits original tm)
  ;; Every cell whose gid differs from the map as loaded: (layer col row gid).
  (let ((layers (tile-layer-count tm)) (w (tilemap-width tm)) (h (tilemap-height tm)))
    (let loop ((layer 0) (row 0) (col 0) (acc '()))
      (cond ((= layer layers) (reverse! acc))
            ((= row h) (loop (+ layer 1) 0 0 acc))
            ((= col w) (loop layer (+ row 1) 0 acc))
            (else
             (let ((gid (tilemap-gid tm layer col row)))
               (loop layer row (+ col 1)
                     (if (= gid (tilemap-gid original layer col row)) acc (cons (list layer col row gid) acc)))))))))

(define (map-entry who tm)
  ;; (tilemap SOURCE EDITS), or (tilemap #f ()) for none.
  (cond ((not tm) '((tilemap #f) (tile-edits ())))
        ((tilemap-source tm)
         => (lambda (source)
              (let ((original (apply load-map source)))
                `((tilemap ,source) (tile-edits ,@(tile-edits original tm))))))
        (else
         (scm-error 'wrong-type-arg who
                    "tilemap: a ~a × ~a map made in memory (make-tilemap) has no file that a scene file could name; save a scene with a map from load-tilemap, or none"
                    (list (tilemap-width tm) (tilemap-height tm)) #f))))

(define (check-entity who i entity)
  ;; A keyword list whose every value is plain data, named by its place.
  (let loop ((p entity))
    (cond ((null? p) #t)
          ((and (pair? p) (keyword? (car p)) (pair? (cdr p)))
           (check-plain-data who (let ((key (car p))) (lambda () (format #f "entity ~a, ~s," i key))) (cadr p))
           (loop (cddr p)))
          (else (scm-error 'wrong-type-arg who "entity ~a: expected a keyword list (#:key value …), got ~S"
                           (list i entity) #f)))))

(define (scene-datum who scene frame)
  (let ((camera (scene-camera scene)))
    (check-plain-data who "camera-target" (scene-camera-target scene))
    (check-plain-data who "data" (scene-data scene))
    (for-each (lambda (e i) (check-entity who i e)) (scene-entities scene) (iota (length (scene-entities scene))))
    `(downstroke-scene
      (version ,scene-file-version)
      (frame ,frame)
      ,@(map-entry who (scene-tilemap scene))
      (camera ,(camera-x camera) ,(camera-y camera))
      (camera-target ,(scene-camera-target scene))
      (gravity ,(scene-gravity scene))
      (data ,(scene-data scene))
      (entities ,@(scene-entities scene)))))

(define (write-scene-file datum port)
  (display ";;; A Downstroke scene (scene-save); scene-load reads it back.\n" port)
  ;; An entry a line, so that a diff of two scene files shows what changed.
  (display "(downstroke-scene" port)
  (for-each (lambda (part)
              (display "\n (" port)
              (write (car part) port)
              (for-each (lambda (item)
                          (display (if (memq (car part) '(entities tile-edits)) "\n  " " ") port)
                          (write item port))
                        (cdr part))
              (display ")" port))
            (cdr datum))
  (display ")\n" port))

(define* (scene-save scene file #:key (frame #f))
  "Write SCENE to FILE as one readable Scheme datum that scene-load reads
back: its entities, data, gravity, camera position, camera target, its map (the file
and options load-tilemap was given) with every cell the game changed
(tilemap-set-tile), and FRAME (an exact integer such as (game-frame game),
or #f). Exact numbers stay exact; flonums read back to the bit. Every
entity value and the data must be plain data (numbers, symbols, keywords,
strings, chars, booleans, lists, vectors): anything else, such as a tween
or a procedure, is an error naming the entity and key, and FILE is then
left as it was. The file is written whole or not at all (a temporary file
renamed onto FILE)."
  (unless (scene? scene)
    (scm-error 'wrong-type-arg "scene-save" "scene: expected a scene, got ~S" (list scene) #f))
  (unless (string? file)
    (scm-error 'wrong-type-arg "scene-save" "file: expected a file name (a string), got ~S" (list file) #f))
  (unless (or (not frame) (and (exact-integer? frame) (>= frame 0)))
    (scm-error 'wrong-type-arg "scene-save" "frame: expected #f or an exact integer ≥ 0, got ~S" (list frame) #f))
  (let* ((datum (scene-datum "scene-save" scene frame))
         (port (catch 'system-error
                 (lambda () (mkstemp (string-append file ".XXXXXX")))
                 (lambda (key . args)
                   (scm-error 'system-error "scene-save" "cannot write ~S: ~a"
                              (list file (strerror (system-error-errno (cons key args)))) #f))))
         (temporary (port-filename port)))
    (catch #t
      (lambda ()
        (write-scene-file datum port)
        (close-port port)
        (chmod temporary (logand #o666 (lognot (umask))))
        (rename-file temporary file))
      (lambda (key . args)
        (unless (port-closed? port) (close-port port))
        (when (file-exists? temporary) (delete-file temporary))
        (apply throw key args)))
    file))

;;; ---------------------------------------------------------------- reading

(define (exactness-prefix? text)
  ;; Whether TEXT holds #e or #E outside a string: #e1e99999 is 10 bytes
  ;; that read as a number of 41 KB, so a file within the size bound could
  ;; still take gigabytes. The scan runs only when the text holds one at all.
  (and (or (string-contains text "#e") (string-contains text "#E"))
       (let ((n (string-length text)))
         (let scan ((i 0) (in-string? #f))
           (and (< i n)
                (let ((c (string-ref text i)))
                  (cond (in-string? (case c
                                      ((#\\) (scan (+ i 2) #t))
                                      ((#\") (scan (+ i 1) #f))
                                      (else (scan (+ i 1) #t))))
                        ((char=? c #\") (scan (+ i 1) #t))
                        ((and (char=? c #\#) (< (+ i 1) n) (char=? (string-ref text (+ i 1)) #\\))
                         (scan (+ i 3) #f))   ; a char: #\" is no string
                        ((and (char=? c #\#) (< (+ i 1) n) (memv (string-ref text (+ i 1)) '(#\e #\E))) #t)
                        (else (scan (+ i 1) #f)))))))))

(define (refuse file message . args)
  (scm-error 'misc-error "scene-load" (string-append "~s: " message) (cons file args) #f))

(define (read-whole file)
  ;; The one datum FILE holds, read as data only.
  (let ((st (catch 'system-error
              (lambda () (stat file))
              (lambda (key . args)
                (refuse file "cannot read it (~a)" (strerror (system-error-errno (cons key args))))))))
    (unless (eq? (stat:type st) 'regular)
      (refuse file "expected a regular file, got a ~a" (stat:type st)))
    (when (> (stat:size st) max-scene-file-bytes)
      (refuse file "~a bytes, more than a scene file may hold (~a)" (stat:size st) max-scene-file-bytes))
    (let ((text (catch #t
                  (lambda () (call-with-input-file file (lambda (port) ((@ (ice-9 textual-ports) get-string-all) port))))
                  (lambda (key . args) (refuse file "cannot read it (~a)" key)))))
      ;; Read as text already in memory: a file that grows while it is read
      ;; cannot pass the bound.
      (when (> (string-length text) max-scene-file-bytes)
        (refuse file "more than a scene file may hold (~a bytes)" max-scene-file-bytes))
      (when (exactness-prefix? text)
        (refuse file "not a scene file: it holds an exactness prefix (#e), which scene-save never writes and which can make a number of millions of digits from a few bytes"))
      (call-with-input-string text
        (lambda (port)
          (let* ((datum (catch #t
                          (lambda () (with-fluids ((read-eval? #f)) (read port)))
                          (lambda (key . args)
                            (refuse file "not a scene file: it does not read as one Scheme datum (~a)"
                                    (if (and (pair? args) (pair? (cdr args)) (string? (cadr args)))
                                        (apply format #f (cadr args) (if (list? (caddr args)) (caddr args) '()))
                                        key)))))
                 (more (catch #t (lambda () (read port)) (lambda _ #f))))
            (unless (eof-object? more)
              (refuse file "not a scene file: more than one datum"))
            datum))))))

(define (part file datum name)
  (let ((entry (assq name (cdr datum))))
    (unless (and entry (list? entry))
      (refuse file "not a scene file: no (~a …)" name))
    (cdr entry)))

(define (one file datum name)
  (let ((items (part file datum name)))
    (unless (= (length items) 1) (refuse file "(~a …) holds ~a values, expected one" name (length items)))
    (car items)))

(define (loaded-map file source edits)
  (cond ((not source) #f)
        ((not (and (list? source) (= (length source) 6) (string? (car source))))
         (refuse file "(tilemap …): expected (path solid-gids max-cells max-bytes strict? project), got ~s" source))
        (else
         (let ((tm (catch #t
                     (lambda () (apply load-tilemap (car source)
                                       (append-map list '(#:solid-gids #:max-cells #:max-bytes #:strict? #:project)
                                                   (cdr source))))
                     (lambda (key . args)
                       (refuse file "its map ~s does not load: ~a" (car source)
                               (error-text key args))))))
           (fold (lambda (edit tm)
                   (catch #t
                     (lambda ()
                       (unless (and (list? edit) (= (length edit) 4)) (error "not (layer col row gid)"))
                       (tilemap-set-tile tm (cadr edit) (caddr edit) (cadddr edit) (car edit)))
                     (lambda (key . args)
                       (refuse file "tile edit ~s: expected (layer col row gid) of a cell of its map" edit))))
                 tm edits)))))

(define (scene-load file)
  "The scene scene-save wrote to FILE, and as a second value the frame it
was saved with (or #f): (let-values (((scene frame) (scene-load file))) …);
where one value is taken, it is the scene. FILE must be a regular file of at
most 8 MiB holding one datum of plain data (Guile's reader with read-eval?
off: no #. evaluation), in the format scene-save writes; its map is loaded
again from the file it names, and its tile edits applied. Anything else is
an error naming scene-load and FILE."
  (unless (string? file)
    (scm-error 'wrong-type-arg "scene-load" "file: expected a file name (a string), got ~S" (list file) #f))
  (let ((datum (read-whole file)))
    (unless (and (pair? datum) (eq? (car datum) 'downstroke-scene) (list? datum)
                 (every (lambda (e) (and (pair? e) (symbol? (car e)))) (cdr datum)))
      (refuse file "not a scene file: expected (downstroke-scene (version ~a) …)" scene-file-version))
    (catch 'wrong-type-arg
      (lambda () (check-plain-data "scene-load" "the file" datum))
      (lambda (key who message args rest)
        (refuse file "not a scene file: ~a" (apply format #f message args))))
    (let ((version (one file datum 'version)))
      (unless (eqv? version scene-file-version)
        (refuse file "version ~s, expected ~a (this engine's)" version scene-file-version)))
    (let ((frame (one file datum 'frame))
          (camera (part file datum 'camera))
          (entities (part file datum 'entities)))
      (unless (or (not frame) (and (exact-integer? frame) (>= frame 0)))
        (refuse file "(frame …): expected #f or an exact integer ≥ 0, got ~s" frame))
      (unless (and (= (length camera) 2) (every real? camera))
        (refuse file "(camera x y): expected two numbers, got ~s" camera))
      (for-each (lambda (e i)
                  (catch 'wrong-type-arg
                    (lambda () (check-entity "scene-load" i e))
                    (lambda (key who message args rest)
                      (refuse file (apply format #f message args)))))
                entities (iota (length entities)))
      (let ((camera (catch 'wrong-type-arg
                      (lambda () (make-camera #:x (car camera) #:y (cadr camera)))
                      (lambda (key who message args rest)
                        (refuse file (apply format #f message args))))))
        (values (make-scene #:entities entities
                            #:tilemap (loaded-map file (one file datum 'tilemap) (part file datum 'tile-edits))
                            #:camera camera
                            #:camera-target (one file datum 'camera-target)
                            #:gravity (file-gravity file datum)
                            #:data (one file datum 'data))
                frame)))))

(define (file-gravity file datum)
  ;; Optional: a file saved before scenes had a gravity falls as the seed's.
  (let ((g (if (assq 'gravity (cdr datum)) (one file datum 'gravity) 1)))
    (unless (and (real? g) (not (nan? g)) (not (inf? g)) (not (inf? (exact->inexact g))))
      (refuse file "(gravity …): expected a finite real number, got ~s" g))
    g))
