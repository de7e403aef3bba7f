;; SPDX-License-Identifier: MIT
;;; Determinism (issue 7, part 5): scene-hash, and runs that hash the same.
;;;
;;; - scene-hash (native, (downstroke hash)) against the plain-Scheme
;;;   scene-hash of (downstroke reference-hash): pinned values (the same ones
;;;   tests/core/state_hash_test.cpp pins), random scenes from scene-gen.scm,
;;;   and scenes stepped frame by frame by the native and by the reference
;;;   step-scene in both collision modes — the two paths must give the same
;;;   hash sequence.
;;; - What the hash covers: every physical value (exactness and the sign of
;;;   a flonum zero included) and nothing else — it hashes the state as
;;;   physics decodes it, so key order, extra keys, later duplicates of a key,
;;;   the tilemap and the camera do not count, and a missing key hashes as its
;;;   default.
;;; - The demos: two runs with the same input script hash the same frame by
;;;   frame; the input held in each frame, recorded and turned into a script
;;;   (input-log->script), replays to the same sequence, also when physics runs
;;;   through the reference step-scene.
;;;
;;; Environment (optional): DS_DET_SCENES random scenes hashed (default
;;; 1000), DS_DET_STEPPED of them also stepped (default 150), DS_DET_FRAMES
;;; frames each (default 30). A mismatch lists the first five seeds.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke)
             ((downstroke reference) #:select ((step-scene . reference-step-scene)))
             ((downstroke reference-hash) #:select ((scene-hash . reference-scene-hash))))

(load "support.scm")
(load "scene-gen.scm")

(define (env-int name default)
  (let ((v (and=> (getenv name) string->number)))
    (if (exact-integer? v) v default)))

(define scene-count (env-int "DS_DET_SCENES" 1000))
(define stepped-count (env-int "DS_DET_STEPPED" 150))
(define frame-count (env-int "DS_DET_FRAMES" 30))

(define (hash-of . entities) (scene-hash (make-scene entities: entities)))
(define (reference-hash-of . entities) (reference-scene-hash (make-scene entities: entities)))

(test-begin "determinism")

;;; ================================================================ pinned values
;;; Computed independently from the byte layout of src/state_hash.hpp.
(define hero '(#:x 100 #:y 50 #:width 12 #:height 16 #:vx 3 #:vy -1.5 #:on-ground? #t))
(define crate '(#:x 0.5 #:y -0.0 #:width 8 #:height 8))

(test-group "pinned"
  (test-equal "the empty scene: the FNV-1a offset basis" 14695981039346656037 (scene-hash (make-scene)))
  (test-equal "one hero" 17386948739817264273 (hash-of hero))
  (test-equal "one crate" 10335750445336562271 (hash-of crate))
  (test-equal "hero and crate" 13637382024834548787 (hash-of hero crate))
  (test-equal "crate and hero: order counts" 2856564895695392583 (hash-of crate hero))
  (test-equal "an entity with no physics keys: all zero" 15263143918111547514 (hash-of '(#:type ghost)))
  (test-equal "reference: the same five values"
    '(14695981039346656037 17386948739817264273 10335750445336562271 13637382024834548787
      2856564895695392583)
    (list (reference-scene-hash (make-scene)) (reference-hash-of hero) (reference-hash-of crate)
          (reference-hash-of hero crate) (reference-hash-of crate hero)))
  (test-assert "an exact integer in [0, 2^64)"
    (let ((h (hash-of hero))) (and (exact-integer? h) (<= 0 h) (< h (expt 2 64))))))

;;; ================================================================ what counts
(define base '(#:x 100 #:y 50 #:width 12 #:height 16 #:vx 3 #:vy 0 #:ay 0 #:on-ground? #f))
(define (with key value) (entity-set base key value))
(define base-hash (hash-of base))
(define (reverse-plist plist)
  (if (null? plist) '() (append (reverse-plist (cddr plist)) (list (car plist) (cadr plist)))))
(define (differs? . entities) (not (= base-hash (apply hash-of entities))))
(define (same? . entities) (= base-hash (apply hash-of entities)))

(test-group "what counts"
  (test-assert "x + 1" (differs? (with #:x 101)))
  (for-each (lambda (key)
              (test-assert (format #f "~s + 1" key) (differs? (with key (+ 1 (entity-ref base key))))))
            '(#:y #:width #:height #:vx #:vy #:ay))
  (test-assert "on-ground?" (differs? (with #:on-ground? #t)))
  (test-assert "103 is not 103.0" (not (= (hash-of '(#:x 103)) (hash-of '(#:x 103.0)))))
  (test-assert "0.0 is not -0.0" (not (= (hash-of '(#:vy 0.0)) (hash-of '(#:vy -0.0)))))
  (test-assert "exact 0 is not 0.0" (not (= (hash-of '(#:vy 0)) (hash-of '(#:vy 0.0)))))
  (test-assert "entity order" (not (= (hash-of hero crate) (hash-of crate hero))))
  (test-assert "one entity more" (not (= (hash-of base) (hash-of base base)))))

(test-group "what does not count"
  (test-assert "keys physics does not hash (#:type, #:hp, #:id, #:solid?, #:gravity?)"
    (same? (append base '(#:type player #:hp 3 #:id p1 #:solid? #t #:gravity? #t))))
  (test-assert "key order" (same? (reverse-plist base)))
  (test-assert "a later duplicate of a key: the first one is what physics reads"
    (same? (append base '(#:x 999 #:on-ground? #t))))
  (test-assert "a missing key hashes as its default (0, #f)"
    (same? '(#:x 100 #:y 50 #:width 12 #:height 16 #:vx 3)))
  (test-assert "any true #:on-ground? is true"
    (= (hash-of (with #:on-ground? #t)) (hash-of (with #:on-ground? 'yes))))
  (test-assert "an exact fraction is read as a flonum, as physics reads it"
    (= (hash-of '(#:x 1/2)) (hash-of '(#:x 0.5))))
  (test-assert "an exact integer past 2^53 is read as its double, still exact"
    (and (= (hash-of `(#:x ,(expt 2 53))) (hash-of `(#:x ,(+ (expt 2 53) 1))))
         (not (= (hash-of `(#:x ,(expt 2 53))) (hash-of `(#:x ,(exact->inexact (expt 2 53))))))))
  (test-assert "the tilemap and the camera"
    (let ((level (make-tilemap 2 2 16 16 (vector 1 1 1 1) '(1))))
      (= base-hash (scene-hash (make-scene entities: (list base) tilemap: level
                                           camera: (make-camera x: 40 y: 7)))))))

;;; ================================================================ errors
(define (both-errors thunk-of)
  "The error texts of the native and the reference scene-hash on the same input."
  (list (error-text (lambda () (thunk-of scene-hash)))
        (error-text (lambda () (thunk-of reference-scene-hash)))))

(test-group "errors"
  (for-each
   (lambda (row)
     (let ((what (car row)) (entities (cadr row)) (parts (cddr row)))
       (let ((texts (both-errors (lambda (hash) (hash (make-scene entities: entities))))))
         (test-assert (string-append what ": names scene-hash and the value")
           (apply mentions? (car texts) "scene-hash" parts))
         (test-equal (string-append what ": the reference says the same") (car texts) (cadr texts)))))
   (list (list "a string velocity" '((#:x 1) (#:vx "fast")) "#:vx" "\"fast\"")
         (list "NaN" '((#:y +nan.0)) "#:y" "+nan.0")
         (list "an exact integer no double holds" `((#:x ,(expt 10 400))) "#:x" "between -1.8e308 and 1.8e308 (a double's range), got 1000")
         (list "a complex width" '((#:width 1+2i)) "#:width" "1.0+2.0i")
         (list "a key with no value" '((#:x 1 #:y)) "#:y" "no value")
         (list "a non-keyword key" '((#:x 1 y 2)) "key position" "(#:x 1 y 2)")
         (list "not a list" '(42) "42")
         (list "a bad skip list" '((#:skip-pipelines gravity)) "#:skip-pipelines" "gravity")
         (list "a bad value in an unhashed physics key" '((#:group-local-x "l")) "#:group-local-x" "\"l\"")))
  (let ((texts (both-errors (lambda (hash) (hash 'not-a-scene)))))
    (test-assert "not a scene" (mentions? (car texts) "scene-hash" "not-a-scene"))
    (test-equal "not a scene: the reference says the same" (car texts) (cadr texts))))

;;; ================================================================ native = reference
(define (first-five lst) (if (> (length lst) 5) (list-head lst 5) lst))

(define (safe thunk)
  "THUNK's value, or the symbol error."
  (catch #t thunk (lambda _ 'error)))

(test-group "random scenes"
  (let ((mismatches
         (filter-map (lambda (seed)
                       (let* ((scene (generate-scene seed))
                              (native (safe (lambda () (scene-hash scene))))
                              (reference (safe (lambda () (reference-scene-hash scene)))))
                         (and (not (equal? native reference)) (list seed native reference))))
                     (iota scene-count 1))))
    (test-equal (format #f "~a scenes: native and reference hash alike" scene-count)
      '() (first-five mismatches))))

;;; The hashes of SCENE and of the next FRAMES scenes STEP makes from it (dt
;;; per scene-gen), each taken with HASH; 'error ends the list if a step
;;; raised.
(define (hash-run step hash scene seed frames)
  (let loop ((scene scene) (frame 0) (acc '()))
    (let ((h (safe (lambda () (hash scene)))))
      (if (or (= frame frames) (eq? h 'error))
          (reverse (cons h acc))
          (let ((next (safe (lambda () (step scene (scene-dt seed frame))))))
            (if (eq? next 'error)
                (reverse (cons* 'error h acc))
                (loop next (+ frame 1) (cons h acc))))))))

(test-group "stepped scenes"
  (for-each
   (lambda (mode)
     (parameterize ((collision-mode mode))
       (let ((mismatches
              (filter-map
               (lambda (seed)
                 (let* ((scene (generate-scene seed))
                        (native (hash-run step-scene scene-hash scene seed frame-count))
                        (reference (hash-run reference-step-scene reference-scene-hash scene seed frame-count)))
                   (and (not (equal? native reference))
                        (let ((k (list-index (lambda (a b) (not (equal? a b))) native reference)))
                          (list 'seed seed 'frame k (list-ref native k) (list-ref reference k))))))
               (iota stepped-count 1))))
         (test-equal (format #f "~a: ~a scenes x ~a frames, the same hash sequence" mode stepped-count frame-count)
           '() (first-five mismatches)))))
   '(swept discrete))
  (let* ((seed 7)
         (scene (generate-scene seed))
         (swept (parameterize ((collision-mode 'swept)) (hash-run step-scene scene-hash scene seed frame-count))))
    (test-assert "the scenes move: a stepped scene's hashes change"
      (> (length (delete-duplicates swept)) 1))))

;;; ================================================================ the demos
;; demo-dir comes from support.scm.

(define (plist-remove plist key)
  (cond ((null? plist) '())
        ((eq? (car plist) key) (cddr plist))
        (else (cons* (car plist) (cadr plist) (plist-remove (cddr plist) key)))))

;;; A fresh module that uses (downstroke), with demo/NAME loaded into it. The
;;; game it makes gets SCRIPT as its input script (when given) and, with
;;; REFERENCE?, the reference step-scene as its physics (unless it has
;;; none): the demo's make-game is wrapped, so the demo file stays as it is.
(define* (load-demo name #:key script reference?)
  (let ((m (make-fresh-user-module)))
    (module-use! m (resolve-interface '(downstroke)))
    (module-define! m 'make-game
      (lambda args
        (let* ((args (if script (append (plist-remove args #:input-script) (list #:input-script script)) args))
               (args (if (and reference? (not (eq? #f (memq-ref args #:engine-update #t))))
                         (append (plist-remove args #:engine-update) (list #:engine-update reference-engine))
                         args)))
          (apply make-game args))))
    (save-module-excursion
     (lambda ()
       (set-current-module m)
       (load (string-append demo-dir "/" name))))
    m))

(define (memq-ref plist key default)
  (let ((tail (memq key plist))) (if tail (cadr tail) default)))

(define (reference-engine game dt)
  (parameterize ((collision-mode (game-collision-mode game)))
    (game-scene-set! game (reference-step-scene (game-scene game) dt))))

;;; Runs demo module M frame by frame for its demo-frames frames. Returns
;;; (hashes log reference-hashes): the scene's hash after each frame, the
;;; actions held in each frame, and the reference scene-hash after each frame.
(define (run-hashed m)
  (let ((game (module-ref m 'game)) (run! (module-ref m 'run!)))
    (let loop ((frame 0) (hashes '()) (log '()) (reference '()))
      (if (= frame (module-ref m 'demo-frames))
          (list (reverse hashes) (reverse log) (reverse reference))
          (begin
            (run! (+ frame 1))
            (let ((scene (game-scene game)))
              (loop (+ frame 1)
                    (cons (scene-hash scene) hashes)
                    (cons (input-held-actions (game-input game)) log)
                    (cons (reference-scene-hash scene) reference))))))))

(define (own-script m)
  "The demo's input script as recorded over its demo-frames: its key frames
before then (each of these demos changes what is held at every key frame),
or ((0)) for a demo that has none."
  (let ((script (if (module-local-variable m 'input-script) (module-ref m 'input-script) '())))
    (if (null? script)
        '((0))
        (filter (lambda (k) (< (car k) (module-ref m 'demo-frames))) script))))

(for-each
 (lambda (name)
   (test-group name
     (let* ((demo (load-demo name))
            (run-1 (run-hashed demo))
            (hashes (car run-1))
            (log (cadr run-1))
            (frames (module-ref demo 'demo-frames))
            (script (input-log->script log))
            (run-2 (run-hashed (load-demo name)))
            (replayed (run-hashed (load-demo name #:script script)))
            (on-reference (run-hashed (load-demo name #:script script #:reference? #t))))
       (test-equal "a hash per frame" frames (length hashes))
       (test-assert "the scene changes during the run" (> (length (delete-duplicates hashes)) 10))
       (test-equal "the reference scene-hash agrees on every frame" hashes (caddr run-1))
       (test-equal "two runs with the same input script: the same hashes" hashes (car run-2))
       (test-equal "the recorded input is the demo's own script" (own-script demo) script)
       (test-equal "the recorded input log, replayed: the same hashes" hashes (car replayed))
       (test-equal "the replay holds the same input in every frame" log (cadr replayed))
       (test-equal "replayed through the reference step-scene: the same hashes" hashes (car on-reference)))))
 '("platformer.scm" "topdown.scm" "sandbox.scm" "shmup.scm" "tweens.scm"))

(test-end "determinism")
