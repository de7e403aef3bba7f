;; SPDX-License-Identifier: MIT
;;; Every source file says its licence in an SPDX line near its top (README,
;;; "Licence"): MIT for the engine, 0BSD for what authors copy into their
;;; own games (the starter in templates/, the demos and examples in demo/).
;;;
;;;   downstroke tools/spdx.scm           list the files without their line; exit 1 if any
;;;   downstroke tools/spdx.scm --fix     add the line where it is missing
;;;
;;; Run from the project's root; ctest runs the check as licence.spdx.
(use-modules (ice-9 ftw) (ice-9 textual-ports) (srfi srfi-1))

;; Where sources live; build folders and data are elsewhere.
(define roots '("src" "include" "bindings" "scheme" "tests" "demo" "templates" "tools" "bench" "cmake" ".ci"))
(define root-files '("CMakeLists.txt"))

(define (comment-prefix file)
  ;; How FILE writes a line comment, or #f when it is not a source file.
  (let ((name (basename file)))
    (cond ((any (lambda (s) (string-suffix? s name)) '(".cpp" ".hpp" ".def")) "// ")
          ((any (lambda (s) (string-suffix? s name)) '(".scm" ".el")) ";; ")
          ((or (string=? name "CMakeLists.txt") (string=? name "run")
               (any (lambda (s) (string-suffix? s name)) '(".cmake" ".in" ".sh" ".py")))
           "# ")
          (else #f))))

(define (licence-of file)
  ;; The licence FILE is under.
  (if (or (string-prefix? "demo/" file) (string-prefix? "templates/" file)) "0BSD" "MIT"))

(define (spdx-line file)
  (string-append (comment-prefix file) "SPDX-License-Identifier: " (licence-of file)))

(define (files-under dir)
  ;; DIR's source files, all the way down (links not followed).
  (append-map (lambda (name)
                (let* ((path (string-append dir "/" name)) (type (stat:type (lstat path))))
                  (cond ((eq? type 'directory) (files-under path))
                        ((and (eq? type 'regular) (comment-prefix path)) (list path))
                        (else '()))))
              (scandir dir (lambda (n) (not (member n '("." "..")))))))

(define (source-files)
  (sort (append (filter file-exists? root-files)
                (append-map files-under (filter file-exists? roots)))
        string<?))

(define (file-text file) (call-with-input-file file get-string-all #:encoding "UTF-8"))

(define (head-lines text n)
  (list-head (string-split text #\newline) (min n (length (string-split text #\newline)))))

(define (has-line? file)
  ;; Within its first three lines, as REUSE tools look for it.
  (member (spdx-line file) (head-lines (file-text file) 3)))

(define (keeps-first-line? file text)
  ;; A first line that must stay first: a #! line, or Emacs's -*- cookie.
  (or (string-prefix? "#!" text)
      (and (string-suffix? ".el" file) (string-contains (car (head-lines text 1)) "-*-"))))

(define (with-line file)
  (let* ((text (file-text file))
         (line (string-append (spdx-line file) "\n")))
    (if (keeps-first-line? file text)
        (let ((nl (string-index text #\newline)))
          (string-append (substring text 0 (+ nl 1)) line (substring text (+ nl 1))))
        (string-append line text))))

(define (main args)
  (let ((missing (remove has-line? (source-files))))
    (cond ((and (pair? args) (string=? (car args) "--fix"))
           (for-each (lambda (file)
                       (let ((text (with-line file)))
                         (call-with-output-file file (lambda (p) (put-string p text)) #:encoding "UTF-8")))
                     missing)
           (format #t "~a files given their SPDX line~%" (length missing))
           0)
          ((null? missing) 0)
          (else
           (for-each (lambda (file)
                       (format (current-error-port) "~a: no \"~a\" in its first three lines~%" file (spdx-line file)))
                     missing)
           (format (current-error-port) "(downstroke tools/spdx.scm --fix adds them)~%")
           1))))

(exit (main (cdr (program-arguments))))
