;; SPDX-License-Identifier: MIT
;;; (downstroke live) — live editing: files a running game watches, and the
;;; procedures called, between two frames, when one of them changes on disk.
;;; docs/repl.org, "Live editing".
;;;
;;; The files are looked at by their stat (device, inode, size, modification
;;; time), at most once every watch-poll-interval seconds: no inotify, so
;;; nothing native and the same on every platform; and no file-system call in
;;; a frame that does not look, which is nearly all of them (the cost is in
;;; docs/repl.org). An editor that saves by writing a new file and renaming
;;; it over the old one (Tiled, Emacs, Vim) gives the path a new inode; one
;;; that writes in place, a new size or time.
(define-module (downstroke live)
  #:use-module ((srfi srfi-1) #:select (append-map find fold remove))
  #:use-module (srfi srfi-9)
  #:use-module (downstroke arity)
  #:use-module (downstroke error-text)
  #:use-module (downstroke game)
  #:use-module (downstroke hook-errors)
  #:use-module ((downstroke native) #:select (%tilemap-edits))
  #:use-module ((downstroke world) #:select (scene-tilemap update-scene))
  #:use-module ((downstroke tilemap) #:select (load-tilemap tilemap-set-tile))
  #:use-module ((downstroke render) #:select (current-display draw-label))
  #:export (watch-file! unwatch-file! poll-watched-files! watch-poll-interval
            game-watch-maps! game-watching-maps? reload-map! watch-default))

;; The least time, in seconds, between two looks at the watched files. A
;; second is what "a saved file shows within a second" needs, and a look
;; costs a stat per file (some µs each): once a second, a frame in sixty
;; pays it. Tests set it to 0, so that every poll looks.
(define watch-poll-interval
  (make-parameter 1 (lambda (seconds)
                      ;; Refused where it is set, not in a frame later.
                      (unless (and (real? seconds) (>= seconds 0) (finite? seconds))
                        (scm-error 'wrong-type-arg "watch-poll-interval"
                                   "expected a number of seconds ≥ 0, got ~S" (list seconds) #f))
                      seconds)))

;; Whether games made from now on watch their maps (game-watch-maps!): the
;; host's --watch, on by default in a window and in a game served to a REPL.
(define watch-default (make-parameter #f))

;;; A game's live state (game-live): the watched files, in the order they
;;; were first watched, and the real time (internal units) of the next look;
;;; and, for its maps, whether they are watched, the files of the current
;;; scene's map that are, the procedure that watches them, whether one of
;;; them changed in this look, and the error the last reload failed with.
(define-record-type <live>
  (make-live files next-look maps? map-files map-watcher stale? error)
  live?
  (files live-files live-files-set!)          ; a list of <watched>
  (next-look live-next-look live-next-look-set!)
  (maps? live-maps? live-maps?-set!)
  (map-files live-map-files live-map-files-set!)
  (map-watcher live-map-watcher live-map-watcher-set!)
  (stale? live-stale? live-stale?-set!)
  (error live-error live-error-set!))       ; the text shown over the game's picture, or #f

(define-record-type <watched>
  (make-watched path stamp callbacks)
  watched?
  (path watched-path)
  (stamp watched-stamp watched-stamp-set!)            ; (file-stamp path) when last looked at
  (callbacks watched-callbacks watched-callbacks-set!))  ; procedures of (path), in the order given

(define (live-of game)
  (or (game-live game)
      (let ((live (make-live '() 0 #f '() #f #f #f)))
        ;; One procedure for all the map's files: a look that finds several
        ;; of them saved reloads the map once (poll-watched-files!).
        (live-map-watcher-set! live (lambda (path) (live-stale?-set! live #t)))
        (game-live-set! game live)
        live)))

(define (file-stamp path)
  ;; What changes when PATH is written or replaced, or #f while it is absent
  ;; (or unreadable): a file removed and made again is then one change.
  (let ((st (stat path #f)))
    (and st (list (stat:dev st) (stat:ino st) (stat:size st) (stat:mtime st) (stat:mtimensec st)))))

(define absolute (@@ (downstroke tilemap) absolute))

(define (check-path who path)
  (unless (and (string? path) (not (string-null? path)))
    (scm-error 'wrong-type-arg who "path: expected a file name (a non-empty string), got ~S" (list path) #f)))

(define (watch-file! game path on-change)
  "Call (ON-CHANGE PATH) once, from GAME's loop between two frames, each
time the file PATH (a string, made absolute against the current folder)
changes on disk: written, replaced by a rename as editors save, or removed
and made again. The files are looked at at most once every
watch-poll-interval seconds. Watching a path with the same procedure twice
is one registration. An error ON-CHANGE raises is reported as a failing
hook's is, and the game runs on. Returns the absolute path."
  (check-game "watch-file!" game)
  (check-path "watch-file!" path)
  (unless (procedure? on-change)
    (scm-error 'wrong-type-arg "watch-file!" "on-change: expected a procedure of (path), got ~S"
               (list on-change) #f))
  (check-hook "watch-file!" "on-change" on-change '(path))
  (let* ((path (absolute path))
         (live (live-of game))
         (watched (find (lambda (w) (string=? (watched-path w) path)) (live-files live))))
    (cond ((not watched)
           (live-files-set! live (append (live-files live)
                                         (list (make-watched path (file-stamp path) (list on-change))))))
          ((not (memq on-change (watched-callbacks watched)))
           (watched-callbacks-set! watched (append (watched-callbacks watched) (list on-change)))))
    path))

(define (unwatch-file! game path)
  "Stop watching PATH (as given to watch-file!, or absolute) for GAME: none
of its procedures is called again."
  (check-game "unwatch-file!" game)
  (check-path "unwatch-file!" path)
  (let ((live (game-live game)) (path (absolute path)))
    (when live
      (live-files-set! live (remove (lambda (w) (string=? (watched-path w) path)) (live-files live))))
    *unspecified*))

(define (report-to-warning-port text)
  (display text (current-warning-port))
  (force-output (current-warning-port)))

(define (call-on-change game path on-change)
  ;; As a frame hook is called: within the game's stack bound, and an
  ;; error reported (to the REPL when the game is served, else on the
  ;; warning port) instead of ending the run.
  (parameterize ((hook-error-reporter (or (hook-error-reporter) report-to-warning-port)))
    (call-reporting (lambda ()
                      (format #f "the procedure watching ~a raised an error in frame ~a; it stays watching"
                              path (game-frame game)))
                    (lambda () (call-bounded game "watch-file! on-change" (lambda () (on-change path))))
                    (lambda () #f))))

(define (poll-watched-files! game)
  "Call the procedures of GAME's watched files that changed since they were
last looked at (watch-file!), if watch-poll-interval seconds have passed
since the last look; else do nothing, and touch no file. The game loop calls
it once a frame."
  (unless (game? game) (check-game "poll-watched-files!" game))  ; every frame: no call unless refused
  (let ((live (game-live game)))
    (when (and live (or (live-maps? live) (pair? (live-files live))))
      (let ((now (get-internal-real-time)))
        (when (>= now (live-next-look live))
          (live-next-look-set! live (+ now (inexact->exact
                                            (round (* (watch-poll-interval) internal-time-units-per-second)))))
          ;; The scene may have a new map since the last look (a new level).
          (when (live-maps? live) (watch-scene-map! game live))
          (look-at-files! game live)
          (when (live-stale? live)
            (live-stale?-set! live #f)
            (reload-scene-map! game live)))))))

(define (look-at-files! game live)
  ;; The changes are all found first: a procedure may watch or unwatch.
  (let ((changed (let collect ((files (live-files live)) (acc '()))
                   (if (null? files)
                       (reverse acc)
                       (let* ((w (car files)) (stamp (file-stamp (watched-path w))))
                         (if (equal? stamp (watched-stamp w))
                             (collect (cdr files) acc)
                             (begin
                               (watched-stamp-set! w stamp)
                               ;; Removed: nothing to read yet; its return is the change.
                               (collect (cdr files) (if stamp (cons w acc) acc)))))))))
    (for-each (lambda (w)
                (for-each (lambda (on-change)
                            ;; … unless an earlier one unwatched it.
                            (when (memq w (live-files live))
                              (call-on-change game (watched-path w) on-change)))
                          (watched-callbacks w)))
              changed)))

(define (forget-callback! live path on-change)
  ;; PATH no longer watched by ON-CHANGE; nor at all, when it was the last.
  (let ((watched (find (lambda (w) (string=? (watched-path w) path)) (live-files live))))
    (when watched
      (watched-callbacks-set! watched (remove (lambda (p) (eq? p on-change)) (watched-callbacks watched)))
      (when (null? (watched-callbacks watched))
        (live-files-set! live (remove (lambda (w) (eq? w watched)) (live-files live)))))))

;;; ---------------------------------------------------------------- maps

(define tilemap-source (@@ (downstroke tilemap) %tilemap-source))
(define tilemap-origin (@@ (downstroke tilemap) %tilemap-origin))

(define (scene-map game)
  ;; The current scene's map, or #f.
  (let ((scene (game-scene game)))
    (and scene (scene-tilemap scene))))

(define (watch-scene-map! game live)
  ;; The files of the current scene's map watched, and those of a map it no
  ;; longer has not.
  (let* ((tm (scene-map game))
         (origin (and tm (tilemap-origin tm)))
         (files (if origin (cdr origin) '()))
         (old (live-map-files live))
         (watcher (live-map-watcher live)))
    (unless (eq? files old)
      (for-each (lambda (f) (unless (member f files) (forget-callback! live f watcher))) old)
      (for-each (lambda (f) (watch-file! game f watcher)) files)
      (live-map-files-set! live files))))

(define (forget-scene-map! live)
  (for-each (lambda (f) (forget-callback! live f (live-map-watcher live))) (live-map-files live))
  (live-map-files-set! live '())
  (live-stale?-set! live #f))

(define (game-watch-maps! game on?)
  "Watch (ON? true) or stop watching (#f) the files GAME's current scene's
map was read from: the map, its tilesets, templates and pictures, and its
project. When one changes on disk, the map is read again between two frames
and put into the current scene (reload-map!); the scenes kept for
game-rewind! keep the map they had. The watched map follows the scene's: a
new level's map is watched from the next look. New games watch their maps
when watch-default is true (the host's --watch, on by default in a window
and in a game served to a REPL)."
  (check-game "game-watch-maps!" game)
  (let ((live (live-of game)))
    (live-maps?-set! live (and on? #t))
    (if on? (watch-scene-map! game live) (forget-scene-map! live))
    *unspecified*))

(define (game-watching-maps? game)
  "Whether GAME watches its maps' files (game-watch-maps!)."
  (check-game "game-watching-maps?" game)
  (let ((live (game-live game)))
    (and live (live-maps? live))))

(define* (reload-map! #:optional (game (current-game)))
  "Read the map of GAME's current scene (by default the game running) again
from its files now, re-apply to it the tile edits the game made
(tilemap-set-tile), and put it into the current scene, entities and all
else kept: #t. An edit whose cell or gid the new map no longer has is
dropped with a warning naming the layer and the cell. A map that does not
load leaves the scene as it was, its error on the warning port (to the REPL
when the game is served) and over the game's picture until a reload
succeeds: #f. #f too when the scene has no map read from a file. The scenes
kept for game-rewind! keep the map they had: rewinding past a reload shows
the old map."
  (check-game "reload-map!" game)
  (reload-scene-map! game (live-of game)))

(define (load-source source)
  ;; The map as SOURCE, its (path solid-gids max-cells max-bytes strict?
  ;; project), says to load it.
  (apply load-tilemap (car source)
         (append-map list '(#:solid-gids #:max-cells #:max-bytes #:strict? #:project) (cdr source))))

(define (reload-scene-map! game live)
  (let* ((tm (scene-map game))
         (source (and tm (tilemap-source tm))))
    (and source
         (let ((fresh (catch #t
                        (lambda () (load-source source))
                        (lambda (key . args) (map-failed! live (car source) key args) #f))))
           (and fresh
                (begin
                  (game-scene-set! game (update-scene (game-scene game) #:tilemap (with-edits tm fresh)))
                  (live-error-set! live #f)
                  ;; Its files may have changed too (a tileset added).
                  (when (live-maps? live) (watch-scene-map! game live))
                  #t))))))

(define (map-failed! live file key args)
  (let ((text (format #f "the map ~a did not load; the game runs on with the map it had:~%~a"
                      file (error-text key args))))
    (live-error-set! live text)
    ((or (hook-error-reporter) report-to-warning-port) (string-append "downstroke: reload-map!: " text))))

(define (with-edits tm fresh)
  ;; FRESH with the cells TM's edits changed (those that differ from TM as
  ;; loaded) changed alike, where FRESH still has them.
  (let ((loaded (car (tilemap-origin tm))))
    (if loaded
        (fold (lambda (edit m) (apply re-edit m edit)) fresh (%tilemap-edits loaded tm))
        fresh)))

(define (re-edit m layer col row gid)
  (catch #t
    (lambda () (tilemap-set-tile m col row gid layer))
    (lambda (key . args)
      (format (current-warning-port)
              "reload-map!: warning: the game's edit of tile layer ~a, cell (~a, ~a) (gid ~a) is dropped: ~a~%"
              layer col row gid (error-message key args))
      m)))

(define (error-message key args)
  ;; An scm-error's message alone, without the procedure it names.
  (if (and (= (length args) 4) (string? (cadr args)) (list? (caddr args)))
      (apply format #f (cadr args) (caddr args))
      (string-trim-right (error-text key args))))

;;; Over the game's picture while a reload has failed: what failed, in the
;;; lines that fit.

;; The most lines of the error shown (9 px each): the file, and the error's
;; first lines, a long one wrapped; the rest is on the warning port.
(define max-error-lines 6)

(define (wrapped line columns)
  ;; LINE in pieces of at most COLUMNS characters.
  (if (<= (string-length line) columns)
      (list line)
      (cons (substring line 0 columns) (wrapped (substring line columns) columns))))

(define (draw-reload-error! game)
  ;; Called by each render tick, after the game's render:.
  (let ((live (game-live game)) (display (game-display game)))
    (when (and live display (live-error live))
      (let* ((columns (max 1 (- (quotient (game-width game) 6) 2)))  ; 6 px a letter
             (lines (append-map (lambda (l) (wrapped l columns))
                                (string-split (string-trim-right (live-error live)) #\newline)))
             (shown (list-head lines (min max-error-lines (length lines)))))
        (parameterize ((current-display display))
          (draw-label (string-join shown "\n") 4 4 '(255 96 96)))))))
