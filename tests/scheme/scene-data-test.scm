;; SPDX-License-Identifier: MIT
;;; A game's own state in its scenes (scene-data): kept by every scene-
;;; producing procedure, restored by a rewind, hashed by scene-hash.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke))

(load "support.scm")

(define reference-scene-hash (@ (downstroke reference-hash) scene-hash))

(test-begin "scene-data")

(define body '(#:id hero #:x 0 #:y 0 #:width 8 #:height 8 #:gravity? #t))
(define plain (make-scene entities: (list body)))
(define scored (make-scene entities: (list body) data: '(#:coins 3 #:lives 2)))

;;; ---------------------------------------------------------------- kept
(test-equal "no data: #f" #f (scene-data plain))
(test-equal '(#:coins 3 #:lives 2) (scene-data scored))
(test-equal "update-scene replaces it" 'won (scene-data (update-scene scored data: 'won)))
(test-equal "… and keeps it when not given" '(#:coins 3 #:lives 2)
  (scene-data (update-scene scored entities: '())))
(test-equal "step-scene keeps it" '(#:coins 3 #:lives 2) (scene-data (step-scene scored 16)))
(test-equal "scene-map-entities keeps it" '(#:coins 3 #:lives 2)
  (scene-data (scene-map-entities scored (lambda (e) (entity-set e #:x 5)))))
(test-equal "scene-transform-entities keeps it" '(#:coins 3 #:lives 2)
  (scene-data (scene-transform-entities scored reverse)))
(test-equal "any value, a procedure too" car (scene-data (make-scene data: car)))
(test-equal "In procedure scene-data: expected a scene, got 42\n" (error-text (lambda () (scene-data 42))))

;;; ---------------------------------------------------------------- rewind
;;; The update hook counts frames in the data; a rewind brings back the
;;; count of the frame it goes back to.
(define counting
  (make-game history: 10
             scene: (make-scene entities: (list body) data: 0)
             update: (lambda (game dt)
                       (let ((s (game-scene game)))
                         (game-scene-set! game (update-scene s data: (+ 1 (scene-data s))))))))
(game-run! counting frames: 6)
(test-equal "six frames counted" 6 (scene-data (game-scene counting)))
(game-rewind! counting 4)
(test-equal "a rewind of 4 frames: the data of frame 2's start" '(2 2)
  (list (game-frame counting) (scene-data (game-scene counting))))
(game-run! counting frames: 5)
(test-equal "and the game counts on from there" 5 (scene-data (game-scene counting)))

;;; ---------------------------------------------------------------- hash
(test-equal "#f data hashes as a scene without data always did"
  (reference-scene-hash plain) (scene-hash (update-scene scored data: #f)))
(test-equal "the native and the reference hash agree on data"
  (reference-scene-hash scored) (scene-hash scored))
(test-assert "data changes the hash" (not (= (scene-hash plain) (scene-hash scored))))
(test-equal "equal? data hashes alike" (scene-hash scored)
  (scene-hash (make-scene entities: (list body) data: (list #:coins 3 #:lives 2))))
(test-equal "every kind of plain datum, each kind distinct"
  7
  (length (delete-duplicates
           (map (lambda (d) (scene-hash (make-scene data: d)))
                (list 'a "a" #:a #\a 1 1.0 #(a))))))
(test-equal "lists, dotted pairs, vectors and nesting, each distinct" 5
  (length (delete-duplicates
           (map (lambda (d) (scene-hash (make-scene data: d)))
                (list '(1 2) '(1 . 2) #(1 2) '((1) 2) '(1 (2)))))))
;; The hash is of the data, not of how it prints: a symbol ending in a colon
;; prints as #{a:}# under the host's postfix keywords, as a: without them.
(define colon-symbol (string->symbol "a:"))
(define (colon-hash) (scene-hash (make-scene data: (list colon-symbol))))
(define postfix-hash (begin (read-set! keywords 'postfix) (colon-hash)))
(define plain-hash (begin (read-set! keywords #f) (colon-hash)))
(read-set! keywords 'postfix)
(test-equal "a symbol hashes alike whatever the reader's keyword style" postfix-hash plain-hash)
(test-assert "the symbol a: and the keyword #:a differ"
  (not (= (colon-hash) (scene-hash (make-scene data: (list #:a))))))
(test-assert "-0.0 and 0.0 differ" (not (= (scene-hash (make-scene data: 0.0)) (scene-hash (make-scene data: -0.0)))))
(test-equal "a procedure is refused, named"
  "In procedure scene-hash: data holds #<procedure car (_)>, which is not plain data (numbers, symbols, keywords, strings, chars, booleans, and lists and vectors of them)\n"
  (error-text (lambda () (scene-hash (make-scene data: (list 'score 1 car))))))
(test-equal "a circular list is refused"
  "In procedure scene-hash: data holds a circular list, which is not plain data: (1 2 . #-1#)\n"
  (error-text (lambda () (let ((c (list 1 2))) (set-cdr! (cdr c) c) (scene-hash (make-scene data: c))))))
(test-equal "a vector holding itself is refused"
  "In procedure scene-hash: data: expected plain data nested at most 10000 deep (a cycle through a car or a vector?)\n"
  (error-text (lambda () (let ((v (vector 1))) (vector-set! v 0 v) (scene-hash (make-scene data: v))))))
(test-equal "… and the reference hash says the same"
  (error-text (lambda () (scene-hash (make-scene data: car))))
  (error-text (lambda () (reference-scene-hash (make-scene data: car)))))

(test-end "scene-data")
