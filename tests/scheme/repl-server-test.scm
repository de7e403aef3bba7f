;; SPDX-License-Identifier: MIT
;;; The live REPL: run a game under `downstroke --repl-server PATH`, connect to
;;; the socket, move an entity from the REPL, and see the running game notice.
(use-modules (srfi srfi-64) (ice-9 popen) (ice-9 rdelim) (ice-9 textual-ports) (ice-9 binary-ports)
             (srfi srfi-1))

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
(test-assert "and removed its socket" (not (file-exists? socket-path)))
(close-port client)

;;; --repl-port listens on loopback only
(define port-game (open-pipe* OPEN_READ host "--repl-port" "0" game-script))
(test-equal "--repl-port 0 is refused (usage)" 2 (status:exit-val (close-pipe port-game)))

;;; ------------------------------------------------------------ the server's bounds
;;; A game served with a short time limit, driven client by client. Replies
;;; are read up to the next prompt.

(define served-script (string-append (getenv "DS_TEST_DATA") "/scripts/repl-served.scm"))
(define served-path (string-append dir "/served.sock"))
(define prompt "scheme@(guile-user)> ")
;; The test sends a line too long for the server on purpose: a closed
;; connection must be an error return here, not the end of the suite.
(sigaction SIGPIPE SIG_IGN)

(define (read-until port marker)
  ;; What PORT sends up to and including MARKER, or up to its end, or up to
  ;; " <no more for 10 s>" should the server fall silent.
  (let loop ((acc '()) (n 0))
    (let ((ch (if (or (char-ready? port) (pair? (car (select (list port) '() '() 10))))
                  (read-char port)
                  #f)))
      (cond ((not ch) (string-append (list->string (reverse acc)) " <no more for 10 s>"))
            ((eof-object? ch) (list->string (reverse acc)))
            (else
             (let ((acc (cons ch acc)) (m (string-length marker)))
               (if (and (>= (+ n 1) m) (string=? marker (list->string (reverse (list-head acc m)))))
                   (list->string (reverse acc))
                   (loop acc (+ n 1)))))))))

(define (open-client path)
  (let ((c (connect-when-ready path 100)))
    (read-until c prompt)               ; the banner and the first prompt
    c))

(define (send! c text) (display text c) (newline c) (force-output c))

(define (reply c text)
  ;; What evaluating TEXT printed, the prompt after it left off.
  (send! c text)
  (let ((r (read-until c prompt)))
    (if (string-suffix? prompt r) (string-drop-right r (string-length prompt)) r)))

;; Guile numbers values ($1, $2 …) across all clients of a process: left out.
(define (unnumbered r)
  (if (and (string-prefix? "$" r) (string-contains r " = "))
      (substring r (+ 3 (string-contains r " = ")))
      r))

(define (answer c text) (unnumbered (reply c text)))

(define (value c text)
  ;; The value TEXT evaluates to, from its "$N = VALUE" line.
  (let* ((r (reply c text)) (at (string-contains r " = ")))
    (and at (read (open-input-string (substring r (+ at 3)))))))

(define (start-served path . options)
  (let ((game (apply open-pipe* OPEN_READ host "--repl-server" path (append options (list served-script)))))
    (read-line game)                    ; "ready"
    game))

(define (stop-served game client)
  ;; An update hook that exits ends the game loop: the script's status.
  (send! client "(game-update-set! game (lambda (g dt) (exit 0)))")
  (status:exit-val (close-pipe game)))

(define (run-joined . argv)
  ;; (exit status . everything printed, error port included) of the host run with ARGV.
  (let* ((cmd (string-append (string-join (map (lambda (a) (string-append "'" a "'")) (cons host argv)) " ")
                             " 2>&1"))
         (p (open-pipe* OPEN_READ "/bin/sh" "-c" cmd))
         (text (get-string-all p)))
    (cons (status:exit-val (close-pipe p)) text)))
;; A limit long enough that a loaded machine (CI shares its cores) still
;; answers within it, short enough that the interrupt tests stay quick.

(define served (start-served served-path "--repl-timeout" "2"))
(define m (open-client served-path))

(test-equal "an expression's value" "3\n" (answer m "(+ 1 2)"))
(test-equal "meta-commands work (,use)" "" (reply m ",use (ice-9 ftw)"))
(test-equal "a 1 MB value arrives whole within the 2 s limit (the output port is buffered)"
  (+ 1000000 3)                         ; the quotes and the newline
  (string-length (answer m "(make-string 1000000 #\\a)")))

;;; Connections leave nothing behind.
(define (fd-count) (value m "(length (scandir \"/proc/self/fd\"))"))
(define (thread-count) (value m "(length (scandir \"/proc/self/task\"))"))
(define fds-before (fd-count))
(define threads-before (thread-count))
(define answers
  (map (lambda (i)
         (let* ((c (open-client served-path)) (r (answer c (format #f "(+ ~a 1)" i))))
           (close-port c)
           r))
       (iota 50)))
(test-equal "50 connections, one after another, each answered"
  (map (lambda (i) (format #f "~a\n" (+ i 1))) (iota 50)) answers)
(reply m "#t")                          ; by now the server saw every close
(test-equal "their descriptors are closed again" fds-before (fd-count))
(test-equal "and no thread is left" threads-before (thread-count))

;;; 32 clients waiting at once are all served.
(define waiting (map (lambda (i) (connect-when-ready served-path 100)) (iota 32)))
(for-each (lambda (c i) (send! c (format #f "(* 2 ~a)" i))) waiting (iota 32))
(test-equal "32 simultaneous clients all get their answer"
  (map (lambda (i) (format #f "~a\n" (* 2 i))) (iota 32))
  (map (lambda (c) (read-until c prompt) (unnumbered (string-drop-right (read-until c prompt) (string-length prompt))))
       waiting))
(for-each close-port waiting)

;;; At most 64 at once: with M, 63 more are served and the next is told so.
(answer m "#t")                         ; by now the 32 closes were seen
(define crowd (map (lambda (i) (open-client served-path)) (iota 63)))
(define one-too-many (connect-when-ready served-path 100))
(test-equal "a 65th client is told the server is full, and closed"
  "\ndownstroke: already 64 clients; closing the connection\n"
  (read-until one-too-many "no such marker"))
(close-port one-too-many)
(test-equal "the 64 are served" "64\n" (answer (last crowd) "(+ 63 1)"))
(for-each close-port crowd)
(answer m "#t")

;;; An evaluation reading the REPL's input waits for it without holding the game.
(define reader (open-client served-path))
(send! reader "(read)")
(define frame-reading (value m "(game-frame game)"))
(usleep 100000)
(test-assert "a client's (read) leaves the game running"
  (< frame-reading (value m "(game-frame game)")))
(send! reader "(typed while the game ran)")
(test-equal "and gets what is typed next" "(typed while the game ran)\n"
  (unnumbered (string-drop-right (read-until reader prompt) (string-length prompt))))
(close-port reader)

;;; A game started from the REPL of a served game is refused (issue 35).
(test-assert "game-run! from a served game's REPL is refused, naming game-run!"
  (mentions? (answer m "(game-run! (make-game) frames: 1)")
             "game-run!" "a game is already running" "run games one after another"))

;;; A recursion that never ends, typed at the REPL, ends in stack-overflow
;;; (64 MiB of stack) and the REPL goes on (issue 35).
(test-equal "a runaway recursion at the REPL ends in stack-overflow, with no flood of frames"
  "In procedure repl: the evaluation used up its 64 MiB of Scheme stack: a recursion that never ends?\n"
  (answer m "(let down ((n 0)) (+ 1 (down n)))"))
(test-equal "… and the REPL goes on" "3\n" (answer m "(+ 1 2)"))

;;; A runaway evaluation is interrupted; the game and other clients go on.
(define looper (open-client served-path))
(define other (open-client served-path))
(define frame-before (value m "(game-frame game)"))
(send! looper "(let loop () (loop))")
(send! other "(+ 40 2)")
(test-equal "the loop is interrupted after --repl-timeout, with an error to its client"
  "In procedure repl: evaluation ran past the 2 s limit (--repl-timeout): interrupted\n"
  (string-drop-right (read-until looper prompt) (string-length prompt)))
(test-equal "a client waiting meanwhile is answered" "42\n"
  (unnumbered (string-drop-right (read-until other prompt) (string-length prompt))))
(test-equal "the interrupted client's REPL goes on" "7\n" (answer looper "(+ 3 4)"))
(define frame-after (value m "(game-frame game)"))
(usleep 100000)
(test-assert "the game's frames advance again after the interruption"
  (< frame-before frame-after (value m "(game-frame game)")))
(send! looper "(let loop () (catch #t (lambda () (let spin () (spin))) (lambda _ (loop))))")
(test-equal "an evaluation that catches its interrupt and goes on loses its connection"
  "\ndownstroke: evaluation still running 2 s after its interrupt; closing the connection\n"
  (read-until looper "no such marker"))
(close-port looper)
(test-equal "others are still served" "2\n" (answer other "(+ 1 1)"))

;;; An input line is bounded.
(define flood (open-client served-path))
(display (make-string (+ 1 (* 1024 1024)) #\a) flood)
(force-output flood)
(test-equal "a line longer than 1 MiB is refused and the connection closed"
  "\ndownstroke: input line longer than 1048576 bytes discarded; closing the connection\n"
  (read-until flood "no such marker"))
(close-port flood)
(test-equal "the game still serves the others" "5\n" (answer other "(+ 2 3)"))

;; A 16 MB line (no newline): discarded as it arrives, so the server closes
;; the connection at 1 MiB while the client still writes; its write then
;; fails (EPIPE), and what the server said is still there to read.
(define torrent (open-client served-path))
(define torrent-write
  (catch 'system-error
    (lambda () (display (make-string (* 16 1024 1024) #\b) torrent) (force-output torrent) 'written)
    (lambda (key . args) (system-error-errno (cons key args)))))
(test-assert "a 16 MB line: the server stops reading it (the client's write fails)"
  (memv torrent-write (list EPIPE ECONNRESET)))
;; Read up to the message's end only: closing with input unread, the server
;; resets the connection, so a read past what it sent fails (ECONNRESET).
(test-equal "and says why before it closes"
  "\ndownstroke: input line longer than 1048576 bytes discarded; closing the connection\n"
  (read-until torrent "closing the connection\n"))
(close-port torrent)
(test-equal "the game serves on after the 16 MB line" "8\n" (answer other "(+ 4 4)"))

;;; Output waiting for a client is bounded too.
(define talker (open-client served-path))
(send! talker "(display (make-string (* 5 1024 1024) #\\x))")
(test-equal "an evaluation printing more than 4 MiB loses its connection, told why"
  "\ndownstroke: more than 4194304 bytes of output unread; closing the connection\n"
  (read-until talker "no such marker"))
(close-port talker)
(test-equal "the game serves on" "9\n" (answer other "(+ 4 5)"))

;;; A hook's error pauses the game; replacing the hook lets it go on.
(define hook-report
  (begin (send! m "(game-update-set! game (lambda (g dt) (car '())))")
         (read-until m "(expecting pair): ()\n")))
(define failed-frame
  (let ((at (string-contains hook-report "in frame ")))
    (and at (read (open-input-string (substring hook-report (+ at 9)))))))
(test-assert "the error is reported to the client, naming the frame"
  (and (string-contains hook-report "downstroke: a hook raised an error in frame ")
       (string-contains hook-report "In procedure car: Wrong type argument in position 1 (expecting pair): ()")
       (exact-integer? failed-frame)))
(test-equal "the game is paused on that frame" failed-frame (value m "(game-frame game)"))
(usleep 100000)
(test-equal "and stays there" failed-frame (value m "(game-frame game)"))
(reply m "(game-update-set! game (lambda (g dt) #t))")
(usleep 100000)
(test-assert "a fixed hook lets the game continue" (< failed-frame (value m "(game-frame game)")))
;; A runaway recursion in the served game's update: pauses it the same way,
;; reported without its million frames (issue 35).
(define overflow-report
  (begin (send! m "(game-update-set! game (lambda (g dt) (let down ((n 0)) (+ 1 (down n)))))")
         (read-until m "a recursion that never ends?\n")))
(test-assert "a stack overflow in update: is reported, naming the hook, and pauses the game"
  (and (string-contains overflow-report "downstroke: a hook raised an error in frame ")
       (string-contains overflow-report
                        "In procedure update:: the hook used up its 64 MiB of Scheme stack (make-game stack-limit:): a recursion that never ends?")))
(test-assert "… in a few lines, not the recursion's frames"
  (<= (length (string-split overflow-report #\newline)) 6))
(reply m "(game-update-set! game (lambda (g dt) #t))")
(usleep 100000)

(send! m "(add-frame-hook! (lambda () (error \"frame hook failed\")))")
(define frame-hook-report (read-until m "frame hook failed\n"))
(test-assert "a failing frame hook is reported and removed"
  (string-contains frame-hook-report "downstroke: a frame hook (now removed) raised an error in frame "))
(define after-frame-hook (value m "(game-frame game)"))
(usleep 100000)
(test-assert "and the game goes on" (< after-frame-hook (value m "(game-frame game)")))

;;; A hook that never ends, set from the REPL, is interrupted after
;;; --repl-timeout like an evaluation: reported as any hook error, the game
;;; paused on the frame, the REPL answering (issue 45).
(define (report-frame report)
  ;; The number after "in frame " (read would take "12:" for a keyword).
  (let ((at (string-contains report "in frame ")))
    (and at (let ((from (+ at 9)))
              (string->number (substring report from (or (string-skip report char-numeric? from)
                                                         (string-length report))))))))
(define (from-report report)
  ;; REPORT from the server's "downstroke: " line on (the prompt and the
  ;; setter's value before it left out).
  (let ((at (string-contains report "downstroke: ")))
    (if at (substring report at) report)))
(define endless-report
  (begin (send! m "(game-update-set! game (lambda (g dt) (let loop () (loop))))")
         (read-until m "interrupted\n")))
(define endless-frame (report-frame endless-report))
(test-equal "an endless update hook is interrupted after --repl-timeout, reported as a hook error"
  (format #f "downstroke: a hook raised an error in frame ~a; the game is paused on it until \
a hook (game-update-set! ...) or the scene (game-scene-set! ...) is replaced:
In procedure update:: the hook ran past the 2 s limit (--repl-timeout): interrupted\n" endless-frame)
  (from-report endless-report))
(test-equal "the REPL answers meanwhile" "3\n" (answer m "(+ 1 2)"))
(test-equal "and the game is paused on that frame" endless-frame (value m "(game-frame game)"))
(reply m "(game-update-set! game (lambda (g dt) #t))")
(usleep 100000)
(test-assert "a fixed hook lets it go on" (< endless-frame (value m "(game-frame game)")))

(define endless-frame-hook-report
  (begin (send! m "(add-frame-hook! (lambda () (let loop () (loop))))")
         (read-until m "interrupted\n")))
(test-equal "an endless frame hook is interrupted, reported and removed"
  (format #f "downstroke: a frame hook (now removed) raised an error in frame ~a:
In procedure frame hook: the hook ran past the 2 s limit (--repl-timeout): interrupted\n"
          (report-frame endless-frame-hook-report))
  (from-report endless-frame-hook-report))
(define after-endless-frame-hook (value m "(game-frame game)"))
(usleep 100000)
(test-assert "and the game goes on without it" (< after-endless-frame-hook (value m "(game-frame game)")))

(define stubborn-report
  (begin (send! m "(game-update-set! game (lambda (g dt) (let loop () (catch #t (lambda () (let spin () (spin))) (lambda _ (loop))))))")
         (read-until m "cut off\n")))
(test-assert "a hook that catches its interrupt and runs on is cut off one limit later"
  (and (string-contains stubborn-report "downstroke: a hook raised an error in frame ")
       (string-suffix? "In procedure update:: the hook still ran 2 s after its interrupt (--repl-timeout): cut off\n"
                       stubborn-report)))
(test-equal "… and the REPL still answers" "5\n" (answer m "(+ 2 3)"))
(reply m "(game-update-set! game (lambda (g dt) #t))")

;;; The socket path: a live socket, a file that is not one, a stale one.
(test-equal "a socket a game is serving on is refused"
  (cons 2 (format #f "downstroke: --repl-server ~a: another server is listening on it\n" served-path))
  (run-joined "--repl-server" served-path served-script))
(test-equal "the refused game left the first one's socket working" "2\n"
  (let* ((c (open-client served-path)) (r (answer c "(+ 1 1)"))) (close-port c) r))
(test-equal "the served game ends by itself (exit 0)" 0 (stop-served served m))
(test-assert "an (exit 0) from a hook removes the socket" (not (file-exists? served-path)))
(close-port m)
(close-port other)

(define plain-path (string-append dir "/plain"))
(call-with-output-file plain-path (lambda (p) (display "keep me" p)))
(test-equal "a path that exists and is not a socket is refused, naming it"
  (cons 2 (format #f "downstroke: --repl-server ~a: it exists and is not a socket; left alone\n" plain-path))
  (run-joined "--repl-server" plain-path served-script))
(test-equal "and left as it was" "keep me" (call-with-input-file plain-path get-string-all))
(delete-file plain-path)

(define stale-path (string-append dir "/stale.sock"))
(let ((s (socket PF_UNIX SOCK_STREAM 0))) (bind s AF_UNIX stale-path) (close-port s))
(test-equal "a stale socket is there" 'socket (stat:type (stat stale-path)))
(define stale-game (start-served stale-path))
(define stale-client (open-client stale-path))
(test-equal "a stale socket is replaced and served on" "6\n" (answer stale-client "(* 2 3)"))
(test-equal "that game ends by itself too" 0 (stop-served stale-game stale-client))
(close-port stale-client)
(test-assert "and the socket it took over is removed with it" (not (file-exists? stale-path)))

;;; The socket goes whichever way the game ends.
(define failing-path (string-append dir "/failing.sock"))
(define failing
  (run-joined "--repl-server" failing-path (string-append (getenv "DS_TEST_DATA") "/scripts/repl-failing.scm")))
(test-equal "a script that fails ends with status 1" 1 (car failing))
(test-assert "and its message" (string-contains (cdr failing) "the script failed after its game"))
(test-assert "and its socket is removed" (not (file-exists? failing-path)))

(define (signalled sig)
  ;; How a served game ended once sent SIG, and whether its socket is left.
  (let* ((path (string-append dir "/signalled.sock"))
         (game (start-served path))
         (c (open-client path))
         (pid (value c "(getpid)")))
    (kill pid sig)
    (let ((status (close-pipe game)))
      (close-port c)
      (list (status:term-sig status) (file-exists? path)))))
(test-equal "SIGTERM still ends the game by that signal, and the socket goes" (list SIGTERM #f) (signalled SIGTERM))
(test-equal "so does SIGINT (Ctrl-C)" (list SIGINT #f) (signalled SIGINT))

(define moved-path (string-append dir "/moved.sock"))
(define moved-game (start-served moved-path))
(define moved-client (open-client moved-path))
(rename-file moved-path (string-append dir "/elsewhere.sock"))
(call-with-output-file moved-path (lambda (p) (display "not the game's" p)))
(test-equal "a file put in the socket's place meanwhile" 0 (stop-served moved-game moved-client))
(test-equal "is left alone when the game ends" "not the game's" (call-with-input-file moved-path get-string-all))
(close-port moved-client)
(for-each delete-file (list moved-path (string-append dir "/elsewhere.sock")))

;;; ------------------------------------------------------------ issue 45
;;; A fresh game, so that its peak memory is this section's alone.
(define fresh-path (string-append dir "/fresh.sock"))
(define fresh (start-served fresh-path "--repl-timeout" "2"))
(define f (open-client fresh-path))
(define (peak-kib)
  (value f "(call-with-input-file \"/proc/self/status\" (lambda (p) (let loop () (let ((l ((@ (ice-9 rdelim) read-line) p))) (if (string-prefix? \"VmHWM:\" l) (read (open-input-string (substring l 6))) (loop))))))"))
(define peak-before (peak-kib))

;; An unfinished expression: 10 MB inside an open string, in lines of
;; 64 KiB (each under the line bound). Without a bound the game grew by
;; over 300 MB holding it.
(define unclosed (open-client fresh-path))
(catch 'system-error
  (lambda ()
    (display "(define big \"" unclosed)
    (do ((i 0 (+ i 1))) ((= i 160))
      (display (make-string 65535 #\x) unclosed) (newline unclosed) (force-output unclosed)))
  (lambda _ #f))                        ; the server closes the connection at its bound
(test-equal "an unfinished expression past 1 MiB is discarded and its client closed"
  "\ndownstroke: unfinished expression longer than 1048576 bytes discarded; closing the connection\n"
  (read-until unclosed "closing the connection\n"))
(close-port unclosed)
(test-assert "and the game's peak memory grew by less than 96 MiB (not the 300 MB it took)"
  (< (- (peak-kib) peak-before) (* 96 1024)))
(test-equal "an expression over several lines is still read whole" "2\n"
  (answer f "(string-length\n \"ab\"\n)"))

;; Bytes that are not UTF-8 (a surrogate's encoding) ended the client's
;; REPL and left its descriptors open: after 64 such clients no one could
;; connect.
(define (fresh-fd-count) (value f "(length (scandir \"/proc/self/fd\"))"))
(reply f ",use (ice-9 ftw)")
(define fresh-fds (fresh-fd-count))
(define not-utf-8-replies
  (map (lambda (i)
         (let ((c (open-client fresh-path)))
           (put-bytevector c #vu8(#x28 #x64 #x69 #x73 #x70 #x6c #x61 #x79 #x20 #x22 #xed #xa0 #x80 #x22 #x29 #x0a))
           (force-output c)
           (let ((r (read-until c "no such marker"))) (close-port c) r)))
       (iota 70)))
(test-equal "70 clients sending bytes that are not UTF-8 are each told so and closed"
  (make-list 70 "\ndownstroke: input that is not valid UTF-8 discarded; closing the connection\n")
  not-utf-8-replies)
(test-equal "then a new client is served" "4\n"
  (let* ((c (open-client fresh-path)) (r (answer c "(+ 2 2)"))) (close-port c) r))
(answer f "#t")                         ; by now the server saw every close
(test-equal "and the descriptors are back where they were" fresh-fds (fresh-fd-count))

;; ,q leaves the REPL and the game runs on; (exit) ends the game, as it
;; does from a hook or the script, and says so.
(define leaver (open-client fresh-path))
(send! leaver ",q")
(test-equal ",q closes only that connection" "" (read-until leaver "no such marker"))
(close-port leaver)
(test-equal "the game runs on" "6\n" (answer f "(* 2 3)"))
(send! f "(exit 4)")
(test-equal "(exit) at the REPL says that it ends the game"
  "\ndownstroke: (exit) ends the game (,q leaves only this REPL); closing the connection\n"
  (read-until f "no such marker"))
(test-equal "and ends it with its status" 4 (status:exit-val (close-pipe fresh)))
(test-assert "removing its socket" (not (file-exists? fresh-path)))
(close-port f)

;;; --repl-port serves the same REPL on 127.0.0.1 (a port some other
;;; program holds is refused, exit 2: then the next one is tried).
(define (start-tcp-served tries)
  (let* ((port (+ 20000 (modulo (+ (getpid) (* 7919 tries)) 20000)))
         (game (open-pipe* OPEN_READ host "--repl-port" (number->string port) served-script)))
    (if (string? (read-line game))
        (cons game port)
        (begin (close-pipe game) (and (> tries 0) (start-tcp-served (- tries 1)))))))
(define tcp-game (start-tcp-served 3))
(define tcp-client
  (let ((s (socket PF_INET SOCK_STREAM 0)))
    (connect s AF_INET INADDR_LOOPBACK (cdr tcp-game))
    (read-until s prompt)
    s))
(test-equal "--repl-port serves on loopback" "12\n" (answer tcp-client "(* 3 4)"))

;; A web page can make a browser POST to 127.0.0.1:PORT (fetch, mode
;; "no-cors"): a first line that looks like HTTP closes the connection
;; before anything reaches the REPL (as Guile's own server, CVE-2016-8606).
(define (tcp-send text)
  ;; What the server answers TEXT with, up to its closing the connection.
  (let ((s (socket PF_INET SOCK_STREAM 0)))
    (connect s AF_INET INADDR_LOOPBACK (cdr tcp-game))
    (display text s)
    (force-output s)
    (let ((r (read-until s "no such marker"))) (close-port s) r)))
(define http-witness (string-append dir "/written-by-a-web-page"))
(define refused-http
  "\ndownstroke: the first line looks like an HTTP request, not Scheme; nothing was evaluated; closing the connection\n")
(define (after-banner r)
  ;; R past the banner and first prompt a client is sent on connecting.
  (let ((at (string-contains r prompt))) (if at (substring r (+ at (string-length prompt))) r)))
(test-equal "an HTTP POST is refused, its body not evaluated"
  refused-http
  (after-banner
   (tcp-send (format #f "POST / HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\n\r\n(call-with-output-file ~s (lambda (p) (display 1 p)))\n" http-witness))))
(test-equal "a first line that is a header is refused too"
  refused-http
  (after-banner (tcp-send (format #f "Host: 127.0.0.1\r\n\r\n(call-with-output-file ~s (lambda (p) (display 1 p)))\n" http-witness))))
(test-equal "as is any request line ending in HTTP/x.y"
  refused-http
  (after-banner (tcp-send (format #f "PROPFIND /x HTTP/1.0\r\n\r\n(call-with-output-file ~s (lambda (p) (display 1 p)))\n" http-witness))))
(test-equal "an ordinary client is still served" "20\n" (answer tcp-client "(* 4 5)"))
(test-assert "and nothing a request carried was evaluated" (not (file-exists? http-witness)))
(test-equal "that game ends by itself as well" 0 (stop-served (car tcp-game) tcp-client))
(close-port tcp-client)

;;; A served game is paced: its loop sleeps between frames. A flonum or a
;;; fraction frame-delay: used to end it on its first frame with usleep's
;;; "Wrong type (expecting exact integer)" (issue 45).
(define flonum-script (string-append dir "/flonum-delay.scm"))
(call-with-output-file flonum-script
  (lambda (p)
    (write '(for-each (lambda (delay)
                        (let ((g (make-game frame-delay: delay)))
                          (game-run! g frames: 5)
                          (format #t "~a: ~a frames~%" delay (game-frame g))))
                      '(16.5 50/3))
           p)))
(test-equal "a served game with a flonum or a fraction frame-delay runs its frames"
  '(0 . "16.5: 5 frames\n50/3: 5 frames\n")
  (run-joined "--no-auto-compile" "--repl-server" (string-append dir "/flonum.sock") flonum-script))
(delete-file flonum-script)

;;; reload-script! from the REPL: the served game's script, saved with a new
;;; update, evaluated again in the running game; a broken one reported to
;;; the client, the game running on. The script runs its game in (once …):
;;; a reload must not print "ready" again, nor exit. Served without
;;; watching (--no-watch): the reloads are the REPL's alone. Its update:
;;; calls `update' by name, as a script written for the REPL does.
(define reload-script (string-append dir "/reloaded.scm"))
(define* (write-reloaded! version #:optional (body "(game-scene-set! game (update-scene (game-scene game) entities: (list (list #:id 'box #:version '~a))))"))
  (call-with-output-file reload-script
    (lambda (p)
      (format p "(define (update game dt) ~a)
(define-once game (make-game frame-delay: 16 scene: (make-scene entities: '()) update: (lambda (g dt) (update g dt))))
(once (display \"ready\\n\") (force-output) (game-run! game frames: 3000) (display \"timeout\\n\") (exit 3))
" (format #f body version)))))
(define (version-now c)
  (value c "(entity-ref (car (scene-entities (game-scene game))) #:version)"))
(write-reloaded! "old")
(define reload-path (string-append dir "/reload.sock"))
(define reloading (let ((g (open-pipe* OPEN_READ host "--no-watch" "--repl-server" reload-path reload-script)))
                    (read-line g)       ; "ready"
                    g))
(define r (open-client reload-path))
(test-equal "a served game runs its script's update" 'old (version-now r))
(write-reloaded! "new")
(test-equal "(reload-script!) from the REPL reloads it" "#t\n" (answer r "(reload-script!)"))
(test-equal "… and the next frames run the new update" 'new (version-now r))
(call-with-output-file reload-script (lambda (p) (display "(define (update game dt) (car '()))\n(car '())\n" p)))
(define reload-report (begin (send! r "(reload-script!)") (read-until r prompt)))
(test-assert "a broken script's reload is reported to the client, and fails"
  (and (string-contains reload-report
                        (string-append "downstroke: reloading " reload-script
                                       " raised an error; its old definitions stay, and the game runs on:\n"))
       (string-contains reload-report "In procedure car: Wrong type argument in position 1 (expecting pair): ()\n")
       (string-suffix? "#f\n" (string-drop-right reload-report (string-length prompt)))))
(define frame-after-reload (value r "(game-frame game)"))
(usleep 100000)
(test-assert "… and the game runs on with the update it had"
  (and (< frame-after-reload (value r "(game-frame game)")) (eq? 'new (version-now r))))
;; A reload that brings a failing update pauses the game on its frame, as a
;; failing hook does; the reload that fixes it lets the frame run again,
;; though no lever changed (update: calls the new update by name).
(write-reloaded! "" "(car '())")
(test-equal "a script whose update fails reloads" "#t\n" (answer r "(reload-script!)"))
(define paused-report (read-until r "(expecting pair): ()\n"))
(define paused-frame (report-frame paused-report))
(test-assert "… and its first frame fails and pauses the game, reported"
  (and (string-contains paused-report "downstroke: a hook raised an error in frame ")
       (exact-integer? paused-frame)))
(usleep 100000)
(test-equal "the game stays on that frame" paused-frame (value r "(game-frame game)"))
(write-reloaded! "fixed")
(test-equal "the reload of the fix" "#t\n" (answer r "(reload-script!)"))
(usleep 100000)
(test-assert "… lets the failed frame run again, and the game go on with the fix"
  (and (< paused-frame (value r "(game-frame game)")) (eq? 'fixed (version-now r))))
(test-equal "the reloaded game ends by itself (exit 0)" 0 (stop-served reloading r))
(close-port r)
(delete-file reload-script)

;;; Options, and the game without a server.
(test-assert "--help documents --repl-timeout"
  (string-contains (cdr (run-joined "--help")) "--repl-timeout S"))
(test-equal "--repl-timeout must be a positive number" 2
  (car (run-joined "--repl-timeout" "0" "--repl-server" served-path served-script)))
(define unserved (run-joined (string-append (getenv "DS_TEST_DATA") "/scripts/hook-error.scm")))
(test-equal "without a server a hook's error still ends the script (status 1)" 1 (car unserved))
(test-assert "with its message" (string-contains (cdr unserved) "update failed in frame 3"))

(when (file-exists? socket-path) (delete-file socket-path))
(when (file-exists? served-path) (delete-file served-path))
(rmdir dir)
(test-end "repl-server")
