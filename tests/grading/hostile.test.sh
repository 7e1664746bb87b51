#!/usr/bin/env bash
# The hostile and broken submissions, each graded by ./labkit grade and compared with
# its expected result. Every submission is the reference of every lab, with one fault
# written into lab 02 (the faults live in its functions); lab 02 must keep every step the
# fault does not reach, and where the fault could reach further (see "grade them all"),
# every other lab its full marks.
#
#   hostile.test.sh RUNNER KIT_ROOT BUILD_DIR SCHEMA_CHECKER
#
# Takes a few minutes: every submission builds each lab (the kit is built already).
set -uo pipefail
runner="$1"
kit="$2"
build="$3"
schema_check="$4"
work="$(mktemp -d /tmp/labkit-hostile.XXXXXX)"
trap 'rm -rf "$work"' EXIT
subs="$work/submissions"
out="$work/results"
secret="hostile suite secret $$ $(date +%s%N)"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
mkdir -p "$subs"

lab02=labs/02_segment_triangle/segment_triangle.cpp
# The reference of every lab the kit has, at the paths students edit.
reference() {
  local into="$1" lab
  for lab in "$kit"/labs/[0-9][0-9]_*/; do
    lab="$(basename "$lab")"
    [ -d "$kit/solutions/$lab" ] || continue
    mkdir -p "$into/labs/$lab"
    cp "$kit/solutions/$lab"/*.cpp "$into/labs/$lab/"
  done
}
# inject NAME FUNCTION CODE: the reference, with CODE first in lab 02's FUNCTION.
inject() {
  local name="$1" function="$2" code="$3"
  reference "$subs/$name"
  awk -v f="$function" -v code="$code" '
    { print }
    !done && $0 ~ ("[ &*]" f "\\(.*\\) \\{$") { print code; done = 1 }
    END { if (!done) exit 1 }' "$kit/solutions/02_segment_triangle/segment_triangle.cpp" >"$subs/$name/$lab02" ||
    { echo "setup: no one-line definition of $function in lab 02's reference"; exit 1; }
  { printf '#include <csignal>\n#include <cstdio>\n#include <cstdlib>\n#include <vector>\n#include <unistd.h>\n'
    cat "$subs/$name/$lab02"; } >"$work/injected.cpp" && mv "$work/injected.cpp" "$subs/$name/$lab02"
}

# stub_with NAME CODE: every lab the reference, but lab 02 its stub, with CODE after it:
# a trick that would earn lab 02 points without writing it.
stub_with() {
  reference "$subs/$1"
  { printf '#include <cstdio>\n#include <cstdlib>\n#include <cstring>\n#include <string>\n#include <unistd.h>\n'
    cat "$kit/$lab02"; printf '%s\n' "$2"; } >"$subs/$1/$lab02"
}

# ---- the submissions --------------------------------------------------------------
reference "$work/ref" && (cd "$work/ref" && zip -qr "$subs/reference.zip" .)
mkdir -p "$subs/empty"
mkdir -p "$subs/stubs/labs" && cp -R "$kit"/labs/* "$subs/stubs/labs/" && find "$subs/stubs" -name '*.h' -delete
reference "$subs/compile_error" && echo 'this is not C++;' >>"$subs/compile_error/$lab02"
inject segfault point_in_triangle_barycentric '  { volatile int* nowhere = nullptr; *nowhere = 42; }'
inject endless_loop point_in_triangle_edges '  for (volatile unsigned spin = 0;; ++spin) {}'
inject allocate_50gb all_hits '  { std::vector<char> huge(std::size_t(50) << 30); huge[12345] = 1; }'
inject print_100mb segment_plane '  { static bool once = false; if (!once) { once = true; for (int i = 0; i < 1600000; ++i) std::puts("flooding the grader with sixty-four bytes of output per line........"); } }'
inject exit_0 any_hit '  std::exit(0);'
# An answer frame declaring 1 GiB, on every 100th call of a process: refused when its
# length is read, it costs the call it answered; it once ran the judge out of memory.
inject giant_frame any_hit '  { static int calls = 0; if (++calls % 100 == 0) {
    unsigned long long n = 1ull << 30; if (write(4, &n, sizeof n) < 0) {} for (;;) pause(); } }'
# Counts the checker keeps itself (README, "Given functions are counted by the checker"):
# lab 06 with a brute force over every triangle that `tests` leaves out, and balls tested
# by a formula of its own instead of the counted given_balls_meet. Before, a brute force
# that wound given::segment_triangle's count back scored 10/10 on the efficiency step.
lab06=labs/06_spatial_trees/spatial_trees.cpp
reference "$subs/forged_counts"
sed -e 's|^  best.tests = tests;$|  for (const Triangle\& t : tree.triangles) given::segment_triangle(segment, t);\n  best.tests = tests;|' \
  -e 's|if (given_balls_meet(sorted\[m\], sorted\[other\]))|if ((sorted[m].center - sorted[other].center).norm() <= sorted[m].radius + sorted[other].radius)|' \
  "$kit/solutions/06_spatial_trees/spatial_trees.cpp" >"$subs/forged_counts/$lab06"
grep -q "t : tree.triangles) given::segment_triangle" "$subs/forged_counts/$lab06" &&
  grep -q ".norm() <= sorted" "$subs/forged_counts/$lab06" || { echo "setup: lab 06's reference changed"; exit 1; }
# Every function its default answer (no hit, false, zeros): a file that does nothing.
reference "$subs/defaults" && sed -E 's/not_implemented\([^;]*\);/return {};/' "$kit/$lab02" >"$subs/defaults/$lab02"
# Writing outside its folder: the kit's tree, /tmp, the grader's folders, the home
# folder (the suite then checks that none of those files exists); reading the reference
# or the kit's git history (the step aborts if it can, and this suite fails); signalling
# every process it can. None of it works, so the step passes as usual.
inject escape test_segment_triangle '  { static bool tried = false; if (!tried) { tried = true; bool escaped = false;
    for (const char* path : {"KIT/HOSTILE_WAS_HERE", "/tmp/labkit-hostile-was-here", "../../../hostile-was-here", "../hostile-was-here", "/root/.labkit-hostile"})
      if (FILE* f = std::fopen(path, "w")) { std::fputs("escaped", f); std::fclose(f); }
    for (const char* path : {"KIT/solutions/02_segment_triangle/segment_triangle.cpp", "KIT/.git/HEAD"})
      if (FILE* f = std::fopen(path, "r")) { std::fclose(f); escaped = true; }
    kill(-1, SIGKILL);
    if (escaped) std::abort(); } }'
sed -i "s|KIT/|$kit/|g" "$subs/escape/$lab02"
# Stealing the secret seed before the tests start: the environment, the seed file, this
# process's and the sandbox's and the grader's command lines and environments. If it
# finds the secret, or can open the seed file at all (it holds this submission's own
# seed, drawn from the secret: runner/seed.h), segment_plane aborts (and this suite fails).
inject steal_seed segment_plane '  if (stolen) std::abort();'
{ printf '#include <cstdio>\n#include <cstdlib>\n#include <cstring>\n#include <string>\n#include <unistd.h>\nnamespace {\nbool seed_stolen() {\n'
  printf '  const char* marker = "hostile suite secret";\n'
  printf '  auto holds = [&](const char* path) { std::FILE* f = std::fopen(path, "rb"); if (!f) return false; std::string text; char b[4096]; std::size_t n;\n'
  printf '    while ((n = std::fread(b, 1, sizeof b, f)) > 0) text.append(b, n); std::fclose(f); return text.find(marker) != std::string::npos; };\n'
  printf '  if (const char* v = std::getenv("LABKIT_SEED")) if (std::strstr(v, marker)) return true;\n'
  printf '  if (const char* v = std::getenv("LABKIT_SEED_FILE")) if (std::FILE* f = std::fopen(v, "rb")) { std::fclose(f); return true; }\n'
  printf '  for (const char* p : {"/proc/self/environ", "/proc/self/cmdline", "/proc/1/environ", "/proc/1/cmdline"}) if (holds(p)) return true;\n'
  printf '  for (int pid : {int(getppid()), 2, 3}) for (const char* what : {"cmdline", "environ"}) {\n'
  printf '    char path[64]; std::snprintf(path, sizeof path, "/proc/%%d/%%s", pid, what); if (holds(path)) return true; }\n'
  printf '  return false;\n}\nconst bool stolen = seed_stolen();\n}  // namespace\n'
  cat "$subs/steal_seed/$lab02"; } >"$work/stolen.cpp" && mv "$work/stolen.cpp" "$subs/steal_seed/$lab02"
# Code that would run before the harness reads its settings.
reference "$subs/early_constructor" &&
  printf '#include <cstdlib>\nvolatile bool early;\n__attribute__((constructor(101))) static void first() { early = std::getenv("LABKIT_SEED_FILE"); }\n' \
    >>"$subs/early_constructor/$lab02"
# Extra files that try to replace the tests, a header, the harness, the build and the points.
mkdir -p "$work/extra" && reference "$work/extra"
mkdir -p "$work/extra/tests/02_segment_triangle" "$work/extra/common/harness" "$work/extra/grading"
echo '#error "the submission replaced the header"' >"$work/extra/labs/02_segment_triangle/segment_triangle.h"
echo '#error "the submission replaced the tests"' >"$work/extra/tests/02_segment_triangle/test.cpp"
echo '#error "the submission replaced the harness"' >"$work/extra/common/harness/check.h"
echo 'message(FATAL_ERROR "the submission replaced the build")' >"$work/extra/CMakeLists.txt"
sed 's/"points": [0-9]*/"points": 1000/' "$kit/grading/manifest.json" >"$work/extra/grading/manifest.json"
(cd "$work/extra" && tar -czf "$subs/extra_files.tar.gz" .)
# A symlink to the reference on the grader's disk, and an #include of it.
reference "$subs/symlink" && rm "$subs/symlink/$lab02" && ln -s "$kit/solutions/02_segment_triangle/segment_triangle.cpp" "$subs/symlink/$lab02"
reference "$subs/include_reference"
echo "#include \"$kit/solutions/02_segment_triangle/segment_triangle.cpp\"" >"$subs/include_reference/$lab02"
# Its own main(), which would write a perfect report, and a call into the oracle.
reference "$subs/own_main" && printf 'int main() { return 0; }\n' >>"$subs/own_main/$lab02"
# Partial credit: a classic mistake in a step with partial credit, and in one without.
reference "$subs/partial" && cp "$build/mutants/02_segment_triangle/beta_sign.cpp" "$subs/partial/$lab02"
reference "$subs/all_or_nothing" && cp "$build/mutants/02_segment_triangle/crossing_t_sign.cpp" "$subs/all_or_nothing/$lab02"

# Untrusted text (feedback must stay valid UTF-8 and show terminal controls as text):
# accented output, a Latin-1 byte and escapes, then a crash (the kept tail starts in the
# middle of a character); a Latin-1 byte and escapes in a compile error.
inject latin1_crash segment_plane '  { static bool once = false; if (!once) { once = true; for (int i = 0; i < 700; ++i) std::fputs("\\xc3\\xa9", stdout);
    std::fputs("\\nr\\xc3\\xa9sultat \\xe9 \\x1b[2J\\x1b]0;owned\\x07\\n", stdout); std::fflush(stdout); volatile int* nowhere = nullptr; *nowhere = 1; } }'
reference "$subs/latin1_compile" && printf '#error caf\351 \033[2J\033]0;owned\007\n' >>"$subs/latin1_compile/$lab02"
# What the code under test leaves in place of its report, after the harness wrote it (a
# static object's destructor runs last): a FIFO (the grader, as root, once blocked in
# open() on it forever), a symlink, JSON of the wrong shape, a crafted replay token.
after_the_report() {
  reference "$subs/$1"
  printf '#include <cstdio>\n#include <cstdlib>\n#include <sys/stat.h>\n#include <unistd.h>\nnamespace {\nstruct LastWord {\n  ~LastWord() {\n    const char* report = std::getenv("LABKIT_REPORT");\n    if (!report) return;\n    %s\n  }\n} last_word;\n}  // namespace\n' "$2" \
    >>"$subs/$1/$lab02"
}
after_the_report fifo_report 'std::remove(report); mkfifo(report, 0600);'
after_the_report symlink_report 'std::remove(report); symlink("/etc/passwd", report);'
write_report() { printf 'if (std::FILE* f = std::fopen(report, "w")) { std::fputs(R"(%s)", f); std::fclose(f); }' "$1"; }
after_the_report queries_5 "$(write_report '{"finished": true, "queries": 5}')"
after_the_report finished_yes "$(write_report '{"finished": "yes"}')"
after_the_report crafted_token "$(write_report '{"finished": true, "queries": [{"query": "segment_plane", "kind": "random", "cases": 1, "failed": 1, "failure": {"title": "t", "input": "i", "expected": "e", "got": "g", "why": "w", "replay": "segment_plane:1'"'"' ; touch /tmp/labkit-hostile-owned ; '"'"'"}}]}')"
# A crafted in-flight marker as the last thing printed, then an early exit.
inject crafted_inflight segment_plane '  { std::puts("LABKIT-INFLIGHT segment_plane:1'"'"' ; touch /tmp/labkit-hostile-owned ; '"'"'"); std::fflush(stdout); _exit(3); }'
# A student's folder that is merely named labs (files uploaded one by one): a class
# member like any other, not a sign that the whole class is one submission.
mkdir -p "$subs/labs" && cp "$kit"/solutions/[0-9][0-9]_*/*.cpp "$subs/labs/"
# Archives where one member is bad: the rest is graded, the feedback says why.
latin1="$(printf 'caf\351')"
mkdir -p "$work/members/$latin1" "$work/members/XX" "$work/members/links" && reference "$work/members/$latin1"
echo 'the escape' >"$work/members/XX/segment_triangle.cpp"
ln -s /etc/passwd "$work/members/links/frustum_split.cpp"
ln -s /etc/passwd "$work/members/$(printf 'esc\033[2J\nape')"
head -c 5M /dev/zero >"$work/members/links/particles.cpp"
(cd "$work/members" && zip -qry "$subs/bad_members.zip" . && LC_ALL=C sed -i 's|XX/segment|../segment|g' "$subs/bad_members.zip")
(cd "$work/members" && tar -czf "$subs/bad_members_tar.tar.gz" -P --transform 's,^\./XX/,/abs/,;s,^\./links/particles,../particles,' .)
# A zip bomb that lies: lab 02's file, first in the zip, declares 10 bytes and unpacks to
# 3 MB; every other lab is the reference.
mkdir -p "$work/bomb/$(dirname "$lab02")" && head -c 3M /dev/zero >"$work/bomb/$lab02"
reference "$work/bomb-rest" && rm "$work/bomb-rest/$lab02"
(cd "$work/bomb" && zip -q "$subs/bomb.zip" "$lab02") && (cd "$work/bomb-rest" && zip -qr "$subs/bomb.zip" labs)
size=$(stat -c %s "$subs/bomb.zip")
first=$(od -An -tu4 -j $((size - 6)) -N4 "$subs/bomb.zip" | tr -d ' ')  # the central directory's first entry
for at in 22 $((first + 24)); do printf '\x0a\x00\x00\x00' | dd of="$subs/bomb.zip" bs=1 seek=$at conv=notrunc status=none; done

# The red team's tricks, each of which once earned points: the student's code no longer
# shares a process with the tests, the judges, the oracle or the report.
# A static initialiser that writes a passing report wherever a report could be, then exits.
stub_with forge_report '#include <glob.h>
namespace { struct Forge { Forge() {
  const char* passed = "{\"finished\": true, \"test_cases\": [], \"queries\": []}";
  std::string paths[64]; int n = 0;
  if (const char* p = std::getenv("LABKIT_REPORT")) paths[n++] = p;
  for (const char* pattern : {"/tmp/labkit-*/report.json", "../labkit-step.*/report.json", "../../*/labkit-step.*/report.json"}) {
    glob_t g; if (glob(pattern, 0, nullptr, &g) == 0) for (std::size_t i = 0; i < g.gl_pathc && n < 64; ++i) paths[n++] = g.gl_pathv[i]; }
  for (int i = 0; i < n; ++i) if (std::FILE* f = std::fopen(paths[i].c_str(), "w")) { std::fputs(passed, f); std::fclose(f); }
  std::exit(0); } } forge; }'
# A weak rename() (the symbol audit refused only strong definitions) that would swap in a
# passing report whenever the harness saved one.
stub_with weak_rename 'extern "C" __attribute__((weak)) int rename(const char*, const char* to) {
  if (std::FILE* f = std::fopen(to, "w")) { std::fputs("{\"finished\": true, \"test_cases\": [], \"queries\": []}", f); std::fclose(f); }
  return 0; }'
# The exact oracle by its mangled name in its own binary (/proc/self/exe); dlsym, the other
# way to look, is refused at the build (load_gmp). If it is there, segment_plane aborts
# (and this suite fails).
inject oracle_by_name segment_plane '  if (oracle_reachable()) std::abort();'
{ printf '#include <fstream>\n#include <iterator>\n#include <string>\nnamespace {\nbool oracle_reachable() {\n'
  printf '  static const bool found = [] { std::ifstream exe("/proc/self/exe", std::ios::binary);\n'
  printf '    const std::string bytes((std::istreambuf_iterator<char>(exe)), std::istreambuf_iterator<char>());\n'
  printf '    const std::string name = std::string("6labkit6") + "oracle";  // built at run time: not in the binary itself\n'
  printf '    return bytes.find(name) != std::string::npos; }();\n'
  printf '  return found;\n}\n}  // namespace\n'
  cat "$subs/oracle_by_name/$lab02"; } >"$work/oracle.cpp" && mv "$work/oracle.cpp" "$subs/oracle_by_name/$lab02"
# A .preinit_array function (runs before any initialiser; the audit refused only numbered
# .init_array sections) that looks for the seed file and the secret and prints what it
# finds, hex-encoded (redaction matched only the plain text); opening the seed file at
# all counts as finding the seed (it holds the submission's own, runner/seed.h).
inject preinit_seed segment_plane '  if (seed_found) std::abort();'
{ printf '#include <cstdio>\n#include <cstdlib>\n#include <fstream>\n#include <iterator>\n#include <string>\nnamespace {\nbool seed_found = false;\n'
  printf 'void look(int, char**, char** env) {\n  std::string seen;\n'
  printf '  for (char** e = env; e && *e; ++e) seen += std::string(*e) + "\\n";\n'
  printf '  bool opened = false;\n'
  printf '  if (const char* p = std::getenv("LABKIT_SEED_FILE")) { std::ifstream f(p); opened = bool(f); seen += std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>()); }\n'
  printf '  for (const char* p : {"/proc/self/environ", "/proc/1/environ"}) { std::ifstream f(p); seen += std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>()); }\n'
  printf '  for (unsigned char c : seen) std::printf("%%02x", c);\n  std::printf("\\n");\n'
  printf '  seed_found = opened || seen.find("hostile suite secret") != std::string::npos;\n}\n'
  printf '__attribute__((section(".preinit_array"), used)) void (*early_look)(int, char**, char**) = look;\n}  // namespace\n'
  cat "$subs/preinit_seed/$lab02"; } >"$work/preinit.cpp" && mv "$work/preinit.cpp" "$subs/preinit_seed/$lab02"
# The kit's own programs: the reference's answer program (exec it, and lab 02 would be the
# reference's), the kit's test program and the reference libraries. Lab 02 is the stub:
# any point it earns is a hole.
stub_with kit_programs "namespace { struct Borrow { Borrow() {
  for (const char* program : {\"$build/answer_02_segment_triangle_reference\", \"$kit/build/answer_02_segment_triangle_reference\"}) {
    char* argv[] = {const_cast<char*>(program), nullptr};
    execv(program, argv); } } } borrow; }"

# The kit's own sources and the libraries the oracle is built on: a lab file may include
# only its lab's header, the geometry types, Eigen and the standard library. The oracle's
# .cpp under another namespace name, with GMP off so that CGAL falls back on header-only
# arithmetic, and thin wrappers, once scored 87 of 100 with no geometry of its own.
reference "$subs/include_oracle"
{ printf '#define CGAL_DISABLE_GMP 1\n#define CGAL_NO_GMP 1\n#define oracle borrowed\n#include "common/oracle/segment_triangle.cpp"\n#undef oracle\n'
  cat "$kit/solutions/02_segment_triangle/segment_triangle.cpp"; } >"$subs/include_oracle/$lab02"
reference "$subs/include_cgal"
{ printf '#include <CGAL/Simple_cartesian.h>\n'; cat "$kit/solutions/02_segment_triangle/segment_triangle.cpp"; } \
  >"$subs/include_cgal/$lab02"
reference "$subs/include_numbers"
{ printf '#include <vector>\n#include <gmp.h>\n#include <mpfr.h>\n#include <boost/multiprecision/cpp_int.hpp>\n'
  printf '#include <dlfcn.h>\n'  # the loader, that would bring them in at run time
  cat "$kit/solutions/02_segment_triangle/segment_triangle.cpp"; } >"$subs/include_numbers/$lab02"
# Lab 06's ready segment-triangle test, borrowed for lab 02 (whose point is to write one):
# included (its header is not lab 02's), or declared by hand and linked.
reference "$subs/include_given"
{ printf '#include "common/given/segment_triangle.h"\n'; cat "$kit/solutions/02_segment_triangle/segment_triangle.cpp"; } \
  >"$subs/include_given/$lab02"
# Exact arithmetic loaded at run time, the loader declared by hand (its header is
# refused): the symbol audit refuses the call.
reference "$subs/load_gmp"
{ printf 'extern "C" void* dlopen(const char*, int);\n'
  printf 'void* gmp_loaded = dlopen("libgmp.so.10", 2);\n'
  cat "$kit/solutions/02_segment_triangle/segment_triangle.cpp"; } >"$subs/load_gmp/$lab02"
reference "$subs/declare_given"
{ printf 'namespace labkit { struct Segment; struct Triangle; namespace given { struct SegmentHit;\n'
  printf 'SegmentHit segment_triangle(const Segment&, const Triangle&); } }\n'
  printf 'void* borrowed = (void*)&labkit::given::segment_triangle;\n'
  cat "$kit/solutions/02_segment_triangle/segment_triangle.cpp"; } >"$subs/declare_given/$lab02"
# Descriptors the grader inherited (the suite grades with two open: 7 reads a file, 8
# writes one): the code under test tries every descriptor from 5 to 20 (3 and 4 are its
# protocol's pipes). If any is open, segment_plane aborts (and this suite fails); what it
# writes would land in $work/inherited.txt, which must stay empty.
inject inherited_fds segment_plane '  { static bool tried = false, open = false; if (!tried) { tried = true;
    for (int fd = 5; fd <= 20; ++fd) { char b[64]; if (read(fd, b, sizeof b) > 0) open = true;
      if (write(fd, "leaked\\n", 7) > 0) open = true; } }
    if (open) std::abort(); }'
: >"$work/inherited.txt"
nothing_written() {
  [ -s "$work/inherited.txt" ] && { fail "$1: the graded code wrote into a descriptor the grader inherited"; : >"$work/inherited.txt"; }
  return 0
}
# UDP, which Landlock cannot refuse: a datagram to a port this suite listens on, at
# 127.0.0.1 and at this machine's outside address, and one to an address outside it. The
# suite checks that nothing arrived; the code gets an error, and the grade is the same.
udp_port=$((20000 + RANDOM % 20000))
outside="$(hostname -I 2>/dev/null | awk '{ print $1 }')"
inject udp_out segment_plane '  { static bool tried = false; if (!tried) { tried = true;
    for (const char* to : {"127.0.0.1", "OUTSIDE", "192.0.2.77"}) {
      int s = socket(AF_INET, SOCK_DGRAM, 0); if (s < 0) continue;
      sockaddr_in a{}; a.sin_family = AF_INET; a.sin_port = htons(PORT); inet_pton(AF_INET, to, &a.sin_addr);
      sendto(s, "escaped", 7, 0, reinterpret_cast<sockaddr*>(&a), sizeof a); close(s); } } }'
sed -i "s|OUTSIDE|${outside:-127.0.0.1}|; s|htons(PORT)|htons($udp_port)|" "$subs/udp_out/$lab02"
{ printf '#include <arpa/inet.h>\n#include <netinet/in.h>\n#include <sys/socket.h>\n'; cat "$subs/udp_out/$lab02"; } >"$work/udp.cpp" &&
  mv "$work/udp.cpp" "$subs/udp_out/$lab02"
listener=""
if command -v python3 >/dev/null; then
  python3 -c 'import socket, sys
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("0.0.0.0", int(sys.argv[1])))
with open(sys.argv[2], "ab", buffering=0) as f:
    while True: f.write(s.recvfrom(65536)[0] + b"\n")' "$udp_port" "$work/udp-received.txt" &
  listener=$!
  trap 'kill "$listener" 2>/dev/null; rm -rf "$work"' EXIT
else
  echo "no python3: the UDP datagrams are sent but not listened for"
fi
nothing_received() {
  [ -s "$work/udp-received.txt" ] && { fail "$1: a UDP datagram reached this machine: $(head -c 200 "$work/udp-received.txt")"; : >"$work/udp-received.txt"; }
  return 0
}
# expect_refused NAME HEADER...: lab 02 does not compile, and its feedback states the
# include rule and names each header.
expect_refused() {
  local name="$1" report="$out/$1/report.txt"
  shift
  expect "$name" "does not compile"
  grep -q "may include only its lab's header, the geometry types, Eigen and the standard library" "$report" ||
    fail "$name: the feedback does not state the include rule"
  for header in "$@"; do grep -qF -- "$header" "$report" || fail "$name: the feedback does not name $header"; done
}

# ---- a machine that can confine nothing ---------------------------------------------
# Neither bubblewrap nor Landlock: grading a kit that holds solutions/ is refused (the
# graded code could read the reference), with what to do instead. That refusal is the
# one promise to check here.
if ! said=$("$runner" grade "$subs/empty" --out "$work/probe" --labs 02 2>&1) && grep -q "nothing can confine" <<<"$said"; then
  grep -q "Gradescope package" <<<"$said" || fail "the refusal does not say what to do instead: $said"
  echo "nothing can confine graded code on this machine: grading this kit is refused, as it must be"
  exit $((failures > 0))
fi

# ---- grade them all at once -------------------------------------------------------
# Every lab of a submission whose fault could reach past its own lab (a crash, memory, a
# flood of output, a kill(-1), files that replace the kit's, a bad archive, an empty or
# stubbed class member): the other labs must keep the reference's grade. A fault that
# stays in lab 02's own process and build (a trick on its report, its includes, its
# seed) is graded on lab 02 alone, in $subs02: grading the six untouched labs again for
# each of those would check nothing new and cost half of this suite's time.
subs02="$work/lab02-only"
mkdir -p "$subs02"
for name in compile_error include_reference own_main early_constructor steal_seed symlink exit_0 defaults \
  all_or_nothing latin1_crash latin1_compile fifo_report symlink_report queries_5 finished_yes crafted_token \
  crafted_inflight forge_report weak_rename kit_programs oracle_by_name preinit_seed include_oracle include_cgal \
  include_given load_gmp declare_given include_numbers inherited_fds udp_out endless_loop; do
  mv "$subs/$name" "$subs02/"
done
# A submission by name, wherever it is graded from.
sub() { if [ -e "$subs/$1" ]; then echo "$subs/$1"; else echo "$subs02/$1"; fi; }
# The endless loop on its own, with a short time limit; the others with a generous one,
# so that a loaded machine never turns a slow step into a time-out (lab 06's big meshes
# once ran past 8 s on a busy CI machine).
mkdir -p "$work/loop" && mv "$subs02/endless_loop" "$work/loop/"
started=$(date +%s)
# Two descriptors left open, as an instructor's script or a CI runner might leave them.
"$runner" grade "$subs" --out "$out" --seed "$secret" --cases 300 --timeout 120 --jobs 2 >"$work/grade.log" 2>&1 \
  7<"$kit/README.md" 8>>"$work/inherited.txt"
code=$?
"$runner" grade "$subs02" --out "$work/results02" --seed "$secret" --cases 300 --timeout 120 --jobs 2 --labs 02 \
  >>"$work/grade.log" 2>&1 7<"$kit/README.md" 8>>"$work/inherited.txt" || code=$?
"$runner" grade "$work/loop/endless_loop" --out "$out/endless_loop" --seed "$secret" --cases 100 --timeout 8 --jobs 2 --labs 02 \
  >>"$work/grade.log" 2>&1 || code=$?
mv "$work/loop/endless_loop" "$subs02/"
echo "graded $(ls "$subs" | wc -l) submissions on every lab and $(ls "$subs02" | wc -l) on lab 02 alone" \
  "in $(($(date +%s) - started)) s (exit $code)"
# One folder of results, as the checks below read them; each run's class page stays its own.
for result in "$work/results02"/*/; do mv "$result" "$out/"; done
[ $code -eq 0 ] || { cat "$work/grade.log"; fail "labkit grade exits $code"; }

# A kit the graded code cannot read (run as root, it runs under an unprivileged uid; here
# the build folder sits behind a folder closed to others): grading stops at once and says
# why, instead of failing every lab of every student as "does not compile".
if [ "$(id -u)" = 0 ]; then
  mkdir -m 700 "$work/closed" && ln -s "$build" "$work/closed/build"
  said=$(LABKIT_BUILD_DIR="$work/closed/build" "$runner" grade "$subs/reference.zip" --out "$work/closed-out" \
    --seed "$secret" 2>&1)
  closed_code=$?
  { [ $closed_code -eq 2 ] && grep -q "closed to other users" <<<"$said"; } ||
    fail "a kit closed to other users: exit $closed_code, and it said: $said"
fi

# expect NAME LAB02 [STEP=STATUS ...]: lab 02 (or $faulty_lab, when set) as LAB02 says
# (graded: each STEP has that status and 0 points, or with STATUS* fewer points than the
# step's, any; or "does not compile", "not submitted" for all of it); every other row
# (each step of every other lab, each step of lab 02 the fault does not reach) exactly as
# the reference's own grade has it: same status, same points.
expect() {
  local name="$1" state="$2"
  shift 2
  local tsv="$out/$name/steps.tsv"
  [ -f "$tsv" ] || { fail "$name: no results"; return; }
  local lab step tag status score max want faulty
  while IFS=$'\t' read -r lab step tag status score max _; do
    [ "$lab" = lab ] && continue
    faulty=""
    if [ "$lab" = "${faulty_lab:-02}" ]; then
      [ "$state" = graded ] || faulty="$state"
      for rule in "$@"; do [ "${rule%%=*}" = "$step" ] && faulty="${rule#*=}"; done
    fi
    if [ -n "$faulty" ] && [ "${faulty%\*}" != "$faulty" ]; then
      [ "$status" = "${faulty%\*}" ] || fail "$name: lab $lab step $step is '$status', expected '${faulty%\*}'"
      awk -v s="$score" -v m="$max" 'BEGIN { exit !(s < m) }' || fail "$name: lab $lab step $step scores $score of $max"
    elif [ -n "$faulty" ]; then
      [ "$status" = "$faulty" ] || fail "$name: lab $lab step $step is '$status', expected '$faulty'"
      [ "$score" = 0 ] || fail "$name: lab $lab step $step scores $score, expected 0"
    else
      want="$(awk -F'\t' -v l="$lab" -v s="$step" '$1 == l && $2 == s { print $4 "\t" $5 }' "$out/reference/steps.tsv")"
      [ "$status"$'\t'"$score" = "$want" ] ||
        fail "$name: lab $lab step $step is '$status' with $score points; without the fault: '${want/$'\t'/' with '} points"
    fi
  done <"$tsv"
}
# The reference itself: every step passed, full points.
awk -F'\t' 'NR > 1 && ($4 != "passed" || $5 != $6) { print "FAIL: reference: lab " $1 " step " $2 " is " $4 " with " $5 " of " $6; bad = 1 }
            END { exit bad }' "$out/reference/steps.tsv" || failures=$((failures + 1))
expect reference graded
expect extra_files graded
expect escape graded
expect compile_error "does not compile"
expect include_reference "does not compile"
expect own_main "does not compile"
expect early_constructor "does not compile"
expect steal_seed graded
expect symlink "not submitted"
# A fault costs the cases that reach the function it is in (the reference calls some of
# its functions from others): a crash or a time-out costs its case, not its step, so a
# step with partial credit keeps the points of its other queries.
# point_in_triangle_barycentric is steps 3 and 8's, point_in_triangle_edges steps 2 and
# 8's, all_hits steps 5 and 8's, segment_plane step 1's, any_hit step 5's (step 8 is a
# robustness step; steps 7 and 9, two moving meshes, call none of them).
expect segfault graded 3="failing*" 8="failing*"
expect endless_loop graded 2=failing 8="failing*"
expect allocate_50gb graded 5="failing*" 8="failing*"
expect print_100mb graded 1="too much output"
expect exit_0 graded 5="failing*"
expect giant_frame graded 5="failing*"
faulty_lab=06 expect forged_counts graded 2="failing*" 5=failing 8=failing 9="failing*" 10="failing*"
expect defaults graded 1=failing 2=failing 3=failing 4=failing 5=failing 6=failing 7=failing 8=failing 9=failing
grep -q "more than any answer to this call can hold" "$out/giant_frame/report.txt" ||
  fail "giant_frame: the report does not say the answer was larger than any answer to its call"
expect all_or_nothing graded 1=failing
expect latin1_crash graded 1=failing
expect latin1_compile "does not compile"
# The code under test has no report to replace (it never knows where the judge's is).
expect fifo_report graded
expect symlink_report graded
expect queries_5 graded
expect finished_yes graded
expect crafted_token graded
expect crafted_inflight graded 1=failing
# The red team's tricks: no point for a stub, nothing reached.
for name in forge_report weak_rename kit_programs; do
  awk -F'\t' -v n="$name" 'NR > 1 && $1 == "02" && $5 != "0" { print "FAIL: " n ": lab 02 step " $2 " scores " $5; bad = 1 }
    END { exit bad }' "$out/$name/steps.tsv" || failures=$((failures + 1))
done
# Code that dies before main fails every input, and so every smaller input: shrinking
# its failure must stop within its budget, not run the step into its time limit (lab 02
# step 7's two meshes once took the whole 120 s).
awk -F'\t' 'NR > 1 && $1 == "02" && $4 != "failing" { print "FAIL: forge_report: lab 02 step " $2 " is " $4 ", not failing"; bad = 1 }
  END { exit bad }' "$out/forge_report/steps.tsv" || failures=$((failures + 1))
expect oracle_by_name graded
expect preinit_seed graded
expect_refused include_oracle '"common/oracle/segment_triangle.cpp" (line 4)'
expect_refused include_cgal '<CGAL/Simple_cartesian.h> (line 1)'
expect_refused include_given '"common/given/segment_triangle.h" (line 1)'
expect load_gmp "does not compile"
grep -q "loads no library at run time" "$out/load_gmp/report.txt" ||
  fail "load_gmp: the feedback does not say a lab's file loads no library"
expect declare_given "does not compile"
grep -q "a given tool of other labs" "$out/declare_given/report.txt" ||
  fail "declare_given: the feedback does not say the given tool is not this lab's"
expect_refused include_numbers '<gmp.h> (line 2)' '<mpfr.h> (line 3)' '<boost/multiprecision/cpp_int.hpp> (line 4)' '<dlfcn.h> (line 5)'
expect inherited_fds graded
nothing_written "sandbox $(grep -o 'sandbox: [A-Za-z]*' "$out/reference/report.txt" | head -n 1)"
expect udp_out graded
nothing_received "sandbox $(grep -o 'sandbox: [A-Za-z]*' "$out/reference/report.txt" | head -n 1)"
expect labs graded
expect bad_members graded
expect bad_members_tar graded
expect bomb "not submitted"
# Empty and stubs: nothing to give points to, in any lab.
for name in empty stubs; do
  awk -F'\t' -v n="$name" 'NR > 1 && $5 != "0" { print "FAIL: " n ": lab " $1 " step " $2 " scores " $5; bad = 1 } END { exit bad }' \
    "$out/$name/steps.tsv" || failures=$((failures + 1))
done
grep -q "not submitted" "$out/empty/steps.tsv" || fail "empty: its labs are not 'not submitted'"
[ "$(awk -F'\t' 'NR > 1 && $4 != "not implemented yet"' "$out/stubs/steps.tsv" | wc -l)" = 0 ] || fail "stubs: a step is not 'not implemented yet'"
# Partial credit: the wrong sign of beta (barycentric, which find_segment_triangle uses
# too, and so the moving meshes sliding in one plane of step 9) keeps some of the points
# of steps 3, 4, 5, 8 and 9, never all; the rest is full.
awk -F'\t' 'NR > 1 && !($1 == "02" && $2 ~ /^[34589]$/) && $5 != $6 { print "FAIL: partial: lab " $1 " step " $2 " scores " $5 " of " $6; bad = 1 }
            NR > 1 && $1 == "02" && $2 ~ /^[34589]$/ && !($4 == "failing" && $5 > 0 && $5 < $6) { print "FAIL: partial: step " $2 " is " $4 " with " $5 " of " $6; bad = 1 }
            END { exit bad }' "$out/partial/steps.tsv" || failures=$((failures + 1))

# What the feedback says, in the student's words.
grep -q "this is not C++" "$out/compile_error/report.txt" || fail "compile_error: the report does not show the compiler's error"
grep -q "segmentation fault" "$out/segfault/report.txt" || fail "segfault: the report does not name the signal"
grep -q "replay    ./labkit check 02 --case" "$out/segfault/report.txt" || fail "segfault: no replay command for the input it died on"
grep -q "did not finish this call" "$out/endless_loop/report.txt" || fail "endless_loop: the report does not say a call timed out"
grep -q "ran out of memory" "$out/allocate_50gb/report.txt" || fail "allocate_50gb: the report does not say it ran out of memory"
grep -q "printed more than" "$out/print_100mb/report.txt" || fail "print_100mb: the report does not say it printed too much"
grep -q "exit()" "$out/exit_0/report.txt" || fail "exit_0: the report does not mention exit()"
grep -q "defines main()" "$out/own_main/report.txt" || fail "own_main: the report does not say it defines main()"
grep -q "constructor priority" "$out/early_constructor/report.txt" || fail "early_constructor: the report does not say why"
# Bubblewrap leaves the kit's solutions out of the build's view ("No such file"); Landlock,
# the fallback where bubblewrap cannot make its namespaces, refuses to open them.
grep -qE "No such file|Permission denied" "$out/include_reference/report.txt" ||
  fail "include_reference: the reference was visible to the compiler"
# The class page lists what cost more than a wrong answer, in the kit's own words.
for row in "segfault:crashed during a call" "compile_error:does not compile" "exit_0:crashed during a call" "print_100mb:too much output"; do
  grep -qF "${row%%:*}</a></td><td>${row#*:}</td>" "$out/class.html" "$work/results02/class.html" ||
    fail "class.html: ${row%%:*} is not listed as '${row#*:}'"
done
# Untrusted text: invalid UTF-8 as U+FFFD, terminal controls shown, never obeyed.
grep -qF $'r\u00e9sultat \ufffd \\x1b[2J\\x1b]0;owned\\x07' "$out/latin1_crash/report.txt" || fail "latin1_crash: its last output is not shown as safe text"
grep -qF $'#error caf\ufffd \\x1b[2J' "$out/latin1_compile/report.txt" || fail "latin1_compile: the compile error is not shown as safe text"
grep -qF $'graded caf\ufffd/labs/02_segment_triangle/segment_triangle.cpp as' "$out/bad_members/report.txt" ||
  fail "bad_members: no note of the Latin-1 folder it was graded from"
for file in "$out"/class.csv "$work/results02"/class.* "$out"/*/*; do
  iconv -f UTF-8 -t UTF-8 "$file" >/dev/null 2>&1 || fail "$file is not valid UTF-8"
  if LC_ALL=C grep -q $'[\x01-\x08\x0b-\x1f\x7f]' "$file"; then fail "$file holds a control character"; fi
done
# A replay token the harness never writes is never printed as a command.
if grep -rhoE "replay +\./labkit [^\\]*" "$out" | grep touch; then fail "a crafted replay token became a command"; fi
[ -e /tmp/labkit-hostile-owned ] && { fail "a crafted replay command ran"; rm -f /tmp/labkit-hostile-owned; }
# The seed, hex-encoded, printed by code that ran before anything else.
hex_secret=$(printf '%s' "$secret" | od -An -tx1 | tr -d ' \n')
if grep -rqF "$hex_secret" "$out" "$work/grade.log"; then fail "the secret seed appears hex-encoded in the results"; fi
# One bad archive member costs only itself, and says why.
for said in 'not unpacked: ../segment_triangle.cpp has ".." in its path' \
  "not unpacked: links/frustum_split.cpp is a symbolic link" "not unpacked: links/particles.cpp is larger than 1 MB" \
  'not unpacked: esc\x1b[2J\x0aape is a symbolic link'; do
  grep -qF -- "$said" "$out/bad_members/report.txt" || fail "bad_members: the report does not say '$said'"
done
for said in "not unpacked: /abs/segment_triangle.cpp has an absolute path" "not unpacked: ../particles.cpp has \"..\" in its path" \
  "not unpacked: ./links/frustum_split.cpp is a symbolic link"; do
  grep -qF -- "$said" "$out/bad_members_tar/report.txt" || fail "bad_members_tar: the report does not say '$said'"
done
grep -qF "not unpacked: labs/02_segment_triangle/segment_triangle.cpp unpacks to more than 1 MB" "$out/bomb/report.txt" ||
  fail "bomb: the report does not say it unpacks to more than 1 MB"

# Names that cannot be told apart: nothing is graded, the message names the files (exit
# 2 at once, before any lab is built).
refused() {
  local class="$work/$1" said code
  shift
  said=$("$runner" grade "$class" --out "$class.out" --seed "$secret" 2>&1)
  code=$?
  [ $code -eq 2 ] || fail "$(basename "$class"): exit $code, expected 2: $said"
  [ -e "$class.out" ] && fail "$(basename "$class"): results were written"
  for what in "$@"; do grep -qF -- "$what" <<<"$said" || fail "$(basename "$class"): the message does not name '$what': $said"; done
}
mkdir -p "$work/two_alices" && cp "$subs/reference.zip" "$work/two_alices/alice.zip" &&
  cp "$subs/reference.zip" "$work/two_alices/alice-2.zip" && cp "$subs/extra_files.tar.gz" "$work/two_alices/alice.tar.gz"
refused two_alices "alice.zip" "alice.tar.gz"
mkdir -p "$work/class_file" && cp "$subs/reference.zip" "$work/class_file/class.csv.zip" && cp "$subs/reference.zip" "$work/class_file/bob.zip"
refused class_file "class.csv.zip"
mkdir -p "$work/labs_in_place" && reference "$work/labs_in_place" && cp "$subs/reference.zip" "$work/labs_in_place/bob.zip"
refused labs_in_place "labs/01_frustum_split/frustum_split.cpp" "bob.zip"

[ -z "$(find /tmp -maxdepth 3 -name hostile-was-here 2>/dev/null)" ] || fail "the escape submission wrote a hostile-was-here under /tmp"

# Every confinement this machine has, on the submissions that try to get out: the same
# promises hold under each (the run above used the one `auto` chose), and the report
# says which it was.
nothing_escaped() {
  for path in "$kit/HOSTILE_WAS_HERE" /tmp/labkit-hostile-was-here /root/.labkit-hostile "$work/hostile-was-here" \
    "$out/hostile-was-here"; do
    [ -e "$path" ] && { fail "$1: the escape submission wrote $path"; rm -f "$path"; }
  done
}
nothing_escaped "sandbox $(grep -o 'sandbox: [A-Za-z]*' "$out/reference/report.txt" | head -n 1)"
for mode in bubblewrap landlock; do
  if ! probe=$("$runner" grade "$subs/empty" --out "$work/probe-$mode" --labs 02 --sandbox "$mode" 2>&1); then
    echo "no $mode on this machine: $(tail -n 1 <<<"$probe")"
    continue
  fi
  mkdir -p "$work/mode-$mode"
  for name in escape steal_seed forge_report weak_rename kit_programs include_reference preinit_seed oracle_by_name \
    include_oracle include_cgal include_numbers inherited_fds udp_out; do
    cp -R "$(sub "$name")" "$work/mode-$mode/"
  done
  "$runner" grade "$work/mode-$mode" --out "$work/out-$mode" --seed "$secret" --cases 50 --labs 02 --sandbox "$mode" \
    --jobs 2 7<"$kit/README.md" 8>>"$work/inherited.txt" >"$work/mode-$mode.log" 2>&1 ||
    { cat "$work/mode-$mode.log"; fail "grading with --sandbox $mode exits $?"; }
  grep -qi "sandbox: $mode" "$work/out-$mode/escape/report.txt" || fail "--sandbox $mode: the report does not say so"
  cp -R "$out/reference" "$work/out-$mode/"
  main_out="$out" && out="$work/out-$mode"
  for name in escape steal_seed oracle_by_name preinit_seed; do expect "$name" graded; done
  expect include_reference "does not compile"
  expect_refused include_oracle '"common/oracle/segment_triangle.cpp" (line 4)'
  expect_refused include_cgal '<CGAL/Simple_cartesian.h> (line 1)'
  expect_refused include_numbers '<gmp.h> (line 2)' '<mpfr.h> (line 3)' '<boost/multiprecision/cpp_int.hpp> (line 4)' '<dlfcn.h> (line 5)'
  expect inherited_fds graded
  nothing_written "--sandbox $mode"
  expect udp_out graded
  nothing_received "--sandbox $mode"
  for name in forge_report weak_rename kit_programs; do
    awk -F'\t' -v n="$name ($mode)" 'NR > 1 && $5 != "0" { print "FAIL: " n ": lab 02 step " $2 " scores " $5; bad = 1 }
      END { exit bad }' "$out/$name/steps.tsv" || failures=$((failures + 1))
  done
  nothing_escaped "--sandbox $mode"
  out="$main_out"
  echo "--sandbox $mode: every trick kept out"
done
# Asked for, no confinement at all: the report says so (the instructor trusts the code).
if [ "$(id -u)" = 0 ]; then
  "$runner" grade "$subs/reference.zip" --out "$work/unsandboxed" --seed "$secret" --cases 50 --labs 02 --sandbox none \
    >"$work/unsandboxed.log" 2>&1 || fail "grading with --sandbox none exits $?"
  grep -q "sandbox: none (turned off" "$work/unsandboxed/report.txt" || fail "--sandbox none: the report does not say so"
fi
# With no sandbox at all, the grader's own promises still hold: the include rule, no
# inherited descriptor, no network (the seccomp filter, where the kernel has one: the
# report says so).
mkdir -p "$work/mode-none"
for name in include_oracle include_cgal include_numbers inherited_fds udp_out; do cp -R "$(sub "$name")" "$work/mode-none/"; done
"$runner" grade "$work/mode-none" --out "$work/out-none" --seed "$secret" --cases 50 --labs 02 --sandbox none --jobs 2 \
  7<"$kit/README.md" 8>>"$work/inherited.txt" >"$work/mode-none.log" 2>&1 ||
  { cat "$work/mode-none.log"; fail "grading with --sandbox none exits $?"; }
cp -R "$out/reference" "$work/out-none/"
main_out="$out" && out="$work/out-none"
expect_refused include_oracle '"common/oracle/segment_triangle.cpp" (line 4)'
expect_refused include_cgal '<CGAL/Simple_cartesian.h> (line 1)'
expect_refused include_numbers '<gmp.h> (line 2)' '<mpfr.h> (line 3)' '<boost/multiprecision/cpp_int.hpp> (line 4)' '<dlfcn.h> (line 5)'
expect inherited_fds graded
nothing_written "--sandbox none"
expect udp_out graded
if grep -q "and no network" "$out/udp_out/report.txt"; then nothing_received "--sandbox none"; else : >"$work/udp-received.txt"; fi
out="$main_out"
echo "--sandbox none: the include rule, the descriptors and the network held"

# The outputs: every results.json matches Gradescope's schema; none holds the seed.
"$schema_check" "$kit/grading/gradescope-results.schema.json" "$out"/*/results.json >"$work/schema.log" ||
  { cat "$work/schema.log"; fail "a results.json does not match the schema"; }
if grep -rqF "$secret" "$out" "$work/results02" "$work/grade.log"; then fail "the secret seed appears in the results"; fi
for xml in "$out"/*/junit.xml; do
  head -n 2 "$xml" | grep -q "<testsuites " || fail "$xml has no <testsuites>"
  [ "$(grep -c "<testcase " "$xml")" = "$(($(wc -l <"${xml%junit.xml}steps.tsv") - 1))" ] || fail "$xml: one <testcase> per step"
done
grep -q "<failure" "$out/segfault/junit.xml" || fail "segfault: junit.xml has no <failure> for the step its crashes cost"
[ "$(wc -l <"$out/class.csv")" = "$(($(ls "$subs" | wc -l) + 1))" ] || fail "class.csv: a header and one row per submission"
[ "$(wc -l <"$work/results02/class.csv")" = "$(ls "$subs02" | wc -l)" ] ||
  fail "lab 02's class.csv: a header and one row per submission (the endless loop is graded apart)"
head -n 1 "$out/class.csv" | grep -qE "^submission,(lab[0-9]{2},)+total,max$" || fail "class.csv's header is $(head -n 1 "$out/class.csv")"

# JUnit XML that a CI server can read.
if command -v python3 >/dev/null; then
  python3 -c 'import sys, xml.etree.ElementTree as T
for f in sys.argv[1:]: T.parse(f)' "$out"/*/junit.xml || fail "a junit.xml is not well-formed XML"
fi

# The table: each fault, what the grader reported for it, what it kept, and the grader's
# seconds for the whole submission. Also left in the build folder (hostile-table.txt)
# for the notes.
declare -A fault=(
  [reference]="none: the reference itself" [empty]="empty submission" [stubs]="the stubs, unchanged"
  [compile_error]="compile error in lab 02" [segfault]="segfault (null write)" [endless_loop]="endless loop"
  [allocate_50gb]="allocating 50 GB" [print_100mb]="printing 100 MB" [exit_0]="exit(0) in a call"
  [giant_frame]="an answer frame declaring 1 GiB" [defaults]="every function its default answer"
  [escape]="writing outside its folder, kill(-1)" [extra_files]="extra files replacing a test, headers, CMake, manifest"
  [steal_seed]="reading the secret seed" [early_constructor]="constructor before the harness"
  [symlink]="lab file is a symlink to the reference" [include_reference]="#include of the reference"
  [own_main]="its own main()" [partial]="classic mistake (beta sign), partial steps" [all_or_nothing]="classic mistake, all-or-nothing step"
  [latin1_crash]="Latin-1 and escapes printed, then a crash" [latin1_compile]="Latin-1 and escapes in a compile error"
  [fifo_report]="a FIFO in place of its report" [symlink_report]="a symlink in place of its report"
  [queries_5]="a report of the wrong shape (queries: 5)" [finished_yes]="a report of the wrong shape (finished: yes)"
  [crafted_token]="a crafted replay token in its report" [crafted_inflight]="a crafted in-flight marker, then exit"
  [labs]="a student's folder named labs" [bad_members]="zip: ../, symlinks, 5 MB, Latin-1 folder"
  [bad_members_tar]="tar: absolute, ../, symlinks, 5 MB" [bomb]="zip bomb declaring 10 bytes"
  [forge_report]="stub + static init writing a passing report" [weak_rename]="stub + weak rename() swapping reports"
  [oracle_by_name]="the oracle by mangled name, /proc/self/exe" [preinit_seed]=".preinit_array reading the seed"
  [kit_programs]="stub + exec of the reference's program" [include_oracle]="#include of the oracle's .cpp, renamed"
  [include_cgal]="#include <CGAL/...>" [include_numbers]="#include <gmp.h>, <mpfr.h>, Boost, <dlfcn.h>"
  [load_gmp]="dlopen of libgmp, declared by hand"
  [inherited_fds]="reading and writing descriptors 5 to 20" [udp_out]="UDP datagrams out")
{
  echo
  printf '%-46s | %-40s | %-9s | %-10s | %s\n' "fault (in lab 02)" "what the grader reported for lab 02" "lab 02" "other labs" "seconds"
  for name in reference empty stubs compile_error segfault endless_loop allocate_50gb print_100mb exit_0 escape extra_files \
    steal_seed early_constructor symlink include_reference own_main partial all_or_nothing latin1_crash latin1_compile \
    fifo_report symlink_report queries_5 finished_yes crafted_token crafted_inflight labs bad_members bad_members_tar bomb \
    forge_report weak_rename oracle_by_name preinit_seed kit_programs include_oracle include_cgal include_numbers \
    load_gmp inherited_fds udp_out giant_frame defaults; do
    [ -f "$out/$name/steps.tsv" ] || continue
    seconds=$(grep -oE '\(([0-9.]+) s\)$' "$out/$name/report.txt" | tail -n 1 | tr -d '() s')
    awk -F'\t' -v f="${fault[$name]}" -v t="$seconds" 'FNR == 1 { next }
      FNR == NR { ref[$1 "/" $2] = $4; refscore[$1] += $5; next }
      $1 == "02" { lab02 += $5; max02 += $6; if ($4 != ref["02/" $2]) said[$4] = said[$4] (said[$4] == "" ? "" : ",") $2 }
      $1 != "02" { other += $5; others = 1 }
      END { for (r in refscore) if (r != "02") otherref += refscore[r]
            for (s in said) reported = reported (reported == "" ? "" : "; ") s " (step " said[s] ")"
            if (reported == "") reported = "as the reference"
            others_said = others ? sprintf("%4s/%-5s", other, otherref) : "lab 02 only"
            printf "%-46s | %-40s | %4s/%-4s | %-10s | %s\n", f, reported, lab02, max02, others_said, t }' \
      "$out/reference/steps.tsv" "$out/$name/steps.tsv"
  done
  echo
  cat "$out/class.csv"
  echo
} | tee "$build/hostile-table.txt"
[ $failures -eq 0 ] && echo "hostile suite: every fault cost only what it should" || { cat "$work/grade.log"; }
exit $((failures > 0))
