;; SPDX-License-Identifier: MIT
;;; Long recordings (issue 45): a replay walks its script once, however many
;;; key frames it has; a recording keeps every change of input from frame 0
;;; on, up to its bound, and past it says so and quits where it stopped.
(use-modules (srfi srfi-64) (srfi srfi-1) (ice-9 ftw) (ice-9 popen) (ice-9 textual-ports) (downstroke) (downstroke testing))

(load "support.scm")

(test-begin "recording")

(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-recording-XXXXXX")))

(define (seconds-since start)
  (exact->inexact (/ (- (get-internal-real-time) start) internal-time-units-per-second)))

;; A game that notes the actions held in each frame in SAMPLES (a list of
;; frames), as (frame . held), in the order the frames ran.
(define (sampler script samples seen)
  (make-game engine-update: #f input-script: script
             update: (lambda (game dt)
                       (when (memv (game-frame game) samples)
                         (set-car! seen (cons (cons (game-frame game) (input-held-actions (game-input game)))
                                              (car seen)))))))

;;; ---------------------------------------------------------------- replay
;; The input changes every frame: one key frame a frame, as when the
;; pointer moves. A replay used to walk the script from its head each
;; frame: 10^5 key frames took 27 s on the machine of docs/limits.org.
(define (moving f) (list (if (even? f) 'right 'left) (list 'mouse (modulo f 640) (quotient f 640) '())))
(define key-frames (map (lambda (f) (cons f (moving f))) (iota 100000)))
(define replay-samples '(0 1 50000 99999))
(define replay-seen (list '()))
(define replay-start (get-internal-real-time))
(game-run! (sampler key-frames replay-samples replay-seen) #:frames 100000)
(define replay-took (seconds-since replay-start))
(test-equal "a replay of 10^5 key frames holds each frame's own actions"
  (map (lambda (f) (cons f (moving f))) replay-samples)
  (reverse (car replay-seen)))
(test-assert (format #f "… and runs in time proportional to them (took ~,2f s; under 5 s)" replay-took)
  (< replay-took 5))

;; A rewind goes back past key frames already passed: the replay takes the
;; script up again from there.
(define rewound-seen '())
(define rewound
  (make-game engine-update: #f history: 10
             input-script: '((0 . (a)) (2 . (b)) (4 . (c)) (6 . (d)))
             update: (let ((rewound? #f))
                       (lambda (game dt)
                         (set! rewound-seen (cons (cons (game-frame game) (input-held-actions (game-input game)))
                                                  rewound-seen))
                         (when (and (= (game-frame game) 7) (not rewound?))
                           (set! rewound? #t)
                           (game-rewind! game 5))))))
(game-run! rewound #:frames 9)
(test-equal "a replay rewound from frame 7 to 2 holds frame 2's actions again, and so on"
  '((0 a) (1 a) (2 b) (3 b) (4 c) (5 c) (6 d) (7 d) (2 b) (3 b) (4 c) (5 c) (6 d) (7 d) (8 d))
  (reverse rewound-seen))

;;; ---------------------------------------------------------------- a long recording
;; More changes than the log once kept (131072, when it cut back to the
;; newest 65536 and the recording began at frame 65537, numbered 0).
(define long-frames 140000)
(define long-script (map (lambda (f) (cons f (moving f))) (iota long-frames)))
(define played (make-game engine-update: #f input-script: long-script))
(game-run! played #:frames long-frames)
(define session (string-append dir "/long.scm"))
(define written (record-input played session))
(test-equal "record-input writes every one of 140000 changes, from frame 0" long-script written)
(test-equal "… as input-log->script of game-input-log says" written (input-log->script (game-input-log played)))
(define read-back (read-input-script session))
(test-equal "read-input-script reads them all back" long-script read-back)
(define long-samples '(0 1 65535 65536 65537 65538 131071 131072 131073 139999))
(define long-seen (list '()))
(game-run! (sampler read-back long-samples long-seen) #:frames long-frames)
(test-equal "… and the replay holds what the session held, at the start, around the old cuts and at the end"
  (map (lambda (f) (cons f (moving f))) long-samples)
  (reverse (car long-seen)))

;;; ---------------------------------------------------------------- the bound
;; 2^21 changes (docs/limits.org, "Recordings"). Playing that many takes
;; seconds and hundreds of MB, so the log is told it already holds all but
;; one of them: the count, not the changes, is what the bound is checked on.
(define bound (@@ (downstroke engine) *max-input-changes*))
(test-equal "the bound is 2^21 changes" 2097152 bound)
;; A game played 3 frames (3 changes), its log then told it holds one
;; change less than the bound.
(define (almost-full script)
  (let ((game (make-game engine-update: #f history: 10 input-script: script)))
    (game-run! game #:frames 3)
    (let ((log ((@@ (downstroke engine) %game-input-log) game)))
      ((@@ (downstroke engine) %game-input-log-set!)
       game ((@@ (downstroke engine) make-input-log) (- bound 1) ((@@ (downstroke engine) input-log-changes) log) #f)))
    game))
(define full (almost-full '((0 . (a)) (1 . (b)) (2 . (c)) (3 . (d)) (4 . (e)) (5 . (f)))))
(define filling
  (call-with-output-string
   (lambda (port) (with-error-to-port port (lambda () (game-run! full #:frames 8))))))
(test-equal "the change past the bound is not recorded, and the game says so once, naming the frame"
  "downstroke: the input log holds 2097152 changes, its bound: the input from frame 4 on is not recorded, and a recording (record-input, --record) replays frames 0 to 3 and quits\n"
  filling)
(test-equal "… the game runs on" 8 (game-frame full))
(test-equal "game-input-log ends at the last frame recorded" '((a) (b) (c) (d)) (game-input-log full))
(define cut-file (string-append dir "/cut.scm"))
(define cut-script #f)
(define writing
  (call-with-output-string
   (lambda (port) (with-error-to-port port (lambda () (set! cut-script (record-input full cut-file)))))))
(test-equal "record-input writes frames 0 to 3 and quit at frame 4"
  '((0 a) (1 b) (2 c) (3 d) (4 quit)) cut-script)
(test-equal "… says so where it is run"
  (format #f "downstroke: record-input: ~s holds frames 0 to 3 of 8: the input log reached its bound of 2097152 changes, and the script quits at frame 4\n"
          cut-file)
  writing)
(test-equal "… and in the file"
  (string-append ";;; The input of \"Downstroke\", 8 frames, as an input script (record-input).\n"
                 ";;; Frames 0 to 3 only: the input log reached its bound of 2097152 changes, and the script quits at frame 4.\n"
                 "((0 a)\n (1 b)\n (2 c)\n (3 d)\n (4 quit))\n")
  (call-with-input-file cut-file (lambda (p) (get-string-all p))))
(define cut-seen (list '()))
(define cut-replay (sampler (read-input-script cut-file) '(0 3 4) cut-seen))
(game-run! cut-replay #:frames 8)
(test-equal "its replay holds what was recorded and stops where the recording did"
  '(4 ((0 a) (3 d))) (list (game-frame cut-replay) (reverse (car cut-seen))))

;; A rewind to the frame the log filled at forgets that it filled: with
;; frame 4 now holding what frame 3 held, there is no change until frame 5.
(define refilled (almost-full '((0 . (a)) (1 . (b)) (2 . (c)) (3 . (d)) (4 . (e)))))
(define refilled-file (string-append dir "/refilled.scm"))
(define refilled-script #f)
(define refilling
  (call-with-output-string
   (lambda (port)
     (with-error-to-port port
       (lambda ()
         (game-run! refilled #:frames 6)                ; fills at frame 4
         (game-rewind! refilled 2)                      ; back to frame 4
         (play refilled #:frames 7 #:input '((0 . (a)) (1 . (b)) (2 . (c)) (3 . (d)) (5 . (f))))
         (set! refilled-script (record-input refilled refilled-file)))))))
(test-equal "a rewind to the frame the log filled at records from there again, up to the bound"
  '((0 a) (1 b) (2 c) (3 d) (5 quit))
  refilled-script)
(test-equal "… game-input-log with it" '((a) (b) (c) (d) (d)) (game-input-log refilled))
(test-equal "… and each filling is said"
  (string-append
   "downstroke: the input log holds 2097152 changes, its bound: the input from frame 4 on is not recorded, and a recording (record-input, --record) replays frames 0 to 3 and quits\n"
   "downstroke: the input log holds 2097152 changes, its bound: the input from frame 5 on is not recorded, and a recording (record-input, --record) replays frames 0 to 4 and quits\n"
   (format #f "downstroke: record-input: ~s holds frames 0 to 4 of 7: the input log reached its bound of 2097152 changes, and the script quits at frame 5\n"
           refilled-file))
  refilling)

(test-equal "record-input refuses what is not a game, naming it"
  "In procedure record-input: game: expected a game (make-game), got 5\n"
  (error-text (lambda () (record-input 5 (string-append dir "/never.scm")))))

;;; ---------------------------------------------------------------- files
;; Only regular files: a FIFO would block for ever, /dev/zero be read
;; without end. Guile has no mkfifo: mkfifo(1) makes it.
(define fifo (string-append dir "/fifo.scm"))
(system* "mkfifo" fifo)
(test-equal "read-input-script refuses a FIFO, naming it, without blocking"
  (format #f "In procedure read-input-script: ~s: it is a FIFO, not a regular file\n" fifo)
  (error-text (lambda () (read-input-script fifo))))
(test-equal "… and a device, without reading it"
  "In procedure read-input-script: \"/dev/zero\": it is a character device, not a regular file\n"
  (error-text (lambda () (read-input-script "/dev/zero"))))
(test-equal "… and a folder"
  (format #f "In procedure read-input-script: ~s: it is a directory, not a regular file\n" dir)
  (error-text (lambda () (read-input-script dir))))
(test-equal "… and a file that is not there, saying so"
  (format #f "In procedure read-input-script: ~s: it cannot be read (No such file or directory)\n"
          (string-append dir "/absent.scm"))
  (error-text (lambda () (read-input-script (string-append dir "/absent.scm")))))
(define small (make-game engine-update: #f input-script: '((0 right) (3 left) (5 quit))))
(game-run! small)
(test-equal "record-input refuses a FIFO, naming it"
  (format #f "In procedure record-input: cannot write ~s: it is a FIFO, not a regular file\n" fifo)
  (error-text (lambda () (record-input small fifo))))
(test-equal "… and a folder that does not exist"
  (format #f "In procedure record-input: cannot write ~s: its folder ~s does not exist\n"
          (string-append dir "/absent/rec.scm") (string-append dir "/absent"))
  (error-text (lambda () (record-input small (string-append dir "/absent/rec.scm")))))
(define small-file (string-append dir "/small.scm"))
(record-input small small-file)
(test-equal "record-input writes the file whole (no temporary file left), read back as it was"
  '(("small.scm") ((0 right) (3 left)))
  (list (scandir dir (lambda (n) (string-prefix? "small" n))) (read-input-script small-file)))

;; A full disk without root: a file size limit of 0 makes every write fail
;; (EFBIG; SIGXFSZ ignored, as a shell passes it on); the error goes through
;; a pipe, which the limit leaves alone.
(define full-script (string-append dir "/full-disk.scm"))
(define full-target (string-append dir "/full-rec.scm"))
(call-with-output-file full-script
  (lambda (port) (format port "(record-input (make-game engine-update: #f) ~s)~%" full-target)))
(test-equal "record-input onto a full disk names the file and why, and leaves no file, not even a temporary one"
  (list 1 (format #f "In procedure record-input: cannot write ~s: File too large" full-target) '())
  (let* ((p (open-pipe* OPEN_READ "/bin/sh" "-c"
             (string-append "trap '' XFSZ; ulimit -f 0; exec '" (readlink "/proc/self/exe")
                            "' --no-auto-compile '" full-script "' 2>&1")))
         (text (get-string-all p))
         (status (status:exit-val (close-pipe p))))
    (list status (car (string-split text #\newline)) (scandir dir (lambda (n) (string-prefix? "full-rec" n))))))
(delete-file full-script)

;; --record writes as the game runs: a windowed game (SDL's dummy video
;; driver) that ends itself with primitive-exit after 6 s, so running no
;; cleanup, has its recording of the first 5 s on disk.
(define recorded (string-append dir "/recorded.scm"))
(define exiting (string-append dir "/exiting.scm"))
(call-with-output-file exiting
  (lambda (port)
    (display "(define start (get-internal-real-time))
(game-run! (make-game width: 64 height: 48 engine-update: #f
  update: (lambda (game dt)
            (when (> (- (get-internal-real-time) start) (* 6 internal-time-units-per-second))
              (primitive-exit 3)))))
" port)))
(when (renderer-available?)
  (test-equal "a --record game that exits part-way, running no cleanup, has exited so"
    3 (status:exit-val (system (string-append "SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy '" (readlink "/proc/self/exe")
                                              "' --window --record '" recorded "' '" exiting "' >/dev/null 2>&1"))))
  (test-equal "… and its recording holds what was played, read back as an input script"
    '((0)) (read-input-script recorded))
  (test-equal "--record into a folder that does not exist is refused before the game starts"
    (list 2 (format #f "downstroke: --record: cannot write ~s: its folder ~s does not exist\n"
                    (string-append dir "/absent/r.scm") (string-append dir "/absent")))
    (let* ((err (string-append dir "/err"))
           (status (system (string-append "SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy '" (readlink "/proc/self/exe")
                                          "' --window --record '" dir "/absent/r.scm' '" exiting "' 2>'" err "'")))
           (text (call-with-input-file err (@ (ice-9 textual-ports) get-string-all))))
      (delete-file err)
      (list (status:exit-val status) text))))

(for-each delete-file (filter file-exists? (list fifo small-file recorded exiting)))
(for-each delete-file (list session cut-file refilled-file))
(rmdir dir)

(test-end "recording")
