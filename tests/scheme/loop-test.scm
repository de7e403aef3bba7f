;; SPDX-License-Identifier: MIT
;;; The fixed-step kernel (downstroke loop) on a fake clock: which turns step
;;; how often, what each present is told, the catch-up cap after a stall,
;;; and no steps (and no burst after) while unfocused.
(use-modules (srfi srfi-64) (downstroke loop))

(test-begin "loop")

;;; Runs the kernel for TURNS turns on a clock that only the kernel's waits
;;; and the stalls move: STALLS is ((turn . time) …), time the clock jumps
;;; by as that turn polls; UNFOCUSED the turns whose poll says the focus is
;;; lost. Returns ((steps elapsed alpha dropped) …), one a turn.
(define* (run-kernel #:key (tick 10) (period 10) (turns 5) (stalls '()) (unfocused '())
                     (pause-when-unfocused? #f) (finished-after #f))
  (let ((now 0) (turn 0) (steps 0) (total 0) (log '()))
    (run-fixed-step!
     #:clock (lambda () now)
     #:sleep-until (lambda (t) (set! now (max now t)))
     #:tick tick #:period period
     #:pause-when-unfocused? pause-when-unfocused?
     #:poll (lambda ()
              (set! turn (+ turn 1))
              (set! now (+ now (or (assv-ref stalls turn) 0)))
              (and (<= turn turns) (cons 'input (not (memv turn unfocused)))))
     #:step (lambda (input)
              (unless (eq? input 'input) (error "step: not the polled input" input))
              (set! steps (+ steps 1))
              (set! total (+ total 1)))
     #:finished? (lambda () (and finished-after (>= total finished-after)))
     #:present (lambda (elapsed alpha dropped)
                 (set! log (cons (list steps elapsed alpha dropped) log))
                 (set! steps 0)))
    (reverse log)))

(define (steps-of log) (map car log))

(test-equal "a present per step: one step each turn, on time"
  '((1 0 0.0 0) (1 10 0.0 0) (1 20 0.0 0) (1 30 0.0 0) (1 40 0.0 0))
  (run-kernel))

(test-equal "presents every 10 for steps of 16: six steps in ten turns, drawn α of the way on"
  '((1 0 0.0 0) (0 10 0.625 0) (1 20 0.25 0) (0 30 0.875 0) (1 40 0.5 0)
    (1 50 0.125 0) (0 60 0.75 0) (1 70 0.375 0) (1 80 0.0 0) (0 90 0.625 0))
  (run-kernel #:tick 16 #:turns 10))

(test-equal "a stall of 30 is caught up in full: four steps, then the next present at once"
  '(1 1 4 0 1)
  (steps-of (run-kernel #:stalls '((3 . 30)))))

(test-equal "a stall of 100: at most 5 steps, the other 6 dropped, and the next present at once"
  '((1 0 0.0 0) (1 10 0.0 0) (5 120 0.0 6) (0 120 0.0 6) (1 130 0.0 6))
  (run-kernel #:stalls '((3 . 100))))

(test-equal "the cap is the kernel's own bound" 5 max-catch-up-steps)

(test-equal "unfocused, told to pause: no steps, and none owed when the focus comes back"
  '(1 1 0 0 0 1 1)
  (steps-of (run-kernel #:turns 7 #:unfocused '(3 4 5) #:pause-when-unfocused? #t)))

(test-equal "unfocused, not told to pause: it steps on"
  '(1 1 1 1 1 1 1)
  (steps-of (run-kernel #:turns 7 #:unfocused '(3 4 5))))

(test-equal "a stall and then the focus lost: the time stalled is not owed"
  '(1 1 0 0 1)
  (steps-of (run-kernel #:stalls '((3 . 100)) #:unfocused '(3) #:pause-when-unfocused? #t)))

(test-equal "finished? ends a turn's steps: 2 of the 4 a stall owes"
  '(1 1 0 0 0)
  (steps-of (run-kernel #:stalls '((3 . 30)) #:finished-after 2)))

(test-equal "a poll of #f ends the run before anything steps" '() (run-kernel #:turns 0))

(test-end "loop")
