#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image; the zip is
# unpacked in /autograder/source. It installs the packages and builds the kit once: each
# submission then costs only the compile of the student's own files.
#
# Base image: Gradescope's default, Ubuntu 22.04 (CMake 3.22, g++ 11, Catch2 2.13). Every
# package the kit needs has the same name there as on Debian 12, in Ubuntu's "universe"
# component, which Gradescope's images enable; Ubuntu 24.04 (Catch2 3) works too. On
# another image, the line below names each package apt-get could not find.
#   LABKIT_AUTOGRADER_ROOT  the folder standing for /autograder (the kit's tests set it)
set -euo pipefail
ROOT="${LABKIT_AUTOGRADER_ROOT:-/autograder}"
if [ -r /etc/os-release ]; then
  . /etc/os-release
  case "${ID:-}:${VERSION_ID:-}" in
    debian:12 | ubuntu:22.04 | ubuntu:24.04) ;;
    *) echo "setup.sh: ${PRETTY_NAME:-this system} is not a base image the kit was tried on (Debian 12," \
            "Ubuntu 22.04 or 24.04); going on" >&2 ;;
  esac
fi
# The code under test runs under unprivileged uids: they may read the kit (it is the
# student release: no solutions), but only the grader (root) reads the seed.
chmod o+x "$ROOT"
chmod -R o+rX "$ROOT/source"
chmod 600 "$ROOT/source/secret_seed"
"$ROOT/source/labkit" prepare-grading
chmod -R o+rX "$ROOT/source/build"
