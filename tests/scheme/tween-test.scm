;; SPDX-License-Identifier: MIT
(use-modules (srfi srfi-64) (downstroke) (srfi srfi-1) (srfi srfi-9)
             ((downstroke native) #:select (%register-tween-type!)))

(load "support.scm")

;;; ENTITY with a tween made from it stored under #:tween.
(define (tweened entity . args)
  (entity-set entity #:tween (apply make-tween entity args)))
;;; Step ENTITY's tween by each dt in turn; the entities after each step.
(define (steps entity . dts)
  (let loop ((e entity) (dts dts) (acc '()))
    (if (null? dts)
        (reverse acc)
        (let ((next (step-tweens e #f (car dts))))
          (loop next (cdr dts) (cons next acc))))))
(define (xs entities) (map (lambda (e) (entity-ref e #:x)) entities))

(test-begin "tween")

;;; ---------------------------------------------------------------- linear
;; x 100 → 200 over 400 ms: value = 100 + 100·t.
(define e0 (tweened '(#:x 100 #:y 5) props: '((#:x . 200)) duration: 400))
(test-assert (tween? (entity-ref e0 #:tween)))
(define run0 (steps e0 100 100 100 100))
(test-equal "t = .25, .5, .75, then the exact target" '(125.0 150.0 175.0 200) (xs run0))
(test-assert "mid-way values are flonums" (every inexact? (xs (list-head run0 3))))
(test-assert "the end value is the target itself (exact)" (exact? (entity-ref (last run0) #:x)))
(test-assert "the tween is still there mid-way" (tween? (entity-ref (caddr run0) #:tween)))
(test-equal "at the end #:tween is removed, other keys untouched" '(#:x 200 #:y 5) (last run0))
(test-equal "overshooting in one step" '(#:x 200 #:y 5) (step-tweens e0 #f 1000))
(test-equal "exactly the duration in one step" '(#:x 200 #:y 5) (step-tweens e0 #f 400))
(test-eq "after the end: nothing to do" (last run0) (step-tweens (last run0) #f 16))
(test-equal "the entity holding the tween is not mutated" 100 (entity-ref e0 #:x))
(test-equal "uneven steps: 30 + 70 + 150 = 250 → 162.5" 162.5
  (entity-ref (last (steps e0 30 70 150)) #:x))
(test-equal "flonum dt" 125.0 (entity-ref (step-tweens e0 #f 100.0) #:x))
;; Several properties; a missing start key reads 0 and is appended.
(define e1 (tweened '(#:name "t" #:x 0 #:y 10) props: '((#:x . 50) (#:y . 0) (#:alpha . 1)) duration: 100))
(let ((half (step-tweens e1 #f 50)))
  (test-equal '(25.0 5.0 0.5) (map (lambda (k) (entity-ref half k)) '(#:x #:y #:alpha)))
  (test-equal "keys in place, the new one appended" '(#:name #:x #:y #:tween #:alpha)
    (let loop ((p half) (acc '())) (if (null? p) (reverse acc) (loop (cddr p) (cons (car p) acc))))))
(test-equal "all targets at the end" '(#:name "t" #:x 50 #:y 0 #:alpha 1) (step-tweens e1 #f 100))
;; A flonum target is written as given.
(test-equal '(#:x 2.5) (step-tweens (tweened '(#:x 0) props: '((#:x . 2.5)) duration: 10) #f 10))
;; Start values are read when the tween is made.
(test-equal "start read at creation" 25.0
  (entity-ref (step-tweens (entity-set '(#:x 50) #:tween (make-tween '(#:x 0) props: '((#:x . 100)) duration: 100))
                           #f 25)
              #:x))
;; Duration 0: done on the first step.
(test-equal "duration 0" '(#:x 7) (step-tweens (tweened '(#:x 0) props: '((#:x . 7)) duration: 0) #f 16))
;; Negative direction.
(test-equal '(75.0 50.0 0) (xs (steps (tweened '(#:x 100) props: '((#:x . 0)) duration: 100) 25 25 50)))
;; Props of physics and non-physics keys alike.
(test-equal "a non-physics key" '(#:hp 5.0)
  (let ((e (step-tweens (tweened '(#:hp 0) props: '((#:hp . 10)) duration: 100) #f 50)))
    (list #:hp (entity-ref e #:hp))))
;; Empty props: the tween only measures time.
(test-equal "no props" '(#:x 1) (step-tweens (tweened '(#:x 1) props: '() duration: 10) #f 10))

;;; ---------------------------------------------------------------- delay
;; delay 100, duration 200, x 0 → 100.
(define ed (tweened '(#:x 0) props: '((#:x . 100)) duration: 200 delay: 100))
(let ((r (steps ed 50 100 150)))
  (test-equal "before the delay: x untouched" 0 (entity-ref (car r) #:x))
  (test-assert "before the delay: the tween stays" (tween? (entity-ref (car r) #:tween)))
  (test-equal "150 ms: t = 50/200" 25.0 (entity-ref (cadr r) #:x))
  (test-equal "300 ms: done" '(#:x 100) (caddr r)))

;;; ---------------------------------------------------------------- repeat and yoyo
;; repeat 1, duration 100, x 0 → 10: two cycles.
(define er (tweened '(#:x 0) props: '((#:x . 10)) duration: 100 repeat: 1))
(test-equal "repeat: 50 → 5.0, 100 → restart (0.0), 150 → 5.0, 200 → end"
  '(5.0 0.0 5.0 10) (xs (steps er 50 50 50 50)))
(test-assert "repeat: still running after the first cycle"
  (tween? (entity-ref (step-tweens er #f 150) #:tween)))
(test-equal "repeat: removed after the last" #f (entity-ref (step-tweens er #f 200) #:tween))
;; Delay only before the first cycle: delay 100, repeat 1 → ends at 300.
(define erd (tweened '(#:x 0) props: '((#:x . 10)) duration: 100 delay: 100 repeat: 1))
(test-equal "delay then two cycles" '(0 5.0 5.0 10) (xs (steps erd 50 100 100 50)))
;; yoyo, repeat 1: 0 → 10, then back 10 → 0.
(define ey (tweened '(#:x 0) props: '((#:x . 10)) duration: 100 repeat: 1 yoyo?: #t))
(test-equal "yoyo: 50 → 5.0, 125 → 7.5, 175 → 2.5, 200 → the start value"
  '(5.0 7.5 2.5 0) (xs (steps ey 50 75 50 25)))
(test-assert "yoyo ends exactly on the start value (exact)" (exact? (entity-ref (step-tweens ey #f 200) #:x)))
(test-equal "yoyo without repeat ends at the target" '(#:x 10)
  (step-tweens (tweened '(#:x 0) props: '((#:x . 10)) duration: 100 yoyo?: #t) #f 100))
(test-equal "yoyo, repeat 2: forward, back, forward" '(#:x 10)
  (step-tweens (tweened '(#:x 0) props: '((#:x . 10)) duration: 100 repeat: 2 yoyo?: #t) #f 300))
(test-equal "yoyo, repeat 2, in the backward cycle: 150 → 5.0, 180 → 2.0" '(5.0 2.0)
  (xs (steps (tweened '(#:x 0) props: '((#:x . 10)) duration: 100 repeat: 2 yoyo?: #t) 150 30)))
;; Forever.
(define ef (tweened '(#:x 0) props: '((#:x . 100)) duration: 100 repeat: -1))
(test-equal "forever: 1050 ms → cycle 10, t .5" 50.0 (entity-ref (step-tweens ef #f 1050) #:x))
(test-assert "forever: never removed" (tween? (entity-ref (step-tweens ef #f 100000) #:tween)))
(define efy (tweened '(#:x 0) props: '((#:x . 100)) duration: 100 repeat: -1 yoyo?: #t))
(test-equal "forever yoyo: 150 → 50.0, 175 → 25.0, 260 → 60.0" '(50.0 25.0 60.0)
  (xs (steps efy 150 25 85)))

;;; ---------------------------------------------------------------- on-complete
(define completions '())
(define ec (tweened '(#:x 0 #:hp 3) props: '((#:x . 10)) duration: 100
                    on-complete: (lambda (e) (set! completions (cons e completions)) 'not-an-entity)))
(define ec-run (steps ec 60 60 60 60))
(test-equal "called once" 1 (length completions))
(test-equal "with the final entity (no #:tween)" '(#:x 10 #:hp 3) (car completions))
(test-equal "a non-entity result is ignored" '(#:x 10 #:hp 3) (cadr ec-run))
(test-eq "later steps: nothing" (cadr ec-run) (cadddr ec-run))
(test-equal "not called before the end" '(6.0) (begin (set! completions '())
                                                      (let ((r (step-tweens ec #f 60)))
                                                        (cons (entity-ref r #:x) completions))))
(define ec2 (tweened '(#:x 0) props: '((#:x . 10)) duration: 100
                     on-complete: (lambda (e) (entity-set e #:done #t))))
(test-equal "its entity is the result" '(#:x 10 #:done #t) (step-tweens ec2 #f 100))
(define ec3 (tweened '(#:x 0) props: '((#:x . 10)) duration: 50 repeat: 1
                     on-complete: (lambda (e) (entity-set e #:cycles-done 2))))
(test-equal "with repeat: only after the last cycle" '(#f 2)
  (list (entity-ref (step-tweens ec3 #f 60) #:cycles-done)
        (entity-ref (step-tweens ec3 #f 100) #:cycles-done)))
;; on-complete may start another tween (chaining).
(define chain (tweened '(#:x 0) props: '((#:x . 10)) duration: 100
                       on-complete: (lambda (e) (tweened e props: '((#:x . 0)) duration: 100))))
(test-equal "chained tween: there and back" '(10 5.0 0) (xs (steps chain 100 50 50)))

;;; ---------------------------------------------------------------- easing
(define easing-list
  '(linear quad-in quad-out quad-in-out cubic-in cubic-out cubic-in-out quart-in quart-out
    quart-in-out sine-in sine-out sine-in-out expo-in expo-out expo-in-out back-in back-out
    back-in-out elastic-in elastic-out elastic-in-out bounce-in bounce-out bounce-in-out))
(test-equal 25 (length easing-list))
(test-equal "easing-names lists them all" (sort (map symbol->string easing-list) string<?)
  (sort (map symbol->string easing-names) string<?))
;; Every name: accepted, starts at the start value, ends exactly at the target.
(for-each
 (lambda (name)
   (let ((e (tweened '(#:x 0) props: '((#:x . 100)) duration: 100 ease: name)))
     (test-equal (string-append (symbol->string name) ": t = 0") 0.0
       (exact->inexact (entity-ref (step-tweens e #f 0) #:x)))
     (test-equal (string-append (symbol->string name) ": end") '(#:x 100) (step-tweens e #f 100))))
 easing-list)
;; Values at t = 1/2 (easings.net formulas).
(define half-values
  `((linear . 0.5) (quad-in . 0.25) (quad-out . 0.75) (quad-in-out . 0.5)
    (cubic-in . 0.125) (cubic-out . 0.875) (cubic-in-out . 0.5)
    (quart-in . 0.0625) (quart-out . 0.9375) (quart-in-out . 0.5)
    (sine-in . ,(- 1 (cos (/ 3.141592653589793 4)))) (sine-out . ,(sin (/ 3.141592653589793 4)))
    (sine-in-out . 0.5)
    (expo-in . 0.03125) (expo-out . 0.96875) (expo-in-out . 0.5)
    ;; back-in: 2.70158·(1/8) − 1.70158·(1/4)
    (back-in . ,(- (* 2.70158 0.125) (* 1.70158 0.25)))
    (back-out . ,(- 1 (- (* 2.70158 0.125) (* 1.70158 0.25))))
    (back-in-out . 0.5)
    ;; elastic-in: −2^(−5)·sin((5 − 10.75)·2π/3) = −(1/32)·sin(π/6)
    (elastic-in . -0.015625) (elastic-out . 1.015625) (elastic-in-out . 0.5)
    ;; bounce-out(.5): u = .5 − 1.5/2.75, 7.5625·u² + .75 = 0.765625
    (bounce-out . 0.765625) (bounce-in . 0.234375) (bounce-in-out . 0.5)))
(for-each
 (lambda (p)
   (test-approximate (string-append (symbol->string (car p)) " at 1/2") (cdr p) (ease (car p) 0.5) 1e-9)
   (test-approximate (string-append (symbol->string (car p)) " through a tween")
     (* 100 (cdr p))
     (entity-ref (step-tweens (tweened '(#:x 0) props: '((#:x . 100)) duration: 100 ease: (car p)) #f 50) #:x)
     1e-7))
 half-values)
(test-equal "quad-in at 1/4" 6.25
  (entity-ref (step-tweens (tweened '(#:x 0) props: '((#:x . 100)) duration: 100 ease: 'quad-in) #f 25) #:x))
(test-equal "ease at 0" 0 (inexact->exact (ease 'bounce-in 0)))
(test-equal "ease at 1" 1 (inexact->exact (ease 'elastic-out 1)))
(test-error "ease: an unknown name" (ease 'wobbly 0.5))
(test-assert "make-tween: a key twice"
  (mentions? (error-text (lambda () (make-tween '(#:x 0) props: '((#:x . 1) (#:y . 2) (#:x . 3)))))
             "make-tween" "duplicate" "#:x"))
(test-assert "make-tween: the #:tween key itself"
  (mentions? (error-text (lambda () (make-tween '(#:x 0) props: '((#:tween . 1))))) "make-tween" "#:tween"))
(let* ((t (make-tween '(#:x 0) props: '((#:x . 5)) duration: 100))
       (u (tween-with-elapsed t 40.0)))
  (test-equal "tween-with-elapsed" '(40.0 0) (list (tween-elapsed u) (tween-elapsed t)))
  (test-equal "tween-with-elapsed keeps the rest" (tween-props t) (tween-props u))
  (test-equal "tween-on-complete" #f (tween-on-complete u)))
;; A custom ease procedure.
(define squares '())
(define custom (tweened '(#:x 0) props: '((#:x . 100)) duration: 100
                        ease: (lambda (t) (set! squares (cons t squares)) (* t t))))
(test-equal "custom ease: t² at .5" 25.0 (entity-ref (step-tweens custom #f 50) #:x))
(test-equal "custom ease receives t" 0.5 (car squares))
(test-approximate "custom ease at .3" 9.0 (entity-ref (step-tweens custom #f 30) #:x) 1e-9)
(test-equal "custom ease: the end is the target" '(#:x 100) (step-tweens custom #f 100))
(test-assert "custom ease returning a non-number is an error"
  (error-text (lambda () (step-tweens (tweened '(#:x 0) props: '((#:x . 1)) duration: 10
                                               ease: (lambda (t) 'fast))
                                      #f 5))))

;;; ---------------------------------------------------------------- errors
(define (make-error . args) (error-text (lambda () (apply make-tween '(#:x 0) args))))
(test-assert "props not a list" (mentions? (make-error props: 'x duration: 10) "make-tween" "props"))
(test-assert "props key not a keyword" (mentions? (make-error props: '((x . 1)) duration: 10) "make-tween" "props"))
(test-assert "props target not a number" (mentions? (make-error props: '((#:x . "1")) duration: 10) "props" "\"1\""))
(test-assert "props target +nan.0" (mentions? (make-error props: (list (cons #:x +nan.0)) duration: 10) "props"))
(test-assert "props entry not a pair" (mentions? (make-error props: '(#:x) duration: 10) "props"))
(test-assert "duration negative" (mentions? (make-error props: '() duration: -1) "make-tween" "duration" "-1"))
(test-assert "duration a string" (mentions? (make-error props: '() duration: "1s") "duration"))
(test-assert "duration +inf.0" (mentions? (make-error props: '() duration: +inf.0) "duration"))
(test-assert "delay negative" (mentions? (make-error props: '() duration: 1 delay: -5) "delay" "-5"))
(test-assert "repeat not an integer" (mentions? (make-error props: '() duration: 1 repeat: 1.5) "repeat" "1.5"))
(test-assert "repeat below -1" (mentions? (make-error props: '() duration: 1 repeat: -2) "repeat"))
(test-assert "forever with duration 0" (mentions? (make-error props: '() duration: 0 repeat: -1) "repeat"))
(test-assert "unknown easing name" (mentions? (make-error props: '() duration: 1 ease: 'wobbly) "ease" "wobbly"))
(test-assert "easing neither name nor procedure" (mentions? (make-error props: '() duration: 1 ease: 3) "ease"))
(test-assert "on-complete not a procedure" (mentions? (make-error props: '() duration: 1 on-complete: 'done) "on-complete" "done"))
(test-assert "a start value that is not a number"
  (mentions? (error-text (lambda () (make-tween '(#:x "left") props: '((#:x . 1)) duration: 10))) "make-tween" "\"left\""))
(test-assert "step-tweens: #:tween is not a tween"
  (mentions? (error-text (lambda () (step-tweens '(#:tween soon) #f 16))) "step-tweens" "#:tween" "soon"))
(test-assert "step-tweens: dt not a number"
  (error-text (lambda () (step-tweens (tweened '(#:x 0) props: '((#:x . 1)) duration: 10) #f "16"))))
(test-assert "step-tweens: a malformed entity"
  (mentions? (error-text (lambda () (step-tweens '(#:x 0 #:tween) #f 16))) "step-tweens" "malformed entity"))
(let ((e '(#:x 0 #:tween #f)))
  (test-eq "#:tween #f: nothing to do" e (step-tweens e #f 16)))

;;; ---------------------------------------------------------------- skip-pipelines + tweens (seed)
;; The seed's knockback pattern: skip acceleration, gravity, velocity-x and
;; velocity-y while a tween drives #:x; tile resolution stays active.
;; Floor: row 10 (y 160); wall: column 3 (x [48, 64)). The enemy rests on the
;; floor; #:vx −5 gives the tile resolution its direction.
(define (grid-map cols rows solid)
  (let ((v (make-vector (* cols rows) 0)))
    (for-each (lambda (c) (vector-set! v (+ (car c) (* cols (cdr c))) 1)) solid)
    (make-tilemap cols rows 16 16 v '(1))))
(define arena (grid-map 20 12 (append (map (lambda (c) (cons c 10)) (iota 20))
                                      (map (lambda (r) (cons 3 r)) (iota 10)))))
(define enemy0 '(#:id enemy #:x 100 #:y 144 #:width 16 #:height 16 #:gravity? #t #:on-ground? #t
                 #:vx -5 #:skip-pipelines (acceleration gravity velocity-x velocity-y)))
(define (frames scene n dt)
  (let loop ((i 0) (s scene) (acc '()))
    (if (= i n) (reverse acc)
        (let ((next (step-scene s dt))) (loop (+ i 1) next (cons (car (scene-entities next)) acc))))))
(define knock-scene
  (make-scene tilemap: arena
              entities: (list (tweened enemy0 props: '((#:x . 60)) duration: 100))))
;; dt 20: t = .2 … 1: x = 100 − 40t = 92.0, 84.0, 76.0, 68.0, then 60 exact;
;; at 60 the box [60, 76) overlaps column 3 and vx < 0 → x = (3 + 1)·16 = 64, vx 0.
;; Afterwards nothing moves it (velocities skipped, vx 0).
(define knock-frames (frames knock-scene 7 20))
(test-equal "x driven by the tween, then snapped out of the wall" '(92.0 84.0 76.0 68.0 64 64 64)
  (xs knock-frames))
(test-assert "snapped value exact" (exact? (entity-ref (list-ref knock-frames 4) #:x)))
(test-equal "vx untouched until the wall is hit" '(-5 -5 -5 -5 0 0 0)
  (map (lambda (e) (entity-ref e #:vx)) knock-frames))
(test-equal "y: gravity and velocity-y skipped" '(144 144 144 144 144 144 144)
  (map (lambda (e) (entity-ref e #:y)) knock-frames))
(test-equal "vy never written" '(#f #f #f #f #f #f #f) (map (lambda (e) (entity-ref e #:vy)) knock-frames))
(test-equal "on the ground throughout" '(#t #t #t #t #t #t #t)
  (map (lambda (e) (entity-ref e #:on-ground?)) knock-frames))
(test-equal "the tween is gone after frame 5" '(#t #t #t #t #f #f #f)
  (map (lambda (e) (tween? (entity-ref e #:tween))) knock-frames))
(test-eq "at rest after the tween: the same entity" (list-ref knock-frames 5) (list-ref knock-frames 6))
;; The same with on-complete clearing the skips: it runs in the tween stage,
;; so the rest of frame 5 already moves the body: x = 60 − 5 = 55, box
;; [55, 71) overlaps column 3 → 64; gravity: vy 1, y 145 → back to 144, vy 0.
(define knock-scene-2
  (make-scene tilemap: arena
              entities: (list (tweened enemy0 props: '((#:x . 60)) duration: 100
                                       on-complete: (lambda (e) (entity-set e #:skip-pipelines '()))))))
(define knock-frames-2 (frames knock-scene-2 7 20))
(test-equal "on-complete: x" '(92.0 84.0 76.0 68.0 64 64 64) (xs knock-frames-2))
(test-equal "on-complete: the skips are cleared" '() (entity-ref (list-ref knock-frames-2 4) #:skip-pipelines))
(test-equal "on-complete: gravity resumes, the floor holds" '(144 144 144)
  (map (lambda (e) (entity-ref e #:y)) (list-tail knock-frames-2 4)))
(test-equal "on-complete: vy 0 after each landing" '(0 0 0)
  (map (lambda (e) (entity-ref e #:vy 0)) (list-tail knock-frames-2 4)))
;; Without tile resolution the tween's target stands inside the wall.
(define ghost-scene
  (make-scene tilemap: arena
              entities: (list (tweened (entity-set enemy0 #:skip-pipelines
                                                   '(acceleration gravity velocity-x velocity-y tile-collisions-x))
                                       props: '((#:x . 60)) duration: 100))))
(test-equal "tile-collisions-x skipped too: ends at 60" 60
  (entity-ref (car (scene-entities (step-scene ghost-scene 100))) #:x))
;; The tweens skip: step-scene leaves the tween alone.
(define frozen
  (make-scene entities: (list (tweened '(#:x 0 #:skip-pipelines (tweens)) props: '((#:x . 10)) duration: 10))))
(test-eq "tweens skipped: the scene is unchanged" frozen (step-scene frozen 16))

;;; ---------------------------------------------------------------- the record the native side reads
;; The stepper reads <tween> by position, so registering a record type with
;; other fields (or the same in another order) is refused, naming both.
(define-record-type <swapped-tween>
  (make-swapped-tween duration props delay ease ease-index repeat yoyo? on-complete elapsed)
  swapped-tween?
  (duration swapped-duration) (props swapped-props) (delay swapped-delay) (ease swapped-ease)
  (ease-index swapped-ease-index) (repeat swapped-repeat) (yoyo? swapped-yoyo?)
  (on-complete swapped-on-complete) (elapsed swapped-elapsed))
(define-record-type <short-tween> (make-short-tween props elapsed) short-tween?
  (props short-props) (elapsed short-elapsed))
(test-assert "a record type with the fields in another order is refused"
  (mentions? (error-text (lambda () (%register-tween-type! <swapped-tween>)))
             "%register-tween-type!" "(duration props delay"
             "(props duration delay ease ease-index repeat yoyo? on-complete elapsed)" "by position"))
(test-assert "a record type with fewer fields is refused"
  (mentions? (error-text (lambda () (%register-tween-type! <short-tween>))) "(props elapsed)"))
(test-assert "a non-record is refused"
  (mentions? (error-text (lambda () (%register-tween-type! 'tween))) "%register-tween-type!" "record type" "tween"))
(test-equal "tweens still step after a refusal" '(#:x 200 #:y 5) (step-tweens e0 #f 1000))

(test-end "tween")
