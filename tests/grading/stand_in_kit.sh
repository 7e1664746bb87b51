# Sourced by the grading tests that build no lab (grader_input.test.sh, cgroup.test.sh).
#
# stand_in_build KIT BUILD HEAD COMPILE LINK: a stand-in for KIT's build folder in BUILD,
# as ./labkit grade reads it, for every lab file of KIT's manifest: compile_commands.json
# "compiles" the file with the sh command COMPILE ($0 the file, $2 the object), and the
# lab's link record "links" it with the sh command LINK ($1 HEAD, $3 the answerer, $4 the
# student's library, which is the compiled file).
stand_in_build() {
  local kit="$1" build="$2" head="$3" compile="$4" link="$5" entries="" file stem
  mkdir -p "$build/grading"
  for file in $(grep -o '"labs/[0-9][0-9]_[a-z_]*/[a-z_]*\.cpp"' "$kit/grading/manifest.json" | tr -d '"'); do
    stem=$(basename "$(dirname "$file")")
    printf '%s\0' "$build" sh -c "$link" sh "$head" -o placeholder "$build/libstub.a" >"$build/grading/$stem.link"
    printf '{"student_library": "%s", "link_record": "%s"}\n' "$build/libstub.a" "$build/grading/$stem.link" >"$build/grading/$stem.json"
    entries+="${entries:+,}{\"directory\": \"$build\", \"file\": \"$kit/$file\", \"arguments\": [\"sh\", \"-c\", \"$compile\", \"$kit/$file\", \"-o\", \"placeholder.o\"]}"
  done
  echo "[$entries]" >"$build/compile_commands.json"
}
