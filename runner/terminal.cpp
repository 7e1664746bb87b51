#include "terminal.h"

#include <unistd.h>
#include <cstdlib>

namespace runner::term {

namespace {
bool colour = isatty(1) && std::getenv("NO_COLOR") == nullptr;
std::string wrap(const char* code, const std::string& s) { return colour ? std::string(code) + s + "\033[0m" : s; }
}  // namespace

void use_colour(bool on) { colour = on; }
std::string bold(const std::string& s) { return wrap("\033[1m", s); }
std::string green(const std::string& s) { return wrap("\033[32m", s); }
std::string red(const std::string& s) { return wrap("\033[1;31m", s); }
std::string yellow(const std::string& s) { return wrap("\033[33m", s); }
std::string dim(const std::string& s) { return wrap("\033[2m", s); }

std::string pad(const std::string& s, std::size_t width) {
  std::size_t columns = 0;
  for (unsigned char c : s) columns += (c & 0xC0) != 0x80;
  return columns >= width ? s : s + std::string(width - columns, ' ');
}

}  // namespace runner::term
