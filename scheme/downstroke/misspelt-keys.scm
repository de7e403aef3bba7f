;; SPDX-License-Identifier: MIT
;;; (downstroke misspelt-keys) — an entity key that is a slip of one the
;;; engine reads, said once per game or refused. docs/entities.org,
;;; "Misspelt keys".
(define-module (downstroke misspelt-keys)
  #:use-module (downstroke native)
  #:use-module (downstroke game)
  #:export (strict-games report-key-slips!))

;;; An entity key the engine does not read but that is a slip of one it does
;;; (#:sensr? for #:sensor?) turns a behaviour off without a word. Decoding
;;; notices it (bindings/key_slips.hpp: which keys are slips, and why it
;;; costs nothing measurable); here each is said once per game, or refused.

;; #t: games made without strict?: are strict. `downstroke test' sets it, so
;; a test suite does not pass on a game with a misspelt key.
(define strict-games (make-parameter #f))

(define (slip-text key suggestion index id)
  (format #f "entity key ~s is not one the engine reads (entity ~a of the list~a): did you mean ~s?"
          key index (if id (format #f ", #:id ~s" id) "") suggestion))

(define (report-key-slips! game)
  ;; The slips decoded in this frame, on this thread: one native call that
  ;; gives () in a game without any.
  (for-each (lambda (slip)
              (let ((key (car slip)) (warned (game-slips-warned game)))
                (unless (hashq-ref warned key)
                  (hashq-set! warned key #t)
                  (if (game-strict? game)
                      (scm-error 'misc-error "game-run!" "~a (make-game strict?: #t makes this an error)"
                                 (list (apply slip-text slip)) #f)
                      (format (current-warning-port) "game-run!: warning: ~a~%" (apply slip-text slip))))))
            (%take-key-slips)))
