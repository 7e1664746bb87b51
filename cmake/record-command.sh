#!/bin/sh
# record-command.sh FILE COMMAND...: writes the folder it runs in and COMMAND to FILE
# (NUL-separated), then runs COMMAND. The kit links each lab's student test binary
# through it, so that `./labkit grade` can link a submission exactly the same way.
record="$1"
shift
mkdir -p "$(dirname "$record")" &&
  printf '%s\0' "$PWD" "$@" >"$record.partial" &&
  mv -f "$record.partial" "$record"
exec "$@"
