;; SPDX-License-Identifier: MIT
;;; (downstroke loop) — the fixed-step kernel every run of a game goes
;;; through: read the clock, poll, take the fixed steps the time owes (at
;;; most a few), present, wait for the next present. It reads no clock of
;;; its own: a back end gives it one, so (downstroke headless) runs it on a
;;; clock that a step's wait moves on exactly, (downstroke window) on the
;;; real one, and a test on a fake one. docs/render.org, "Three ways to run
;;; a game".
(define-module (downstroke loop)
  #:export (run-fixed-step! max-catch-up-steps real-clock wait-until step-ticks))

;; A display frame that finds more than this many fixed steps due runs only
;; these and drops the rest of the backlog: a stall (a breakpoint, a slow
;; REPL expression, a dragged window) is then a hiccup, never a spiral of
;; ever longer catch-up frames.
(define max-catch-up-steps 5)

(define* (run-fixed-step! #:key clock sleep-until tick period poll step finished? present
                          (pause-when-unfocused? #f) (catch-up max-catch-up-steps))
  ;; Real time at a fixed timestep ("Fix Your Timestep!"): time accumulates,
  ;; and each fixed step of TICK (in CLOCK's units) consumes it. Each turn:
  ;; (POLL) gives #f to end the run, or (input . focused?); then as many
  ;; (STEP input) as the time owes, at most CATCH-UP, stopping early once
  ;; (FINISHED?); then (PRESENT elapsed alpha dropped): ELAPSED the clock
  ;; since the run began, ALPHA the share of a step the clock holds past the
  ;; last one (what drawing between the last two steps needs), DROPPED the
  ;; steps stalls have lost so far. The next present is PERIOD on; a loop
  ;; that fell behind presents at once and counts afresh from there
  ;; ((SLEEP-UNTIL time) waits for it). Unfocused, with
  ;; PAUSE-WHEN-UNFOCUSED?, no time is owed: no step, and no burst of
  ;; catch-up steps when the focus comes back. The first turn owes one step.
  (let ((start (clock)))
    (let loop ((last start) (owed tick) (next-present start) (dropped 0))
      (let ((polled (poll)))
        (when polled
          (let* ((input (car polled))
                 (paused? (and pause-when-unfocused? (not (cdr polled))))
                 (now (clock))
                 (owed (if paused? 0 (+ owed (- now last))))
                 (due (floor (/ owed tick)))
                 (steps (min due catch-up)))
            (let step-due ((k 0))
              (when (and (< k steps) (not (finished?)))
                (step input)
                (step-due (+ k 1))))
            (let* ((dropped (+ dropped (- due steps)))
                   (owed (if (> due steps) 0 (- owed (* steps tick))))
                   (alpha (min 1 (max 0 (exact->inexact (/ owed tick))))))
              (present (- now start) alpha dropped)
              (let* ((next (+ next-present period))
                     (next (if (< next (clock)) (clock) next)))
                (sleep-until next)
                (loop now owed next dropped)))))))))

;;; The real clock, in internal time units.
(define (real-clock) (get-internal-real-time))

(define (wait-until deadline)
  ;; usleep takes an exact count of µs: a deadline off a flonum frame-delay
  ;; is rounded to one.
  (let ((now (get-internal-real-time)))
    (when (< now deadline)
      (usleep (round (/ (* (- (inexact->exact deadline) now) 1000000) internal-time-units-per-second))))))

(define (step-ticks frame-delay)
  ;; One step of FRAME-DELAY ms in internal time units, exact (a flonum
  ;; frame-delay taken as the exact number it is): the loops' deadlines and
  ;; counts of steps due are then exact integers, as usleep and the step
  ;; loop need.
  (* (inexact->exact frame-delay) (/ internal-time-units-per-second 1000)))
