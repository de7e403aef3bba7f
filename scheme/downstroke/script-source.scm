;; SPDX-License-Identifier: MIT
;;; (downstroke script-source) — what the host reads in a script's source
;;; itself, where Guile's compiler and expander say too little: the names
;;; defined by the files a script `load's (its compiler cannot know them, and
;;; warned of each as possibly unbound), and where in a file a form the
;;; expander refused without a place is.
(define-module (downstroke script-source)
  #:use-module (srfi srfi-1)
  #:export (loaded-definitions loaded-files form-location))

(define (read-forms file)
  ;; FILE's top-level forms, with their source positions; () when it cannot
  ;; be read (loading it says why, named).
  (catch #t
    (lambda ()
      (call-with-input-file file
        (lambda (port)
          (let loop ((acc '()))
            (let ((form (read port)))
              (if (eof-object? form) (reverse acc) (loop (cons form acc))))))))
    (lambda _ '())))

(define (quoted? form)
  (and (pair? form) (memq (car form) '(quote quasiquote syntax quasisyntax))))

(define (loads-in form dir)
  ;; The files FORM loads by a literal name, `load' resolving a relative one
  ;; against the folder of the file it is written in (DIR), as Guile's does.
  (cond ((not (pair? form)) '())
        ((quoted? form) '())
        ((and (eq? (car form) 'load) (pair? (cdr form)) (string? (cadr form)))
         (list (if (absolute-file-name? (cadr form)) (cadr form) (string-append dir "/" (cadr form)))))
        (else (let walk ((rest form))
                (if (pair? rest) (append (loads-in (car rest) dir) (walk (cdr rest))) '())))))

(define (defined-names form)
  ;; The top-level names FORM defines: any (define… NAME …) or
  ;; (define… (NAME …) …) — define*, define-syntax, the engine's
  ;; define-pipeline —, a record type's procedures, define-values' names.
  (define (head-name x) (if (pair? x) (head-name (car x)) x))
  (define (definer? x)
    (and (symbol? x) (string-prefix? "define" (symbol->string x))))
  (cond ((not (and (pair? form) (pair? (cdr form)))) '())
        ((eq? (car form) 'begin) (append-map defined-names (cdr form)))
        ((eq? (car form) 'define-record-type)
         (filter symbol?
                 (append (list (cadr form))
                         (if (pair? (cddr form)) (list (head-name (caddr form))) '())
                         (if (and (pair? (cddr form)) (pair? (cdddr form))) (list (cadddr form)) '())
                         (if (and (pair? (cddr form)) (pair? (cdddr form)))
                             (append-map (lambda (field) (if (pair? field) (cdr field) '()))
                                         (cddddr form))
                             '()))))
        ((eq? (car form) 'define-values)
         (let names ((formals (cadr form)))
           (cond ((symbol? formals) (list formals))
                 ((pair? formals) (append (names (car formals)) (names (cdr formals))))
                 (else '()))))
        ((eq? (car form) 'define-module) '())
        ((definer? (car form))
         (let ((name (head-name (cadr form)))) (if (symbol? name) (list name) '())))
        (else '())))

(define (loaded-definitions file)
  "The names defined at the top level of the files FILE loads by a literal
name, and of the files those load, each file read once."
  (delete-duplicates
   (append-map (lambda (loaded) (append-map defined-names (read-forms loaded)))
               (cdr (loaded-files file)))
   eq?))

(define (loaded-files file)
  "FILE, then the files it loads by a literal name, and the files those
load, each once."
  (let loop ((pending (list file)) (seen '()))
    (cond ((null? pending) (reverse seen))
          ((member (car pending) seen) (loop (cdr pending) seen))
          (else
           (loop (append (cdr pending)
                         (append-map (lambda (form) (loads-in form (dirname (car pending))))
                                     (read-forms (car pending))))
                 (cons (car pending) seen))))))

(define (form-location form files)
  "Where FORM (a pair) is written outside quoted data in the first of FILES
holding it: the alist of its source properties (filename, line, column),
or #f."
  (define (find-in x)
    (cond ((not (pair? x)) #f)
          ((quoted? x) #f)
          ((and (equal? x form) (pair? (source-properties x))) (source-properties x))
          (else (let walk ((rest x))
                  (and (pair? rest)
                       (or (find-in (car rest)) (walk (cdr rest))))))))
  (and (pair? form)
       (any (lambda (file) (any find-in (read-forms file))) files)))
