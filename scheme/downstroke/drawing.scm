;; SPDX-License-Identifier: MIT
;;; (downstroke drawing) — drawing a game's frame into its display: the
;;; debug overlay, captures to PNG and reading a pixel back.
;;; docs/render.org, "What is drawn" and "The debug overlay".
(define-module (downstroke drawing)
  #:use-module ((srfi srfi-1) #:select (filter-map))
  #:use-module (downstroke native)
  #:use-module ((downstroke render) #:select (renderer-available?))
  #:use-module (downstroke world)
  #:use-module (downstroke game)
  #:use-module ((downstroke time-travel) #:select (game-history))
  #:export (game-debug-draw-set! draw-game! game-capture game-pixel))

(define (game-debug-draw-set! game on?)
  "Show (#t) or hide (#f) the debug overlay when GAME is drawn: every box
coloured by role (solid, immovable, ghost, plain, resting), velocities,
on-ground marks, the pairs pushed apart in the last frame and, with
history:, each entity's trail over the remembered frames. F1 toggles it in a
window."
  (%game-debug-draw-set! game (and on? #t))
  (when (renderer-available?) (%note-pushed-pairs! (and on? #t))))

(define (trail-scenes game)
  ;; The remembered frames' entities, oldest first, for the overlay's trails.
  (if (game-debug-draw? game)
      (filter-map (lambda (e) (and (cdr e) (scene-entities (cdr e)))) (reverse (game-history game)))
      '()))

(define* (draw-game! game #:optional (between #f))
  ;; One frame into the game's display (and its window, when one is open);
  ;; BETWEEN, (previous-entities alpha camera-x camera-y), draws it between
  ;; the step before and this one.
  (let ((display (game-display game))
        (scene (game-scene game)))
    (unless display
      (scm-error 'misc-error "game-capture" "this build has no renderer (SDL2)" '() #f))
    (%display-draw! display
                    (and scene (scene-tilemap scene))
                    (if scene (camera-x (scene-camera scene)) 0)
                    (if scene (camera-y (scene-camera scene)) 0)
                    (if scene (scene-entities scene) '())
                    (game-debug-draw? game)
                    (trail-scenes game)
                    ;; The game's clock, for animated tiles, and a frame's
                    ;; ms, for each entity's #:animation-start.
                    (* (game-frame game) (game-frame-delay game))
                    between
                    (game-frame-delay game))))

(define (game-capture game file)
  "Draw GAME's current frame — its map, entities, what its render: procedure
drew last, and the overlay when on — and write it to FILE as a PNG of
exactly the game's width × height. Works in any mode, headless included."
  (unless (string? file)
    (scm-error 'wrong-type-arg "game-capture" "file: expected a string, got ~S" (list file) #f))
  (draw-game! game)
  (%display-save-png (game-display game) file))

(define (game-pixel game x y)
  "The colour (r g b a) at pixel (X, Y) of the frame GAME drew last (by
game-capture, a capture run or a window)."
  (unless (game-display game)
    (scm-error 'misc-error "game-pixel" "this build has no renderer (SDL2)" '() #f))
  (%display-pixel (game-display game) x y))
