;; SPDX-License-Identifier: MIT
;;; A game's script evaluated again under the running game (reload-script!):
;;; the next frame runs the new procedures, the game, its scene and history
;;; stay; (once …) and define-once are not run again; a broken script
;;; leaves the old definitions, says why, and the game runs on.
(use-modules (srfi srfi-64) (srfi srfi-1) (ice-9 textual-ports) (downstroke)
             ((downstroke game) #:select (current-game))
             ((downstroke script-reload) #:select (script-loaded!))
             ((downstroke live) #:select (watch-poll-interval)))

(load "support.scm")

(test-begin "script-reload")

(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-reload-XXXXXX")))
(define script (string-append dir "/game.scm"))

(define (write-script! text)
  ;; As most editors save: a new file renamed over the old one.
  (let ((new (string-append script ".new")))
    (call-with-output-file new (lambda (port) (display text port)))
    (rename-file new script)))

;; The watcher looks at every poll, not once a second: a test need not wait.
(watch-poll-interval 0)

;; The first lines of every version: a count of the script's evaluations,
;; and one of its (once …) forms' runs.
(define counting
  "(define-once runs 0)
(set! runs (+ runs 1))
(define-once once-runs 0)
(once (set! once-runs (+ once-runs 1)))
")

(define (updating version)
  ;; An update leaving one entity that says which version ran it, in which frame.
  (format #f "(define (update game dt)
  (game-scene-set! game (update-scene (game-scene game)
                                      entities: (list (list #:id 'a #:frame (game-frame game) #:version '~a)))))
" version))

(define (script-module)
  ;; A script's module, as the host makes guile-user one.
  (let ((m ((@ (downstroke host) use-script-environment!) (make-fresh-user-module))))
    (set-module-declarative?! m #f)
    m))

(define (run-script! text)
  ;; TEXT written as the script and run as the host runs one; its module.
  (write-script! text)
  (let ((m (script-module)))
    (save-module-excursion
     (lambda ()
       (set-current-module m)
       (script-loaded! script m #t)
       ((@ (downstroke host) load-script) script #t)))
    m))

(define (versions game)
  ;; (frame version) of the frames GAME's history holds, oldest first, and
  ;; of its scene now.
  (map (lambda (scene)
         (let ((e (car (scene-entities scene))))
           (list (entity-ref e #:frame) (entity-ref e #:version))))
       (append (reverse (filter-map (lambda (entry) (and (pair? (scene-entities (cdr entry))) (cdr entry)))
                                    (game-history game)))
               (list (game-scene game)))))

(define (save-at! frame game edit)
  ;; A frame hook that, at the start of FRAME, saves the script as (EDIT)
  ;; makes it: the author saving in an editor. The game watches it, and
  ;; reloads it in the same poll, before the frame's step.
  (let ((saved? #f))
    (add-frame-hook! (lambda ()
                       (when (and (eq? (current-game) game) (= (game-frame game) frame) (not saved?))
                         (set! saved? #t)
                         (write-script! (edit)))))))

;;; ---------------------------------------------------------------- a new procedure
(define m (run-script! (string-append counting (updating "old") "
(define game (make-game scene: (make-scene entities: '()) update: update history: 20))
")))
(define game (module-ref m 'game))
(define old-update (game-update game))
(game-watch-script! game #t)
(save-at! 5 game (lambda () (string-append counting (updating "new") "
(define game (make-game scene: (make-scene entities: '()) update: update history: 20))
")))
(define reload-warnings
  (call-with-output-string (lambda (port) (parameterize ((current-warning-port port)) (game-run! game frames: 10)))))

(test-equal "the reload under the running game said nothing" "" reload-warnings)
(test-equal "the frames before it ran the old update, the frames from it on the new one"
  '((0 old) (1 old) (2 old) (3 old) (4 old) (5 new) (6 new) (7 new) (8 new) (9 new))
  (versions game))
(test-assert "the game's update: is the script's new update"
  (and (eq? (game-update game) (module-ref m 'update)) (not (eq? (game-update game) old-update))))
(test-assert "the script's `game' is the running game again, not the one its reload made"
  (eq? (module-ref m 'game) game))
(test-equal "the script ran twice, its (once …) form once" '(2 1)
  (list (module-ref m 'runs) (module-ref m 'once-runs)))
(test-equal "the running game went on to its end" 10 (game-frame game))
(test-equal "rewinding past the reload finds the scenes the old update made"
  '(3 (2 old))
  (begin (game-rewind! game 7)
         (let ((e (car (scene-entities (game-scene game)))))
           (list (game-frame game) (list (entity-ref e #:frame) (entity-ref e #:version))))))
(test-equal "… and stepping on from there runs the new one: the procedures are the script's now"
  '(4 (3 new))
  (begin (game-run! game frames: 4)
         (let ((e (car (scene-entities (game-scene game)))))
           (list (game-frame game) (list (entity-ref e #:frame) (entity-ref e #:version))))))

(game-watch-script! game #f)
(write-script! (string-append counting (updating "unwatched")))
(game-run! game frames: 6)
(test-equal "a game that stopped watching its script runs on with the update it had"
  '(5 new)
  (let ((e (car (scene-entities (game-scene game)))))
    (list (entity-ref e #:frame) (entity-ref e #:version))))

;;; ---------------------------------------------------------------- game-run! in the script
;;; As a game's script is written: it runs the game itself, and the reload
;;; comes inside that run. Its game-run!, reached again, starts no second
;;; loop (it would be refused: a game is running) and returns the running game.
(define m2 (run-script! (string-append counting (updating "old") "
(define-once game (make-game scene: (make-scene entities: '()) update: update history: 20))
(once (add-frame-hook!
       (lambda ()
         (when (and (= (game-frame game) 4) (eq? reloaded 'not-reached))
           (set! reloaded (reload-script!))))))
(define-once reloaded 'not-reached)
(define ran (game-run! game frames: 8))
(define frame-ran (game-frame ran))
")))
(define game2 (module-ref m2 'game))
(test-equal "the reload inside the script's own run reloaded" #t (module-ref m2 'reloaded))
(test-equal "the game ran to its end once" 8 (game-frame game2))
(test-assert "game-run! returned the running game" (eq? (module-ref m2 'ran) game2))
;; The reload saw the game at frame 4; the first load's frame-ran, 8, was
;; set after the run returned.
(test-equal "… and the first load's game-run! returned after the reload's" 8 (module-ref m2 'frame-ran))
(test-equal "its (once …) ran once" '(2 1) (list (module-ref m2 'runs) (module-ref m2 'once-runs)))

;;; ---------------------------------------------------------------- a broken script
(define (broken-reload version-text)
  ;; GAME of a fresh script, watched, saved at frame 5 as VERSION-TEXT:
  ;; (versions warning-text module game).
  (let* ((m (run-script! (string-append counting (updating "old") "
(define game (make-game scene: (make-scene entities: '()) update: update history: 20))
")))
         (game (module-ref m 'game)))
    (game-watch-script! game #t)
    (save-at! 5 game (lambda () version-text))
    (let ((warnings (call-with-output-string
                     (lambda (port)
                       (parameterize ((current-warning-port port))
                         (game-run! game frames: 10))))))
      (list (versions game) warnings m game))))

(define all-old '((0 old) (1 old) (2 old) (3 old) (4 old) (5 old) (6 old) (7 old) (8 old) (9 old)))
(define report-head
  (string-append "downstroke: reloading " script " raised an error; its old definitions stay, and the game runs on:\n"))

(define top-level-error
  (broken-reload (string-append counting (updating "new") "(define added 1)\n(car '())\n")))
(test-equal "an error at the top level: every frame ran the old update" all-old (first top-level-error))
(test-assert "… the report says which script and that the game runs on"
  (string-prefix? report-head (second top-level-error)))
(test-assert "… and ends with the error"
  (string-suffix? "In procedure car: Wrong type argument in position 1 (expecting pair): ()\n"
                  (second top-level-error)))
(test-equal "… the names it had redefined are back, the one it added gone, its counts as before"
  '(#t #f 1 1)
  (let ((m (third top-level-error)))
    (list (eq? (module-ref m 'update) (game-update (fourth top-level-error)))
          (module-defined? m 'added) (module-ref m 'runs) (module-ref m 'once-runs))))

(define unreadable (broken-reload (string-append counting (updating "new") "(define (oops")))
(test-equal "a script that cannot be read: the game ran on with the old update" all-old (first unreadable))
(test-assert "… the report names the script and ends with the reader's error, at its place"
  (and (string-prefix? report-head (second unreadable))
       (string-suffix? (string-append script ":8:14: unexpected end of input while searching for: )\n")
                       (second unreadable))))

(define wrong-arity
  (broken-reload (string-append counting "(define (update game) 'one-argument)\n"
                                "(define game (make-game scene: (make-scene entities: '()) history: 20))\n")))
(test-equal "an update of the wrong arity is refused: the old update stays" all-old (first wrong-arity))
(test-assert "… said as make-game says it"
  (string-suffix? (string-append "In procedure reload-script!: update: expected a procedure of (game dt), got update, a procedure of (game), at "
                                 script ":5:0\n")
                  (second wrong-arity)))

;;; ---------------------------------------------------------------- downstroke --watch
;;; The host itself, headless with --watch: the script saves a new version
;;; of itself at frame 1 (as its author would), and the host's watcher,
;;; looking once a second, reloads it; the new update ends the game.
(define watched-script (string-append dir "/watched.scm"))
(define (watched-version update-body)
  (format #f "(define (update game dt) ~a)
(define-once game (make-game update: update))
(once
 (add-frame-hook!
  (lambda ()
    (when (= (game-frame game) 1)
      (call-with-output-file (string-append (current-filename*) \".new\")
        (lambda (port) (display edited port)))
      (rename-file (string-append (current-filename*) \".new\") (current-filename*)))))
 (game-run! game frames: 100000000)
 (display \"not reloaded\\n\"))
" update-body))
(call-with-output-file watched-script
  (lambda (port)
    (display (string-append "(define (current-filename*) " (format #f "~s" watched-script) ")\n"
                            (format #f "(define edited ~s)\n"
                                    (string-append "(define (current-filename*) " (format #f "~s" watched-script) ")\n"
                                                   "(define edited \"\")\n"
                                                   (watched-version "(format #t \"reloaded, frame ~a~%\" (game-frame game)) (exit 0)")))
                            (watched-version "#t"))
             port)))
(define host (readlink "/proc/self/exe"))
(define (host-output . args)
  ;; (exit-status . stdout) of the host run with ARGS.
  (let* ((out (string-append dir "/out"))
         (status (system (string-append (string-join (map (lambda (a) (string-append "'" a "'")) (cons host args)) " ")
                                        " >" out))))
    (cons (status:exit-val status) (call-with-input-file out get-string-all))))
(define watched-run (host-output "--watch" "--timeout" "30" watched-script))
(test-assert "downstroke --watch: a script saved under its running headless game is reloaded within a second or so"
  (and (= 0 (car watched-run)) (string-prefix? "reloaded, frame " (cdr watched-run))))

;; The plain REPL (downstroke with no script) has nothing to reload.
(define repl-answer
  (let ((in (string-append dir "/in")) (out (string-append dir "/out")))
    (call-with-output-file in (lambda (port) (display "(reload-script!)\n" port)))
    (system (string-append "'" host "' <'" in "' >'" out "' 2>&1"))
    (delete-file in)
    (call-with-input-file out get-string-all)))
(test-assert "(reload-script!) with no script is refused, saying why"
  (string-contains repl-answer
                   "In procedure reload-script!: no script to reload: only a script run by downstroke (downstroke FILE.scm) can be reloaded\n"))

;;; ---------------------------------------------------------------- a module from the game's folder
;;; The script uses a module of its own, found on the load path through the
;;; script's folder: saving the module reloads it, then the script. The
;;; folder is then on the load path, and the reload still finds
;;; (current-filename), though the test runs from another folder. Last:
;;; the folder stays on the load path.
(define module-file (string-append dir "/reload-test/versions.scm"))
(mkdir (dirname module-file))
(define (write-module! version)
  (let ((new (string-append module-file ".new")))
    (call-with-output-file new
      (lambda (port)
        (format port "(define-module (reload-test versions) #:export (edition))\n(define (edition) '~a)\n" version)))
    (rename-file new module-file)))
(write-module! "old")
(define module-user (string-append counting "
(eval-when (expand load eval) (add-to-load-path (dirname (current-filename))))
(use-modules (reload-test versions))
(define (update game dt)
  (game-scene-set! game (update-scene (game-scene game)
                                      entities: (list (list #:id 'a #:frame (game-frame game) #:version (edition))))))
(define game (make-game scene: (make-scene entities: '()) update: update history: 20))
"))
(define m3 (run-script! module-user))
(define game3 (module-ref m3 'game))
(game-watch-script! game3 #t)
(let ((saved? #f))
  (add-frame-hook! (lambda ()
                     (when (and (eq? (current-game) game3) (= (game-frame game3) 3) (not saved?))
                       (set! saved? #t)
                       (write-module! "new")))))
(game-run! game3 frames: 6)
(test-equal "saving a module the script uses from its folder: the next frame runs its new code"
  '((0 old) (1 old) (2 old) (3 new) (4 new) (5 new))
  (versions game3))
(test-equal "… and the script was evaluated again after it" 2 (module-ref m3 'runs))

;; Saved together, the module and the script are two changes in one look:
;; one reload reads both. The script, changed, is compiled again: its
;; (current-filename) must name it though its folder is on the load path.
(let ((saved? #f))
  (add-frame-hook! (lambda ()
                     (when (and (eq? (current-game) game3) (= (game-frame game3) 7) (not saved?))
                       (set! saved? #t)
                       (write-module! "newer")
                       (write-script! (string-append module-user "\n;; saved again\n"))))))
(game-run! game3 frames: 9)
(test-equal "a module and the script saved together: the next frame runs the new code"
  '((6 new) (7 newer) (8 newer))
  (list-tail (versions game3) 6))
(test-equal "… after one reload, not two" 3 (module-ref m3 'runs))

;; A module that fails to load again: its old definitions stay too.
(let ((saved? #f))
  (add-frame-hook! (lambda ()
                     (when (and (eq? (current-game) game3) (= (game-frame game3) 10) (not saved?))
                       (set! saved? #t)
                       (let ((new (string-append module-file ".new")))
                         (call-with-output-file new
                           (lambda (port)
                             (display "(define-module (reload-test versions) #:export (edition))\n(define (edition) 'broken)\n(car '())\n" port)))
                         (rename-file new module-file))))))
(define module-warnings
  (call-with-output-string (lambda (port) (parameterize ((current-warning-port port)) (game-run! game3 frames: 12)))))
(test-equal "a module that fails to reload: the game runs on with its old code"
  '((10 newer) (11 newer))
  (list-tail (versions game3) 10))
(test-assert "… and the failure is reported, naming the script"
  (and (string-prefix? report-head module-warnings)
       (string-suffix? "In procedure car: Wrong type argument in position 1 (expecting pair): ()\n" module-warnings)))
(game-watch-script! game3 #f)
(delete-file module-file)
(rmdir (dirname module-file))

;;; ---------------------------------------------------------------- bad calls
(test-equal "reload-script! of something not a game is refused, naming it"
  "In procedure reload-script!: game: expected a game (make-game), got nope\n"
  (error-text (lambda () (reload-script! 'nope))))

(for-each delete-file (list script watched-script (string-append dir "/out")))
(rmdir dir)

(test-end "script-reload")
