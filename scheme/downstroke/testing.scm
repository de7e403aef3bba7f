;;; (downstroke testing) — testing a game like code: `downstroke test' runs
;;; every *-test.scm under the paths it is given, each in a script's own
;;; environment with SRFI-64, and says what failed, where, expected what.
(define-module (downstroke testing)
  #:use-module (srfi srfi-1)
  #:use-module (srfi srfi-64)
  #:use-module (ice-9 ftw)
  #:use-module (ice-9 format)
  #:use-module (downstroke engine)
  #:use-module (downstroke render)
  #:use-module ((downstroke native) #:select (%display-compare-png))
  #:use-module (downstroke tool-files)
  #:use-module ((ice-9 textual-ports) #:select (get-string-n))
  #:re-export (record-input read-input-script)
  #:export (test-files run-tests play check-frame))

;;; ---------------------------------------------------------------- games in tests

(define* (play game #:key frames (input #f))
  "Run GAME headless up to frame FRAMES (as game-run! counts: from where it
stopped), with INPUT as its input script when given (a list, or the file
record-input wrote), and return it."
  (when input
    (let ((script (if (string? input) (read-input-script input) input)))
      ((@@ (downstroke engine) check-input-script) "play" script)
      ((@@ (downstroke engine) game-input-script-set!) game script)))
  (parameterize ((display-mode 'headless))
    (game-run! game #:frames frames))
  game)

(define (sibling file suffix)
  ;; expected.png → expected.actual.png
  (let ((dot (string-rindex file #\.)))
    (if dot (string-append (substring file 0 dot) suffix (substring file dot)) (string-append file suffix))))

(define (check-frame game file)
  "Draw GAME's current frame and compare it, pixel by pixel, with the golden
PNG FILE: #t when they are the same. When not, write FILE's .actual.png and
.diff.png siblings (the frame, and it darkened with each differing pixel
magenta) and raise an error saying how many pixels differ and the first.
With DOWNSTROKE_UPDATE_GOLDEN=1 in the environment, write FILE instead."
  (unless (string? file)
    (scm-error 'wrong-type-arg "check-frame" "file: expected a string, got ~S" (list file) #f))
  (cond ((equal? (getenv "DOWNSTROKE_UPDATE_GOLDEN") "1")
         (game-capture game file)
         #t)
        ((not (file-exists? file))
         (scm-error 'misc-error "check-frame" "no golden picture ~S (DOWNSTROKE_UPDATE_GOLDEN=1 writes it)"
                    (list file) #f))
        (else
         ((@@ (downstroke engine) draw-game!) game)
         (let* ((actual (sibling file ".actual")) (diff (sibling file ".diff"))
                (r (%display-compare-png ((@@ (downstroke engine) game-display) game) file actual diff)))
           (cond ((not r) #t)
                 ((eq? (car r) 'size)
                  (scm-error 'misc-error "check-frame" "the frame is ~Ax~A, ~S is ~Ax~A; see ~S"
                             (list (game-width game) (game-height game) file (cadr r) (caddr r) actual) #f))
                 (else
                  (scm-error 'misc-error "check-frame"
                             "~A pixel(s) differ from ~S, the first at (~A, ~A): expected ~S, got ~S; see ~S and ~S"
                             (list (car r) file (cadr r) (caddr r) (list-ref r 3) (list-ref r 4) actual diff) #f)))))))

(define (test-file? name) (string-suffix? "-test.scm" name))

(define (test-files paths)
  "The *-test.scm files under PATHS (files or folders, searched all the way
down), each once, in name order within a folder."
  (delete-duplicates
   (append-map
    (lambda (path)
      (cond ((not (file-exists? path)) '())
            ((eq? 'directory (stat:type (stat path)))
             (sort (file-system-fold (lambda (name stat acc) #t)  ; enter every folder
                                     (lambda (name stat acc) (if (test-file? (basename name)) (cons name acc) acc))
                                     (lambda (name stat acc) acc) (lambda (name stat acc) acc)
                                     (lambda (name stat acc) acc) (lambda (name stat errno acc) acc)
                                     '() path)
                   string<?))
            (else (list path))))
    paths)))

;;; One result: (file name kind expected actual line), kind pass, fail or error.
(define (runner-for file results)
  (let ((runner (test-runner-null)))
    (test-runner-on-test-end! runner
      (lambda (r)
        (let ((kind (test-result-kind r)))
          (set-car! results
                    (cons (list file (or (test-runner-test-name r) "")
                                (if (memq kind '(pass xfail skip)) 'pass 'fail)
                                (test-result-ref r 'expected-value)
                                ;; A check that raised: (raised . the error, as it would print).
                                (let ((err (test-result-ref r 'actual-error)))
                                  (if err
                                      (cons 'raised
                                            (call-with-output-string
                                              (lambda (port)
                                                (if (pair? err) (print-exception port #f (car err) (cdr err)) (write err port)))))
                                      (test-result-ref r 'actual-value)))
                                (test-result-ref r 'source-line))
                          (car results))))))
    runner))

(define (run-file file make-environment load-file)
  "Load FILE with a runner that records each check; a file that does not
load is one failure naming its error. Returns its results."
  (let ((results (list '())))
    (test-runner-factory (lambda () (runner-for file results)))
    (test-runner-current #f)
    (catch #t
      (lambda ()
        (save-module-excursion
         (lambda ()
           (set-current-module (make-environment))
           (load-file (canonicalize-path file)))))
      (lambda (key . args)
        (set-car! results
                  (cons (list file "(the file did not run to its end)" 'error
                              #f (call-with-output-string
                                   (lambda (port) (print-exception port #f key args)))
                              #f)
                        (car results)))))
    (reverse (car results))))

(define (raised? actual) (and (pair? actual) (eq? (car actual) 'raised)))

(define (one-line text)
  ;; An error's text on one line: its lines joined, the last newline gone.
  (string-join (remove string-null? (map string-trim-both (string-split text #\newline))) " "))

(define (outcome-text expected actual)
  ;; "expected 5, actual 4", or "expected 5, raised: In procedure car: …".
  (if (raised? actual)
      (format #f "expected ~s, raised: ~a" expected (one-line (cdr actual)))
      (format #f "expected ~s, actual ~s" expected actual)))

(define (report-failure port r)
  ;; One line a failed check: where, its name, what was expected and what came.
  (apply (lambda (file name kind expected actual line)
           (if (eq? kind 'error)
               (format port "FAIL ~a: ~a: ~a~%" file name (one-line actual))
               (format port "FAIL ~a:~a: ~a: ~a~%" file (or line "?") name (outcome-text expected actual))))
         r))

(define (xml-escape s)
  (string-concatenate
   (map (lambda (c)
          (case c ((#\<) "&lt;") ((#\>) "&gt;") ((#\&) "&amp;") ((#\") "&quot;") (else (string c))))
        (string->list s))))

;; How much of an existing file is read to tell a JUnit report: its XML
;; declaration and the <testsuites> after it fit in the first line or two.
(define junit-sniff-chars 512)

(define (junit-target-problem file)
  ;; #f when FILE may take a JUnit report: absent, or a regular file that
  ;; holds one (a report of an earlier run). Else why not: `--junit' with
  ;; its name forgotten takes the next argument, a test file or the game.
  (or (output-file-problem file)
      (and (file-exists? file)
           (or (input-file-problem file)
               (let ((head (false-if-exception
                            (call-with-input-file file
                              (lambda (port) (get-string-n port junit-sniff-chars))
                              #:encoding "UTF-8"))))
                 (and (not (and (string? head) (string-prefix? "<?xml" head) (string-contains head "<testsuites")))
                      "it exists and is not a JUnit report (it does not start with <?xml and hold <testsuites>), so it is not written over"))))))

(define (write-junit file by-file)
  (call-with-output-file/whole "downstroke test" file
    (lambda (port)
      (format port "<?xml version=\"1.0\" encoding=\"UTF-8\"?>~%<testsuites>~%")
      (for-each
       (lambda (entry)
         (let* ((name (car entry)) (results (cdr entry))
                (failures (count (lambda (r) (eq? (caddr r) 'fail)) results))
                (errors (count (lambda (r) (eq? (caddr r) 'error)) results)))
           (format port "  <testsuite name=\"~a\" tests=\"~a\" failures=\"~a\" errors=\"~a\">~%"
                   (xml-escape name) (length results) failures errors)
           (for-each
            (lambda (r)
              (format port "    <testcase classname=\"~a\" name=\"~a\"" (xml-escape name) (xml-escape (cadr r)))
              (case (caddr r)
                ((pass) (format port "/>~%"))
                ((fail) (format port "><failure message=\"~a\">~a</failure></testcase>~%"
                                (xml-escape (format #f "line ~a" (or (list-ref r 5) "?")))
                                (xml-escape (outcome-text (list-ref r 3) (list-ref r 4)))))
                (else (format port "><error message=\"the file did not run to its end\">~a</error></testcase>~%"
                              (xml-escape (list-ref r 4))))))
            results)
           (format port "  </testsuite>~%")))
       by-file)
      (format port "</testsuites>~%"))))

(define* (run-tests paths make-environment #:key junit (load-file load))
  "Run every *-test.scm under PATHS, each loaded in a module MAKE-ENVIRONMENT
returns; print each failure (file:line, the check's name, expected and
actual) and then `N passed, N failed'. With JUNIT, also write a JUnit XML
report there. LOAD-FILE loads one file (the host's compiles it quietly).
Games made while they run are strict (strict-games): an entity key that is
a slip of an engine key is an error. Returns the exit status: 0 only when
nothing failed."
  (let ((problem (and junit (junit-target-problem junit))))
    (when problem
      (scm-error 'misc-error "downstroke test" "--junit ~s: ~a" (list junit problem) #f)))
  (let* ((missing (remove file-exists? paths))
         (found (test-files paths))
         ;; A FIFO would block the run, a device be read without end.
         (files (filter (lambda (f) (not (input-file-problem f))) found))
         (by-file (append
                   (map (lambda (p) (cons p (list (list p "(no such file or folder)" 'error #f
                                                         (format #f "no such file or folder: ~a~%" p) #f))))
                        missing)
                   (filter-map (lambda (f)
                                 (let ((problem (input-file-problem f)))
                                   (and problem
                                        (cons f (list (list f "(the file was not run)" 'error #f
                                                            (string-append problem "\n") #f))))))
                               found)
                   ;; Games made in tests are strict: a misspelt entity key
                   ;; fails the test that runs it (make-game strict?: #f opts out).
                   (parameterize ((strict-games #t))
                     (map (lambda (f) (cons f (run-file f make-environment load-file))) files))))
         (all (append-map cdr by-file))
         (passed (count (lambda (r) (eq? (caddr r) 'pass)) all))
         (failed (- (length all) passed)))
    (when (null? files)
      (format (current-error-port) "downstroke test: no *-test.scm under ~a~%" (string-join paths " ")))
    (for-each (lambda (r) (unless (eq? (caddr r) 'pass) (report-failure (current-output-port) r))) all)
    (when junit (write-junit junit by-file))
    (format #t "~a passed, ~a failed~%" passed failed)
    (if (zero? failed) 0 1)))
