;; SPDX-License-Identifier: MIT
(use-modules (srfi srfi-64) (downstroke) (srfi srfi-1))

(load "support.scm")

(test-begin "entity")

;;; ---------------------------------------------------------------- entity-ref
(define e (list #:x 100 #:y 50 #:name "bob"))
(test-equal 100 (entity-ref e #:x))
(test-equal 0 (entity-ref e #:vx 0))
(test-equal #f (entity-ref e #:vx))
(test-equal "bob" (entity-ref e #:name 'default))
(test-equal "default ignored when present" 50 (entity-ref e #:y 7))
(test-equal "missing key, explicit default" 'none (entity-ref e #:tween 'none))
(test-equal "missing key in the empty entity" #f (entity-ref '() #:x))
(test-equal "empty entity with default" 3 (entity-ref '() #:x 3))
(test-equal "a stored #f is a value, not absence" #f (entity-ref '(#:on-ground? #f) #:on-ground? #t))
(test-equal "first occurrence wins" 1 (entity-ref '(#:x 1 #:y 2 #:x 3) #:x))
(test-equal "lists as values" '(gravity) (entity-ref '(#:skip-pipelines (gravity)) #:skip-pipelines))

;;; ---------------------------------------------------------------- entity-set
(test-equal '(#:x 7 #:y 50 #:name "bob") (entity-set e #:x 7))
(test-equal "replace in place (middle)" '(#:x 100 #:y 9 #:name "bob") (entity-set e #:y 9))
(test-equal "replace in place (last)" '(#:x 100 #:y 50 #:name "al") (entity-set e #:name "al"))
(test-equal '(#:x 100 #:y 50 #:name "bob" #:vx 3) (entity-set e #:vx 3))
(test-equal "append to the empty entity" '(#:x 1) (entity-set '() #:x 1))
(test-equal "only the first occurrence is replaced" '(#:x 5 #:y 2 #:x 3)
  (entity-set '(#:x 1 #:y 2 #:x 3) #:x 5))
(test-eq "entity-set shares the tail after the key" (cddr e) (cddr (entity-set e #:x 1)))
(test-eq "tail after a middle key is shared" (cddddr e) (cddddr (entity-set e #:y 1)))
(test-equal '(#:x 100 #:y 50 #:name "bob") e)
(let* ((orig (list #:a 1 #:b 2))
       (copy (list-copy orig)))
  (entity-set orig #:a 10)
  (entity-set orig #:c 3)
  (test-equal "entity-set never mutates its argument" copy orig))
(test-equal "setting a value to #f keeps the key" '(#:x #f) (entity-set '(#:x 1) #:x #f))

;;; ---------------------------------------------------------------- malformed
(test-error 'wrong-type-arg (entity-ref '(#:x) #:x))
(test-assert "odd length: message names the problem"
  (mentions? (error-text (lambda () (entity-ref '(#:x 1 #:y) #:y))) "malformed entity" "(#:x 1 #:y)"))
(test-assert "non-keyword key: message names the problem"
  (mentions? (error-text (lambda () (entity-ref '(x 1) #:x))) "malformed entity" "(x 1)"))
(test-assert "not a list: message names the problem"
  (mentions? (error-text (lambda () (entity-ref 42 #:x))) "malformed entity" "42"))
(test-assert "entity-set, odd length"
  (mentions? (error-text (lambda () (entity-set '(#:x 1 #:y) #:z 2))) "entity-set" "malformed entity"))
(test-assert "entity-set, non-keyword key"
  (mentions? (error-text (lambda () (entity-set '("x" 1) #:x 2))) "entity-set" "malformed entity"))
(test-assert "entity-set, not a list"
  (mentions? (error-text (lambda () (entity-set 'player #:x 2))) "entity-set" "malformed entity" "player"))
(test-assert "entity-ref with a non-keyword key"
  (mentions? (error-text (lambda () (entity-ref '(#:x 1) 'x))) "entity-ref" "keyword" "x"))
(test-assert "entity-set with a non-keyword key"
  (mentions? (error-text (lambda () (entity-set '(#:x 1) "x" 2))) "entity-set" "keyword"))

;;; ---------------------------------------------------------------- entity-skips-pipeline?
(test-equal #f (entity-skips-pipeline? '(#:x 1) 'gravity))
(test-equal #f (entity-skips-pipeline? '(#:skip-pipelines ()) 'gravity))
(test-equal #t (entity-skips-pipeline? '(#:skip-pipelines (gravity)) 'gravity))
(test-equal #t (entity-skips-pipeline? '(#:skip-pipelines (acceleration tweens on-solid)) 'on-solid))
(test-equal #f (entity-skips-pipeline? '(#:skip-pipelines (acceleration tweens)) 'velocity-x))
(for-each
 (lambda (sym)
   (test-equal (symbol->string sym) #t
     (entity-skips-pipeline? (list #:skip-pipelines (list sym)) sym)))
 '(acceleration gravity velocity-x velocity-y tile-collisions-x tile-collisions-y
   on-solid entity-collisions tweens))
(test-assert "a skip list that is not a list: message names the key"
  (mentions? (error-text (lambda () (entity-skips-pipeline? '(#:skip-pipelines gravity) 'gravity)))
             "entity-skips-pipeline?" "#:skip-pipelines" "gravity"))
;; semantics §2: a wrongly typed value is an error naming the procedure, the key
;; and the value; a skip list must be a list of symbols, here as in the
;; native steps.
(test-assert "a skip list holding a non-symbol is an error"
  (mentions? (error-text (lambda () (entity-skips-pipeline? '(#:skip-pipelines (gravity 3)) 'velocity-x)))
             "#:skip-pipelines"))

;;; ---------------------------------------------------------------- define-pipeline
;; Without a guard: skipped only through #:skip-pipelines.
(define-pipeline (bump-x velocity-x) (entity scene dt)
  (entity-set entity #:x (+ (entity-ref entity #:x 0) dt)))
(test-equal "no guard: the body runs" '(#:x 16) (bump-x '(#:x 0) #f 16))
(test-equal "no guard: dt reaches the body" '(#:x 5) (bump-x '(#:x 2) #f 3))
(let ((skipping '(#:x 0 #:skip-pipelines (velocity-x))))
  (test-eq "no guard: a skipping entity is returned itself" skipping (bump-x skipping #f 16)))
(let ((other '(#:x 0 #:skip-pipelines (velocity-y gravity))))
  (test-equal "skipping another step does not matter" '(#:x 16 #:skip-pipelines (velocity-y gravity))
    (bump-x other #f 16)))

;; A body of several forms; its value is the last one's.
(define-pipeline (two-forms gravity) (entity scene dt)
  (define base (entity-ref entity #:vy 0))
  (entity-set entity #:vy (+ base 1)))
(test-equal "multi-form body" '(#:vy 3) (two-forms '(#:vy 2) #f 16))

;; The scene reaches the body.
(define-pipeline (scene-reader on-solid) (entity scene dt)
  (entity-set entity #:seen scene))
(test-equal '(#:seen the-scene) (scene-reader '() 'the-scene 16))

;; With the guard written `guard:' (postfix keywords, as this file is read).
(define guard-runs 0)
(define-pipeline (fall-postfix gravity) (entity scene dt)
  guard: (begin (set! guard-runs (+ guard-runs 1)) (entity-ref entity #:gravity? #f))
  (entity-set entity #:vy (+ (entity-ref entity #:vy 0) 1)))
(test-equal "postfix guard: true → body" '(#:gravity? #t #:vy 1) (fall-postfix '(#:gravity? #t) #f 16))
(let ((e0 '(#:gravity? #f #:vy 0)))
  (test-eq "postfix guard: false → the entity itself" e0 (fall-postfix e0 #f 16)))
(let ((e0 '(#:vy 0)))
  (test-eq "postfix guard: absent flag → the entity itself" e0 (fall-postfix e0 #f 16)))
(let ((e0 '(#:gravity? #t #:skip-pipelines (gravity))))
  (test-eq "postfix guard: skipping wins over a true guard" e0 (fall-postfix e0 #f 16)))
(test-equal "the guard is evaluated once per call when not skipped" 3 guard-runs)
(test-equal "the guard is not the body's first form"
  '(#:gravity? #t #:vy 5) (fall-postfix '(#:gravity? #t #:vy 4) #f 16))

;; With the guard written as the prefix keyword.
(define-pipeline (fall-prefix gravity) (entity scene dt)
  #:guard (entity-ref entity #:gravity? #f)
  (entity-set entity #:vy (+ (entity-ref entity #:vy 0) 1)))
(test-equal "prefix #:guard true" '(#:gravity? #t #:vy 3) (fall-prefix '(#:gravity? #t #:vy 2) #f 16))
(let ((e0 '(#:gravity? #f #:vy 2)))
  (test-eq "prefix #:guard false" e0 (fall-prefix e0 #f 16)))
(let ((e0 '(#:gravity? #t #:vy 2 #:skip-pipelines (gravity))))
  (test-eq "prefix #:guard, skipped" e0 (fall-prefix e0 #f 16)))

;; A guard that uses the scene and dt.
(define-pipeline (dt-guarded tweens) (entity scene dt)
  guard: (and scene (> dt 10))
  (entity-set entity #:ran #t))
(test-equal '(#:ran #t) (dt-guarded '() 'scene 16))
(test-equal '() (dt-guarded '() 'scene 5))
(test-equal '() (dt-guarded '() #f 16))

;; With keywords not read at all: `guard:' is the plain symbol guard:.
(define symbol-mode-step
  (dynamic-wind
    (lambda () (read-set! keywords #f))
    (lambda ()
      (let ((form (read (open-input-string
                         "(let ()
                            (define-pipeline (fall-symbol gravity) (entity scene dt)
                              guard: (entity-ref entity #:gravity? #f)
                              (entity-set entity #:vy (+ (entity-ref entity #:vy 0) 1)))
                            fall-symbol)"))))
        (eval form (current-module))))
    (lambda () (read-set! keywords 'postfix))))
(test-equal "keywords off: `guard:' was read as a symbol" (string->symbol "guard:")
  (dynamic-wind
    (lambda () (read-set! keywords #f))
    (lambda () (read (open-input-string "guard:")))
    (lambda () (read-set! keywords 'postfix))))
(test-assert "keywords restored to postfix" (keyword? (read (open-input-string "guard:"))))
(test-equal "symbol guard: true" '(#:gravity? #t #:vy 1) (symbol-mode-step '(#:gravity? #t) #f 16))
(let ((e0 '(#:gravity? #f)))
  (test-eq "symbol guard: false" e0 (symbol-mode-step e0 #f 16)))
(let ((e0 '(#:gravity? #t #:skip-pipelines (gravity))))
  (test-eq "symbol guard: skipped" e0 (symbol-mode-step e0 #f 16)))

;; The same, reading the whole definition through `guard:' with prefix keywords:
;; `guard:' is then a plain symbol too.
(define prefix-mode-step
  (dynamic-wind
    (lambda () (read-set! keywords 'prefix))
    (lambda ()
      (eval (read (open-input-string
                   "(let ()
                      (define-pipeline (fall-pre gravity) (entity scene dt)
                        #:guard (entity-ref entity #:gravity? #f)
                        (entity-set entity #:vy 10))
                      fall-pre)"))
            (current-module)))
    (lambda () (read-set! keywords 'postfix))))
(test-equal "prefix-mode read, guard true" '(#:gravity? #t #:vy 10) (prefix-mode-step '(#:gravity? #t) #f 16))
(let ((e0 '(#:vy 1)))
  (test-eq "prefix-mode read, guard false" e0 (prefix-mode-step e0 #f 16)))

;; The built-in steps are defined the same way: guards on #:gravity?.
(let ((floating '(#:vy 0 #:ay -15)))
  (test-eq "apply-acceleration needs #:gravity?" floating (apply-acceleration floating #f 16))
  (test-eq "apply-gravity needs #:gravity?" floating (apply-gravity floating #f 16)))

(test-end "entity")
