#!/usr/bin/env bash
# Grading inside Gradescope's default envelope (issue 16): half a CPU and 768 MB for the
# whole container, and a 10-minute global time-out. It grades one seven-lab submission
# (the reference solutions, or the one named) inside a control group with exactly those
# limits and prints its wall time and peak memory.
#
#   bash bench/envelope.sh [SUBMISSION] [--cpu 0.5] [--memory-mb 768] [--jobs N]
#   (`./labkit bench --envelope` runs it; needs root, for the control group)
#
# The kit's build (Gradescope's setup.sh) is done first, outside the limits, as it is
# when Gradescope builds the autograder's image. Peak memory is what the kernel charged
# to the group at its highest (cgroup v2 memory.peak, v1 memory.max_usage_in_bytes: page
# cache included), and the highest resident memory of its processes, sampled every
# 100 ms; an out-of-memory kill inside the group is reported.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
say() { printf 'envelope: %s\n' "$*" >&2; }

submission="" cpu=0.5 memory_mb=768 jobs=()
while [ $# -gt 0 ]; do
  case "$1" in
    --cpu) cpu="$2"; shift 2 ;;
    --memory-mb) memory_mb="$2"; shift 2 ;;
    --jobs) jobs=(--jobs "$2"); shift 2 ;;
    -*) say "unknown option '$1'"; exit 2 ;;
    *) submission="$1"; shift ;;
  esac
done
[ "$(id -u)" = 0 ] || { say "needs root (it makes a control group with the limits)"; exit 2; }

WORK="$(mktemp -d /tmp/labkit-envelope.XXXXXX)"
chmod 755 "$WORK"
group_dirs=()
cleanup() {
  local dir
  for dir in "${group_dirs[@]}"; do
    # Anything left in the group goes back to the parent before the group is removed.
    if [ -f "$dir/cgroup.procs" ]; then
      while read -r pid; do echo "$pid" >"$(dirname "$dir")/cgroup.procs" 2>/dev/null || true; done <"$dir/cgroup.procs"
    fi
    rmdir "$dir" 2>/dev/null || true
  done
  rm -rf "$WORK"
}
trap cleanup EXIT

if [ -z "$submission" ]; then
  submission="$WORK/reference"
  for lab in "$ROOT"/labs/*/; do
    name=$(basename "$lab")
    [ -d "$ROOT/solutions/$name" ] || continue
    mkdir -p "$submission/labs/$name"
    cp "$ROOT/solutions/$name"/*.cpp "$submission/labs/$name/"
  done
  say "grading the reference solutions"
fi

say "building what grading needs (outside the limits, as Gradescope's setup.sh does)"
"$ROOT/labkit" prepare-grading >"$WORK/prepare.log" 2>&1 || { tail -n 20 "$WORK/prepare.log" >&2; exit 1; }

# The group: under this process's own group, in the unified hierarchy or in v1's cpu and
# memory hierarchies.
name="labkit-envelope-$$"
quota=$(awk -v c="$cpu" 'BEGIN { printf "%d", c * 100000 }')
memory_bytes=$((memory_mb * 1024 * 1024))
if [ -f /sys/fs/cgroup/cgroup.controllers ]; then
  group="/sys/fs/cgroup$(awk -F: '$1 == "0" { print $3 }' /proc/self/cgroup)/$name"
  group="${group/\/\//\/}"
  mkdir "$group"
  group_dirs+=("$group")
  echo "$quota 100000" >"$group/cpu.max"
  echo "$memory_bytes" >"$group/memory.max"
  echo 0 >"$group/memory.swap.max" 2>/dev/null || true
  join=("$group")
  peak_file="$group/memory.peak"
  rss_of() { awk '$1 == "anon" { print $2 }' "$group/memory.stat"; }
  ooms() { awk '$1 == "oom_kill" { print $2 }' "$group/memory.events"; }
else
  cpu_group="/sys/fs/cgroup/cpu$(awk -F: '$2 ~ /(^|,)cpu(,|$)/ { print $3 }' /proc/self/cgroup)/$name"
  memory_group="/sys/fs/cgroup/memory$(awk -F: '$2 == "memory" { print $3 }' /proc/self/cgroup)/$name"
  mkdir "$cpu_group" "$memory_group"
  group_dirs+=("$cpu_group" "$memory_group")
  echo 100000 >"$cpu_group/cpu.cfs_period_us"
  echo "$quota" >"$cpu_group/cpu.cfs_quota_us"
  echo "$memory_bytes" >"$memory_group/memory.limit_in_bytes"
  echo "$memory_bytes" >"$memory_group/memory.memsw.limit_in_bytes" 2>/dev/null || true
  join=("$cpu_group" "$memory_group")
  peak_file="$memory_group/memory.max_usage_in_bytes"
  rss_of() { awk '$1 == "total_rss" { print $2 }' "$memory_group/memory.stat"; }
  ooms() { awk '$1 == "oom_kill" { print $2 }' "$memory_group/memory.oom_control"; }
fi

say "grading inside the group: $cpu CPU, $memory_mb MB (load $(cut -d' ' -f1 /proc/loadavg))"
: >"$WORK/rss"
(
  while sleep 0.1; do rss_of >>"$WORK/rss" 2>/dev/null || break; done
) &
sampler=$!
start=$(date +%s.%N)
status=0
# The grading shell joins the group first: everything it starts is in it.
LABKIT="$ROOT/labkit" SUBMISSION="$submission" OUT="$WORK/out" \
  bash -c 'for g; do echo $$ >"$g/cgroup.procs"; done; exec "$LABKIT" grade "$SUBMISSION" --out "$OUT" '"${jobs[*]:-}" \
  _ "${join[@]}" >"$WORK/grade.log" 2>&1 || status=$?
end=$(date +%s.%N)
kill "$sampler" 2>/dev/null || true
wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }')
peak=$(awk '{ printf "%.0f", $1 / 1048576 }' "$peak_file")
rss=$(sort -n "$WORK/rss" | tail -n 1 | awk '{ printf "%.0f", $1 / 1048576 }')
score=$(sed -n 's/^ *Total  *\([0-9.]* \/ [0-9.]*\).*/\1/p' "$WORK/grade.log" | tail -n 1)
if [ "$status" != 0 ] || [ -z "$score" ]; then
  tail -n 30 "$WORK/grade.log" >&2
  say "grading failed (exit $status)"
  exit 1
fi
echo "| limits | wall time | peak memory (group, cache included) | peak resident | out-of-memory kills | score |"
echo "|---|---|---|---|---|---|"
echo "| $cpu CPU, $memory_mb MB | $wall s | $peak MB | ${rss:-?} MB | $(ooms || echo ?) | $score |"
grep -E '^ *(Lab|Total)' "$WORK/grade.log" >&2 || true
