;; SPDX-License-Identifier: MIT
;;; (downstroke testing) — testing a game like code: `downstroke test' runs
;;; every *-test.scm under the paths it is given, each in a script's own
;;; environment with SRFI-64, and says what failed, where, expected what.
(define-module (downstroke testing)
  #:use-module (downstroke error-text)
  #:use-module (srfi srfi-1)
  #:use-module (srfi srfi-64)
  #:use-module (ice-9 ftw)
  #:use-module (ice-9 format)
  #:use-module (downstroke engine)
  #:use-module (downstroke render)
  #:use-module (downstroke native)
  #:use-module ((downstroke game) #:select (game-input-script-set! game-display current-game))
  #:use-module ((downstroke input) #:select (check-input-script))
  #:use-module ((downstroke drawing) #:select (draw-game!))
  #:use-module (downstroke tool-files)
  #:use-module ((ice-9 textual-ports) #:select (get-string-n))
  #:re-export (record-input read-input-script)
  #:export (test-files run-tests run-test-file play check-frame))

;;; ---------------------------------------------------------------- games in tests

(define* (play game #:key frames (input #f))
  "Run GAME headless up to frame FRAMES (as game-run! counts: from where it
stopped), with INPUT as its input script when given (a list, or the file
record-input wrote), and return it."
  (when input
    (let ((script (if (string? input) (read-input-script input) input)))
      (check-input-script "play" script)
      (game-input-script-set! game script)))
  (parameterize ((display-mode 'headless))
    (game-run! game #:frames frames))
  game)

(define (sibling file suffix)
  ;; expected.png → expected.actual.png; the extension is the file name's
  ;; own: a dot in a folder's name (v1.2/expected) or a name's leading dot
  ;; (.expected) is no extension, and SUFFIX then goes at the end.
  (let* ((slash (string-rindex file #\/))
         (name-start (if slash (+ slash 1) 0))
         (dot (string-rindex file #\. name-start)))
    (if (and dot (> dot name-start))
        (string-append (substring file 0 dot) suffix (substring file dot))
        (string-append file suffix))))

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
         (draw-game! game)
         (let* ((actual (sibling file ".actual")) (diff (sibling file ".diff"))
                (r (%display-compare-png (game-display game) file actual diff)))
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
                                     (lambda (name stat acc) acc)
                                     ;; A test file that cannot be looked at is still named: it fails.
                                     (lambda (name stat errno acc) (if (test-file? (basename name)) (cons name acc) acc))
                                     '() path)
                   string<?))
            (else (list path))))
    paths)))

;;; One result: (file name kind expected actual line), kind pass, fail or
;;; error. EXPECTED and ACTUAL are as `write' prints them (a string), ACTUAL
;;; (raised . the error's text) for a check that raised: a file runs in a
;;; child process, which sends its results to the runner as text.

;;; How long one test file may run, by default (downstroke test --timeout S):
;;; long enough for a file that plays several games to their ends on a slow
;;; machine, short enough that a file that loops is noticed in a CI run.
(define default-test-timeout 60)

;;; How long a file that ran out of time has, once told, to say the frame its
;;; game reached and end, before its process group is killed: a file stuck in
;;; native code cannot answer.
(define timeout-grace-seconds 1)

;;; How often the runner looks whether a file's process has ended.
(define wait-poll-microseconds 20000)

;;; The most of a value a FAIL line shows: a value as long as a screenful
;;; says what it is, and one failed check once printed a 13.8 MB line.
(define max-shown-chars 400)

(define (shown text)
  ;; TEXT, or its first max-shown-chars characters and how long it was.
  (if (<= (string-length text) max-shown-chars)
      text
      (format #f "~a… (~a characters in all)" (substring text 0 max-shown-chars) (string-length text))))

(define (written value) (shown (call-with-output-string (lambda (port) (write value port)))))

(define (asserted form)
  ;; The expression a (test-assert [name] expr) form checks.
  (if (and (pair? form) (eq? (car form) 'test-assert) (list? form)) (last form) form))

(define (check-record r)
  ;; A finished check as the child sends it: (check name kind expected actual line).
  (let ((kind (test-result-kind r)))
    (list 'check (or (test-runner-test-name r) "")
          (if (memq kind '(pass xfail skip)) 'pass 'fail)
          ;; test-assert has no expected value: (assert . its expression).
          (if (assq 'expected-value (test-result-alist r))
              (written (test-result-ref r 'expected-value))
              (cons 'assert (written (asserted (test-result-ref r 'source-form)))))
          ;; A check that raised: (raised . the error, as it would print).
          (let ((err (test-result-ref r 'actual-error)))
            (if err
                (cons 'raised
                      (shown
                       (call-with-output-string
                         (lambda (port)
                           (if (pair? err) (print-error port (car err) (cdr err)) (write err port))))))
                (written (test-result-ref r 'actual-value))))
          (test-result-ref r 'source-line))))

(define (send port record)
  ;; Each record on its own line, out at once: what was sent is kept
  ;; whatever ends the process after it.
  (write record port)
  (newline port)
  (force-output port))

(define (run-test-file file make-environment load-file results)
  "The child's side of `downstroke test': load FILE (in a module
MAKE-ENVIRONMENT returns, with LOAD-FILE) and append each check's result to
the file RESULTS as it ends, then (end). A file that does not load is one
error naming it. Told to stop (SIGTERM), it sends the frame its game reached
and exits. Returns 0."
  (let ((port (open-file results "a"))
        (out (current-output-port)))
    (set-port-encoding! port "UTF-8")
    (sigaction SIGTERM
      (lambda (sig)
        (let ((game (current-game)))
          (send port (list 'timeout (and game (game-frame game))))
          (unless (zero? (port-column out)) (newline out))
          (force-output out)
          (force-output (current-output-port))
          (force-output (current-error-port))
          (primitive-_exit 124))))
    (let ((runner (test-runner-null)))
      (test-runner-on-test-end! runner (lambda (r) (send port (check-record r))))
      (test-runner-factory (lambda () runner)))
    (test-runner-current #f)
    (catch #t
      (lambda ()
        ;; Games made in tests are strict: a misspelt entity key
        ;; fails the test that runs it (make-game strict?: #f opts out).
        (parameterize ((strict-games #t))
          (save-module-excursion
           (lambda ()
             (set-current-module (make-environment))
             (load-file (canonicalize-path file))))))
      (lambda (key . args)
        (send port (list 'check "(the file did not run to its end)" 'error #f
                         (error-text key args)
                         #f))))
    ;; The runner's count line follows: a last line the file left open
    ;; would run into it.
    (unless (zero? (port-column out)) (newline out))
    (send port '(end))
    (close-port port)
    0))

(define (read-records file)
  ;; The records a child sent, up to the first it did not finish writing.
  (call-with-input-file file
    (lambda (port)
      (set-port-encoding! port "UTF-8")
      (let loop ((acc '()))
        (let ((r (false-if-exception (read port))))
          (if (pair? r) (loop (cons r acc)) (reverse acc)))))))

(define (kill-group pid sig)
  ;; The file's process group (a game it started too), or the process alone
  ;; if it has not made its group yet.
  (catch 'system-error
    (lambda () (kill (- pid) sig))
    (lambda _ (false-if-exception (kill pid sig)))))

(define (wait-until pid deadline)
  ;; The process's status, or #f when DEADLINE (internal real time) came first.
  (let loop ()
    (let ((r (waitpid pid WNOHANG)))
      (cond ((not (zero? (car r))) (cdr r))
            ((>= (get-internal-real-time) deadline) #f)
            (else (usleep wait-poll-microseconds) (loop))))))

(define (seconds->ticks s) (inexact->exact (round (* s internal-time-units-per-second))))

(define (results-file)
  ;; A new empty file for a child's results, or the reason there is none.
  (let ((template (string-append (or (getenv "TMPDIR") "/tmp") "/downstroke-test-XXXXXX")))
    (catch 'system-error
      (lambda () (let* ((port (mkstemp template)) (name (port-filename port))) (close-port port) name))
      (lambda (key . args)
        (cons 'error (format #f "cannot make a file for its results like ~a: ~a"
                             template (strerror (system-error-errno (cons key args)))))))))

(define (run-child file child-command timeout)
  ;; FILE's results, run by the command CHILD-COMMAND makes of it and a file
  ;; for its results; a child that did not end normally adds an error.
  (let ((results (results-file)))
    (if (pair? results)
        (list (list file "(the file did not run)" 'error #f (cdr results) #f))
        (run-child-with file child-command timeout results))))

(define (run-child-with file child-command timeout results)
  ;; The same, with its results file RESULTS made.
  (force-output (current-output-port))
  (force-output (current-error-port))
  (let* ((argv (child-command file results))
         (pid (primitive-fork)))
    (when (zero? pid)
      ;; The child: a process group of its own, so that a timeout ends what
      ;; it started too.
      (catch #t
        (lambda () (setpgid 0 0) (apply execl (car argv) argv))
        (lambda _ (primitive-_exit 127))))
    (let* ((status (wait-until pid (+ (get-internal-real-time) (seconds->ticks timeout))))
           (ran-out? (not status))
           (status (or status
                       (begin (kill-group pid SIGTERM)
                              (wait-until pid (+ (get-internal-real-time) (seconds->ticks timeout-grace-seconds))))
                       (begin (kill-group pid SIGKILL) (cdr (waitpid pid)))))
           (records (read-records results))
           (checks (filter-map (lambda (r) (and (eq? (car r) 'check) (cons file (cdr r)))) records))
           (frame (let ((r (assq 'timeout records))) (and r (cadr r)))))
      (delete-file results)
      (if (and (assq 'end records) (not ran-out?))
          checks
          (append checks
                  (list (list file (if ran-out? "(the file ran out of time)" "(the file did not run to its end)")
                              'error #f
                              (cond (ran-out?
                                     (format #f "it ran past the time limit of ~a s~a and was ended" timeout
                                             (if frame (format #f " (its game at frame ~a)" frame) "")))
                                    ((status:exit-val status)
                                     (format #f "it exited with status ~a before its end" (status:exit-val status)))
                                    (else
                                     (format #f "it was ended by signal ~a before its end" (status:term-sig status))))
                              #f)))))))

(define (raised? actual) (and (pair? actual) (eq? (car actual) 'raised)))

(define (one-line text)
  ;; An error's text on one line: its lines joined, the last newline gone.
  (string-join (remove string-null? (map string-trim-both (string-split text #\newline))) " "))

(define (outcome-text expected actual)
  ;; "expected 5, actual 4", or "expected 5, raised: In procedure car: …";
  ;; for test-assert, "assertion failed: (= 1 2)" or "… raised: …".
  (cond ((and (pair? expected) (eq? (car expected) 'assert))
         (if (raised? actual)
             (format #f "assertion ~a raised: ~a" (cdr expected) (one-line (cdr actual)))
             (format #f "assertion failed: ~a" (cdr expected))))
        ((raised? actual) (format #f "expected ~a, raised: ~a" expected (one-line (cdr actual))))
        (else (format #f "expected ~a, actual ~a" expected actual))))

(define (report-failure port r)
  ;; One line a failed check: where, its name, what was expected and what came.
  (apply (lambda (file name kind expected actual line)
           (if (eq? kind 'error)
               (format port "FAIL ~a: ~a: ~a~%" file name (one-line actual))
               (format port "FAIL ~a:~a: ~a: ~a~%" file (or line "?") name (outcome-text expected actual))))
         r))

(define (xml-escape s)
  ;; XML 1.0 allows no control character but tab, newline and return, not
  ;; even as a reference: the others (from a test's name or a value) are
  ;; written as \xN; so the report still parses.
  (string-concatenate
   (map (lambda (c)
          (case c
            ((#\<) "&lt;") ((#\>) "&gt;") ((#\&) "&amp;") ((#\") "&quot;")
            ((#\tab #\newline #\return) (string c))
            (else (if (or (char<? c #\space) (char=? c #\delete))
                      (format #f "\\x~x;" (char->integer c))
                      (string c)))))
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

(define (count-text results)
  ;; "3 checks", "1 check, 1 failed", "0 checks".
  (let ((n (length results)) (failed (count (lambda (r) (not (eq? (caddr r) 'pass))) results)))
    (format #f "~a check~a~a" n (if (= n 1) "" "s") (if (zero? failed) "" (format #f ", ~a failed" failed)))))

(define* (run-tests paths child-command #:key junit timeout)
  "Run every *-test.scm under PATHS, each in a child process of its own
(CHILD-COMMAND, given the file and a file for its results, makes its
command line: see run-test-file) for at most TIMEOUT seconds (#f: 60).
Print, file by
file as each ends, each failure (file:line, the check's name, expected and
actual) and the file with its count of checks; then `N passed, N failed'. A
file that ran out of time, or ended before its end, is a failure saying so;
a test file that is not a regular file (a FIFO, a device) is not run and is
a failure saying what it is. With JUNIT, also write a JUnit XML report
there, refused before any test runs when that file may not be written.
Returns the exit status: 0 only when a file was found and nothing failed."
  (let ((problem (and junit (junit-target-problem junit))))
    (when problem
      (scm-error 'misc-error "downstroke test" "--junit ~s: ~a" (list junit problem) #f)))
  (let* ((missing (remove file-exists? paths))
         (found (test-files paths))
         ;; A FIFO would block the run, a device be read without end.
         (files (filter (lambda (f) (not (input-file-problem f))) found))
         (report (lambda (file results)
                   (for-each (lambda (r) (unless (eq? (caddr r) 'pass) (report-failure (current-output-port) r)))
                             results)
                   (format #t "~a: ~a~%" file (count-text results))
                   (force-output (current-output-port))
                   (cons file results)))
         (by-file (append
                   (map (lambda (p) (report p (list (list p "(no such file or folder)" 'error #f
                                                          (format #f "no such file or folder: ~a~%" p) #f))))
                        missing)
                   (filter-map (lambda (f)
                                 (let ((problem (input-file-problem f)))
                                   (and problem
                                        (report f (list (list f "(the file was not run)" 'error #f
                                                              (string-append problem "\n") #f))))))
                               found)
                   (map (lambda (f) (report f (run-child f child-command (or timeout default-test-timeout)))) files)))
         (all (append-map cdr by-file))
         (passed (count (lambda (r) (eq? (caddr r) 'pass)) all))
         (failed (- (length all) passed)))
    (when (null? found)
      ;; A failure: a CI job pointed at the wrong folder must not pass.
      (format (current-error-port) "downstroke test: no *-test.scm under ~a: nothing was tested~%"
              (string-join paths " ")))
    (when junit (write-junit junit by-file))
    (format #t "~a passed, ~a failed~%" passed failed)
    (if (and (zero? failed) (pair? found)) 0 1)))
