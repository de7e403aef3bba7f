;; SPDX-License-Identifier: MIT
;;; The window test's focus game (tests/scheme/window-test.scm): a 64 × 48
;;; window with pause-when-unfocused?, saying "frame N" every 20 frames, so
;;; the test sees when it steps and when it does not.
(define game
  (make-game title: "focus-test" width: 64 height: 48 pause-when-unfocused?: #t
             update: (lambda (g dt)
                       (when (zero? (modulo (game-frame g) 20))
                         (format #t "frame ~a~%" (game-frame g))
                         (force-output)))))
(game-run! game frames: 6000)  ; 100 s at most: the test ends it long before
