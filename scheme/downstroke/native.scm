;; SPDX-License-Identifier: MIT
;;; (downstroke native) — the procedures implemented in C++.
;;; Not for direct use: the other modules wrap and re-export them.
(define-module (downstroke native))

;; Defines and exports every native procedure in this module. The host
;; registers the extension in-process; a plain `guile' finds the library
;; through GUILE_EXTENSIONS_PATH.
(load-extension "libdownstroke-guile" "ds_init_native")
