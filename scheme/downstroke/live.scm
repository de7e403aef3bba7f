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
  #:use-module ((srfi srfi-1) #:select (find remove))
  #:use-module (srfi srfi-9)
  #:use-module (downstroke arity)
  #:use-module (downstroke game)
  #:use-module (downstroke hook-errors)
  #:export (watch-file! unwatch-file! poll-watched-files! watch-poll-interval))

;; The least time, in seconds, between two looks at the watched files. A
;; second is what "a saved file shows within a second" needs, and a look
;; costs a stat per file (some µs each): once a second, a frame in sixty
;; pays it. Tests set it to 0, so that every poll looks.
(define watch-poll-interval (make-parameter 1))

;;; A game's live state (game-live): the watched files, in the order they
;;; were first watched, and the real time (internal units) of the next look.
(define-record-type <live>
  (make-live files next-look)
  live?
  (files live-files live-files-set!)          ; a list of <watched>
  (next-look live-next-look live-next-look-set!))

(define-record-type <watched>
  (make-watched path stamp callbacks)
  watched?
  (path watched-path)
  (stamp watched-stamp watched-stamp-set!)            ; (file-stamp path) when last looked at
  (callbacks watched-callbacks watched-callbacks-set!))  ; procedures of (path), in the order given

(define (live-of game)
  (or (game-live game)
      (let ((live (make-live '() 0)))
        (game-live-set! game live)
        live)))

(define (file-stamp path)
  ;; What changes when PATH is written or replaced, or #f while it is absent
  ;; (or unreadable): a file removed and made again is then one change.
  (let ((st (stat path #f)))
    (and st (list (stat:dev st) (stat:ino st) (stat:size st) (stat:mtime st) (stat:mtimensec st)))))

(define (absolute path)
  (if (absolute-file-name? path) path (string-append (getcwd) "/" path)))

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
  (let ((live (game-live game)))
    (when (and live (pair? (live-files live)))
      (let ((now (get-internal-real-time)))
        (when (>= now (live-next-look live))
          (live-next-look-set! live (+ now (inexact->exact
                                            (round (* (watch-poll-interval) internal-time-units-per-second)))))
          (look-at-files! game live))))))

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
