;; SPDX-License-Identifier: MIT
;;; (downstroke starter) — `downstroke new DIR': a new game, written from the
;;; templates installed with the engine (templates/starter in the source
;;; tree, PREFIX/share/downstroke/templates once installed).
(define-module (downstroke starter)
  #:use-module (ice-9 binary-ports)
  #:use-module (ice-9 ftw)
  #:use-module (ice-9 textual-ports)
  #:use-module (srfi srfi-1)
  #:use-module ((downstroke tool-files) #:select (input-file-problem))
  #:export (write-starter starter-name-token))

;;; Text files of the template say @NAME@ where the game's name goes (its
;;; folder's name), "@NAME@" where it goes as a string literal; every other
;;; file is copied byte for byte.
(define starter-name-token "@NAME@")
(define text-suffixes '(".scm" ".md"))

(define (fail fmt . args)
  (scm-error 'misc-error "downstroke new" fmt args #f))

(define (folder? path)
  (and (file-exists? path) (eq? (stat:type (stat path)) 'directory)))

(define (folder-entries dir)
  ;; The names in DIR but "." and "..", in name order (none if unreadable).
  (or (scandir dir (lambda (n) (not (member n '("." ".."))))) '()))

(define (template-files root)
  ;; The files under ROOT, as paths relative to it, in name order.
  (define (walk dir rel)
    (append-map (lambda (name)
                  (let ((path (string-append dir "/" name))
                        (r (if (string-null? rel) name (string-append rel "/" name))))
                    (if (folder? path) (walk path r) (list r))))
                (folder-entries dir)))
  (walk root ""))

(define (string-replace-all text from to)
  (let loop ((start 0) (acc '()))
    (let ((i (string-contains text from start)))
      (if i
          (loop (+ i (string-length from)) (cons* to (substring text start i) acc))
          (string-concatenate-reverse (cons (substring text start) acc))))))

(define (naming-system-errors what path thunk)
  ;; THUNK's value; a system error (a folder that cannot be made, a file
  ;; that cannot be written) becomes one naming WHAT is done to PATH and why.
  (catch 'system-error thunk
    (lambda args
      (fail "cannot ~a ~S: ~a" what path (strerror (system-error-errno args))))))

(define (make-folders! path)
  ;; mkdir -p.
  (unless (or (string-null? path) (folder? path))
    (make-folders! (dirname path))
    (naming-system-errors "make the folder" path (lambda () (mkdir path)))))

(define (one-line name)
  ;; NAME where it stands in a comment or a heading, which a line break
  ;; would end: each line break a space.
  (string-map (lambda (c) (if (memv c '(#\newline #\return)) #\space c)) name))

(define (fill-in text name)
  ;; TEXT with the token in quotes, a string literal of the game, the name
  ;; written as a Scheme string (a " or \ in it escaped, so that game.scm
  ;; still reads), and everywhere else the name on one line.
  (let ((quoted-token (string-append "\"" starter-name-token "\"")))
    (string-replace-all (string-replace-all text quoted-token (object->string name))
                        starter-name-token (one-line name))))

(define (copy-file! from to name)
  (if (any (lambda (s) (string-suffix? s from)) text-suffixes)
      (let ((text (call-with-input-file from get-string-all #:encoding "UTF-8")))
        (call-with-output-file to
          (lambda (port) (put-string port (fill-in text name)))
          #:encoding "UTF-8"))
      (let ((bytes (call-with-input-file from get-bytevector-all #:binary #t)))
        (call-with-output-file to (lambda (port) (put-bytevector port bytes)) #:binary #t))))

(define* (write-starter dir templates #:key (template "starter"))
  "Write a new game into DIR from TEMPLATES/TEMPLATE (a folder copied whole,
@NAME@ in its .scm and .md files replaced by DIR's own name: written as a
Scheme string literal where the template has \"@NAME@\", so that any name
gives a game that reads, and on one line elsewhere). DIR may be
absent (it is made, with its parents) or an empty folder; anything else is
refused with an error naming it, before anything is written. Returns the
list of the files written, relative to DIR."
  (let ((source (string-append templates "/" template))
        (dir (if (and (> (string-length dir) 1) (string-suffix? "/" dir))
                 (string-trim-right dir #\/)
                 dir)))
    (when (string-null? dir) (fail "the folder's name is empty"))
    (unless (folder? source)
      (fail "no template folder ~S (the engine's templates are missing; DOWNSTROKE_TEMPLATE_DIR names another folder)"
            source))
    (cond ((not (file-exists? dir)))
          ((not (folder? dir)) (fail "~S exists and is not a folder" dir))
          ((pair? (folder-entries dir))
           (fail "~S exists and is not empty: give a new folder's name" dir)))
    (let ((files (template-files source))
          (name (basename (canonical-or-as-is dir))))
      ;; A FIFO among the templates would block `new', a device be copied
      ;; without end: each is checked before anything is written.
      (for-each (lambda (rel)
                  (let* ((from (string-append source "/" rel)) (problem (input-file-problem from)))
                    (when problem (fail "template file ~S: ~a" from problem))))
                files)
      (make-folders! dir)
      (for-each (lambda (rel)
                  (let ((to (string-append dir "/" rel)))
                    (make-folders! (dirname to))
                    (naming-system-errors "write" to
                      (lambda () (copy-file! (string-append source "/" rel) to name)))))
                files)
      files)))

(define (canonical-or-as-is dir)
  ;; "." and ".." name a folder whose name is the game's.
  (or (false-if-exception (canonicalize-path dir)) dir))
