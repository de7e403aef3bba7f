;; SPDX-License-Identifier: MIT
;;; (downstroke testing): play, check-frame against golden pictures, and a
;;; recorded session replayed.
(use-modules (srfi srfi-64) (srfi srfi-1) (ice-9 ftw) (downstroke) (downstroke testing) (downstroke hash))

(load "support.scm")

(test-begin "testing")

(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-testing-XXXXXX")))

(define (walker)
  (make-game width: 32 height: 16
             scene: (make-scene entities: '((#:id w #:x 0 #:y 4 #:width 4 #:height 4 #:color (170 170 170))))
             update: (lambda (game dt)
                       (let* ((s (game-scene game)) (e (car (scene-entities s))))
                         (when (input-held? (game-input game) 'right)
                           (game-scene-set! game (update-scene s entities: (list (entity-set e #:x (+ 1 (entity-ref e #:x)))))))))))
(define (x-of game) (entity-ref (car (scene-entities (game-scene game))) #:x))

;;; ---------------------------------------------------------------- play
(define played (play (walker) #:frames 10 #:input '((0 . ()) (2 . (right)) (7 . ()))))
(test-equal "play runs the game headless with its script, and returns it" '(10 5) (list (game-frame played) (x-of played)))
(test-equal "… and again up to a later frame" 10 (game-frame (play played #:frames 10)))

;;; ---------------------------------------------------------------- a recorded session
(define session (string-append dir "/session.scm"))
(test-equal "record-input writes the input as a script" '((0) (2 right) (7)) (record-input played session))
(test-equal "read-input-script reads it back" '((0) (2 right) (7)) (read-input-script session))
(define replayed (play (walker) #:frames 10 #:input session))
(test-equal "the session replays exactly: the same scene, frame for frame" (scene-hash (game-scene played))
  (scene-hash (game-scene replayed)))
(test-assert "a file that is no input script is refused, naming it"
  (let ((bad (string-append dir "/bad.scm")))
    (call-with-output-file bad (lambda (p) (write '((0 . (right)) (x . ())) p)))
    (mentions? (error-text (lambda () (read-input-script bad))) "read-input-script" "input-script")))

(test-equal "a recorded script out of frame order is refused, naming the file's reader and both frames"
  "In procedure read-input-script: input-script: entry 2 is for frame 1, after an entry for frame 5: frames must increase\n"
  (let ((unordered (string-append dir "/unordered.scm")))
    (call-with-output-file unordered (lambda (p) (write '((0 . ()) (5 . (right)) (1 . ())) p)))
    (error-text (lambda () (read-input-script unordered)))))
(test-equal "… and so is a list given to play, which then runs nothing"
  '("In procedure play: input-script: entry 1 is for frame 2, after an entry for frame 2: frames must increase\n" 0)
  (let* ((game (walker))
         (text (error-text (lambda () (play game #:frames 10 #:input '((2 . (right)) (2 . ())))))))
    (list text (game-frame game))))

(define (script-file name text)
  (let ((file (string-append dir "/" name)))
    (call-with-output-file file (lambda (p) (display text p)))
    file))
(let ((cut (script-file "cut.scm" "((0) (1 right")))
  (test-equal "a script that does not read is refused with the file, line, column and what is wrong"
    (string-append "In procedure read-input-script: cannot read an input script from \"" cut "\": " cut
                   ":1:14: unexpected end of input while searching for: )\n")
    (error-text (lambda () (read-input-script cut)))))
(let ((twice (script-file "twice.scm" "((0) (1 right))\n; a comment\n\n  ((2 left))\n")))
  (test-equal "text after the script is refused, with where it starts"
    (string-append "In procedure read-input-script: " twice
                   ":4:3: text after the input script (a file holds one list of (frame . actions))\n")
    (error-text (lambda () (read-input-script twice)))))
(test-equal "… but comments after it are not text"
  '((0) (1 right)) (read-input-script (script-file "commented.scm" "((0) (1 right)) ; done\n#| end |#\n")))
(test-equal "a missing file is named, with the reason"
  (string-append "In procedure read-input-script: \"" dir
                 "/none.scm\": it cannot be read (No such file or directory)\n")
  (error-text (lambda () (read-input-script (string-append dir "/none.scm")))))
(test-equal "a scripted pointer at infinity is refused, naming it"
  "In procedure read-input-script: input-script: expected (frame . actions), a frame ≥ 0 and a list of symbols and at most one (mouse x y buttons), got (1 (mouse +inf.0 2 ()))\n"
  (error-text (lambda () (read-input-script (script-file "inf.scm" "((0) (1 (mouse +inf.0 2 ())))")))))

;;; ---------------------------------------------------------------- golden frames
(when (renderer-available?)
  (let ((golden (string-append dir "/walker.png")))
    (test-assert "a missing golden picture is an error that says how to make it"
      (mentions? (error-text (lambda () (check-frame played golden))) "check-frame" "DOWNSTROKE_UPDATE_GOLDEN=1"))
    (setenv "DOWNSTROKE_UPDATE_GOLDEN" "1")
    (test-assert "DOWNSTROKE_UPDATE_GOLDEN=1 writes it" (and (check-frame played golden) (file-exists? golden)))
    (unsetenv "DOWNSTROKE_UPDATE_GOLDEN")
    (test-assert "the same frame matches it" (check-frame replayed golden))
    (let* ((moved (play (walker) #:frames 10 #:input '((0 . (right)) (9 . ()))))
           (text (error-text (lambda () (check-frame moved golden)))))
      (test-assert "a different frame fails, saying how many pixels differ and the first"
        (mentions? text "check-frame" "pixel(s) differ" "the first at (5, 4)"))
      (test-assert "… and writes the frame and a diff picture beside the golden one"
        (and (file-exists? (string-append dir "/walker.actual.png"))
             (file-exists? (string-append dir "/walker.diff.png"))))
      (test-assert "… naming the two colours there: the golden box's colour expected, the background got"
        (mentions? text "expected (170 170 170 255)" "got (24 28 40 255)")))
    (let* ((folder (string-append dir "/v1.2")) (golden (string-append folder "/walker"))
           (moved (play (walker) #:frames 10 #:input '((0 . (right)) (9 . ())))))
      (mkdir folder)
      (copy-file (string-append dir "/walker.png") golden)
      (test-equal "a golden file with no extension, in a folder with a dot: the mismatch, and the pictures beside it"
        (list (string-append "In procedure check-frame: 32 pixel(s) differ from \"" golden
                             "\", the first at (5, 4): expected (170 170 170 255), got (24 28 40 255); see \""
                             golden ".actual\" and \"" golden ".diff\"\n")
              '("walker" "walker.actual" "walker.diff"))
        (list (error-text (lambda () (check-frame moved golden)))
              (cddr (scandir folder)))))
    (let ((broken (string-append dir "/broken.png")))
      (call-with-output-file broken (lambda (p) (display "\x89PNG\r\n\x1a\nnot a picture" p)))
      (test-assert "a golden file that is no picture is an error naming it as the golden picture"
        (mentions? (error-text (lambda () (check-frame played broken)))
                   "check-frame" "the golden picture" broken "not a PNG")))))

(test-end "testing")
