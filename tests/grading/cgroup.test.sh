#!/usr/bin/env bash
# A graded step's limits hold for the graded code's processes together (runner/cgroup.h),
# not for each process alone: four children that each take half the step's memory, two
# hundred forks, eight busy children each in a session (an autogroup) of its own, sixty
# files in bubblewrap's /tmp; and the step's control group is gone when the step ends.
#
# No lab is built. A stand-in kit's "compiler" copies the student's file; its "linker"
# makes the answerer a script that runs cgroup.hostile.cpp (compiled here) with the
# file's words as arguments; its test binary, the judge, starts that answerer the way
# the harness does (the command line in LABKIT_ANSWERER), then notes what the answerer
# measured and what its control group saw. It needs labkit-runner, root, a C++ compiler,
# python3 and cgroups: without them it is skipped (exit 77), saying why.
#
#   cgroup.test.sh RUNNER KIT_ROOT
set -uo pipefail
runner="$1"
kit="$2"
skip() { echo "SKIPPED: $*"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "graded code gets a uid and a control group of its own only when the grader runs as root"
command -v python3 >/dev/null || skip "the stand-in judge is a python3 script"
command -v c++ >/dev/null || skip "no C++ compiler for the hostile answerer"
work="$(mktemp -d /tmp/labkit-cgroup.XXXXXX)"
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
chmod 755 "$work"  # the sandbox's runs read the stand-in build as other users
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
memory_mb=512

# ---- the stand-in kit ---------------------------------------------------------------
build="$work/build"
measured="$work/measured"
mkdir -p "$build/grading" "$measured"
c++ -std=c++17 -O1 -o "$build/hostile" "$(dirname "$0")/cgroup.hostile.cpp" || { echo "FAIL: cannot compile the hostile answerer"; exit 1; }
# The judge: on step 1, the answerer's line and the group's peak memory go to
# $measured/ATTACK; every step passes.
cat >"$build/test_02_segment_triangle" <<EOF
#!/usr/bin/env python3
import json, os, subprocess, sys
if "[step1]" in sys.argv[1]:
    argv = json.loads(os.environ["LABKIT_ANSWERER"])
    launcher = argv[:argv.index("--")]
    groups = [launcher[i + 1] for i, word in enumerate(launcher) if word == "--cgroup"]
    run = subprocess.run(argv, env={"PATH": "/usr/bin:/bin"}, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
    line = run.stdout.decode(errors="replace").strip()
    peaks = [open(os.path.join(g, f)).read().strip() for g in groups for f in ("memory.max_usage_in_bytes", "memory.peak")
             if os.path.exists(os.path.join(g, f))]
    with open(os.path.join("$measured", line.split(":")[0] or "nothing"), "w") as out:
        out.write(line + "\ngroups " + " ".join(groups) + "\npeak_mb " + str(int(peaks[0]) >> 20 if peaks else -1) + "\n")
# Every field common/protocol/report.h reads.
passed = {"test_case": "t", "query": "q", "kind": "examples", "cases": 1, "passed": 1, "ambiguous": 0, "failed": 0,
          "not_implemented": "", "error": "", "failure": None, "notes": []}
with open(os.environ["LABKIT_REPORT"], "w") as report:
    json.dump({"seed": "hidden", "cases_per_query": 1, "finished": True, "queries": [passed],
               "test_cases": [{"name": "t", "tags": [], "passed": True, "ended": True, "failures": [], "not_implemented": ""}]},
              report)
EOF
chmod 755 "$build/test_02_segment_triangle"
# Compiling copies the file; linking makes the answerer: the hostile program beside it,
# and a script that runs it with the student's words.
source "$(dirname "$0")/stand_in_kit.sh"
stand_in_build "$kit" "$build" "$build/hostile" 'cp $0 $2' \
  'dir=$(dirname $3); cp $1 $dir/hostile && { echo "#!/bin/sh"; printf "exec $dir/hostile "; cat $4; } >$3 && chmod 755 $3 $dir/hostile'

# ---- the submissions: lab 02's file holds the attack ---------------------------------
subs="$work/submissions"
lab02=labs/02_segment_triangle/segment_triangle.cpp
attack() { mkdir -p "$subs/$1/$(dirname $lab02)" && echo "$2" >"$subs/$1/$lab02"; }
attack memory "memory 4 $((memory_mb / 2))"
attack fork "fork 200"
attack spin "spin 8 5"
attack files "files 60 50"

# ---- graded one at a time: the CPU share is measured alone ---------------------------
out="$work/results"
LABKIT_BUILD_DIR="$build" timeout 600 "$runner" grade "$subs" --out "$out" --seed "cgroup test seed" --labs 02 \
  --jobs 1 --timeout 60 --memory $memory_mb >"$work/grade.log" 2>&1
code=$?
[ $code -eq 0 ] || { cat "$work/grade.log"; fail "labkit grade exits $code (124: it hung)"; }
sandbox=$(grep -h -m 1 -i "sandbox" "$out/memory/report.txt")
echo "$sandbox"
case "$sandbox" in
  *"no per-step cgroup limits"*) skip "no per-step cgroup limits here ${sandbox#*no per-step cgroup limits }" ;;
  *"per-step cgroup limits in part only"*) skip "per-step cgroup limits only in part here ${sandbox#*in part only }" ;;
  *"per step, the graded code's processes together"*) ;;
  *) fail "the report does not say whether per-step cgroup limits are in force" ;;
esac

# number ATTACK PATTERN: the first number after PATTERN in what ATTACK measured.
number() { sed -n "s/.*$2 *\([0-9][0-9.]*\).*/\1/p" "$measured/$1" 2>/dev/null | head -n 1; }
for a in memory fork spin files; do
  [ -f "$measured/$a" ] && head -n 1 "$measured/$a" || fail "$a: the judge measured nothing"
done

held=$(number memory "memory:")
peak=$(number memory "peak_mb")
[ -n "$held" ] && [ $((held * memory_mb / 2)) -lt $memory_mb ] ||
  fail "memory: $held children held $((memory_mb / 2)) MB at once, beyond the step's $memory_mb MB"
[ -n "$peak" ] && [ "$peak" -le $memory_mb ] || fail "memory: the group's peak was ${peak:-unknown} MB, the limit $memory_mb MB"

started=$(number fork "fork:")
[ -n "$started" ] && [ "$started" -le 64 ] || fail "fork: ${started:-no} children started; the group allows 64 processes"

cores=$(sed -n 's/.*: \([0-9.]*\) cores.*/\1/p' "$measured/spin" 2>/dev/null)
[ -n "$cores" ] && awk -v c="$cores" 'BEGIN { exit !(c <= 1.2) }' ||
  fail "spin: eight children in sessions of their own got ${cores:-unknown} cores; the group allows one"

if [[ "$sandbox" == *"sandbox: bubblewrap"* ]]; then
  written=$(number files "files:")
  [ -n "$written" ] && [ "$written" -le 256 ] || fail "files: ${written:-unknown} MB written in /tmp, which holds 256 MB"
fi

# Every step's group is gone: the ones the judge saw, and any other of this grader's.
for g in $(sed -n 's/^groups //p' "$measured"/* 2>/dev/null); do
  [ ! -e "$g" ] || fail "the step's control group $g is still there"
done
[ -n "$(sed -n 's/^groups //p' "$measured/memory" 2>/dev/null)" ] || fail "the answerer joined no control group"

[ $failures -eq 0 ] && echo "cgroup: every limit held for the graded code as a whole" || echo "cgroup: $failures failure(s)"
[ $failures -eq 0 ]
