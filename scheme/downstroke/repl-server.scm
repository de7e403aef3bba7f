;; SPDX-License-Identifier: MIT
;;; (downstroke repl-server) — the live REPL into a running game.
;;;
;;; Polled once per frame on the game's own thread, so expressions see and
;;; change the game between two frames without locks. It never blocks and
;;; keeps no thread per client: each client runs Guile's own REPL (prompts,
;;; meta-commands, the debugger — what Geiser expects) inside a prompt, and
;;; when that REPL would wait for input it is suspended (suspendable ports)
;;; and resumed by a later poll that brought it some. What one client may
;;; cost is bounded: its input line, its unread output, the time one
;;; evaluation may hold the game.
(define-module (downstroke repl-server)
  #:use-module (downstroke error-text)
  #:use-module (system repl repl)
  #:use-module (system repl common)
  #:use-module (system repl debug)
  #:use-module (system repl error-handling)
  #:use-module ((system syntax) #:select (syntax?))
  #:use-module (ice-9 suspendable-ports)
  #:use-module (rnrs bytevectors)
  #:use-module ((ice-9 iconv) #:select (bytevector->string))
  #:use-module (ice-9 regex)
  #:use-module (srfi srfi-1)
  #:use-module (srfi srfi-9)
  #:use-module ((system vm vm) #:select (call-with-stack-overflow-handler))
  #:export (default-repl-timeout open-unix-repl-socket open-tcp-repl-socket
            remove-unix-repl-socket!
            make-repl-server repl-server-poll! repl-server-broadcast!
            call-with-hook-time-limit))

;;; ---------------------------------------------------------------- tunables

;; Seconds one evaluation may hold the game before it is interrupted: long
;; enough for any reasonable expression typed at a game, short enough that
;; a runaway loop is a hiccup, not a hang (--repl-timeout changes it).
(define default-repl-timeout 3)

;; Connections the kernel queues until the next frame accepts them: a burst
;; of editors and scripts connecting at once (the suite checks 32).
(define *listen-backlog* 64)

;; Clients served at once: each costs three descriptors and its buffers.
(define *max-clients* 64)

;; The longest input line a client may send: far beyond any form typed or
;; sent by an editor, and small enough that a runaway sender (a 16 MB string)
;; cannot make the game hold it in memory.
(define *max-line-bytes* (* 1024 1024))

;; Text fed to a client's REPL since it last began reading an expression at
;; its prompt: an unfinished expression (an unclosed string or list) is held
;; by Guile's reader, which took about 27 bytes of memory per byte (10 MB
;; in an open string grew the game by 271 MB). As much as one line may
;; hold, which is far beyond any form typed or pasted.
(define *max-pending-bytes* (* 1024 1024))

;; Bytes read from a client's socket per frame: a fast sender gets 4 MB/s
;; at 60 frames a second, and a frame's work stays bounded however many
;; clients send at once.
(define *recv-chunk-bytes* 65536)

;; Output waiting to be sent to a client — what one evaluation prints (it is
;; sent between frames) and what the client has not read yet: past it, a
;; client that stopped reading, or a value far too big to print, is dropped.
(define *max-output-bytes* (* 4 1024 1024))

;;; ---------------------------------------------------------------- sockets

(define (refuse fmt . args)
  (scm-error 'misc-error "open-unix-repl-socket" fmt args #f))

(define (socket-live? path)
  ;; Whether something accepts connections on PATH (else it is stale).
  (let ((probe (socket PF_UNIX SOCK_STREAM 0)))
    (catch 'system-error
      (lambda () (connect probe AF_UNIX path) (close-port probe) #t)
      (lambda args (close-port probe) #f))))

(define (clear-socket-path! path)
  ;; Only a stale socket is ever removed: a file of the user's, or a socket
  ;; another game serves on, is left alone and refused.
  (let ((st (false-if-exception (lstat path))))
    (when st
      (cond ((not (eq? (stat:type st) 'socket))
             (refuse "--repl-server ~a: it exists and is not a socket; left alone" path))
            ((socket-live? path)
             (refuse "--repl-server ~a: another server is listening on it" path))
            (else (delete-file path))))))

(define (open-unix-repl-socket path)
  "A listening Unix socket at PATH, mode 0600. PATH may not exist yet or be
a stale socket; anything else there is refused (a 'misc-error naming PATH)."
  (clear-socket-path! path)
  ;; Created under umask 077, so it is never open to others, not even
  ;; between bind and chmod.
  (let ((old (umask #o077))
        (sock (socket PF_UNIX SOCK_STREAM 0)))
    (dynamic-wind
      (lambda () #t)
      (lambda () (bind sock AF_UNIX path) (chmod path #o600))
      (lambda () (umask old)))
    (set! (socket-file sock) (cons path (socket-identity path)))
    sock))

;; What open-unix-repl-socket bound a socket to: (PATH . identity).
(define socket-file (make-object-property))

(define (socket-identity path)
  (let ((st (false-if-exception (lstat path))))
    (and st (eq? (stat:type st) 'socket) (cons (stat:dev st) (stat:ino st)))))

(define (remove-unix-repl-socket! sock)
  "Remove the file SOCK (from open-unix-repl-socket) was bound to, if that
path still is this socket: a game that ends leaves nothing behind, and never
removes what someone else put there since."
  (let ((bound (socket-file sock)))
    (when (and bound (equal? (cdr bound) (socket-identity (car bound))))
      (false-if-exception (delete-file (car bound)))
      (set! (socket-file sock) #f))))

(define (open-tcp-repl-socket port)
  "A listening TCP socket on 127.0.0.1:PORT: loopback only, since a REPL is
arbitrary code execution."
  (let ((sock (socket PF_INET SOCK_STREAM 0)))
    (setsockopt sock SOL_SOCKET SO_REUSEADDR 1)
    (bind sock AF_INET INADDR_LOOPBACK port)
    sock))

(define (non-blocking! port)
  (fcntl port F_SETFL (logior O_NONBLOCK (fcntl port F_GETFL))))

;;; ---------------------------------------------------------------- clients
;;; Input goes socket → our staging (where the line bound is kept) → one end
;;; of a socket pair → the REPL, which reads the other end; output goes the
;;; REPL → a soft port into OUTBOX → the socket. The game writes and reads
;;; only what the kernel takes at once.

(define-record-type <client>
  (%make-client sock feed in out)
  client?
  (sock client-sock)                          ; the connection
  (feed client-feed)                          ; our end of the pair
  (in client-in)                              ; the REPL's end
  (out client-out set-client-out!)            ; the REPL's output port
  (partial client-partial set-client-partial!)   ; the unfinished line, reversed pieces
  (partial-bytes client-partial-bytes set-client-partial-bytes!)
  (ready client-ready set-client-ready!)      ; whole lines not yet fed, in order
  (ready-bytes client-ready-bytes set-client-ready-bytes!)
  (outbox client-outbox set-client-outbox!)   ; bytevectors not yet sent, newest first
  (outbox-bytes client-outbox-bytes set-client-outbox-bytes!)
  (cont client-cont set-client-cont!)         ; the suspended REPL, or #f
  (eof? client-eof? set-client-eof!)          ; the client sent all it will send
  (closing client-closing set-client-closing!) ; #f, or why it is dropped
  (vetted? client-vetted? set-client-vetted!) ; its first line was checked (not HTTP)
  (pending client-pending set-client-pending!) ; bytes fed since its REPL's last prompt
  (evaluating? client-evaluating? set-client-evaluating!) ; an expression of its runs
  (exit client-exit set-client-exit!))        ; #f, or the arguments of its (exit)

(define (make-client sock)
  (let* ((pair (socketpair PF_UNIX SOCK_STREAM 0))
         (c (%make-client sock (car pair) (cdr pair) #f)))
    (for-each non-blocking! (list sock (car pair) (cdr pair)))
    (set-port-encoding! (cdr pair) "UTF-8")
    (set-client-partial! c '()) (set-client-partial-bytes! c 0)
    (set-client-ready! c '()) (set-client-ready-bytes! c 0)
    (set-client-outbox! c '()) (set-client-outbox-bytes! c 0)
    (set-client-cont! c #f) (set-client-eof! c #f) (set-client-closing! c #f)
    (set-client-vetted! c #f) (set-client-pending! c 0)
    (set-client-evaluating! c #f) (set-client-exit! c #f)
    (set-client-out! c (output-port-for c))
    c))

(define (queue-output! c bv)
  ;; OUTBOX is newest first: a printing loop queues in constant time.
  (set-client-outbox! c (cons bv (client-outbox c)))
  (set-client-outbox-bytes! c (+ (client-outbox-bytes c) (bytevector-length bv))))

(define (output-port-for c)
  ;; Writing never blocks: a client that does not read fills its outbox up
  ;; to the bound, and is then dropped with the rest unsent.
  (define (put-string s)
    (cond ((client-closing c) #t)
          ((> (+ (client-outbox-bytes c) (string-length s)) *max-output-bytes*)
           ;; what is unsent goes, and only the reason is still said
           (set-client-outbox! c '()) (set-client-outbox-bytes! c 0)
           (queue-output! c (string->utf8 (format #f "~%downstroke: more than ~a bytes of output unread; closing the connection~%" *max-output-bytes*)))
           (set-client-closing! c "output unread"))
          (else (queue-output! c (string->utf8 s)))))
  (let ((port (make-soft-port (vector (lambda (ch) (put-string (string ch))) put-string
                                      (lambda () #t) (lambda () #f) (lambda () #t))
                              "w")))
    (set-port-encoding! port "UTF-8")
    ;; Block-buffered: unbuffered, printing a value made one call per
    ;; character, so any value past about 75 KB ran into the time limit.
    ;; flush! forces it out before each send.
    (setvbuf port 'block 4096)
    port))

(define (say! c text)
  ;; A message of the server's own, after whatever the REPL printed.
  (force-output (client-out c))
  (queue-output! c (string->utf8 text)))

(define (drop! c why)
  ;; Output still unsent goes: the reason is what the client gets next.
  (unless (client-closing c)
    (force-output (client-out c))
    (set-client-outbox! c '()) (set-client-outbox-bytes! c 0)
    (say! c (format #f "~%downstroke: ~a; closing the connection~%" why))
    (set-client-closing! c why))
  (set-client-cont! c #f))

(define (close-client! c)
  (for-each (lambda (p) (false-if-exception (close-port p)))
            (list (client-sock c) (client-feed c) (client-in c) (client-out c))))

;;; ---------------------------------------------------------------- input

(define (last-newline bv n)
  (let loop ((i (- n 1)))
    (cond ((< i 0) #f)
          ((= (bytevector-u8-ref bv i) 10) i)
          (else (loop (- i 1))))))

(define (first-newline bv n)
  (let loop ((i 0))
    (cond ((= i n) #f)
          ((= (bytevector-u8-ref bv i) 10) i)
          (else (loop (+ i 1))))))

(define (sub bv start end)
  (let ((out (make-bytevector (- end start))))
    (bytevector-copy! bv start out 0 (- end start))
    out))

(define (stage-chunk! c bv n)
  ;; Whole lines become ready to feed; the unfinished rest waits, bounded.
  (let ((first (first-newline bv n)))
    (if (> (+ (client-partial-bytes c) (or first n)) *max-line-bytes*)
        (begin (set-client-partial! c '()) (set-client-partial-bytes! c 0)
               (drop! c (format #f "input line longer than ~a bytes discarded" *max-line-bytes*)))
        (let ((last (last-newline bv n)))
          (if (not last)
              (begin (set-client-partial! c (cons (sub bv 0 n) (client-partial c)))
                     (set-client-partial-bytes! c (+ (client-partial-bytes c) n)))
              (begin
                (make-ready! c (apply bytevector-append
                                      (reverse (cons (sub bv 0 (+ last 1)) (client-partial c)))))
                (set-client-partial! c (list (sub bv (+ last 1) n)))
                (set-client-partial-bytes! c (- n last 1))))))))

(define (make-ready! c lines)
  ;; LINES (whole lines, or the last text the client sent) may go to the
  ;; REPL: unless the client's first line is an HTTP request, or they are
  ;; not UTF-8 — which Guile's reader on a suspendable port does not
  ;; replace but failed on (a surrogate, past U+10FFFF), ending the REPL.
  ;; Whole lines are whole characters: a newline is never inside one.
  (cond ((and (not (client-vetted? c)) (http-first-line lines))
         => (lambda (line) (refuse-http! c line)))
        ((not (false-if-exception (utf8->string lines)))
         (drop! c "input that is not valid UTF-8 discarded"))
        (else
         (set-client-vetted! c #t)
         (set-client-ready! c (append (client-ready c) (list lines)))
         (set-client-ready-bytes! c (+ (client-ready-bytes c) (bytevector-length lines))))))

;;; A web page can make a browser send an HTTP request to any port on
;;; 127.0.0.1 (an HTML form, or fetch with mode "no-cors"); the request's
;;; body would be evaluated. So, as Guile's own REPL server since 2.0.13
;;; (CVE-2016-8606), a client whose first line looks like HTTP is closed
;;; before anything it sent reaches the REPL. No REPL input is either: a
;;; request line ends in " HTTP/1.1" (whatever its method), a header line
;;; is "Name: value" (a proxy or a browser may put one first).

(define http-request-line (make-regexp " HTTP/[0-9]+\\.[0-9]+$"))
(define http-header-line (make-regexp "^[A-Za-z][A-Za-z0-9]*(-[A-Za-z0-9]+)*:[ \t]*[^ \t]"))

(define (http-first-line bytes)
  ;; The first line of BYTES (up to a CR or LF), non-ASCII shown as ?, if
  ;; it looks like an HTTP request's; else #f.
  (let* ((end (let loop ((i 0))
                (if (or (= i (bytevector-length bytes)) (memv (bytevector-u8-ref bytes i) '(10 13)))
                    i
                    (loop (+ i 1)))))
         (line (string-map (lambda (ch) (if (char<=? #\space ch #\~) ch #\?))
                           (bytevector->string (sub bytes 0 end) "ISO-8859-1"))))
    (and (or (regexp-exec http-request-line line) (regexp-exec http-header-line line))
         line)))

;; What of a refused first line the console shows: enough to recognise it.
(define *shown-line-chars* 100)

(define (refuse-http! c line)
  (format *console* "downstroke: refused a REPL client whose first line looks like HTTP (a web page reaching the REPL?); nothing it sent was evaluated: ~s~%"
          (if (> (string-length line) *shown-line-chars*)
              (string-append (substring line 0 *shown-line-chars*) "...")
              line))
  (force-output *console*)
  (drop! c "the first line looks like an HTTP request, not Scheme; nothing was evaluated"))

(define (bytevector-append . bvs)
  (let ((out (make-bytevector (apply + (map bytevector-length bvs)))))
    (let loop ((bvs bvs) (at 0))
      (unless (null? bvs)
        (bytevector-copy! (car bvs) 0 out at (bytevector-length (car bvs)))
        (loop (cdr bvs) (+ at (bytevector-length (car bvs))))))
    out))

(define (receive! c)
  ;; What the socket has; end of input once the client has shut its side.
  (let* ((bv (make-bytevector *recv-chunk-bytes*))
         (n (catch 'system-error (lambda () (recv! (client-sock c) bv)) (lambda _ 0))))
    (if (zero? n)
        (set-client-eof! c #t)
        (stage-chunk! c bv n))))

(define (send-some port bv)
  ;; How many bytes of BV the kernel took now (0 when it would block); #f
  ;; when the other side is gone.
  (catch 'system-error
    (lambda () (send port bv))
    (lambda args
      (let ((errno (system-error-errno args)))
        (and (or (= errno EAGAIN) (= errno EWOULDBLOCK) (= errno EINTR)) 0)))))

(define (feed! c)
  ;; Ready lines into the REPL's end, as far as the pair takes them now.
  ;; #t when something new reached the REPL.
  (let loop ((fed? #f))
    (if (null? (client-ready c))
        (begin
          (when (and (client-eof? c) (pair? (client-partial c)))
            ;; the last line had no newline: it is whole now
            (let ((last (apply bytevector-append (reverse (client-partial c)))))
              (set-client-partial! c '()) (set-client-partial-bytes! c 0)
              (make-ready! c last)))
          (if (or (null? (client-ready c)) (client-closing c)) fed? (loop fed?)))
        (let* ((bv (car (client-ready c)))
               (sent (or (send-some (client-feed c) bv) 0)))
          (set-client-ready-bytes! c (- (client-ready-bytes c) sent))
          (set-client-pending! c (+ (client-pending c) sent))
          (cond ((= sent (bytevector-length bv))
                 (set-client-ready! c (cdr (client-ready c)))
                 (loop #t))
                (else
                 (when (> sent 0)
                   (set-client-ready! c (cons (sub bv sent (bytevector-length bv)) (cdr (client-ready c)))))
                 (or fed? (> sent 0))))))))

(define (end-input! c)
  ;; Everything the client sent has been fed: the REPL reads end-of-file.
  (false-if-exception (shutdown (client-feed c) 1)))

;;; ---------------------------------------------------------------- output

(define (flush! c)
  ;; Send what the client's socket takes now: how many bytes went, or #f
  ;; once the client is gone.
  (force-output (client-out c))
  (let loop ((bvs (reverse (client-outbox c))) (total 0))
    (define (keep! rest)
      (set-client-outbox! c (reverse rest))
      (set-client-outbox-bytes! c (- (client-outbox-bytes c) total))
      total)
    (if (null? bvs)
        (keep! '())
        (let* ((bv (car bvs))
               (sent (send-some (client-sock c) bv)))
          (cond ((not sent) #f)
                ((= sent (bytevector-length bv)) (loop (cdr bvs) (+ total sent)))
                (else
                 (set! total (+ total sent))
                 (keep! (cons (sub bv sent (bytevector-length bv)) (cdr bvs)))))))))

;;; ---------------------------------------------------------------- the REPL
;;; A client's REPL runs in slices: from a resume until it waits for input
;;; again (or ends). Only during a slice are the ports suspendable and the
;;; time limit armed.

(define repl-tag (make-prompt-tag "downstroke-repl"))

(define *active* #f)                 ; the client whose slice runs, or #f
(define *timeout* default-repl-timeout)
(define *strikes* 0)                 ; timer expiries in this slice's evaluation
(define *watched* #f)                ; the game hook running under the limit, or #f

;; An evaluation's Scheme stack, in bytes: as a game's hooks have by default
;; (make-game stack-limit:), so a recursion that never ends fails in about a
;; second instead of growing Guile's stack to gigabytes.
(define repl-stack-limit (* 64 1024 1024))

(define (seconds->timer s)
  (let ((us (inexact->exact (round (* s 1000000)))))
    (values (quotient us 1000000) (remainder us 1000000))))

(define (arm-timer!)
  ;; Expires after the limit, then every limit again: the first expiry
  ;; interrupts the evaluation with an error, a second one (the error was
  ;; caught and the loop went on) drops the client.
  (set! *strikes* 0)
  (call-with-values (lambda () (seconds->timer *timeout*))
    (lambda (s us) (setitimer ITIMER_REAL s us s us))))

(define (disarm-timer!) (setitimer ITIMER_REAL 0 0 0 0))

(define (on-alarm signal)
  (cond (*active*
         (set! *strikes* (+ *strikes* 1))
         (if (= *strikes* 1)
             (scm-error 'misc-error "repl"
                        "evaluation ran past the ~a s limit (--repl-timeout): interrupted"
                        (list *timeout*) #f)
             (abort-to-prompt repl-tag 'runaway)))
        (*watched*
         (set! *strikes* (+ *strikes* 1))
         (if (= *strikes* 1)
             (scm-error 'misc-error *watched*
                        "the hook ran past the ~a s limit (--repl-timeout): interrupted"
                        (list *timeout*) #f)
             (abort-to-prompt hook-tag)))))

(define (on-read)
  ;; Each new prompt starts a new evaluation's time, and a new expression's
  ;; text.
  (when *active*
    (set-client-pending! *active* 0)
    (set-client-evaluating! *active* #f)
    (load-geiser-when-found!)
    (arm-timer!)))

(define (on-eval expression)
  ;; What ends the REPL from here on is the expression's (exit), not ,q.
  (when *active* (set-client-evaluating! *active* #t)))

;;; ---------------------------------------------------------------- game hooks
;;; The limit covers the game's hooks too while it is served: an endless
;;; update hook set from the REPL (game-update-set!) froze the game and,
;;; with it, the REPL that could have replaced it. The engine calls each
;;; hook through call-with-hook-time-limit (its hook-time-limit parameter,
;;; set by the host); the interrupt is an error in that hook, reported and
;;; pausing the game as any other.

(define hook-tag (make-prompt-tag "downstroke-hook"))

(define (call-with-hook-time-limit what thunk)
  "(THUNK) — the game hook WHAT (\"update:\" …) — interrupted by an error
once it has run the REPL's time limit, and cut off (an error too) one more
limit later if it caught that error and ran on."
  (if (or *active* *watched*)
      (thunk)                           ; already under the limit
      (dynamic-wind
        (lambda () (set! *watched* what) (arm-timer!))
        (lambda ()
          (call-with-prompt hook-tag thunk
            (lambda (k)
              (scm-error 'misc-error what
                         "the hook still ran ~a s after its interrupt (--repl-timeout): cut off"
                         (list *timeout*) #f))))
        (lambda () (disarm-timer!) (set! *watched* #f)))))

;;; ---------------------------------------------------------------- Geiser
;;; Geiser (geiser-guile) puts its Scheme directory on the load path, then
;;; sends `,use (geiser emacs)' for its meta-commands (,geiser-eval …). The
;;; host reads postfix keywords, under which Geiser's source (`'ge:') does
;;; not compile, and every reply was "Unknown meta command". So the server
;;; loads (geiser emacs) itself, with the standard keyword syntax, at the
;;; first prompt after the load path finds it: the client's `,use' then
;;; finds the module loaded, and Geiser's own code serves it.

(define geiser-witness "geiser/emacs.scm")   ; what Geiser's elisp looks for too
(define *searched-load-path* #f)             ; %load-path when last searched
(define *geiser-served?* #f)                 ; (geiser emacs) loaded and served

(define (load-geiser-when-found!)
  ;; One test per prompt: the load path is searched only when it changed.
  (unless (or *geiser-served?* (eq? %load-path *searched-load-path*))
    (set! *searched-load-path* %load-path)
    (when (%search-load-path geiser-witness)
      (load-geiser!))))

(define (load-geiser!)
  ;; Compiling it the first time may take longer than an evaluation's limit;
  ;; its compiler's notes go to the game's console, not into the session.
  (disarm-timer!)
  (catch #t
    (lambda ()
      (parameterize ((current-error-port *console*) (current-warning-port *console*))
        (with-standard-keywords (lambda () (resolve-interface '(geiser emacs)))))
      (when (geiser-0.10-eval?) (serve-geiser-eval!))
      (set! *geiser-served?* #t))
    (lambda (key . args)
      (format (current-error-port) "downstroke: Geiser's (geiser emacs) did not load: ~a ~s~%" key args))))

(define (geiser-0.10-eval?)
  ;; Only the definition below is replaced: another Geiser's ,geiser-eval
  ;; (its usage line differs) is left as it is.
  (let ((info (hashq-ref (@@ (system repl command) *command-infos*) 'geiser-eval)))
    (and info
         (equal? (procedure-documentation (car info))
                 "geiser-eval module form args ()
Meta-command used by Geiser to evaluate and compile code."))))

(define (serve-geiser-eval!)
  ;; Geiser 0.10's ,geiser-eval, as Geiser defines it but for two things:
  ;; Guile 3.0.8 reads a meta-command's expressions as syntax objects, and
  ;; Geiser tests them as data ((null? args) was never true, so every
  ;; evaluation failed); and an error is reported, as at the served prompt,
  ;; instead of entering the debugger, which could not wait for input here.
  (let* ((command-infos (@@ (system repl command) *command-infos*))
         (geiser (hashq-ref command-infos 'geiser-eval))
         (geiser-emacs (resolve-module '(geiser emacs)))
         (evaluation (resolve-interface '(geiser evaluation)))
         (compile (module-ref evaluation 'ge:compile))
         (evaluate (module-ref evaluation 'ge:eval)))
    (define (served-geiser-eval repl . expressions)
      (apply (lambda (mod form args . rest)
               (if (null? args)
                   (let ((port (current-output-port)))
                     (call-with-error-handling
                      (lambda () (compile form mod))
                      #:on-error (lambda (key . args)
                                   (write-error-retort port key args (make-stack #t)))))
                   (evaluate `(,(eval form geiser-emacs) ,@args) mod)))
             (map (lambda (x) (if (syntax? x) (syntax->datum x) x)) expressions)))
    (set-procedure-property! served-geiser-eval 'documentation
                             (procedure-documentation (car geiser)))
    (hashq-set! command-infos 'geiser-eval (cons served-geiser-eval (cdr geiser)))))

(define (write-error-retort port key args stack)
  ;; Geiser's retort for an error: its key, and as output the backtrace
  ;; and message the served prompt prints (what Geiser shows the user).
  (let* ((tag (and (pair? (fluid-ref %stacks)) (cdr (fluid-ref %stacks))))
         (text (call-with-output-string
                (lambda (p)
                  (print-frames (narrow-stack->vector stack 1 tag 0 (and tag 1)) p)
                  (print-error p key args)))))
    (write `((error (key . ,key)) (output . ,text)) port)
    (newline port)))

(define (with-standard-keywords thunk)
  (let ((style (cadr (memq 'keywords (read-options)))))
    (dynamic-wind
      (lambda () (read-set! keywords #f))
      thunk
      (lambda () (read-set! keywords style)))))

(define *console* (current-error-port))      ; the game's own error port

(define (client-repl c module)
  (lambda ()
    (parameterize ((current-input-port (client-in c))
                   (current-output-port (client-out c))
                   (current-error-port (client-out c))
                   (current-warning-port (client-out c))
                   (current-read-waiter (lambda (port) (abort-to-prompt repl-tag 'read))))
      (with-fluids ((*repl-stack* '()))
        (save-module-excursion
         (lambda ()
           (set-current-module module)
           (let ((status (run-repl (served-repl))))
             ;; #t: it ended (,q or end of input); (exit ARGS …): by (exit)
             (if (client-evaluating? c) (cons 'exit status) #t))))))))

(define (served-repl)
  ;; Guile's REPL, but an error reports its backtrace and returns to the
  ;; prompt instead of entering the debugger: errors raised in C (most of
  ;; them) leave C frames under the debugger's prompt, and a REPL waiting
  ;; there for input could never be suspended and resumed.
  (let ((repl (make-repl (current-language))))
    ;; call-with-error-handling takes a procedure, but the option's checker
    ;; knows only the symbols: set it past the checker.
    (set-car! (cdr (assq 'on-error (repl-options repl))) report-error)
    repl))

(define (report-error key . args)
  ;; As Guile's 'backtrace: the failed evaluation's frames, then the error.
  ;; A timeout's frames are the signal's, and Guile cannot print them. A
  ;; stack overflow Guile's REPL reports itself (its report-keys), without
  ;; the frames (a million of the same recursion); and it hands the error
  ;; here more than once as it unwinds: left to Guile.
  (unless (eq? key 'stack-overflow)
    (let ((port (current-error-port)))
      (when (zero? *strikes*)
        (let ((tag (and (pair? (fluid-ref %stacks)) (cdr (fluid-ref %stacks)))))
          (print-frames (narrow-stack->vector (make-stack #t) 3 tag 0 (and tag 1)) port)))
      (print-error port key args))))

(define (call-with-bounded-stack thunk)
  ;; (THUNK) with at most repl-stack-limit of stack; past it a
  ;; stack-overflow error, which the REPL reports as any other.
  (call-with-stack-overflow-handler
   (quotient repl-stack-limit 8)  ; in words of 8 bytes
   thunk
   (lambda ()
     (scm-error 'stack-overflow "repl"
                "the evaluation used up its ~a MiB of Scheme stack: a recursion that never ends?"
                (list (quotient repl-stack-limit (* 1024 1024))) #f))))

(define (run-slice! c thunk)
  ;; Runs THUNK (a REPL start or resume) until it suspends or ends.
  (dynamic-wind
    (lambda () (set! *active* c) (install-suspendable-ports!) (arm-timer!))
    (lambda ()
      ;; The barrier would catch an error itself, print it on the console
      ;; and return #f: the error is caught inside it, and said to the client.
      (let ((ended (with-continuation-barrier
                    (lambda ()
                      (catch #t
                        (lambda ()
                          (call-with-bounded-stack
                           (lambda ()
                             (call-with-prompt repl-tag thunk
                               (lambda (k why)
                                 (if (eq? why 'read)
                                     (set-client-cont! c k)
                                     (drop! c (format #f "evaluation still running ~a s after its interrupt" *timeout*)))
                                 #f)))))
                        (lambda (key . args)
                          (drop! c (format #f "REPL failed: ~a ~s" key args))
                          #f))))))
        (cond ((client-cont c))                 ; waiting for input
              ((client-closing c))              ; dropped
              ((pair? ended)                    ; (exit): the poll ends the game
               (set-client-exit! c (cdr ended))
               (drop! c "(exit) ends the game (,q leaves only this REPL)"))
              (ended (set-client-closing! c "ended"))
              ;; Whatever else ended it, a client no REPL serves is closed.
              (else (drop! c "REPL ended")))))
    (lambda () (disarm-timer!) (uninstall-suspendable-ports!) (set! *active* #f))))

(define (resume! c)
  (let ((k (client-cont c)))
    (set-client-cont! c #f)
    (run-slice! c (lambda () (k)))))

;;; ---------------------------------------------------------------- the server

(define-record-type <repl-server>
  (%make-repl-server socket module clients)
  repl-server?
  (socket server-socket)
  (module server-module)
  (clients server-clients set-server-clients!))

(define* (make-repl-server socket #:key (module (resolve-module '(guile-user)))
                           (timeout default-repl-timeout))
  "Serve a REPL on SOCKET (bound, not yet listening) into MODULE; each
evaluation may hold the game TIMEOUT seconds. Call repl-server-poll! once
per frame."
  (set! *timeout* timeout)
  (set! *console* (current-error-port))
  (non-blocking! socket)
  (listen socket *listen-backlog*)
  ;; A client that hangs up must cost an error return, not the process.
  (sigaction SIGPIPE SIG_IGN)
  (sigaction SIGALRM on-alarm)
  (add-hook! before-read-hook on-read)
  (add-hook! before-eval-hook on-eval)
  (%make-repl-server socket module '()))

(define (accept-all! server)
  (let loop ()
    (let ((conn (catch 'system-error (lambda () (accept (server-socket server))) (lambda _ #f))))
      (when conn
        (let ((c (make-client (car conn))))
          (if (>= (length (server-clients server)) *max-clients*)
              (begin (drop! c (format #f "already ~a clients" *max-clients*))
                     (flush! c) (close-client! c))
              (begin
                (set-server-clients! server (append (server-clients server) (list c)))
                (run-slice! c (client-repl c (server-module server))))))
        (loop)))))

(define (readable-sockets clients)
  ;; Clients with room in their staging whose sockets have input (or EOF).
  (let ((wanted (filter (lambda (c) (and (not (client-eof? c)) (not (client-closing c))
                                         (< (client-ready-bytes c) *max-line-bytes*)))
                        clients)))
    (if (null? wanted)
        '()
        (car (select (map client-sock wanted) '() '() 0)))))

(define (serve-client! c readable)
  (when (memq (client-sock c) readable) (receive! c))
  (unless (client-closing c) (serve-input! c))
  (when (client-exit c)
    ;; As (exit) in a hook or the script does: what the client was told
    ;; goes first, as far as its socket takes it now.
    (flush! c)
    (apply throw 'quit (client-exit c))))

(define (serve-input! c)
  (when (and (feed! c) (client-cont c)) (resume! c))
  (when (and (client-eof? c) (null? (client-ready c)) (client-cont c))
    (end-input! c)
    (resume! c))
  (when (and (> (client-pending c) *max-pending-bytes*) (not (client-closing c)))
    (drop! c (format #f "unfinished expression longer than ~a bytes discarded" *max-pending-bytes*))))

(define (still-open? c)
  ;; #f once the client is closed: it is gone, or its REPL ended or it was
  ;; dropped and its last output went out (or stopped going out).
  (let ((sent (flush! c)))
    (if (or (not sent)
            (and (client-closing c) (or (null? (client-outbox c)) (zero? sent))))
        (begin (close-client! c) #f)
        #t)))

(define *polling* #f)

(define (repl-server-poll! server)
  "Accept new clients, read what clients sent, evaluate it, send the
replies — without ever waiting. Call it from the game's thread."
  ;; A client running a game loop of its own (game-run! on a new game)
  ;; polls again from inside its evaluation: that inner poll does nothing.
  (unless *polling*
    (dynamic-wind
      (lambda () (set! *polling* #t))
      (lambda ()
        (accept-all! server)
        (let* ((clients (server-clients server))
               (readable (readable-sockets clients)))
          (for-each (lambda (c) (serve-client! c readable)) clients)
          (set-server-clients! server (filter still-open? clients))))
      (lambda () (set! *polling* #f)))))

(define (repl-server-broadcast! server text)
  "Show TEXT to every connected client (a game's error, say)."
  (for-each (lambda (c) (say! c text)) (server-clients server)))
