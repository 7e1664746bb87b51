#!/usr/bin/env bash
# The student's loop, timed as a new user meets it: day one (a fresh copy's first
# `./labkit check`, packages installed), the time from saving a finished lab's file to
# `./labkit check NN`'s table and to one step's, for every lab, the viewer's first build,
# `./labkit test` (after the rest of the build, timed apart), and grading one submission.
# Each is given in wall seconds and in CPU-seconds (user + system, of every process it
# waited for), with the machine's load when it started.
#
#   bash bench/student_loop.sh [OUT.md]      (`./labkit bench --loop` runs it)
#
# It works on a copy of the kit in a temporary folder, so the caller's build and files
# stay as they are. Targets (issue 29, on a quiet 2-core machine): day one 150 s and 300
# CPU-seconds, a finished lab 4 s, one step 2 s, the viewer's first build 2 minutes,
# `./labkit test` 5 minutes.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="${1:-$ROOT/bench/student_loop.md}"
WORK="$(mktemp -d /tmp/labkit-loop.XXXXXX)"
trap 'rm -rf "$WORK"' EXIT
# Graded code runs under an unprivileged uid when this runs as root: the copy of the kit
# must be readable by others (mktemp makes its folder 0700).
chmod 755 "$WORK"

say() { printf 'student loop: %s\n' "$*" >&2; }

# Runs a command (its output goes to LOG, its exit status to LOG.status) and prints its
# wall seconds; its CPU-seconds go to LOG.cpu: those of every process the command waited
# for (getrusage's RUSAGE_CHILDREN, read before and after it).
seconds() {
  local log=$1
  shift
  python3 - "$log" "$@" <<'PY'
import resource, subprocess, sys, time
log, command = sys.argv[1], sys.argv[2:]
before = resource.getrusage(resource.RUSAGE_CHILDREN)
start = time.monotonic()
with open(log, "wb") as out:
    status = subprocess.call(command, stdout=out, stderr=subprocess.STDOUT)
wall = time.monotonic() - start
after = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
open(log + ".status", "w").write(f"{status}\n")
open(log + ".cpu", "w").write(f"{cpu:.1f}\n")
print(f"{wall:.1f}")
PY
}
cpu() { cat "$1.cpu"; }

load() { cut -d' ' -f1 /proc/loadavg; }

# The host's speed at compiling, apart from the kit: the CPU-seconds g++ takes to parse
# <Eigen/Dense> (best of 3). A shared host's speed drifts by a third within an hour;
# figures from two runs compare only after dividing by this.
host_gauge() {
  local best=999 t
  for _ in 1 2 3; do
    t=$(seconds "$WORK/gauge.log" sh -c 'printf "#include <Eigen/Dense>\n" | g++ -std=c++17 -isystem /usr/include/eigen3 -fsyntax-only -x c++ -')
    t=$(cpu "$WORK/gauge.log")
    best=$(python3 -c "print(min($best, $t))")
  done
  echo "$best"
}

# The kit's files as they are in the caller's tree (tracked and new, not ignored).
say "copying the kit to $WORK/kit"
mkdir -p "$WORK/kit"
(cd "$ROOT" && git ls-files -z --cached --others --exclude-standard | tar --null -T - -c) | tar -x -C "$WORK/kit"
if [ -d "$ROOT/../shared" ]; then ln -s "$ROOT/../shared" "$WORK/shared"; fi
cd "$WORK/kit"
export LABKIT_BUILD_DIR="$WORK/kit/build"
say "day one: ./labkit check in a fresh copy (load $(load))"
gauge_before=$(host_gauge)
day_one_load=$(load)
day_one=$(seconds "$WORK/day-one.log" ./labkit check)
day_one_cpu=$(cpu "$WORK/day-one.log")
grep -q "steps pass" "$WORK/day-one.log" || { say "day one's check printed no table:"; tail -n 30 "$WORK/day-one.log" >&2; exit 1; }

# The viewer's first build right after day one, as a new user who opens it first meets
# it: in a second fresh copy, so that the copy above keeps the order of the labs' loop.
say "day one again, in a second copy, then the viewer's first build"
mkdir -p "$WORK/kit2"
(cd "$ROOT" && git ls-files -z --cached --others --exclude-standard | tar --null -T - -c) | tar -x -C "$WORK/kit2"
(cd "$WORK/kit2" && LABKIT_BUILD_DIR="$WORK/kit2/build" ./labkit check >"$WORK/day-one-2.log" 2>&1 || true)
first_viewer_load=$(load)
first_viewer_time=$(seconds "$WORK/first-viewer.log" cmake --build "$WORK/kit2/build" --target labkit-viewer)
first_viewer_cpu=$(cpu "$WORK/first-viewer.log")
[ "$(cat "$WORK/first-viewer.log.status")" = 0 ] || first_viewer_time="$first_viewer_time (failed: $(tail -n 1 "$WORK/first-viewer.log"))"
rm -rf "$WORK/kit2"

say "saving each finished lab to its table"
rows=""
for lab_dir in labs/[0-9][0-9]_*/; do
  stem=$(basename "$lab_dir")
  lab=${stem%%_*}
  [ -d "solutions/$stem" ] || continue
  cp solutions/"$stem"/*.cpp "$lab_dir"
  student=$(ls "$lab_dir"*.cpp | head -n 1)
  # The lab's first check after day one builds its checker (check.cpp, "not begun"):
  # the first lab's also builds what every checker shares (the oracle, the harness).
  first=$(seconds "$WORK/first-$lab.log" ./labkit check "$lab")
  first_cpu=$(cpu "$WORK/first-$lab.log")
  touch "$student"
  whole=$(seconds "$WORK/check-$lab.log" ./labkit check "$lab")
  whole_cpu=$(cpu "$WORK/check-$lab.log")
  passed=$(grep -o "[0-9]* of [0-9]* steps pass" "$WORK/check-$lab.log" | tail -n 1)
  # One step: the slowest of the lab's steps, each from a save.
  slowest=0 slowest_step=0 slowest_cpu=0
  # A row starts with the step's number, then its tag ("  9  L06S9", "  10 L06S10").
  for step in $(sed -n 's/^ *\([0-9][0-9]*\)  *L[0-9]*S[0-9]* .*/\1/p' "$WORK/check-$lab.log"); do
    touch "$student"
    t=$(seconds "$WORK/step-$lab-$step.log" ./labkit check "$lab" --step "$step")
    if python3 -c "import sys; sys.exit(not $t > $slowest)"; then
      slowest=$t slowest_step=$step slowest_cpu=$(cpu "$WORK/step-$lab-$step.log")
    fi
  done
  # The compile alone: what the student's own file costs the compiler.
  touch "$student"
  compile=$(seconds "$WORK/compile-$lab.log" cmake --build build --target "answer_${stem}_student")
  rows+="| $lab | $first s, $first_cpu CPU-s | $whole s, $whole_cpu CPU-s ($passed) | $slowest s, $slowest_cpu CPU-s (step $slowest_step) | $compile s, $(cpu "$WORK/compile-$lab.log") CPU-s |"$'\n'
  git -C "$ROOT" show "HEAD:$student" >"$student" 2>/dev/null || cp "$ROOT/$student" "$student"
done

# The viewer's first build, as `./labkit view` starts it on a student's build.
viewer_load=$(load)
say "the viewer's first build (load $viewer_load)"
viewer_time=$(seconds "$WORK/viewer.log" cmake --build build --target labkit-viewer)
viewer_cpu=$(cpu "$WORK/viewer.log")
[ "$(cat "$WORK/viewer.log.status")" = 0 ] || viewer_time="$viewer_time (failed: $(tail -n 1 "$WORK/viewer.log"))"

say "the rest of the build (mutants, the reference viewer), then ./labkit test (load $(load))"
rest_build=$(seconds "$WORK/build.log" cmake --build build)
rest_build_cpu=$(cpu "$WORK/build.log")
test_load=$(load)
test_time=$(seconds "$WORK/test.log" ./labkit test)
test_cpu=$(cpu "$WORK/test.log")
test_summary=$(grep -E "tests passed|tests failed" "$WORK/test.log" | tail -n 1)
failed_tests=$(sed -n '/The following tests FAILED/,$p' "$WORK/test.log" | grep -E "^\s+[0-9]+ - " | sed 's/^ *//' | tr '\n' ';' || true)
if [ -n "$failed_tests" ]; then
  say "./labkit test failed: $failed_tests"
  sed -n '/The following tests FAILED/,$p' "$WORK/test.log" >&2
  test_summary="$test_summary; failed: $failed_tests"
fi
# The grader's end-to-end suites (label "whole"), which `./labkit test --all` and CI add.
say "the hostile submissions and the release rehearsal (load $(load))"
release_time=$(seconds "$WORK/release.log" ctest --test-dir build -L whole -j 2 --output-on-failure)
release_cpu=$(cpu "$WORK/release.log")
release_summary=$(grep -E "tests passed|tests failed" "$WORK/release.log" | tail -n 1)
if [ "$(cat "$WORK/release.log.status")" != 0 ]; then
  say "the end-to-end suites failed:"
  grep -E "FAIL|exits|error" "$WORK/release.log" | head -n 40 >&2 || tail -n 40 "$WORK/release.log" >&2
  cp "$WORK/release.log" "${OUT%.md}.release.log" && say "its whole log: ${OUT%.md}.release.log"
fi

# The help is read whole first: `grep -q` would close the pipe early, and under pipefail
# the help's SIGPIPE read as "no grade command here".
grade_time="not measured (no ./labkit grade in this tree)"
help_text=$(./labkit help 2>&1 || true)
if grep -q "grade SUBMISSION" <<<"$help_text"; then
  say "grading one submission (the reference solutions)"
  mkdir -p "$WORK/submission"
  for lab in labs/*/; do
    name=$(basename "$lab")
    [ -d "solutions/$name" ] && mkdir -p "$WORK/submission/labs/$name" && cp solutions/"$name"/*.cpp "$WORK/submission/labs/$name/"
  done
  ./labkit grade "$WORK/submission" --out "$WORK/grade-warm" >/dev/null 2>&1 || true
  grade_time="$(seconds "$WORK/grade.log" ./labkit grade "$WORK/submission" --out "$WORK/grade") s, $(cpu "$WORK/grade.log") CPU-s"
  score=$(sed -n 's/^ *Total  *\([0-9.]* \/ [0-9.]*\).*/\1/p' "$WORK/grade.log" | tail -n 1 || true)
  if [ "$(cat "$WORK/grade.log.status")" != 0 ] || [ -z "$score" ]; then
    say "grading failed:"
    tail -n 20 "$WORK/grade.log" >&2
    grade_time="$grade_time (grading failed: $(tail -n 1 "$WORK/grade.log"))"
  else
    grade_time="$grade_time (the reference scored $score)"
  fi
fi

gauge_after=$(host_gauge)
cat >"$OUT" <<EOF
## The student's loop

Measured by \`bench/student_loop.sh\` on $(date -u +%Y-%m-%d), $(nproc) cores, $(g++ --version | head -n 1).
The host's speed: g++ parsed \`<Eigen/Dense>\` in $gauge_before CPU-s before the run and $gauge_after after it (best of 3; see host_gauge).
Load average (1 min) when each part started: day one $day_one_load, the viewer right after day one $first_viewer_load, the viewer after the labs' first checks $viewer_load, the suite $test_load.
CPU-seconds are the user and system time of every process a step waited for.

| step | wall time | CPU-seconds | target |
|---|---|---|---|
| day one: a fresh copy's first \`./labkit check\` (packages installed): configure, build, table | $day_one s | $day_one_cpu | 150 s and 300 CPU-s |
| the viewer's first build right after day one (in a second fresh copy: it also builds the seven labs' judges) | $first_viewer_time s | $first_viewer_cpu | 120 s |
| the viewer's first build after each lab's first check below | $viewer_time s | $viewer_cpu | 120 s |
| the rest of the build (mutants, the reference viewer), before the suite | $rest_build s | $rest_build_cpu | |
| \`./labkit test\` (the suite, reference solutions) | $test_time s ($test_summary) | $test_cpu | 300 s |
| the grader's end to end: hostile submissions and release rehearsal (\`ctest -L whole\`; \`./labkit test --all\` and CI add them) | $release_time s ($release_summary) | $release_cpu | |
| grading one submission (after the first build) | $grade_time | | |

From saving a finished lab's file (the reference, copied in) to the table: the lab's
first check (which builds its checker, once: day one builds none of a lab not begun; the
first lab's also builds what all checkers share), then the whole lab (\`./labkit check NN\`),
its slowest step (\`./labkit check NN --step K\`), and of that the compile and link of the
student's file alone. Default case count, every random case run.

| lab | first check (builds its checker) | whole lab (target 4 s) | slowest step (target 2 s) | compile and link alone |
|---|---|---|---|---|
$rows
EOF
say "wrote $OUT"
