// Text helpers the kit's programs share: the runner, the harness's reports, the
// benchmarks' report and the kit's own tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace labkit {

// A file's whole contents, byte for byte; "" when it cannot be read.
inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// `text` with every line after the first starting with `prefix`.
inline std::string indent(const std::string& text, const std::string& prefix) {
  std::string out;
  for (char c : text) {
    out += c;
    if (c == '\n') out += prefix;
  }
  return out;
}

}  // namespace labkit
