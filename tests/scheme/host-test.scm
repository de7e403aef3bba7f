;; SPDX-License-Identifier: MIT
;;; The `downstroke' executable itself: its options, its quiet compiling of
;;; edited scripts, and how an uncaught error in a script reads.
(use-modules (srfi srfi-64) (ice-9 textual-ports) (ice-9 ftw) (srfi srfi-1))

(load "support.scm")

(define host (readlink "/proc/self/exe"))
(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-host-XXXXXX")))
;; A cache of its own, so that the first run of every script here compiles.
(define cache (string-append dir "/cache"))

(define (quoted s) (string-append "'" s "'"))

(define (run . argv)
  ;; (exit-status stdout stderr) of the host run with ARGV.
  (apply run-in "." argv))

(define (run-in where . argv)
  ;; The same, run in the folder WHERE.
  (apply run-in-locale #f where argv))

(define (run-in-locale locale where . argv)
  ;; The same, with LOCALE the only locale in the environment: a name, or
  ;; 'unset for none at all (#f: the environment as it is).
  (let ((out (string-append dir "/out")) (err (string-append dir "/err"))
        (environment (cond ((eq? locale 'unset) "env -u LANG -u LC_CTYPE -u LC_ALL ")
                           (locale (string-append "env -u LANG -u LC_CTYPE LC_ALL=" locale " "))
                           (else ""))))
    (let ((status (system (string-append "cd " (quoted where) " && " environment
                                         "XDG_CACHE_HOME=" (quoted cache) " "
                                         (string-join (map quoted (cons host argv)) " ")
                                         " >" (quoted out) " 2>" (quoted err)))))
      (list (status:exit-val status)
            (call-with-input-file out get-string-all)
            (call-with-input-file err get-string-all)))))

(define (write-script name text)
  (let ((file (string-append dir "/" name)))
    (call-with-output-file file (lambda (p) (display text p)))
    file))

;;; ---------------------------------------------------------------- options
(test-begin "host")
(define help (run "--help"))
(test-equal "--help exits 0" 0 (first help))
(test-equal "… printing nothing on stderr" "" (third help))
(for-each
 (lambda (option)
   (test-assert (string-append "--help lists " option) (string-contains (second help) option)))
 '("--window" "--scale" "--debug" "--watch" "--no-watch" "--capture" "--repl-server" "--repl-port" "--repl-timeout"
   "--frames N" "--timeout S" "--no-auto-compile" "--version" "--help" "new DIR" "test [--junit FILE]" "DOWNSTROKE_BACKTRACE=full"))
(test-equal "--version prints the project's version" '(0 "downstroke 0.1.0\n" "") (run "--version"))
(test-equal "an unknown option is refused with the usage, on stderr" '(2 "")
  (let ((r (run "--no-such-option"))) (list (first r) (second r))))

;;; ---------------------------------------------------------------- compiling quietly
(define hello (write-script "hello.scm" "(display \"hello\\n\")\n"))
(test-equal "a script's first run prints only its own output" '(0 "hello\n" "") (run hello))
(write-script "hello.scm" "(display \"edited\\n\")\n")
(test-equal "… and so does its first run after an edit" '(0 "edited\n" "") (run hello))
(test-equal "… and the run after that" '(0 "edited\n" "") (run hello))
(test-equal "--no-auto-compile runs the script as it is" '(0 "edited\n" "") (run "--no-auto-compile" hello))
(write-script "hello.scm" "(display \"interpreted\\n\")\n")
(test-equal "… interpreted, not from the stale cache" '(0 "interpreted\n" "") (run "--no-auto-compile" hello))
(define unbound (write-script "unbound.scm" "(define (f) (no-such-procedure 1))\n(display \"ran\\n\")\n"))
(test-equal "a real compile warning about the script is kept, alone, naming file:line:column"
  (list 0 "ran\n" (string-append ";;; " unbound ":1:13: warning: possibly unbound variable `no-such-procedure'\n"))
  (run unbound))
(mkdir (string-append dir "/loads"))
(write-script "loads/game.scm"
              (string-append "(define (new-game) 'a-game)\n(define-values (lives score) (values 3 0))\n"
                             "(define-record-type <ship> (make-ship x) ship? (x ship-x ship-x-set!))\n"
                             "(load \"more/level.scm\")\n"))
(mkdir (string-append dir "/loads/more"))
(write-script "loads/more/level.scm" "(define level-one '(1 2 3))\n")
(define loader
  (write-script "loads/loader.scm"
                (string-append "(use-modules (srfi srfi-9))\n(load \"game.scm\")\n"
                               "(write (list (new-game) lives score level-one))\n"
                               ;; Never called: a record's constructor and accessors are macros,
                               ;; which a compiled call cannot meet before the load.
                               "(define (never) (ship-x-set! (make-ship 1) 2) (ship? 3))\n"
                               "(newline)\n(define (later) (lvel-one))\n")))
(test-equal "a script that loads a game file is not warned of the names it defines, and files it loads; a real one still is"
  (list 0 "(a-game 3 0 (1 2 3))\n"
        (string-append ";;; " loader ":6:17: warning: possibly unbound variable `lvel-one'\n"))
  (run loader))

(define unbalanced (write-script "unbalanced.scm" "(display \"read\\n\")\n(define (f x) (+ x 1)\n"))
(test-equal "a script that does not compile reports its error once, as the run raises it"
  (list 1 "read\n" (string-append unbalanced ":3:1: unexpected end of input while searching for: )\n"
                                 "(the whole backtrace: DOWNSTROKE_BACKTRACE=full)\n"))
  (run unbalanced))

(define dotted (write-script "dotted.scm" "(display \"read\\n\")\n(define shot\n  (list #:aim (1 . 0)))\n"))
(define dotted-error
  (list 1 "read\n"
        (string-append "Syntax error:\n" dotted ":3:14: a dotted pair is not code (quote it to make it data: '(1 . 0)) in form (1 . 0)\n"
                       "(the whole backtrace: DOWNSTROKE_BACKTRACE=full)\n")))
(test-equal "a dotted pair in code is a syntax error naming its file, line and column, and what to write"
  dotted-error (run dotted))
(test-equal "… run interpreted too" dotted-error (run "--no-auto-compile" dotted))
(test-equal "… and in a file the script loads, naming that file"
  (list 1 "read\n" (third dotted-error))
  (run (write-script "loads-dotted.scm" "(load \"dotted.scm\")\n")))

;;; ---------------------------------------------------------------- uncaught errors
(define failing
  (write-script "failing.scm"
                "(display \"before\\n\")\n(define (go)\n  (let ((s (car 5)))\n    s))\n(go)\n(display \"after\\n\")\n"))
(define failure (run failing))
(define error-lines (string-split (third failure) #\newline))
(test-equal "a script's uncaught error is a non-zero exit" 1 (first failure))
(test-equal "… after the output it made" "before\n" (second failure))
(test-equal "… the first line of stderr is the error"
  "In procedure car: Wrong type argument in position 1 (expecting pair): 5" (first error-lines))
(test-equal "… then the script's own calls, innermost first, then how to see everything"
  (list (string-append "  at " failing ":3: (go)") (string-append "  at " failing ":5")
        "(the whole backtrace: DOWNSTROKE_BACKTRACE=full)" "")
  (cdr error-lines))
(test-assert "… with no boot-9 frame"
  (not (string-contains (third failure) "boot-9")))
(test-assert "DOWNSTROKE_BACKTRACE=full prints the whole backtrace after the error"
  (let* ((full (begin (setenv "DOWNSTROKE_BACKTRACE" "full") (run failing)))
         (text (third full)))
    (unsetenv "DOWNSTROKE_BACKTRACE")
    (and (string-prefix? "In procedure car:" text) (string-contains text "boot-9"))))
(test-equal "an engine procedure's refusal names it, first"
  "In procedure step-scene: scene: expected a scene (make-scene), got 5"
  (car (string-split (third (run (write-script "engine-error.scm" "(step-scene 5 16)\n(newline)\n")))
                     #\newline)))
(test-equal "a missing script is an error naming it, status 1"
  (list 1 "" (string-append "In procedure open-file: No such file or directory: \"" dir "/no-such.scm\"\n"
                            "(the whole backtrace: DOWNSTROKE_BACKTRACE=full)\n"))
  (run (string-append dir "/no-such.scm")))
(test-equal "a script sees SRFI-1 and SRFI-11 without importing them, as the docs' examples assume"
  '(0 "(#:id b #:x 2) 3 (b)\n" "")
  (run (write-script "plain.scm"
                     (string-append
                      "(define es '((#:id a #:x 1) (#:id b #:x 2)))\n"
                      "(let-values (((x y) (values 1 2)))\n"
                      "  (format #t \"~s ~s ~s~%\" (find (lambda (e) (eq? (entity-ref e #:id) 'b)) es) (+ x y)\n"
                      "          (filter-map (lambda (e) (and (> (entity-ref e #:x) 1) (entity-ref e #:id))) es)))\n"))))
(test-equal "an option only a window has is refused without --window, before the script runs: status 2, the option named"
  '((2 "" "downstroke: --record applies only with --window: a headless run's input is its input-script:\n")
    (2 "" "downstroke: --frame-log applies only with --window\n")
    (2 "" "downstroke: --scale applies only with --window\n")
    (2 "" "downstroke: --fullscreen applies only with --window\n"))
  (let ((script (write-script "never-run.scm" "(display \"ran\")\n")))
    (map (lambda (opts) (apply run (append opts (list script))))
         '(("--record" "r.scm") ("--frame-log" "f.log") ("--scale" "2") ("--fullscreen")))))
;;; ---------------------------------------------------------------- downstroke test
(define suite-dir (string-append dir "/suite"))
(mkdir suite-dir)
(mkdir (string-append suite-dir "/more"))
(mkdir (string-append dir "/raises"))
(write-script "suite/good-test.scm"
              "(test-begin \"good\")\n(test-equal \"adds\" 4 (+ 2 2))\n(test-equal \"sees srfi-1\" 2 (find even? '(1 2 3)))\n(test-assert \"sees the engine\" (entity-ref '(#:x 1) #:x))\n(test-end \"good\")\n")
(write-script "suite/more/bad-test.scm"
              "(test-begin \"bad\")\n(test-equal \"wrong sum\" 5 (+ 2 2))\n(test-end \"bad\")\n")
(write-script "suite/helpers.scm" "(error \"never loaded: not a *-test.scm\")\n")
(test-equal "downstroke test PATH: a passing file, exit 0, the file named with its count"
  (list 0 (string-append suite-dir "/good-test.scm: 3 checks\n3 passed, 0 failed\n"))
  (list-head (run "test" (string-append suite-dir "/good-test.scm")) 2))
(define suite-run (run "test" "--junit" (string-append dir "/report.xml") suite-dir))
(test-equal "a failing check: exit 1, file:line, expected, actual, then the count"
  (list 1 (string-append suite-dir "/good-test.scm: 3 checks\n"
                         "FAIL " suite-dir "/more/bad-test.scm:2: wrong sum: expected 5, actual 4\n"
                         suite-dir "/more/bad-test.scm: 1 check, 1 failed\n"
                         "3 passed, 1 failed\n"))
  (list-head suite-run 2))
(test-assert "--junit writes a JUnit report naming the failure"
  (let ((xml (call-with-input-file (string-append dir "/report.xml") get-string-all)))
    (and (string-contains xml "<testsuite name=\"") (string-contains xml "failures=\"1\"")
         (string-contains xml "<failure message=\"line 2\">expected 5, actual 4</failure>"))))
(mkdir (string-append dir "/controls"))
(write-script "controls/ctl-test.scm"
              "(test-begin \"c\")\n(test-equal \"bell\\a and escape\\x1b\" \"\\x01\" \"ok\")\n(test-end \"c\")\n")
(run "test" "--junit" (string-append dir "/controls.xml") (string-append dir "/controls"))
(test-equal "control characters in a JUnit report are written as \\xN;, so the report parses as XML"
  '("bell\\x7; and escape\\x1b;" "expected \"\\x01\", actual \"ok\"")
  (let* ((sxpath (@ (sxml xpath) sxpath))
         (doc ((@ (sxml simple) xml->sxml) (call-with-input-file (string-append dir "/controls.xml") get-string-all)))
         (tc (car ((sxpath '(// testcase)) doc))))
    (list (car ((sxpath '(@ name *text*)) tc)) (car ((sxpath '(failure *text*)) tc)))))
;; --junit with the report's name forgotten takes the next argument: a test
;; file, or the game. It is refused, before any test runs, and left as it was.
(define good-text (call-with-input-file (string-append suite-dir "/good-test.scm") get-string-all))
(test-equal "--junit onto a file that is not a JUnit report: refused, exit 2, naming it and why"
  (list 2 "" (string-append "downstroke test: --junit \"" suite-dir "/good-test.scm\": it exists and is not a JUnit report (it does not start with <?xml and hold <testsuites>), so it is not written over\n"))
  (run "test" "--junit" (string-append suite-dir "/good-test.scm") suite-dir))
(test-equal "… and the file is unchanged" good-text
  (call-with-input-file (string-append suite-dir "/good-test.scm") get-string-all))
(test-equal "--junit onto an earlier report replaces it" 1
  (first (run "test" "--junit" (string-append dir "/report.xml") suite-dir)))
(test-equal "… whole, and leaves no temporary file beside it"
  '("report.xml")
  (scandir dir (lambda (n) (string-prefix? "report.xml" n))))
;; Guile has no mkfifo: mkfifo(1) makes them.
(define (make-fifo path) (system* "mkfifo" path))
(make-fifo (string-append dir "/junit-fifo"))
(test-equal "--junit onto a FIFO: refused, never blocking"
  (list 2 "" (string-append "downstroke test: --junit \"" dir "/junit-fifo\": it is a FIFO, not a regular file\n"))
  (run "test" "--junit" (string-append dir "/junit-fifo") suite-dir))
(test-equal "--junit onto a device: refused"
  (list 2 "" "downstroke test: --junit \"/dev/null\": it is a character device, not a regular file\n")
  (run "test" "--junit" "/dev/null" suite-dir))
(test-equal "--junit into a folder that does not exist: refused before any test runs"
  (list 2 "" (string-append "downstroke test: --junit \"" dir "/no-such-dir/r.xml\": its folder \"" dir "/no-such-dir\" does not exist\n"))
  (run "test" "--junit" (string-append dir "/no-such-dir/r.xml") suite-dir))
(mkdir (string-append dir "/fifos"))
(make-fifo (string-append dir "/fifos/pipe-test.scm"))
(test-equal "a *-test.scm that is a FIFO is a failure saying so, not a run that blocks"
  (list 1 (string-append "FAIL " dir "/fifos/pipe-test.scm: (the file was not run): it is a FIFO, not a regular file\n"
                         dir "/fifos/pipe-test.scm: 1 check, 1 failed\n"
                         "0 passed, 1 failed\n"))
  (list-head (run "test" (string-append dir "/fifos")) 2))
(mkdir (string-append dir "/ünï"))
(write-script "ünï/ünï-test.scm" "(test-begin \"u\")\n(test-equal 1 1)\n(test-end \"u\")\n")
(for-each
 (lambda (locale)
   (test-equal (format #f "a test file with a non-ASCII name runs and is named (locale ~a)" locale)
     (list 0 (string-append dir "/ünï/ünï-test.scm: 1 check\n1 passed, 0 failed\n"))
     (list-head (run-in-locale locale "." "test" (string-append dir "/ünï")) 2)))
 '(unset "C"))
(mkdir (string-append dir "/asserts"))
(write-script "asserts/assert-test.scm"
              "(test-begin \"a\")\n(test-assert \"one is two\" (= 1 2))\n(test-assert \"car of 5\" (car 5))\n(test-equal \"long\" (make-string 1000 #\\a) \"b\")\n(test-end \"a\")\n")
(test-equal "a failed test-assert says so with its expression; a long value is cut, saying how long it was"
  (list 1 (string-append
           "FAIL " dir "/asserts/assert-test.scm:2: one is two: assertion failed: (= 1 2)\n"
           "FAIL " dir "/asserts/assert-test.scm:3: car of 5: assertion (car 5) raised: In procedure car: Wrong type argument in position 1 (expecting pair): 5\n"
           "FAIL " dir "/asserts/assert-test.scm:4: long: expected \"" (make-string 399 #\a) "… (1002 characters in all), actual \"b\"\n"
           dir "/asserts/assert-test.scm: 3 checks, 3 failed\n"
           "0 passed, 3 failed\n"))
  (list-head (run "test" (string-append dir "/asserts")) 2))
(write-script "raises/raises-test.scm" "(test-begin \"raises\")\n(test-equal \"car of 5\" 1 (car 5))\n(test-end \"raises\")\n")
(test-equal "a check that raises: one line, the error on it"
  (list 1 (string-append "FAIL " dir "/raises/raises-test.scm:2: car of 5: expected 1, raised: "
                         "In procedure car: Wrong type argument in position 1 (expecting pair): 5\n"
                         dir "/raises/raises-test.scm: 1 check, 1 failed\n0 passed, 1 failed\n"))
  (list-head (run "test" (string-append dir "/raises")) 2))
(mkdir (string-append dir "/raise42"))
(write-script "raise42/raise-test.scm"
              "(test-begin \"r\")\n(test-assert \"raises 42\" (raise 42))\n(test-equal \"guarded\" '(caught 7) (guard (e ((number? e) (list 'caught e))) (raise 7)))\n(raise 'oops)\n(test-end \"r\")\n")
(test-equal "scripts get SRFI-34 raise: a raised non-condition is reported as an error, not a signal, and guard catches it"
  (list 1 (string-append "FAIL " dir "/raise42/raise-test.scm:2: raises 42: assertion (raise 42) raised: uncaught raise of a non-condition: 42\n"
                         "FAIL " dir "/raise42/raise-test.scm: (the file did not run to its end): uncaught raise of a non-condition: oops\n"
                         dir "/raise42/raise-test.scm: 3 checks, 2 failed\n1 passed, 2 failed\n"))
  (list-head (run "test" (string-append dir "/raise42")) 2))
(test-equal "a script's uncaught (raise '(1 2)) is reported as an error: exit 1, the value written"
  (list 1 "uncaught raise of a non-condition: (1 2)\n")
  (let ((r (run (write-script "raise42/raises.scm" "(raise (list 1 2))\n"))))
    (list (first r) (string-append (car (string-split (third r) #\newline)) "\n"))))
(mkdir (string-append dir "/restored"))
(mkdir (string-append dir "/restored/tests"))
(define (restore-old! name text)
  ;; NAME written with TEXT and dated 2020, as cp -p or tar leaves an older copy.
  (let ((file (write-script name text)))
    (utime file 1577836800 1577836800)
    file))
(define (restored-run answer sum)
  (restore-old! "restored/game.scm" (format #f "(define answer ~a)\n" answer))
  (restore-old! "restored/tests/s-test.scm"
                (format #f "(load \"../game.scm\")\n(test-begin \"s\")\n(test-equal \"answer\" 1 answer)\n(test-equal \"sum\" 2 ~a)\n(test-end \"s\")\n" sum))
  (list-head (run "test" (string-append dir "/restored")) 2))
(test-equal "a test file and the game it loads, restored with an older date, run as they now read, not their older compiled copies"
  (list (list 0 (string-append dir "/restored/tests/s-test.scm: 2 checks\n2 passed, 0 failed\n"))
        (list 1 (string-append "FAIL " dir "/restored/tests/s-test.scm:3: answer: expected 1, actual 2\n"
                               "FAIL " dir "/restored/tests/s-test.scm:4: sum: expected 2, actual 3\n"
                               dir "/restored/tests/s-test.scm: 2 checks, 2 failed\n0 passed, 2 failed\n")))
  (list (restored-run 1 "(+ 1 1)") (restored-run 2 "(+ 1 2)")))
(test-equal "so does a script"
  '("1\n" "2\n")
  (map (lambda (n)
         (second (run (restore-old! "restored/show.scm" (format #f "(display ~a)\n(newline)\n" n)))))
       '(1 2)))
(mkdir (string-append dir "/no-tests"))
(write-script "no-tests/helpers.scm" "1\n")
(test-equal "a run that finds no *-test.scm fails: exit 1, said on stderr"
  (list 1 "0 passed, 0 failed\n" (string-append "downstroke test: no *-test.scm under " dir "/no-tests: nothing was tested\n"))
  (run "test" (string-append dir "/no-tests")))
(mkdir (string-append dir "/open-line"))
(write-script "open-line/open-test.scm" "(test-begin \"o\")\n(test-equal \"one\" 1 1)\n(display \"no newline\")\n(test-end \"o\")\n")
(test-equal "a test file's last line left open does not run into its count line"
  (list 0 (string-append "no newline\n" dir "/open-line/open-test.scm: 1 check\n1 passed, 0 failed\n"))
  (list-head (run "test" (string-append dir "/open-line")) 2))
(write-script "suite/broken-test.scm" "(test-begin \"broken\")\n(car '())\n")
(test-assert "a file that does not load is a failure, named with its error"
  (let ((r (run "test" (string-append suite-dir "/broken-test.scm"))))
    (and (= 1 (first r))
         (string-contains (second r) (string-append "FAIL " suite-dir "/broken-test.scm: (the file did not run to its end)"))
         (string-contains (second r) "0 passed, 1 failed"))))
(test-equal "a path that is not there is a failure" 1 (first (run "test" (string-append dir "/no-such-dir"))))

;;; Each file runs in a child process of its own, for a limited time.
(define alone-dir (string-append dir "/alone"))
(mkdir alone-dir)
(write-script "alone/a-loops-test.scm"
              "(test-begin \"loops\")\n(test-assert \"before the loop\" #t)\n(let loop () (loop))\n")
(write-script "alone/b-game-loops-test.scm"
              "(test-begin \"game\")\n(game-run! (make-game width: 8 height: 8 update: (lambda (game dt) (when (= (game-frame game) 5) (let loop () (loop))))))\n")
(write-script "alone/c-exits-test.scm"
              "(test-begin \"exits\")\n(test-equal \"wrong\" 5 (+ 2 2))\n(primitive-exit 0)\n")
(write-script "alone/d-moves-test.scm"
              (string-append "(test-begin \"moves\")\n(chdir \"/\")\n(set-current-output-port (open-output-string))\n"
                             "(test-end \"moves\")\n"))
(write-script "alone/e-here-test.scm"
              "(test-begin \"here\")\n(test-assert \"starts in the runner's folder\" (file-exists? \"alone/e-here-test.scm\"))\n(test-end \"here\")\n")
(write-script "alone/f-empty-test.scm" "(define nothing-checked #t)\n")
(define alone-run (run-in dir "test" "--timeout" "1" "alone"))
(test-equal "a file that loops is ended at --timeout, named with what it checked, and the next file runs; a game's frame is said; primitive-exit after a failed check fails the run; a chdir or a port set in one file does not reach the next; a file with no checks is named"
  (list 1 (string-append
           "FAIL alone/a-loops-test.scm: (the file ran out of time): it ran past the time limit of 1 s and was ended\n"
           "alone/a-loops-test.scm: 2 checks, 1 failed\n"
           "FAIL alone/b-game-loops-test.scm: (the file ran out of time): it ran past the time limit of 1 s (its game at frame 5) and was ended\n"
           "alone/b-game-loops-test.scm: 1 check, 1 failed\n"
           "FAIL alone/c-exits-test.scm:2: wrong: expected 5, actual 4\n"
           "FAIL alone/c-exits-test.scm: (the file did not run to its end): it exited with status 0 before its end\n"
           "alone/c-exits-test.scm: 2 checks, 2 failed\n"
           "alone/d-moves-test.scm: 0 checks\n"
           "alone/e-here-test.scm: 1 check\n"
           "alone/f-empty-test.scm: 0 checks\n"
           "2 passed, 4 failed\n"))
  (list-head alone-run 2))
(mkdir (string-append dir "/signal"))
(write-script "signal/signal-test.scm" "(test-begin \"signal\")\n(kill (getpid) SIGKILL)\n")
(test-equal "a file killed by a signal is a failure naming the signal"
  (list 1 (string-append "FAIL signal/signal-test.scm: (the file did not run to its end): it was ended by signal 9 before its end\n"
                         "signal/signal-test.scm: 1 check, 1 failed\n0 passed, 1 failed\n"))
  (list-head (run-in dir "test" "signal") 2))
(test-equal "a file whose results have nowhere to go is a failure saying why, and the run goes on"
  (list 1 (string-append "FAIL alone/f-empty-test.scm: (the file did not run): cannot make a file for its results like "
                         "/nonexistent/downstroke-test-XXXXXX: No such file or directory\n"
                         "alone/f-empty-test.scm: 1 check, 1 failed\n0 passed, 1 failed\n"))
  (let ((tmpdir (getenv "TMPDIR")))
    (setenv "TMPDIR" "/nonexistent")
    (let ((r (run-in dir "test" "alone/f-empty-test.scm")))
      (if tmpdir (setenv "TMPDIR" tmpdir) (unsetenv "TMPDIR"))
      (list-head r 2))))
(test-equal "--timeout takes a number of seconds > 0"
  '(2 "" "downstroke: --timeout: expected a number of seconds > 0, got \"0\"\n")
  (run "test" "--timeout" "0" alone-dir))

;;; ---------------------------------------------------------------- downstroke new
(define games (string-append dir "/games"))
(define starter (string-append games "/first"))
(define made (run "new" starter))
(test-equal "downstroke new DIR makes DIR (and its parents), saying what to run next"
  (list 0 (string-append "Made " starter ": 9 files, a game that plays at once.") "")
  (list (first made) (car (string-split (second made) #\newline)) (third made)))
(test-equal "… its files: the game, its map and tileset, sounds, tests, a README"
  '("README.md" "game.scm" "maps/level.tmx" "maps/tiles.png" "maps/tiles.tsx"
    "sounds/coin.wav" "sounds/jump.wav" "tests/game-test.scm")
  (filter (lambda (f) (file-exists? (string-append starter "/" f)))
          '("README.md" "game.scm" "maps/level.tmx" "maps/tiles.png" "maps/tiles.tsx"
            "sounds/coin.wav" "sounds/jump.wav" "tests/game-test.scm")))
(test-assert "… the game is named after its folder"
  (string-contains (call-with-input-file (string-append starter "/game.scm") get-string-all)
                   "first, a Downstroke game."))
(test-equal "the new game plays at once, headless, from any folder: all four coins"
  '(0 "frame 300: 4 coins, the player at (588, 208)\n" "")
  (run (string-append starter "/game.scm")))
(test-equal "… and its own tests pass under downstroke test, run in its folder"
  '(0 "tests/game-test.scm: 7 checks\n7 passed, 0 failed\n" "")
  (run-in starter "test"))
(test-equal "a folder that is not empty is refused, named, and left as it was"
  (list 1 "" (string-append "downstroke new: \"" starter "\" exists and is not empty: give a new folder's name\n")
        '(".gitignore" "README.md" "game.scm" "maps" "sounds" "tests"))
  (append (run "new" starter) (list (cddr (scandir starter)))))
(test-equal "a file is refused, named"
  (list 1 (string-append "downstroke new: \"" starter "/game.scm\" exists and is not a folder\n"))
  (let ((r (run "new" (string-append starter "/game.scm")))) (list (first r) (third r))))
(test-equal "a folder that cannot be made is named, with the reason"
  (list 1 (string-append "downstroke new: cannot make the folder \"" starter "/game.scm\": File exists\n"))
  (let ((r (run "new" (string-append starter "/game.scm/inside")))) (list (first r) (third r))))
(mkdir (string-append games "/empty"))
(test-equal "an empty folder is taken" 0 (first (run "new" (string-append games "/empty"))))
(test-equal "downstroke new with no folder: the usage, status 2" '(2 "" "usage: downstroke new DIR\n")
  (run "new"))
(test-equal "… and with an empty name (never the root folder)" '(2 "" "usage: downstroke new DIR\n")
  (run "new" ""))
(test-equal "missing templates are named"
  (list 1 (string-append "downstroke new: no template folder \"" dir "/none/starter\" (the engine's templates are missing; DOWNSTROKE_TEMPLATE_DIR names another folder)\n"))
  (begin
    (setenv "DOWNSTROKE_TEMPLATE_DIR" (string-append dir "/none"))
    (let ((r (run "new" (string-append games "/second"))))
      (unsetenv "DOWNSTROKE_TEMPLATE_DIR")
      (list (first r) (third r)))))

(mkdir (string-append dir "/piped"))
(mkdir (string-append dir "/piped/starter"))
(call-with-output-file (string-append dir "/piped/starter/game.scm") (lambda (p) (display "(display 1)\n" p)))
(make-fifo (string-append dir "/piped/starter/zz-pipe"))
(test-equal "a FIFO among the templates is refused, named, before anything is written"
  (list 1 (string-append "downstroke new: template file \"" dir "/piped/starter/zz-pipe\": it is a FIFO, not a regular file\n") #f)
  (begin
    (setenv "DOWNSTROKE_TEMPLATE_DIR" (string-append dir "/piped"))
    (let ((r (run "new" (string-append games "/piped"))))
      (unsetenv "DOWNSTROKE_TEMPLATE_DIR")
      (list (first r) (third r) (file-exists? (string-append games "/piped"))))))

;;; Names as the author gives them: in any locale the environment sets (or
;;; none), non-ASCII ones are kept; quotes, backslashes and line breaks in
;;; a game's name still give a game that runs.
(define (game-title-in name)
  ;; The title of the game games/NAME/game.scm makes, as the host runs it.
  (let ((title (write-script (string-append "games/" name "/title.scm")
                             "(load \"game.scm\")\n(write (game-title (new-game)))\n")))
    (second (run-in (dirname title) title))))
(for-each
 (lambda (locale tag)
   (let* ((name (string-append "ünï-" tag)) (game (string-append games "/" name)))
     (test-equal (string-append "with " tag ": downstroke new keeps a non-ASCII name")
       (list 0 (string-append "Made " game ": 9 files, a game that plays at once.") "" #t)
       (let ((r (run-in-locale locale "." "new" game)))
         (list (first r) (car (string-split (second r) #\newline)) (third r)
               (and (member name (scandir games)) #t))))
     (test-equal (string-append "… and its game, in that folder, is found and plays (" tag ")")
       '(0 "frame 300: 4 coins, the player at (588, 208)\n" "")
       (run-in-locale locale "." (string-append game "/game.scm")))
     (test-equal (string-append "… titled with the name (" tag ")")
       (object->string name) (game-title-in name))
     (test-equal (string-append "record-input writes the file it is given (" tag ")")
       '(0 "" "" #t)
       (let ((r (run-in-locale locale game
                               (write-script "record.scm"
                                             "(record-input (make-game) \"rec-ü≥.scm\")\n"))))
         (append r (list (file-exists? (string-append game "/rec-ü≥.scm"))))))
     (test-equal (string-append "… and \"≥\" in an error prints as itself (" tag ")")
       "In procedure make-game: history: expected a count of frames ≥ 0, got -1"
       (car (string-split (third (run-in-locale locale "."
                                                (write-script "history.scm" "(make-game history: -1)\n")))
                          #\newline)))))
 '("C" unset) '("C" "unset"))
(for-each
 (lambda (name)
   (let ((game (string-append games "/" name)))
     (test-equal (string-append "a game named " (object->string name) " is made and runs")
       '(0 0 "frame 300: 4 coins, the player at (588, 208)\n")
       (let* ((made (run "new" game)) (ran (run-in game "--no-auto-compile" "game.scm")))
         (list (first made) (first ran) (second ran))))
     (test-equal "… titled with its name, whole" (object->string name) (game-title-in name))))
 '("say \"hi\"" "back\\slash" "two\nlines"))

(test-equal "(exit 3) in a script is its status, not an error" '(3 "" "")
  (run (write-script "exit.scm" "(exit 3)\n")))

;;; ---------------------------------------------------------------- runs that end
;;; Headless, nothing closes a window: a run that nothing ends is said at
;;; its start, --frames bounds each game-run!, --timeout the whole script.
(define endless
  (write-script "endless.scm"
                "(define g (make-game title: \"shooter\"))\n(game-run! g)\n(format #t \"frame ~a~%\" (game-frame g))\n"))
(define (timed-out file seconds)
  (string-append "downstroke: " file " ran past --timeout " seconds " s: ended (status 124)\n"))
(define endless-warning
  "game-run!: warning: \"shooter\" runs headless until quit, and nothing quits it (no frames:, no quit in its input script): pass frames: N, or run it with downstroke --frames N\n")
(test-equal "a headless game-run! that nothing ends is warned of as it starts; --timeout ends it, status 124"
  (list 124 "" (string-append endless-warning (timed-out endless "1")))
  (run "--timeout" "1" endless))
(test-equal "--frames N ends it after N frames, and it is not warned of"
  '(0 "frame 100\n" "")
  (run "--frames" "100" endless))
(define quitting
  (write-script "quitting.scm"
                (string-append
                 "(define g (make-game input-script: '((0 . (fire)) (30 . (quit)))))\n"
                 "(game-run! g)\n(format #t \"frame ~a~%\" (game-frame g))\n"
                 "(game-run! g frames: 40)\n(format #t \"frame ~a~%\" (game-frame g))\n"
                 "(define h (make-game))\n(game-run! h frames: +inf.0)\n(format #t \"frame ~a~%\" (game-frame h))\n")))
(test-equal "an input script that quits ends the run: no warning"
  '(0 "frame 30\nframe 30\n" "")
  (run (write-script "quits-only.scm"
                     "(define g (make-game input-script: '((30 . (quit)))))\n(game-run! g)\n(format #t \"frame ~a~%\" (game-frame g))\n(game-run! g frames: 40)\n(format #t \"frame ~a~%\" (game-frame g))\n")))
(test-equal "--frames bounds each game-run! from where it starts; frames: and quit still end it sooner"
  '(0 "frame 25\nframe 30\nframe 25\n" "")
  (run "--frames" "25" quitting))
(define spinning (write-script "spinning.scm" "(display \"start\\n\")\n(let loop () (loop))\n"))
(test-equal "--timeout S ends a script that never returns, after its output, with status 124"
  (list 124 "start\n" (timed-out spinning "0.5"))
  (run "--timeout" "0.5" spinning))
(define stubborn
  (write-script "stubborn.scm"
                "(display \"start\\n\")\n(let loop () (catch #t (lambda () (let spin () (spin))) (lambda _ #f)) (loop))\n"))
(test-equal "… and one that catches the ending and runs on is cut off, its output kept"
  (list 124 "start\n" (timed-out stubborn "0.5"))
  (run "--timeout" "0.5" stubborn))
(define socket (string-append dir "/served.sock"))
(test-equal "a served game runs on without the warning (--timeout still ends it), and its socket goes"
  (list 124 "" (timed-out endless "1") #f)
  (append (run "--repl-server" socket "--timeout" "1" endless) (list (file-exists? socket))))
(test-equal "--frames takes a whole number > 0, named"
  '(2 "downstroke: --frames: expected a whole number of frames > 0, got \"0\"")
  (let ((r (run "--frames" "0" endless))) (list (first r) (car (string-split (third r) #\newline)))))
(test-equal "--timeout takes a number of seconds > 0, named"
  '(2 "downstroke: --timeout: expected a number of seconds > 0, got \"soon\"")
  (let ((r (run "--timeout" "soon" endless))) (list (first r) (car (string-split (third r) #\newline)))))
(test-equal "--frames and --timeout need a script"
  '(2 "" "downstroke: --frames and --timeout bound the run of a script: give its FILE.scm\n")
  (run "--frames" "5" "test"))

;;; ---------------------------------------------------------------- what a game carries
;;; Every module loaded is live data each collection marks: the REPL and the
;;; VM's debugging modules are loaded only when a REPL or an error report
;;; needs them (docs/engine.org, "Memory against time").
(define loaded-modules
  (write-script "loaded.scm"
                (string-append
                 "(write (map (lambda (name)\n"
                 "              (let ((m (resolve-module name #f #f #:ensure #f)))\n"
                 "                (and m (module-public-interface m) #t)))\n"
                 "            '((downstroke engine) (system repl repl) (system repl debug)\n"
                 "              (system vm frame) (system vm debug) (downstroke repl-server))))\n")))
(test-equal "a game runs with the engine and without the REPL's or debugger's modules"
  '(0 "(#t #f #f #f #f #f)" "")
  (run "--no-auto-compile" loaded-modules))

(test-end "host")
