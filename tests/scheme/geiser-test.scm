;; SPDX-License-Identifier: MIT
;;; Geiser attached to a served game: Emacs in batch mode runs
;;; tests/emacs/geiser-session.el, which attaches with geiser-connect-local
;;; (--repl-server) and geiser-connect (--repl-port) as a user does, and
;;; prints what evaluation, completion and documentation lookup answered.
;;; Registered only when emacs and Geiser are installed (tests/CMakeLists.txt).
(use-modules (srfi srfi-64) (ice-9 popen) (ice-9 rdelim) (ice-9 textual-ports))

(load "support.scm")

(define host (readlink "/proc/self/exe"))
(define served-script (string-append (getenv "DS_TEST_DATA") "/scripts/repl-served.scm"))
(define session (string-append (dirname (getenv "DS_TEST_DATA")) "/emacs/geiser-session.el"))
(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-geiser-XXXXXX")))

(define (geiser-answers address)
  ;; What the session printed, as (name value) lists; ADDRESS is the
  ;; environment naming the game (DS_GEISER_SOCKET=… or DS_GEISER_PORT=…).
  ;; timeout: a hung editor fails the test instead of hanging it.
  (let* ((p (open-pipe* OPEN_READ "env" address "timeout" "60" "emacs" "--batch" "-Q" "-l" session))
         (text (get-string-all p)))
    (close-pipe p)
    (let ((in (open-input-string text)))
      (let loop ((acc '()))
        (let ((x (read in)))
          (if (eof-object? x) (reverse acc) (loop (cons x acc))))))))

(define (stop! game)
  ;; The served game ends when an update hook exits: via a plain client.
  (let ((c (socket PF_UNIX SOCK_STREAM 0)))
    (connect c AF_UNIX (string-append dir "/game.sock"))
    (display "(game-update-set! game (lambda (g dt) (exit 0)))\n" c)
    (force-output c)
    (let ((status (status:exit-val (close-pipe game))))
      (close-port c)
      status)))

(define expected
  `((eval "=> 3")
    (downstroke "=> 7")
    (error wrong-type-arg)
    (after-error "=> 42")
    (completions ("scene-query-point" "scene-query-rect"))
    ;; Geiser names the module it found the binding in: (downstroke), whose
    ;; public interface holds every export of the user modules.
    (docstring ,(string-append "A procedure in module (downstroke).\n\n"
                               (procedure-documentation step-scene)))
    (autodoc ((entity-set ("args" (("required" entity key value) ("optional") ("key")))
                          ("module" downstroke))))))

(test-begin "geiser")

(define socket-path (string-append dir "/game.sock"))
(define game (open-pipe* OPEN_READ host "--repl-server" socket-path served-script))
(test-equal "the served game starts" "ready" (read-line game))
(define local-answers (geiser-answers (string-append "DS_GEISER_SOCKET=" socket-path)))
(for-each (lambda (want)
            (test-equal (format #f "geiser-connect-local: ~a" (car want))
              want (assq (car want) local-answers)))
          expected)
(test-equal "the game ends by itself after Geiser left (exit 0)" 0 (stop! game))

;;; --repl-port: a port some other program holds is refused (exit 2), then the next is tried.
(define (start-tcp-served tries)
  (let* ((port (+ 20000 (modulo (+ (getpid) 4099 (* 7919 tries)) 20000)))
         (game (open-pipe* OPEN_READ host "--repl-port" (number->string port) served-script)))
    (if (string? (read-line game))
        (cons game port)
        (begin (close-pipe game) (and (> tries 0) (start-tcp-served (- tries 1)))))))
(define tcp-game (start-tcp-served 3))
(define tcp-answers (geiser-answers (format #f "DS_GEISER_PORT=~a" (cdr tcp-game))))
(for-each (lambda (want)
            (test-equal (format #f "geiser-connect: ~a" (car want))
              want (assq (car want) tcp-answers)))
          expected)
(let ((c (socket PF_INET SOCK_STREAM 0)))
  (connect c AF_INET INADDR_LOOPBACK (cdr tcp-game))
  (display "(game-update-set! game (lambda (g dt) (exit 0)))\n" c)
  (force-output c)
  (test-equal "that game ends by itself too" 0 (status:exit-val (close-pipe (car tcp-game))))
  (close-port c))

(rmdir dir)
(test-end "geiser")
