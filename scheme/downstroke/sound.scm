;; SPDX-License-Identifier: MIT
;;; (downstroke sound) — sounds and music: what a game plays is recorded
;;; with its frame (game-sounds, game-music), headless as in a window, and
;;; heard when a window is open. docs/engine.org, "Sounds", and
;;; docs/render.org, "Sound".
(define-module (downstroke sound)
  #:use-module (downstroke native)
  #:use-module (downstroke history)
  #:use-module (downstroke game)
  #:export (load-sound load-music game-sounds play-sound game-music play-music stop-music
            music-volume-set! sound-volume-set!))

;; A game that runs for hours must not keep every sound it ever played.
(define *sounds-kept* 4096)

(define (game-sounds game)
  "The sounds played lately, as (frame . name), oldest first: at least the
newest 4096 (older ones are dropped, so a long run stays in bounded memory)."
  (reverse (bounded-log-items (game-sound-log game))))

(define (play-sound game-or-name . rest)
  "Play a sound: (play-sound 'jump) in the running game, (play-sound game
'jump) naming it. It is recorded with the frame it was played in (see
game-sounds) and, when a window is open and load-sound loaded it, heard."
  (let ((game (if (game? game-or-name) game-or-name (current-game)))
        (name (if (game? game-or-name) (car rest) game-or-name)))
    (when game
      (game-sound-log-set! game (bounded-log-push (game-sound-log game)
                                                  (cons (game-frame game) name) *sounds-kept*)))
    ;; Heard only with a window open; a sound never loaded is only recorded.
    (when (and (symbol? name) (%renderer?)) (%play-sound name))))

(define (game-music game)
  "The music events lately, oldest first, as (frame . event): (play NAME
LOOP? FADE-IN-MS), (stop FADE-OUT-MS), (music-volume V) and (sound-volume
V). Recorded headless as in a window, so a test sees what a player would
hear; at least the newest 4096 are kept."
  (reverse (bounded-log-items (game-music-log game))))

(define (note-music! event)
  (let ((game (current-game)))
    (when game
      (game-music-log-set! game (bounded-log-push (game-music-log game)
                                                  (cons (game-frame game) event) *sounds-kept*)))))

;; A fade longer than ten minutes is a typo (seconds for milliseconds, say).
(define *max-fade-ms* 600000)

(define (check-fade who what ms)
  (unless (and (real? ms) (not (nan? ms)) (<= 0 ms *max-fade-ms*))
    (scm-error 'wrong-type-arg who "~A: expected a number of ms from 0 to ~A, got ~S"
               (list what *max-fade-ms* ms) #f)))

(define (check-volume who v)
  (unless (and (real? v) (not (nan? v)) (<= 0 v 1))
    (scm-error 'wrong-type-arg who "volume: expected a number from 0 to 1, got ~S" (list v) #f)))

(define* (play-music name #:key (loop? #t) (fade-in 0))
  "Play the music NAME (load-music), in place of any playing: looping unless
LOOP? is #f, fading in over FADE-IN ms. Recorded in game-music; heard when
a window is open. #f when no music of that name was loaded."
  (unless (symbol? name)
    (scm-error 'wrong-type-arg "play-music" "name: expected a symbol, got ~S" (list name) #f))
  (check-fade "play-music" "fade-in" fade-in)
  (note-music! (list 'play name (and loop? #t) fade-in))
  (and (%renderer?) (%play-music name (and loop? #t) fade-in)))

(define* (stop-music #:key (fade-out 0))
  "Stop the music, fading out over FADE-OUT ms."
  (check-fade "stop-music" "fade-out" fade-out)
  (note-music! (list 'stop fade-out))
  (when (%renderer?) (%stop-music fade-out)))

(define (music-volume-set! v)
  "The music's volume, from 0 (silent) to 1 (as recorded, the default)."
  (check-volume "music-volume-set!" v)
  (note-music! (list 'music-volume v))
  (when (%renderer?) (%set-volume! 'music v)))

(define (sound-volume-set! v)
  "Every sound's volume, from 0 (silent) to 1 (as recorded, the default)."
  (check-volume "sound-volume-set!" v)
  (note-music! (list 'sound-volume v))
  (when (%renderer?) (%set-volume! 'sound v)))

;;; A file a build without the renderer can only check is there.
(define (check-sound-file who what name file)
  (cond ((not (symbol? name))
         (scm-error 'wrong-type-arg who "name: expected a symbol, got ~S" (list name) #f))
        ((not (and (string? file) (file-exists? file) (eq? 'regular (stat:type (stat file)))))
         (scm-error 'misc-error who (string-append what " ~S: no such file") (list file) #f))))

(define (load-music name file)
  "Open FILE as the music NAME, a symbol, for play-music: Ogg Vorbis, WAV,
FLAC, MP3, MIDI, or a MOD, XM, S3M or IT module, recognised by its bytes
(not its name). The file is read whole, within its format's bound (64 MiB
streamed, 32 MiB a module, 4 MiB MIDI: docs/limits.org, \"Music\"), and
decoded from memory as it plays. Headless runs open it too (a missing,
unreadable or oversized file, another format, or a WAV or OGG whose
header is broken, is an error naming it at once) but play nothing."
  (if (%renderer?)
      (%load-music name file)
      (check-sound-file "load-music" "music" name file)))

(define (load-sound name file)
  "Decode FILE (WAV or OGG) as the sound NAME, a symbol, for play-sound.
Headless runs decode it too (so a bad file is found at once) but play
nothing. A missing, unreadable or undecodable file, or one past the
bounds of docs/limits.org (\"Sounds\"), is an error naming it. In a build
without the renderer it only checks that FILE is a file."
  (cond ((%renderer?) (%load-sound name file))
        ((not (symbol? name))
         (scm-error 'wrong-type-arg "load-sound" "name: expected a symbol, got ~S" (list name) #f))
        ((not (and (string? file) (file-exists? file) (eq? 'regular (stat:type (stat file)))))
         (scm-error 'misc-error "load-sound" "sound ~S: no such file" (list file) #f))))
