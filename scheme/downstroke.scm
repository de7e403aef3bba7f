;; SPDX-License-Identifier: MIT
;;; (downstroke) — everything a game imports.
;;;
;;; Its public interface holds the user-facing modules' bindings themselves
;;; (not a use of their interfaces), so that module-map, ,apropos and an
;;; editor's completion list them: a used interface is invisible to all
;;; three.
(define-module (downstroke)
  #:use-module (downstroke entity)
  #:use-module (downstroke world)
  #:use-module (downstroke physics)
  #:use-module (downstroke tween)
  #:use-module (downstroke tilemap)
  #:use-module (downstroke query)
  #:use-module (downstroke contacts)
  #:use-module (downstroke engine)
  #:use-module (downstroke hash)
  #:use-module (downstroke scene-file)
  #:use-module (downstroke history)
  #:use-module (downstroke render)
  #:use-module (downstroke documentation))

(eval-when (expand load eval)
  (let ((public (module-public-interface (current-module))))
    (for-each
     (lambda (module-name)
       (module-for-each
        (lambda (name variable)
          (let ((held (module-local-variable public name)))
            ;; Two modules exporting one name would make a game's meaning of
            ;; it depend on this list's order.
            (when (and held (not (eq? held variable)))
              (error "(downstroke): two modules export" name))
            (module-add! public name variable)))
        (resolve-interface module-name)))
     user-modules)))
