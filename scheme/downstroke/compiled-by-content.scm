;; SPDX-License-Identifier: MIT
;;; (downstroke compiled-by-content) — a script's compiled copy is used only
;;; while its source reads as it did when it was compiled.
;;;
;;; Guile's auto-compilation keeps a file's compiled copy (in its cache,
;;; ~/.cache/guile/ccache/…) for as long as the copy is not older than the
;;; source. A source restored with an older date — cp -p, tar, rsync, a git
;;; checkout of an older commit onto a newer clock — then runs its stale
;;; copy: a test "passes" against code that is no longer there. Beside each
;;; compiled copy the host keeps the source it was compiled from
;;; (FILE.go.source); a copy whose source differs, or that has none, is
;;; deleted before the load, which then compiles the file afresh.
(define-module (downstroke compiled-by-content)
  #:use-module ((system base compile) #:select (compiled-file-name))
  #:use-module ((ice-9 binary-ports) #:select (get-bytevector-all put-bytevector))
  #:use-module ((rnrs bytevectors) #:select (bytevector=?))
  #:use-module ((downstroke script-source) #:select (loaded-files))
  #:use-module ((downstroke tool-files) #:select (call-with-output-file/whole))
  #:export (forget-stale-compiled!))

(define (file-bytes file)
  ;; FILE's bytes, or #f when it cannot be read as a regular file.
  (false-if-exception
   (and (eq? 'regular (stat:type (stat file)))
        (let ((bytes (call-with-input-file file get-bytevector-all #:binary #t)))
          (if (eof-object? bytes) #vu8() bytes)))))

(define (same-bytes? file bytes)
  (let ((kept (file-bytes file)))
    (and kept (bytevector=? kept bytes))))

(define (forget-stale-compiled-file! file)
  (let ((bytes (file-bytes file))
        (go (false-if-exception (compiled-file-name file))))
    (when (and bytes go)
      (let ((record (string-append go ".source")))
        (unless (same-bytes? record bytes)
          (false-if-exception (delete-file go))
          ;; Written now, before the load compiles the file: a cache that
          ;; cannot be written (no home, a read-only disk) is Guile's to
          ;; report, or to do without.
          (false-if-exception
           (begin (mkdir-p (dirname record))
                  ;; Whole or not at all, through a temporary file of its own:
                  ;; a record must never match a source it was not taken from.
                  (call-with-output-file/whole "downstroke" record
                    (lambda (port) (put-bytevector port bytes))))))))))

(define (mkdir-p dir)
  (unless (file-exists? dir)
    (mkdir-p (dirname dir))
    (mkdir dir)))

(define (forget-stale-compiled! file)
  "Delete the compiled copies of FILE, and of the files it loads by a
literal name, whose source is not byte for byte the one they were compiled
from, so that loading FILE compiles them afresh."
  (for-each forget-stale-compiled-file! (loaded-files file)))
