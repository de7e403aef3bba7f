;; SPDX-License-Identifier: MIT
;;; Misspelt entity keys: a key a slip away from an engine key is said once
;;; per key per game (or refused, strict?), and the author's own keys are not.
(use-modules (srfi srfi-64) (srfi srfi-1) (downstroke) (downstroke testing))

(load "support.scm")

(test-begin "key-slips")

;; Fresh plists each time: a plist the engine has decoded at the same place
;; before is taken from its cache and not read again.
(define (misspelt-scene)
  (make-scene entities: (list (list #:id 'player #:x 0 #:y 0 #:width 8 #:height 8 #:sensr? #t
                                    #:score 10 #:life 3 #:weight 2 #:dx 1 #:hp 3 #:sprite 1 #:tag 'p)
                              (list #:x 20 #:y 0 #:width 8 #:height 8 #:bounse 1/2
                                    #:colides-with '(default) #:gravty? #t)
                              (list #:id "coin" #:x 40 #:sensr? #t))))

;; The entities rewritten each frame, so each is decoded afresh every frame.
(define (drift game dt)
  (let ((s (game-scene game)))
    (game-scene-set! game (update-scene s entities: (map (lambda (e) (entity-set e #:x (+ 1 (entity-ref e #:x))))
                                                          (scene-entities s))))))

(define (warnings-of thunk)
  (let ((port (open-output-string)))
    (parameterize ((current-warning-port port)) (thunk))
    (get-output-string port)))

(define expected-warnings
  (string-append
   "game-run!: warning: entity key #:sensr? is not one the engine reads (entity 0 of the list, #:id player): did you mean #:sensor??\n"
   "game-run!: warning: entity key #:bounse is not one the engine reads (entity 1 of the list): did you mean #:bounce?\n"
   "game-run!: warning: entity key #:colides-with is not one the engine reads (entity 1 of the list): did you mean #:collides-with?\n"
   "game-run!: warning: entity key #:gravty? is not one the engine reads (entity 1 of the list): did you mean #:gravity??\n"))

(test-equal "each near miss is one warning per game, naming the key, the entity and the engine key; far keys are silent"
  expected-warnings
  (warnings-of (lambda () (play (make-game strict?: #f scene: (misspelt-scene) update: drift) #:frames 5))))

(test-equal "… and a second game is told again"
  expected-warnings
  (warnings-of (lambda () (play (make-game strict?: #f scene: (misspelt-scene) update: drift) #:frames 2))))

(test-equal "the author's own keys, however many, say nothing"
  ""
  (warnings-of
   (lambda ()
     (play (make-game strict?: #t
                      scene: (make-scene entities: (list (list #:x 0 #:score 1 #:life 2 #:weight 3 #:type 'coin
                                                               #:name "a" #:facing 'left #:state 'idle #:timer 4
                                                               #:flip-x? #t #:sprite 2 #:tag 't #:vx 1))))
           #:frames 3))))

(test-equal "the renderer's look keys are engine keys, and a slip of one is said"
  "game-run!: warning: entity key #:rotaton is not one the engine reads (entity 0 of the list): did you mean #:rotation?\n"
  (warnings-of
   (lambda ()
     (play (make-game strict?: #f
                      scene: (make-scene entities: (list (list #:x 0 #:visible? #t #:color '(1 2 3) #:sprite-offset '(1 . 2)
                                                               #:sprite-scale 2 #:rotation 90 #:animation '((1 . 10))
                                                               #:animation-start 0 #:rotaton 5))))
           #:frames 2))))

(test-equal "strict?: #t makes the first one an error, naming the key, the entity and the engine key"
  "In procedure game-run!: entity key #:sensr? is not one the engine reads (entity 0 of the list, #:id player): did you mean #:sensor?? (make-game strict?: #t makes this an error)\n"
  (error-text (lambda () (play (make-game strict?: #t scene: (misspelt-scene)) #:frames 1))))

(test-equal "a string #:id is named as written"
  "In procedure game-run!: entity key #:sensr? is not one the engine reads (entity 0 of the list, #:id \"coin\"): did you mean #:sensor?? (make-game strict?: #t makes this an error)\n"
  (error-text (lambda () (play (make-game strict?: #t
                                          scene: (make-scene entities: (list (list #:id "coin" #:x 40 #:sensr? #t))))
                               #:frames 1))))

(test-equal "strict?: defaults to (strict-games): #f, and #t under downstroke test"
  '(#f #t #f)
  (list (strict-games)
        (parameterize ((strict-games #t))
          (and (error-text (lambda () (play (make-game scene: (misspelt-scene)) #:frames 1))) #t))
        (parameterize ((strict-games #t))
          ;; a test opts out with strict?: #f
          (and (error-text (lambda () (warnings-of (lambda () (play (make-game strict?: #f scene: (misspelt-scene))
                                                                     #:frames 1)))))
               #t))))

(test-equal "slips decoded outside the game (a step-scene of its own) are not the game's"
  ""
  (begin
    (step-scene (make-scene entities: (list (list #:x 0 #:gravty? #t))) 16)
    (warnings-of (lambda () (play (make-game strict?: #t) #:frames 1)))))

;; downstroke test itself (the host, in a child): the game of a test file is strict.
(test-equal "downstroke test makes games strict: a misspelt key fails the check that plays the game"
  '(1 "FAIL slip-test.scm:3: plays: assertion (game? (play (make-game #:scene (make-scene #:entities (list (list #:x 0 #:sensr? #t)))) #:frames 1)) raised: In procedure game-run!: entity key #:sensr? is not one the engine reads (entity 0 of the list): did you mean #:sensor?? (make-game strict?: #t makes this an error)")
  (let* ((dir (mkdtemp (string-append (or (getenv "TMPDIR") "/tmp") "/ds-slips-XXXXXX")))
         (file (string-append dir "/slip-test.scm"))
         (out (string-append dir "/out")))
    (call-with-output-file file
      (lambda (port)
        (for-each (lambda (form) (write form port) (newline port))
                  '((use-modules (downstroke testing))
                    (test-begin "slip")
                    (test-assert "plays" (game? (play (make-game scene: (make-scene entities: (list (list #:x 0 #:sensr? #t))))
                                                      #:frames 1)))
                    (test-end "slip")))))
    (let* ((status (system (string-append "cd '" dir "' && '" (readlink "/proc/self/exe") "' test slip-test.scm >out 2>&1")))
           (text (call-with-input-file out (@ (ice-9 textual-ports) get-string-all))))
      (for-each delete-file (list file out))
      (rmdir dir)
      (list (status:exit-val status) (find (lambda (line) (string-prefix? "FAIL" line)) (string-split text #\newline))))))

;; The tutorial's aside shows the warning as the engine prints it.
(define (tutorial-warning)
  ;; The line of the example block after the aside about #:sensr?.
  (let* ((text (call-with-input-file (string-append (dirname (current-filename)) "/../../docs/tutorial.org")
                 (@ (ice-9 textual-ports) get-string-all)))
         (aside (string-contains text "=#:sensr? #t="))
         (start (+ (string-contains text "#+begin_example\n" aside) (string-length "#+begin_example\n"))))
    (substring text start (+ 1 (string-index text #\newline start)))))
(test-equal "docs/tutorial.org shows the warning exactly"
  (tutorial-warning)
  (warnings-of
   (lambda ()
     (play (make-game strict?: #f
                      scene: (make-scene entities: (list (list #:id 'player #:x 0 #:y 0 #:width 12 #:height 16)
                                                         (list #:id 'coin-0 #:x 40 #:sensor? #t)
                                                         (list #:id 'coin-1 #:kind 'coin #:x 60 #:y 0 #:width 8 #:height 8
                                                               #:sensr? #t #:collides-with '(player)))))
           #:frames 1))))

(test-end "key-slips")
