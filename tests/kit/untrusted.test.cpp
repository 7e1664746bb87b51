// What the grader does with what a submission controls (runner/untrusted.h): any bytes
// become valid UTF-8 with terminal controls shown as text, a replay command is a single
// shell word whatever the token, and a file left behind is read only if it is a regular
// file of a sane size. Runs without the kit's build: `kit_untrusted` is this file and
// runner/untrusted.cpp alone.
#define CATCH_CONFIG_MAIN  // Catch2 2: main() is here; Catch2 3: it is Catch2::Catch2WithMain's
#include "runner/untrusted.h"
#include "runner/seed.h"

#include "common/harness/catch.h"
#include "common/text.h"

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

using runner::is_replay_token;
using runner::read_untrusted_file;
using runner::replay_command;
using runner::safe_text;
using runner::shell_quote;

namespace {

const std::string fffd = "\xEF\xBF\xBD";

// Strict UTF-8 with no C0 control but \n and \t: what nlohmann::json and XML accept.
bool valid_and_quiet(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = s[i];
    if (c < 0x80) {
      if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7F) return false;
      ++i;
      continue;
    }
    const std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 ? 2 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    i += n;
  }
  return true;
}

// Runs `word` through sh as the argument of printf, and returns what sh passed on.
std::string through_the_shell(const std::string& word) {
  const std::string out = "/tmp/kit-untrusted-shell." + std::to_string(getpid());
  const std::string command = "printf %s " + word + " >" + out;
  if (std::system(command.c_str()) != 0) return "<sh failed>";
  const std::string text = labkit::read_file(out);
  std::filesystem::remove(out);
  return text;
}

}  // namespace

TEST_CASE("text that is already fine passes unchanged", "[kit][untrusted]") {
  for (const std::string s : {"", "plain ASCII", "line one\n\tline two\n", "élève, naïve, 日本語, 🙂",
                              "error: expected ';' before '}' token"})
    CHECK(safe_text(s) == s);
}

TEST_CASE("invalid UTF-8 becomes U+FFFD, one per broken sequence, and the rest is kept", "[kit][untrusted]") {
  CHECK(safe_text("caf\xE9 ok") == "caf" + fffd + " ok");             // a Latin-1 byte
  CHECK(safe_text("\xA9t\xC3\xA9") == fffd + "t\xC3\xA9");            // a tail cut mid-character
  CHECK(safe_text("ab\xE2\x82") == "ab" + fffd);                      // cut short at the end
  CHECK(safe_text("\xC0\xAF") == fffd + fffd);                        // an overlong '/'
  CHECK(safe_text("\xED\xA0\x80") == fffd + fffd + fffd);             // a surrogate
  CHECK(safe_text("\xF4\x90\x80\x80") == fffd + fffd + fffd + fffd);  // past U+10FFFF
  CHECK(safe_text("\xF0\x9F\x99") == fffd);                           // one maximal subpart
  CHECK(safe_text(std::string("a\0b", 3)) == "a\\x00b");
  std::string every_byte;
  for (int c = 0; c < 256; ++c) every_byte += char(c);
  for (int i = 0; i < 3; ++i) every_byte += every_byte;
  CHECK(valid_and_quiet(safe_text(every_byte)));
}

TEST_CASE("terminal controls are shown, not obeyed", "[kit][untrusted]") {
  CHECK(safe_text("\x1b[2J\x1b]0;owned\x07") == "\\x1b[2J\\x1b]0;owned\\x07");
  CHECK(safe_text("100%\rpassed") == "100%\\x0dpassed");
  CHECK(safe_text("dos line\r\nnext") == "dos line\nnext");
  CHECK(safe_text("\x7f") == "\\x7f");
  CHECK(safe_text("\xC2\x9B"
                  "31m") == "\\u009b31m");                      // C1 CSI
  CHECK(safe_text("\xE2\x80\xAEtxt.exe") == "\\u202etxt.exe");  // right-to-left override
  CHECK(safe_text("\xEF\xBF\xBE") == "\\ufffe");                // XML refuses it
}

TEST_CASE("safe_text is idempotent", "[kit][untrusted]") {
  for (const std::string s : {"caf\xE9\x1b[31m\r\n\xC2\x9B\xE2\x80\xAE", "\\x1b already shown", "\xF0\x9F\x99"})
    CHECK(safe_text(safe_text(s)) == safe_text(s));
}

// Every way a reader may start a line: newline, CR, CR LF, VT, FF, the C0 separators,
// NEL, U+2028 and U+2029 (Python's str.splitlines, which the grading tests read with).
std::vector<std::string> reader_lines(const std::string& text) {
  static const std::vector<std::string> breaks = {"\r\n", "\n",   "\r",       "\v",           "\f",          "\x1c",
                                                  "\x1d", "\x1e", "\xC2\x85", "\xE2\x80\xA8", "\xE2\x80\xA9"};
  std::vector<std::string> lines;
  std::string line;
  for (std::size_t i = 0; i < text.size();) {
    bool broke = false;
    for (const std::string& b : breaks)
      if (text.compare(i, b.size(), b) == 0) {
        lines.push_back(line);
        line.clear();
        i += b.size();
        broke = true;
        break;
      }
    if (!broke) line += text[i++];
  }
  lines.push_back(line);
  return lines;
}

TEST_CASE("quoted student text: every line a reader sees starts with the quote", "[kit][untrusted]") {
  const std::string forged = "  Total 700 / 700";
  for (const std::string separator :
       {"\n", "\r", "\r\n", "\v", "\f", "\x1e", "\xC2\x85", "\xE2\x80\xA8", "\xE2\x80\xA9", "\n\n"}) {
    const std::string text = "error: static assertion failed: x" + separator + forged + separator;
    const std::string block = runner::quoted_lines(text, "  ");
    for (const std::string& line : reader_lines(block)) CHECK(line.rfind("  |", 0) == 0);
    const std::string labelled = "why       " + runner::quoted_after_label(text, "          ");
    const std::vector<std::string> lines = reader_lines(labelled);
    CHECK(lines.front().rfind("why       error: static assertion failed", 0) == 0);
    for (std::size_t k = 1; k < lines.size(); ++k) CHECK(lines[k].rfind("          |", 0) == 0);
  }
  CHECK(runner::quoted_lines("one\n\ntwo\n") == "| one\n|\n| two");
  CHECK(runner::quoted_lines("") == "|");
  CHECK(runner::quoted_after_label("one line", "  ") == "one line");
}

TEST_CASE("a quoted word is one word, literally, for sh", "[kit][untrusted]") {
  for (const std::string s : {"q:1,2", "it's", "'; touch /tmp/x; '", "$(id) `id` $HOME \\ \" *", "a\nb", "''''", ""})
    CHECK(through_the_shell(shell_quote(s)) == s);
  CHECK(shell_quote("it's") == "'it'\\''s'");
}

TEST_CASE("replay tokens: the harness's grammar, and nothing else", "[kit][untrusted]") {
  for (const char* token : {"segment_plane:1,2,3", "distance sphere box:0.1,-3,1e-06,1e+300,inf,-inf,nan",
                            "robust.advance:4.9406564584124654e-324,-0", "q:",
                            "first_hit:1,3,5,1,3,-1,8,0,0,0,4,0,0,4,4,0,0,4,0,0,0,2,4,0,2,4,4,2,0,4,2,4,0,1,2,0,2"})
    CHECK(is_replay_token(token));
  for (const char* token : {"", "nonsense", ":1,2", "q:1,,2", "q:1,2,", "q:1;id", "q:$(id)", "q':1", "q:1 2", "q\n:1",
                            "q:0x1p3", "q:1,2' ; rm -rf ~ ; echo '"})
    CHECK_FALSE(is_replay_token(token));
  CHECK(replay_command("check", "02", "segment_plane:1,2,3") == "./labkit check 02 --case 'segment_plane:1,2,3'");
  CHECK(replay_command("check", "02", "q:1' ; touch /tmp/owned ; '") == "");
}

TEST_CASE("files left behind: only a regular file of a sane size is read", "[kit][untrusted]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("kit-untrusted." + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "report.json") << "{\"finished\": true}";
  const auto read = read_untrusted_file((dir / "report.json").string(), 100);
  CHECK(read.error.empty());
  CHECK(read.text == "{\"finished\": true}");
  CHECK(read_untrusted_file((dir / "report.json").string(), 5).error == "is larger than 5 bytes");

  REQUIRE(mkfifo((dir / "fifo").c_str(), 0600) == 0);  // open() would wait for a writer forever
  CHECK(read_untrusted_file((dir / "fifo").string(), 100).error == "is a FIFO, not a regular file");
  fs::create_symlink(dir / "report.json", dir / "link");
  CHECK(read_untrusted_file((dir / "link").string(), 100).error == "is a symbolic link");
  CHECK(read_untrusted_file(dir.string(), 100).error == "is a folder, not a regular file");
  CHECK(read_untrusted_file((dir / "absent").string(), 100).error == "cannot be opened (No such file or directory)");
  CHECK(read_untrusted_file("/dev/zero", 100).error == "is a device, not a regular file");

  CHECK(runner::copy_untrusted_file((dir / "report.json").string(), (dir / "copy").string(), 100).empty());
  CHECK(read_untrusted_file((dir / "copy").string(), 100).text == read.text);
  CHECK(runner::copy_untrusted_file((dir / "fifo").string(), (dir / "copy2").string(), 100) ==
        "is a FIFO, not a regular file");
  fs::remove_all(dir);
}

namespace {
std::string hex(const std::array<std::uint8_t, 32>& digest) {
  static const char* const digits = "0123456789abcdef";
  std::string out;
  for (const std::uint8_t b : digest) out += std::string{digits[b >> 4], digits[b & 15]};
  return out;
}
}  // namespace

TEST_CASE("SHA-256: the standard's test vectors", "[kit][seed]") {
  CHECK(hex(runner::sha256("")) == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(hex(runner::sha256("abc")) == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(hex(runner::sha256("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq")) ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(hex(runner::sha256(std::string(1000000, 'a'))) ==
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("a submission's seed: its own files, the secret and the lab, nothing else", "[kit][seed]") {
  const std::map<std::string, std::string> a = {{"labs/02_x/x.cpp", "int f() { return 1; }"}};
  const std::map<std::string, std::string> b = {{"labs/02_x/x.cpp", "int f() { return 2; }"}};
  const std::string seed = runner::submission_seed("secret phrase", "02", a);
  CHECK(seed == runner::submission_seed("secret phrase", "02", a));  // a regrade draws the same cases
  CHECK(seed != runner::submission_seed("secret phrase", "02", b));  // a changed file draws new ones
  CHECK(seed != runner::submission_seed("secret phrase", "03", a));
  CHECK(seed != runner::submission_seed("secret phrasf", "02", a));
  // Parts cannot run together: the secret "ab" and lab "c" are not the secret "a" and lab "bc".
  CHECK(runner::submission_seed("ab", "c", a) != runner::submission_seed("a", "bc", a));
  // Decimal, at most 19 digits: the harness reads it as the number (parse_seed).
  CHECK(!seed.empty());
  CHECK(seed.size() <= 19);
  CHECK(seed.find_first_not_of("0123456789") == std::string::npos);
  CHECK(seed.find("secret") == std::string::npos);
}
