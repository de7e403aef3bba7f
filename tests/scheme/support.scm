;; SPDX-License-Identifier: MIT
;;; Helpers shared by the SRFI-64 suites; each suite (load "support.scm").
(use-modules (srfi srfi-1))

;;; The printed error (procedure, message, irritants) raised by THUNK, or #f.
(define (error-text thunk)
  (catch #t
    (lambda () (thunk) #f)
    (lambda (key . args)
      (call-with-output-string
       (lambda (port) (print-exception port #f key args))))))

;;; Whether TEXT contains every one of PARTS.
(define (mentions? text . parts)
  (and (string? text) (every (lambda (p) (string-contains text p)) parts) #t))

;;; The demo/ directory: ../../demo from this file, else from DS_TEST_DATA
;;; (tests/data), else the working directory's demo/.
(define demo-dir
  (let ((candidates
         (append (let ((here (current-filename)))
                   (if here (list (string-append (dirname here) "/../../demo")) '()))
                 (let ((data (getenv "DS_TEST_DATA")))
                   (if data (list (string-append data "/../../demo")) '()))
                 (list "demo"))))
    (canonicalize-path
     (or (find (lambda (d) (file-exists? (string-append d "/platformer.scm"))) candidates)
         (error "cannot find the demo directory" candidates)))))

(define (load-in-fresh-module file)
  "A fresh module that uses (downstroke), with FILE loaded into it, so that
a demo's or an example's top-level names stay its own."
  (let ((m (make-fresh-user-module)))
    (module-use! m (resolve-interface '(downstroke)))
    (save-module-excursion
     (lambda ()
       (set-current-module m)
       (load file)))
    m))
