;; SPDX-License-Identifier: MIT
;;; (downstroke game) — the game record: its fields, and the checks and
;;; setters that keep them valid. Every concern of a running game (input,
;;; sound, pause, time travel, recording, drawing, the loop) reads and
;;; writes a game through this module; make-game, which fills one in, is in
;;; (downstroke engine). docs/engine.org, "make-game".
(define-module (downstroke game)
  #:use-module (srfi srfi-9)
  #:use-module (downstroke native)
  #:use-module ((downstroke world) #:select (scene?))
  #:use-module (downstroke arity)
  #:export (%make-game game? game-title game-width game-height game-frame-delay
            game-scene %game-scene-set! game-update %game-update-set! game-render %game-render-set!
            game-engine-update %game-engine-update-set!
            game-collision-mode %game-collision-mode-set! game-substeps %game-substeps-set!
            game-push-rule
            game-resting-contacts? game-resting-contacts-set!
            game-input game-input-set! game-input-script game-input-script-set!
            game-script-cursor game-script-cursor-set! game-frame game-frame-set!
            game-sound-log game-sound-log-set! game-music-log game-music-log-set!
            game-history-size game-history-log game-history-log-set!
            game-display game-debug-draw? %game-debug-draw-set!
            %game-input-log %game-input-log-set! game-stack-limit
            game-pause-when-unfocused? game-interpolate? game-strict? game-slips-warned
            game-bindings game-paused? %game-paused-set! game-paused-update %game-paused-update-set!
            game-paused-ticks game-paused-ticks-set! game-pause-marks game-pause-marks-set!
            game-live game-live-set!
            check-game check-scene-or-false check-hook-or-false
            check-collision-mode check-push-rule check-substeps
            game-scene-set! game-update-set! game-engine-update-set!
            game-collision-mode-set! game-push-rule-set! game-substeps-set!
            current-game))

(define-record-type <game>
  (%make-game title width height frame-delay scene update render engine-update
              collision-mode push-rule substeps resting-contacts
              input input-script script-cursor frame sounds music history-size history
              display debug-draw input-log stack-limit pause-when-unfocused interpolate
              strict slips-warned bindings paused paused-update paused-ticks pause-marks live)
  game?
  (title game-title)
  (width game-width)
  (height game-height)
  (frame-delay game-frame-delay)
  (scene game-scene %game-scene-set!)
  (update game-update %game-update-set!)
  (render game-render %game-render-set!)  ; set only by a script's reload (script-reload.scm)
  (engine-update game-engine-update %game-engine-update-set!)
  (collision-mode game-collision-mode %game-collision-mode-set!)
  (push-rule game-push-rule %game-push-rule-set!)
  (substeps game-substeps %game-substeps-set!)
  (resting-contacts game-resting-contacts? game-resting-contacts-set!)
  (input game-input game-input-set!)
  (input-script game-input-script game-input-script-set!)
  (script-cursor game-script-cursor game-script-cursor-set!)  ; where the replay is (scripted-held!), or #f
  (frame game-frame game-frame-set!)
  (sounds game-sound-log game-sound-log-set!)  ; (count . ((frame . name) …)), newest first
  (music game-music-log game-music-log-set!)   ; a bounded log of (frame . event), newest first
  (history-size game-history-size)
  (history game-history-log game-history-log-set!)  ; a bounded log of (frame . scene)
  (display game-display)            ; the renderer's, or #f in a build without it
  (debug-draw game-debug-draw? %game-debug-draw-set!)
  (input-log %game-input-log %game-input-log-set!)  ; an <input-log>: (frame . held) at each change
  (stack-limit game-stack-limit)    ; bytes of Scheme stack each hook may use
  (pause-when-unfocused game-pause-when-unfocused?)
  (interpolate game-interpolate?)
  (strict game-strict?)             ; a misspelt entity key is an error, not a warning
  (slips-warned game-slips-warned)  ; the misspelt keys warned of, a hash table: once each
  (bindings game-bindings)          ; a <bindings> of its input map, or #f when it is not known
  (paused game-paused? %game-paused-set!)      ; game-paused-set!: ticks run the paused: hook, not a frame
  (paused-update game-paused-update %game-paused-update-set!)  ; (game dt) called in each paused tick, or #f
  ;; Ticks spent paused so far: the input clock (input-clock) counts them.
  (paused-ticks game-paused-ticks game-paused-ticks-set!)
  ;; A bounded log of (frame . the ticks paused before the pause at that
  ;; frame), newest first: where a rewind finds the input clock of its frame.
  (pause-marks game-pause-marks game-pause-marks-set!)
  ;; What (downstroke live) keeps for the game: the files it watches, whether
  ;; its maps are watched, the last reload's error; #f until it watches one.
  (live game-live game-live-set!))

;;; Refused where they are passed, not frames later inside the loop, where
;;; the error would name struct-vtable or camera-follow!.
(define (check-game who game)
  (unless (game? game)
    (scm-error 'wrong-type-arg who "game: expected a game (make-game), got ~S" (list game) #f)))

(define (check-scene-or-false who scene)
  (unless (or (not scene) (scene? scene))
    (scm-error 'wrong-type-arg who "scene: expected a scene (make-scene) or #f, got ~S" (list scene) #f)))

(define (check-procedure-or-false who what proc)
  (unless (or (not proc) (procedure? proc))
    (scm-error 'wrong-type-arg who "~A: expected a procedure or #f, got ~S" (list what proc) #f)))

;; The arguments the frame loop calls each of a game's hooks with
;; (step-game!): one home, for the checks and the messages.
(define hook-arguments '((engine-update game dt) (update game dt) (render game) (paused game dt)))

(define (check-hook-or-false who what proc)
  (check-procedure-or-false who what proc)
  (when proc (check-hook who what proc (assq-ref hook-arguments what))))


(define (game-scene-set! game scene)
  "Make SCENE (a scene, or #f for none) GAME's scene from now on."
  (check-game "game-scene-set!" game)
  (check-scene-or-false "game-scene-set!" scene)
  (%game-scene-set! game scene))

(define (game-update-set! game update)
  "Make UPDATE, (lambda (game dt) …) or #f, GAME's update from the next frame on."
  (check-game "game-update-set!" game)
  (check-hook-or-false "game-update-set!" 'update update)
  (%game-update-set! game update))

(define (game-engine-update-set! game engine-update)
  "Make ENGINE-UPDATE, (lambda (game dt) …) or #f, run first in GAME's frames."
  (check-game "game-engine-update-set!" game)
  (check-hook-or-false "game-engine-update-set!" 'engine-update engine-update)
  (%game-engine-update-set! game engine-update))

;; Checked where it is given, not first in a frame, where the error would
;; name the collision-mode parameter and come frames after the typo.
(define (check-choice who key choices value)
  (unless (memq value choices)
    (scm-error 'wrong-type-arg who (string-append key ": expected one of ~S, got ~S")
               (list choices value) #f)))

(define (check-collision-mode who mode)
  (check-choice who "collision-mode" '(swept discrete) mode))

(define (game-collision-mode-set! game mode)
  "Make MODE ('swept or 'discrete) GAME's collision mode from the next frame on."
  (check-game "game-collision-mode-set!" game)
  (check-collision-mode "game-collision-mode-set!" mode)
  (%game-collision-mode-set! game mode))

;; As the collision mode: checked where it is given.
(define (check-push-rule who rule)
  (check-choice who "push-rule" '(clipped seed) rule))

(define (game-push-rule-set! game rule)
  "Make RULE ('clipped or 'seed) GAME's push rule from the next frame on."
  (check-game "game-push-rule-set!" game)
  (check-push-rule "game-push-rule-set!" rule)
  (%game-push-rule-set! game rule))

(define (check-substeps who k)
  (unless (and (exact-integer? k) (<= 1 k %max-substeps))
    (scm-error 'wrong-type-arg who "substeps: expected an exact integer from 1 to ~S, got ~S"
               (list %max-substeps k) #f)))

(define (game-substeps-set! game k)
  "Split GAME's physics frames into K sub-frames from the next frame on."
  (check-substeps "game-substeps-set!" k)
  (%game-substeps-set! game k))

;; The game game-run! is running, or #f: a hook's (play-sound 'jump) is
;; that game's, and game-run! refuses to start a second one inside it.
(define current-game (make-parameter #f))
