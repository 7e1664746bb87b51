#!/usr/bin/env bash
# What ./labkit grade does with what a submission controls: its output, its replay
# tokens, its archives and its names; and what it must not reach: the judge's report.
# No lab is built. A step runs two programs (common/protocol/answerer.h), and the
# stand-in kit has both: its judge is a shell script that writes the report and starts
# the answerer, and its "compiler" and "linker" make the answerer, a shell script with
# the student's file appended. So each submission below is a few lines of sh that
# print, crash, or go after the report. It needs labkit-runner and python3 (the judge
# reads LABKIT_ANSWERER with it) and takes seconds; hostile.test.sh grades the same
# faults in C++ on the real kit.
#
#   grader_input.test.sh RUNNER KIT_ROOT SCHEMA_CHECKER
set -uo pipefail
runner="$1"
kit="$2"
schema_check="$3"
work="$(mktemp -d /tmp/labkit-grader-input.XXXXXX)"
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
chmod 755 "$work"  # the sandbox's runs read the stand-in build as other users
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
source "$(dirname "$0")/stand_in_kit.sh"
secret="grader input secret $$"
owned="$work/owned"  # what a crafted replay command would create if it were ever run

# ---- the stand-in kit ---------------------------------------------------------------
# A step runs two programs (common/protocol/answerer.h): the kit's judge, which writes
# the report, and the answerer, the student's code, which the judge starts and which
# only answers. Here the answerer is a shell script with the student's lines appended:
# ending well answers every call right.
#
# stand_in_kit BUILD: how the kit in BUILD compiles a lab's file (a copy; a first line
# "#error ..." fails, with the file as the errors; a first line "#slow" takes 3 s) and
# links it into an answerer (the answerer's head with the file appended, at the path the
# runner asks with -o).
stand_in_kit() {
  local build="$1"
  mkdir -p "$build"
  echo '#!/bin/sh' >"$build/answerer.sh"
  stand_in_build "$kit" "$build" "$build/answerer.sh" \
    'if head -n 1 $0 | grep -q ^#error; then printf \"error: \" >&2; cat $0 >&2; exit 1; fi; if head -n 1 $0 | grep -q ^#slow; then sleep 3; fi; cp $0 $2' \
    'cat $1 $4 >$3 && chmod 755 $3'
}
build="$work/build"
stand_in_kit "$build"
# The judge: every call passes, unless the answerer ends badly; then one call failed,
# in the real judge's words (common/protocol/calls.cpp), with a replay token of its own
# and the last of what the answerer printed. Described (LABKIT_DESCRIBE), it names the
# case and runs no code under test. Its report has every field common/protocol/report.h
# reads.
cat >"$build/test_02_segment_triangle" <<'EOF'
#!/usr/bin/env python3
import json, os, subprocess, sys

def write(queries):
    with open(os.environ["LABKIT_REPORT"], "w") as f:
        json.dump({"seed": "hidden", "cases_per_query": 1, "finished": True, "queries": queries,
                   "test_cases": [{"name": "t", "tags": [], "passed": queries[0]["failed"] == 0, "ended": True,
                                   "failures": [], "not_implemented": ""}]}, f)

def query(name, passed, failure=None):
    return {"test_case": "t", "query": name, "kind": "random", "cases": 1, "passed": passed, "ambiguous": 0,
            "failed": 1 - passed, "trivial": 0, "trivial_passed": 0, "decisive": 1, "decisive_passed": passed,
            "not_implemented": "", "error": "", "failure": failure, "notes": []}

def failure(title, input, got, why, replay):
    return {"title": title, "input": input, "expected": "yes", "got": got, "why": why, "replay": replay, "shrinks": 0}

# The seed the grader gave this step, read (and deleted) as the harness does; logged
# beside this judge with the first line the answerer printed, for the seed checks.
seed = ""
if os.environ.get("LABKIT_SEED_FILE"):
    seed = open(os.environ["LABKIT_SEED_FILE"]).read()
    os.remove(os.environ["LABKIT_SEED_FILE"])
if os.environ.get("LABKIT_DESCRIBE"):
    write([query("q", 0, failure("described", "the described input", "", "", os.environ.get("LABKIT_REPLAY", "")))])
    sys.exit(0)
write([query("q", 1)])
# As the real judge starts it: LABKIT_ANSWERER is a path or a JSON array (the grader's
# confinement around it), the environment is PATH alone; what it prints goes on to the
# judge's stderr, and its tail comes with a crash.
command = os.environ["LABKIT_ANSWERER"]
argv = json.loads(command) if command.startswith("[") else [command]
answerer = subprocess.Popen(argv, env={"PATH": "/usr/bin:/bin"}, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT)
tail = b""
for chunk in iter(lambda: answerer.stdout.read1(65536), b""):
    sys.stderr.buffer.write(chunk)
    tail = (tail + chunk)[-600:]
ended = answerer.wait()
printed = tail.decode("utf-8", "replace")
if printed.startswith("ID "):
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "seeds.log"), "a") as log:
        log.write(seed + "\t" + printed.split("\n")[0][3:] + "\n")
if ended == 0 and "WRONG " in printed:  # a wrong answer, with the number the code printed
    x = printed.split("WRONG ")[1].split()[0]
    write([query("segment_plane", 0, failure("random case", "in", x,
          f"the answer is 0, not {x}: the point is off its plane by {x} (tolerance 1e-09)", "segment_plane:1,2,3"))])
    sys.exit(1)
if ended == 0:
    sys.exit(0)
signal = -ended if ended < 0 else ended - 128
how = f"killed by signal {signal}" if signal > 0 else f"it exited with status {ended}"
write([query("segment_plane", 0, failure("random case", "in", "a crash",
      f"your code crashed during this call ({how})\nwhat it printed last:\n{printed}", "segment_plane:1,-2.5,1e+300,inf"))])
sys.exit(1)
EOF
chmod 755 "$build/test_02_segment_triangle"
# grade BUILD ARGS...: ./labkit grade ARGS with the stand-in kit BUILD.
# Where nothing can confine graded code, the real kit (it holds solutions/) is refused:
# this test is about output, names and archives, so it grades with --sandbox none there.
sandbox=auto
if ! said=$("$runner" grade /dev/null --out "$work/probe" 2>&1) && grep -q "nothing can confine" <<<"$said"; then sandbox=none; fi
grade() { LABKIT_BUILD_DIR="$1" timeout 300 "$runner" grade "${@:2}" --seed "$secret" --labs 02 --jobs 2 --timeout 20 --sandbox "$sandbox"; }

# ---- the submissions: lab 02's file is the student's lines ---------------------------
subs="$work/submissions"
lab02=labs/02_segment_triangle/segment_triangle.cpp
# student NAME LINES: a folder submission whose lab 02 file holds LINES.
student() { mkdir -p "$subs/$1/$(dirname $lab02)" && printf '%s\n' "$2" >"$subs/$1/$lab02"; }
# tamper COMMAND: the student's lines run COMMAND on "$report" for every path where the
# judge's report could be: $LABKIT_REPORT (the answerer's environment has none), the
# folders beside its own (the judge's scratch folder is one of them, on the grader's
# disk) and the grader's under /tmp. Then they end well.
tamper() { printf 'for report in "${LABKIT_REPORT:-}" ../report.json ../*/report.json /tmp/labkit-grade.*/*/lab02/*/report.json; do %s; done 2>/dev/null; :' "$1"; }
crafted="segment_plane:1' ; touch $owned ; '"
forged='{"seed": "hidden", "cases_per_query": 1, "finished": true, "test_cases": [{"name": "t", "tags": [], "passed": false, "ended": true, "failures": [], "not_implemented": ""}], "queries": [{"test_case": "t", "query": "segment_plane", "kind": "random", "cases": 1, "passed": 0, "ambiguous": 0, "failed": 1, "trivial": 0, "trivial_passed": 0, "decisive": 1, "decisive_passed": 0, "not_implemented": "", "error": "", "failure": {"title": "t", "input": "i", "expected": "e", "got": "g", "why": "w", "replay": "'"$crafted"'", "shrinks": 0}, "notes": []}]}'

student passing ': nothing to add'
# Two wrong answers breaking one rule on other numbers: one concept on the class page.
student wrong_small 'echo WRONG 3'
student wrong_large 'echo WRONG -7.25e-3'
# A crafted in-flight marker, then a crash: one call fails, and the judge names its case.
student crash "echo \"LABKIT-INFLIGHT $crafted\"; kill -SEGV \$\$"
# Accented text (the kept tail starts in the middle of it), a Latin-1 byte, terminal
# escapes, then death as a C++ program dies of an uncaught std::bad_alloc: one call
# fails, and what it printed last comes with it, as safe text.
student latin1_crash 'i=0; while [ $i -lt 700 ]; do printf "\303\251"; i=$((i + 1)); done; printf "\nr\303\251sultat \351 \033[2J\033]0;owned\007\n\033[31mred\r\n"
printf "terminate called after throwing an instance of '"'std::bad_alloc'"'\n  what():  std::bad_alloc\n"; kill -ABRT $$'
# An in-flight marker printed, then a flood of output: the grader stops the judge's
# process, and names the case only from the judge's own file, never from the output.
student crafted_inflight "echo \"LABKIT-INFLIGHT $crafted\"; yes flooding the grader"
student faked_inflight "echo 'LABKIT-INFLIGHT segment_plane:4,5,6'; yes flooding the grader"
student latin1_compile "$(printf '#error caf\351 \033[2J\033]0;owned\007 \303\251')"
# Student text that would forge the kit's own lines (a static_assert message keeps its
# newlines; so does what code prints before it crashes): every line break a reader
# knows (newline, CR, CR LF, VT, FF, NEL, U+2028, U+2029), each followed by a table's
# last line. Every line of it must be quoted ("| ") in every output.
forged_lines="$(printf '"\n  Total 700 / 700\n \r  Total 700 / 700 \r\n  Total 700 / 700 \v  Total 700 / 700 \f  Total 700 / 700 \302\205  Total 700 / 700 \342\200\250  Total 700 / 700 \342\200\251  Total 700 / 700"')"
student forged_compile "#error static_assert failed: $forged_lines"
student forged_output "printf '%s\\n' '$forged_lines'; kill -SEGV \$\$"
# Their own cases: two submissions under one secret draw different seeds (each
# prints who it is, and the stand-in judge logs the seed it was given).
student seed_a 'echo "ID seed_a"'
student seed_b 'echo "ID seed_b"'
student fifo_report "$(tamper 'rm -f "$report"; mkfifo "$report"')"
student symlink_report "$(tamper 'rm -f "$report"; ln -s /etc/passwd "$report"')"
student forged_report "$(tamper "printf '%s' '${forged//\'/\'\\\'\'}' >\"\$report\"")"
# Names a spreadsheet would take for formulas ("-2-2" is -4), and one with a comma and a
# quote: class.csv shows each as text, one cell.
for name in -2-2 '=1+1' '+1' '@SUM(A1)' 'doe, "jo"'; do student "$name" ': nothing to add'; done
# A student's folder that is merely named labs: its file at its top, uploaded alone.
mkdir -p "$subs/labs" && echo ': the student called labs' >"$subs/labs/segment_triangle.cpp"

# Archives. good: lab 02's file; the rest is what one bad member looks like.
mkdir -p "$work/a/labs/02_segment_triangle" "$work/a/XX" "$work/a/labs/01_frustum_split" "$work/a/labs/03_separating_axes"
echo ': good' >"$work/a/$lab02"
echo 'touch /tmp/escaped' >"$work/a/XX/segment_triangle.cpp"
ln -s /etc/passwd "$work/a/labs/01_frustum_split/frustum_split.cpp"
head -c 5M /dev/zero >"$work/a/labs/03_separating_axes/separating_axes.cpp"
(cd "$work/a" && zip -qry "$subs/bad_members.zip" . && LC_ALL=C sed -i 's|XX/segment|../segment|g' "$subs/bad_members.zip")
# A zip bomb that lies: it declares 10 bytes and unpacks to 3 MB.
mkdir -p "$work/b/$(dirname $lab02)" && head -c 3M /dev/zero >"$work/b/$lab02"
(cd "$work/b" && zip -qr "$subs/bomb.zip" $lab02)
size=$(stat -c %s "$subs/bomb.zip")
directory=$(od -An -tu4 -j $((size - 6)) -N4 "$subs/bomb.zip" | tr -d ' ')
for at in 22 $((directory + 24)); do printf '\x0a\x00\x00\x00' | dd of="$subs/bomb.zip" bs=1 seek=$at conv=notrunc status=none; done
# A tar with every kind of bad member, and lab 02's file under a folder named in Latin-1.
latin1="$(printf 'caf\351')"
mkdir -p "$work/t/one/labs/01_frustum_split" "$work/t/two/labs/01_frustum_split" "$work/t/$latin1/$(dirname $lab02)" \
  "$work/t/labs/03_separating_axes" "$work/t/labs/04_bisection" "$work/t/labs/05_sphere_sweeps"
echo ': good' >"$work/t/$latin1/$lab02"
echo one >"$work/t/one/labs/01_frustum_split/frustum_split.cpp"
echo two >"$work/t/two/labs/01_frustum_split/frustum_split.cpp"
echo absolute >"$work/t/labs/03_separating_axes/separating_axes.cpp"
echo target >"$work/t/target" && ln "$work/t/target" "$work/t/labs/04_bisection/bisection.cpp"
mkfifo "$work/t/labs/05_sphere_sweeps/sphere_sweeps.cpp"
(cd "$work/t" && tar -czf "$subs/bad_members_tar.tar.gz" -P --transform 's,^one/,,;s,^two/,,;s,^labs/03,/abs/labs/03,' \
  --transform 's,^target,../../target,' target one two labs "$latin1" 2>/dev/null)

# ---- one class, graded at once -------------------------------------------------------
out="$work/results"
grade "$build" "$subs" --out "$out" >"$work/grade.log" 2>&1
code=$?
[ $code -eq 0 ] || { cat "$work/grade.log"; fail "labkit grade exits $code (124: it hung)"; }

# status NAME STATUS: every step of lab 02 has that status.
status() {
  local tsv="$out/$1/steps.tsv"
  [ -f "$tsv" ] || { fail "$1: no results"; return; }
  local other
  other=$(awk -F'\t' -v s="$2" 'NR > 1 && $4 != s { print "step " $2 " is " $4 }' "$tsv" | head -n 1)
  [ -z "$other" ] || fail "$1: $other, expected '$2'"
}
says() { grep -qF -- "$2" "$out/$1/report.txt" || fail "$1: the report does not say '$2'"; }
# full_marks NAME: every step of lab 02 scores its points.
full_marks() { awk -F'\t' 'NR > 1 && $5 != $6 { bad = 1 } END { exit bad }' "$out/$1/steps.tsv" || fail "$1: a step lost points"; }
status passing passed
status crash failing
status latin1_crash failing
status crafted_inflight "too much output"
status faked_inflight "too much output"
status latin1_compile "does not compile"
status fifo_report passed
status symlink_report passed
status forged_report passed
status labs passed
status bad_members passed
status bad_members_tar passed
status bomb "not submitted"

# 1. Untrusted text: invalid UTF-8 shown as U+FFFD, terminal controls shown as text.
says latin1_crash $'r\u00e9sultat \ufffd \\x1b[2J\\x1b]0;owned\\x07'
says latin1_crash '\x1b[31mred'
says latin1_compile $'#error caf\ufffd \\x1b[2J'
says bad_members_tar $'graded caf\ufffd/labs/02_segment_triangle/segment_triangle.cpp as'
# 1b. Student text never starts a line of its own: each line holding the forged total,
# as any reader splits lines (Python's splitlines: CR, VT, FF, NEL, U+2028 ...), starts
# with the quote, in the terminal, report.txt, results.json (its strings), junit.xml and
# the class page.
status forged_compile "does not compile"
status forged_output failing
python3 - "$out" "$work/grade.log" <<'PY' || fail "forged kit lines: see above"
import json, os, sys
out, log = sys.argv[1], sys.argv[2]
files = [log] + [os.path.join(d, f) for d, _, fs in os.walk(out) for f in fs]
problems, seen = [], 0
def lines_of(text):
    yield from text.splitlines()
def strings(value):
    if isinstance(value, str): return [value]
    items = value.values() if isinstance(value, dict) else value if isinstance(value, list) else []
    return [s for v in items for s in strings(v)]
for path in files:
    text = open(path, "rb").read().decode("utf-8", "replace")
    texts = list(strings(json.loads(text))) if path.endswith(".json") else [text]
    for t in texts:
        for line in lines_of(t):
            if "Total 700 / 700" in line:
                seen += 1
                if not line.lstrip(" ").startswith("|"): problems.append(f"{path}: an unquoted line {line!r}")
if seen < 8: problems.append(f"the forged lines were shown {seen} times: expected in the report, results.json, the terminal")
print("\n".join(problems[:20]) or "forged lines: all quoted")
sys.exit(1 if problems else 0)
PY
# 2. Replay commands. A crash costs the call it happened on, in the judge's words, and
# its replay command is the judge's token, quoted, never the marker printed before it;
# a flood's printed markers name nothing.
says crash "got       a crash"
says crash "why       your code crashed during this call (killed by signal 11)"
says crash "replay    ./labkit check 02 --case 'segment_plane:1,-2.5,1e+300,inf'"
for name in crafted_inflight faked_inflight; do
  grep -qE "on input|segment_plane:4,5,6|touch /tmp" "$out/$name/report.txt" && fail "$name: its printed marker named a case"
done
# 3. The judge's report is out of the answerer's reach: whatever it puts where the report
# might be (a FIFO the grader would wait on, a link, a forged failure), the step keeps
# the judge's verdict.
for name in passing fifo_report symlink_report forged_report; do full_marks $name; done
# 5. One bad member costs only itself, and says why.
says bad_members 'not unpacked: ../segment_triangle.cpp has ".." in its path'
says bad_members "not unpacked: labs/01_frustum_split/frustum_split.cpp is a symbolic link"
says bad_members "not unpacked: labs/03_separating_axes/separating_axes.cpp is larger than 1 MB"
says bomb "not unpacked: labs/02_segment_triangle/segment_triangle.cpp unpacks to more than 1 MB"
says bad_members_tar "labs/01_frustum_split/frustum_split.cpp appears 2 times in the archive"
says bad_members_tar "/abs/labs/03_separating_axes/separating_axes.cpp has an absolute path"
says bad_members_tar "labs/04_bisection/bisection.cpp is a hard link"
says bad_members_tar "labs/05_sphere_sweeps/sphere_sweeps.cpp is not a regular file"
[ -e /tmp/escaped ] && { fail "a member with .. was unpacked"; rm -f /tmp/escaped; }
# 4. Each student their own folder: the one called labs too.
[ "$(wc -l <"$out/class.csv")" = "$(($(ls "$subs" | wc -l) + 1))" ] || fail "class.csv: one row per submission"
# No cell of class.csv is a formula: a name that starts like one starts with an apostrophe.
python3 - "$out/class.csv" <<'PY' || fail "class.csv: see above"
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="", encoding="utf-8")))
names = [r[0] for r in rows[1:]]
problems = [f"a formula cell: {c!r}" for r in rows for c in r if c[:1] in ("=", "+", "-", "@", "\t", "\r")]
# Names are folder names with every byte but letters, digits, '.', '_' and '-' made '_'
# (submission_name): '-' is the one formula start left.
if "'-2-2" not in names: problems.append(f"-2-2 is not shown as text ('-2-2): {names}")
if any(len(r) != len(rows[0]) for r in rows): problems.append("a row has another number of cells than the header")
print("\n".join(problems) or "class.csv: fine")
sys.exit(1 if problems else 0)
PY

# ---- the class page: where the class stands, in a browser from the folder -------------
# It parses as HTML with each section; every link stays in the results folder and finds
# its report; every submission has its row; each plot is an SVG beside the page (or, with
# no gnuplot, the page says how to get one); the crashes, floods and compile errors are
# listed (crashed calls among them, not among the concepts); two wrong answers breaking
# one rule on other numbers are one concept.
python3 - "$out" "$(command -v gnuplot || true)" >"$work/page.log" 2>&1 <<'PY' || { cat "$work/page.log"; fail "class.html: see above"; }
import html.parser, os, re, sys, urllib.parse
out, gnuplot = sys.argv[1], sys.argv[2]
text = open(os.path.join(out, "class.html"), encoding="utf-8").read()
class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.links, self.images, self.headings, self.rows, self.cell, self.cells = [], [], [], [], None, []
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "a": self.links.append(a["href"])
        if tag == "img": self.images.append(a["src"])
        if tag in ("h2", "td", "th"): self.cell = ""
        if tag == "script": raise SystemExit("the page has a script")
    def handle_data(self, data):
        if self.cell is not None: self.cell += data
    def handle_endtag(self, tag):
        if tag == "h2": self.headings.append(self.cell)
        if tag in ("td", "th"): self.cells.append(self.cell)
        if tag == "tr": self.rows.append(" | ".join(self.cells)); self.cells = []
        if tag in ("h2", "td", "th"): self.cell = None
page = Page()
page.feed(text)
problems = []
for heading in ["Totals", "Each step", "Concepts most often broken", "Crashed, timed out or not compiled", "Submissions"]:
    if heading not in page.headings: problems.append(f"no section '{heading}'")
root = os.path.realpath(out)
for href in page.links:
    target = os.path.realpath(os.path.join(out, urllib.parse.unquote(href)))
    if not target.startswith(root + os.sep) or not os.path.isfile(target): problems.append(f"link {href} finds no report")
linked = {urllib.parse.unquote(h).split("/")[0] for h in page.links}
for s in sorted(d for d in os.listdir(out) if os.path.isdir(os.path.join(out, d))):
    if s not in linked: problems.append(f"{s} has no row linked to its report")
if gnuplot:
    if len(page.images) != 2: problems.append(f"{len(page.images)} plots, expected 2 (totals, steps)")
    for src in page.images:
        svg = open(os.path.join(out, src), encoding="utf-8").read()
        if "<svg" not in svg or "</svg>" not in svg: problems.append(f"{src} is not an SVG")
elif "apt-get install gnuplot-nox" not in text: problems.append("no plots and no word on gnuplot")
def row_with(*words):
    return any(all(w in r for w in words) for r in page.rows)
for name, what in [("crafted_inflight", "too much output"), ("faked_inflight", "too much output"),
                   ("latin1_compile", "does not compile"), ("crash", "crashed during a call")]:
    if not row_with(name, what): problems.append(f"the trouble list has no '{what}' row for {name}")
if not any(r.startswith("2 | ") and "the answer is #, not #: the point is off its plane by # (tolerance #)" in r for r in page.rows):
    problems.append("the two wrong answers are not one concept of 2 submissions")
if any("your code crashed" in r and not r.startswith(("crash", "latin1_crash", "forged_output")) for r in page.rows):
    problems.append("a crash is listed among the concepts, not with the crashes")
count = len([d for d in os.listdir(out) if os.path.isdir(os.path.join(out, d))])
if f"<p>{count} submissions; mean" not in text: problems.append("the totals do not count every submission")
print("\n".join(problems) or "class page: fine")
sys.exit(1 if problems else 0)
PY

# ---- results.json as steps end: a run stopped midway keeps every finished step ---------
# The stand-in judge of step 4 never ends; once it starts, the grader is killed as a
# global time-out would. Steps 1 to 3 ran first (one worker) and keep their points.
stopping="$work/stopping_build"
stand_in_kit "$stopping"
marker="$work/step4.pid"
printf '#!/bin/sh\ncase "$1" in %s) echo $$ >"%s"; exec sleep 600 ;; esac\nexec "%s" "$@"\n' \
  "'[lab02][step4]'" "$marker" "$build/test_02_segment_triangle" >"$stopping/test_02_segment_triangle"
chmod 755 "$stopping/test_02_segment_triangle"
stopped_out="$work/stopped_results"
mkdir -p "$work/tmp"
TMPDIR="$work/tmp" LABKIT_BUILD_DIR="$stopping" "$runner" grade "$subs/passing" --out "$stopped_out" --seed "$secret" \
  --labs 02 --jobs 1 --timeout 900 --sandbox "$sandbox" >"$work/stopped.log" 2>&1 &
grader=$!
for ((k = 0; k < 1200; k++)); do [ -s "$marker" ] && break; sleep 0.1; done
kill -KILL $grader 2>/dev/null
wait $grader 2>/dev/null
[ -s "$marker" ] && kill -KILL "$(cat "$marker")" 2>/dev/null
python3 - "$stopped_out/results.json" <<'PY' || { cat "$work/stopped.log"; fail "results.json after a stop: see above"; }
import json, sys
r = json.load(open(sys.argv[1]))
steps = [t for t in r["tests"] if "max_score" in t]
problems = []
for t in steps[:3]:
    if t["score"] != t["max_score"]: problems.append(f"{t['name']}: {t['score']} of {t['max_score']}, expected full marks")
for t in steps[3:]:
    if t["score"] != 0 or "grading stopped before this step ran" not in t["output"]:
        problems.append(f"{t['name']}: not marked as not graded")
if abs(r["score"] - sum(t["max_score"] for t in steps[:3])) > 1e-9: problems.append(f"total {r['score']}")
print("\n".join(problems) or "stopped run: fine")
sys.exit(1 if problems else 0)
PY

# ---- a broken kit: reports the grader must survive -----------------------------------
# The student's code cannot reach the report, but a kit's bug can still spoil it: this
# kit's judge leaves another bad report at each step (JSON of other shapes or cut short,
# a FIFO the grader would wait on forever, a link, a crafted replay token, as a report or
# as the case a dying judge names). Each is no verdict, at once, and the token never a
# command.
broken="$work/broken_build"
stand_in_kit "$broken"
printf '%s' "$forged" >"$broken/forged.json"
cat >"$broken/test_02_segment_triangle" <<'EOF'
#!/bin/sh
case "$1" in
  '[lab02][step1]') printf '{"finished": true, "queries": 5}' >"$LABKIT_REPORT" ;;
  '[lab02][step2]') printf '{"finished": "yes"}' >"$LABKIT_REPORT" ;;
  '[lab02][step3]') printf '[1, 2, 3]' >"$LABKIT_REPORT" ;;
  '[lab02][step4]') printf '{"finished": true, "queries": [' >"$LABKIT_REPORT" ;;
  '[lab02][step5]') mkfifo "$LABKIT_REPORT" ;;
  '[lab02][step6]') ln -s /etc/passwd "$LABKIT_REPORT"; printf '%s' "segment_plane:1' ; touch /tmp/labkit-owned ; '" >"$LABKIT_INFLIGHT"; kill -KILL $$ ;;
  '[lab02][step7]') cat "$(dirname "$0")/forged.json" >"$LABKIT_REPORT" ;;
esac
EOF
chmod 755 "$broken/test_02_segment_triangle"
broken_out="$work/broken_results"
grade "$broken" "$subs/passing" --out "$broken_out" >"$work/broken.log" 2>&1
code=$?
[ $code -eq 0 ] || { cat "$work/broken.log"; fail "labkit grade on a broken kit exits $code (124: it hung)"; }
steps=$(awk -F'\t' 'NR > 1 { print $4 }' "$broken_out/steps.tsv" | paste -sd ,)
expected="exited early,exited early,exited early,exited early,exited early,crashed,failing"
# Lab 02's later steps (if the manifest has more than 7) write no report: exited early.
lab02_steps=$(awk '/"id": "02"/ { on = 1 } on && /"step":/ { n++ } on && /^ *\]/ { exit } END { print n }' "$kit/grading/manifest.json")
for ((k = 8; k <= lab02_steps; k++)); do expected+=",exited early"; done
[ "$steps" = "$expected" ] || fail "broken kit: the steps are '$steps', expected '$expected'"
grep -qF "replay    none (the case it reported is not a replay token the kit writes)" "$broken_out/report.txt" ||
  fail "broken kit: the crafted token is not refused"

# No crafted token became a replay command, and none ran.
if grep -rhoE "replay +\./labkit [^\\]*" "$out" "$broken_out" | grep touch; then fail "a crafted token became a replay command"; fi
[ -e "$owned" ] && fail "a crafted replay command ran"
# Every output is valid UTF-8 without a control character but newline and tab (and
# JSON, XML and the schema agree).
for file in "$out"/class.csv "$out"/class.html "$out"/*/* "$broken_out"/*; do
  iconv -f UTF-8 -t UTF-8 "$file" >/dev/null 2>&1 || fail "$file is not valid UTF-8"
  if LC_ALL=C grep -q $'[\x01-\x08\x0b-\x1f\x7f]' "$file"; then fail "$file holds a control character"; fi
done
"$schema_check" "$kit/grading/gradescope-results.schema.json" "$out"/*/results.json "$broken_out"/results.json "$stopped_out"/results.json >"$work/schema.log" ||
  { cat "$work/schema.log"; fail "a results.json does not match the schema"; }
python3 -c 'import sys, xml.etree.ElementTree as T
for f in sys.argv[1:]: T.parse(f)' "$out"/*/junit.xml "$broken_out"/junit.xml || fail "a junit.xml is not well-formed XML"
if grep -rqF "$secret" "$out" "$work/grade.log" "$broken_out" "$work/broken.log"; then fail "the secret seed appears in the results"; fi

# ---- each submission its own cases, never shown ----------------------------------------
# seeds_of NAME: the distinct seeds the judge was given for NAME's steps.
seeds_of() { awk -F'\t' -v n="$1" '$2 == n { print $1 }' "$build/seeds.log" | sort -u; }
seed_a=$(seeds_of seed_a)
seed_b=$(seeds_of seed_b)
[ -n "$seed_a" ] && [ "$(wc -l <<<"$seed_a")" = 1 ] || fail "seed_a: its steps were given the seeds '$seed_a', expected one"
[ -n "$seed_b" ] && [ "$seed_a" != "$seed_b" ] || fail "two submissions under one secret drew the same seed ($seed_a)"
# The same files again (a regrade, alone this time) draw the same seed; a changed file
# (a resubmission that special-cases a shown input) draws another.
cp -r "$subs/seed_a" "$work/seed_a_again"
grade "$build" "$work/seed_a_again" --out "$work/seed_again" >"$work/seed_again.log" 2>&1 || fail "the regrade of seed_a failed"
[ "$(seeds_of seed_a)" = "$seed_a" ] || fail "the same submission drew another seed on a regrade: $(seeds_of seed_a | paste -sd ' ')"
mkdir -p "$work/seed_a_changed/$(dirname $lab02)" && printf 'echo "ID seed_a_changed"\n' >"$work/seed_a_changed/$lab02"
grade "$build" "$work/seed_a_changed" --out "$work/seed_changed" >"$work/seed_changed.log" 2>&1 || fail "the resubmission failed"
seed_c=$(seeds_of seed_a_changed)
[ -n "$seed_c" ] && [ "$seed_c" != "$seed_a" ] || fail "a changed file drew the same seed ($seed_c)"
# No output holds the secret or a seed drawn from it; the report says how to regrade.
mapfile -t drawn < <(printf '%s\n' "$seed_a" "$seed_b" "$seed_c" "$secret")
for seed in "${drawn[@]}"; do
  [ -n "$seed" ] || continue
  if grep -rqF -- "$seed" "$out" "$work/grade.log" "$work/seed_again" "$work/seed_again.log" "$work/seed_changed" \
    "$work/seed_changed.log"; then fail "an output shows the secret or a seed drawn from it ($seed)"; fi
done
grep -qF "regrade: ./labkit grade <this submission> --seed <your secret>" "$work/seed_again/report.txt" ||
  fail "report.txt does not say how to regrade"
grep -qF "regrade: ./labkit grade <this submission> --seed <your secret>" "$work/seed_again/results.json" ||
  fail "results.json does not say how to regrade"

# ---- a submission's time budget: its compiles and steps together ----------------------
# This one compiles in 3 s, and every step of it sleeps 3 s in the code under test, well
# inside its own limit (20 s): with a budget of 8 s and one worker, the compile counts,
# the first step runs, the rest are not graded and say why, the report names what used
# the time, and the grader's own wall clock stays near the budget, not near 3 + 8 x 3 s.
mkdir -p "$work/sleeper/$(dirname $lab02)" && printf '#slow\nsleep 3\n' >"$work/sleeper/$lab02"
started=$(date +%s.%N)
LABKIT_BUILD_DIR="$build" timeout 300 "$runner" grade "$work/sleeper" --out "$work/sleeper_out" --seed "$secret" \
  --labs 02 --jobs 1 --timeout 20 --budget 8 --sandbox "$sandbox" >"$work/sleeper.log" 2>&1 || fail "grading the sleeper failed"
took=$(echo "$(date +%s.%N) - $started" | bc)
python3 - "$work/sleeper_out" "$took" <<'PY' || { cat "$work/sleeper.log"; fail "the time budget: see above"; }
import json, re, sys
out, took = sys.argv[1], float(sys.argv[2])
rows = [line.split("\t") for line in open(f"{out}/steps.tsv").read().splitlines()[1:]]
states = [r[3] for r in rows]
report = open(f"{out}/report.txt").read()
results = json.load(open(f"{out}/results.json"))
problems = []
if states[0] != "passed": problems.append(f"step 1 is '{states[0]}': the budget had room for it")
if "not graded: no time" not in states: problems.append(f"no step ran out of time: {states}")
first = states.index("not graded: no time") if "not graded: no time" in states else len(states)
if any(s != "not graded: no time" for s in states[first:]): problems.append(f"a step ran after the budget ran out: {states}")
used = re.search(r"time budget: ([0-9.]+) s of 8 s used; the submission's time budget ran out", report)
if not used: problems.append("report.txt does not say the budget ran out")
elif float(used.group(1)) > 8.5: problems.append(f"its processes took {used.group(1)} s of an 8 s budget")  # a stopped process ends a moment after its limit
if not re.search(r"what used it, the slowest first: lab 02 [0-9.]+ s \((step [0-9]|build) 3\.[0-9]* s, (step [0-9]|build) 3\.", report):
    problems.append("report.txt does not name the slowest steps and the compile, with their seconds")
if "not graded: the submission's time budget ran out" not in report: problems.append("no step says it was not graded")
if "Time: the submission's time budget ran out" not in results["output"]: problems.append("results.json does not say so")
if took > 8 + 10: problems.append(f"grading took {took:.1f} s for an 8 s budget")
print("\n".join(problems) or f"time budget: fine ({states.count('passed')} steps in {took:.1f} s)")
sys.exit(1 if problems else 0)
PY

# ---- report.txt's columns never touch ------------------------------------------------
# Lab 03's title is long, and a partial score ("11.47 / 15") is as wide as its column
# once was: every row of the table still splits, on two spaces or more, into its cells.
columns_build="$work/columns_build"
stand_in_kit "$columns_build"
cat >"$columns_build/test_02_segment_triangle" <<'EOF2'
#!/usr/bin/env python3
import json, os
failure = {"title": "random case 7 of 1000", "input": "in", "expected": "yes", "got": "no", "why": "w", "replay": "q:1",
           "shrinks": 0}
query = {"test_case": "t", "query": "q", "kind": "random", "cases": 1000, "passed": 791, "ambiguous": 0, "failed": 209,
         "trivial": 0, "trivial_passed": 0, "decisive": 1000, "decisive_passed": 791,
         "not_implemented": "", "error": "", "failure": failure, "notes": []}
with open(os.environ["LABKIT_REPORT"], "w") as f:
    json.dump({"seed": "hidden", "cases_per_query": 1000, "finished": True, "queries": [query],
               "test_cases": [{"name": "t", "tags": [], "passed": False, "ended": True, "failures": [],
                               "not_implemented": ""}]}, f)
EOF2
chmod 755 "$columns_build/test_02_segment_triangle"
cp "$columns_build/test_02_segment_triangle" "$columns_build/test_03_separating_axes"
mkdir -p "$work/columns/labs/03_separating_axes" "$work/columns/$(dirname $lab02)"
echo ': x' >"$work/columns/$lab02" && echo ': x' >"$work/columns/labs/03_separating_axes/separating_axes.cpp"
LABKIT_BUILD_DIR="$columns_build" timeout 300 "$runner" grade "$work/columns" --out "$work/columns_out" --seed "$secret" \
  --labs 02 03 --jobs 2 --timeout 20 --sandbox "$sandbox" >"$work/columns.log" 2>&1 || fail "grading the columns failed"
python3 - "$work/columns_out/report.txt" <<'PY' || fail "report.txt's columns: see above"
import re, sys
problems, rows = [], 0
for line in open(sys.argv[1], encoding="utf-8").read().split("\n"):
    cells = re.split(r" {2,}", line.strip())
    if re.match(r"  Lab \d\d  ", line):
        rows += 1
        if len(cells) != 4 or not re.fullmatch(r"\d+(\.\d+)? / \d+", cells[3]): problems.append(f"lab row {cells}")
    elif re.match(r"    \d+ +L\d\dS\d", line):
        rows += 1
        if len(cells) != 6 or not re.fullmatch(r"\d+(\.\d+)? / \d+", cells[4]) or not re.fullmatch(r"\d+\.\d{3} s", cells[5]):
            problems.append(f"step row {cells}")
    elif line.startswith("  Total"):
        rows += 1
        if len(cells) != 3 or not re.fullmatch(r"\d+(\.\d+)? / \d+", cells[1]): problems.append(f"total row {cells}")
text = open(sys.argv[1], encoding="utf-8").read()
if "Lab 03  Separating axes: oriented boxes, triangle pairs, moving boxes  " not in text: problems.append("lab 03's title is cut")
if "11.47 / 15  " not in text: problems.append("no partial score of 11.47 / 15")
if rows < 17: problems.append(f"{rows} table rows, expected 2 labs, 14 steps and the total")
print("\n".join(problems) or "report columns: fine")
sys.exit(1 if problems else 0)
PY

# ---- 4. names that cannot be told apart: nothing is graded --------------------------
# refused NAME WHAT...: grading the class folder NAME exits 2 at once, writes nothing,
# and its message names each WHAT.
refused() {
  local class="$work/$1" said code
  shift
  said=$(grade "$build" "$class" --out "$class.out" 2>&1)
  code=$?
  [ $code -eq 2 ] || fail "$(basename "$class"): exit $code, expected 2: $said"
  [ -e "$class.out" ] && fail "$(basename "$class"): results were written"
  for what in "$@"; do grep -qF -- "$what" <<<"$said" || fail "$(basename "$class"): the message does not name '$what': $said"; done
}
mkdir -p "$work/two_alices" && cp "$subs/bomb.zip" "$work/two_alices/alice.zip" && cp "$subs/bomb.zip" "$work/two_alices/alice-2.zip" &&
  cp "$subs/bad_members_tar.tar.gz" "$work/two_alices/alice.tar.gz"
refused two_alices "alice.zip" "alice.tar.gz"
mkdir -p "$work/class_file" && cp "$subs/bomb.zip" "$work/class_file/class.csv.zip" && cp "$subs/bomb.zip" "$work/class_file/bob.zip"
refused class_file "class.csv.zip"
mkdir -p "$work/labs_in_place/labs/02_segment_triangle" && echo ': x' >"$work/labs_in_place/$lab02" &&
  cp "$subs/bomb.zip" "$work/labs_in_place/bob.zip"
refused labs_in_place "labs/02_segment_triangle/segment_triangle.cpp" "bob.zip"

# ---- 5. one assignment: its steps, its total, its gradebook -------------------------
# An assignment (runner/assignment.h) narrows everything written to its steps, with its
# total; a wrong one, or a wrong roster, stops the grader before it grades anything.
assigned="$work/assigned"
core_steps=$(python3 -c 'import json, sys
lab = [l for l in json.load(open(sys.argv[1]))["labs"] if l["id"] == "02"][0]
print(" ".join(str(s["step"]) for s in lab["steps"] if s["tier"] == "core"),
      sum(s["points"] for s in lab["steps"] if s["tier"] == "core"))' "$kit/grading/manifest.json")
read -r -a core <<<"$core_steps"
core_points="${core[-1]}"
unset 'core[-1]'
grade "$build" "$subs/passing" --assignment 02:1,3 --out "$assigned/one" >"$work/assigned.log" 2>&1 ||
  fail "an assignment of steps 1 and 3: exit $? ($(tail -n 3 "$work/assigned.log"))"
python3 - "$assigned/one/results.json" <<'PY' || fail "an assignment's results.json: see above"
import json, sys
r = json.load(open(sys.argv[1]))
numbers = sorted(t["number"] for t in r["tests"] if "score" in t)
problems = []
if numbers != ["2.1", "2.3"]: problems.append(f"results.json has steps {numbers}, the assignment 02:1,3")
if not r["output"].startswith("Assignment: Lab 02, steps 1, 3\n"): problems.append("its output does not name the assignment first")
if r["score"] != sum(t["max_score"] for t in r["tests"] if "score" in t): problems.append(f"score {r['score']} is not its steps' total")
print("\n".join(problems) or "an assignment's results.json: fine")
sys.exit(1 if problems else 0)
PY
printf 'Student,ID,SIS User ID,submission\n"Pass, Ada",101,s101,passing\nNo Show,102,s102,absent\n' >"$work/roster.csv"
grade "$build" "$subs/passing" "$subs/crash" --assignment 02:core --roster "$work/roster.csv" --out "$assigned/class" \
  >"$work/assigned.log" 2>&1 || fail "a class graded on 02:core with a roster: exit $?"
steps=$(awk -F'\t' 'NR > 1 { printf "%s%s", sep, $2; sep = " " }' "$assigned/class/passing/steps.tsv")
[ "$steps" = "${core[*]}" ] || fail "02:core graded steps '$steps'; the manifest's core steps are '${core[*]}'"
expected_book=$(printf 'Student,ID,SIS User ID,"Lab 02, core steps"\n"Pass, Ada",101,s101,%s\nNo Show,102,s102,\n' "$core_points")
[ "$(cat "$assigned/class/gradebook.csv")" = "$expected_book" ] ||
  fail "gradebook.csv with a roster: got '$(cat "$assigned/class/gradebook.csv")', expected '$expected_book'"
grep -q 'submission "crash" .* is not on the roster' "$work/assigned.log" || fail "a submission off the roster is not named"
grep -q '(absent)' "$work/assigned.log" || fail "a roster student with no submission is not named"
grep -q '^lab02,' "$assigned/class/class.csv" && fail "class.csv has a row that is not a submission"
head -n 1 "$assigned/class/class.csv" | grep -qx 'submission,lab02,total,max' || fail "class.csv's columns: $(head -n 1 "$assigned/class/class.csv")"
grep -q "<h1>Class report: Lab 02, core steps</h1>" "$assigned/class/class.html" || fail "the class page does not name the assignment"
# A wrong assignment or roster: exit 2, the reason, nothing written.
printf 'Student,ID\nAda,101\n' >"$work/no_key.csv"
printf 'ID,submission\n1,ada\n2,ada\n' >"$work/twice.csv"
for wrong in "--assignment 02:99|step 99 of lab 02" "--assignment 99|lab '99'" "--assignment 02:core,1|'core' is none" \
             "--assignment 02:extra|'extra' is none" "--roster $work/no_key.csv|no \"submission\" column" \
             "--roster $work/twice.csv|two students" "--roster $work/missing.csv|cannot read the roster"; do
  read -r -a args <<<"${wrong%%|*}"
  said=$(grade "$build" "$subs/passing" "$subs/crash" "${args[@]}" --out "$assigned/wrong" 2>&1)
  code=$?
  [ $code -eq 2 ] || fail "${wrong%%|*}: exit $code, expected 2"
  grep -qF -- "${wrong#*|}" <<<"$said" || fail "${wrong%%|*}: the message does not say '${wrong#*|}': $said"
  [ -e "$assigned/wrong" ] && fail "${wrong%%|*}: results were written" && rm -rf "$assigned/wrong"
done
# Frozen for a package, and its GitHub Classroom workflow: a command grader per step,
# awarding the step's points when `./labkit check 02 --step K` passes, and the reporter.
"$runner" assignment 02:core --out "$assigned/frozen.json" --workflow "$assigned/classroom.yml" >/dev/null ||
  fail "the assignment 02:core cannot be frozen"
python3 - "$assigned/frozen.json" "$assigned/classroom.yml" "$kit/grading/manifest.json" <<'PY' || fail "frozen assignment or workflow: see above"
import json, re, sys
frozen, workflow = json.load(open(sys.argv[1])), open(sys.argv[2]).read()
lab = [l for l in json.load(open(sys.argv[3]))["labs"] if l["id"] == "02"][0]
core = [s for s in lab["steps"] if s["tier"] == "core"]
problems = []
if frozen["labs"] != [{"lab": "02", "steps": [s["step"] for s in core],
                       "points": {str(s["step"]): s["points"] for s in core}}]:
    problems.append(f"frozen: {frozen}")
graders = re.findall(r"command: (.*)\n +timeout: \d+\n +max-score: (\S+)", workflow)
if graders != [(f"./labkit check 02 --step {s['step']}", f"{s['points']:g}") for s in core]:
    problems.append(f"the workflow's graders: {graders}")
ids = ",".join(f"lab02-step{s['step']}" for s in core)
if f"runners: {ids}" not in workflow: problems.append("the reporter does not list every grader")
for s in core:
    if f'LAB02-STEP{s["step"]}_RESULTS: "${{{{steps.lab02-step{s["step"]}.outputs.result}}}}"' not in workflow:
        problems.append(f"the reporter has no result of step {s['step']}")
if "./labkit check 02 > check-02.txt || true" not in workflow or "GITHUB_STEP_SUMMARY" not in workflow:
    problems.append("the workflow does not put the step table in the run's summary")
print("\n".join(problems) or "frozen assignment and its workflow: fine")
sys.exit(1 if problems else 0)
PY

[ $failures -eq 0 ] && echo "grader input: every hostile output, name and archive cost only what it should, and no report was reached" || cat "$work/grade.log"
exit $((failures > 0))
