;; SPDX-License-Identifier: MIT
;;; Prints the names (downstroke native) exports, one a line, sorted: the
;;; build without the renderer must export the same as the build with it
;;; (tools/without-renderer.sh compares them).
(define names '())
(module-for-each (lambda (name variable) (set! names (cons (symbol->string name) names)))
                 (resolve-interface '(downstroke native)))
(for-each (lambda (name) (display name) (newline)) (sort names string<?))
