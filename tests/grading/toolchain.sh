#!/usr/bin/env bash
# The kit built and checked with another toolchain than Debian 12's: another compiler
# (g++-11 is Ubuntu 22.04's, and a Debian package), another CMake (3.22 is Ubuntu
# 22.04's), or libraries from a prefix (Catch2 3 as Ubuntu 24.04 ships it, CLI11 or
# nlohmann-json at Ubuntu 22.04's versions). It copies the kit's committed files to a
# scratch folder, configures it there with what it is given, builds what grading needs
# and the reference solutions' programs, runs every lab's steps on the references, and
# grades the reference solutions as a submission: all 700 points, or it fails.
#
#   bash tests/grading/toolchain.sh [--cxx g++-11] [--cmake PATH] [--prefix DIR[;DIR]]
#
# CI runs it with --cxx g++-11. Nothing it uses is downloaded: a CMake or library from
# elsewhere is installed by whoever runs it, and named here.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
say() { printf 'toolchain: %s\n' "$*" >&2; }
cxx=g++ cmake=cmake prefix=""
while [ $# -gt 0 ]; do
  case "$1" in
    --cxx) cxx="$2"; shift 2 ;;
    --cmake) cmake="$2"; shift 2 ;;
    --prefix) prefix="$2"; shift 2 ;;
    *) say "unknown option '$1'"; exit 2 ;;
  esac
done
command -v "$cxx" >/dev/null || { say "no compiler $cxx here (Debian: apt-get install $cxx)"; exit 2; }
ctest="$(dirname "$(command -v "$cmake")")/ctest"
[ -x "$ctest" ] || ctest=ctest

WORK="$(mktemp -d /tmp/labkit-toolchain.XXXXXX)"
trap 'rm -rf "$WORK"' EXIT
chmod 755 "$WORK"  # graded code runs under other uids and reads the kit
git -C "$ROOT" ls-files -z | (cd "$ROOT" && xargs -0 cp --parents -t "$WORK")
cd "$WORK"
say "configuring with $("$cmake" --version | head -n 1), $("$cxx" --version | head -n 1)${prefix:+, prefix $prefix}"
CXX="$cxx" "$cmake" -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLABKIT_VIEWER=OFF \
  ${prefix:+"-DCMAKE_PREFIX_PATH=$prefix"} >configure.log 2>&1 || { cat configure.log >&2; say "configuring failed"; exit 1; }
grep -E 'Catch2_DIR|CLI11_DIR|nlohmann_json_DIR|rapidcheck_DIR' build/CMakeCache.txt | sed 's/^/  /' >&2

targets=(labkit-grading test_kit_harness kit_untrusted)
for lab in labs/[0-9][0-9]_*/; do
  stem=$(basename "$lab")
  targets+=("test_$stem" "answer_${stem}_reference")
done
say "building what grading needs and the references' programs"
"$cmake" --build build --target "${targets[@]}" >build.log 2>&1 || { grep -E -A5 'error|Error' build.log | head -n 60 >&2; say "the build failed"; exit 1; }

say "every lab's steps on the references, and the kit's own unit tests"
"$ctest" --test-dir build -R '^lab[0-9][0-9]\.(step[0-9]+|contract)$|^kit\.(harness|untrusted)$' -j2 --output-on-failure >ctest.log 2>&1 ||
  { tail -n 40 ctest.log >&2; say "a test failed"; exit 1; }
grep -E 'tests passed' ctest.log >&2

say "grading the references as a submission"
mkdir -p submission
for lab in solutions/*/; do
  mkdir -p "submission/labs/$(basename "$lab")"
  cp "$lab"*.cpp "submission/labs/$(basename "$lab")/"
done
build/runner/labkit-runner grade submission --out results --seed "toolchain check" >grade.log 2>&1 ||
  { tail -n 30 grade.log >&2; say "grading failed"; exit 1; }
total=$(sed -n 's/^ *Total  *\([0-9.]* \/ [0-9.]*\).*/\1/p' grade.log)
labs=$(ls -d solutions/*/ | wc -l)
[ "$total" = "$((labs * 100)) / $((labs * 100))" ] || { grep -E '^ *(Lab|Total)' grade.log >&2; say "the references scored $total"; exit 1; }
say "the references score $total with this toolchain"
