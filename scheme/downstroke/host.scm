;; SPDX-License-Identifier: MIT
;;; (downstroke host) — what the `downstroke' executable runs.
(define-module (downstroke host)
  #:declarative? #f
  #:use-module (downstroke engine)
  #:use-module (downstroke error-text)
  #:use-module (downstroke render)
  #:use-module (ice-9 format)
  #:use-module ((rnrs bytevectors) #:select (string->utf8 utf8->string bytevector->u8-list u8-list->bytevector))
  #:use-module ((srfi srfi-1) #:select (any find))
  #:export (main script-interfaces use-script-environment! load-script))

;;; What a script run by `downstroke' (and its REPL) sees without importing
;;; anything: the engine, and the list and multiple-value tools Scheme game
;;; code reaches for (find, any, filter-map, fold, let-values …), so an
;;; example copied from the docs runs as it is. The docs test evaluates
;;; every example in exactly this environment (tests/scheme/docs-test.scm).
(define script-interfaces '((downstroke) (srfi srfi-1) (srfi srfi-11) (srfi srfi-34)))

(define (use-script-environment! module)
  "Make MODULE see what a script sees (script-interfaces)."
  (for-each (lambda (name) (module-use! module (resolve-interface name))) script-interfaces)
  module)

;;; Guile's REPL, (downstroke repl-server) and (system vm frame) are named
;;; with @, which loads a module when the code naming it first runs: only
;;; when a REPL is asked for or an error reported. Loaded with every game,
;;; they and the VM's debugging modules they bring would be live data that
;;; each of its collections marks (docs/engine.org).

;;; ---------------------------------------------------------------- script errors
;;; An uncaught error reads as the user's: the message first, then the
;;; frames of the user's own files; the engine's and Guile's frames only when
;;; asked for (DOWNSTROKE_BACKTRACE=full).

(define (full-backtrace?)
  (equal? (getenv "DOWNSTROKE_BACKTRACE") "full"))

(define (frame-file-line frame)
  ;; (file . line) of FRAME's source, 1-based line, or #f when it has none.
  (let ((source (frame-source frame)))
    (and source (cadr source) (cons (cadr source) (+ 1 (caddr source))))))

(define (user-file? file dir)
  (string-prefix? dir file))

(define max-reported-frames 20)  ; a runaway recursion has a million, all alike

(define (stack-user-frames stack dir)
  ;; (file line call) of STACK's frames in files under DIR, innermost first,
  ;; at most max-reported-frames of them and then #t if more were left
  ;; out. Walked frame to frame (stack-ref from the top each time would be
  ;; quadratic in a deep stack).
  (let loop ((frame (and (> (stack-length stack) 0) (stack-ref stack 0))) (n 0) (acc '()))
    (cond ((not frame) (reverse acc))
          ((= n max-reported-frames) (reverse (cons #t acc)))
          (else
           (let ((where (frame-file-line frame)))
             (if (and where (user-file? (car where) dir))
                 (loop (frame-previous frame) (+ n 1)
                       (cons (list (car where) (cdr where)
                                   ((@ (system vm frame) frame-call-representation) frame))
                             acc))
                 (loop (frame-previous frame) n acc)))))))

(define (report-error key args script)
  (let ((port (current-error-port))
        (stack (make-stack #t 3)))
    (force-output (current-output-port))  ; the script's output came first
    (print-error port key args)
    (if (full-backtrace?)
        (display-backtrace stack port)
        (begin
          (for-each (lambda (f)
                      (if (eq? f #t)
                          (format port "  ... (more frames left out)~%")
                          (format port "  at ~a:~a~a~%" (car f) (cadr f)
                                  (call-text (caddr f)))))
                    (stack-user-frames stack (string-append (dirname script) "/")))
          (display "(the whole backtrace: DOWNSTROKE_BACKTRACE=full)\n" port)))))

(define (call-text call)
  ;; ": (proc arg …)" on one short line (an entity list can print as pages);
  ;; "" for a script's top level, which has no name worth showing.
  (if (eq? (car call) '_)
      ""
      (let ((text (call-with-output-string (lambda (p) (write call p)))))
        (string-append ": " (if (> (string-length text) 72)
                                (string-append (substring text 0 69) "...")
                                text)))))

;;; ---------------------------------------------------------------- compiling quietly
;;; Guile announces every compilation of an edited file (";;; compiling …")
;;; on the warning port; its warnings about the code itself stay useful.

(define guile-compile-notes
  '(";;; note: source file " ";;;       newer than compiled " ";;; compiling " ";;; compiled "
    ";;; note: auto-compilation is enabled" ";;;       or pass the --no-auto-compile"))

(define (compile-note? line)
  (any (lambda (prefix) (string-prefix? prefix line)) guile-compile-notes))

(define (compile-failure? line)
  ;; The first line of a block Guile writes before it loads the file anyway.
  (or (string-prefix? ";;; WARNING: compilation of " line)
      (string-prefix? ";;; Stat of " line)))

(define (unbound-warning-name line)
  ;; The name in Guile's "possibly unbound variable `NAME'" warning, or #f.
  (let* ((lead "possibly unbound variable `")
         (at (string-contains line lead)))
    (and at (string-suffix? "'\n" line)
         (substring line (+ at (string-length lead)) (- (string-length line) 2)))))

(define (filtering-warning-port out loaded)
  ;; A port passing each whole line to OUT unless it is a compile note, the
  ;; report of a failed compilation (the file then runs interpreted, which
  ;; raises the same error, reported as any other), or a name said to be
  ;; unbound that a file the script loads defines (LOADED, a promise of a
  ;; list of symbols, read at the first such warning): the compiler cannot
  ;; see the load, which defines it.
  (let ((pending "") (in-failure? #f))
    (define (defined-by-load? line)
      (let ((name (unbound-warning-name line)))
        (and name (memq (string->symbol name) (force loaded)))))
    (define (put-line! line)
      (cond ((or (compile-note? line) (compile-failure? line))
             (set! in-failure? (compile-failure? line)))
            ((and in-failure? (string-prefix? ";;; " line)))
            ((defined-by-load? line) (set! in-failure? #f))
            (else (set! in-failure? #f) (display line out))))
    (define (put-string! text)
      (let loop ((text (string-append pending text)))
        (let ((nl (string-index text #\newline)))
          (if nl
              (begin (put-line! (substring text 0 (+ nl 1)))
                     (loop (substring text (+ nl 1))))
              (set! pending text)))))
    (make-soft-port
     (vector (lambda (c) (put-string! (string c)))
             put-string!
             (lambda () (force-output out))
             #f
             (lambda () (unless (string-null? pending) (put-string! "\n"))))
     "w")))

;;; Guile 3.0.8's compiler gives a warning's place as a vector #(file line
;;; column), and its printer (location-string) reads only the alist form:
;;; every "possibly unbound variable" read "<unknown-location>". The host
;;; hands the printer the alist, once, when it first compiles.
(define warning-locations-mended? #f)

(define (mend-warning-locations!)
  (unless warning-locations-mended?
    (set! warning-locations-mended? #t)
    (let* ((message (resolve-module '(system base message)))
           (warning (module-ref message 'warning)))
      (module-set! message 'warning
                   (lambda (type location . args)
                     (apply warning type
                            (if (and (vector? location) (= (vector-length location) 3))
                                `((filename . ,(vector-ref location 0))
                                  (line . ,(vector-ref location 1))
                                  (column . ,(vector-ref location 2)))
                                location)
                            args))))))

;;; Guile's expander refuses a dotted pair in code, `(list #:aim (1 . 0))',
;;; as "source expression failed to match any pattern", with no place: it
;;; reads the pair without its source. The host finds the pair in the
;;; script, or a file it loaded, and raises the error again with the place
;;; and a message that says what is wrong.
(define (improper-list? x)
  (and (pair? x) (not (list? x))))

(define (call-placing-syntax-errors file thunk)
  (let ((loaded '()) (previous %load-hook))
    (define (note-load! f)
      (set! loaded (cons f loaded))
      (when previous (previous f)))
    (with-throw-handler 'syntax-error
      (lambda ()
        (dynamic-wind (lambda () (set! %load-hook note-load!))
                      thunk
                      (lambda () (set! %load-hook previous))))
      (lambda (key who message where form . rest)
        ;; Loads newest first: one that ran to its end holds no such code.
        (let ((at (and (not where)
                       ((@ (downstroke script-source) form-location) form (append loaded (list file))))))
          (when at
            (apply throw key who
                   (if (improper-list? form)
                       (format #f "a dotted pair is not code (quote it to make it data: '~s)" form)
                       message)
                   at form rest)))))))

(define (load-script file compile?)
  ;; COMPILE?: auto-compiled into the cache, quietly; else interpreted.
  (call-placing-syntax-errors file (lambda () (load-script-as file compile?))))

(define (load-script-as file compile?)
  (if compile?
      (let ((warnings (filtering-warning-port
                       (current-error-port)
                       (delay ((@ (downstroke script-source) loaded-definitions) file)))))
        (mend-warning-locations!)
        ((@ (downstroke compiled-by-content) forget-stale-compiled!) file)
        (parameterize ((current-warning-port warnings))
          (load file))
        (close-port warnings))
      (primitive-load file)))

;;; ---------------------------------------------------------------- --timeout
;;; A watchdog thread, not SIGALRM and setitimer: those are the REPL
;;; server's, for its time limit on each evaluation (repl-server.scm).

;; The exit status of a script ended by --timeout: timeout(1)'s, so that a
;; CI job tells a run cut off by time from one that failed (1) or was
;; refused (2).
(define timeout-status 124)

;; A script that catches the ending (a catch-all handler) and runs on is
;; cut off this long after it, without running its cleanups: time enough
;; for the ones an ending runs (a window closed, a --record file written).
(define timeout-grace-seconds 5)

(define (sleep-seconds s)
  (let ((deadline (+ (get-internal-real-time) (* s internal-time-units-per-second))))
    (let loop ()
      (let ((left (- deadline (get-internal-real-time))))
        (when (> left 0)
          (usleep (min 1000000 (round (/ (* (inexact->exact left) 1000000) internal-time-units-per-second))))
          (loop))))))

(define (call-with-timeout seconds file thunk)
  ;; (THUNK), ended after SECONDS as (exit timeout-status) is, said on the
  ;; error port; SECONDS #f: no limit.
  (if (not seconds)
      (thunk)
      ;; (ice-9 threads) named with @: loaded only when a limit is asked for.
      (let ((main ((@ (ice-9 threads) current-thread))) (done? #f))
        ((@ (ice-9 threads) call-with-new-thread)
         (lambda ()
           (sleep-seconds seconds)
           (unless done?
             (format (current-error-port) "downstroke: ~a ran past --timeout ~a s: ended (status ~a)~%"
                     file seconds timeout-status)
             (force-output (current-error-port))
             (system-async-mark (lambda () (unless done? (throw 'quit timeout-status))) main)
             (sleep-seconds timeout-grace-seconds)
             (unless done?
               (force-output (current-output-port))  ; what the script printed is kept
               (primitive-_exit timeout-status)))))
        (dynamic-wind (lambda () #t) thunk (lambda () (set! done? #t))))))

(define (run-script file args compile?)
  (set-program-arguments (cons file args))
  ;; A missing file is left to load, inside the catch, to refuse.
  (let ((path (or (false-if-exception (canonicalize-path file)) file)))
    (catch #t
      (lambda ()
        (save-module-excursion
         (lambda ()
           (set-current-module (use-script-environment! (resolve-module '(guile-user))))
           ;; Before the load, inside which the game runs and may reload it.
           ((@ (downstroke script-reload) script-loaded!) path (current-module) compile?)
           (load-script path compile?)))
        0)
      (lambda (key . args)
        ;; (exit n) inside the script is a quit, not an error.
        (if (eq? key 'quit) (quit-status args) 1))
      (lambda (key . args)
        (unless (eq? key 'quit) (report-error key args path))))))

(define (test-environment)
  ;; A test file's module: a script's environment, with SRFI-64. Not
  ;; declarative, as guile-user is not: a test `load's its game.
  (let ((m (use-script-environment! (make-fresh-user-module))))
    (set-module-declarative?! m #f)
    (module-use! m (resolve-interface '(srfi srfi-64)))
    m))

(define (load-test-file path)
  ;; As a script is: a test `load's its game, whose names are then not
  ;; warned of as unbound (filtering-warning-port).
  (load-script path #t))

(define (path->hex path)
  ;; A path as its UTF-8 bytes in hex: the child decodes its command line
  ;; before it can set its locale, and would read any other byte as "?".
  (string-concatenate
   (map (lambda (b) (string-pad (number->string b 16) 2 #\0)) (bytevector->u8-list (string->utf8 path)))))

(define (hex->path hex)
  (utf8->string
   (u8-list->bytevector
    (map (lambda (i) (string->number (substring hex i (+ i 2)) 16)) (iota (quotient (string-length hex) 2) 0 2)))))

(define (test-child-command file results)
  ;; The command that runs one test file in a child process: this same
  ;; executable, in the runner's folder, with the runner's ports.
  (list (readlink "/proc/self/exe") "test" "--run-one" (path->hex results) (path->hex file)))

(define (run-test-command args)
  ;; downstroke test [--junit FILE] [--timeout S] [PATH…]: every *-test.scm
  ;; under the paths (default tests/), each in a child process. The child's
  ;; own form, test --run-one RESULTS FILE, is internal.
  (if (and (= (length args) 3) (string=? (car args) "--run-one"))
      ((@ (downstroke testing) run-test-file) (hex->path (caddr args)) test-environment load-test-file
       (hex->path (cadr args)))
      (let loop ((args args) (junit #f) (timeout #f) (paths '()))
        (cond ((null? args)
               ;; A --junit FILE that may not be written is refused before any
               ;; test runs (run-tests says why).
               (catch 'misc-error
                 (lambda ()
                   ((@ (downstroke testing) run-tests) (if (null? paths) '("tests") (reverse paths)) test-child-command
                    #:junit junit
                    #:timeout (and timeout (string->number timeout))))
                 (lambda (key who fmt fargs . _)
                   (format (current-error-port) "~a: ~a~%" who (apply format #f fmt fargs))
                   2)))
              ((string=? (car args) "--junit")
               (if (pair? (cdr args))
                   (loop (cddr args) (cadr args) timeout paths)
                   (begin (display "downstroke test: --junit needs a file\n" (current-error-port)) 2)))
              ((string=? (car args) "--timeout")
               (if (and (pair? (cdr args)) (seconds-text? (cadr args)))
                   (loop (cddr args) junit (cadr args) paths)
                   (begin (unless (pair? (cdr args))
                            (display "downstroke test: --timeout needs a number of seconds\n" (current-error-port)))
                          2)))
              (else (loop (cdr args) junit timeout (cons (car args) paths)))))))

(define (run-new-command args templates)
  ;; downstroke new DIR: a starter game in DIR (see (downstroke starter)).
  (if (not (and (pair? args) (null? (cdr args)) (not (string-null? (car args)))
                (not (string-prefix? "-" (car args)))))
      (begin (display "usage: downstroke new DIR\n" (current-error-port)) 2)
      (let ((dir (car args)))
        (catch 'misc-error
          (lambda ()
            (let ((files ((@ (downstroke starter) write-starter) dir templates)))
              (format #t "Made ~a: ~a files, a game that plays at once.~%" dir (length files))
              (format #t "  cd ~a~%  downstroke --window game.scm   play it~%  downstroke game.scm            run it headless~%  downstroke test                test it~%" dir)
              0))
          (lambda (key who fmt fargs . _)
            (format (current-error-port) "~a: ~a~%" who (apply format #f fmt fargs))
            1)))))

(define (quit-status args)
  (cond ((null? args) 0)
        ((eq? (car args) #t) 0)
        ((eq? (car args) #f) 1)
        ((integer? (car args)) (car args))
        (else 1)))

(define (run-repl)
  (set-current-module (use-script-environment! (resolve-module '(guile-user))))
  (false-if-exception
   (begin ((module-ref (resolve-interface '(ice-9 readline)) 'activate-readline)) #t))
  ((@ (system repl repl) start-repl))
  0)

;;; ---------------------------------------------------------------- live REPL
;;; (downstroke repl-server), polled by a frame hook at the start of every
;;; frame: expressions run on the game's own thread, between two frames.

(define (serve-repl! socket timeout)
  (let ((server ((@ (downstroke repl-server) make-repl-server) socket #:timeout timeout)))
    (add-frame-hook! (let ((poll (lambda () ((@ (downstroke repl-server) repl-server-poll!) server))))
                       ;; Each evaluation has its own stack bound (repl-server.scm);
                       ;; a frame hook's around them would be reached first.
                       (set-procedure-property! poll 'own-stack-limit #t)
                       poll))
    ;; A hook's error pauses the game instead of ending the session.
    (hook-error-reporter
     (lambda (text)
       (display text (current-error-port))
       (force-output (current-error-port))
       ((@ (downstroke repl-server) repl-server-broadcast!) server text)))
    ;; … and so does a hook that never ends: the REPL's time limit covers
    ;; the hooks as it covers evaluations.
    (hook-time-limit (@ (downstroke repl-server) call-with-hook-time-limit))
    (frame-pacing #t)
    ;; Its author ends it from the REPL: running on is what was asked for.
    ((@ (downstroke headless) game-served?) #t)
    (remove-socket-on-signals! socket)))

;; The signals that end a served game from outside (Ctrl-C in its terminal,
;; kill, a closed terminal): each still ends it as before, by that signal,
;; but only once the socket file is gone.
(define ending-signals (list SIGINT SIGTERM SIGHUP))

(define (remove-socket-on-signals! socket)
  (for-each (lambda (sig)
              (sigaction sig
                (lambda (sig)
                  ((@ (downstroke repl-server) remove-unix-repl-socket!) socket)
                  (sigaction sig SIG_DFL)
                  (kill (getpid) sig))))
            ending-signals))

(define (open-repl-socket opts)
  ;; The listening socket the options ask for, #f for none, or 'refused
  ;; (said on the error port).
  (let ((path (assq-ref opts 'repl-server))
        (port (assq-ref opts 'repl-port)))
    (catch #t
      (lambda ()
        (cond (path ((@ (downstroke repl-server) open-unix-repl-socket) path))
              (port ((@ (downstroke repl-server) open-tcp-repl-socket) (string->number port)))
              (else #f)))
      (lambda (key . args)
        (if (eq? key 'system-error)
            (format (current-error-port) "downstroke: cannot serve the REPL on ~a: ~a~%"
                    (or path (string-append "127.0.0.1:" port))
                    (strerror (system-error-errno (cons key args))))
            (format (current-error-port) "downstroke: ~a~%"
                    (apply format #f (cadr args) (caddr args))))
        'refused))))

(define (repl-timeout opts)
  (let ((v (assq-ref opts 'repl-timeout)))
    (if v (string->number v) (@ (downstroke repl-server) default-repl-timeout))))

(define (usage-text)
  (string-append "usage: downstroke [OPTION...] [FILE.scm ARGS...]
Runs FILE.scm with (downstroke) imported, or a REPL when no file is given.

  --window            show the game in a window: real time, keyboard, mouse
                      and controllers, sound and music (closing it quits; F1:
                      debug overlay; F11 or Alt+Return: fullscreen)
  --scale N           the window's whole scale factor (default: fit the screen);
                      the window can be resized, the picture stays whole-scaled
  --fullscreen        open the window fullscreen
  --record FILE       with --window: write its input to FILE as an input
                      script a test can replay, every 5 s and as it ends
  --frame-log FILE    with --window: write each presented frame's time (ms),
                      step, alpha (the share of a step drawn past it) and
                      the steps dropped after stalls so far
  --debug             start with the debug overlay on (F1 toggles it in a window)
  --watch             reload a running game's map when it or a file it reads
                      (a tileset, a template, a picture) changes on disk,
                      and FILE.scm into the running game when it, a file it
                      loads or a module from its folder is saved: on by
                      default with --window, --repl-server and --repl-port
  --no-watch          do not
  --capture DIR       headless, and draw every frame off-screen into
                      DIR/NNNNNN.png (NNNNNN: the frame number)
  --repl-server PATH  serve a REPL into the game on a Unix socket (mode 0600)
  --repl-port N       serve it on 127.0.0.1:N instead
  --repl-timeout S    interrupt a REPL evaluation that holds the game longer
                      than S seconds (default " (number->string (@ (downstroke repl-server) default-repl-timeout)) ")
  --frames N          end each headless game-run! of FILE.scm after N frames at
                      most (fewer when its frames: says so; a window runs on)
  --timeout S         end FILE.scm after S seconds of wall time, saying so,
                      with exit status 124
  --no-auto-compile   run FILE.scm interpreted, compiling nothing into the
                      cache (by default an edited file is compiled, quietly)
  --version           the version of downstroke
  new DIR             write a new game into DIR (absent or empty): game.scm,
                      a Tiled map and tileset, sounds, tests, a README
  test [--junit FILE] [--timeout S] [PATH...]
                      run every *-test.scm under PATH (default: tests/), each
                      in its own process with (downstroke) and SRFI-64, for
                      at most S seconds (default 60); print each failed check
                      (file:line, expected, actual), each file with its count
                      of checks, and N passed, N failed; exit 0 only when
                      a test file was found and nothing failed
  --help              this text

An uncaught error prints its message and the calls in FILE.scm's folder;
DOWNSTROKE_BACKTRACE=full prints the whole backtrace instead.
"))

(define (usage)
  (display (usage-text) (current-error-port))
  2)

;; Options before the script, as (name . value); #f when one is malformed.
(define (parse-options args)
  (let loop ((args args) (opts '()))
    (define (with-value name check)
      (if (and (pair? (cdr args)) (check (cadr args)))
          (loop (cddr args) (acons name (cadr args) opts))
          #f))
    (cond ((null? args) (cons (reverse opts) '()))
          ((string=? (car args) "--window") (loop (cdr args) (acons 'window #t opts)))
          ((string=? (car args) "--help") (loop (cdr args) (acons 'help #t opts)))
          ((string=? (car args) "--version") (loop (cdr args) (acons 'version #t opts)))
          ((string=? (car args) "--no-auto-compile") (loop (cdr args) (acons 'no-auto-compile #t opts)))
          ((string=? (car args) "--debug") (loop (cdr args) (acons 'debug #t opts)))
          ((string=? (car args) "--fullscreen") (loop (cdr args) (acons 'fullscreen #t opts)))
          ((string=? (car args) "--watch") (loop (cdr args) (acons 'watch #t opts)))
          ((string=? (car args) "--no-watch") (loop (cdr args) (acons 'no-watch #t opts)))
          ((string=? (car args) "--frame-log") (with-value 'frame-log string?))
          ((string=? (car args) "--record") (with-value 'record string?))
          ((string=? (car args) "--scale")
           (with-value 'scale (lambda (v) (let ((n (string->number v))) (and n (exact-integer? n) (<= 1 n 64))))))
          ((string=? (car args) "--capture") (with-value 'capture string?))
          ((string=? (car args) "--repl-server") (with-value 'repl-server string?))
          ((string=? (car args) "--repl-timeout")
           (with-value 'repl-timeout (lambda (v) (let ((n (string->number v))) (and n (real? n) (< 0 n 1000000))))))
          ((string=? (car args) "--repl-port")
           (with-value 'repl-port (lambda (v) (let ((n (string->number v))) (and n (exact-integer? n) (< 0 n 65536))))))
          ((string=? (car args) "--frames")
           (with-value 'frames frame-count-text?))
          ((string=? (car args) "--timeout")
           (with-value 'timeout seconds-text?))
          ((string-prefix? "--" (car args)) #f)
          (else (cons (reverse opts) args)))))

;; --frames and --timeout: refused, said on the error port, when malformed.
(define (frame-count-text? v)
  (let ((n (string->number v)))
    (or (and n (exact-integer? n) (> n 0))
        (begin (format (current-error-port) "downstroke: --frames: expected a whole number of frames > 0, got ~s~%" v)
               #f))))

(define (seconds-text? v)
  (let ((n (string->number v)))
    (or (and n (real? n) (> n 0) (finite? n))
        (begin (format (current-error-port) "downstroke: --timeout: expected a number of seconds > 0, got ~s~%" v)
               #f))))

;; What only a window has: refused without --window.
(define window-only-options '(record frame-log scale fullscreen))

(define (prepare-display! opts)
  ;; #f when the options cannot be honoured (said on the error port).
  (let ((window? (assq-ref opts 'window))
        (capture (assq-ref opts 'capture)))
    (when (assq-ref opts 'debug) (debug-draw-default #t))
    (cond ((and window? capture)
           (display "downstroke: --window and --capture exclude each other\n" (current-error-port))
           #f)
          ((and (not window?) (find (lambda (o) (assq-ref opts o)) window-only-options))
           => (lambda (o)
                ;; Said, not ignored: a session played headless with
                ;; --record would end with no recording and no word why.
                (format (current-error-port) "downstroke: --~a applies only with --window~a~%" o
                        (if (eq? o 'record) ": a headless run's input is its input-script:" ""))
                #f))
          ((and (or window? capture) (not (renderer-available?)))
           (display "downstroke: this build has no renderer (SDL2): no --window or --capture\n"
                    (current-error-port))
           #f)
          (capture
           (catch 'system-error
             (lambda ()
               (unless (file-exists? capture) (mkdir capture))
               (capture-directory capture)
               (display-mode 'capture)
               #t)
             (lambda (key . args)
               (format (current-error-port) "downstroke: cannot make capture folder ~a: ~a~%"
                       capture (strerror (system-error-errno (cons key args))))
               #f)))
          (window?
           (display-mode 'window)
           (frame-pacing #t)
           (let ((scale (assq-ref opts 'scale)))
             (when scale (window-scale (string->number scale))))
           (when (assq-ref opts 'fullscreen) (window-fullscreen #t))
           (let ((log (assq-ref opts 'frame-log))) (when log (frame-log-file log)))
           (let ((record (assq-ref opts 'record)))
             ;; Checked now, not when the game ends: a session played
             ;; onto a path that cannot be written would be lost.
             (let ((problem (and record ((@ (downstroke tool-files) output-file-problem) record))))
               (cond (problem
                      (format (current-error-port) "downstroke: --record: cannot write ~s: ~a~%" record problem)
                      #f)
                     (else
                      (when record (record-file record))
                      #t)))))
          (else #t))))

(define (prepare-watch! opts)
  ;; Whether games watch their files (watch-default): asked for, or by
  ;; default where someone is at the game to edit it, a window or a REPL;
  ;; #f when both --watch and --no-watch are given (said on the error port).
  (cond ((and (assq-ref opts 'watch) (assq-ref opts 'no-watch))
         (display "downstroke: --watch and --no-watch exclude each other\n" (current-error-port))
         #f)
        (else
         ((@ (downstroke live) watch-default)
          (and (not (assq-ref opts 'no-watch))
               (any (lambda (o) (assq-ref opts o)) '(watch window repl-server repl-port))
               #t))
         #t)))

(define* (main args #:optional (version "unknown") (templates "templates"))
  "ARGS: the command line after the program's name (see usage-text);
VERSION: the project's, for --version; TEMPLATES: the folder of the
templates `downstroke new' copies. Returns the exit status."
  ;; Scripts are written as the seed writes them: `title: \"x\"'.
  (read-set! keywords 'postfix)
  (let ((parsed (parse-options args)))
    (cond ((not parsed) (usage))
          ((assq-ref (car parsed) 'help) (display (usage-text)) 0)
          ((assq-ref (car parsed) 'version) (format #t "downstroke ~a~%" version) 0)
          ((not (prepare-display! (car parsed))) 2)
          ((not (prepare-watch! (car parsed))) 2)
          (else
           (let ((opts (car parsed)) (rest (cdr parsed)))
             (cond ((and (or (assq-ref opts 'frames) (assq-ref opts 'timeout))
                         (or (null? rest) (member (car rest) '("test" "new"))))
                    (display "downstroke: --frames and --timeout bound the run of a script: give its FILE.scm\n"
                             (current-error-port))
                    2)
                   ((and (pair? rest) (string=? (car rest) "test"))
                    (run-test-command (cdr rest)))
                   ((and (pair? rest) (string=? (car rest) "new"))
                    (run-new-command (cdr rest) templates))
                   ((and (null? rest) (or (assq-ref opts 'repl-server) (assq-ref opts 'repl-port)))
                    (usage))
                   ((null? rest) (run-repl))
                   (else
                    (let ((socket (open-repl-socket opts))
                          (frames (assq-ref opts 'frames))
                          (timeout (assq-ref opts 'timeout)))
                      (cond ((eq? socket 'refused) 2)
                            (else
                             (when socket (serve-repl! socket (repl-timeout opts)))
                             (when frames ((@ (downstroke headless) headless-frame-limit) (string->number frames)))
                             (let ((status (call-with-timeout
                                            (and timeout (string->number timeout)) (car rest)
                                            (lambda ()
                                              (run-script (car rest) (cdr rest)
                                                          (not (assq-ref opts 'no-auto-compile)))))))
                               (when socket ((@ (downstroke repl-server) remove-unix-repl-socket!) socket))
                               status)))))))))))
