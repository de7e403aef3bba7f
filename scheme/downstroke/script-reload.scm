;; SPDX-License-Identifier: MIT
;;; (downstroke script-reload) — a game's script evaluated again in the
;;; running game: its new definitions take effect at the next frame, and
;;; the game record, its scene and its history stay. docs/repl.org, "Live
;;; editing".
;;;
;;; The modules from the script's folder are loaded again, then the script
;;; as the host loaded it (compiled, in the module it ran in), so every
;;; top-level form runs again; the ones that must not are written in
;;; (once …) or define-once. A game-run! reached again starts nothing
;;; (engine.scm). A hook the game was made with that was the value of one
;;; of the script's top-level names is re-pointed to that name's new
;;; value; a name that held the running game holds it again. A reload that fails puts every top-level name of the script's
;;; module and of those modules back as it was, and reports the error as a
;;; failing hook's is. game-watch-script! reloads it when one of its files
;;; changes on disk, through (downstroke live).
(define-module (downstroke script-reload)
  #:use-module ((srfi srfi-1) #:select (find filter-map remove))
  #:use-module (downstroke game)
  #:use-module ((downstroke hook-errors) #:select (call-reporting hook-error-reporter retry-failed-frame!))
  #:use-module ((downstroke live) #:select (watch-file! unwatch-file! watch-default))
  #:export (reload-script! game-watch-script! arm-script-watch! once script-reloading?
            script-loaded! script-files))

;; #t while a script is being evaluated again: (once …) skips its forms and
;; game-run! starts nothing.
(define script-reloading? (make-parameter #f))

(define-syntax-rule (once form form* ...)
  ;; Documented in (downstroke documentation): a macro has no docstring.
  (if (script-reloading?) *unspecified* (begin form form* ...)))

;;; The script the host runs: one a process. (file module compile?), or #f.
(define the-script #f)

(define (script-loaded! file module compile?)
  ;; FILE (a canonical path) is the game's script, loaded into MODULE,
  ;; compiled when COMPILE? (the host's --no-auto-compile makes it #f).
  (set! the-script (list file module compile?)))

(define (script-files)
  "The files a reload evaluates again: the script, the files it loads by a
literal name, and the files of the modules from its folder (or a folder in
it) that are loaded; () when no script runs."
  (if the-script
      (append ((@ (downstroke script-source) loaded-files) (car the-script))
              (map cdr (folder-modules)))
      '()))

(define (all-modules)
  ;; Every module Guile has loaded, from the root of its module tree.
  (let walk ((m (resolve-module '() #f)) (acc '()))
    (hash-fold (lambda (name sub acc) (walk sub (cons sub acc))) acc (module-submodules m))))

(define (folder-modules)
  ;; ((module . file) …): the loaded modules whose file is in the script's
  ;; folder or a folder in it — the game's own modules, used by the script
  ;; (use-modules) with its folder on the load path.
  (let ((folder (string-append (dirname (car the-script)) "/")))
    (filter-map (lambda (m)
                  (let* ((name (module-filename m))
                         (found (and (string? name) (%search-load-path name)))
                         (file (and found (false-if-exception (canonicalize-path found)))))
                    (and file (string-prefix? folder file) (cons m file))))
                (all-modules))))

;;; ---------------------------------------------------------------- the names kept

(define (module-bindings module)
  ;; ((name variable bound? . value) …) of MODULE's own top-level names.
  (let ((acc '()))
    (module-for-each (lambda (name var)
                       (set! acc (cons (cons* name var (variable-bound? var)
                                              (and (variable-bound? var) (variable-ref var)))
                                       acc)))
                     module)
    acc))

(define (restore-bindings! module kept)
  ;; MODULE's names as KEPT (module-bindings) had them: a name the failed
  ;; reload added is removed, one it changed is set back.
  (let ((added '()))
    (module-for-each (lambda (name var) (unless (assq name kept) (set! added (cons name added))))
                     module)
    (for-each (lambda (name) (module-remove! module name)) added))
  (for-each (lambda (entry)
              (let ((name (car entry)) (var (cadr entry)) (bound? (caddr entry)) (value (cdddr entry)))
                (unless (eq? (module-local-variable module name) var)
                  (module-add! module name var))
                (if bound? (variable-set! var value) (variable-unset! var))))
            kept))

;;; ---------------------------------------------------------------- re-pointing
;;; The game's hooks are procedure values in its record: a hook given as
;;; update: update holds the procedure `update' had when the game was made,
;;; which a new (define (update …)) does not change. A hook called through
;;; its name, update: (lambda (g dt) (update g dt)), needs nothing.

;; (what getter setter): the hooks a reload re-points, with the name
;; check-hook-or-false gives each.
(define hook-slots
  (list (list 'update game-update %game-update-set!)
        (list 'render game-render %game-render-set!)
        (list 'engine-update game-engine-update %game-engine-update-set!)
        (list 'paused game-paused-update %game-paused-update-set!)))

(define (names-holding value kept)
  ;; The names KEPT (module-bindings) bound to VALUE itself.
  (filter-map (lambda (entry) (and (caddr entry) (eq? (cdddr entry) value) (car entry))) kept))

(define (hook-names game kept)
  ;; ((slot name …) …): for each hook of GAME, the script's names that held it.
  (if game
      (filter-map (lambda (slot)
                    (let ((hook ((cadr slot) game)))
                      (and (procedure? hook)
                           (let ((names (names-holding hook kept)))
                             (and (pair? names) (cons slot names))))))
                  hook-slots)
      '()))

(define (re-point! game module held game-names)
  ;; Each hook in HELD (hook-names) set to the new value of the first of its
  ;; names the reload gave a new procedure, all checked before any is set;
  ;; each of GAME-NAMES set back to GAME where the reload bound it to
  ;; another game.
  (let ((changes
         (filter-map (lambda (entry)
                       (let* ((slot (car entry)) (old ((cadr slot) game))
                              (new (find (lambda (value) (and (procedure? value) (not (eq? value old))))
                                         (map (lambda (name) (module-ref module name #f)) (cdr entry)))))
                         (and new (cons slot new))))
                     held)))
    (for-each (lambda (change) (check-hook-or-false "reload-script!" (car (car change)) (cdr change)))
              changes)
    (for-each (lambda (change) ((caddr (car change)) game (cdr change))) changes))
  (for-each (lambda (name)
              (let ((var (module-local-variable module name)))
                (when (and var (variable-bound? var) (game? (variable-ref var))
                           (not (eq? (variable-ref var) game)))
                  (variable-set! var game))))
            game-names))

;;; ---------------------------------------------------------------- reloading

(define (inside? dir folder)
  ;; Whether FOLDER is DIR or in it (both canonical).
  (or (string=? dir folder) (string-prefix? (string-append dir "/") folder)))

(define (with-files-named-whole folder thunk)
  ;; (THUNK) with no folder holding FOLDER on the load path. Guile names a
  ;; file it loads from under a load-path folder relative to that folder,
  ;; and (current-filename) canonicalizes the name against the working
  ;; folder: #f when the game runs from elsewhere. The first load came
  ;; before the script put its folder on the load path (add-to-load-path,
  ;; for its modules); a reload comes after. The folders are put back
  ;; after, in front, unless the script put them back itself.
  (let* ((held? (lambda (entry)
                  (let ((dir (false-if-exception (canonicalize-path entry))))
                    (and dir (inside? dir folder)))))
         (taken (filter held? %load-path)))
    (dynamic-wind
      (lambda () (set! %load-path (remove held? %load-path)))
      thunk
      (lambda ()
        (set! %load-path (append (remove (lambda (e) (member e %load-path)) taken) %load-path))))))

(define (report-to-warning-port text)
  (display text (current-warning-port))
  (force-output (current-warning-port)))

(define* (reload-script! #:optional (game (current-game)))
  "Evaluate the game's script (the FILE.scm downstroke runs, with the files
it loads) again in the module it runs in, after loading again the modules
from its folder it uses: new definitions take effect at the next frame;
GAME (by default the running game), its scene and history stay.
Forms in (once …) and define-once are not run again, and game-run! starts
nothing. GAME's hooks (update:, render:, engine-update:, paused:) that were
the value of a top-level name of the script are set to that name's new
value. An error while reloading puts every top-level name of the script and
of those modules back as it was, is reported as a failing hook's is (on the
warning port; in a served game, to the REPL too) and the game runs on.
Returns #t when it reloaded, #f when it failed."
  (when game (check-game "reload-script!" game))
  (unless the-script
    (scm-error 'misc-error "reload-script!"
               "no script to reload: only a script run by downstroke (downstroke FILE.scm) can be reloaded"
               '() #f))
  (set! reloaded-stamps (map (lambda (f) (cons f (file-stamp f))) (script-files)))
  (let* ((file (car the-script)) (module (cadr the-script)) (compile? (caddr the-script))
         (modules (folder-modules))
         ;; ((module . its bindings) …), the script's module first.
         (kept (map (lambda (m) (cons m (module-bindings m))) (cons module (map car modules))))
         (held (hook-names game (cdar kept)))
         (game-names (if game (names-holding game (cdar kept)) '())))
    (define (load-in! m file)
      (save-module-excursion
       (lambda ()
         (set-current-module m)
         ((@ (downstroke host) load-script) file compile?))))
    (parameterize ((hook-error-reporter (or (hook-error-reporter) report-to-warning-port))
                   (script-reloading? #t))
      (call-reporting
       (lambda ()
         (format #f "reloading ~a raised an error; its old definitions stay, and the game runs on" file))
       (lambda ()
         (with-files-named-whole (dirname file)
           (lambda ()
             ;; The modules first: the script's top level may call them.
             (for-each (lambda (entry) (load-in! (car entry) (cdr entry))) modules)
             (load-in! module file)))
         (when game
           (re-point! game module held game-names)
           ;; A served game paused on a failing hook tries again: the new
           ;; code may be the fix.
           (retry-failed-frame! game))
         #t)
       (lambda ()
         (for-each (lambda (entry) (restore-bindings! (car entry) (cdr entry))) kept)
         #f)))))

;;; ---------------------------------------------------------------- watching

;; ((file . stamp) …): the script's files as the last reload found them as
;; it began. Two files saved together (a module and the script) are two
;; changes in one look of the watcher: the second finds its file as the
;; reload for the first read it, and reloads nothing.
(define reloaded-stamps '())

;; What an edit of a file changes, or #f: the stamp (downstroke live)
;; compares, so that a file this reload read is not reloaded again.
(define file-stamp (@@ (downstroke live) file-stamp))

(define (read-by-last-reload? file)
  (let ((stamp (file-stamp file)))
    (and stamp (equal? stamp (assoc-ref reloaded-stamps file)))))

;; game → the procedure its script's files are watched with (watch-file!
;; takes the same procedure twice as one registration).
(define watching (make-weak-key-hash-table))

(define (watch-files! game on-change)
  ;; Every file of the script watched; after a reload there may be new ones.
  (for-each (lambda (file) (watch-file! game file on-change)) (script-files)))

(define (game-watch-script! game on?)
  "With ON? true, reload GAME's script (reload-script!) between two frames
each time it, a file it loads by a literal name, or a module from its folder
changes on disk (a look at them at most once a second, see (downstroke
live)); with ON? #f, stop. `downstroke --watch' turns it on for every game
the script runs (the default in a window and in a served game). Does
nothing when no script runs (a script run by downstroke)."
  (check-game "game-watch-script!" game)
  (let ((on-change (hashq-ref watching game)))
    (cond ((and on? (not on-change) the-script)
           (let ((on-change (lambda (path)
                              (unless (read-by-last-reload? path)
                                (reload-script! game))
                              (when (hashq-ref watching game)
                                (watch-files! game (hashq-ref watching game))))))
             (hashq-set! watching game on-change)
             (watch-files! game on-change)))
          ((and (not on?) on-change)
           (hashq-remove! watching game)
           (for-each (lambda (file) (unwatch-file! game file)) (script-files))))
    *unspecified*))

;; Games run while watch-default is true (the host's --watch, shared with
;; the maps' watching) watch their script: game-run! arms each as it starts
;; (arm-script-watch!), not a frame hook: a frame hook, even one that does
;; nothing, costs each frame about 0.5 M instructions in its stack bound
;; (measured, docs/repl.org).

;; The games arm-script-watch! has turned watching on for: each once, so
;; that one turned off (game-watch-script! game #f) stays off.
(define offered (make-weak-key-hash-table))

(define (arm-script-watch! game)
  ;; Called by game-run! as GAME starts.
  (when (and (watch-default) (not (hashq-ref offered game)))
    (hashq-set! offered game #t)
    (game-watch-script! game #t)))
