#!/usr/bin/env bash
# A mutant is written in the reference, above the code it edits (cmake/Mutants.cmake):
# reformatting the code or rewording a comment never breaks one, and a mutant the configure
# cannot place, or cannot read, stops it with a line that names the file, the line and why.
#   mutants.test.sh ROOT
set -uo pipefail
root="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# apply NAME < reference: the reference with mutant NAME written in, on stdout, and its
# step and words in $work/spec; or the configure's error and a non-zero exit.
apply() {
  cat >"$work/reference.cpp"
  cat >"$work/apply.cmake" <<SCRIPT
cmake_minimum_required(VERSION 3.25)
include("$root/cmake/Mutants.cmake")
file(READ "$work/reference.cpp" text)
labkit_mutant_specs(m "\${text}" "reference.cpp")
file(WRITE "$work/spec" "names=\${m_names} step=\${m_$1_step} says=\${m_$1_says}")
labkit_mutant_source(mutated m "$1" "\${text}" "reference.cpp")
file(WRITE "$work/mutated.cpp" "\${mutated}")
SCRIPT
  rm -f "$work/mutated.cpp" "$work/spec"
  cmake -P "$work/apply.cmake" >"$work/log" 2>&1 || { cat "$work/log"; return 1; }
  cat "$work/mutated.cpp"
}

echo "--- 1. the place below the mutant is edited, however the code around it is laid out"
out=$(apply late <<'CPP'
int f(double t, double best) {
  if (t >= best) return 0;  // elsewhere: the same words, no mutant above them
  // A comment of the reference, reworded freely.
  // mutant late (step 3, "first contact", "t"): `t >= best` -> `t <= best`
  if (t >=
      best)   return;  // a comment reworded freely
  return 1;
}
CPP
) || fail "a mutant was refused: $out"
grep -q "if (t <= best)   return;  // a comment reworded freely" <<<"$out" || fail "the line below was not edited: $out"
grep -q "if (t >= best) return 0;  // elsewhere" <<<"$out" || fail "the line above the mutant was edited: $out"
grep -qx 'names=late step=3 says=first contact;t' "$work/spec" || fail "its step and words were misread: $(cat "$work/spec")"

echo "--- 2. two mutants above one place, one written over three lines"
reference='
  // mutant first (step 1, "one"): `x = 1` -> `x = 0`
  // Why the second one is a classic mistake.
  // mutant second (step 2, "two words", "three"):
  //   `x = 1;`
  //   -> `x = 2; y = 3;`
  x = 1;
  z = 4;
'
out=$(apply second <<<"$reference") || fail "a mutant written over three lines was refused: $out"
grep -q "x = 2; y = 3;" <<<"$out" || fail "the second mutant did not edit its place: $out"
grep -q "// mutant first" <<<"$out" || fail "the reference's other lines were lost: $out"
grep -qx 'names=first;second step=2 says=two words;three' "$work/spec" || fail "the names or words were misread: $(cat "$work/spec")"
out=$(apply first <<<"$reference") || fail "the first of two mutants was refused: $out"
grep -q "x = 0;" <<<"$out" || fail "the first mutant did not edit the shared place: $out"

echo "--- 3. one name at two places edits both"
out=$(apply both <<'CPP'
  // mutant both (step 5, "each"): `x = 1;` -> `x = 2;`
  x = 1;

  // mutant both (step 5, "each"): `x = 1;` -> `x = 2;`
  x = 1;
CPP
) || fail "a name at two places was refused: $out"
[ "$(grep -c "^  x = 2;" <<<"$out")" -eq 2 ] || fail "the two places were not both edited: $out"

echo "--- 4. refused, each with the line and the reason"
refused() {  # WHAT WORDS NAME < reference
  local what="$1" words="$2"
  if out=$(apply "$3"); then
    fail "$what was accepted"
  else
    # CMake wraps a long message: its words, on one line.
    out=$(tr -s ' \n' '  ' <<<"$out")
    grep -qF "$words" <<<"$out" || fail "$what: the error does not say '$words': $out"
  fi
}
refused "text not in the code below" "reference.cpp:3: mutant 'far': \`x = 1;\` is not in the code below it" far <<'CPP'
x = 1;
z = 0;
// mutant far (step 1, "w"): `x = 1;` -> `y`
z = 3;

x = 1;
CPP
refused "text not above the next mutant" "is not in the code below it" near <<'CPP'
// mutant near (step 1, "w"): `x = 1;` -> `y`
z = 3;
// The next mistake.
// mutant other (step 1, "w"): `x = 1;` -> `y`
x = 1;
CPP
refused "text twice below" "appears twice in the code below it" twice <<'CPP'
// mutant twice (step 1, "w"): `x = 1;` -> `y`
x = 1;
x = 1;
CPP
refused "no step" "a mutant is written // mutant NAME (step K" bad <<'CPP'
// mutant bad ("w"): `x = 1;` -> `y`
x = 1;
CPP
refused "no words" "a mutant is written" bad <<'CPP'
// mutant bad (step 2): `x = 1;` -> `y`
x = 1;
CPP
refused "no replacement" "reference.cpp:2: a mutant is written" bad <<'CPP'
x = 0;
// mutant bad (step 2, "w"): `x = 1;`
x = 1;
CPP
refused "nothing to replace" "names no text to replace" bad <<'CPP'
// mutant bad (step 2, "w"): `` -> `y`
x = 1;
CPP
refused "one name, two steps" "appears again with another edit, step or words" both <<'CPP'
// mutant both (step 1, "w"): `x = 1;` -> `y`
x = 1;

// mutant both (step 2, "w"): `x = 1;` -> `y`
x = 1;
CPP
refused "one name, two edits" "appears again with another edit" both <<'CPP'
// mutant both (step 1, "w"): `x = 1;` -> `y`
x = 1;

// mutant both (step 1, "w"): `x = 1;` -> `z`
x = 1;
CPP
refused "the old form" "the old form of a mutant" old <<'CPP'
// mutant: old
x = 1;
CPP

echo "--- 5. every mutant of the references is read: one test per name"
for reference in "$root"/solutions/*/*.cpp; do
  [ -f "$reference" ] || continue
  lines=$(grep -c '^ *// mutant ' "$reference")
  [ "$lines" -gt 0 ] || fail "${reference#$root/} has no mutant"
done

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "mutants: all good"
