;; SPDX-License-Identifier: MIT
;;; Each public procedure's docstring is in one place (bindings/registry.hpp):
;;; the native code of a public Scheme procedure only names it, and the
;;; procedure it names exists and has a docstring.
(use-modules (srfi srfi-64) (srfi srfi-1) (ice-9 documentation) (downstroke)
             (downstroke documentation))

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

;; Every export of (downstroke) — procedures, macros, parameters, variables —
;; is documented: by its own docstring, or (when it cannot carry one) by
;; (downstroke documentation)'s notes.
(for-each
 (lambda (module-name)
   (for-each
    (lambda (name)
      (test-assert (format #f "~a, exported by ~a, is documented" name module-name)
        (string? (export-documentation module-name name))))
    (export-names module-name)))
 user-modules)
(test-equal "no export is undocumented" '() (undocumented-exports))

;; The notes are where the REPL looks.
(test-equal "a record accessor's note is its procedure-documentation"
  "GAME's title (a window shows it)."
  (procedure-documentation game-title))
(test-equal "a parameter's note is its object-documentation"
  "A parameter, #f by default: whether every game starts with the debug overlay on (the host's --debug)."
  (object-documentation debug-draw-default))
(test-equal "a variable's note is its variable's documentation property"
  "How far below its feet (px) detect-on-solid looks for ground: 4."
  (object-property (module-variable (resolve-interface '(downstroke)) '*on-solid-tolerance*)
                   'documentation))
(test-equal "a macro's docstring is its transformer's"
  "(define-pipeline (name skip-symbol) (entity scene dt) [guard: expr] body ...)"
  (car (string-split (export-documentation '(downstroke entity) 'define-pipeline) #\newline)))

;; Words a game author knows: no machinery in the documentation.
(define jargon '("Batch" "SCM" "decode cache" "native call" "beyond the seed" "semantics §"))
(for-each
 (lambda (module-name)
   (for-each
    (lambda (name)
      (let ((doc (or (export-documentation module-name name) "")))
        (test-equal (format #f "~a's documentation uses no internal jargon" name)
          '()
          (filter (lambda (word) (string-contains doc word)) jargon))))
    (export-names module-name)))
 user-modules)

(test-equal "signatures: a docstring's leading call, else the arguments"
  '("(tilemap-set-tile tm col row gid [layer])" "(entity-ref entity key [default])"
    "(make-scene [#:entities] [#:tilemap] [#:camera] [#:camera-target] [#:gravity] [#:data])"
    "(game-scene-set! game scene)" "(collision-mode)" "*gravity*"
    "(scene-map-entities scene . steps)")
  (map (lambda (m+n) (export-signature (car m+n) (cdr m+n)))
       '(((downstroke tilemap) . tilemap-set-tile) ((downstroke entity) . entity-ref)
         ((downstroke world) . make-scene) ((downstroke engine) . game-scene-set!)
         ((downstroke physics) . collision-mode) ((downstroke physics) . *gravity*)
         ((downstroke world) . scene-map-entities))))

(test-end "docstring")
