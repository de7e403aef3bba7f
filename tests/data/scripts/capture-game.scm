;; SPDX-License-Identifier: MIT
;;; A tiny game for the capture tests: a box falls onto the render map's
;;; floor; the render hook writes the frame number in the corner.
(define here (dirname (current-filename)))
(define level (load-tilemap (string-append here "/../maps/render/render.tmx")))
(define game
  (make-game title: "capture" width: 48 height: 32
             scene: (make-scene entities: (list (list #:id 'box #:x 20 #:y 8 #:width 8 #:height 8
                                                      #:gravity? #t #:sprite 4))
                                tilemap: level)
             render: (lambda (game) (draw-text (number->string (game-frame game)) 0 0 'white space: 'screen))))
(game-run! game frames: (script-number-argument 0 5))
