;; SPDX-License-Identifier: MIT
;;; (downstroke hash) — a fingerprint of a scene's physical state, for
;;; checking that two runs are the same run (determinism, replays, native
;;; against reference) one integer per frame.
(define-module (downstroke hash)
  #:use-module (downstroke native)
  #:use-module (downstroke world)
  #:use-module ((downstroke plain-data) #:select (plain-data-hash))
  #:export (scene-hash))

(define (scene-hash scene)
  "The 64-bit FNV-1a hash of SCENE's physical state, an exact integer in
[0, 2^64): for each entity in list order, #:x #:y #:width #:height #:vx #:vy
#:ay (each as physics reads it: exactness and, for flonums, the sign of
zero count; a missing key is exact 0) and #:on-ground?, then the scene's
gravity when it is not the default 1. Nothing else counts: not other keys
(#:id, #:solid?, your own), not key order, not the tilemap or the camera.
The byte layout is in src/state_hash.hpp; (downstroke reference-hash)
computes the same value in plain Scheme.
A scene whose scene-data is not #f hashes it too, after the rest: each
value's kind and contents, so equal? data hashes alike. The data must then be plain data
(numbers, symbols, keywords, strings, chars, booleans, lists, pairs and
vectors of them); anything else (a procedure, a record, a hash table) is an
error naming scene-hash, never hashed as if it were something else."
  (unless (scene? scene)
    (scm-error 'wrong-type-arg "scene-hash" "expected a scene, got ~S" (list scene) #f))
  (let ((h (%scene-hash-entities (scene-entities scene) (scene-gravity scene)))
        (data (scene-data scene)))
    (if data (plain-data-hash h "scene-hash" data) h)))
