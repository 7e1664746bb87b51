// Landlock (Linux 5.13 and later): a process takes away its own access to the file
// system, except below the paths it names, and can never get it back; its children
// inherit the restriction. It needs no privilege and no namespace, so it confines graded
// code where bubblewrap cannot run (a container that forbids namespaces): the code reads
// the system and the folders it is given, writes its own folder, and nothing else
// (never solutions/, .git, the kit's build tree, another submission, the seed, /tmp).
#pragma once

#include <string>
#include <vector>

namespace runner::landlock {

// The kernel's Landlock version, 0 when it has none (or it is turned off).
int version();

// Restricts this process: read (and run) the system folders and `readable`, read and
// write `writable`; no TCP where the kernel can refuse it; no signals to processes
// outside the restriction where it can. "" when done, else why not.
std::string restrict_self(const std::vector<std::string>& readable, const std::vector<std::string>& writable);

}  // namespace runner::landlock
