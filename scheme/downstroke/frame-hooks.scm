;; SPDX-License-Identifier: MIT
;;; (downstroke frame-hooks) — procedures of no arguments called at the
;;; start of every frame of every game, on the game's thread (the host polls
;;; its REPL server from one), and whether a headless run keeps to
;;; wall-clock time. docs/engine.org, "Frame hooks".
(define-module (downstroke frame-hooks)
  #:use-module ((srfi srfi-1) #:select (delete))
  #:use-module (downstroke arity)
  #:use-module ((downstroke game) #:select (game-frame))
  #:use-module (downstroke hook-errors)
  #:export (add-frame-hook! remove-frame-hook! run-frame-hooks! frame-pacing))

(define frame-hooks '())
(define (add-frame-hook! proc)
  "Call PROC, a procedure of no arguments, at the start of every frame of
every game run from now on, after the hooks added before it."
  (unless (procedure? proc)
    (scm-error 'wrong-type-arg "add-frame-hook!" "proc: expected a procedure of no arguments, got ~S"
               (list proc) #f))
  (check-hook "add-frame-hook!" "proc" proc '())
  (set! frame-hooks (append frame-hooks (list proc))))
(define (remove-frame-hook! proc)
  "Stop calling PROC (the very procedure add-frame-hook! was given) each frame."
  (set! frame-hooks (delete proc frame-hooks eq?)))

;; #t: game-run! keeps to wall-clock time (frame-delay ms per frame), as a
;; game someone is watching or poking from a REPL must; #f: as fast as it can.
(define frame-pacing (make-parameter #f))


(define (run-frame-hooks! game)
  (for-each (lambda (hook)
              ;; A hook that bounds its own calls (the REPL server's poll) is
              ;; left to do so.
              (let ((bounded (if (procedure-property hook 'own-stack-limit)
                                 hook
                                 (lambda () (call-bounded game "frame hook" hook)))))
                (if (hook-error-reporter)
                    (call-reporting (lambda ()
                                      (format #f "a frame hook (now removed) raised an error in frame ~a"
                                              (game-frame game)))
                                    bounded (lambda () (remove-frame-hook! hook)))
                    (bounded))))
            frame-hooks))
