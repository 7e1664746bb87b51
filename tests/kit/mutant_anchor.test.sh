#!/usr/bin/env bash
# A mutant is anchored by its name (cmake/MutantAnchor.cmake): reformatting the code or
# rewording a comment never breaks one, and a name anchored nowhere, or twice, stops the
# configure with a line that says which.
#   mutant_anchor.test.sh ROOT
set -uo pipefail
root="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# apply NAME FIND REPLACE EVERYWHERE < reference: the mutated text on stdout, or the
# configure's error and a non-zero exit.
apply() {
  cat >"$work/reference.cpp"
  cat >"$work/apply.cmake" <<SCRIPT
cmake_minimum_required(VERSION 3.25)
include("$root/cmake/MutantAnchor.cmake")
file(READ "$work/reference.cpp" text)
labkit_mutant_apply(text "$1" "$2" "$3" "$4" "reference.cpp")
file(WRITE "$work/mutated.cpp" "\${text}")
SCRIPT
  rm -f "$work/mutated.cpp"
  cmake -P "$work/apply.cmake" >"$work/log" 2>&1 || { cat "$work/log"; return 1; }
  cat "$work/mutated.cpp"
}

echo "--- 1. the anchored place is edited, however the code around it is laid out"
out=$(apply late "if (t >= best) return;" "if (t <= best) return;" FALSE <<'CPP'
int f(double t, double best) {
  if (t >= best) return 0;  // elsewhere: the same words, no anchor
  // mutant: late
  if (t >=
      best)   return;  // a comment reworded freely
  return 1;
}
CPP
) || fail "an anchored mutant was refused: $out"
grep -q "if (t <= best) return;  // a comment reworded freely" <<<"$out" || fail "the anchored line was not edited: $out"
grep -q "if (t >= best) return 0;  // elsewhere" <<<"$out" || fail "the line above the anchor was edited: $out"

echo "--- 2. two names on one anchor line"
out=$(apply second "x = 1;" "x = 2;" FALSE <<'CPP'
  // mutants: first, second
  x = 1;
CPP
) || fail "a name in a 'mutants:' list was refused: $out"
grep -q "x = 2;" <<<"$out" || fail "the listed name did not edit its place: $out"

echo "--- 3. refused: no anchor, FIND not below it, FIND twice, two anchors without EVERYWHERE"
refused() {  # WHAT WORDS NAME FIND EVERYWHERE < reference
  local what="$1" words="$2"
  shift 2
  if out=$(apply "$1" "$2" "y" "$3"); then
    fail "$what was accepted"
  else
    grep -q "$words" <<<"$out" || fail "$what: the error does not say '$words': $out"
  fi
}
refused "a name with no anchor" "no anchor" missing "x = 1;" FALSE <<<'x = 1;'
refused "FIND not below its anchor" "is not in the code below its anchor" far "x = 1;" FALSE <<'CPP'
x = 1;
// mutant: far
z = 3;

x = 1;
CPP
refused "FIND twice below one anchor" "appears twice" twice "x = 1;" FALSE <<'CPP'
// mutant: twice
x = 1;
x = 1;
CPP
refused "two anchors without EVERYWHERE" "2 anchors" both "x = 1;" FALSE <<'CPP'
// mutant: both
x = 1;
// mutant: both
x = 1;
CPP

echo "--- 4. EVERYWHERE: each anchor's place"
out=$(apply both "x = 1;" "x = 2;" TRUE <<'CPP'
// mutant: both
x = 1;
// mutant: both
x = 1;
CPP
) || fail "EVERYWHERE was refused: $out"
[ "$(grep -c "x = 2;" <<<"$out")" -eq 2 ] || fail "EVERYWHERE did not edit both places: $out"

echo "--- 5. every anchor in the references names a mutant"
names=$(sed -n 's/.*NAME \([a-z0-9_]*\).*/\1/p' "$root"/tests/*/mutants.cmake | sort -u)
for reference in "$root"/solutions/*/*.cpp; do
  [ -f "$reference" ] || continue
  while read -r name; do
    grep -qx "$name" <<<"$names" || fail "${reference#$root/} anchors '$name', which no mutant has"
  done < <(sed -n 's|^ *// mutants\{0,1\}: \(.*\)$|\1|p' "$reference" | tr ', ' '\n\n' | sed '/^$/d')
done

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "mutant anchors: all good"
