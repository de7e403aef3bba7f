;; SPDX-License-Identifier: MIT
;;; geiser-session.el --- what tests/scheme/geiser-test.scm has Geiser do
;;; against a served game: attach the way a user does (geiser-connect to
;;; DS_GEISER_PORT, or geiser-connect-local to DS_GEISER_SOCKET), then ask
;;; what the editor asks, printing each answer as one readable line.
;;; Run with: emacs --batch -Q -l geiser-session.el (DS_GEISER_LISP: Geiser's elisp).

(setq load-path (cons (getenv "DS_GEISER_LISP") load-path))
(require 'geiser-guile)
(require 'geiser-repl)
(setq geiser-repl-query-on-kill-p nil
      geiser-repl-history-filename nil)

(let ((port (getenv "DS_GEISER_PORT")))
  (if port
      (geiser-connect 'guile "localhost" (string-to-number port))
    (geiser-connect-local 'guile (getenv "DS_GEISER_SOCKET"))))

(defun ds-answer (name value)
  (princ (format "(%s %S)\n" name value)))

;; What C-x C-e sends (geiser-debug--send-region).
(defun ds-eval (code)
  (geiser-eval--send/wait `(:eval (:scm ,code))))

(ds-answer 'eval (geiser-eval--retort-result-str (ds-eval "(+ 1 2)") nil))
(ds-answer 'downstroke (geiser-eval--retort-result-str
                        (ds-eval "(entity-ref (entity-set (car (scene-entities (game-scene game))) #:x 7) #:x)") nil))
(ds-answer 'error (geiser-eval--error-key (geiser-eval--retort-error (ds-eval "(car '())"))))
(ds-answer 'after-error (geiser-eval--retort-result-str (ds-eval "(* 6 7)") nil))
(ds-answer 'completions (geiser-completion--symbol-list "scene-q"))
(ds-answer 'docstring (cdr (assoc "docstring" (geiser-doc--get-docstring 'step-scene :f))))
(ds-answer 'autodoc (geiser-eval--send/result '(:eval (:ge autodoc (:scm "'(entity-set)")))))
