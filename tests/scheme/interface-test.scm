;; SPDX-License-Identifier: MIT
;;; (downstroke)'s public interface holds every user-facing binding, so that
;;; module-map, ,apropos and an editor's completion find them.
(use-modules (srfi srfi-64) (srfi srfi-1) (ice-9 session) (downstroke documentation))

(load "support.scm")

(test-begin "interface")

(define (symbol<? a b) (string<? (symbol->string a) (symbol->string b)))
(define downstroke-names (module-map (lambda (name variable) name) (resolve-interface '(downstroke))))

(for-each
 (lambda (name)
   (test-assert (format #f "(downstroke)'s interface lists ~a" name)
     (memq name downstroke-names)))
 '(step-scene scene-query-rect tilemap-set-tile contacts-begun carry-riders
   define-pipeline *gravity* collision-mode make-game draw-rect scene-hash make-frame-ring))

(test-equal "it lists exactly the user modules' exports, each once"
  (sort (append-map export-names user-modules) symbol<?)
  (sort downstroke-names symbol<?))

(test-assert "each is the defining module's own binding"
  (every (lambda (module-name)
           (every (lambda (name)
                    (eq? (module-variable (resolve-interface module-name) name)
                         (module-variable (resolve-interface '(downstroke)) name)))
                  (export-names module-name)))
         user-modules))

(test-assert "no machinery: nothing named with %, nothing only (downstroke reference) or (downstroke native) has"
  (not (any (lambda (name)
              (or (string-prefix? "%" (symbol->string name))
                  (memq name '(register-tween-type! step-entities))))
            downstroke-names)))

;; What ,apropos finds: the REPL command calls apropos from the REPL's module.
(define game-module
  (let ((m (make-fresh-user-module)))
    (eval '(use-modules (downstroke)) m)
    m))

(define (apropos-lines pattern)
  (save-module-excursion
   (lambda ()
     (set-current-module game-module)
     (string-split (string-trim-right (with-output-to-string (lambda () (apropos pattern))))
                   #\newline))))

(test-equal ",apropos tilemap lists the tilemap procedures (downstroke) exports"
  '("(downstroke): load-tilemap" "(downstroke): make-tilemap"
    "(downstroke): scene-tilemap"
    "(downstroke): tilemap-cell-one-way?" "(downstroke): tilemap-cell-shape"
    "(downstroke): tilemap-cell-solid?"
    "(downstroke): tilemap-gid" "(downstroke): tilemap-gid-at"
    "(downstroke): tilemap-height" "(downstroke): tilemap-layers"
    "(downstroke): tilemap-objects" "(downstroke): tilemap-properties"
    "(downstroke): tilemap-set-tile" "(downstroke): tilemap-solid-at?"
    "(downstroke): tilemap-solid-cells" "(downstroke): tilemap-solid-extent"
    "(downstroke): tilemap-steepest-ramp" "(downstroke): tilemap-tile-height" "(downstroke): tilemap-tile-width"
    "(downstroke): tilemap-tilesets" "(downstroke): tilemap-warnings"
    "(downstroke): tilemap-width" "(downstroke): tilemap?")
  (sort (filter (lambda (line) (string-prefix? "(downstroke):" line))
                (map (lambda (line) (car (string-split line #\tab))) (apropos-lines "tilemap")))
        string<?))

(test-end "interface")
