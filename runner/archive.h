// What a submission's archive holds, read without trusting it, and one member unpacked.
//
// Nothing is unpacked because of its name alone. The archive is listed first: a .zip's
// central directory is read here (names exactly as stored, whatever their encoding); a
// tar's listing comes from GNU tar, confined, with C-quoted names. Each member is then
// either refused, with the reason (an absolute path, a ".." component, a link, a device,
// a declared size over the cap, an encrypted or duplicated entry), or may be unpacked.
// The caller picks the members it wants among the others, and each is unpacked on its
// own, confined, under a cap on the bytes it may write: a member that lies about its
// size is stopped there, and costs only itself.
#pragma once

#include "sandbox.h"

#include <cstdint>
#include <string>
#include <vector>

namespace runner {

enum class ArchiveFormat { zip, tar_gz, tar };

struct ArchiveMember {
  enum class Kind { file, folder, symlink, hard_link, special };
  std::string name;  // as stored: any bytes
  std::string path;  // "labs/02_x/y.cpp": no "./", no "//", no trailing '/'
  Kind kind = Kind::file;
  std::uintmax_t size = 0;  // unpacked, as declared
  std::string refused;      // why it is never unpacked ("" when it may be; folders never are)

  // Where a .zip entry lies, and how it is stored (its central directory's fields).
  struct Zip {
    std::uint16_t version_needed = 0, flags = 0, method = 0, time = 0, date = 0;
    std::uint32_t crc = 0;
    std::uint64_t compressed = 0, header_offset = 0;
  } zip;
};

struct ArchiveListing {
  std::vector<ArchiveMember> members;
  std::string error;  // why it could not be read, or not to its end ("" when it was)
};

// Lists `archive`; members over `largest` bytes are refused. `scratch`: an empty folder
// for a confined listing run (tar).
ArchiveListing list_archive(const std::string& archive, ArchiveFormat format, std::uintmax_t largest,
                            const std::string& scratch, const Sandbox& sandbox);

struct UnpackedMember {
  std::string file;   // the member's bytes, written by the confined unpacker (untrusted)
  std::string error;  // why it was not unpacked ("" when it was)
};

// Unpacks one member that was not refused into the empty folder `into`, confined, writing
// at most `largest` bytes.
UnpackedMember unpack_member(const std::string& archive, ArchiveFormat format, const ArchiveMember& member,
                             std::uintmax_t largest, const std::string& into, const Sandbox& sandbox);

}  // namespace runner
