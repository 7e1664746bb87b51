// No network for a process that has no network namespace of its own (Landlock mode, or
// no sandbox at all): a seccomp filter refuses every socket but a Unix one. Landlock
// can refuse TCP only (and only from its version 4); UDP, raw sockets and the rest need
// this. The refusal is an error (EACCES), never a kill: the code gets a clean failure.
#pragma once

#include <string>

namespace runner::no_network {

// Installs the filter on this process (its children inherit it, across exec too): then
// socket() fails with EACCES for every family but AF_UNIX (socketpair() is unaffected:
// it only makes Unix sockets), io_uring cannot be set up (it could make sockets on its
// own), and a system call made through another architecture's entry (a 64-bit program
// using the 32-bit one) fails with EPERM. Sets no_new_privs, as seccomp requires.
// "" when done, else why not.
std::string restrict_self();

}  // namespace runner::no_network
