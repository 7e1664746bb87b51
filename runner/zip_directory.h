// A .zip's central directory, read in the grader byte by byte, every field checked
// against the bytes there are: the members' names exactly as stored (any encoding),
// their kinds, declared sizes and where their data lies. And one member's data, still
// compressed, re-wrapped as a zip of its own. Nothing is decompressed here.
#pragma once

#include "archive.h"

#include <cstddef>
#include <string>

namespace runner {

// The members as stored, not yet judged (archive.cpp does that); `error` says why the
// directory could not be read, or not to its end (after `most_members`).
ArchiveListing read_zip_directory(const std::string& archive, std::size_t most_members);

// A .zip of `member`'s data alone, as a regular file named "member": what unzip unpacks
// from it is that data, whatever name, type or path the original entry had. Throws
// std::runtime_error ("is cut short in its data") when the archive is damaged there.
std::string single_member_zip(const std::string& archive, const ArchiveMember& member);

}  // namespace runner
