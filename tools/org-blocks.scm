;; SPDX-License-Identifier: MIT
;;; The source blocks of an Org file, as Org reads them: loaded by the docs
;;; test (tests/scheme/docs-test.scm) and by tools/tangle.scm.
;;;
;;; (org-blocks PATH) → a list of blocks (LINE LANGUAGE HEADERS TEXT): LINE
;;; the 1-based line of the #+begin_src, HEADERS its header arguments as
;;; strings (":eval" "no" …). A file-level
;;;   #+property: header-args:LANGUAGE :dir X :tangle Y
;;; (or header-args, for every language) comes before the block's own, so a
;;; block's own argument wins (header-ref finds the last).
(use-modules (ice-9 textual-ports) (srfi srfi-1))

(define (org-read-lines path)
  (string-split (call-with-input-file path get-string-all #:encoding "UTF-8") #\newline))

(define (org-prefix-ci? prefix s)
  (and (>= (string-length s) (string-length prefix))
       (string-ci=? prefix (substring s 0 (string-length prefix)))))

(define (org-words s)
  (remove string-null? (string-split s #\space)))

(define (org-file-headers lines)
  ;; ((LANGUAGE-or-#t . headers) …) from the #+property: header-args lines.
  (filter-map (lambda (line)
                (let ((t (string-trim line)))
                  (and (org-prefix-ci? "#+property:" t)
                       (let ((ws (org-words (substring t (string-length "#+property:")))))
                         (and (pair? ws) (string-prefix? "header-args" (car ws))
                              (cons (if (string-prefix? "header-args:" (car ws))
                                        (substring (car ws) (string-length "header-args:"))
                                        #t)
                                    (cdr ws)))))))
              lines))

(define (org-blocks path)
  (let* ((lines (org-read-lines path))
         (file-headers (org-file-headers lines)))
    (define (inherited lang)
      (append-map (lambda (h) (if (or (eq? (car h) #t) (equal? (car h) lang)) (cdr h) '()))
                  file-headers))
    (let loop ((lines lines) (n 1) (acc '()))
      (if (null? lines)
          (reverse acc)
          (let ((line (string-trim (car lines))))
            (if (org-prefix-ci? "#+begin_src" line)
                (let* ((ws (org-words (substring line (string-length "#+begin_src"))))
                       (lang (if (null? ws) "" (car ws)))
                       (headers (append (inherited lang) (if (null? ws) '() (cdr ws)))))
                  (let body ((rest (cdr lines)) (m (+ n 1)) (text '()))
                    (cond ((null? rest) (error "unterminated #+begin_src" path n))
                          ((org-prefix-ci? "#+end_src" (string-trim (car rest)))
                           (loop (cdr rest) (+ m 1)
                                 (cons (list n lang headers (string-join (reverse text) "\n")) acc)))
                          (else (body (cdr rest) (+ m 1) (cons (car rest) text))))))
                (loop (cdr lines) (+ n 1) acc)))))))

(define (header-ref headers name)
  ;; The value after the last NAME (":tangle") in HEADERS, or #f.
  (let loop ((h headers) (found #f))
    (cond ((or (null? h) (null? (cdr h))) found)
          ((string=? (car h) name) (loop (cddr h) (cadr h)))
          (else (loop (cdr h) found)))))
