#include "archive.h"
#include "untrusted.h"

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

constexpr std::size_t kMostMembers = 20000;                      // listed this far, no further
constexpr std::uintmax_t kLargestListing = std::uintmax_t(16) << 20;  // a tar listing's text
constexpr std::uint64_t kLargestDirectory = std::uint64_t(64) << 20;  // a zip's central directory

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

// Marks what may never be unpacked, and why; folders are simply never unpacked.
void judge(std::vector<ArchiveMember>& members, std::uintmax_t largest) {
  using Kind = ArchiveMember::Kind;
  std::map<std::string, int> copies;
  for (const ArchiveMember& m : members)
    if (m.kind == Kind::file) ++copies[m.path];
  for (ArchiveMember& m : members) {
    if (!m.refused.empty() || m.kind == Kind::folder) continue;
    // A link's content is a path, not code, and unpacking it would point anywhere.
    if (m.kind == Kind::symlink) m.refused = "is a symbolic link";
    else if (m.kind == Kind::hard_link) m.refused = "is a hard link";
    // Devices, FIFOs and the like would block or never end when read.
    else if (m.kind == Kind::special) m.refused = "is not a regular file (a device, a FIFO, ...)";
    // Declared too large: a zip bomb is refused before anything is unpacked.
    else if (m.size > largest || m.zip.compressed > largest + 65536) m.refused = "is larger than " + megabytes(largest);
    else if (m.path.empty()) m.refused = "has an empty name";
    // The archive holds it twice: which one is meant is not known.
    else if (copies[m.path] > 1) m.refused = "appears " + std::to_string(copies[m.path]) + " times in the archive";
  }
}

// ---- .zip: the central directory, read here -----------------------------------------

struct BadZip : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A little-endian field of `bytes`; a field past their end means the archive is damaged.
std::uint64_t field(const std::string& bytes, std::size_t at, std::size_t size) {
  if (at > bytes.size() || size > bytes.size() - at) throw BadZip("is cut short or damaged");
  std::uint64_t value = 0;
  for (std::size_t k = size; k-- > 0;) value = (value << 8) | static_cast<unsigned char>(bytes[at + k]);
  return value;
}

void put(std::string& out, std::uint64_t value, int size) {
  for (int k = 0; k < size; ++k, value >>= 8) out += char(value & 0xFF);
}

std::string read_at(std::ifstream& in, std::uint64_t offset, std::uint64_t size) {
  std::string bytes(std::size_t(size), '\0');
  in.clear();
  in.seekg(std::streamoff(offset));
  in.read(bytes.data(), std::streamsize(size));
  bytes.resize(std::size_t(std::max<std::streamsize>(0, in.gcount())));
  return bytes;
}

struct Directory {
  std::uint64_t entries = 0, size = 0, offset = 0;
  std::uint64_t shift = 0;  // bytes before the archive proper (a self-extracting stub)
};

// The Zip64 end record, for an archive whose counts or offsets overflow 16 or 32 bits.
Directory zip64_directory(std::ifstream& in, std::uint64_t end_record) {
  if (end_record < 20) throw BadZip("has a damaged Zip64 end record");
  const std::string locator = read_at(in, end_record - 20, 20);
  if (field(locator, 0, 4) != 0x07064b50) throw BadZip("has a damaged Zip64 end record");
  const std::string record = read_at(in, field(locator, 8, 8), 56);
  if (field(record, 0, 4) != 0x06064b50) throw BadZip("has a damaged Zip64 end record");
  return {field(record, 32, 8), field(record, 40, 8), field(record, 48, 8), 0};
}

// The end of central directory record: the last one in the file's last 64 KB.
Directory find_directory(std::ifstream& in, std::uint64_t file_size) {
  const std::uint64_t span = std::min<std::uint64_t>(file_size, 22 + 65535);
  const std::string tail = read_at(in, file_size - span, span);
  for (std::size_t at = tail.size() >= 22 ? tail.size() - 21 : 0; at-- > 0;) {
    if (field(tail, at, 4) != 0x06054b50 || at + 22 + field(tail, at + 20, 2) > tail.size()) continue;
    // Split archives need their other parts, which a submission does not have.
    if (field(tail, at + 4, 2) != 0 || field(tail, at + 6, 2) != 0) throw BadZip("is split across several files");
    Directory d{field(tail, at + 10, 2), field(tail, at + 12, 4), field(tail, at + 16, 4), 0};
    const std::uint64_t end_record = file_size - span + at;
    if (d.entries == 0xFFFF || d.size == 0xFFFFFFFF || d.offset == 0xFFFFFFFF) return zip64_directory(in, end_record);
    if (d.size + d.offset > end_record) throw BadZip("has its central directory past its end");
    d.shift = end_record - d.size - d.offset;
    d.offset += d.shift;
    return d;
  }
  throw BadZip("is not a zip file (it has no end of central directory record)");
}

// Sizes and offsets too large for their 32-bit fields are in the Zip64 extra field,
// each present only when its field is 0xFFFFFFFF, in this order.
void read_zip64_fields(const std::string& extra, ArchiveMember& m) {
  for (std::size_t at = 0; at + 4 <= extra.size(); at += 4 + field(extra, at + 2, 2)) {
    if (field(extra, at, 2) != 0x0001) continue;
    std::size_t next = at + 4;
    for (std::uint64_t* value : {&m.size, &m.zip.compressed, &m.zip.header_offset})
      if (*value == 0xFFFFFFFF) *value = field(extra, std::exchange(next, next + 8), 8);
    return;
  }
}

ArchiveMember::Kind zip_kind(unsigned host, std::uint32_t attributes, const std::string& name) {
  using Kind = ArchiveMember::Kind;
  if (!name.empty() && (name.back() == '/' || name.back() == '\\')) return Kind::folder;
  const unsigned mode = attributes >> 16;
  if (host == 3 && mode != 0) {  // made on Unix: the high half is the file's mode
    switch (mode & 0170000) {
      case 0: case 0100000: return Kind::file;
      case 0040000: return Kind::folder;
      case 0120000: return Kind::symlink;
      default: return Kind::special;
    }
  }
  return attributes & 0x10 ? Kind::folder : Kind::file;  // MS-DOS attributes: 0x10 is a folder
}

// The central directory entry at cd[at]; `at` moves past it.
ArchiveMember zip_member(const std::string& cd, std::size_t& at, std::uint64_t shift) {
  if (field(cd, at, 4) != 0x02014b50) throw BadZip("has a damaged central directory");
  ArchiveMember m;
  m.zip.version_needed = std::uint16_t(field(cd, at + 6, 2));
  m.zip.flags = std::uint16_t(field(cd, at + 8, 2));
  m.zip.method = std::uint16_t(field(cd, at + 10, 2));
  m.zip.time = std::uint16_t(field(cd, at + 12, 2));
  m.zip.date = std::uint16_t(field(cd, at + 14, 2));
  m.zip.crc = std::uint32_t(field(cd, at + 16, 4));
  m.zip.compressed = field(cd, at + 20, 4);
  m.size = field(cd, at + 24, 4);
  m.zip.header_offset = field(cd, at + 42, 4);
  const std::size_t name_length = field(cd, at + 28, 2), extra_length = field(cd, at + 30, 2);
  const std::size_t entry_length = 46 + name_length + extra_length + field(cd, at + 32, 2);
  if (entry_length > cd.size() - at) throw BadZip("has a damaged central directory");
  m.name = cd.substr(at + 46, name_length);
  read_zip64_fields(cd.substr(at + 46 + name_length, extra_length), m);
  m.zip.header_offset += shift;
  m.kind = zip_kind(unsigned(field(cd, at + 5, 1)), std::uint32_t(field(cd, at + 38, 4)), m.name);
  at += entry_length;

  std::string slashed = m.name;  // Windows tools write backslashes
  for (char& c : slashed)
    if (c == '\\') c = '/';
  const Normalised n = normalise(slashed);
  m.path = n.path;
  m.refused = n.problem;
  // Its data cannot be read without the password.
  if (m.refused.empty() && (m.zip.flags & 0x0001)) m.refused = "is encrypted";
  return m;
}

ArchiveListing list_zip(const std::string& archive) {
  ArchiveListing listing;
  std::ifstream in(archive, std::ios::binary);
  try {
    std::error_code e;
    const std::uint64_t size = fs::file_size(archive, e);
    if (e || !in) throw BadZip("cannot be read");
    const Directory d = find_directory(in, size);
    // A directory this large holds far more than a submission's files.
    if (d.size > kLargestDirectory) throw BadZip("has a central directory over " + megabytes(kLargestDirectory));
    const std::string cd = read_at(in, d.offset, d.size);
    std::size_t at = 0;
    for (std::uint64_t i = 0; i < d.entries; ++i) {
      if (listing.members.size() == kMostMembers)
        throw BadZip("has more than " + std::to_string(kMostMembers) + " members: the rest were not read");
      listing.members.push_back(zip_member(cd, at, d.shift));
    }
  } catch (const BadZip& e) {
    listing.error = std::string("the archive ") + e.what();
  }
  return listing;
}

// A .zip of `m`'s data alone, under the name "member" as a regular file: what unzip
// unpacks from it is that data, whatever name, type or path the original entry had.
std::string single_member_zip(const std::string& archive, const ArchiveMember& m) {
  std::ifstream in(archive, std::ios::binary);
  const std::string local = read_at(in, m.zip.header_offset, 30);
  if (field(local, 0, 4) != 0x04034b50) throw BadZip("has a damaged entry for it");
  const std::uint64_t data_at = m.zip.header_offset + 30 + field(local, 26, 2) + field(local, 28, 2);
  const std::string data = read_at(in, data_at, m.zip.compressed);
  if (data.size() != m.zip.compressed) throw BadZip("is cut short in its data");

  const std::string name = "member";
  const std::uint16_t flags = m.zip.flags & ~0x0808;  // sizes in the header, not after the data; an ASCII name
  std::string out;
  const auto common = [&] {
    put(out, m.zip.version_needed, 2);
    put(out, flags, 2);
    put(out, m.zip.method, 2);
    put(out, m.zip.time, 2);
    put(out, m.zip.date, 2);
    put(out, m.zip.crc, 4);
    put(out, m.zip.compressed, 4);
    put(out, m.size, 4);
    put(out, name.size(), 2);
    put(out, 0, 2);  // no extra field
  };
  put(out, 0x04034b50, 4);
  common();
  out += name + data;
  const std::size_t directory_at = out.size();
  put(out, 0x02014b50, 4);
  put(out, (3 << 8) | 20, 2);  // made on Unix
  common();
  put(out, 0, 2);               // no comment
  put(out, 0, 2);               // disk 0
  put(out, 0, 2);               // internal attributes
  put(out, 0100644u << 16, 4);  // a regular file, rw-r--r--
  put(out, 0, 4);               // its local header is at 0
  out += name;
  const std::size_t directory_size = out.size() - directory_at;
  put(out, 0x06054b50, 4);
  put(out, 0, 4);  // disk 0, directory on disk 0
  put(out, 1, 2);
  put(out, 1, 2);
  put(out, directory_size, 4);
  put(out, directory_at, 4);
  put(out, 0, 2);
  return out;
}

// ---- tar: GNU tar's listing, confined --------------------------------------------------

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
      for (int k = 0; k < 3 && i < line.size() && line[i] >= '0' && line[i] <= '7'; ++k, ++i) value = value * 8 + (line[i] - '0');
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
  const Normalised n = normalise(m.name);
  m.path = n.path;
  m.refused = n.problem;
  return m;
}

ArchiveListing list_tar(const std::string& archive, ArchiveFormat format, const std::string& scratch,
                        const Sandbox& sandbox) {
  std::vector<std::string> argv = {"tar", "-t", "-v", "-f", archive, "--quoting-style=c", "--numeric-owner",
                                   "--index-file=listing"};
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
  if (r.timed_out) listing.error = "the archive could not be read to its end within 60 s";
  else if (!r.ok()) listing.error = "the archive could not be read to its end: " + first_line(r.output);
  else if (!text.error.empty()) listing.error = "the archive's listing " + text.error;
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
  ArchiveListing listing = format == ArchiveFormat::zip ? list_zip(archive) : list_tar(archive, format, scratch, sandbox);
  judge(listing.members, largest);
  return listing;
}

UnpackedMember unpack_member(const std::string& archive, ArchiveFormat format, const ArchiveMember& member,
                             std::uintmax_t largest, const std::string& into, const Sandbox& sandbox) {
  std::vector<std::string> argv, readable;
  std::string file;
  if (format == ArchiveFormat::zip) {
    try {
      std::ofstream(into + "/member.zip", std::ios::binary) << single_member_zip(archive, member);
    } catch (const BadZip& e) {
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
