;; SPDX-License-Identifier: MIT
;;; Differential suite: the native physics, (downstroke physics), against the
;;; pure-Scheme reference, (downstroke reference), on random scenes from
;;; scene-gen.scm.
;;;
;;; For every seed and both collision modes ('swept, 'discrete) it steps the
;;; scene frame by frame with each side's step-scene (each side feeding its own
;;; output to the next frame) and compares the entity lists exactly: same
;;; keys, same order, numbers with eqv? (1 ≠ 1.0, 0.0 ≠ -0.0), tweens field by
;;; field, and the same "unchanged → the very same object" answers. On the
;;; first frames and every Nth frame it also compares every single step on its
;;; own: each per-entity step on each entity of the frame's input, the frame's
;;; composition stage by stage (each stage on the native output of the stage
;;; before), the two bulk steps, and aabb-overlap? on pairs. A check already
;;; passed on the very same entity, scene, dt (and mode, for the tile steps) is
;;; not repeated, and in lists of more than 24 entities detect-on-solid (n² per
;;; frame in the reference) is compared on a sample of 24 that changes every
;;; frame. An error raised by one side only is a mismatch; errors on both sides
;;; are agreement (and end that run). One SRFI-64 test per (scene, mode); the
;;; first mismatch of a run ends it and is printed to stderr with a reproducer,
;;; shrunk to the fewest entities and tilemap cells that still disagree. A
;;; summary (runtime, how often each step changed something) goes to stdout.
;;; The scenes are described in scene-gen.scm.
;;;
;;; Run it alone (from the repository root):
;;;   XDG_CACHE_HOME=build/cache build/bin/downstroke tests/scheme/run-suite.scm \
;;;       tests/scheme/differential-test.scm
;;; A longer search, e.g. 50 000 scenes of 120 frames from seed 100 000:
;;;   DS_DIFF_SEED=100000 DS_DIFF_SCENES=50000 DS_DIFF_FRAMES=120 XDG_CACHE_HOME=build/cache \
;;;       build/bin/downstroke tests/scheme/run-suite.scm tests/scheme/differential-test.scm
;;; Re-run one scene: DS_DIFF_SEED=<seed> DS_DIFF_SCENES=1.
;;;
;;; Environment (all optional):
;;;   DS_DIFF_SCENES      number of scenes (seeds)                       default 2000
;;;   DS_DIFF_FRAMES      frames per scene and mode                      default 30
;;;   DS_DIFF_SEED        first seed                                     default 1
;;;   DS_DIFF_CHECK_EVERY per-step checks on frames 0–2 and every Nth    default 10
;;;                       (1: on every frame; 0: on frames 0–2 only)
;;;   DS_DIFF_STEPS       0: no single-step checks, only step-scene (a step-scene
;;;                       mismatch is still traced to the first single step that differs)
;;;   DS_DIFF_REPORTS     scenes reported in full (with shrinking)       default 5
;;;   DS_DIFF_IDENTITY    0: do not compare eq?-ness of unchanged results
;;;   DS_DIFF_INVALID     1: let the generator put a wrongly typed value in ~1 scene in 30
;;;   DS_DIFF_IMPL        the side compared with the native physics:
;;;                         reference  (downstroke reference) (the default; when
;;;                                    scheme/downstroke/reference.scm does not exist
;;;                                    the suite warns and uses `composed')
;;;                         physics    the native physics itself (checks the harness)
;;;                         composed   native per-entity steps composed in Scheme
;;;                         broken:WHAT  `composed' with one deliberate bug, to check
;;;                                    that the harness catches and shrinks it. WHAT:
;;;                                    gravity (apply-gravity adds 2), frame (step-scene
;;;                                    forgets sync-groups: only whole frames differ),
;;;                                    overlap (aabb-overlap? not strict), detect
;;;                                    (detect-on-solid sees the others 1 px lower),
;;;                                    collide (resolve-entity-collisions walks the
;;;                                    pairs backwards), tween (step-tweens adds 1 ms),
;;;                                    raise (apply-velocity-x raises when |vx| > 100)
(use-modules (srfi srfi-64) (downstroke) (srfi srfi-1) (srfi srfi-9) (srfi srfi-11) (ice-9 format))

(load "support.scm")
(load "scene-gen.scm")

;;; ---------------------------------------------------------------- settings
(define (env-int name default)
  (let ((v (getenv name)))
    (or (and v (string->number v) (exact-integer? (string->number v)) (string->number v))
        default)))

(define scene-count (env-int "DS_DIFF_SCENES" 2000))
(define frame-count (env-int "DS_DIFF_FRAMES" 30))
(define first-seed (env-int "DS_DIFF_SEED" 1))
(define check-every (env-int "DS_DIFF_CHECK_EVERY" 10))
(define single-steps? (not (equal? (getenv "DS_DIFF_STEPS") "0")))
(define max-reports (env-int "DS_DIFF_REPORTS" 5))
(define check-identity? (not (equal? (getenv "DS_DIFF_IDENTITY") "0")))
(set! scene-gen-invalid? (equal? (getenv "DS_DIFF_INVALID") "1"))

(define (check-frame? frame)
  (and single-steps?
       (or (< frame 3) (and (positive? check-every) (zero? (modulo frame check-every))))))

(define step-names
  '(step-tweens apply-acceleration apply-gravity apply-speed-limits apply-velocity-x apply-velocity-y
    apply-velocity resolve-tile-collisions-x resolve-tile-collisions-y detect-on-solid
    resolve-entity-collisions sync-groups aabb-overlap? *gravity* *jump-force*
    *on-solid-tolerance* collision-mode push-rule resting-contacts? carry-riders step-scene))

;;; Per-entity steps, checked on every entity of the frame's input.
(define per-entity-steps
  '(step-tweens apply-acceleration apply-gravity apply-speed-limits apply-velocity-x apply-velocity-y
    apply-velocity resolve-tile-collisions-x resolve-tile-collisions-y detect-on-solid))
;;; The frame's composition (semantics §5), then the two bulk steps.
(define frame-stages
  '(step-tweens apply-acceleration apply-gravity apply-speed-limits apply-velocity-x resolve-tile-collisions-x
    apply-velocity-y resolve-tile-collisions-y detect-on-solid))

;;; ---------------------------------------------------------------- the two sides
(define native (resolve-interface '(downstroke physics)))

;;; The per-entity steps of IFACE composed into a frame, as semantics §5 describes
;;; default-engine-update; detect-on-solid sees the frame-start scene without
;;; the entity's own slot, as the native frame step does, and an entity that
;;; ends the frame equal to how it started is kept as the very same object.
(define (composed-step-scene iface)
  (let ((stages (map (lambda (name) (module-ref iface name)) frame-stages))
        (detect (module-ref iface 'detect-on-solid))
        (carry (module-ref iface 'carry-riders))
        (collide (module-ref iface 'resolve-entity-collisions))
        (sync (module-ref iface 'sync-groups)))
    (lambda (scene dt)
      (let* ((entities (scene-entities scene))
             (stepped
              (let loop ((es entities) (before '()) (acc '()))
                (if (null? es)
                    (reverse acc)
                    (let* ((e (fold (lambda (step e) (step e scene dt)) (car es)
                                    (drop-right stages 1)))
                           (others (update-scene scene #:entities (append-reverse before (cdr es))))
                           (e (detect e others dt)))
                      (loop (cdr es) (cons (car es) before) (cons e acc))))))
             (result (map (lambda (new old) (if (same? new old) old new))
                          (sync (collide (carry stepped scene dt))) entities)))
        (if (every eq? result entities) scene (update-scene scene #:entities result))))))

;;; A module whose bindings are physics' with OVERRIDES ((name . value) ...),
;;; and a step-scene composed from its own steps (unless OVERRIDES has one).
(define (stand-in overrides)
  (let ((m (make-module)))
    (for-each (lambda (name) (module-define! m name (module-ref native name))) step-names)
    (for-each (lambda (o) (module-define! m (car o) (cdr o))) overrides)
    (unless (assq 'step-scene overrides)
      (module-define! m 'step-scene (composed-step-scene m)))
    m))

;;; The deliberate bugs of DS_DIFF_IMPL=broken:WHAT, as stand-in overrides.
(define (sabotage what)
  (define (n name) (module-ref native name))
  (case what
    ((gravity)
     `((apply-gravity
        . ,(lambda (entity scene dt)
             (let ((e ((n 'apply-gravity) entity scene dt)))
               (if (eq? e entity) e (entity-set e #:vy (+ 1 (entity-ref e #:vy 0)))))))))
    ((frame)
     `((step-scene
        . ,(lambda (scene dt)
             ((composed-step-scene (stand-in `((sync-groups . ,(lambda (es) es))))) scene dt)))))
    ((overlap)
     `((aabb-overlap?
        . ,(lambda (x1 y1 w1 h1 x2 y2 w2 h2)
             (and (<= x1 (+ x2 w2)) (<= x2 (+ x1 w1)) (<= y1 (+ y2 h2)) (<= y2 (+ y1 h1)))))))
    ((detect)
     `((detect-on-solid
        . ,(lambda (entity scene dt)
             ((n 'detect-on-solid) entity
              (update-scene scene #:entities
                            (map (lambda (o) (if (eq? o entity) o
                                                 (entity-set o #:y (+ 1 (entity-ref o #:y 0)))))
                                 (scene-entities scene)))
              dt)))))
    ((collide)
     `((resolve-entity-collisions
        . ,(lambda (es)
             (let ((r ((n 'resolve-entity-collisions) (reverse es))))
               (if (every eq? r (reverse es)) es (reverse r)))))))
    ((tween) `((step-tweens . ,(lambda (e scene dt) ((n 'step-tweens) e scene (+ dt 1))))))
    ((raise)
     `((apply-velocity-x
        . ,(lambda (e scene dt)
             (when (> (abs (entity-ref e #:vx 0)) 100) (error "too fast:" (entity-ref e #:vx)))
             ((n 'apply-velocity-x) e scene dt)))))
    (else #f)))

(define reference-file (search-path %load-path "downstroke/reference.scm"))
(define impl-choice
  (let ((v (getenv "DS_DIFF_IMPL")))
    (cond ((and v (not (string-null? v))) (string->symbol v))
          (reference-file 'reference)
          (else
           (format (current-error-port)
                   "differential: scheme/downstroke/reference.scm not found; comparing with \
the `composed' stand-in instead (DS_DIFF_IMPL=reference to insist)~%")
           'composed))))

;;; The interface compared with native, or the error text if it cannot be had.
(define reference
  (case impl-choice
    ((reference) (or (error-text (lambda () (resolve-interface '(downstroke reference))))
                     (resolve-interface '(downstroke reference))))
    ((physics) native)
    ((composed) (stand-in '()))
    (else
     (let* ((name (symbol->string impl-choice))
            (what (and (string-prefix? "broken:" name) (string->symbol (substring name 7))))
            (overrides (and what (sabotage what))))
       (if overrides
           (stand-in overrides)
           (format #f "unknown DS_DIFF_IMPL ~a" impl-choice))))))

(define (ref name) (module-ref reference name))
(define (nat name) (module-ref native name))

;;; ---------------------------------------------------------------- comparing
;;; (ok . value) or (error key . args).
(define (attempt thunk)
  (catch #t
    (lambda () (cons 'ok (thunk)))
    (lambda (key . args) (cons* 'error key args))))
(define (ok? outcome) (eq? (car outcome) 'ok))
;;; What an outcome shows in a report: its value, or "error: " and the message.
(define (shown outcome)
  (if (ok? outcome)
      (cdr outcome)
      (string-append
       "error: "
       (or (false-if-exception
            (call-with-output-string
             (lambda (port) (print-exception port #f (cadr outcome) (cddr outcome)))))
           (format #f "~s" (cdr outcome))))))

(define tween-rtd
  (record-type-descriptor (make-tween '() #:props '() #:duration 1)))
(define tween-field-count (length (record-type-fields tween-rtd)))

;;; Equality that tells 1 from 1.0 and 0.0 from -0.0 at any depth; tweens
;;; field by field (procedures by identity).
(define (same? a b)
  (cond ((eq? a b) #t)
        ((number? a) (and (number? b) (eqv? a b)))
        ((pair? a) (and (pair? b) (same? (car a) (car b)) (same? (cdr a) (cdr b))))
        ((string? a) (and (string? b) (string=? a b)))
        ((vector? a) (and (vector? b) (= (vector-length a) (vector-length b))
                          (every same? (vector->list a) (vector->list b))))
        ((tween? a)
         (and (tween? b)
              (every (lambda (i) (same? (struct-ref a i) (struct-ref b i)))
                     (iota tween-field-count))))
        (else (equal? a b))))

;;; Where two entities differ: (key native-value reference-value), or #f.
(define (entity-diff a b)
  (let loop ((p a) (q b) (pos 0))
    (cond ((and (null? p) (null? q)) #f)
          ((and (pair? p) (pair? (cdr p)) (pair? q) (pair? (cdr q)))
           (cond ((not (eq? (car p) (car q)))
                  (list (format #f "<key at position ~a>" pos) (car p) (car q)))
                 ((same? (cadr p) (cadr q)) (loop (cddr p) (cddr q) (+ pos 1)))
                 (else (list (car p) (cadr p) (cadr q)))))
          ((and (pair? p) (pair? (cdr p)) (null? q))
           (list (car p) (cadr p) '<absent>))
          ((and (null? p) (pair? q) (pair? (cdr q)))
           (list (car q) '<absent> (cadr q)))
          ((same? p q) #f)
          (else (list "<entity>" a b)))))

;;; The identity check for one result: whether each side returned its input.
(define (identity-diff in nout rout)
  (and check-identity?
       (not (eq? (eq? nout in) (eq? rout in)))
       (list "<returned its argument (eq?)>" (eq? nout in) (eq? rout in))))

;;; Where two outcomes of a per-entity step on IN differ: (key native reference), or #f.
(define (outcome-diff in n r)
  (cond ((and (not (ok? n)) (not (ok? r))) #f)
        ((not (and (ok? n) (ok? r))) (list "<error>" (shown n) (shown r)))
        ((same? (cdr n) (cdr r)) (identity-diff in (cdr n) (cdr r)))
        (else (entity-diff (cdr n) (cdr r)))))

;;; Where two entity lists differ, given the inputs each side started from:
;;; (index key native reference), or #f.
(define (list-diff n-in r-in n r)
  (cond ((not (and (list? n) (list? r))) (list #f "<result>" n r))
        ((not (= (length n) (length r))) (list #f "<length>" (length n) (length r)))
        (else
         (let loop ((i 0) (n n) (r r) (ni n-in) (ri r-in))
           (if (null? n)
               #f
               (let* ((ni* (and (pair? ni) (car ni))) (ri* (and (pair? ri) (car ri)))
                      (d (if (same? (car n) (car r))
                             (and check-identity? ni* ri*
                                  (not (eq? (eq? (car n) ni*) (eq? (car r) ri*)))
                                  (list "<unchanged element is its input (eq?)>"
                                        (eq? (car n) ni*) (eq? (car r) ri*)))
                             (entity-diff (car n) (car r)))))
                 (if d
                     (cons i d)
                     (loop (+ i 1) (cdr n) (cdr r) (if (pair? ni) (cdr ni) '())
                           (if (pair? ri) (cdr ri) '())))))))))

;;; ---------------------------------------------------------------- mismatches
;;; KIND is entity (INPUTS: entity scene-entities dt), bulk (INPUTS: entities),
;;; pair (INPUTS: a b) or scene (INPUTS: initial-entities, frame k: frames 0…k
;;; reproduce it).
(define-record-type <mismatch>
  (make-mismatch kind step where frame index key nval rval before inputs)
  mismatch?
  (kind mismatch-kind) (step mismatch-step) (where mismatch-where)
  (frame mismatch-frame) (index mismatch-index) (key mismatch-key)
  (nval mismatch-nval) (rval mismatch-rval) (before mismatch-before)
  (inputs mismatch-inputs))

;;; ---------------------------------------------------------------- statistics
(define stats (make-hash-table))           ; step → #(checks changed both-errors runs)
(define run-changed '())                   ; the steps that changed something in this run
(define (count! step checks changed both-errors)
  (when (and (positive? changed) (not (memq step run-changed)))
    (set! run-changed (cons step run-changed)))
  (let ((v (or (hash-ref stats step)
               (let ((v (make-vector 4 0))) (hash-set! stats step v) v))))
    (vector-set! v 0 (+ checks (vector-ref v 0)))
    (vector-set! v 1 (+ changed (vector-ref v 1)))
    (vector-set! v 2 (+ both-errors (vector-ref v 2)))))
(define (count1! step changed? both-error?)
  (count! step 1 (if changed? 1 0) (if both-error? 1 0)))

;;; ---------------------------------------------------------------- single steps
;;; Run STEP on E with SCENE on both sides: (native-outcome . mismatch-or-#f).
(define (check-entity-step step where e scene dt frame index)
  (let* ((n (attempt (lambda () ((nat step) e scene dt))))
         (r (attempt (lambda () ((ref step) e scene dt))))
         (d (outcome-diff e n r)))
    (count1! step (and (ok? n) (not (eq? (cdr n) e))) (not (or (ok? n) (ok? r))))
    (cons n (and d (entity-mismatch step where frame index d e scene dt)))))

(define (entity-mismatch step where frame index d e scene dt)
  (apply make-mismatch 'entity step where frame index
         (append d (list e (list e (scene-entities scene) dt)))))

;;; Per-entity checks already passed for this seed: entity → ((step . #(scene-entities
;;; tilemap dt mode native-result)) …), by identity. The frame's composition
;;; re-runs most steps on the very entities the input pass checked, and frame 0
;;; is the same in both modes; such checks are not repeated.
(define memo (make-hash-table))
(define mode-dependent '(resolve-tile-collisions-x resolve-tile-collisions-y))
(define detect-sample 24)               ; detect-on-solid checks per list and frame, at most

(define (memo-ref step e scene dt)
  (let ((hit (assq step (hashq-ref memo e '()))))
    (and hit
         (let ((v (cdr hit)))
           (and (eq? (vector-ref v 0) (scene-entities scene))
                (eq? (vector-ref v 1) (scene-tilemap scene))
                (eqv? (vector-ref v 2) dt)
                (or (not (memq step mode-dependent)) (eq? (vector-ref v 3) (collision-mode)))
                v)))))

(define (memo-set! step e scene dt result)
  (hashq-set! memo e (acons step (vector (scene-entities scene) (scene-tilemap scene) dt
                                         (collision-mode) result)
                            (hashq-ref memo e '()))))

;;; Run STEP on each of ENTITIES with SCENE on both sides:
;;; (native-results . mismatch-or-#f), where an entity both sides refused
;;; stands for its own result. Each side runs the whole list under one catch;
;;; only when something raised is it redone entity by entity.
(define (check-step-over step where entities scene dt frame)
  (let* ((known (map (lambda (e) (memo-ref step e scene dt)) entities))
         (todo (filter-map (lambda (e k i) (and (not k) (cons i e))) entities known
                           (iota (length entities))))
         (np (nat step)) (rp (ref step))
         ;; detect-on-solid reads the whole scene, so a frame of it costs n²:
         ;; in big scenes only a sample (a different one every frame) is
         ;; compared; the native side still runs on all, for the next stage.
         (sampled (if (and (eq? step 'detect-on-solid) (> (length todo) detect-sample))
                      (let ((k (ceiling-quotient (length todo) detect-sample)))
                        (filter (lambda (ie) (= (modulo (car ie) k) (modulo frame k))) todo))
                      todo))
         (skipped (if (eq? sampled todo)
                      '()
                      (let ((r (attempt (lambda ()
                                          (map (lambda (ie) (cons (car ie) (np (cdr ie) scene dt)))
                                               (lset-difference eq? todo sampled))))))
                        (if (ok? r) (cdr r) '()))))
         (todo sampled)
         (n (attempt (lambda () (map (lambda (ie) (np (cdr ie) scene dt)) todo))))
         (r (attempt (lambda () (map (lambda (ie) (rp (cdr ie) scene dt)) todo))))
         ;; ((index . native-outcome) …) and the first mismatch, for TODO
         (checked
          (if (and (ok? n) (ok? r))
              (let loop ((ies todo) (ns (cdr n)) (rs (cdr r)) (acc '()) (changed 0))
                (if (null? ies)
                    (begin (count! step (length acc) changed 0) (cons (reverse! acc) #f))
                    (let* ((i (caar ies)) (e (cdar ies)) (nx (car ns)) (rx (car rs))
                           (d (if (same? nx rx) (identity-diff e nx rx) (entity-diff nx rx)))
                           (acc (acons i (cons 'ok nx) acc)))
                      (if d
                          (begin (count! step (length acc) changed 0)
                                 (cons (reverse! acc) (entity-mismatch step where frame i d e scene dt)))
                          (begin
                            (memo-set! step e scene dt nx)
                            (loop (cdr ies) (cdr ns) (cdr rs) acc
                                  (if (eq? nx e) changed (+ changed 1))))))))
              (let ((each (map (lambda (ie) (check-entity-step step where (cdr ie) scene dt frame (car ie)))
                               todo)))
                (cons (map (lambda (ie c) (cons (car ie) (car c))) todo each)
                      (any cdr each)))))
         (outcomes (car checked)))
    (cons (map (lambda (e k i)
                 (if k
                     (vector-ref k 4)
                     (let ((o (assv-ref outcomes i)))
                       (cond ((and o (ok? o)) (cdr o))
                             ((assv i skipped) => cdr)
                             (else e)))))
               entities known (iota (length entities)))
          (cdr checked))))

;;; Run bulk STEP on ENTITIES on both sides: (native-outcome . mismatch-or-#f).
(define* (check-bulk-step step where entities frame #:optional (args '()))
  (let* ((n (attempt (lambda () (apply (nat step) entities args))))
         (r (attempt (lambda () (apply (ref step) entities args))))
         (d (cond ((and (not (ok? n)) (not (ok? r))) #f)
                  ((not (and (ok? n) (ok? r))) (list #f "<error>" (shown n) (shown r)))
                  ((and check-identity? (not (eq? (eq? (cdr n) entities) (eq? (cdr r) entities))))
                   (list #f "<returned its argument (eq?)>" (eq? (cdr n) entities) (eq? (cdr r) entities)))
                  (else (list-diff entities entities (cdr n) (cdr r))))))
    (count1! step (and (ok? n) (not (eq? (cdr n) entities))) (not (or (ok? n) (ok? r))))
    (cons n
          (and d
               (make-mismatch 'bulk step where frame (car d) (cadr d) (caddr d) (cadddr d)
                              (and (car d) (< (car d) (length entities)) (list-ref entities (car d)))
                              (list entities))))))

;;; Pairs of indices into ENTITIES to try aabb-overlap? on: all of them for
;;; small lists, about 3 per entity for large ones.
(define (pairs-of entities)
  (let ((n (length entities)))
    (if (<= n 12)
        (append-map (lambda (i) (map (lambda (j) (cons i j)) (iota (- n i) i))) (iota n))
        (append-map (lambda (i) (list (cons i (modulo (+ i 1) n)) (cons i (modulo (+ i 2) n))
                                      (cons i (modulo (+ (* 7 i) 3) n))))
                    (iota n)))))

;;; aabb-overlap? takes the two boxes as 8 numbers: (x y width height) of
;;; each entity (missing keys read 0).
(define (box-of e)
  (let ((b (attempt (lambda () (map (lambda (k) (entity-ref e k 0)) '(#:x #:y #:width #:height))))))
    (and (ok? b) (cdr b))))

(define (check-pairs where entities frame)
  (let* ((v (list->vector (map box-of entities)))
         (pairs (filter (lambda (ij) (and (vector-ref v (car ij)) (vector-ref v (cdr ij))))
                        (pairs-of entities)))
         (args (map (lambda (ij) (append (vector-ref v (car ij)) (vector-ref v (cdr ij)))) pairs))
         (np (nat 'aabb-overlap?)) (rp (ref 'aabb-overlap?))
         (n-all (attempt (lambda () (map (lambda (a) (apply np a)) args))))
         (r-all (attempt (lambda () (map (lambda (a) (apply rp a)) args)))))
    (if (and (ok? n-all) (ok? r-all) (every eq? (cdr n-all) (cdr r-all)))
        (begin (count! 'aabb-overlap? (length args) (count identity (cdr n-all)) 0) #f)
        (any (lambda (ij a)
               (let ((n (attempt (lambda () (apply np a))))
                     (r (attempt (lambda () (apply rp a)))))
                 (count1! 'aabb-overlap? (and (ok? n) (cdr n)) (not (or (ok? n) (ok? r))))
                 (and (not (and (not (ok? n)) (not (ok? r))))
                      (not (and (ok? n) (ok? r) (eq? (cdr n) (cdr r))))
                      (make-mismatch 'pair 'aabb-overlap? where frame (list (car ij) (cdr ij))
                                     "<result>" (shown n) (shown r) a
                                     (list (list-ref entities (car ij))
                                           (list-ref entities (cdr ij)))))))
             pairs args))))

;;; Every single-step check of one frame, whose input is SCENE: a mismatch or #f.
(define (check-steps scene dt frame)
  (let ((entities (scene-entities scene)))
    (or
     ;; Each per-entity step on the frame's input.
     (any (lambda (step) (cdr (check-step-over step "on the frame's input" entities scene dt frame)))
          per-entity-steps)
     ;; The composition, stage by stage, each on the native output of the last.
     (let loop ((stages frame-stages) (es entities) (after "the frame's input"))
       (if (null? stages)
           (let* ((where (string-append "after " after))
                  (carried (check-bulk-step 'carry-riders where es frame (list scene dt))))
             ;; carry-riders hands back its argument on scenes without carriers.
             (or (cdr carried)
                 (let* ((es (if (ok? (car carried)) (cdar carried) es))
                        (c (check-bulk-step 'resolve-entity-collisions where es frame)))
                   (or (cdr c)
                       (check-pairs where es frame)
                       (let ((es2 (if (ok? (car c)) (cdar c) es)))
                         (cdr (check-bulk-step 'sync-groups "after resolve-entity-collisions" es2 frame)))))))
           (let ((c (check-step-over (car stages) (string-append "after " after) es scene dt frame)))
             (or (cdr c) (loop (cdr stages) (car c) (symbol->string (car stages)))))))
     ;; The bulk steps and aabb-overlap? on the frame's input.
     (cdr (check-bulk-step 'resolve-entity-collisions "on the frame's input" entities frame))
     (cdr (check-bulk-step 'sync-groups "on the frame's input" entities frame))
     (check-pairs "on the frame's input" entities frame))))

;;; ---------------------------------------------------------------- whole frames
;;; Compare the outcomes of step-scene on N-IN / R-IN: a mismatch (without
;;; inputs) or #f.
(define (scene-diff n-in r-in n r frame)
  (define (mm index key nv rv)
    (make-mismatch 'scene 'step-scene "whole frame" frame index key nv rv
                   (and index (< index (length (scene-entities n-in)))
                        (list-ref (scene-entities n-in) index))
                   #f))
  (cond ((and (not (ok? n)) (not (ok? r))) #f)
        ((not (and (ok? n) (ok? r))) (mm #f "<error>" (shown n) (shown r)))
        ((not (and (scene? (cdr n)) (scene? (cdr r)))) (mm #f "<result is a scene>" (cdr n) (cdr r)))
        ((and check-identity? (not (eq? (eq? (cdr n) n-in) (eq? (cdr r) r-in))))
         (mm #f "<returned its argument (eq?)>" (eq? (cdr n) n-in) (eq? (cdr r) r-in)))
        ((not (and (eq? (scene-tilemap (cdr n)) (scene-tilemap n-in))
                   (eq? (scene-tilemap (cdr r)) (scene-tilemap r-in))))
         (mm #f "<tilemap carried>" (scene-tilemap (cdr n)) (scene-tilemap (cdr r))))
        (else
         (let ((d (list-diff (scene-entities n-in) (scene-entities r-in)
                             (scene-entities (cdr n)) (scene-entities (cdr r)))))
           (cond (d (apply mm d))
                 ((not (equal? (scene-contacts (cdr n)) (scene-contacts (cdr r))))
                  (mm #f "<scene-contacts>" (scene-contacts (cdr n)) (scene-contacts (cdr r))))
                 ((not (equal? (scene-contact-sides (cdr n)) (scene-contact-sides (cdr r))))
                  (mm #f "<scene-contact-sides>" (scene-contact-sides (cdr n)) (scene-contact-sides (cdr r))))
                 (else #f))))))

;;; Both sides' scenes with FRAME's tile edits (scene-gen's tile-edits, drawn
;;; from the native side's entities) made to the map: the same new map on
;;; both sides, as (values native reference). Without edits, NS and RS.
(define edit-log '())                      ; this run's edits: ((frame edit …) …), last first

(define (edit-scenes seed frame ns rs)
  (let ((edits (tile-edits seed frame (scene-tilemap ns) (scene-entities ns))))
    (when (= frame 0) (set! edit-log '()))
    (if (null? edits)
        (values ns rs)
        (let ((m (edit-tilemap (scene-tilemap ns) edits)))
          (set! edit-log (cons (cons frame edits) edit-log))
          (count! 'tilemap-set-tile (length edits) (length edits) 0)
          (values (update-scene ns #:tilemap m) (update-scene rs #:tilemap m))))))

;;; Step SCENE for frames 0 … LAST (#f: frame-count − 1) on both sides.
;;; Returns (mismatch . native-final-entities); the mismatch is #f when all
;;; agree. With STEPS? the single-step checks run on the chosen frames.
(define* (run-scene seed scene #:key (last #f) (steps? #t))
  (let ((last (or last (- frame-count 1))))
    (let loop ((frame 0) (ns scene) (rs scene))
      (if (> frame last)
          (cons #f (scene-entities ns))
          (let*-values (((ns rs) (edit-scenes seed frame ns rs))
                        ((dt) (scene-dt seed frame)))
           (let* (
                 (m (and steps? (check-frame? frame) (check-steps ns dt frame))))
            (if m
                (cons m #f)
                (let* ((n (attempt (lambda () ((nat 'step-scene) ns dt))))
                       (r (attempt (lambda () ((ref 'step-scene) rs dt))))
                       (m (scene-diff ns rs n r frame)))
                  (count1! 'step-scene (and (ok? n) (not (eq? (cdr n) ns))) (not (or (ok? n) (ok? r))))
                  (cond (m (cons m ns))         ; ns: the input of the failing frame
                        ((not (ok? n)) (cons #f #f))   ; both raised: agreement, stop
                        (else (loop (+ frame 1) (cdr n) (cdr r))))))))))))

;;; ---------------------------------------------------------------- shrinking
(define shrink-budget 3000)                 ; predicate calls per shrink

;;; A smaller list for which (FAILS? list) still holds: removes chunks of
;;; halving size, then single elements until none can go.
(define (shrink-list lst fails?)
  (let ((budget shrink-budget))
    (define (try cand) (and (> budget 0) (begin (set! budget (- budget 1)) (fails? cand))))
    (let outer ((lst lst) (chunk (max 1 (quotient (length lst) 2))))
      (let inner ((start 0) (lst lst) (removed? #f))
        (cond ((>= start (length lst))
               (cond ((> chunk 1) (outer lst (quotient chunk 2)))
                     ((and removed? (> budget 0)) (outer lst 1))
                     (else lst)))
              (else
               (let ((cand (append (take lst start) (drop lst (min (length lst) (+ start chunk))))))
                 (if (try cand)
                     (inner start cand #t)
                     (inner (+ start chunk) lst removed?)))))))))

;;; Whether the mismatch M (its step and kind) still shows with ENTITIES and TILEMAP.
(define (still-fails? m seed mode entities tilemap)
  (parameterize ((collision-mode mode))
    (case (mismatch-kind m)
      ((entity)
       (let* ((in (mismatch-inputs m)) (e (car in)) (dt (caddr in))
              (scene (make-scene #:entities entities #:tilemap tilemap #:gravity (scene-gravity-for seed))))
         (and (cdr (check-entity-step (mismatch-step m) "" e scene dt 0 0)) #t)))
      ((bulk)
       (and (cdr (check-bulk-step (mismatch-step m) "" entities 0)) #t))
      ((pair) #t)
      ((scene)
       (and (car (run-scene seed (make-scene #:entities entities #:tilemap tilemap #:gravity (scene-gravity-for seed))
                            #:last (mismatch-frame m) #:steps? #f))
            #t)))))

;;; The list that shrinking works on, and the entity to try alone first.
(define (shrink-start m)
  (case (mismatch-kind m)
    ((entity) (cadr (mismatch-inputs m)))
    ((bulk) (car (mismatch-inputs m)))
    ((pair) (mismatch-inputs m))
    ((scene) (car (mismatch-inputs m)))))

;;; (entities . tilemap-cells): a small failing case; CELLS is ((index . gid) …) or #f.
(define (shrink m seed mode spec)
  (let* ((tilemap (tilemap-spec->tilemap spec))
         (start (shrink-start m))
         (fails? (lambda (es) (still-fails? m seed mode es tilemap)))
         (index (mismatch-index m))
         (entities
          (cond ((eq? (mismatch-kind m) 'pair) start)
                ((fails? '()) '())
                ((and (integer? index) (< index (length start))
                      (fails? (list (list-ref start index))))
                 (list (list-ref start index)))
                (else (shrink-list start fails?)))))
    (cons entities
          (and spec
               (if (still-fails? m seed mode entities #f)
                   #f
                   (let ((cells-fail?
                          (lambda (cells)
                            (still-fails? m seed mode entities
                                          (apply (lambda (cols rows tw th v)
                                                   (sparse-tilemap cols rows tw th cells))
                                                 spec)))))
                     (shrink-list (spec-cells spec) cells-fail?)))))))

;;; ---------------------------------------------------------------- reporting
(define reports 0)
(define failures '())

(define (err . args) (apply format (current-error-port) args))

(define (report! m seed mode spec)
  (set! failures (cons (list seed mode) failures))
  (set! reports (+ reports 1))
  (if (> reports max-reports)
      (err "DIFF seed ~a ~a: frame ~a, ~a (~a), entity ~a, ~a: native ~s, reference ~s~%"
           seed mode (mismatch-frame m) (mismatch-step m) (mismatch-where m)
           (mismatch-index m) (mismatch-key m) (mismatch-nval m) (mismatch-rval m))
      (begin
        (err "~%==== DIFF seed ~a, mode ~a, frame ~a, dt ~a~%" seed mode (mismatch-frame m)
             (scene-dt seed (mismatch-frame m)))
        (err "  step:      ~a (~a)~%" (mismatch-step m) (mismatch-where m))
        (err "  entity:    ~a~%" (or (mismatch-index m) "-"))
        (err "  key:       ~a~%" (mismatch-key m))
        (err "  native:    ~s~%" (mismatch-nval m))
        (err "  reference: ~s~%" (mismatch-rval m))
        (err "  before:    ~s~%" (mismatch-before m))
        (unless (null? edit-log)
          (err "  tile edits before frames ((frame (col row gid) ...) ...), made on both sides (edit-tilemap):~%    ~s~%"
               (reverse edit-log)))
        (err "  re-run:    DS_DIFF_SEED=~a DS_DIFF_SCENES=1 XDG_CACHE_HOME=build/cache build/bin/downstroke \
tests/scheme/run-suite.scm tests/scheme/differential-test.scm~%" seed)
        (let* ((small (shrink m seed mode spec))
               (entities (car small)) (cells (cdr small))
               (scene-expr (format #f "(make-scene #:entities '~s #:gravity ~s #:tilemap ~a)" entities (scene-gravity-for seed)
                                   (if (and spec cells)
                                       (apply (lambda (cols rows tw th v)
                                                (format #f "(sparse-tilemap ~a ~a ~a ~a '~s)"
                                                        cols rows tw th cells))
                                              spec)
                                       "#f"))))
          (err "  shrunk to ~a~a entit~a~a; still disagrees:~%"
               (if (eq? (mismatch-kind m) 'entity) "a scene of " "")
               (length entities) (if (= 1 (length entities)) "y" "ies")
               (if (and spec cells) (format #f " and ~a tilemap cells" (length cells)) ", no tilemap"))
          (err "  (load \"tests/scheme/scene-gen.scm\")  ; for sparse-tilemap~%")
          (case (mismatch-kind m)
            ((entity)
             (err "  (parameterize ((collision-mode '~a))~%    (~a '~s~%      ~a~%      ~s))~%"
                  mode (mismatch-step m) (car (mismatch-inputs m)) scene-expr
                  (caddr (mismatch-inputs m))))
            ((bulk)
             (err "  (parameterize ((collision-mode '~a)) (~a '~s))~%" mode (mismatch-step m) entities))
            ((pair)
             (err "  (aabb-overlap?~{ ~s~})~%" (mismatch-before m)))
            ((scene)
             (err "  (parameterize ((collision-mode '~a))~%    (fold (lambda (dt s) (step-scene s dt))~%          ~a~%          '~s))~%"
                  mode scene-expr
                  (map (lambda (f) (scene-dt seed f)) (iota (+ 1 (mismatch-frame m))))))))
        (err "====~%"))))

;;; A scene's step-scene mismatch: find the single step that differs on that
;;; frame (its input is agreed on), else keep the whole-frame mismatch.
(define (localize m seed mode scene-in)
  (let* ((frame (mismatch-frame m))
         (single (and scene-in (check-steps scene-in (scene-dt seed frame) frame))))
    (when single
      (err "DIFF seed ~a ~a frame ~a: step-scene differs at entity ~a ~a; the first single step \
that differs on that frame is ~a (~a)~%"
           seed mode frame (mismatch-index m) (mismatch-key m) (mismatch-step single)
           (mismatch-where single)))
    (or single m)))

;;; ---------------------------------------------------------------- the suite
(test-begin "differential")

(define reference-ok? (module? reference))
(test-assert (format #f "the compared side loads (~a)" impl-choice) reference-ok?)
(unless reference-ok? (err "differential: ~a~%" reference))

(when reference-ok?
  (test-equal "it has every name physics has" '()
    (remove (lambda (name) (module-variable reference name)) step-names))
  (when (eq? impl-choice 'reference)
    (test-equal "it exports exactly those names" '()
      (lset-difference eq? (module-map (lambda (name var) name) reference) step-names)))
  ;; physics' constants are read-only identifier macros: read them as a game does.
  (test-equal "the same constants"
    (map (lambda (name) (eval name (resolve-module '(downstroke physics))))
         '(*gravity* *jump-force* *on-solid-tolerance*))
    (false-if-exception (map ref '(*gravity* *jump-force* *on-solid-tolerance*))))
  (test-eq "collision-mode is physics' parameter" (nat 'collision-mode)
    (false-if-exception (ref 'collision-mode)))

  (let ((start (get-internal-real-time))
        (entity-total 0)
        (mode-sensitive 0))
    (do ((seed first-seed (+ seed 1))) ((= seed (+ first-seed scene-count)))
      (let ((finals
             (call-with-values (lambda () (generate-scene-parts seed))
               (lambda (entities spec)
                 (set! entity-total (+ entity-total (length entities)))
                 (set! memo (make-hash-table))
                 (let ((tilemap (tilemap-spec->tilemap spec)))
                  (map (lambda (mode)
                        (set! run-changed '())
                        (let* ((scene (make-scene #:entities entities #:tilemap tilemap #:gravity (scene-gravity-for seed)))
                               (outcome (parameterize ((collision-mode mode))
                                          (attempt (lambda () (run-scene seed scene)))))
                               (m (cond ((not (ok? outcome))
                                         (make-mismatch 'none "harness" "" #f #f "<error>"
                                                        (shown outcome) "" #f #f))
                                        ((and (car (cdr outcome))
                                              (eq? (mismatch-kind (car (cdr outcome))) 'scene))
                                         (let ((m (car (cdr outcome))))
                                           (parameterize ((collision-mode mode))
                                            (localize
                                            (make-mismatch 'scene 'step-scene "whole frame"
                                                           (mismatch-frame m) (mismatch-index m)
                                                           (mismatch-key m) (mismatch-nval m)
                                                           (mismatch-rval m) (mismatch-before m)
                                                           (list entities))
                                            seed mode (cdr (cdr outcome))))))
                                        (else (car (cdr outcome))))))
                          (for-each (lambda (step)
                                      (let ((v (hash-ref stats step)))
                                        (vector-set! v 3 (+ 1 (vector-ref v 3)))))
                                    run-changed)
                          (when m
                            (if (eq? (mismatch-kind m) 'none)
                                (err "DIFF seed ~a ~a: the harness itself failed: ~a~%" seed mode
                                     (mismatch-nval m))
                                (catch #t
                                  (lambda () (report! m seed mode spec))
                                  (lambda (key . args)
                                    (err "DIFF seed ~a ~a: reporting failed: ~a~%" seed mode
                                         (shown (cons* 'error key args)))))))
                          (test-equal (format #f "seed ~a ~a" seed mode) "agree"
                            (if m
                                (format #f "frame ~a, ~a (~a), entity ~a, ~a"
                                        (mismatch-frame m) (mismatch-step m) (mismatch-where m)
                                        (mismatch-index m) (mismatch-key m))
                                "agree"))
                          (and (not m) (ok? outcome) (cdr (cdr outcome)))))
                      '(swept discrete)))))))
        (when (and (car finals) (cadr finals) (not (same? (car finals) (cadr finals))))
          (set! mode-sensitive (+ mode-sensitive 1)))))
    (unless (null? failures)
      (err "differential: ~a (scene, mode) runs disagree~a: ~s~%" (length failures)
           (if (> (length failures) 40) ", the first 40" "")
           (list-head (reverse failures) (min 40 (length failures)))))
    (force-output (current-error-port))
    (let ((seconds (/ (- (get-internal-real-time) start) internal-time-units-per-second 1.0)))
      (format #t "differential: ~a vs native, seeds ~a..~a, ~a frames, ~a entities in all (~,1f per scene); \
~a scenes end differently in swept and discrete mode; ~,1f s~%"
              impl-choice first-seed (+ first-seed scene-count -1) frame-count
              entity-total (/ entity-total 1.0 (max 1 scene-count)) mode-sensitive seconds)
      (format #t "differential: per step: checks, how many changed their input (aabb-overlap?: \
answered #t), in how many of the ~a runs, and how many both sides refused:~%" (* 2 scene-count))
      (for-each (lambda (step)
                  (let ((v (hash-ref stats step)))
                    (when v
                      (format #t "  ~26a ~8d checks ~8d changed  ~5d runs ~6d both raised~%"
                              step (vector-ref v 0) (vector-ref v 1) (vector-ref v 3)
                              (vector-ref v 2)))))
                (append step-names '(tilemap-set-tile)))
      (force-output (current-output-port)))))

;;; ---------------------------------------------------------------- sub-frames, resting contacts
;;; The frame options beyond the seed: seeds 1..DS_DIFF_VARIANTS (300) again,
;;; each with substeps 1 + seed mod 4, resting contacts on odd seeds and the
;;; seed's push rule on seeds 2, 3, 6, 7, … (the default, 'clipped, on the
;;; others and in every run above), in both modes; whole frames only (the
;;; single steps do not take options).
(define variant-count (env-int "DS_DIFF_VARIANTS" 300))

(define (push-rule-for seed) (if (even? (quotient seed 2)) 'clipped 'seed))

(define (run-variant seed scene k rest?)
  "The first frame at which native and reference disagree, with its
mismatch, as (frame . mismatch); #f when all FRAME-COUNT frames agree."
  (parameterize ((resting-contacts? rest?) (push-rule (push-rule-for seed)))
    (let loop ((frame 0) (ns scene) (rs scene))
      (and (< frame frame-count)
           (let*-values (((ns rs) (edit-scenes seed frame ns rs))
                         ((dt) (scene-dt seed frame)))
             (let* ((n (attempt (lambda () ((nat 'step-scene) ns dt #:substeps k))))
                    (r (attempt (lambda () ((ref 'step-scene) rs dt #:substeps k))))
                    (m (scene-diff ns rs n r frame)))
               (cond (m (cons frame m))
                     ((not (ok? n)) #f)
                     (else (loop (+ frame 1) (cdr n) (cdr r))))))))))

(when (and reference-ok? (module-variable reference 'resting-contacts?))
  (do ((seed 1 (+ seed 1))) ((> seed variant-count))
    (call-with-values (lambda () (generate-scene-parts seed))
      (lambda (entities spec)
        (let ((tilemap (tilemap-spec->tilemap spec))
              (k (+ 1 (modulo seed 4)))
              (rest? (odd? seed)))
          (for-each
           (lambda (mode)
             (let ((d (parameterize ((collision-mode mode))
                        (run-variant seed (make-scene #:entities entities #:tilemap tilemap #:gravity (scene-gravity-for seed)) k rest?))))
               (when d
                 (err "DIFF variant seed ~a ~a substeps ~a resting ~a push-rule ~a: frame ~a, entity ~a, ~a: native ~s, reference ~s~%"
                      seed mode k rest? (push-rule-for seed) (car d) (mismatch-index (cdr d)) (mismatch-key (cdr d))
                      (mismatch-nval (cdr d)) (mismatch-rval (cdr d))))
               (test-equal (format #f "seed ~a ~a substeps ~a resting ~a" seed mode k rest?) "agree"
                 (if d (format #f "frame ~a, entity ~a, ~a" (car d) (mismatch-index (cdr d))
                               (mismatch-key (cdr d)))
                     "agree"))))
           '(swept discrete)))))))

;;; ---------------------------------------------------------------- nothing sinks (§4)
;;; The clipped push rule's guarantee on the same random scenes, natively:
;;; a body push-apart may move and put out (solid, movable, not a sensor,
;;; skipping nothing, in no group, with no tween, at a finite place) never
;;; ends a frame 1 px or more inside a whole solid cell. (Issue 50 counts
;;; 1 px; the seed's rule breaks it in most scenes with a map.)
(define (sunk-depth e tm)
  "How deep box E sits in one whole solid cell of TM: per cell, the smaller
of the two axis overlaps."
  (let* ((tw (tilemap-tile-width tm)) (th (tilemap-tile-height tm))
         (x (entity-ref e #:x)) (y (entity-ref e #:y)) (w (entity-ref e #:width)) (h (entity-ref e #:height))
         (span (lambda (a b) (iota (- (inexact->exact (ceiling b)) (inexact->exact (floor a)))
                                   (inexact->exact (floor a))))))
    (fold (lambda (r best)
            (fold (lambda (c best)
                    (if (eq? (tilemap-cell-shape tm c r) 'solid)
                        (max best (min (- (min (+ x w) (* (+ c 1) tw)) (max x (* c tw)))
                                       (- (min (+ y h) (* (+ r 1) th)) (max y (* r th)))))
                        best))
                  best (span (/ x tw) (/ (+ x w) tw))))
          0 (span (/ y th) (/ (+ y h) th)))))

(define (pushed-and-put-out? e)
  (let ((place-ok? (lambda (k) (let ((v (entity-ref e k #f))) (and (real? v) (< (abs v) 1e6))))))
    (and (eq? (entity-ref e #:solid? #f) #t) (not (entity-ref e #:immovable? #f))
         (not (entity-ref e #:sensor? #f)) (not (entity-ref e #:group-id #f)) (not (entity-ref e #:tween #f))
         (null? (entity-ref e #:skip-pipelines '()))
         (every place-ok? '(#:x #:y #:width #:height))
         (> (entity-ref e #:width) 0) (> (entity-ref e #:height) 0))))

(let ((checked 0) (sunk '()))
  (do ((seed first-seed (+ seed 1))) ((= seed (+ first-seed scene-count)))
    (let ((scene (generate-scene seed)))
      (when (scene-tilemap scene)
        (parameterize ((push-rule 'clipped))
          (let loop ((frame 0) (s scene))
            (when (< frame frame-count)
              (let* ((s (let-values (((ns rs) (edit-scenes seed frame s s))) ns))
                     (next (false-if-exception ((nat 'step-scene) s (scene-dt seed frame)))))
                (when next
                  (for-each (lambda (e)
                              (when (pushed-and-put-out? e)
                                (set! checked (+ checked 1))
                                (when (>= (sunk-depth e (scene-tilemap next)) 1)
                                  (set! sunk (cons (list seed frame e) sunk)))))
                            (scene-entities next))
                  (loop (+ frame 1) next)))))))))
  (for-each (lambda (c) (err "SUNK seed ~a frame ~a: ~s~%" (car c) (cadr c) (caddr c))) (take sunk (min 5 (length sunk))))
  (test-assert "the clipped push rule: bodies checked" (> checked 0))
  (test-equal "the clipped push rule: no body ends a frame 1 px or more inside a solid cell" 0 (length sunk)))

(test-end "differential")
