;;; (downstroke host) — what the `downstroke' executable runs.
(define-module (downstroke host)
  #:declarative? #f
  #:use-module (system repl repl)
  #:use-module (system repl server)
  #:use-module (system repl coop-server)
  #:use-module (downstroke engine)
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
;;; A cooperative REPL server: clients' expressions are evaluated on the
;;; game's own thread, between frames (a frame hook polls it), so they see
;;; and change the running game without locks.

(define (unix-server-socket path)
  ;; Only the owner may connect: create the socket under umask 077, so it is
  ;; never open to others, not even between bind and a chmod.
  (when (file-exists? path) (delete-file path))
  (let ((old (umask #o077)))
    (dynamic-wind
      (lambda () #t)
      (lambda ()
        (let ((socket (make-unix-domain-server-socket #:path path)))
          (chmod path #o600)
          socket))
      (lambda () (umask old)))))

(define (serve-repl! socket)
  (let ((server (spawn-coop-repl-server socket)))
    (add-frame-hook! (lambda () (poll-coop-repl-server server)))
    (frame-pacing #t)))

(define usage-text
  "usage: downstroke [OPTION...] [FILE.scm ARGS...]
Runs FILE.scm with (downstroke) imported, or a REPL when no file is given.

  --window            show the game in a window: real time, keyboard and
                      controllers, sound (closing it quits; F1: debug overlay)
  --scale N           the window's whole scale factor (default: fit the screen)
  --debug             start with the debug overlay on (F1 toggles it in a window)
  --capture DIR       headless, and draw every frame off-screen into
                      DIR/NNNNNN.png (NNNNNN: the frame number)
  --repl-server PATH  serve a REPL into the game on a Unix socket (mode 0600)
  --repl-port N       serve it on 127.0.0.1:N instead
  --help              this text
")

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
                    (let ((path (assq-ref opts 'repl-server))
                          (port (assq-ref opts 'repl-port)))
                      (cond (path (serve-repl! (unix-server-socket path)))
                            ;; loopback only: a REPL is arbitrary code execution
                            (port (serve-repl! (make-tcp-server-socket #:addr INADDR_LOOPBACK
                                                                        #:port (string->number port)))))
                      (run-script (car rest) (cdr rest))))))))))
