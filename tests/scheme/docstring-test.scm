;;; Each public procedure's docstring is in one place (bindings/registry.hpp):
;;; the native code of a public Scheme procedure only names it, and the
;;; procedure it names exists and has a docstring.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke))

(load "support.scm")

(test-begin "docstring")

(define native (resolve-interface '(downstroke native)))
(define native-procedures
  (filter-map (lambda (name) (let ((v (module-ref native name))) (and (procedure? v) (cons name v))))
              (module-map (lambda (name var) name) native)))

(test-assert "(downstroke native) has procedures" (> (length native-procedures) 40))
(for-each
 (lambda (entry)
   (test-assert (format #f "~a has a docstring" (car entry))
     (string? (procedure-documentation (cdr entry)))))
 native-procedures)

;; "ARGS: native code for NAME in (MODULE …), which documents it." → (NAME MODULE)
(define (pointer-of doc)
  (let* ((for (string-contains doc "native code for "))
         (in (and for (string-contains doc " in (" for)))
         (end (and in (string-contains doc "), which documents it." in))))
    (and end
         (list (string->symbol (substring doc (+ for (string-length "native code for ")) in))
               (map string->symbol (string-split (substring doc (+ in (string-length " in (")) end) #\space))))))
(define pointers
  (filter-map (lambda (entry)
                (let ((p (pointer-of (or (procedure-documentation (cdr entry)) ""))))
                  (and p (cons (car entry) p))))
              native-procedures))
(test-assert "native code of public procedures names them" (> (length pointers) 15))
(for-each
 (lambda (p)
   (let* ((name (cadr p)) (module (caddr p))
          (iface (false-if-exception (resolve-interface module)))
          (proc (and iface (module-variable iface name) (module-ref iface name))))
     (test-assert (format #f "~a: ~a exported by ~a, with its own docstring" (car p) name module)
       (and (procedure? proc)
            (not (eq? proc (module-ref native (car p))))
            (string? (procedure-documentation proc))
            (not (string-contains (procedure-documentation proc) "native code for"))
            ;; and (downstroke) hands users the same procedure
            (eq? proc (module-ref (resolve-interface '(downstroke)) name))))))
 pointers)

(test-end "docstring")
