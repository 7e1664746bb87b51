#!/usr/bin/env bash
# A class graded as an instructor grades one (issue 16): N students (default 20), each
# lab of each student drawn from what a class hands in: the reference (half the time), one
# of the lab's classic mistakes (build/mutants/, as the build wrote them), the
# untouched stub, a file that does not compile, one that crashes after a few calls, or no
# file at all; each file but the stubs is made the student's own, as in a real class, so
# that only untouched stubs share a compile. The draw is fixed (--seed), so runs compare.
# It prints the wall time of `./labkit grade CLASS --jobs J` and keeps the results
# (class.html) in OUT.
#
#   bash bench/class_run.sh [--students 20] [--jobs 2] [--seed 16] [--out DIR]
#   (`./labkit bench --class` runs it)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LABKIT_BUILD_DIR:-$ROOT/build}"
say() { printf 'class run: %s\n' "$*" >&2; }

students=20 jobs=2 seed=16 out="$BUILD/class-run"
while [ $# -gt 0 ]; do
  case "$1" in
    --students) students="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    *) say "unknown option '$1'"; exit 2 ;;
  esac
done

say "building what grading needs"
"$ROOT/labkit" prepare-grading >/dev/null
# The classic mistakes' files: configuring the kit writes them (cmake/LabKit.cmake).
ls "$BUILD"/mutants/*/*.cpp >/dev/null 2>&1 || { say "no classic mistakes in $BUILD/mutants (a kit with solutions/ writes them)"; exit 1; }

WORK="$(mktemp -d /tmp/labkit-class.XXXXXX)"
trap 'rm -rf "$WORK"' EXIT
chmod 755 "$WORK"
class="$WORK/class"
RANDOM=$seed
declare -A drawn=()
for ((s = 1; s <= students; s++)); do
  name=$(printf 'student%02d' "$s")
  for lab in "$ROOT"/labs/[0-9][0-9]_*/; do
    lab=$(basename "$lab")
    [ -d "$ROOT/solutions/$lab" ] || continue
    file=$(basename "$(ls "$ROOT/solutions/$lab"/*.cpp | head -n 1)")
    into="$class/$name/labs/$lab"
    mkdir -p "$into"
    roll=$((RANDOM % 100))
    mutants=("$BUILD/mutants/$lab"/*.cpp)
    if ((roll < 50)); then kind=reference; cp "$ROOT/solutions/$lab/$file" "$into/"
    elif ((roll < 78)); then kind=mistake; cp "${mutants[RANDOM % ${#mutants[@]}]}" "$into/$file"
    elif ((roll < 88)); then kind=stub; cp "$ROOT/labs/$lab/$file" "$into/"
    elif ((roll < 93)); then kind=no_compile; { cat "$ROOT/solutions/$lab/$file"; echo 'this line is not C++'; } >"$into/$file"
    elif ((roll < 97)); then
      kind=crash
      # The reference, with a null write after 40 calls of its first function.
      awk '{ print } !done && /^[A-Za-z].*\) \{$/ { print "  static int calls = 0; if (++calls > 40) *static_cast<volatile int*>(nullptr) = 1;"; done = 1 }' \
        "$ROOT/solutions/$lab/$file" >"$into/$file"
    else kind=missing; rm -rf "$into"
    fi
    # Every student's file is their own (a real class hands in no two alike), so that
    # only the untouched stubs share a compile; the figure is then a real class's.
    [ "$kind" = stub ] || [ "$kind" = missing ] || echo "// $name" >>"$into/$file"
    drawn[$kind]=$((${drawn[$kind]:-0} + 1))
  done
done
mix=""
for kind in reference mistake stub no_compile crash missing; do mix+="${mix:+, }${drawn[$kind]:-0} $kind"; done
say "$students students; their labs: $mix"

rm -rf "$out"
load=$(cut -d' ' -f1 /proc/loadavg)
start=$(date +%s.%N)
"$ROOT/labkit" grade "$class" --out "$out" --jobs "$jobs" >"$WORK/grade.log" 2>&1 || { tail -n 30 "$WORK/grade.log" >&2; exit 1; }
end=$(date +%s.%N)
wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.0f", b - a }')
echo "| students | jobs | wall time | per submission | load at the start | labs handed in |"
echo "|---|---|---|---|---|---|"
echo "| $students | $jobs | $wall s | $(awk -v w="$wall" -v n="$students" 'BEGIN { printf "%.1f", w / n }') s | $load | $mix |"
say "the class page: $out/class.html"
