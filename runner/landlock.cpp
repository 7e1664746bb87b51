#include "landlock.h"

#include <fcntl.h>
#include <linux/landlock.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace runner::landlock {

namespace {

// What a program needs to read to start and run: the loader, the C and C++ libraries,
// the compiler and its headers, the time zone and locale files.
const char* const kSystem[] = {"/usr", "/etc", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"};
// Devices any program may use.
const char* const kDevices[] = {"/dev/null", "/dev/zero", "/dev/random", "/dev/urandom", "/dev/full"};

constexpr std::uint64_t kRead = LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
constexpr std::uint64_t kFileRights = LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_WRITE_FILE |
                                      LANDLOCK_ACCESS_FS_READ_FILE
#ifdef LANDLOCK_ACCESS_FS_TRUNCATE
                                      | LANDLOCK_ACCESS_FS_TRUNCATE
#endif
    ;

// Every file-system right the kernel's version knows: all of them are denied unless a
// rule allows them.
std::uint64_t handled(int abi) {
  std::uint64_t rights = (LANDLOCK_ACCESS_FS_MAKE_SYM << 1) - 1;  // version 1: execute .. make_sym
#ifdef LANDLOCK_ACCESS_FS_REFER
  if (abi >= 2) rights |= LANDLOCK_ACCESS_FS_REFER;
#endif
#ifdef LANDLOCK_ACCESS_FS_TRUNCATE
  if (abi >= 3) rights |= LANDLOCK_ACCESS_FS_TRUNCATE;
#endif
#ifdef LANDLOCK_ACCESS_FS_IOCTL_DEV
  if (abi >= 5) rights |= LANDLOCK_ACCESS_FS_IOCTL_DEV;
#endif
  return rights;
}

// Allows `rights` below `path` (only the file rights, when it is a file). A path that
// does not exist is skipped: nothing there to allow.
bool allow(int ruleset, const std::string& path, std::uint64_t rights, std::uint64_t handled_rights) {
  const int fd = open(path.c_str(), O_PATH | O_CLOEXEC);
  if (fd < 0) return errno == ENOENT || errno == ENOTDIR;
  struct stat st {};
  fstat(fd, &st);
  if (!S_ISDIR(st.st_mode)) rights &= kFileRights;
  landlock_path_beneath_attr rule{};
  rule.allowed_access = rights & handled_rights;
  rule.parent_fd = fd;
  const long done = syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
  close(fd);
  return done == 0;
}

}  // namespace

int version() {
  const long v = syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  return v > 0 ? int(v) : 0;
}

std::string restrict_self(const std::vector<std::string>& readable, const std::vector<std::string>& writable) {
  const int abi = version();
  if (abi == 0) return "this kernel has no Landlock (or it is turned off)";
  // The kernel's struct landlock_ruleset_attr as of version 6 (Debian 12's headers stop
  // at version 1's): the kernel reads as much of it as its version knows.
  struct {
    std::uint64_t handled_access_fs = 0;
    std::uint64_t handled_access_net = 0;  // version 4: TCP bind and connect
    std::uint64_t scoped = 0;              // version 6: signals, abstract unix sockets
  } attributes;
  attributes.handled_access_fs = handled(abi);
  std::size_t size = sizeof attributes.handled_access_fs;
  if (abi >= 4) {
    attributes.handled_access_net = 1 | 2;  // LANDLOCK_ACCESS_NET_BIND_TCP | LANDLOCK_ACCESS_NET_CONNECT_TCP
    size += sizeof attributes.handled_access_net;
  }
  if (abi >= 6) {
    attributes.scoped = 1 | 2;  // LANDLOCK_SCOPE_ABSTRACT_UNIX_SOCKET | LANDLOCK_SCOPE_SIGNAL
    size += sizeof attributes.scoped;
  }
  const int ruleset = int(syscall(SYS_landlock_create_ruleset, &attributes, size, 0));
  if (ruleset < 0) return std::string("Landlock refused a ruleset: ") + std::strerror(errno);
  const std::uint64_t all = attributes.handled_access_fs;
  bool ok = true;
  for (const char* path : kSystem) ok = ok && allow(ruleset, path, kRead, all);
  for (const char* path : kDevices) ok = ok && allow(ruleset, path, kRead | LANDLOCK_ACCESS_FS_WRITE_FILE, all);
  for (const std::string& path : readable) ok = ok && allow(ruleset, path, kRead, all);
  for (const std::string& path : writable) ok = ok && allow(ruleset, path, all, all);
  std::string why;
  if (!ok)
    why = std::string("Landlock refused a rule: ") + std::strerror(errno);
  else if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0)
    why = std::string("no_new_privs: ") + std::strerror(errno);
  else if (syscall(SYS_landlock_restrict_self, ruleset, 0) != 0)
    why = std::string("Landlock: ") + std::strerror(errno);
  close(ruleset);
  return why;
}

}  // namespace runner::landlock
