#!/usr/bin/env bash
# What students and Gradescope get, and nothing more (run through ./labkit):
#
#   release OUT_DIR [--classroom ITEM...]      the students' repository; with an
#                                              assignment (e.g. 03:core), its GitHub
#                                              Classroom workflow in .github/workflows/
#   package gradescope [--out FILE] [--seed S] [--budget SECONDS] [--assignment ITEM...]
#                                              the autograder zip: the release, plus
#                                              setup.sh, run_autograder and secret_seed
#                                              (and grading_budget, with --budget; and
#                                              assignment.json, with --assignment)
#
# An assignment's items (03:core, 06, 05:1,4,5,8, or a JSON file) are checked against
# the manifest and frozen by the kit's runner ($LABKIT_RUNNER, which ./labkit builds).
#
# The release is a list of what to take, not of what to leave out, so that a file added
# to the kit later never reaches students by default. It never holds solutions/ (nor,
# so, the classic mistakes written in the references' `// mutant` lines), the hostile
# submissions of tests/grading/, .ci/ or anything of grading/ but the manifest.
# tests/kit/release.test.sh checks that no reference function body appears in it.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
say() { printf 'labkit: %s\n' "$*" >&2; }

make_release() {
  local out="$1"
  if [ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null)" ]; then
    say "$out exists and is not empty; name a new folder"
    exit 2
  fi
  mkdir -p "$out"
  out="$(cd "$out" && pwd)"
  case "$out/" in "$ROOT"/*) say "the release cannot go inside the kit itself"; exit 2 ;; esac
  cd "$ROOT"
  cp -p CMakeLists.txt CMakePresets.json labkit .gitignore "$out/"
  local folder
  for folder in cmake common labs runner viewer handouts .devcontainer; do
    [ -d "$folder" ] && cp -pR "$folder" "$out/"
  done
  mkdir -p "$out/tests" "$out/grading"
  # Each lab's checker (tests/NN_name/: its inputs, generators, judge, wire and tests,
  # every file cmake/LabKit.cmake compiles into a judge) but its mutants, and what every
  # judge shares.
  local piece lab_dir
  for piece in tests/CMakeLists.txt tests/judging.h; do
    cp -p "$piece" "$out/tests/"
  done
  for lab_dir in tests/[0-9][0-9]_*/; do
    mkdir -p "$out/$lab_dir"
    cp -p "$lab_dir"* "$out/$lab_dir"
  done
  cp -pR tests/kit "$out/tests/"
  cp -p grading/manifest.json "$out/grading/"
  cp -p grading/student-README.md "$out/README.md"

  # A stub always has a step left to write; a lab file that has none is not a stub
  # (the reference copied over it, as CI does for a moment): never ship that.
  local file
  for file in "$out"/labs/*/*.cpp; do
    if ! grep -q "not_implemented(" "$file"; then
      say "${file#$out/} has no 'not_implemented(' step left: it is not a stub; release stopped"
      rm -rf "$out"
      exit 1
    fi
  done
  say "wrote the student release in $out"
}

# freeze_assignment OUT_JSON [WORKFLOW] ITEM...: the assignment checked and frozen.
freeze_assignment() {
  local out="$1" workflow="$2"
  shift 2
  [ -n "${LABKIT_RUNNER:-}" ] || { say "an assignment needs the kit's runner: run this through ./labkit"; exit 2; }
  [ $# -gt 0 ] || { say "--assignment and --classroom take items, e.g. 03:core (README, \"Fitting a course\")"; exit 2; }
  "$LABKIT_RUNNER" assignment "$@" --out "$out" ${workflow:+--workflow "$workflow"} >&2 || exit 2
}

# Items after an option, up to the next option.
take_items() {
  items=()
  while [ $# -gt 0 ] && [[ "$1" != --* ]]; do items+=("$1"); shift; done
}

command="${1:-}"
shift || true
case "$command" in
  release)
    usage="usage: ./labkit release OUT_DIR [--classroom ITEM...]"
    [ $# -ge 1 ] && [[ "$1" != --* ]] || { say "$usage"; exit 2; }
    out="$1"
    shift
    classroom=()
    if [ $# -gt 0 ]; then
      [ "$1" = --classroom ] || { say "unknown option '$1'; $usage"; exit 2; }
      shift
      take_items "$@"
      classroom=("${items[@]}")
      [ ${#classroom[@]} -eq $# ] || { say "$usage"; exit 2; }
      [ ${#classroom[@]} -gt 0 ] || { say "--classroom takes an assignment, e.g. 03:core"; exit 2; }
      # Checked before the release is written: a wrong item leaves no half-made folder.
      scratch="$(mktemp -d)"
      trap 'rm -rf "$scratch"' EXIT
      freeze_assignment "$scratch/assignment.json" "$scratch/classroom.yml" "${classroom[@]}"
    fi
    make_release "$out"
    if [ ${#classroom[@]} -gt 0 ]; then
      mkdir -p "$out/.github/workflows"
      cp "$scratch/classroom.yml" "$out/.github/workflows/classroom.yml"
      say "with its GitHub Classroom workflow: $out/.github/workflows/classroom.yml (README, \"GitHub Classroom\")"
    fi
    ;;
  package)
    [ "${1:-}" = gradescope ] || { say "usage: ./labkit package gradescope [--out FILE] [--seed S] [--budget SECONDS] [--assignment ITEM...]"; exit 2; }
    shift
    zip_file="${LABKIT_BUILD_DIR:-$ROOT/build}/gradescope-autograder.zip"
    seed="${LABKIT_GRADING_SEED:-}"
    budget=""
    assignment=()
    while [ $# -gt 0 ]; do
      case "$1" in
        --assignment)
          shift
          take_items "$@"
          [ ${#items[@]} -gt 0 ] || { say "--assignment takes items, e.g. --assignment 03:core"; exit 2; }
          assignment+=("${items[@]}")
          shift ${#items[@]} ;;
        --out) zip_file="$2"; shift 2 ;;
        --seed) seed="$2"; shift 2 ;;
        --budget)
          [[ "${2:-}" =~ ^[0-9]+([.][0-9]+)?$ ]] || { say "--budget takes seconds, e.g. --budget 480"; exit 2; }
          budget="$2"; shift 2 ;;
        *) say "unknown option '$1'"; exit 2 ;;
      esac
    done
    seed_note="the one you gave"
    if [ -z "$seed" ]; then
      seed="$(od -An -N24 -tx1 /dev/urandom | tr -d ' \n')"
      seed_note="a new random one (unzip -p the zip secret_seed shows it)"
    fi
    staging="$(mktemp -d)"
    trap 'rm -rf "$staging"' EXIT
    # The assignment first: a wrong item stops here, before anything is written.
    if [ ${#assignment[@]} -gt 0 ]; then freeze_assignment "$staging/assignment.json" "" "${assignment[@]}"; fi
    make_release "$staging/source" 2>/dev/null
    # run_autograder grades this assignment only (./labkit grade --assignment).
    [ ${#assignment[@]} -eq 0 ] || mv "$staging/assignment.json" "$staging/source/assignment.json"
    cp -p "$ROOT"/grading/gradescope/setup.sh "$ROOT"/grading/gradescope/run_autograder "$staging/source/"
    (umask 077 && printf '%s' "$seed" >"$staging/source/secret_seed")
    # A submission's time budget (./labkit grade --budget); without it, the grader's default.
    [ -z "$budget" ] || printf '%s\n' "$budget" >"$staging/source/grading_budget"
    mkdir -p "$(dirname "$zip_file")"
    zip_file="$(cd "$(dirname "$zip_file")" && pwd)/$(basename "$zip_file")"
    rm -f "$zip_file"
    (cd "$staging/source" && zip -qr -X "$zip_file" .)
    say "wrote $zip_file: upload it as the Gradescope autograder"
    say "its secret seed is $seed_note; it is in the zip only, never commit it"
    ;;
  *)
    say "usage: release.sh release OUT_DIR [--classroom ITEM...] | package gradescope [--out FILE] [--seed S] [--budget SECONDS] [--assignment ITEM...]"
    exit 2
    ;;
esac
