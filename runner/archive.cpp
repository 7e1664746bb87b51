#include "archive.h"
#include "untrusted.h"
#include "zip_directory.h"

#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace runner {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMostMembers = 20000;                           // listed this far, no further
constexpr std::uintmax_t kLargestListing = std::uintmax_t(16) << 20;  // a tar listing's text

std::string megabytes(std::uintmax_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MB"; }

// The first line of a tool's message that says something (gzip starts its with a blank one).
std::string first_line(const std::string& text) {
  const std::size_t start = std::min(text.find_first_not_of(" \n"), text.size());
  return text.substr(start, std::min(text.find('\n', start) - start, std::size_t(200)));
}

Limits unpacking_limits(std::uintmax_t file_bytes) {
  Limits limits;
  limits.seconds = 60;
  limits.memory_bytes = std::size_t(1) << 30;
  limits.file_bytes = std::size_t(file_bytes);
  return limits;
}

// ---- names and verdicts, for any format ---------------------------------------------

struct Normalised {
  std::string path;
  std::string problem;  // why the name is no safe relative path ("" when it is)
};

// "./labs//02_x/./y.cpp" -> "labs/02_x/y.cpp".
Normalised normalise(const std::string& name) {
  // An absolute path would be written wherever it says.
  if (!name.empty() && name[0] == '/') return {"", "has an absolute path"};
  std::string path;
  for (std::size_t start = 0; start <= name.size();) {
    const std::size_t end = std::min(name.find('/', start), name.size());
    const std::string part = name.substr(start, end - start);
    // ".." would climb out of the folder it is unpacked into.
    if (part == "..") return {"", "has \"..\" in its path"};
    if (!part.empty() && part != ".") path += (path.empty() ? "" : "/") + part;
    start = end + 1;
  }
  return {path, ""};
}

// Each member's path, and what may never be unpacked, and why (folders simply never are).
void judge(std::vector<ArchiveMember>& members, ArchiveFormat format, std::uintmax_t largest) {
  using Kind = ArchiveMember::Kind;
  for (ArchiveMember& m : members) {
    std::string name = m.name;
    if (format == ArchiveFormat::zip)  // Windows tools write backslashes
      for (char& c : name)
        if (c == '\\') c = '/';
    const Normalised n = normalise(name);
    m.path = n.path;
    m.refused = n.problem;
  }
  std::map<std::string, int> copies;
  for (const ArchiveMember& m : members)
    if (m.kind == Kind::file) ++copies[m.path];
  for (ArchiveMember& m : members) {
    if (!m.refused.empty() || m.kind == Kind::folder) continue;
    // A link's content is a path, not code, and unpacking it would point anywhere.
    if (m.kind == Kind::symlink)
      m.refused = "is a symbolic link";
    else if (m.kind == Kind::hard_link)
      m.refused = "is a hard link";
    // Devices, FIFOs and the like would block or never end when read.
    else if (m.kind == Kind::special)
      m.refused = "is not a regular file (a device, a FIFO, ...)";
    // Declared too large: a zip bomb is refused before anything is unpacked.
    else if (m.size > largest || m.zip.compressed > largest + 65536)
      m.refused = "is larger than " + megabytes(largest);
    else if (m.path.empty())
      m.refused = "has an empty name";
    // Its data cannot be read without the password.
    else if (m.zip.flags & 0x0001)
      m.refused = "is encrypted";
    // The archive holds it twice: which one is meant is not known.
    else if (copies[m.path] > 1)
      m.refused = "appears " + std::to_string(copies[m.path]) + " times in the archive";
  }
}

// ---- tar: GNU tar's listing, confined (a .zip's directory is read in zip_directory.cpp) ----

// The C-quoted string that starts at line[at] (a quote), unquoted: "\351" is byte 0351.
std::optional<std::string> unquote(const std::string& line, std::size_t at) {
  std::string out;
  for (std::size_t i = at + 1; i < line.size(); ++i) {
    if (line[i] == '"') return out;
    if (line[i] != '\\') {
      out += line[i];
      continue;
    }
    if (++i == line.size()) break;
    if (line[i] >= '0' && line[i] <= '7') {
      int value = 0;
      for (int k = 0; k < 3 && i < line.size() && line[i] >= '0' && line[i] <= '7'; ++k, ++i)
        value = value * 8 + (line[i] - '0');
      out += char(value);
      --i;
      continue;
    }
    const std::string from = "abfnrtv", to = "\a\b\f\n\r\t\v";
    const std::size_t known = from.find(line[i]);
    out += known == std::string::npos ? line[i] : to[known];  // \\, \", \? stand for themselves
  }
  return std::nullopt;  // no closing quote: a line cut short
}

// One line of `tar -tv --quoting-style=c --numeric-owner`:
//   -rw-r--r-- 0/0        1234 2024-01-01 12:00 "labs/02_x/y.cpp"
// the type first, the size third, the name C-quoted. What lies between (the date, in a
// form that varies with the archive) and after (a link's target) is not needed.
std::optional<ArchiveMember> tar_member(const std::string& line) {
  using Kind = ArchiveMember::Kind;
  std::istringstream words(line);
  std::string mode, owner, size;
  const std::size_t quote = line.find('"');
  // Not a member's line (too few words, no quoted name, a name cut short): not listed.
  if (!(words >> mode >> owner >> size) || quote == std::string::npos) return std::nullopt;
  const std::optional<std::string> name = unquote(line, quote);
  if (!name) return std::nullopt;
  ArchiveMember m;
  m.name = *name;
  switch (mode[0]) {
    case '-': m.kind = Kind::file; break;
    case 'd': m.kind = Kind::folder; break;
    case 'l': m.kind = Kind::symlink; break;
    case 'h': m.kind = Kind::hard_link; break;
    default: m.kind = Kind::special;
  }
  if (!m.name.empty() && m.name.back() == '/') m.kind = Kind::folder;
  m.size = size.find_first_not_of("0123456789") == std::string::npos ? std::stoull(size.substr(0, 19)) : 0;
  return m;
}

ArchiveListing list_tar(const std::string& archive, ArchiveFormat format, const std::string& scratch,
                        const Sandbox& sandbox) {
  std::vector<std::string> argv = {
      "tar", "-t", "-v", "-f", archive, "--quoting-style=c", "--numeric-owner", "--index-file=listing"};
  if (format == ArchiveFormat::tar_gz) argv.push_back("-z");
  const Confined c = sandbox.confine(argv, scratch, {archive}, unpacking_limits(kLargestListing));
  Run r = run(c.argv, {{"LC_ALL", "C"}}, c.limits, scratch);  // C: every byte past ASCII is quoted
  sandbox.interpret(r);

  ArchiveListing listing;
  const UntrustedRead text = read_untrusted_file(scratch + "/listing", kLargestListing);
  std::istringstream lines(text.text);
  std::string line;
  while (std::getline(lines, line) && !lines.eof()) {  // whole lines only: the last may be cut short
    if (listing.members.size() == kMostMembers) {
      listing.error = "the archive has more than " + std::to_string(kMostMembers) + " members: the rest were not read";
      return listing;
    }
    if (const std::optional<ArchiveMember> m = tar_member(line)) listing.members.push_back(*m);
  }
  if (r.timed_out)
    listing.error = "the archive could not be read to its end within 60 s";
  else if (!r.ok())
    listing.error = "the archive could not be read to its end: " + first_line(r.output);
  else if (!text.error.empty())
    listing.error = "the archive's listing " + text.error;
  return listing;
}

// Why a confined unpacking run did not give the member ("" when it did).
std::string unpack_failure(const Run& r, std::uintmax_t largest) {
  if (r.timed_out) return "was not unpacked within 60 s";
  // It declared a size within the cap, and wrote more: a bomb, stopped at the cap.
  if (r.signal == SIGXFSZ) return "unpacks to more than " + megabytes(largest);
  if (!r.ok()) return "could not be unpacked: " + first_line(r.output);
  return "";
}

}  // namespace

ArchiveListing list_archive(const std::string& archive, ArchiveFormat format, std::uintmax_t largest,
                            const std::string& scratch, const Sandbox& sandbox) {
  ArchiveListing listing = format == ArchiveFormat::zip ? read_zip_directory(archive, kMostMembers)
                                                        : list_tar(archive, format, scratch, sandbox);
  judge(listing.members, format, largest);
  return listing;
}

UnpackedMember unpack_member(const std::string& archive, ArchiveFormat format, const ArchiveMember& member,
                             std::uintmax_t largest, const std::string& into, const Sandbox& sandbox) {
  std::vector<std::string> argv, readable;
  std::string file;
  if (format == ArchiveFormat::zip) {
    try {
      std::ofstream(into + "/member.zip", std::ios::binary) << single_member_zip(archive, member);
    } catch (const std::runtime_error& e) {
      return {"", std::string("could not be unpacked: the archive ") + e.what()};
    }
    argv = {"unzip", "-qq", "-o", "member.zip"};
    file = into + "/member";
  } else {
    // Exactly that name (no wildcards), its first copy (the only one: copies are refused).
    argv = {"tar", "-x", "-f", archive, "--no-wildcards", "--occurrence=1", "--no-same-owner", "--no-same-permissions"};
    if (format == ArchiveFormat::tar_gz) argv.push_back("-z");
    argv.insert(argv.end(), {"--", member.name});
    readable.push_back(archive);
    file = into + "/" + member.path;
  }
  const Confined c = sandbox.confine(argv, into, readable, unpacking_limits(largest));
  Run r = run(c.argv, {{"LC_ALL", "C"}}, c.limits, into);
  sandbox.interpret(r);
  const std::string failure = unpack_failure(r, largest);
  if (failure.empty()) return {file, ""};
  // A damaged tar can end after this member: tar then fails, yet the member came out whole
  // (tar keeps no checksum of the data; a zip's member is checked by unzip).
  std::error_code e;
  const bool whole = format != ArchiveFormat::zip && !r.timed_out && r.signal == 0 &&
                     fs::is_regular_file(fs::symlink_status(file, e)) && fs::file_size(file, e) == member.size;
  return whole ? UnpackedMember{file, ""} : UnpackedMember{"", failure};
}

}  // namespace runner
