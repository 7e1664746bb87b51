#!/usr/bin/env bash
# The student's loop, timed: a clean configure and build of everything, the time from
# saving one student file to `./labkit check NN` printing its table (with the stub as
# shipped, and with a finished lab), `./labkit test`, and grading one submission.
#
#   bash bench/student_loop.sh [OUT.md]      (`./labkit bench --loop` runs it)
#
# It works on a copy of the kit in a temporary folder, so the caller's build and files
# stay as they are. Targets (issue 7): 3 s or less from saving a file to the table, a
# clean build under 3 minutes on 2 cores.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="${1:-$ROOT/bench/student_loop.md}"
LAB="${LABKIT_LOOP_LAB:-02}"
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

# The kit's files as they are in the caller's tree (tracked and new, not ignored).
say "copying the kit to $WORK/kit"
mkdir -p "$WORK/kit"
(cd "$ROOT" && git ls-files -z --cached --others --exclude-standard | tar --null -T - -c) | tar -x -C "$WORK/kit"
if [ -d "$ROOT/../shared" ]; then ln -s "$ROOT/../shared" "$WORK/shared"; fi
cd "$WORK/kit"
export LABKIT_BUILD_DIR="$WORK/kit/build"
student=$(ls labs/"$LAB"_*/*.cpp | head -n 1)
reference=solutions/$(basename "$(dirname "$student")")/$(basename "$student")

say "clean configure and build of everything"
clean_build=$(seconds "$WORK/build.log" bash -c \
  'cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo && cmake --build build')
grep -q "FAILED" "$WORK/build.log" && { say "the clean build failed:"; tail -n 30 "$WORK/build.log" >&2; exit 1; }

say "from saving $student to the check table"
./labkit check "$LAB" >/dev/null 2>&1 || true  # warm: the first run may still link
touch "$student"
save_stub=$(seconds "$WORK/check-stub.log" ./labkit check "$LAB")
cp "$reference" "$student"
./labkit check "$LAB" >/dev/null 2>&1 || true
touch "$student"
save_done=$(seconds "$WORK/check-done.log" ./labkit check "$LAB")
git -C "$ROOT" show "HEAD:$student" >"$student" 2>/dev/null || cp "$ROOT/$student" "$student"

say "./labkit test"
test_time=$(seconds "$WORK/test.log" ./labkit test)
test_summary=$(grep -E "tests passed|tests failed" "$WORK/test.log" | tail -n 1)
failed_tests=$(sed -n '/The following tests FAILED/,$p' "$WORK/test.log" | grep -E "^\s+[0-9]+ - " | sed 's/^ *//' | tr '\n' ';' || true)
if [ -n "$failed_tests" ]; then
  say "./labkit test failed: $failed_tests"
  sed -n '/The following tests FAILED/,$p' "$WORK/test.log" >&2
  test_summary="$test_summary; failed: $failed_tests"
fi

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

| step | wall time | target |
|---|---|---|
| clean configure and build of everything | $clean_build s | under 180 s |
| saving \`$student\` (the stub) to \`./labkit check $LAB\`'s table | $save_stub s | 3 s or less |
| saving \`$student\` (a finished lab, every random case run) to the table | $save_done s | 3 s or less |
| \`./labkit test\` (the whole suite, reference solutions) | $test_time s ($test_summary) | |
| grading one submission (after the first build) | $grade_time | 30 s or less |
EOF
say "wrote $OUT"
