;; SPDX-License-Identifier: MIT
;;; Ends every § of docs/semantics.org with an "Implemented in" line: the
;;; C++ functions and the reference procedures that cite it, read from the
;;; code's own citations, so that a reader goes from a rule to its code.
;;;
;;;   build/bin/downstroke tools/semantics-map.scm docs/semantics.org
;;;   build/bin/downstroke tools/semantics-map.scm --check docs/semantics.org
;;;
;;; --check writes nothing and fails when the file is not what it would write
;;; (ctest runs it as docs.semantics-map-current).
;;;
;;; A citation is "§N" (N a section's number) in:
;;; - C++ (src/, include/, bindings/): the block of // comments right above a function's
;;;   declaration or definition — the function implements §N;
;;; - scheme/downstroke/reference.scm: a top-level procedure's docstring, or
;;;   the ;; comments right above its define.
;;; A citation elsewhere (on a field, a constant, a section banner) names no
;;; function and is not listed.
(use-modules (ice-9 ftw) (ice-9 regex) (ice-9 rdelim) (ice-9 textual-ports)
             (srfi srfi-1) (srfi srfi-26))

(define cpp-roots '("src" "include" "bindings"))
(define reference-file "scheme/downstroke/reference.scm")
(define marker "Implemented in:")

;;; ---------------------------------------------------------------- citations
(define section-pattern (make-regexp "§([0-9]+)"))

(define (cited-sections text)
  ;; The section numbers TEXT cites, each once, in order.
  (delete-duplicates
   (map (lambda (m) (string->number (match:substring m 1))) (list-matches section-pattern text))))

(define (file-lines file)
  (call-with-input-file file
    (lambda (port)
      (let loop ((acc '()))
        (let ((line (read-line port)))
          (if (eof-object? line) (list->vector (reverse acc)) (loop (cons line acc))))))))

;;; ---------------------------------------------------------------- C++
(define comment-line (make-regexp "^[ \t]*//"))

;; A declaration or definition of a function: a return type, then NAME and
;; its parameters; not a statement, a macro, a type or a variable.
(define function-line (make-regexp "^[ \t]*([A-Za-z_][A-Za-z0-9_:<>,*& ]*[ *&])([A-Za-z_][A-Za-z0-9_]*)\\("))
(define not-a-function (make-regexp "^[ \t]*(return|if|for|while|switch|case|else|struct|class|enum|using|namespace|#|DS_|static_assert|throw)\\b"))

(define (cpp-functions file)
  ;; ((name . sections) …) for FILE's cited functions.
  (let ((lines (file-lines file)))
    (let loop ((i 0) (block "") (acc '()))
      (if (= i (vector-length lines))
          (reverse acc)
          (let ((line (vector-ref lines i)))
            (cond ((regexp-exec comment-line line)
                   (loop (+ i 1) (string-append block line "\n") acc))
                  ((string-null? block) (loop (+ i 1) "" acc))
                  (else
                   (let ((m (and (not (regexp-exec not-a-function line))
                                 (regexp-exec function-line line)))
                         (sections (cited-sections block)))
                     (loop (+ i 1) ""
                           ;; An = before the name's ( is a variable's initialiser.
                           (if (and m (pair? sections) (not (string-index (match:prefix m) #\=))
                                    (not (string-index (match:substring m 1) #\=)))
                               (cons (cons (qualified lines i (match:substring m 2)) sections) acc)
                               acc))))))))))

;; A type's head; an export macro (DOWNSTROKE_API) before its name is skipped.
(define type-line (make-regexp "^([ \t]*)(class|struct)[ \t]+(DOWNSTROKE_API[ \t]+)?([A-Za-z_][A-Za-z0-9_]*)"))

(define (indent-of line) (- (string-length line) (string-length (string-trim line))))

(define (qualified lines i name)
  ;; NAME, as Type::NAME when line I declares it inside a class or struct.
  (let ((depth (indent-of (vector-ref lines i))))
    (if (zero? depth)
        name
        (let up ((j (- i 1)))
          (if (< j 0)
              name
              (let ((m (regexp-exec type-line (vector-ref lines j))))
                (cond ((and m (< (string-length (match:substring m 1)) depth)
                            (not (string-suffix? ";" (string-trim-right (vector-ref lines j)))))
                       (string-append (match:substring m 4) "::" name))
                      ((and (not (string-null? (string-trim (vector-ref lines j))))
                            (< (indent-of (vector-ref lines j)) depth)
                            (not (string-prefix? "//" (string-trim (vector-ref lines j))))
                            (not (regexp-exec type-line (vector-ref lines j)))
                            (not (string-prefix? "public:" (string-trim (vector-ref lines j))))
                            (not (string-prefix? "private:" (string-trim (vector-ref lines j)))))
                       name)        ; inside a function or namespace block, not a type
                      (else (up (- j 1))))))))))

(define (source-files root)
  ;; ROOT's .hpp and .cpp files, all the way down, sorted.
  (if (not (file-exists? root))
      '()
      (sort (let walk ((dir root))
              (append-map (lambda (name)
                            (let ((path (string-append dir "/" name)))
                              (cond ((eq? 'directory (stat:type (stat path))) (walk path))
                                    ((or (string-suffix? ".hpp" name) (string-suffix? ".cpp" name)) (list path))
                                    (else '()))))
                          (scandir dir (lambda (n) (not (member n '("." "..")))))))
            string<?)))

(define (cpp-citations)
  ;; ((name file . sections) …): a function cited in its header and its
  ;; source file is listed once, with its header.
  (let ((all (append-map (lambda (file) (map (lambda (f) (cons* (car f) file (cdr f))) (cpp-functions file)))
                         (append-map source-files cpp-roots))))
    (filter-map (lambda (entry)
                  (let ((same (filter (lambda (e) (string=? (car e) (car entry))) all)))
                    (and (eq? entry (or (find (lambda (e) (string-suffix? ".hpp" (cadr e))) same) (car same)))
                         (cons* (car entry) (cadr entry)
                                (delete-duplicates (append-map cddr same))))))
                all)))

;;; ---------------------------------------------------------------- the reference
(define (definition-name form)
  ;; The procedure FORM defines at the top level, or #f.
  (and (pair? form) (memq (car form) '(define define* define-step)) (pair? (cdr form)) (pair? (cadr form))
       (symbol? (caadr form)) (caadr form)))

(define (comments-above lines line)
  ;; The ;; lines right above the 0-based LINE, banners (;;; ----) excluded.
  (let loop ((i (- line 1)) (acc '()))
    (if (and (>= i 0) (string-prefix? ";;" (string-trim (vector-ref lines i)))
             (not (string-contains (vector-ref lines i) "-----")))
        (loop (- i 1) (cons (vector-ref lines i) acc))
        (string-join acc "\n"))))

(define (reference-citations)
  ;; ((name . sections) …) for the reference's cited procedures.
  (let ((lines (file-lines reference-file)))
    (call-with-input-file reference-file
      (lambda (port)
        (let loop ((acc '()))
          (let* ((line (port-line port)) (form (read port)))
            (if (eof-object? form)
                (reverse acc)
                (let* ((name (definition-name form))
                       (doc (and name (pair? (cddr form)) (string? (caddr form)) (pair? (cdddr form)) (caddr form)))
                       (start (or (and (pair? form) (source-property form 'line)) line))
                       (sections (and name (cited-sections (string-append (or doc "") "\n" (comments-above lines start))))))
                  (loop (if (and name (pair? sections)) (cons (cons (symbol->string name) sections) acc) acc))))))))))

;;; ---------------------------------------------------------------- the lines
(define (implemented-line n cpp reference)
  (let ((functions (filter (lambda (e) (memv n (cddr e))) cpp))
        (procedures (filter (lambda (e) (memv n (cdr e))) reference)))
    (string-append
     marker " C++ "
     (if (null? functions)
         "none"
         (string-join
          (map (lambda (file)
                 (string-append (string-join (map (lambda (e) (string-append "=" (car e) "=")) 
                                                  (filter (lambda (e) (string=? (cadr e) file)) functions))
                                             ", ")
                                " (=" file "=)"))
               (delete-duplicates (map cadr functions)))
          "; "))
     "; reference "
     (if (null? procedures)
         "none (the rule is not modelled in =reference.scm=)"
         (string-append (string-join (map (lambda (e) (string-append "=" (car e) "=")) procedures) ", ")
                        " (=" reference-file "=)"))
     ".")))

(define heading (make-regexp "^\\* §([0-9]+) "))

(define (mapped-text text)
  ;; TEXT with each § section's last paragraph an "Implemented in" line,
  ;; replacing the one it has.
  (let ((cpp (cpp-citations)) (reference (reference-citations)))
    (let loop ((lines (string-split text #\newline)) (section #f) (out '()))
      (define (close-section out)
        ;; OUT (newest first) with SECTION's line added before its trailing blank lines.
        (if (not section)
            out
            (let* ((blanks (take-while string-null? out)) (body (drop-while string-null? out)))
              (append blanks (list (implemented-line section cpp reference) "") body))))
      (cond ((null? lines) (reverse (close-section out)))
            ((string-prefix? marker (car lines))
             ;; The old line and the blank line before it go.
             (loop (cdr lines) section (drop-while string-null? out)))
            ((regexp-exec heading (car lines))
             => (lambda (m)
                  (loop (cdr lines) (string->number (match:substring m 1)) (cons (car lines) (close-section out)))))
            ((string-prefix? "* " (car lines))
             (loop (cdr lines) #f (cons (car lines) (close-section out))))
            (else (loop (cdr lines) section (cons (car lines) out)))))))

(define (main args)
  (let* ((check? (and (pair? args) (string=? (car args) "--check")))
         (file (if check? (cadr args) (car args)))
         (text (call-with-input-file file get-string-all))
         (mapped (string-join (mapped-text text) "\n")))
    (cond ((not check?)
           (unless (string=? mapped text)
             (call-with-output-file file (cut display mapped <>)))
           0)
          ((string=? mapped text) 0)
          (else
           (format (current-error-port)
                   "~a: its \"Implemented in\" lines are not the code's citations; run:\n  build/bin/downstroke tools/semantics-map.scm ~a\n"
                   file file)
           1))))

(exit (main (cdr (program-arguments))))
