;; SPDX-License-Identifier: MIT
;;; (downstroke script-arguments) — what a game script was started with:
;;; whether it is the program itself, and its arguments.
;;; docs/engine.org, "The downstroke command".
(define-module (downstroke script-arguments)
  #:export (main-script? script-number-argument))

(define (main-script? name)
  "Whether the script the host was started with is named NAME (its base
name): a file can define a game for others to load and run it only when it
is the program itself."
  (let ((args (program-arguments)))
    (and (pair? args) (string? (car args)) (string=? (basename (car args)) name))))

(define (script-number-argument n default)
  "The script's Nth argument (from 0) as a number, or DEFAULT: e.g. how many
frames to run, as in `downstroke demo/sandbox.scm 3600'."
  (let* ((args (program-arguments))
         (arg (and (> (length args) (+ n 1)) (list-ref args (+ n 1))))
         (v (and arg (string->number arg))))
    (or v default)))
