;; SPDX-License-Identifier: 0BSD
;;; (demo events) — what happened in a demo, (frame . what), newest first:
;;; printed as it happens when the demo is the host's script, and kept, the
;;; newest 500 to 1000 (a bounded log, docs/engine.org), for a REPL looking
;;; back and for the soak bench, which checks that it stays bounded. The
;;; tests watch the frames themselves, through a frame hook.
(define-module (demo events)
  #:use-module (srfi srfi-9)
  #:use-module (downstroke)
  #:export (make-events events? events-items note-event!))

(define-record-type <events>
  (%make-events log trace?)
  events?
  (log events-log set-events-log!)
  (trace? events-trace?))

;; The newest kept, at least: the log drops its older half past twice this.
(define kept-events 500)

(define (make-events trace?)
  "A new, empty log; TRACE?: print each note as it comes."
  (%make-events (make-bounded-log) trace?))

(define (events-items events)
  "What EVENTS holds, newest first."
  (bounded-log-items (events-log events)))

(define (note-event! events frame what)
  "Note WHAT at FRAME in EVENTS, and print it when tracing."
  (set-events-log! events (bounded-log-push (events-log events) (cons frame what) kept-events))
  (when (events-trace? events) (format #t "frame ~3d: ~a~%" frame what)))
