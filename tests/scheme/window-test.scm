;;; A real window: `downstroke --window --scale 2 --repl-server S' under
;;; Xvfb, the Right arrow held with xdotool (the X server's own key events,
;;; through SDL's keyboard path and the default input map), a screenshot of
;;; the whole display with xwd, read back here: the window shows the game's
;;; picture scaled ×2 pixel-exactly with the box where the held key walked
;;; it; a change made from the REPL shows in the next screenshot; then Escape
;;; quits. Every wait is bounded.
(use-modules (srfi srfi-64) (srfi srfi-1) (ice-9 rdelim) (ice-9 binary-ports) (rnrs bytevectors))

(load "support.scm")

(define host (readlink "/proc/self/exe"))
(define game-script (string-append (getenv "DS_TEST_DATA") "/scripts/window-game.scm"))
(define dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-window-XXXXXX")))
(define background '(24 28 40))

(define (spawn program args out-fd)
  ;; Runs PROGRAM with ARGS, its standard output on OUT-FD (or /dev/null).
  (let ((pid (primitive-fork)))
    (if (zero? pid)
        (begin
          (let ((null (open-fdes "/dev/null" O_RDWR)))
            (dup2 null 0)
            (dup2 (or out-fd null) 1))
          (apply execlp program program args))
        pid)))

;; A display number of our own, free of any other server's.
(define display-number
  (let loop ((n (+ 50 (modulo (getpid) 40))))
    (if (file-exists? (format #f "/tmp/.X11-unix/X~a" n)) (loop (+ n 1)) n)))
(define display-name (format #f ":~a" display-number))
(setenv "DISPLAY" display-name)
(define xvfb (spawn "Xvfb" (list display-name "-screen" "0" "320x240x24" "-nolisten" "tcp") #f))

(define (wait-for ok? seconds)
  (let loop ((tries (* seconds 20)))
    (cond ((ok?) #t)
          ((zero? tries) #f)
          (else (usleep 50000) (loop (- tries 1))))))

(define (read-line-within port seconds)
  ;; The next line, or #f when none comes in time.
  (let ((ready (select (list port) '() '() seconds)))
    (and (pair? (car ready)) (read-line port))))

(define (xwd-pixels file)
  ;; An xwd dump of a TrueColor screen (its header is 25 big-endian words,
  ;; then the window name, the colour map of 12-byte entries, the pixels):
  ;; (width height bytes-per-line bytes-per-pixel little-endian? offset bytevector).
  (let* ((bv (call-with-input-file file get-bytevector-all #:binary #t))
         (u32 (lambda (i) (bytevector-u32-ref bv (* 4 i) (endianness big))))
         (header (u32 0)) (ncolors (u32 19)))
    (list (u32 4) (u32 5) (u32 12) (quotient (u32 11) 8) (zero? (u32 7)) (+ header (* 12 ncolors)) bv)))

(define (screen-pixel shot x y)
  ;; (r g b) of a 24-bit pixel, red in the high byte of its value.
  (let* ((bpl (list-ref shot 2)) (bpp (list-ref shot 3)) (little? (list-ref shot 4))
         (at (+ (list-ref shot 5) (* y bpl) (* bpp x))) (bv (list-ref shot 6))
         (byte (lambda (i) (bytevector-u8-ref bv (+ at i))))
         (v (if little?
                (+ (byte 0) (ash (byte 1) 8) (ash (byte 2) 16))
                (+ (byte (- bpp 1)) (ash (byte (- bpp 2)) 8) (ash (byte (- bpp 3)) 16)))))
    (list (logand (ash v -16) 255) (logand (ash v -8) 255) (logand v 255))))

(test-begin "window")

(test-assert "Xvfb starts" (wait-for (lambda () (file-exists? (format #f "/tmp/.X11-unix/X~a" display-number))) 10))

(define out (pipe))
(define socket-path (string-append dir "/repl.sock"))
(define game (spawn host (list "--window" "--scale" "2" "--repl-server" socket-path game-script)
                    (port->fdes (cdr out))))
(close-port (cdr out))
(define from-game (car out))

(test-equal "the game shows its window" "ready" (read-line-within from-game 20))
;; The pointer over the window: with no window manager, keys go to the window under it.
(system* "xdotool" "mousemove" "160" "120")
(system* "xdotool" "keydown" "Right")
(test-equal "holding Right walks the box to x = 20" "arrived" (read-line-within from-game 20))
(system* "xdotool" "keyup" "Right")
(usleep 300000)  ; a few more frames drawn
(define (screenshot name)
  (let ((file (string-append dir "/" name)))
    (and (zero? (status:exit-val (system* "sh" "-c" (string-append "xwd -root -silent > " file))))
         (xwd-pixels file))))
(define shot (screenshot "screen.xwd"))
(test-assert "xwd takes a screenshot" shot)
(test-equal "the display is 320 × 240" '(320 240) (list-head shot 2))

;; Find the window: the picture's background, 64 × 48 scaled ×2, centred.
(define origin
  (let search ((y 0) (x 0))
    (cond ((>= y 240) #f)
          ((>= x 320) (search (+ y 1) 0))
          ((equal? (screen-pixel shot x y) '(230 60 60)) (cons x y))  ; the red bar's first pixel
          (else (search y (+ x 1))))))
(test-assert "the window shows the game's red bar" origin)
(define (canvas-pixel cx cy)
  (canvas-pixel-of shot cx cy))
(define (canvas-pixel-of shot cx cy)
  ;; The screen's 2 × 2 block for canvas pixel (cx, cy), if all four agree.
  (let* ((x (+ (car origin) (* 2 cx))) (y (+ (cdr origin) (* 2 cy)))
         (block (list (screen-pixel shot x y) (screen-pixel shot (+ x 1) y)
                      (screen-pixel shot x (+ y 1)) (screen-pixel shot (+ x 1) (+ y 1)))))
    (and (every (lambda (p) (equal? p (car block))) block) (car block))))
(when origin
  (test-equal "the window is the picture scaled ×2 and centred" '(96 . 72) origin)
  (test-equal "the red bar spans the width" '(230 60 60) (canvas-pixel 63 3))
  (test-equal "below it, the background" background (canvas-pixel 0 10))
  (test-equal "the box outline where the key walked it (x 20)" '(80 220 100) (canvas-pixel 20 20))
  (test-equal "… its far edge at x 25" '(80 220 100) (canvas-pixel 25 25))
  (test-equal "… and not where it started" background (canvas-pixel 4 21))
  (test-equal "every canvas pixel is one 2 × 2 block: a pixel-exact scale" #t
    (every (lambda (cy) (every (lambda (cx) (and (canvas-pixel cx cy) #t)) (iota 64))) (iota 48))))

;; The REPL moves the box; the next frame drawn shows it.
(define client
  (let ((s (socket PF_UNIX SOCK_STREAM 0)))
    (and (wait-for (lambda () (false-if-exception (begin (connect s AF_UNIX socket-path) #t))) 10) s)))
(test-assert "the REPL server of the windowed game accepts a client" client)
(when client
  (display "(game-scene-set! game (scene-map-entities (game-scene game) (lambda (e) (entity-set e #:x 40))))\n" client)
  (force-output client)
  (usleep 500000)
  (let ((after (screenshot "after-repl.xwd")))
    (test-equal "the REPL's change shows in the window: the box at x 40" '(80 220 100)
      (and after origin (canvas-pixel-of after 40 20)))
    (test-equal "… and no longer at x 20" background (and after origin (canvas-pixel-of after 20 21))))
  (close-port client))

(system* "xdotool" "key" "Escape")
(test-equal "Escape quits the game" "quit" (read-line-within from-game 20))
(define status #f)
(unless (wait-for (lambda ()
                    (let ((r (waitpid game WNOHANG)))
                      (and (> (car r) 0) (begin (set! status (status:exit-val (cdr r))) #t))))
                  10)
  (kill game SIGKILL)
  (waitpid game))
(test-equal "… which exits with status 0" 0 status)
(kill xvfb SIGTERM)
(waitpid xvfb)
(test-end "window")
