#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# install.prefix: a plain `guile' with only the three documented variables
# for a non-system prefix loads (downstroke) from it (compiled, nothing
# auto-compiled) and steps a scene; the installed host runs the installed
# demo, finding the modules of its own prefix.
source "$(dirname "$0")/common.sh"

ball=$(clean GUILE_LOAD_PATH="$sitedir" GUILE_LOAD_COMPILED_PATH="$ccachedir" GUILE_EXTENSIONS_PATH="$extdir" \
  guile -c "(use-modules (downstroke))
            (define floor-map (make-tilemap 4 4 16 16 '(0 0 0 0  0 0 0 0  0 0 0 0  1 1 1 1) '(1)))
            (define ball '(#:id ball #:x 20 #:y 0 #:width 8 #:height 8 #:gravity? #t #:vx 1))
            (define (run scene frames) (if (= frames 0) scene (run (step-scene scene 16) (- frames 1))))
            (write (car (scene-entities (run (make-scene #:tilemap floor-map #:entities (list ball)) 10))))")
[ "$ball" = "(#:id ball #:x 30 #:y 40 #:width 8 #:height 8 #:gravity? #t #:vx 1 #:vy 0 #:on-ground? #t)" ] ||
  fail "guile stepped the ball to $ball"
compiled=$(find "$prefix/cache" -path '*downstroke*' -name '*.go' | wc -l)
[ "$compiled" = 0 ] || fail "guile auto-compiled $compiled installed modules instead of loading their .go"

echo '(display (search-path %load-path "downstroke.scm"))' > "$prefix/where.scm"
where=$(clean "$bindir/downstroke" "$prefix/where.scm")
[ "$where" = "$sitedir/downstroke.scm" ] || fail "the installed host loads (downstroke) from $where"

demo=$(clean "$bindir/downstroke" "$demodir/fall.scm")
expected_demo=$(XDG_CACHE_HOME="$build/cache" "$build/bin/downstroke" "$(dirname "$0")/../../demo/fall.scm")
[ "$demo" = "$expected_demo" ] || fail "the installed demo printed
$demo
instead of
$expected_demo"
# The installed host writes a new game from the installed templates, and the
# game's own tests pass with nothing from this tree.
clean "$bindir/downstroke" new "$prefix/newgame" >/dev/null || fail "downstroke new failed"
tested=$(cd "$prefix/newgame" && clean "$bindir/downstroke" test) || fail "the new game's tests failed: $tested"
[ "$tested" = "tests/game-test.scm: 7 checks
7 passed, 0 failed" ] || fail "the new game's tests said $tested"
echo "install.prefix: guile and the installed host both ran from $prefix"
