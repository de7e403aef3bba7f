;; SPDX-License-Identifier: MIT
;;; (downstroke render) — drawing from a game's render: procedure, and how
;;; the host asked frames to be shown (headless, a window, captures); it
;;; also offers the loading of sounds ((downstroke sound)) and the default
;;; input map ((downstroke input)). docs/render.org, "Drawing from =render:=".
(define-module (downstroke render)
  #:use-module (downstroke native)
  #:use-module ((downstroke entity) #:select (entity-set))
  #:use-module ((downstroke sound) #:select (load-sound load-music))
  #:use-module ((downstroke input) #:select (default-input-map))
  #:export (renderer-available? display-mode capture-directory window-scale window-fullscreen frame-log-file
            record-file
            debug-draw-default
            current-display
            draw-rect draw-line draw-sprite draw-text draw-label text-width
            color-rgba
            entity-animate)
  ;; Sounds are (downstroke sound)'s and input maps (downstroke input)'s;
  ;; this module has offered them since before those were split out.
  #:re-export (default-input-map load-sound load-music))

(define (renderer-available?)
  "Whether this build can draw (it was built with SDL2)."
  (%renderer?))

;; Set by the host from its command line: 'headless (the default: nothing is
;; drawn unless game-capture asks), 'window (--window), or 'capture
;; (--capture DIR: every frame is drawn off-screen and written to DIR).
(define display-mode (make-parameter 'headless))
(define capture-directory (make-parameter #f))
;; --scale N: the window's whole scale factor; 0 fits the screen.
(define window-scale (make-parameter 0))
;; --frame-log FILE: the window loop writes a line per presented frame, "ms
;; step alpha dropped" (the frame's clock: ms since the loop began when it
;; took its steps and α; the game's frame counter,
;; the share of a step drawn past it, and the steps a stall's backlog lost
;; so far), to check its pacing.
(define frame-log-file (make-parameter #f))
;; --record FILE: when a windowed game ends, its input is written there as
;; an input script (record-input), for a test to replay.
(define record-file (make-parameter #f))
;; --fullscreen: the window opens fullscreen (F11 or Alt+Return toggles it).
(define window-fullscreen (make-parameter #f))
;; --debug: every game starts with the debug overlay on.
(define debug-draw-default (make-parameter #f))

;; The display of the game being run: where draw-* queue their commands.
(define current-display (make-parameter #f))

(define named-colors
  ;; The native table (src/render/color.hpp), which #:color reads too; asked
  ;; for when first needed, as a build without the renderer has none.
  (let ((table #f))
    (lambda ()
      (unless table (set! table (%named-colors)))
      table)))

(define (color-rgba who color)
  "COLOR as the (r g b [a]) list the drawing procedures take, or an error
naming WHO (the procedure asking) when it is not a colour: a list of 3 or 4
integers 0–255 as it is, or one of the names white black red green blue
yellow cyan magenta orange grey."
  (cond ((symbol? color)
         (or (assq-ref (named-colors) color)
             (scm-error 'wrong-type-arg who "color: no color is named ~S (try ~S)"
                        (list color (map car (named-colors))) #f)))
        (else color)))

;; The display to draw into, or #f in a build without the renderer, where a
;; running game has none (headless games still run there: their render:
;; procedures draw nothing).
(define (display-for who)
  (cond ((current-display))
        ((renderer-available?)
         (scm-error 'misc-error who "no game is being drawn: call it from a game's render: procedure" '() #f))
        (else #f)))

(define* (draw-rect x y w h #:optional (color 'white) #:key (fill? #f) (space 'world))
  "Draw a W × H rectangle with its top-left corner at (X, Y): its outline, or
filled when FILL? is true. COLOR is a name ('red) or (r g b [a]); alpha
below 255 blends. SPACE is 'world (moves with the camera) or 'screen (a HUD)."
  (let ((display (display-for "draw-rect")))
    (when display (%draw-rect! display x y w h (color-rgba "draw-rect" color) fill? space))))

(define* (draw-line x0 y0 x1 y1 #:optional (color 'white) #:key (space 'world))
  "Draw a one-pixel line from (X0, Y0) to (X1, Y1), both ends included."
  (let ((display (display-for "draw-line")))
    (when display (%draw-line! display x0 y0 x1 y1 (color-rgba "draw-line" color) space))))

(define* (draw-sprite gid x y #:key (space 'world) (flip-x? #f))
  "Draw the tile picture GID (of the scene's map's tilesets; flip bits
honoured) with its top-left corner at (X, Y)."
  (let ((display (display-for "draw-sprite")))
    (when display (%draw-sprite! display (if flip-x? (logxor gid #x80000000) gid) x y space))))

(define* (draw-text text x y #:optional (color 'white) #:key (scale 1) (space 'world))
  "Draw TEXT in the built-in 5×7 font with its top-left corner at (X, Y);
each font pixel is SCALE × SCALE, each letter 6 × SCALE wide, and a newline
starts a line 9 × SCALE lower."
  (let ((display (display-for "draw-text")))
    (when display (%draw-text! display text x y (color-rgba "draw-text" color) scale space))))

(define* (text-width text #:key (scale 1))
  "How many pixels wide TEXT is in the built-in font at SCALE: 6 × SCALE per
letter of its longest line (for centring or right-aligning a label)."
  (* 6 scale (apply max 0 (map string-length (string-split text #\newline)))))

;; A label's plate: dark and translucent, so the text reads over any tile.
(define label-plate '(22 17 31 150))
(define label-shadow '(22 17 31))

(define* (draw-label text x y #:optional (color 'white) #:key (scale 1) (space 'screen))
  "Draw TEXT as draw-text does, with a one-pixel shadow on a translucent dark
plate, so it reads over any map: for a score or a message. SPACE defaults
to 'screen (a HUD); the plate reaches 2 px beyond the text on every side."
  (let ((lines (length (string-split text #\newline))))
    (draw-rect (- x 2) (- y 2) (+ (text-width text #:scale scale) 3)
               (+ (* 9 scale (- lines 1)) (* 7 scale) 4) label-plate #:fill? #t #:space space)
    (draw-text text (+ x scale) (+ y scale) label-shadow #:scale scale #:space space)
    (draw-text text x y color #:scale scale #:space space)))

(define (entity-animate entity animation frame)
  "ENTITY playing ANIMATION from FRAME on: #:animation set to ANIMATION (a
gid whose tile has a Tiled animation, or a list of (gid . ms)) and
#:animation-start to FRAME (an exact integer, a frame number). Pass the
game's frame to start it now, and again to restart it; entities given
different frames play out of phase. The picture depends only on the scene
and the frame drawn, so rewinding shows it again as it was."
  (unless (exact-integer? frame)
    (scm-error 'wrong-type-arg "entity-animate" "frame: expected an exact integer (a frame number), got ~S"
               (list frame) #f))
  (entity-set (entity-set entity #:animation animation) #:animation-start frame))
