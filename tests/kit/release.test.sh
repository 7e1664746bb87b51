#!/usr/bin/env bash
# The student release and the Gradescope autograder, from a student's and from
# Gradescope's side:
#   1. ./labkit release: no solutions, no mutants, no grading secrets, and no reference
#      function body anywhere in it;
#   2. ./labkit package gradescope: the release plus setup.sh, run_autograder and the
#      secret seed, at the zip's root;
#   3. the zip unpacked under a folder laid out as Gradescope's /autograder, setup.sh
#      run there (it builds the kit from scratch: the slow part), the release's own
#      `./labkit check` run (every step "not implemented yet"), then run_autograder on
#      the reference and on an empty submission;
#   6. one assignment (lab 03's core steps): its package freezes it, run_autograder grades
#      a lab-03-only submission on those steps alone, and the GitHub Classroom workflow's
#      commands give each step's points on the stub (none) and the reference (all).
#
#   release.test.sh KIT_ROOT NO_SOLUTION_CHECKER SCHEMA_CHECKER
set -uo pipefail
kit="$1"
no_solution="$2"
schema_check="$3"
unset LABKIT_BUILD_DIR LABKIT_GRADING_SEED  # the release builds in its own folder
work="$(mktemp -d /tmp/labkit-release.XXXXXX)"
chmod 755 "$work"
trap 'rm -rf "$work"' EXIT
secret="release test secret $$ $(date +%s%N)"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

echo "--- 1. the student release"
"$kit/labkit" release "$work/release" || fail "./labkit release exits $?"
for absent in solutions .ci tests/grading grading/release.sh grading/gradescope; do
  [ -e "$work/release/$absent" ] && fail "the release holds $absent"
done
mutant=$(grep -rlE --include='*.cpp' --include='*.h' '^ *// mutant [a-z]' "$work/release" | head -1)
[ -n "$mutant" ] && fail "the release holds a mutant: $mutant"
for present in README.md labkit CMakeLists.txt grading/manifest.json common/harness/check.h runner/main.cpp; do
  [ -e "$work/release/$present" ] || fail "the release has no $present"
done
grep -q "How you are graded" "$work/release/README.md" || fail "the release's README is not the student README"
"$no_solution" "$kit" "$work/release" || fail "reference code in the release"
# The checker can see reference code: it finds it where it is.
"$no_solution" "$kit" "$kit/solutions" >/dev/null && fail "kit_no_solution finds nothing in solutions/ itself"
"$kit/labkit" release "$work/release" 2>/dev/null && fail "./labkit release writes over a folder that is not empty"

echo "--- 2. the Gradescope zip"
"$kit/labkit" package gradescope --out "$work/autograder.zip" --seed "$secret" || fail "./labkit package gradescope exits $?"
listing="$(unzip -Z1 "$work/autograder.zip")"
for file in setup.sh run_autograder secret_seed labkit grading/manifest.json; do
  grep -qx "$file" <<<"$listing" || fail "the zip has no $file at its root"
done
grep -q "^solutions/" <<<"$listing" && fail "the zip holds solutions/"
root="$work/autograder"
mkdir -p "$root/source" "$root/submission" "$root/results"
unzip -q "$work/autograder.zip" -d "$root/source"
cp "$root/source/run_autograder" "$root/run_autograder"
diff -r -x setup.sh -x run_autograder -x secret_seed "$work/release" "$root/source" >/dev/null ||
  fail "the zip's kit is not the student release"
"$no_solution" "$kit" "$root/source" || fail "reference code in the zip"

echo "--- 3. Gradescope's image: setup.sh builds the kit (minutes)"
started=$(date +%s)
LABKIT_AUTOGRADER_ROOT="$root" bash "$root/source/setup.sh" || fail "setup.sh exits $?"
echo "setup.sh took $(($(date +%s) - started)) s"

echo "--- 4. the release's own ./labkit check, as a new student runs it"
out=$(cd "$root/source" && ./labkit check --cases 50 2>&1); code=$?
echo "$out" | tail -n 4
[ $code -eq 1 ] || fail "the release's ./labkit check exits $code (expected 1: nothing implemented yet)"
steps=$(sed -n 's/^.*[0-9]* of \([0-9]*\) steps pass.*$/\1/p' <<<"$out" | tail -n 1)
[ -n "$steps" ] && [ "$(grep -c "not implemented yet" <<<"$out")" = "$steps" ] ||
  fail "not every step of the release says 'not implemented yet'"
# What cannot work without the references is not offered there, and says why if asked for.
help=$(cd "$root/source" && ./labkit help 2>&1)
grep -qE "^  (figures|bench|package|release) " <<<"$help" && fail "the release's ./labkit help offers a command it cannot run"
out=$(cd "$root/source" && ./labkit check 02 --implementation reference 2>&1) &&
  fail "the release's ./labkit check --implementation reference runs"
grep -q "student release" <<<"$out" || fail "the release's --implementation reference does not say why it is refused: $out"
out=$(cd "$root/source" && ./labkit figures 2>&1) && fail "the release's ./labkit figures runs"
grep -q "student release" <<<"$out" || fail "the release's ./labkit figures does not say why it is refused: $out"

echo "--- 5. run_autograder: the reference (files uploaded one by one), then nothing"
for lab in "$kit"/solutions/*/; do cp "$lab"*.cpp "$root/submission/"; done
(cd "$root" && LABKIT_AUTOGRADER_ROOT="$root" ./run_autograder --cases 200 >"$work/autograder.log" 2>&1) ||
  { cat "$work/autograder.log"; fail "run_autograder exits $?"; }
"$schema_check" "$kit/grading/gradescope-results.schema.json" "$root/results/results.json" || fail "results.json does not match the schema"
score=$(grep -m1 '^  "score"' "$root/results/results.json" | tr -dc '0-9.')
max=$(grep -o '"max_score": [0-9.]*' "$root/results/results.json" | awk '{ s += $2 } END { print s }')
echo "reference: $score of $max"
[ -n "$score" ] && awk -v s="$score" -v m="$max" 'BEGIN { exit !(s == m && m > 0) }' || fail "the reference scores $score of $max"
grep -rqF "$secret" "$root/results" "$work/autograder.log" && fail "the secret seed appears in the results"
grep -q '"seed": "secret"' "$root/results/results.json" || fail "run_autograder did not grade on the secret seed"
rm -rf "$root/submission"/* "$root/results"/*
(cd "$root" && LABKIT_AUTOGRADER_ROOT="$root" ./run_autograder --cases 200 >"$work/autograder.log" 2>&1) ||
  fail "run_autograder on an empty submission exits $?"
grep -q '^  "score": 0' "$root/results/results.json" || fail "an empty submission does not score 0"

echo "--- 6. one assignment: lab 03's core steps, on Gradescope and GitHub Classroom"
"$kit/labkit" package gradescope --assignment 03:core --out "$work/lab03.zip" --seed "$secret" >/dev/null 2>&1 ||
  fail "./labkit package gradescope --assignment 03:core exits $?"
core=$(python3 -c 'import json, sys
lab = [l for l in json.load(open(sys.argv[1]))["labs"] if l["id"] == "03"][0]
print(" ".join(str(s["step"]) for s in lab["steps"] if s["tier"] == "core"))' "$kit/grading/manifest.json")
diff <(unzip -Z1 "$work/lab03.zip" | grep -vx assignment.json | sort) <(sort <<<"$listing") >/dev/null ||
  fail "the lab 03 zip holds more than the full kit's zip and assignment.json"
unzip -p "$work/lab03.zip" assignment.json >"$root/source/assignment.json" || fail "the lab 03 zip has no assignment.json"
rm -rf "$root/submission"/* "$root/results"/*
cp "$kit"/solutions/03_*/*.cpp "$root/submission/"
(cd "$root" && LABKIT_AUTOGRADER_ROOT="$root" ./run_autograder --cases 200 >"$work/autograder.log" 2>&1) ||
  { cat "$work/autograder.log"; fail "run_autograder on lab 03's core exits $?"; }
rm "$root/source/assignment.json"
python3 - "$root/results/results.json" "$core" <<'PY' || fail "lab 03's core results.json: see above"
import json, sys
r, core = json.load(open(sys.argv[1])), sys.argv[2].split()
steps = [t for t in r["tests"] if "score" in t]
problems = []
if [t["number"] for t in steps] != [f"3.{k}" for k in core]: problems.append(f"steps {[t['number'] for t in steps]}, expected 3.{core}")
total = sum(t["max_score"] for t in steps)
if r["score"] != total or total == 0: problems.append(f"a lab-03-only reference scores {r['score']} of {total}")
if not r["output"].startswith("Assignment: Lab 03, core steps"): problems.append("its output does not name the assignment")
print("\n".join(problems) or f"lab 03 core on Gradescope: {r['score']:g} of {total:g}, steps {core}")
sys.exit(1 if problems else 0)
PY
"$schema_check" "$kit/grading/gradescope-results.schema.json" "$root/results/results.json" || fail "lab 03's results.json does not match the schema"
"$kit/labkit" release "$work/classroom" --classroom 03:core >/dev/null 2>&1 || fail "./labkit release --classroom 03:core exits $?"
workflow="$work/classroom/.github/workflows/classroom.yml"
[ -f "$workflow" ] || fail "the Classroom release has no $workflow"
diff -r -x .github "$work/release" "$work/classroom" >/dev/null || fail "the Classroom release differs from the release beyond .github/"
# The workflow's commands, in the built release (as the runner's checkout would run them).
mapfile -t graders < <(sed -n 's/^ *command: //p' "$workflow")
[ "${#graders[@]}" = "$(wc -w <<<"$core")" ] || fail "the workflow has ${#graders[@]} graders for core steps $core"
lab03="$root/source/labs/03_separating_axes/separating_axes.cpp"
(cd "$root/source" && ./labkit check 03 >check-03.txt; [ -s check-03.txt ] && grep -q "core path" check-03.txt) ||
  fail "the workflow's table step shows no table with the core path"
for command in "${graders[@]}"; do
  (cd "$root/source" && bash -c "$command" >/dev/null 2>&1) && fail "the stub earns the points of '$command'"
done
cp "$kit"/solutions/03_*/*.cpp "$lab03"
for command in "${graders[@]}"; do
  (cd "$root/source" && bash -c "$command" >/dev/null 2>&1) || fail "the reference does not earn the points of '$command'"
done
cp "$work/release/labs/03_separating_axes/separating_axes.cpp" "$lab03"
rm -f "$root/source/check-03.txt"

[ $failures -eq 0 ] && echo "release and Gradescope package: all checks passed"
exit $((failures > 0))
