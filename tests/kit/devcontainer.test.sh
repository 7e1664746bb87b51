#!/usr/bin/env bash
# The dev container (.devcontainer/) as a student on macOS or Windows meets it: its JSON
# is valid, the command it runs after creation is one of the README's set-up commands,
# its image takes the packages from the kit's own list (`./labkit install`, never a list
# of its own), and clangd reads the compile commands where the kit's build writes them.
# Docker cannot run here: the image itself is built where the student opens it.
#
#   devcontainer.test.sh KIT_ROOT
set -uo pipefail
kit="$1"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

python3 - "$kit" <<'PY' || failures=$((failures + 1))
import json, re, sys
kit = sys.argv[1]
config = json.load(open(f"{kit}/.devcontainer/devcontainer.json"))
readme = open(f"{kit}/README.md", encoding="utf-8").read()
# The README's set-up: the commands of the first sh block after the "Set-up" heading.
setup = readme[readme.index("## Set-up"):]
block = re.search(r"```sh\n(.*?)```", setup, re.S).group(1)
commands = [line.split("#")[0].strip() for line in block.splitlines() if line.split("#")[0].strip()]
problems = []
created = [c.strip() for c in re.split(r"&&|;", config["postCreateCommand"])]
for c in created:
    if c not in commands: problems.append(f"postCreateCommand runs '{c}', which is not a set-up command of the README ({commands})")
if config["build"]["dockerfile"] != "Dockerfile" or config["build"].get("context") != "..":
    problems.append("the image is not .devcontainer/Dockerfile built from the kit's root")
args = config["customizations"]["vscode"]["settings"]["clangd.arguments"]
if "--compile-commands-dir=${containerWorkspaceFolder}/build" not in args:
    problems.append("clangd does not read build/compile_commands.json")
if "CMAKE_EXPORT_COMPILE_COMMANDS ON" not in open(f"{kit}/CMakeLists.txt").read():
    problems.append("the build writes no compile_commands.json")
if "devcontainer" not in readme.lower(): problems.append("the README does not say how to open the kit in a dev container")
print("\n".join(problems) or "devcontainer.json: fine")
sys.exit(1 if problems else 0)
PY

dockerfile="$kit/.devcontainer/Dockerfile"
grep -q 'labkit install' "$dockerfile" || fail "the Dockerfile does not install the kit's packages with ./labkit install"
# Every package the kit's commands install comes from that list, never named twice.
eval "$(awk '/^[A-Z_]*PACKAGES=\(/ { on = 1 } on { print } on && /\)/ { on = 0 }' "$kit/labkit")"
for package in "${CORE_PACKAGES[@]}" "${VIEWER_PACKAGES[@]}" "${HEADLESS_PACKAGES[@]}" "${GRADE_PACKAGES[@]}" "${CLASS_PACKAGES[@]}"; do
  grep -qw -- "$package" "$dockerfile" && fail "the Dockerfile names $package, which ./labkit install already installs"
done
[ $failures -eq 0 ] && echo "dev container: valid, the README's command, the kit's own package list"
exit $((failures > 0))
