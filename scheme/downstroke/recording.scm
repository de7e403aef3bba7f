;; SPDX-License-Identifier: MIT
;;; (downstroke recording) — replaying an input script and recording the
;;; input played, so that a session replays frame for frame.
;;; docs/engine.org, "Determinism: scene-hash and replaying input".
(define-module (downstroke recording)
  #:use-module (srfi srfi-1)
  #:use-module (srfi srfi-9)
  #:use-module (downstroke tool-files)
  #:use-module (downstroke game)
  #:use-module (downstroke input)
  #:use-module ((downstroke pause) #:select (input-clock))
  #:export (scripted-held! record-input! game-input-log input-log->script
            record-input read-input-script
            empty-input-log input-log-full-at
            ;; The log's parts, for a test that fills it up to its bound.
            *max-input-changes* make-input-log input-log-changes))

;;; Replaying: a cursor into the script, kept from frame to frame, so a
;;; replay walks its script once. Walking it from its head every frame made
;;; a replay quadratic: 10^5 key frames took 27 s (docs/limits.org,
;;; "Recordings").
(define-record-type <script-cursor>
  (make-script-cursor script ahead held since)
  script-cursor?
  (script cursor-script)                  ; the script it walks
  (ahead cursor-ahead cursor-ahead-set!)  ; the entries not passed yet
  (held cursor-held cursor-held-set!)     ; the actions of the last entry passed; () before the first
  (since cursor-since cursor-since-set!)) ; that entry's frame; -1 before the first

(define (scripted-held! game frame)
  ;; The actions of the last script entry at or before FRAME: entries are
  ;; key frames, in increasing order (check-input-script). The cursor holds
  ;; for any frame from its last key frame on; an earlier frame (a rewind)
  ;; or another script (play input:) starts a walk from the head.
  (let* ((script (game-input-script game))
         (kept (game-script-cursor game))
         (cursor (if (and kept (eq? (cursor-script kept) script) (>= frame (cursor-since kept)))
                     kept
                     (let ((fresh (make-script-cursor script script '() -1)))
                       (game-script-cursor-set! game fresh)
                       fresh))))
    (let pass ()
      (let ((ahead (cursor-ahead cursor)))
        (when (and (pair? ahead) (<= (caar ahead) frame))
          (cursor-held-set! cursor (with-clicked-actions (cdar ahead) (game-bindings game)))
          (cursor-since-set! cursor (caar ahead))
          (cursor-ahead-set! cursor (cdr ahead))
          (pass))))
    (cursor-held cursor)))


;;; Recording input, to replay a run exactly (a bug report, a determinism test).

;;; The input log: each change of the actions held, as (frame . held) from
;;; that frame on, newest first. Every change is kept, from frame 0 on, up
;;; to a bound; a log that reaches it stops there and says so, and a
;;; recording of it replays up to that frame and quits. (It used to keep the
;;; newest 65536 changes, cut from 131072: a long session was then recorded
;;; from its middle and replayed as if that were frame 0.)
(define-record-type <input-log>
  (make-input-log count changes full-at)
  input-log?
  (count input-log-count)        ; how many changes it holds
  (changes input-log-changes)    ; (frame . held) at each change, newest first
  (full-at input-log-full-at))   ; the first frame it did not record, once at the bound; else #f

(define empty-input-log (make-input-log 0 '() #f))

;; The bound is for memory: a change of a key or two keeps about 70 bytes,
;; one with the pointer (its (mouse x y buttons) entry) about 150. Moving
;; the pointer changes the input every frame, so 2^21 changes are 9.7 hours
;; of it at 60 frames a second, in about 320 MB; keys alone change a few
;; times a second, days of play. (Figures: docs/limits.org, "Recordings".)
(define *max-input-changes* (expt 2 21))

(define (forget-from log frame)
  ;; A rewind replays from an earlier frame: forget what was recorded from
  ;; it on (and that the log was full, if it filled there or later).
  (let ((changes (input-log-changes log)) (full-at (input-log-full-at log)))
    (if (or (and (pair? changes) (>= (caar changes) frame)) (and full-at (>= full-at frame)))
        (let forget ((changes changes) (count (input-log-count log)))
          (if (and (pair? changes) (>= (caar changes) frame))
              (forget (cdr changes) (- count 1))
              (make-input-log count changes #f)))
        log)))

(define (record-input! game frame held)
  (let* ((log (forget-from (%game-input-log game) frame))
         (changes (input-log-changes log)))
    (%game-input-log-set!
     game
     (cond ((and (pair? changes) (lset= equal? (cdar changes) held)) log)
           ((input-log-full-at log) log)
           ((< (input-log-count log) *max-input-changes*)
            (make-input-log (+ (input-log-count log) 1) (cons (cons frame held) changes) #f))
           (else
            (format (current-error-port)
                    "downstroke: the input log holds ~a changes, its bound: the input from frame ~a on is not recorded, and a recording (record-input, --record) replays frames 0 to ~a and quits~%"
                    *max-input-changes* frame (- frame 1))
            (make-input-log (input-log-count log) changes frame))))))

(define (game-input-log game)
  "The actions held in each frame played so far, one list per frame, from
frame 0 on (and one per tick the game was paused, game-paused-set!): give it
to input-log->script to replay a played session headless, frame for frame. A log that reached its bound (2^21 changes of
input) ends at the frame before the first it did not record."
  (let* ((log (%game-input-log game))
         (end (if (input-log-full-at log) (min (input-log-full-at log) (input-clock game)) (input-clock game))))
    (let loop ((changes (input-log-changes log)) (frame end) (acc '()))
      ;; CHANGES is newest first: each (start . held) holds from START on.
      (if (null? changes)
          acc
          (let* ((start (caar changes)) (n (max 0 (- frame start))))
            (loop (cdr changes) (min frame start) (append (make-list n (cdar changes)) acc)))))))

(define (recorded-script game)
  ;; input-log->script of game-input-log, straight from the changes, in
  ;; time and memory proportional to their number (game-input-log takes a
  ;; pair a frame played). Changes at or after the game's frame were undone
  ;; by a rewind. A full log's script ends in quit at the first frame it did
  ;; not record, so its replay stops where the recording did.
  (let* ((log (%game-input-log game))
         (full-at (input-log-full-at log))
         (end (if full-at (min full-at (input-clock game)) (input-clock game)))
         (kept (drop-while (lambda (c) (>= (car c) end)) (input-log-changes log))))
    (reverse (if (and full-at (< full-at (input-clock game))) (cons (list full-at 'quit) kept) kept))))


(define (input-log->script log)
  "The input script that replays LOG, a list of the actions held in each
frame from frame 0 on: a key frame (frame . actions) for frame 0 and for
every frame whose set of held actions differs from the frame before."
  (let loop ((log log) (frame 0) (previous #f) (acc '()))
    (cond ((null? log) (reverse acc))
          ((and previous (lset= equal? previous (car log))) (loop (cdr log) (+ frame 1) previous acc))
          (else (loop (cdr log) (+ frame 1) (car log) (cons (cons frame (car log)) acc))))))

(define (record-input game file)
  "Write GAME's input so far to FILE as an input script (input-log->script
of game-input-log), which read-input-script reads back: a session played in
a window replays headless, frame for frame. `downstroke --window --record
FILE' writes it when the game ends. Every change of input is kept up to
2^21; a session with more is written up to the frame the bound was reached,
where the script quits, and record-input says so on the error port."
  (check-game "record-input" game)
  (unless (string? file)
    (scm-error 'wrong-type-arg "record-input" "file: expected a string, got ~S" (list file) #f))
  (let* ((script (recorded-script game))
         (full-at (input-log-full-at (%game-input-log game)))
         (cut (and full-at (< full-at (input-clock game)) full-at)))  ; where the script quits
    (call-with-output-file/whole "record-input" file
      (lambda (port)
        (format port ";;; The input of ~s, ~a frames, as an input script (record-input).~%" (game-title game)
                (input-clock game))
        (when cut
          (format port ";;; Frames 0 to ~a only: the input log reached its bound of ~a changes, and the script quits at frame ~a.~%"
                  (- cut 1) *max-input-changes* cut))
        ;; An entry a line: Guile's write of the whole list takes time
        ;; quadratic in its length (0.9 s for 25 000 entries, 3.2 s for
        ;; 50 000, 8.5 to 12 s for 10^5).
        (display "(" port)
        (let write-entries ((entries script) (first? #t))
          (when (pair? entries)
            (unless first? (display "\n " port))
            (write (car entries) port)
            (write-entries (cdr entries) #f)))
        (display ")\n" port)))
    (when cut
      (format (current-error-port)
              "downstroke: record-input: ~s holds frames 0 to ~a of ~a: the input log reached its bound of ~a changes, and the script quits at frame ~a~%"
              file (- cut 1) (input-clock game) *max-input-changes* cut))
    script))

;; The largest input script read-input-script reads: a recording at the
;; input log's bound, 2^21 changes, each a line of at most about 120 bytes
;; (a frame number, a few actions, the pointer with its buttons), is 252 MB.
(define max-input-script-bytes (* 256 1024 1024))

(define (error-args->text key args)
  ;; What a caught error says, as Guile prints it (for a read error, with
  ;; the file, line and column); KEY alone when its arguments are not the
  ;; usual (who message message-args …).
  (or (and (= (length args) 4) (string? (cadr args)) (list? (caddr args))
           (false-if-exception (apply format #f (cadr args) (caddr args))))
      (object->string key)))

(define (skip-blanks-and-comments port)
  ;; Past white space and ; comments, to where a datum would start.
  (let ((c (peek-char port)))
    (cond ((eof-object? c))
          ((char-whitespace? c) (read-char port) (skip-blanks-and-comments port))
          ((char=? c #\;)
           (let to-line-end ()
             (let ((c (read-char port)))
               (unless (or (eof-object? c) (char=? c #\newline)) (to-line-end))))
           (skip-blanks-and-comments port)))))

(define (read-one-datum file port)
  ;; PORT's one datum (the eof object for none), refusing text after it: it
  ;; would be silently ignored, and is more likely a script pasted twice or
  ;; cut than anything meant.
  (let ((datum (read port)))
    (skip-blanks-and-comments port)
    (let* ((line (+ 1 (port-line port))) (column (+ 1 (port-column port)))
           (more (read port)))  ; past a #| |# or #; comment: the end, or more
      (unless (eof-object? more)
        (scm-error 'misc-error "read-input-script"
                   "~A:~A:~A: text after the input script (a file holds one list of (frame . actions))"
                   (list file line column) #f)))
    datum))

(define (read-input-script file)
  "The input script record-input wrote to FILE, checked as make-game checks
one. FILE must be a regular file (not a FIFO or a device) of at most 256
MiB. A file that cannot be read, or holds text after the script, is refused
with an error naming it, and for text that does not read, the line and
column and what is wrong."
  (unless (string? file)
    (scm-error 'wrong-type-arg "read-input-script" "file: expected a string, got ~S" (list file) #f))
  (check-input-file "read-input-script" file)
  (let ((size (stat:size (stat file))))
    (when (> size max-input-script-bytes)
      (scm-error 'misc-error "read-input-script" "~s: ~a bytes, more than an input script may hold (~a)"
                 (list file size max-input-script-bytes) #f)))
  (let ((script (catch #t
                  (lambda () (call-with-input-file file (lambda (port) (read-one-datum file port))))
                  (lambda (key . args)
                    (if (and (eq? key 'misc-error) (pair? args) (equal? (car args) "read-input-script"))
                        (apply throw key args)
                        (scm-error 'misc-error "read-input-script" "cannot read an input script from ~S: ~a"
                                   (list file (error-args->text key args)) #f))))))
    (let ((script (if (eof-object? script) '() script)))  ; an empty file: no input
      (check-input-script "read-input-script" script)
      script)))
