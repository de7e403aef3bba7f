;; SPDX-License-Identifier: MIT
;;; Tangles an Org file as Org's C-c C-v t does: every source block with a
;;; :tangle FILE (its own, or from the file's #+property: header-args) is
;;; written to FILE (relative to the Org file), the blocks of one FILE in
;;; order, a blank line between them.
;;;
;;;   downstroke tools/tangle.scm docs/tutorial.org           write the files
;;;   downstroke tools/tangle.scm --check docs/tutorial.org   exit 1, naming
;;;       each file that differs from what the Org file holds
;;;
;;; docs/tutorial.org is the one source of the tutorial's game: its files
;;; under demo/tutorial are tangled from it, and the docs.tutorial-current
;;; test checks that they still are.
(use-modules (ice-9 textual-ports) (srfi srfi-1))
(include "org-blocks.scm")

(define (tangled org)
  ;; ((file . text) …) in the order the files first appear.
  (let ((base (dirname org)))
    (fold-right
     (lambda (block acc)
       (let ((target (header-ref (caddr block) ":tangle")))
         (if (or (not target) (member target '("no" "yes")))
             acc
             (let* ((file (string-append base "/" target))
                    (held (assoc file acc)))
               (if held
                   (cons (cons file (string-append (cadddr block) "\n\n" (cdr held)))
                         (alist-delete file acc))
                   (cons (cons file (string-append (cadddr block) "\n")) acc))))))
     '()
     (org-blocks org))))

(define (file-text file)
  (and (file-exists? file) (call-with-input-file file get-string-all #:encoding "UTF-8")))

(define (main args)
  (let* ((check? (and (pair? args) (string=? (car args) "--check")))
         (org (if check? (cadr args) (car args)))
         (files (tangled org))
         (stale (remove (lambda (f) (equal? (file-text (car f)) (cdr f))) files)))
    (cond ((null? files)
           (format (current-error-port) "~a: no block has a :tangle file~%" org) 1)
          (check?
           (for-each (lambda (f)
                       (format (current-error-port) "~a is not what ~a tangles to: run downstroke tools/tangle.scm ~a~%"
                               (car f) org org))
                     stale)
           (if (null? stale) 0 1))
          (else
           (for-each (lambda (f)
                       (call-with-output-file (car f) (lambda (p) (put-string p (cdr f))) #:encoding "UTF-8")
                       (format #t "wrote ~a~%" (car f)))
                     stale)
           0))))

(exit (main (cdr (program-arguments))))
