#!/usr/bin/env bash
# The student's loop, timed as a new user meets it (issue 15): day one (a fresh copy's
# first `./labkit check`, packages installed), the time from saving a finished lab's file
# to `./labkit check NN`'s table and to one step's, for every lab, `./labkit test` (after
# the rest of the build, timed apart), and grading one submission.
#
#   bash bench/student_loop.sh [OUT.md]      (`./labkit bench --loop` runs it)
#
# It works on a copy of the kit in a temporary folder, so the caller's build and files
# stay as they are. Targets: day one 150 s, a finished lab 3 s, one step 1.5 s,
# `./labkit test` 8 minutes, grading one submission 30 s (on a quiet 2-core machine).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="${1:-$ROOT/bench/student_loop.md}"
WORK="$(mktemp -d /tmp/labkit-loop.XXXXXX)"
trap 'rm -rf "$WORK"' EXIT
# Graded code runs under an unprivileged uid when this runs as root: the copy of the kit
# must be readable by others (mktemp makes its folder 0700).
chmod 755 "$WORK"

say() { printf 'student loop: %s\n' "$*" >&2; }

# Wall time of a command in seconds (its output goes to a log).
seconds() {
  local log=$1
  shift
  local start end
  start=$(date +%s.%N)
  status=0
  "$@" >"$log" 2>&1 || status=$?
  end=$(date +%s.%N)
  echo "$status" >"$log.status"
  python3 -c "print(f'{$end - $start:.1f}')"
}

load() { cut -d' ' -f1 /proc/loadavg; }

# The kit's files as they are in the caller's tree (tracked and new, not ignored).
say "copying the kit to $WORK/kit"
mkdir -p "$WORK/kit"
(cd "$ROOT" && git ls-files -z --cached --others --exclude-standard | tar --null -T - -c) | tar -x -C "$WORK/kit"
if [ -d "$ROOT/../shared" ]; then ln -s "$ROOT/../shared" "$WORK/shared"; fi
cd "$WORK/kit"
export LABKIT_BUILD_DIR="$WORK/kit/build"
say "day one: ./labkit check in a fresh copy (load $(load))"
day_one_load=$(load)
day_one=$(seconds "$WORK/day-one.log" ./labkit check)
grep -q "steps pass" "$WORK/day-one.log" || { say "day one's check printed no table:"; tail -n 30 "$WORK/day-one.log" >&2; exit 1; }

say "saving each finished lab to its table"
rows=""
for lab_dir in labs/[0-9][0-9]_*/; do
  stem=$(basename "$lab_dir")
  lab=${stem%%_*}
  [ -d "solutions/$stem" ] || continue
  cp solutions/"$stem"/*.cpp "$lab_dir"
  student=$(ls "$lab_dir"*.cpp | head -n 1)
  ./labkit check "$lab" >/dev/null 2>&1 || true  # warm: the first run links
  touch "$student"
  whole=$(seconds "$WORK/check-$lab.log" ./labkit check "$lab")
  passed=$(grep -o "[0-9]* of [0-9]* steps pass" "$WORK/check-$lab.log" | tail -n 1)
  # One step: the slowest of the lab's steps, each from a save.
  slowest=0 slowest_step=0
  for step in $(sed -n 's/^ *\([0-9][0-9]*\)  L[0-9]*S[0-9]* .*/\1/p' "$WORK/check-$lab.log"); do
    touch "$student"
    t=$(seconds "$WORK/step-$lab-$step.log" ./labkit check "$lab" --step "$step")
    if python3 -c "import sys; sys.exit(not $t > $slowest)"; then slowest=$t slowest_step=$step; fi
  done
  # The compile alone: what the student's own file costs the compiler.
  touch "$student"
  compile=$(seconds "$WORK/compile-$lab.log" cmake --build build --target "answer_${stem}_student")
  rows+="| $lab | $whole s ($passed) | $slowest s (step $slowest_step) | $compile s |"$'\n'
  git -C "$ROOT" show "HEAD:$student" >"$student" 2>/dev/null || cp "$ROOT/$student" "$student"
done

say "the rest of the build (mutants, viewer), then ./labkit test (load $(load))"
rest_build=$(seconds "$WORK/build.log" cmake --build build)
test_load=$(load)
test_time=$(seconds "$WORK/test.log" ./labkit test)
test_summary=$(grep -E "tests passed|tests failed" "$WORK/test.log" | tail -n 1)
failed_tests=$(sed -n '/The following tests FAILED/,$p' "$WORK/test.log" | grep -E "^\s+[0-9]+ - " | sed 's/^ *//' | tr '\n' ';' || true)
if [ -n "$failed_tests" ]; then
  say "./labkit test failed: $failed_tests"
  sed -n '/The following tests FAILED/,$p' "$WORK/test.log" >&2
  test_summary="$test_summary; failed: $failed_tests"
fi
# The release rehearsal, which `./labkit test --all` and CI add to the suite.
say "the release rehearsal alone (load $(load))"
release_time=$(seconds "$WORK/release.log" ctest --test-dir build -L release --output-on-failure)
release_summary=$(grep -E "tests passed|tests failed" "$WORK/release.log" | tail -n 1)

grade_time="not measured (no ./labkit grade in this tree)"
if ./labkit help 2>&1 | grep -q "grade"; then
  say "grading one submission (the reference solutions)"
  mkdir -p "$WORK/submission"
  for lab in labs/*/; do
    name=$(basename "$lab")
    [ -d "solutions/$name" ] && mkdir -p "$WORK/submission/labs/$name" && cp solutions/"$name"/*.cpp "$WORK/submission/labs/$name/"
  done
  ./labkit grade "$WORK/submission" --out "$WORK/grade-warm" >/dev/null 2>&1 || true
  grade_time="$(seconds "$WORK/grade.log" ./labkit grade "$WORK/submission" --out "$WORK/grade") s"
  score=$(sed -n 's/^ *Total  *\([0-9.]* \/ [0-9.]*\).*/\1/p' "$WORK/grade.log" | tail -n 1 || true)
  if [ "$(cat "$WORK/grade.log.status")" != 0 ] || [ -z "$score" ]; then
    say "grading failed:"
    tail -n 20 "$WORK/grade.log" >&2
    grade_time="$grade_time (grading failed: $(tail -n 1 "$WORK/grade.log"))"
  else
    grade_time="$grade_time (the reference scored $score)"
  fi
fi

cat >"$OUT" <<EOF
## The student's loop

Measured by \`bench/student_loop.sh\` on $(date -u +%Y-%m-%d), $(nproc) cores, $(g++ --version | head -n 1).
Load average (1 min) when each part started: day one $day_one_load, the suite $test_load.

| step | wall time | target |
|---|---|---|
| day one: a fresh copy's first \`./labkit check\` (packages installed): configure, build, table | $day_one s | 150 s or less |
| the rest of the build (mutants, viewer), before the suite | $rest_build s | |
| \`./labkit test\` (the suite, reference solutions) | $test_time s ($test_summary) | 480 s or less |
| the release rehearsal alone (\`ctest -L release\`; \`./labkit test --all\` and CI add it) | $release_time s ($release_summary) | |
| grading one submission (after the first build) | $grade_time | 30 s or less |

From saving a finished lab's file (the reference, copied in) to the table: the whole lab
(\`./labkit check NN\`), its slowest step (\`./labkit check NN --step K\`), and of that the
compile and link of the student's file alone. Default case count, every random case run.

| lab | whole lab (target 3 s) | slowest step (target 1.5 s) | compile and link alone |
|---|---|---|---|
$rows
EOF
say "wrote $OUT"
