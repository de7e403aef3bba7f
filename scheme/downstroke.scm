;;; (downstroke) — everything a game imports.
(define-module (downstroke)
  #:use-module (downstroke entity)
  #:use-module (downstroke world)
  #:use-module (downstroke physics)
  #:use-module (downstroke tween)
  #:use-module (downstroke tilemap)
  #:use-module (downstroke engine))

(eval-when (expand load eval)
  (for-each (lambda (name)
              (module-use! (module-public-interface (current-module))
                           (resolve-interface (list 'downstroke name))))
            '(entity world physics tween tilemap engine)))
