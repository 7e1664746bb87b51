#include "no_network.h"

#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <cerrno>
#include <cstddef>
#include <cstring>

namespace runner::no_network {

namespace {

#if defined(__x86_64__)
constexpr unsigned kArchitecture = AUDIT_ARCH_X86_64;
#elif defined(__aarch64__)
constexpr unsigned kArchitecture = AUDIT_ARCH_AARCH64;
#endif

#ifndef __NR_io_uring_setup
#define __NR_io_uring_setup 425  // the same number on every architecture (Linux 5.1)
#endif

constexpr unsigned kRefuse = SECCOMP_RET_ERRNO | (EACCES & SECCOMP_RET_DATA);
constexpr unsigned kRefuseForeign = SECCOMP_RET_ERRNO | (EPERM & SECCOMP_RET_DATA);

sock_filter statement(unsigned short code, unsigned k) { return {code, 0, 0, k}; }
sock_filter jump(unsigned short code, unsigned k, unsigned char if_true, unsigned char if_false) {
  return {code, if_true, if_false, k};
}

}  // namespace

std::string restrict_self() {
#if !defined(__x86_64__) && !defined(__aarch64__)
  return "no seccomp network filter for this architecture (x86-64 and aarch64 only)";
#else
  constexpr unsigned arch = offsetof(seccomp_data, arch), nr = offsetof(seccomp_data, nr);
  // A socket's family is an int: the low half of the first argument (little-endian).
  constexpr unsigned family = offsetof(seccomp_data, args[0]);
  const sock_filter program[] = {
    statement(BPF_LD | BPF_W | BPF_ABS, arch),
    jump(BPF_JMP | BPF_JEQ | BPF_K, kArchitecture, 1, 0),
    statement(BPF_RET | BPF_K, kRefuseForeign),  // another architecture's numbers: refuse all
    statement(BPF_LD | BPF_W | BPF_ABS, nr),
#if defined(__x86_64__)
    jump(BPF_JMP | BPF_JGE | BPF_K, 0x40000000, 0, 1),  // the x32 ABI's numbers (__X32_SYSCALL_BIT)
    statement(BPF_RET | BPF_K, kRefuseForeign),
#endif
    jump(BPF_JMP | BPF_JEQ | BPF_K, __NR_io_uring_setup, 0, 1),
    statement(BPF_RET | BPF_K, kRefuse),
    jump(BPF_JMP | BPF_JEQ | BPF_K, __NR_socket, 1, 0),
    statement(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
    statement(BPF_LD | BPF_W | BPF_ABS, family),
    jump(BPF_JMP | BPF_JEQ | BPF_K, AF_UNIX, 0, 1),
    statement(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
    statement(BPF_RET | BPF_K, kRefuse),
  };
  const sock_fprog filter{static_cast<unsigned short>(sizeof program / sizeof program[0]),
                          const_cast<sock_filter*>(program)};
  if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return std::string("no_new_privs: ") + std::strerror(errno);
  if (prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &filter) != 0)
    return std::string("the kernel refused a seccomp filter: ") + std::strerror(errno);
  return "";
#endif
}

}  // namespace runner::no_network
