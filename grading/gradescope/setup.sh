#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image; the zip is
# unpacked in /autograder/source. It installs the Debian packages and builds the kit
# once: each submission then costs only the compile of the student's own files.
#   LABKIT_AUTOGRADER_ROOT  the folder standing for /autograder (the kit's tests set it)
set -euo pipefail
ROOT="${LABKIT_AUTOGRADER_ROOT:-/autograder}"
# The code under test runs under unprivileged uids: they may read the kit (it is the
# student release: no solutions), but only the grader (root) reads the seed.
chmod o+x "$ROOT"
chmod -R o+rX "$ROOT/source"
chmod 600 "$ROOT/source/secret_seed"
"$ROOT/source/labkit" prepare-grading
chmod -R o+rX "$ROOT/source/build"
