;;; The live REPL: run a game under `downstroke --repl-server PATH`, connect to
;;; the socket, move an entity from the REPL, and see the running game notice.
(use-modules (srfi srfi-64) (ice-9 popen) (ice-9 rdelim) (ice-9 textual-ports))

(load "support.scm")

(define host (readlink "/proc/self/exe"))
(define game-script (string-append (getenv "DS_TEST_DATA") "/scripts/repl-game.scm"))
(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-repl-XXXXXX")))
(define socket-path (string-append dir "/repl.sock"))

(define (connect-when-ready path tries)
  ;; The game creates the socket before its first frame; wait for it.
  (let ((s (socket PF_UNIX SOCK_STREAM 0)))
    (catch 'system-error
      (lambda () (connect s AF_UNIX path) s)
      (lambda args
        (close-port s)
        (if (zero? tries)
            (apply throw args)
            (begin (usleep 50000) (connect-when-ready path (- tries 1))))))))

(test-begin "repl-server")

(define game (open-pipe* OPEN_READ host "--repl-server" socket-path game-script))
(test-equal "the game starts" "ready" (read-line game))
(test-equal "the socket is private to its owner" #o600
  (logand #o777 (stat:perms (stat socket-path))))

(define client (connect-when-ready socket-path 100))
(display "(game-scene-set! game (scene-map-entities (game-scene game) (lambda (e) (entity-set e x: 500))))\n"
         client)
(force-output client)

(define report (read-line game))
(test-assert "the running game saw the box moved by the REPL"
  (and (string? report) (string-prefix? "moved: x=500 at frame " report)))
(test-equal "the game ended by itself (exit 0)" 0 (status:exit-val (close-pipe game)))
(close-port client)

;;; --repl-port listens on loopback only
(define port-game (open-pipe* OPEN_READ host "--repl-port" "0" game-script))
(test-equal "--repl-port 0 is refused (usage)" 2 (status:exit-val (close-pipe port-game)))

(delete-file socket-path)
(rmdir dir)
(test-end "repl-server")
