;;; (downstroke host) — what the `downstroke' executable runs.
(define-module (downstroke host)
  #:declarative? #f
  #:use-module (system repl repl)
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

(define (main args)
  "ARGS: () for a REPL, or (FILE ARG ...) to run a script. Returns the exit status."
  ;; Scripts are written as the seed writes them: `title: \"x\"'.
  (read-set! keywords 'postfix)
  (if (null? args)
      (run-repl)
      (run-script (car args) (cdr args))))
