;;; Long recordings (issue 45): a replay walks its script once, however many
;;; key frames it has.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke))

(load "support.scm")

(test-begin "recording")

(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-recording-XXXXXX")))

(define (seconds-since start)
  (exact->inexact (/ (- (get-internal-real-time) start) internal-time-units-per-second)))

;; A game that notes the actions held in each frame in SAMPLES (a list of
;; frames), as (frame . held), in the order the frames ran.
(define (sampler script samples seen)
  (make-game engine-update: #f input-script: script
             update: (lambda (game dt)
                       (when (memv (game-frame game) samples)
                         (set-car! seen (cons (cons (game-frame game) (input-held-actions (game-input game)))
                                              (car seen)))))))

;;; ---------------------------------------------------------------- replay
;; The input changes every frame: one key frame a frame, as when the
;; pointer moves. A replay used to walk the script from its head each
;; frame: 10^5 key frames took 27 s on the machine of docs/limits.org.
(define (moving f) (list (if (even? f) 'right 'left) (list 'mouse (modulo f 640) (quotient f 640) '())))
(define key-frames (map (lambda (f) (cons f (moving f))) (iota 100000)))
(define replay-samples '(0 1 50000 99999))
(define replay-seen (list '()))
(define replay-start (get-internal-real-time))
(game-run! (sampler key-frames replay-samples replay-seen) #:frames 100000)
(define replay-took (seconds-since replay-start))
(test-equal "a replay of 10^5 key frames holds each frame's own actions"
  (map (lambda (f) (cons f (moving f))) replay-samples)
  (reverse (car replay-seen)))
(test-assert (format #f "… and runs in time proportional to them (took ~,2f s; under 5 s)" replay-took)
  (< replay-took 5))

;; A rewind goes back past key frames already passed: the replay takes the
;; script up again from there.
(define rewound-seen '())
(define rewound
  (make-game engine-update: #f history: 10
             input-script: '((0 . (a)) (2 . (b)) (4 . (c)) (6 . (d)))
             update: (let ((rewound? #f))
                       (lambda (game dt)
                         (set! rewound-seen (cons (cons (game-frame game) (input-held-actions (game-input game)))
                                                  rewound-seen))
                         (when (and (= (game-frame game) 7) (not rewound?))
                           (set! rewound? #t)
                           (game-rewind! game 5))))))
(game-run! rewound #:frames 9)
(test-equal "a replay rewound from frame 7 to 2 holds frame 2's actions again, and so on"
  '((0 a) (1 a) (2 b) (3 b) (4 c) (5 c) (6 d) (7 d) (2 b) (3 b) (4 c) (5 c) (6 d) (7 d) (8 d))
  (reverse rewound-seen))

(rmdir dir)

(test-end "recording")
