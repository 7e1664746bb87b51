#!/usr/bin/env bash
# ./labkit check as students meet it, run against the kit's own build.
#   runner.test.sh RUNNER ROOT
set -uo pipefail
runner="$1"
root="$2"
cases=200
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Bad input (PROGRAM ARGS, ARGS split on spaces): one clear line, exit 2, never a crash.
rejects() {
  local program="$1" args="$2" out code
  out=$("$program" $args 2>&1); code=$?
  echo "\$ labkit $args -> exit $code: $out"
  [ $code -eq 2 ] || fail "'$args' exits $code, not 2"
  [ "$(wc -l <<<"$out")" -le 2 ] || fail "'$args' says more than one line"
}

# "N of M steps pass": M counts every step of every lab the kit has.
total_steps() { sed -n 's/^.*[0-9]* of \([0-9]*\) steps pass.*$/\1/p' <<<"$1" | tail -n 1; }

echo "--- 1. the stubs: every step 'not implemented yet', nothing crashes, exit 1"
out=$("$runner" check --cases $cases 2>&1); code=$?
echo "$out"
steps=$(total_steps "$out")
[ -n "$steps" ] && [ "$steps" -gt 0 ] || fail "no summary line"
[ $code -eq 1 ] || fail "check on the stubs exits $code, not 1"
grep -qE "crashed|timed out|does not compile|too much output|kit error" <<<"$out" && fail "a stub step did not say 'not implemented yet'"
n=$(grep -c "not implemented yet" <<<"$out")
[ "$n" -eq "$steps" ] || fail "$n steps say 'not implemented yet'; the manifest has $steps"

echo "--- 1b. labs not begun: shown without building their checkers; a lab that answers is judged"
# LABKIT_PROBE_ONLY=1: as on day one, when no checker is built yet (check.cpp, not_begun).
out=$(LABKIT_PROBE_ONLY=1 "$runner" check 2>&1); code=$?
echo "$out"
[ $code -eq 1 ] || fail "check on the stubs, no checker built, exits $code, not 1"
[ "$(total_steps "$out")" = "$steps" ] || fail "check on the stubs, no checker built, does not count every step"
n=$(grep -c "not implemented yet   *$" <<<"$out")
[ "$n" -eq "$steps" ] || fail "$n steps say 'not implemented yet' with no checker built; the manifest has $steps"
ids=$(grep -o '^Lab [0-9]*' <<<"$out" | cut -d' ' -f2 | paste -sd, | sed 's/,/, /g')
grep -q "^Not begun: lab $ids (" <<<"$out" || fail "the stubs' labs ($ids) are not all said to be not begun"
out=$(LABKIT_PROBE_ONLY=1 "$runner" check 02 --step 3 --cases $cases --implementation mutant_beta_sign 2>&1); code=$?
echo "$out"
[ $code -eq 1 ] && grep -q " failing " <<<"$out" || fail "a begun lab with no checker built is not judged (the mutant is not failing)"
grep -q "Not begun" <<<"$out" && fail "a lab whose functions answer is said to be not begun"

echo "--- 2. the reference: every step passes, exit 0"
out=$("$runner" check --cases $cases --implementation reference 2>&1); code=$?
echo "$out"
[ $code -eq 0 ] || fail "check on the reference exits $code"
n=$(grep -c " passed " <<<"$out")
[ "$n" -eq "$steps" ] || fail "$n steps pass on the reference; the manifest has $steps"

echo "--- 3. a classic mistake: the report names the case, and its replay fails again"
out=$("$runner" check 02 --step 3 --cases 500 --implementation mutant_beta_sign 2>&1); code=$?
echo "$out"
[ $code -eq 1 ] || fail "the beta-sign mutant passes step 3"
for field in "query " "input " "expected " "got " "why " "replay " "see it "; do
  grep -q "  $field" <<<"$out" || fail "the failure report has no '$field' line"
done
token=$(grep -o -- "--case '[^']*'" <<<"$out" | head -n 1 | sed "s/^--case '//; s/'\$//")
if [ -z "$token" ]; then
  fail "no replay command in the failure report"
else
  out=$("$runner" check 02 --case "$token" --implementation mutant_beta_sign 2>&1); code=$?
  echo "$out"
  [ $code -eq 1 ] && grep -q "fails" <<<"$out" || fail "replaying the case on the mutant does not fail again"
  out=$("$runner" check 02 --case "$token" --implementation reference 2>&1); code=$?
  echo "$out"
  [ $code -eq 0 ] && grep -q "passes" <<<"$out" || fail "replaying the case on the reference does not pass"
fi

echo "--- 3b. a worked example's replay runs that example (its query has no random cases)"
out=$("$runner" check 04 --step 1 --implementation mutant_axes_not_turned 2>&1); code=$?
echo "$out"
[ $code -eq 1 ] || fail "the axes-not-turned mutant passes lab 04's step 1"
token=$(grep -o -- "--case '[^']*'" <<<"$out" | head -n 1 | sed "s/^--case '//; s/'\$//")
grep -q "example" <<<"$out" || fail "the axes-not-turned mutant's first failure is no longer an example: pick another"
if [ -z "$token" ]; then
  fail "no replay command in the example's failure report"
else
  out=$("$runner" check 04 --case "$token" --implementation mutant_axes_not_turned 2>&1); code=$?
  echo "$out"
  [ $code -eq 1 ] && grep -q "replayed .*fails" <<<"$out" && grep -q "example" <<<"$out" ||
    fail "replaying an example's case on the mutant does not fail again (exit $code)"
  out=$("$runner" check 04 --case "$token" --implementation reference 2>&1); code=$?
  echo "$out"
  [ $code -eq 0 ] && grep -q "passes" <<<"$out" || fail "replaying an example's case on the reference does not pass (exit $code)"
fi

echo "--- 4. bad input: one clear line, exit 2, never a crash"
for args in "check 99" "check 02 --case nonsense" "check 02 --case no_such_query:1,2,3" "check 02 --case segment_plane:1,2,3" "check 02 --step 42"; do
  rejects "$runner" "$args"
done

echo "--- 5. hints: every 'Stuck? ./labkit hint NN K' of a handout opens that step's hints"
pointers=$(grep -oh "\./labkit hint [0-9][0-9]* [0-9][0-9]*" "$root"/handouts/*.md | sort -u)
while read -r _ _ lab step; do
  [ -n "$lab" ] || continue
  out=$("$root/labkit" hint "$lab" "$step" 2>&1); code=$?
  [ $code -eq 0 ] && grep -q "^## Step $step" <<<"$out" || fail "'./labkit hint $lab $step' (a handout's pointer) exits $code: $out"
done <<<"$pointers"
for args in "hint" "hint 99" "hint 02 99" "hint x" "hint 02 1 2"; do
  rejects "$root/labkit" "$args"
done

echo "--- 6. handouts: one session each, every step where the runner points, every link resolves"
manifest="$root/grading/manifest.json"
for handout in "$root"/handouts/[0-9][0-9]_*.md; do
  name=${handout#$root/}
  lines=$(wc -l <"$handout")
  [ "$lines" -le 450 ] || fail "$name has $lines lines; a handout is one lab session, at most 450"
done
if [ -f "$manifest" ]; then
  # "Next: ... handouts/NN_name.md, \"Step K\"": each manifest step has its heading, with its
  # tag, in the lab's handout or, for a step the manifest puts there, its extensions handout.
  while read -r file step tag; do
    grep -q "^## Step $step: .*($tag)" "$root/handouts/$file" ||
      fail "handouts/$file has no heading '## Step $step: ... ($tag)' (the manifest's step, where the runner points)"
  done < <(sed -n 's/^ *"id": *"\([0-9]*\)".*/ID \1/p; s/^ *"name": *"\([^"]*\)".*/NAME \1/p
                  s/.*"step": *\([0-9]*\), *"tag": *"\([^"]*\)".*"handout": *"extensions".*/STEP \1 \2 .extensions/p; t
                  s/.*"step": *\([0-9]*\), *"tag": *"\([^"]*\)".*/STEP \1 \2/p' "$manifest" |
           awk '$1 == "ID" { id = $2 } $1 == "NAME" { stem = id "_" $2 } $1 == "STEP" { print stem $4 ".md", $2, $3 }')
fi
for page in "$root"/handouts/*.md "$root"/handouts/hints/*.md; do
  folder=$(dirname "$page")
  while read -r link; do
    [ -e "$folder/$link" ] || fail "${page#$root/} links $link, which does not exist"
  done < <(grep -o '](\([^)#]*\)' "$page" | sed 's/^](//' | grep -v -e '^http' -e '^$' | sort -u)
done

echo "--- 7. numbers a handout quotes from the code: the header, the handout and the code agree"
# The value a judge or the reference uses, then each text that must quote it.
pin() {  # pin NAME VALUE FILE PATTERN...: each FILE holds PATTERN with VALUE in place of @
  local name=$1 value=$2; shift 2
  [ -n "$value" ] || { fail "$name: its value is not found in the code"; return; }
  while [ $# -gt 0 ]; do
    grep -qF -- "${2//@/$value}" "$root/$1" || fail "$1 does not say '${2//@/$value}' ($name is $value in the code)"
    shift 2
  done
}
constant() { sed -n "s/.*constexpr double $2 = \([0-9]*\)\.0;.*/\1/p" "$root/$1" | head -1; }
pin "lab 05's ambiguity band for tests" "$(constant tests/05_sphere_sweeps/judge.cpp kTestDoubt)" \
  labs/05_sphere_sweeps/sphere_sweeps.h "within @ tol of r0 + r1" handouts/05_sphere_sweeps.md "\`@ tol\` (tests)"
pin "lab 05's ambiguity band for sweeps" "$(constant tests/05_sphere_sweeps/judge.sweeps.cpp kSweepDoubt)" \
  labs/05_sphere_sweeps/sphere_sweeps.h "within @ tol of zero" handouts/05_sphere_sweeps.md "\`@ tol\` (sweeps)"
pin "lab 06's traversal cost" "$(constant solutions/06_spatial_trees/spatial_trees.cpp kTraversalCost)" \
  handouts/06_spatial_trees.md "\`C_trav = @\`" handouts/hints/06_spatial_trees.md "\`C_trav = @\`" \
  solutions/06_spatial_trees/spatial_trees.cpp "hence @,"

echo "--- 8. the plan: every lab of the manifest, its core path summed, an assignment's steps only"
out=$("$runner" plan 2>&1); code=$?
echo "$out"
labs=$(grep -c '^ *"id": *"[0-9]*"' "$manifest")
[ $code -eq 0 ] || fail "plan exits $code"
[ "$(grep -c "^    core path: " <<<"$out")" -eq "$labs" ] || fail "plan does not give each of the manifest's $labs labs a core path"
while read -r _ _ list; do  # "1 (20), 2 (45): 65 min": the minutes add up
  sum=0
  for m in $(grep -o '([0-9]*)' <<<"${list%%:*}" | tr -d '()'); do sum=$((sum + m)); done
  [ "${list##*: }" = "$sum min" ] || fail "plan's core path '$list' does not add up to $sum min"
done < <(grep "^    core path: " <<<"$out")
out=$("$runner" plan --assignment 03:core 2>&1); code=$?
echo "$out"
[ $code -eq 0 ] && grep -q '^Assignment "Lab 03, core steps": ' <<<"$out" || fail "plan --assignment 03:core does not name the assignment"
grep -q "  extension  " <<<"$out" && fail "plan --assignment 03:core lists an extension step"
for args in "plan 99" "plan --assignment 03:nonsense"; do
  rejects "$runner" "$args"
done

[ $failures -eq 0 ] && echo "all runner checks passed"
exit $((failures > 0))
