;;; (downstroke host) — what the `downstroke' executable runs.
(define-module (downstroke host)
  #:declarative? #f
  #:use-module (system repl repl)
  #:use-module (downstroke engine)
  #:use-module (downstroke repl-server)
  #:use-module (downstroke render)
  #:use-module (ice-9 format)
  #:export (main))

(define (report-error key args)
  (let ((port (current-error-port)))
    (display-backtrace (make-stack #t 3) port)
    (newline port)
    (print-exception port #f key args)))

(define (run-script file args)
  (set-program-arguments (cons file args))
  (catch #t
    (lambda ()
      (save-module-excursion
       (lambda ()
         (set-current-module (resolve-module '(guile-user)))
         (module-use! (current-module) (resolve-interface '(downstroke)))
         (load (canonicalize-path file))))
      0)
    (lambda (key . args)
      ;; (exit n) inside the script is a quit, not an error.
      (if (eq? key 'quit) (quit-status args) 1))
    (lambda (key . args)
      (unless (eq? key 'quit) (report-error key args)))))

(define (quit-status args)
  (cond ((null? args) 0)
        ((eq? (car args) #t) 0)
        ((eq? (car args) #f) 1)
        ((integer? (car args)) (car args))
        (else 1)))

(define (run-repl)
  (set-current-module (resolve-module '(guile-user)))
  (module-use! (current-module) (resolve-interface '(downstroke)))
  (false-if-exception
   (begin ((module-ref (resolve-interface '(ice-9 readline)) 'activate-readline)) #t))
  (start-repl)
  0)

;;; ---------------------------------------------------------------- live REPL
;;; (downstroke repl-server), polled by a frame hook at the start of every
;;; frame: expressions run on the game's own thread, between two frames.

(define (serve-repl! socket timeout)
  (let ((server (make-repl-server socket #:timeout timeout)))
    (add-frame-hook! (lambda () (repl-server-poll! server)))
    ;; A hook's error pauses the game instead of ending the session.
    (hook-error-reporter
     (lambda (text)
       (display text (current-error-port))
       (force-output (current-error-port))
       (repl-server-broadcast! server text)))
    (frame-pacing #t)
    (remove-socket-on-signals! socket)))

;; The signals that end a served game from outside (Ctrl-C in its terminal,
;; kill, a closed terminal): each still ends it as before, by that signal,
;; but only once the socket file is gone.
(define ending-signals (list SIGINT SIGTERM SIGHUP))

(define (remove-socket-on-signals! socket)
  (for-each (lambda (sig)
              (sigaction sig
                (lambda (sig)
                  (remove-unix-repl-socket! socket)
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
        (cond (path (open-unix-repl-socket path))
              (port (open-tcp-repl-socket (string->number port)))
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
    (if v (string->number v) default-repl-timeout)))

(define usage-text
  (string-append "usage: downstroke [OPTION...] [FILE.scm ARGS...]
Runs FILE.scm with (downstroke) imported, or a REPL when no file is given.

  --window            show the game in a window: real time, keyboard and
                      controllers, sound (closing it quits; F1: debug overlay)
  --scale N           the window's whole scale factor (default: fit the screen)
  --debug             start with the debug overlay on (F1 toggles it in a window)
  --capture DIR       headless, and draw every frame off-screen into
                      DIR/NNNNNN.png (NNNNNN: the frame number)
  --repl-server PATH  serve a REPL into the game on a Unix socket (mode 0600)
  --repl-port N       serve it on 127.0.0.1:N instead
  --repl-timeout S    interrupt a REPL evaluation that holds the game longer
                      than S seconds (default " (number->string default-repl-timeout) ")
  --help              this text
"))

(define (usage)
  (display usage-text (current-error-port))
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
          ((string=? (car args) "--debug") (loop (cdr args) (acons 'debug #t opts)))
          ((string=? (car args) "--scale")
           (with-value 'scale (lambda (v) (let ((n (string->number v))) (and n (exact-integer? n) (<= 1 n 64))))))
          ((string=? (car args) "--capture") (with-value 'capture string?))
          ((string=? (car args) "--repl-server") (with-value 'repl-server string?))
          ((string=? (car args) "--repl-timeout")
           (with-value 'repl-timeout (lambda (v) (let ((n (string->number v))) (and n (real? n) (< 0 n 1000000))))))
          ((string=? (car args) "--repl-port")
           (with-value 'repl-port (lambda (v) (let ((n (string->number v))) (and n (exact-integer? n) (< 0 n 65536))))))
          ((string-prefix? "--" (car args)) #f)
          (else (cons (reverse opts) args)))))

(define (prepare-display! opts)
  ;; #f when the options cannot be honoured (said on the error port).
  (let ((window? (assq-ref opts 'window))
        (capture (assq-ref opts 'capture)))
    (when (assq-ref opts 'debug) (debug-draw-default #t))
    (cond ((and window? capture)
           (display "downstroke: --window and --capture exclude each other\n" (current-error-port))
           #f)
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
           #t)
          (else #t))))

(define (main args)
  "ARGS: the command line after the program's name (see usage-text).
Returns the exit status."
  ;; Scripts are written as the seed writes them: `title: \"x\"'.
  (read-set! keywords 'postfix)
  (let ((parsed (parse-options args)))
    (cond ((not parsed) (usage))
          ((assq-ref (car parsed) 'help) (display usage-text) 0)
          ((not (prepare-display! (car parsed))) 2)
          (else
           (let ((opts (car parsed)) (rest (cdr parsed)))
             (cond ((and (null? rest) (or (assq-ref opts 'repl-server) (assq-ref opts 'repl-port)))
                    (usage))
                   ((null? rest) (run-repl))
                   (else
                    (let ((socket (open-repl-socket opts)))
                      (cond ((eq? socket 'refused) 2)
                            (else
                             (when socket (serve-repl! socket (repl-timeout opts)))
                             (let ((status (run-script (car rest) (cdr rest))))
                               (when socket (remove-unix-repl-socket! socket))
                               status)))))))))))
