;; SPDX-License-Identifier: MIT
;;; (downstroke plain-data) — the values a scene can hash and write to a
;;; file: numbers, symbols, keywords, strings, chars, booleans, '(), and
;;; pairs and vectors of them. `write' prints each so that `read' gives an
;;; equal? value back (a flonum to the bit, an exact number exactly), which
;;; is what makes a scene file mean one thing; the hash walks them itself.
(define-module (downstroke plain-data)
  #:use-module (rnrs bytevectors)
  #:export (check-plain-data plain-data-hash))

;; Nesting deeper than this is refused: a pair whose car leads back to
;; itself nests without end, and no game's data nests anywhere near it
;; (a list's length does not count: its cdrs are walked, not nested).
(define max-plain-depth 10000)

(define (atom? v)
  (or (number? v) (symbol? v) (keyword? v) (string? v) (char? v) (boolean? v) (null? v)))

(define (refuse who message args)
  (scm-error 'wrong-type-arg who message args #f))

(define (check-plain-data who where value)
  "Refuse VALUE, naming WHO (the procedure) and WHERE (what it is, e.g.
\"data\" or \"entity 3, #:on-hit,\", or a thunk that makes it, called only
to say what was refused), unless it is plain data: numbers,
symbols, keywords, strings, chars, booleans and '(), in lists, pairs and
vectors, without cycles. Returns VALUE."
  (define (where-text) (if (procedure? where) (where) where))
  (define (bad v)
    (refuse who "~a holds ~S, which is not plain data (numbers, symbols, keywords, strings, chars, booleans, and lists and vectors of them)"
            (list (where-text) v)))
  (let walk ((v value) (depth 0))
    (when (> depth max-plain-depth)
      (refuse who "~a: expected plain data nested at most ~a deep (a cycle through a car or a vector?)"
              (list (where-text) max-plain-depth)))
    (cond ((atom? v) #t)
          ((vector? v)
           (let loop ((i 0))
             (when (< i (vector-length v))
               (walk (vector-ref v i) (+ depth 1))
               (loop (+ i 1)))))
          ((pair? v)
           ;; The cdrs with a tortoise: a circular list is refused, not walked forever.
           (let loop ((p v) (tortoise v) (odd? #f))
             (cond ((pair? p)
                    (walk (car p) (+ depth 1))
                    (let ((tortoise (if odd? (cdr tortoise) tortoise)))
                      (when (and odd? (eq? (cdr p) tortoise))
                        (refuse who "~a holds a circular list, which is not plain data: ~S" (list (where-text) value)))
                      (loop (cdr p) tortoise (not odd?))))
                   (else (walk p (+ depth 1))))))
          (else (bad v))))
  value)

;;; FNV-1a 64, as src/state_hash.hpp hashes the entities, continued over
;;; the data's own bytes: a tag for each value's kind, then what it holds,
;;; each text with its length first, so that no two plain data that differ
;;; (equal? tells) feed the same bytes. Not the written text: how `write'
;;; prints a symbol such as foo: depends on the reader's keyword style,
;;; and a hash must be one value for one scene everywhere.
(define fnv-prime #x100000001b3)
(define mask64 #xffffffffffffffff)

(define (fnv-bytes h bv)
  (let loop ((i 0) (h h))
    (if (= i (bytevector-length bv))
        h
        (loop (+ i 1) (logand (* (logxor h (bytevector-u8-ref bv i)) fnv-prime) mask64)))))

(define (fnv-byte h byte) (logand (* (logxor h byte) fnv-prime) mask64))

(define (fnv-text h tag text)
  ;; TAG, the text's length in bytes as decimal digits and a colon, its UTF-8.
  (let ((bytes (string->utf8 text)))
    (fnv-bytes (fnv-bytes (fnv-byte h (char->integer tag))
                          (string->utf8 (string-append (number->string (bytevector-length bytes)) ":")))
               bytes)))

(define (fnv-datum h v)
  (cond ((null? v) (fnv-byte h (char->integer #\n)))
        ((eq? v #t) (fnv-byte h (char->integer #\t)))
        ((eq? v #f) (fnv-byte h (char->integer #\f)))
        ((and (number? v) (exact? v)) (fnv-text h #\e (number->string v)))
        ((and (number? v) (real? v))    ; a flonum: its IEEE-754 bits
         (let ((bv (make-bytevector 8)))
           (bytevector-ieee-double-set! bv 0 v (endianness little))
           (fnv-bytes (fnv-byte h (char->integer #\d)) bv)))
        ((number? v) (fnv-datum (fnv-datum (fnv-byte h (char->integer #\c)) (real-part v)) (imag-part v)))
        ((symbol? v) (fnv-text h #\s (symbol->string v)))
        ((keyword? v) (fnv-text h #\k (symbol->string (keyword->symbol v))))
        ((string? v) (fnv-text h #\" v))
        ((char? v) (fnv-text h #\h (number->string (char->integer v))))
        ((pair? v)                      ; a list's cdrs in a loop, not nested
         (let loop ((p v) (h h))
           (if (pair? p)
               (loop (cdr p) (fnv-datum (fnv-byte h (char->integer #\p)) (car p)))
               (fnv-datum h p))))
        (else                           ; a vector
         (let ((n (vector-length v)))
           (let loop ((i 0) (h (fnv-text h #\v (number->string n))))
             (if (= i n) h (loop (+ i 1) (fnv-datum h (vector-ref v i)))))))))

(define (plain-data-hash h who value)
  "H (a 64-bit FNV-1a state) continued over a tag byte and VALUE's bytes (a
tag for each value's kind, then its contents); VALUE is checked as
check-plain-data checks it, naming WHO."
  (check-plain-data who "data" value)
  (fnv-datum (fnv-byte h #xda) value))
