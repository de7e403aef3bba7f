;;; What every demo looks and sounds like: included by each demo after it
;;; defines `demo-dir'. Every demo map holds demo-tiles.tsx (or tiles.tsx)
;;; from gid 1 and sprites.tsx from gid 5.
(define (sprite local-id)
  "The gid of sprites.tsx's tile LOCAL-ID (demo/maps/make_art.py lists them)."
  (+ 5 local-id))

(define (load-demo-music!)
  "Load demo/sounds/theme.ogg (made by make_music.py there) as the music
'theme. Headless runs only record what play-music plays (game-music)."
  (load-music 'theme (string-append demo-dir "/sounds/theme.ogg")))

(define (theme-from-the-start game)
  "Start the theme, looping, on GAME's first frame (call it from update:)."
  (when (= (game-frame game) 0) (play-music 'theme)))

(define (load-demo-sounds! . names)
  "Load demo/sounds/NAME.wav as the sound NAME, for each NAME. Headless runs
only record what play-sound plays (game-sounds)."
  (for-each (lambda (name)
              (load-sound name (string-append demo-dir "/sounds/" (symbol->string name) ".wav")))
            names))
