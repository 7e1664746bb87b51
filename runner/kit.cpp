#include "kit.h"

#include <sstream>

namespace runner {

namespace {

std::string lines_from(const std::string& text, std::size_t first, std::size_t count) {
  std::istringstream in(text);
  std::string line, out;
  for (std::size_t i = 0; std::getline(in, line) && i < first + count; ++i)
    if (i >= first) out += line + "\n";
  return out;
}

}  // namespace

std::string first_errors(const std::string& log, const std::string& root) {
  std::istringstream in(log);
  std::string line;
  std::size_t index = 0, first = std::string::npos;
  while (std::getline(in, line)) {
    if (first == std::string::npos && (line.find("error:") != std::string::npos || line.find("Error") == 0))
      first = index;
    ++index;
  }
  std::string excerpt = lines_from(log, first == std::string::npos ? 0 : first, 24);
  for (std::size_t at; (at = excerpt.find(root + "/")) != std::string::npos;) excerpt.erase(at, root.size() + 1);
  return excerpt;
}

}  // namespace runner
