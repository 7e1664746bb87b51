#include "zip_directory.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace runner {

namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kLargestDirectory = std::uint64_t(64) << 20;  // far more than a submission's files

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
    // Not the record, or those bytes within a comment or data that merely look like it.
    if (field(tail, at, 4) != 0x06054b50 || at + 22 + field(tail, at + 20, 2) > tail.size()) continue;
    // Split archives need their other parts, which a submission does not have.
    if (field(tail, at + 4, 2) != 0 || field(tail, at + 6, 2) != 0) throw BadZip("is split across several files");
    Directory d{field(tail, at + 10, 2), field(tail, at + 12, 4), field(tail, at + 16, 4), 0};
    const std::uint64_t end_record = file_size - span + at;
    if (d.entries == 0xFFFF || d.size == 0xFFFFFFFF || d.offset == 0xFFFFFFFF) return zip64_directory(in, end_record);
    // Offsets that point past the record: not a directory this file holds.
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
      case 0:
      case 0100000: return Kind::file;
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
  return m;
}

}  // namespace

ArchiveListing read_zip_directory(const std::string& archive, std::size_t most_members) {
  ArchiveListing listing;
  std::ifstream in(archive, std::ios::binary);
  try {
    std::error_code e;
    const std::uint64_t size = fs::file_size(archive, e);
    if (e || !in) throw BadZip("cannot be read");
    const Directory d = find_directory(in, size);
    // A directory this large holds far more than a submission's files.
    if (d.size > kLargestDirectory) throw BadZip("has a central directory over 64 MB");
    const std::string cd = read_at(in, d.offset, d.size);
    std::size_t at = 0;
    for (std::uint64_t i = 0; i < d.entries; ++i) {
      if (listing.members.size() == most_members)
        throw BadZip("has more than " + std::to_string(most_members) + " members: the rest were not read");
      listing.members.push_back(zip_member(cd, at, d.shift));
    }
  } catch (const BadZip& e) {
    listing.error = std::string("the archive ") + e.what();
  }
  return listing;
}

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

}  // namespace runner
