;;; (downstroke plain-data) — the values a scene can hash and write to a
;;; file: numbers, symbols, keywords, strings, chars, booleans, '(), and
;;; pairs and vectors of them. `write' prints each so that `read' gives an
;;; equal? value back (a flonum to the bit, an exact number exactly), which
;;; is what makes a scene file and a scene's data hash mean one thing.
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
;;; the data's written text (UTF-8): equal? plain data writes the same
;;; text, and data that differs writes a different one.
(define fnv-prime #x100000001b3)
(define mask64 #xffffffffffffffff)

(define (plain-data-hash h who value)
  "H (a 64-bit FNV-1a state) continued over a tag byte and VALUE's written
text; VALUE is checked as check-plain-data checks it, naming WHO."
  (check-plain-data who "data" value)
  (let ((bytes (string->utf8 (call-with-output-string (lambda (port) (write value port))))))
    (let loop ((i 0) (h (logand (* (logxor h #xda) fnv-prime) mask64)))
      (if (= i (bytevector-length bytes))
          h
          (loop (+ i 1) (logand (* (logxor h (bytevector-u8-ref bytes i)) fnv-prime) mask64))))))
