;; SPDX-License-Identifier: MIT
;;; (downstroke reference-hash) — scene-hash in plain Scheme.
;;;
;;; The same value as (downstroke hash)'s native scene-hash, computed from
;;; the byte layout documented in src/state_hash.hpp with nothing but plist
;;; walking, exact integers mod 2^64 and the IEEE-754 bits of doubles, so
;;; that the layout has a second, independent implementation to be tested
;;; against. It also refuses what the native decoder refuses, with the same
;;; messages, naming scene-hash.
(define-module (downstroke reference-hash)
  #:use-module (rnrs bytevectors)
  #:use-module (srfi srfi-1)
  #:use-module (downstroke world)
  #:use-module ((downstroke plain-data) #:select (plain-data-hash))
  #:export (scene-hash))

;;; ---------------------------------------------------------------- FNV-1a 64

(define fnv-offset-basis #xcbf29ce484222325)
(define fnv-prime #x100000001b3)
(define mask64 #xffffffffffffffff)

(define (fnv-byte h byte) (logand (* (logxor h byte) fnv-prime) mask64))

;;; ---------------------------------------------------------------- numbers

;;; The core reads a number as the nearest double and remembers only whether
;;; it was an exact integer: 1/3 is read as a flonum, 2^64 as an exact value
;;; held in a double.
(define (exact-flag v) (and (exact? v) (integer? v)))

(define (double-bytes d)
  "D's IEEE-754 binary64 bits, least significant byte first."
  (let ((bv (make-bytevector 8)))
    (bytevector-ieee-double-set! bv 0 d (endianness little))
    (bytevector->u8-list bv)))

(define (hash-number h v)
  ;; An exact value's double is never -0.0 here: exact 0 converts to +0.0.
  (fold (lambda (byte h) (fnv-byte h byte))
        (fnv-byte h (if (exact-flag v) 1 0))
        (double-bytes (exact->inexact v))))

;;; ---------------------------------------------------------------- reading entities

(define hashed-number-keys '(#:x #:y #:width #:height #:vx #:vy #:ay))
(define number-keys (append hashed-number-keys '(#:group-local-x #:group-local-y)))

(define (fail message . irritants)
  (scm-error 'wrong-type-arg "scene-hash" message irritants #f))

(define (check-value key v)
  (cond ((memq key number-keys)
         (unless (real? v) (fail "entity key ~S: expected a real number, got ~S" key v))
         (when (or (nan? v) (inf? v)) (fail "entity key ~S: expected a finite number, got ~S" key v))
         ;; An exact number past a double's range is finite: say the range.
         (when (inf? (exact->inexact v))
           (scm-error 'out-of-range "scene-hash"
                      "entity key ~S: expected a number between -1.8e308 and 1.8e308 (a double's range), got ~S"
                      (list key v) #f)))
        ((eq? key #:skip-pipelines)
         (unless (and (list? v) (every symbol? v))
           (fail "entity key ~S: expected a list of symbols, got ~S" key v)))))

(define (physical-state e)
  "The first occurrence of each key of E, as an alist, after checking E as
the native decoder does: keys in order, each physics key's first value."
  (let loop ((p e) (seen '()))
    (cond ((null? p) seen)
          ((not (pair? p)) (fail "malformed entity: expected a keyword plist, got ~S" e))
          ((not (keyword? (car p))) (fail "malformed entity: ~S in key position of ~S" (car p) e))
          ((not (pair? (cdr p))) (fail "malformed entity: key ~S has no value in ~S" (car p) e))
          ((assq (car p) seen) (loop (cddr p) seen))
          (else (check-value (car p) (cadr p))
                (loop (cddr p) (acons (car p) (cadr p) seen))))))

(define (hash-entity h e)
  (let* ((state (physical-state e))
         (value (lambda (key default) (let ((hit (assq key state))) (if hit (cdr hit) default))))
         (h (fold (lambda (key h) (hash-number h (value key 0))) h hashed-number-keys)))
    (fnv-byte h (if (value #:on-ground? #f) 1 0))))

(define (scene-hash scene)
  "SCENE's physical state hashed as the native scene-hash of (downstroke
hash) hashes it, computed in plain Scheme."
  (unless (scene? scene)
    (scm-error 'wrong-type-arg "scene-hash" "expected a scene, got ~S" (list scene) #f))
  (let* ((entities (scene-entities scene))
         (g (scene-gravity scene))
         (h (let loop ((p entities) (h fnv-offset-basis))
              (cond ((null? p)
                     ;; A gravity other than the default exact 1: 'G', then it.
                     (if (and (exact-flag g) (= g 1)) h (hash-number (fnv-byte h #x47) g)))
                    ((pair? p) (loop (cdr p) (hash-entity h (car p))))
                    (else (fail "expected a list of entities, got ~S" entities))))))
    ;; The data is text, not physics: one implementation serves both.
    (if (scene-data scene) (plain-data-hash h "scene-hash" (scene-data scene)) h)))
