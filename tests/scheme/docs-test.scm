;; SPDX-License-Identifier: MIT
;;; Every Scheme example of the documentation, run.
;;;
;;; For each docs/*.org file (in name order) the `#+begin_src scheme' blocks
;;; are taken in order and evaluated, form by form, in one fresh module per
;;; file, so a later block sees what an earlier block of the same file
;;; defined. The module is a script's environment, made by the host's own
;;; use-script-environment! ((downstroke), (srfi srfi-1), (srfi srfi-11)),
;;; so an example that runs here runs in a user's script; the text is read
;;; as the host reads scripts, with postfix keywords (`entities:' is
;;; #:entities).
;;;
;;; Conventions for the documentation:
;;;
;;; - A form may be followed by a comment `; ⇒ VALUE' (any number of
;;;   semicolons), either on the line where the form ends or alone on the
;;;   line right after it. VALUE is read as a datum and the form's value
;;;   must be equal? to it: 103 and 103.0 differ, so exact and inexact
;;;   results are both checked. A ⇒ anywhere else in a block (after a
;;;   blank line, say, or inside a form) is reported as a failure, so no
;;;   claimed value goes unchecked.
;;; - Blocks that must not run use another language (sh, cpp, text, ...) or
;;;   the header argument `:eval no', e.g. `#+begin_src scheme :eval no'.
;;; - Header arguments come from the block and from the file's
;;;   `#+property: header-args:scheme ...' lines, as in Org. `:dir D' runs
;;;   the block in the folder D (relative to docs/): the tutorial's game
;;;   runs in demo/tutorial, where its maps are. A block tangled into a
;;;   *-test.scm (`:tangle .../tests/game-test.scm') is part of a test file,
;;;   which runs whole, under `downstroke test', after the file's blocks.
;;; - Examples run with the project root as the working directory (as under
;;;   ctest), so they load maps by their paths in the repository:
;;;   (load-tilemap "demo/maps/level1.tmx"). The module also predefines
;;;   `demo-map', the absolute path of demo/maps/level1.tmx, and
;;;   `test-data', the absolute path of tests/data, for examples that would
;;;   rather not depend on the working directory.
;;;
;;; Tests: one per block, named FILE:LINE (the line of its #+begin_src),
;;; passing when every form of the block evaluated without an error; and one
;;; per ⇒ check, named FILE:LINE => (the line of the comment).
(use-modules (srfi srfi-1) (srfi srfi-64) (ice-9 textual-ports) (ice-9 rdelim) (ice-9 ftw))

;;; ---------------------------------------------------------------- locations
(define project-root
  (let ((here (current-filename)))
    (if here
        (dirname (dirname (dirname (canonicalize-path here))))
        (getcwd))))
(define docs-dir (string-append project-root "/docs"))
(define demo-map-path (string-append project-root "/demo/maps/level1.tmx"))
(define test-data-path (string-append project-root "/tests/data"))

;;; ---------------------------------------------------------------- org parsing
;;; org-blocks and header-ref: blocks as (line language headers text), with
;;; a file's #+property: header-args before each block's own.
(include "../../tools/org-blocks.scm")

(define (eval-no? headers)
  (member (header-ref headers ":eval") '("no" "never")))

(define (test-file-block? headers)
  ;; A block tangled into a *-test.scm: a test file's part, which runs whole
  ;; under `downstroke test' (run-test-files), not block by block.
  (let ((target (header-ref headers ":tangle")))
    (and target (string-suffix? "-test.scm" target))))

(define (runnable? block)
  (and (string=? (cadr block) "scheme")
       (not (eval-no? (caddr block)))
       (not (test-file-block? (caddr block)))))

(define (block-dir block)
  ;; The folder a block runs in: its :dir (relative to docs/, as Org takes
  ;; it relative to the file), else the project's root.
  (let ((dir (header-ref (caddr block) ":dir")))
    (if dir (string-append docs-dir "/" dir) project-root)))

;;; "  ;; ⇒ 42" → "42"; anything else → #f.
(define (arrow-comment text)
  (let ((t (string-trim text)))
    (and (string-prefix? ";" t)
         (let ((after (string-trim (string-trim t #\;))))
           (and (string-prefix? "⇒" after)
                (string-trim (substring after 1)))))))

(define (count-arrows text)
  (let loop ((i 0) (n 0))
    (let ((j (string-index text #\⇒ i)))
      (if j (loop (+ j 1) (+ n 1)) n))))

;;; ---------------------------------------------------------------- running
(define (fresh-docs-module)
  ;; A script's own environment, as the host gives it (guile-user's, plus
  ;; script-interfaces): an example that runs here runs as a user's script.
  (let ((m ((@ (downstroke host) use-script-environment!) (make-fresh-user-module))))
    (module-define! m 'demo-map demo-map-path)
    (module-define! m 'test-data test-data-path)
    m))

(define (describe-error key args)
  (call-with-output-string
   (lambda (port) (print-exception port #f key args))))

;;; Evaluates the block's forms in MODULE. Returns #t, or the text of the
;;; first error (evaluation of the block stops there). Runs one test per ⇒.
(define (run-block file block module)
  (let* ((first-line (+ (car block) 1))  ; the block's first line of code
         (text (cadddr block))
         (port (open-input-string text))
         (checked 0))
    (set-port-line! port 0)
    (let loop ()
      (let ((form (catch #t
                    (lambda () (read port))
                    (lambda (key . args) (cons 'read-error (describe-error key args))))))
        (cond
         ((eof-object? form)
          (if (= checked (count-arrows text))
              #t
              (format #f "~a arrows (=>) in the block, only ~a of them after a form's last line"
                      (count-arrows text) checked)))
         ((and (pair? form) (eq? (car form) 'read-error))
          (string-append "read error: " (cdr form)))
         (else
          ;; The rest of the line the form ended on: a ⇒ comment, or more code.
          (let* ((pos (seek port 0 SEEK_CUR))
                 (line-index (port-line port))
                 (column (port-column port))
                 (rest (read-line port))
                 ;; On the form's last line, or alone on the next line.
                 (same-line (and (string? rest) (arrow-comment rest)))
                 (next (and (not same-line) (string? rest)
                            (string-null? (string-trim rest))
                            (read-line port)))
                 (next-line (and (string? next) (arrow-comment next)))
                 (expected-text (or same-line next-line))
                 (line (+ first-line line-index (if next-line 1 0))))
            (unless expected-text
              (seek port pos SEEK_SET)
              (set-port-line! port line-index)
              (set-port-column! port column))
            (let ((result (catch #t
                            (lambda () (cons 'ok (eval form module)))
                            (lambda (key . args) (cons 'error (describe-error key args))))))
              (cond
               ((eq? (car result) 'error)
                (format #f "line ~a: ~a" line (cdr result)))
               (expected-text
                (set! checked (+ checked 1))
                (let ((expected (catch #t
                                  (lambda () (read (open-input-string expected-text)))
                                  (lambda _ (list 'unreadable expected-text)))))
                  (test-equal (format #f "~a:~a =>" file line) expected (cdr result)))
                (loop))
               (else (loop)))))))))))

(define (doc-files)
  ;; render.org's examples draw: a build without the renderer skips them.
  (sort (filter (lambda (f) (and (string-suffix? ".org" f)
                                 (or (renderer-available?) (not (string=? f "render.org")))))
                (or (scandir docs-dir) '()))
        string<?))

(test-begin "docs")

(define examples 0)
(define checks-before 0)

;; Examples load maps by their repository paths.
(chdir project-root)

(define host (readlink "/proc/self/exe"))

(define (run-test-files file blocks)
  ;; The test files FILE's blocks are tangled into (docs.tutorial-current
  ;; checks they hold exactly those blocks), run as a user runs them: one
  ;; test each, passing when `downstroke test' exits 0.
  (for-each
   (lambda (target)
     (set! examples (+ examples 1))
     (test-equal (format #f "~a: ~a passes under downstroke test" file target)
       0 (status:exit-val (system* host "test" (string-append docs-dir "/" target)))))
   (delete-duplicates
    (filter-map (lambda (b) (and (test-file-block? (caddr b)) (header-ref (caddr b) ":tangle"))) blocks))))

(for-each
 (lambda (file)
   (let* ((all (org-blocks (string-append docs-dir "/" file)))
          (blocks (filter runnable? all))
          (module (fresh-docs-module)))
     (for-each
      (lambda (block)
        (set! examples (+ examples 1))
        (let ((outcome (begin (chdir (block-dir block))
                              (let ((o (run-block file block module))) (chdir project-root) o))))
          (unless (eq? outcome #t)
            (format (current-error-port) "~a:~a: ~a~%" file (car block) outcome))
          (test-equal (format #f "~a:~a" file (car block)) #t outcome)))
      blocks)
     ;; A game's golden-frame check draws: a build without the renderer skips them.
     (when (renderer-available?) (run-test-files file all))))
 (doc-files))

(test-assert "the documentation has examples" (> examples 0))
(format #t "docs: ~a example blocks~%" examples)

(test-end "docs")
