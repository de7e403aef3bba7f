;; SPDX-License-Identifier: MIT
;;; (downstroke live): files a running game watches, and what is called when
;;; one changes on disk.
(use-modules (srfi srfi-64) (downstroke) (downstroke live) (srfi srfi-1))

(load "support.scm")

(test-begin "live")

;; A fresh folder for this run's files, removed at the end.
(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-live-XXXXXX")))
(define (in-dir name) (string-append dir "/" name))
(define (write-file path text)
  (call-with-output-file path (lambda (port) (display text port))))
(define (replace-file path text)
  ;; As Tiled and most editors save: a new file renamed over the old one.
  (let ((tmp (string-append path ".new")))
    (write-file tmp text)
    (rename-file tmp path)))
(define (warnings-of thunk)
  (let ((port (open-output-string)))
    (parameterize ((current-warning-port port)) (thunk))
    (get-output-string port)))

;; Every poll looks, unless a test says otherwise.
(watch-poll-interval 0)

(define file (in-dir "watched.txt"))
(write-file file "one")
(define game (make-game))
(define calls '())
(define (note! path) (set! calls (cons path calls)))
(define (calls-after thunk)
  (set! calls '())
  (thunk)
  (poll-watched-files! game)
  (reverse calls))

(test-equal "watch-file! returns the path it watches" file (watch-file! game file note!))
(test-equal "nothing changed: nothing is called" '() (calls-after (lambda () #t)))
(test-equal "written in place: called once, with the path" (list file)
  (calls-after (lambda () (write-file file "two, longer"))))
(test-equal "and only once" '() (calls-after (lambda () #t)))
(test-equal "replaced by a rename (a new inode): called once" (list file)
  (calls-after (lambda () (replace-file file "three"))))
(test-equal "removed: not called, there is nothing to read" '()
  (calls-after (lambda () (delete-file file))))
(test-equal "made again: called once" (list file)
  (calls-after (lambda () (write-file file "four"))))

(test-equal "the same procedure watching the same path twice is one registration" (list file)
  (begin (watch-file! game file note!)
         (calls-after (lambda () (write-file file "five, longer")))))

(define other-calls '())
(test-equal "a second procedure is called after the first" (list (list file) (list file))
  (let ((second (lambda (path) (set! other-calls (cons path other-calls)))))
    (watch-file! game file second)
    (list (calls-after (lambda () (write-file file "six"))) other-calls)))

(test-equal "a relative path is made absolute against the current folder"
  (in-dir "relative.txt")
  (let ((cwd (getcwd)))
    (dynamic-wind (lambda () (chdir dir))
                  (lambda () (write-file "relative.txt" "x") (watch-file! game "relative.txt" note!))
                  (lambda () (chdir cwd)))))
(test-equal "... and is watched there" (list (in-dir "relative.txt"))
  (calls-after (lambda () (write-file (in-dir "relative.txt") "xy"))))

(test-equal "unwatch-file!: no procedure of the path is called again" '()
  (begin (unwatch-file! game file)
         (unwatch-file! game (in-dir "relative.txt"))
         (calls-after (lambda () (write-file file "seven, longer")))))

;; Between two looks, no file is looked at: a change waits for the next.
(test-equal "within watch-poll-interval of the last look, nothing is looked at" '(() ("a"))
  (let* ((g (make-game)) (seen '()) (f (in-dir "slow.txt")))
    (write-file f "1")
    (watch-file! g f (lambda (path) (set! seen (cons "a" seen))))
    (poll-watched-files! g)   ; a look under interval 0: the next is due at once
    (parameterize ((watch-poll-interval 60))
      (poll-watched-files! g) ; a look, which sets the next one a minute on
      (write-file f "22")
      (poll-watched-files! g))
    (let ((before seen))
      ;; The next look brought forward, as a minute having passed would.
      ((@@ (downstroke live) live-next-look-set!) ((@@ (downstroke game) game-live) g) 0)
      (poll-watched-files! g)
      (list before seen))))

;;; An error in a procedure is reported as a failing hook's, and the game
;;; and the watching go on.
(define failing (in-dir "failing.txt"))
(write-file failing "a")
(define failures 0)
(define g2 (make-game))
(watch-file! g2 failing (lambda (path) (set! failures (+ failures 1)) (error "no good:" path)))
(define report (warnings-of (lambda () (write-file failing "bb") (poll-watched-files! g2))))
(test-assert "the error is reported on the warning port, naming the file and the error"
  (mentions? report (string-append "downstroke: the procedure watching " failing
                                   " raised an error in frame 0; it stays watching:")
             "no good:"))
(test-equal "and the procedure is called again at the next change" 2
  (begin (warnings-of (lambda () (write-file failing "ccc") (poll-watched-files! g2)))
         failures))
(test-equal "served, the error goes to the REPL's reporter instead" '(1 "")
  (let* ((reported '())
         (warned (warnings-of
                  (lambda ()
                    (parameterize ((hook-error-reporter (lambda (text) (set! reported (cons text reported)))))
                      (write-file failing "dddd")
                      (poll-watched-files! g2))))))
    (list (length reported) warned)))

;;; In a running game: looked at between two frames.
(test-equal "in game-run!, a change made in frame 2 is seen before frame 3" '(3)
  (let* ((f (in-dir "running.txt")) (seen '())
         (g (make-game update: (lambda (game dt)
                                 (when (= (game-frame game) 2) (write-file f "changed"))))))
    (write-file f "start")
    (watch-file! g f (lambda (path) (set! seen (cons (game-frame g) seen))))
    (game-run! g frames: 6)
    seen))

;;; Refused where they are given.
(test-equal "watch-poll-interval: a negative number of seconds"
  "In procedure watch-poll-interval: expected a number of seconds ≥ 0, got -1\n"
  (error-text (lambda () (watch-poll-interval -1))))
(test-equal "… and the interval is left as it was" 0 (watch-poll-interval))
(test-equal "watch-file!: a path that is not a string"
  "In procedure watch-file!: path: expected a file name (a non-empty string), got 42\n"
  (error-text (lambda () (watch-file! game 42 note!))))
(test-equal "watch-file!: a procedure of the wrong arity"
  #t (mentions? (error-text (lambda () (watch-file! game file (lambda () #t))))
                "In procedure watch-file!: on-change: expected a procedure of (path)"))
(test-equal "watch-file!: not a game"
  "In procedure watch-file!: game: expected a game (make-game), got #f\n"
  (error-text (lambda () (watch-file! #f file note!))))
(test-equal "poll-watched-files!: not a game"
  "In procedure poll-watched-files!: game: expected a game (make-game), got 3\n"
  (error-text (lambda () (poll-watched-files! 3))))
(test-equal "unwatch-file!: an empty path"
  "In procedure unwatch-file!: path: expected a file name (a non-empty string), got \"\"\n"
  (error-text (lambda () (unwatch-file! game ""))))

(system* "rm" "-rf" dir)
(test-end "live")
