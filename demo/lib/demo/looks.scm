;; SPDX-License-Identifier: 0BSD
;;; (demo looks) — what every demo looks and sounds like: the sprites'
;;; gids, the sound effects and the theme, found beside the demos wherever
;;; they are run from. A demo puts demo/lib on its load path and uses it:
;;;
;;;   (add-to-load-path (string-append (dirname (current-filename)) "/lib"))
;;;   (use-modules (demo looks))
;;;
;;; Every demo map holds demo-tiles.tsx (or tiles.tsx) from gid 1 and
;;; sprites.tsx from gid 5.
(define-module (demo looks)
  #:use-module (downstroke)
  #:export (demo-file sprite load-demo-music! theme-from-the-start load-demo-sounds! centred-x))

(define demo-dir
  ;; demo/, two folders up from this file, found where the demo found it:
  ;; on the load path (a compiled copy's current-filename is #f).
  (dirname (dirname (dirname (search-path %load-path "demo/looks.scm")))))

(define (demo-file name)
  "The file NAME under demo/ (\"maps/platformer.tmx\")."
  (string-append demo-dir "/" name))

(define (sprite local-id)
  "The gid of sprites.tsx's tile LOCAL-ID (demo/maps/make_art.py lists them)."
  (+ 5 local-id))

(define (load-demo-music!)
  "Load demo/sounds/theme.ogg (made by make_music.py there) as the music
'theme. Headless runs only record what play-music plays (game-music)."
  (load-music 'theme (demo-file "sounds/theme.ogg")))

(define (theme-from-the-start game)
  "Start the theme, looping, on GAME's first frame (call it from update:)."
  (when (= (game-frame game) 0) (play-music 'theme)))

(define (load-demo-sounds! . names)
  "Load demo/sounds/NAME.wav as the sound NAME, for each NAME. Headless runs
only record what play-sound plays (game-sounds)."
  (for-each (lambda (name)
              (load-sound name (demo-file (string-append "sounds/" (symbol->string name) ".wav"))))
            names))

(define* (centred-x text width #:key (scale 1))
  "The x that centres TEXT, drawn at SCALE in the built-in font, on a
picture WIDTH wide."
  (quotient (- width (text-width text #:scale scale)) 2))
