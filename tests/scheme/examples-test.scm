;; SPDX-License-Identifier: MIT
;;; The five short examples (demo/examples/*.scm), one idea each, run
;;; headless with their built-in input and checked with exact values. The
;;; test watches each run through a frame hook: the examples keep no record
;;; of themselves.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke) (downstroke testing))

(load "support.scm")   ; demo-dir

(define (load-example name)
  (load-in-fresh-module (string-append demo-dir "/examples/" name)))

(define (traced name frames)
  "(game . ends): the example NAME's fresh game played FRAMES frames, and a
vector of the entities each frame ended with. A frame hook runs at the
start of each frame, so it sees the frame before ended; it runs once more
after the last."
  (let* ((game ((module-ref (load-example name) 'new-game)))
         (ends (make-vector frames #f))
         (hook (lambda ()
                 (let ((frame (- (game-frame game) 1)))
                   (when (<= 0 frame (- frames 1))
                     (vector-set! ends frame (scene-entities (game-scene game))))))))
    (add-frame-hook! hook)
    (play game frames: frames)
    (remove-frame-hook! hook)
    (cons game ends)))

(define (at run frame . keys)
  "The first entity's KEYS as FRAME ended, in RUN (from traced)."
  (let ((e (car (vector-ref (cdr run) frame))))
    (map (lambda (k) (entity-ref e k #f)) keys)))

(define (range a b) (iota (- b a) a))   ; a .. b-1

(test-begin "examples")

(test-group "jump.scm"
  ;; Pressed at frame 20 on the ground (y 160): vy -15 + gravity 1 = -14 at
  ;; frame 21, then 13, 12, … up: the apex is 160 - (14 + 13 + … + 1) = 55.
  (let ((run (traced "jump.scm" 60)))
    (test-equal "standing, then rising from frame 21" '((160 #t) (146 #f))
      (list (at run 20 #:y #:on-ground?) (at run 21 #:y #:on-ground?)))
    (test-equal "the apex: y 55, reached at frame 34" '(55 34)
      (let ((ys (map (lambda (k) (car (at run k #:y))) (range 0 60))))
        (list (apply min ys) (list-index (lambda (y) (= y 55)) ys))))
    (test-equal "the scene's data kept it" 55 (scene-data (game-scene (car run))))
    (test-equal "and the way down mirrors the way up: landed where it stood at frame 49"
      '((146 #f) (160 #t)) (list (at run 48 #:y #:on-ground?) (at run 49 #:y #:on-ground?)))))

(test-group "plank.scm"
  ;; The plank's top is y 128: the 16 px hero stands on it at y 112.
  (let ((run (traced "plank.scm" 90)))
    (test-equal "from below it passes up through the plank, to y 55" '(55 -1 #f)
      (at run 24 #:y #:vy #:on-ground?))
    (test-equal "and from above the plank holds it: landed at frame 36" '((110 10 #f) (112 0 #t))
      (list (at run 35 #:y #:vy #:on-ground?) (at run 36 #:y #:vy #:on-ground?)))
    (test-assert "standing on it until Down (frame 60)"
      (every (lambda (k) (equal? '(112 #t) (at run k #:y #:on-ground?))) (range 36 61)))
    (test-equal "with Down held it dropped through, back on the ground at frame 70" '((157 9 #f) (160 0 #t))
      (list (at run 69 #:y #:vy #:on-ground?) (at run 70 #:y #:vy #:on-ground?)))))

(test-group "ramp.scm"
  ;; Foot of the 1:2 ramp at x 704 (y 176), 45° from 720 to 736, top y 144.
  (let ((run (traced "ramp.scm" 60)))
    (test-equal "on the flat, y exact" '(691 160) (at run 22 #:x #:y))
    (test-equal "up the 1:2 ramp: 1.5 px for 3 across, as flonums" '((709 151.5) (712 150.0))
      (list (at run 28 #:x #:y) (at run 29 #:x #:y)))
    (test-equal "up the 45° one: 3 for 3" '((727 141.0) (730 138.0))
      (list (at run 34 #:x #:y) (at run 35 #:x #:y)))
    (test-equal "on top, y 144 - 16 = 128, from frame 39 to the end" '(745 128.0 #t)
      (at run 40 #:x #:y #:on-ground?))
    (test-assert "on the ground every frame of the climb"
      (every (lambda (k) (car (at run k #:on-ground?))) (range 0 60)))
    (test-equal "stopped there (Right released at 45)" '(760 128.0 #t) (at run 59 #:x #:y #:on-ground?))))

(test-group "pickup.scm"
  ;; The coin (8×8 at x 100) meets the 12 px hero at x 91: 40 + 3·17.
  (let ((run (traced "pickup.scm" 60)))
    (test-equal "the coin is there at frame 21, gone at 22"
      '((hero coin) (hero)) (map (lambda (k) (map (lambda (e) (entity-ref e #:id)) (vector-ref (cdr run) k)))
                                 '(21 22)))
    (test-equal "counted at frame 22, the hero at x 91" '(91 1) (at run 22 #:x #:coins))
    (test-equal "the sensor never moved the hero: 3 px a frame through it" '(88 91 94)
      (map (lambda (k) (car (at run k #:x))) '(21 22 23)))
    (test-equal "one coin sound, at frame 22" '((22 . coin)) (game-sounds (car run)))))

(test-group "tween.scm"
  ;; 16 ms a frame: after frame k the tween has run 16(k + 1) ms. Each leg
  ;; takes 480 ms (30 frames); quad-in-out is halfway at half the time.
  (let ((run (traced "tween.scm" 125)))
    (test-equal "halfway across at frame 14 (240 ms)" '(152.0) (at run 14 #:x))
    (test-equal "there at frame 29, back at 59, there at 89" '((264.0) (40.0) (264.0))
      (map (lambda (k) (at run k #:x)) '(29 59 89)))
    (test-equal "frame 9: 40 + 224 · ease(160/480)"
      (+ 40 (* 224 (ease 'quad-in-out 1/3))) (car (at run 9 #:x)))
    ;; Frame 118 ends 1904 ms in: 464 ms into the last leg, 16 ms from home.
    (test-equal "still in flight at frame 118, blue" '(40.49777777777777 (120 180 255))
      (at run 118 #:x #:color))
    (test-equal "done at frame 119: x exactly 40, the tween gone, on-complete made it yellow"
      '(40 #f yellow) (at run 119 #:x #:tween #:color))))

(test-end "examples")
