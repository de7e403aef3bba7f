;; SPDX-License-Identifier: MIT
;;; (downstroke tool-files) — what the author's tools (downstroke test and
;;; its --junit, read-input-script, record-input and --record, downstroke
;;; new) ask of the files they read and write. Only regular files: opening
;;; a FIFO blocks the tool for ever, and a device such as /dev/zero is read
;;; without end. A file written is written whole or not at all (a temporary
;;; file beside it, renamed over it), so a failed write leaves no half file.
(define-module (downstroke tool-files)
  #:export (file-kind-text input-file-problem output-file-problem
            check-input-file check-output-file call-with-output-file/whole))

(define (file-kind-text type)
  ;; What a stat:type is, as an error says it.
  (case type
    ((directory) "a directory")
    ((fifo) "a FIFO")
    ((char-special) "a character device")
    ((block-special) "a block device")
    ((socket) "a socket")
    (else (format #f "not a regular file (~a)" type))))

(define (input-file-problem file)
  ;; #f when FILE is a regular file that can be read; else why not.
  (catch 'system-error
    (lambda ()
      (let ((st (stat file)))
        (cond ((not (eq? (stat:type st) 'regular))
               (string-append "it is " (file-kind-text (stat:type st)) ", not a regular file"))
              ((not (access? file R_OK)) "it cannot be read (permission denied)")
              (else #f))))
    (lambda args (string-append "it cannot be read (" (strerror (system-error-errno args)) ")"))))

(define (output-file-problem file)
  ;; #f when FILE can be written whole: absent or a regular file, in a
  ;; folder that exists and can be written to; else why not.
  (let ((st (false-if-exception (stat file)))
        (folder (dirname file)))
    (cond ((and st (not (eq? (stat:type st) 'regular)))
           (string-append "it is " (file-kind-text (stat:type st)) ", not a regular file"))
          ((not (file-exists? folder)) (format #f "its folder ~s does not exist" folder))
          ((not (eq? (stat:type (stat folder)) 'directory)) (format #f "~s is not a folder" folder))
          ;; The file is replaced by renaming a new one over it: its folder
          ;; must be writable, not only the file.
          ((not (access? folder W_OK)) (format #f "its folder ~s cannot be written to" folder))
          (else #f))))

(define (check-input-file who file)
  (let ((problem (input-file-problem file)))
    (when problem (scm-error 'misc-error who "~s: ~a" (list file problem) #f))))

(define (check-output-file who file)
  (let ((problem (output-file-problem file)))
    (when problem (scm-error 'misc-error who "cannot write ~s: ~a" (list file problem) #f))))

(define (call-with-output-file/whole who file proc)
  ;; (PROC port) writing FILE: into a temporary file beside it, renamed
  ;; over FILE once PROC has returned and the port is closed. A raise or a
  ;; failed write (a full disk) leaves FILE as it was and no temporary file,
  ;; and is an error naming WHO and FILE.
  (check-output-file who file)
  (let* ((port (catch 'system-error
                 (lambda () (mkstemp (string-append file ".tmp-XXXXXX")))
                 (lambda args
                   (scm-error 'misc-error who "cannot write ~s: ~a"
                              (list file (strerror (system-error-errno args))) #f))))
         (temp (port-filename port))
         (done? #f))
    (dynamic-wind
      (lambda () #t)
      (lambda ()
        (catch 'system-error
          (lambda ()
            (set-port-encoding! port "UTF-8")
            (let ((result (proc port)))
              (close-port port)
              (chmod temp (logand #o666 (lognot (umask))))
              (rename-file temp file)
              (set! done? #t)
              result))
          (lambda args
            (scm-error 'misc-error who "cannot write ~s: ~a"
                       (list file (strerror (system-error-errno args))) #f))))
      (lambda ()
        (unless done?
          (close-port port)
          (false-if-exception (delete-file temp)))))))
