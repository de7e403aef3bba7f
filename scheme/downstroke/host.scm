;;; (downstroke host) — what the `downstroke' executable runs.
(define-module (downstroke host)
  #:declarative? #f
  #:use-module (system repl repl)
  #:use-module (system repl server)
  #:use-module (system repl coop-server)
  #:use-module (downstroke engine)
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

(define (usage)
  (display "usage: downstroke [--repl-server PATH | --repl-port N] [FILE.scm ARGS...]\n"
           (current-error-port))
  2)

(define (main args)
  "ARGS: () for a REPL, or ([--repl-server PATH | --repl-port N] FILE ARG ...)
to run a script, serving a REPL into it. Returns the exit status."
  ;; Scripts are written as the seed writes them: `title: \"x\"'.
  (read-set! keywords 'postfix)
  (cond ((null? args) (run-repl))
        ((and (member (car args) '("--repl-server" "--repl-port")) (< (length args) 3))
         (usage))
        ((string=? (car args) "--repl-server")
         (serve-repl! (unix-server-socket (cadr args)))
         (run-script (caddr args) (cdddr args)))
        ((string=? (car args) "--repl-port")
         (let ((port (string->number (cadr args))))
           (if (and port (exact-integer? port) (< 0 port 65536))
               (begin
                 ;; loopback only: a REPL is arbitrary code execution
                 (serve-repl! (make-tcp-server-socket #:addr INADDR_LOOPBACK #:port port))
                 (run-script (caddr args) (cdddr args)))
               (usage))))
        ((string-prefix? "--" (car args)) (usage))
        (else (run-script (car args) (cdr args)))))
