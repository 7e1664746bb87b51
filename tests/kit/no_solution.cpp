// kit_no_solution KIT_ROOT FOLDER: exits 1 when any file under FOLDER holds reference
// code: the body of any function of solutions/*/*.cpp (the mutants are in those files
// too, as `// mutant` lines, so a release without solutions/ holds none). Both sides are
// compared with comments and all whitespace taken out, so reformatting hides nothing.
// Bodies shorter than 40 such characters (`{ return {}; }`) are too common to mean much,
// and text the exact oracle also holds (common/oracle/, in every release by design: a
// sort by t, say) is not the reference's own.
#include "common/text.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// Without comments and whitespace (inside string literals too: code quoted in a CMake
// file or a string must still be found). Literals are kept whole otherwise, so that a
// "//" inside one does not start a comment.
std::string normalise(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      const std::size_t end = text.find("*/", i + 2);
      i = end == std::string::npos ? text.size() : end + 1;
    } else if (c == '"' || c == '\'') {
      out += c;
      for (++i; i < text.size() && text[i] != c && text[i] != '\n'; ++i) {
        if (text[i] == '\\' && i + 1 < text.size()) out += text[i++];
        if (!std::isspace(static_cast<unsigned char>(text[i]))) out += text[i];
      }
      if (i < text.size()) out += c;
    } else if (!std::isspace(static_cast<unsigned char>(c))) {
      out += c;
    }
  }
  return out;
}

std::size_t matching_brace(const std::string& s, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < s.size(); ++i) {
    if (s[i] == '"' || s[i] == '\'') {
      const char q = s[i];
      for (++i; i < s.size() && s[i] != q; ++i)
        if (s[i] == '\\') ++i;
    } else if (s[i] == '{') {
      ++depth;
    } else if (s[i] == '}' && --depth == 0) {
      return i;
    }
  }
  return std::string::npos;
}

bool ends_with(const std::string& s, std::size_t end, const std::string& tail) {
  return end >= tail.size() && s.compare(end - tail.size(), tail.size(), tail) == 0;
}

// Function bodies outside other bodies: a '{' right after ')' (or ") const", ...).
std::vector<std::string> function_bodies(const std::string& code) {
  std::vector<std::string> bodies;
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (code[i] == '"' || code[i] == '\'') {
      const char q = code[i];
      for (++i; i < code.size() && code[i] != q; ++i)
        if (code[i] == '\\') ++i;
      continue;
    }
    if (code[i] != '{') continue;
    const bool body = ends_with(code, i, ")") || ends_with(code, i, ")const") || ends_with(code, i, ")noexcept") ||
                      ends_with(code, i, ")override");
    if (!body) continue;
    const std::size_t close = matching_brace(code, i);
    if (close == std::string::npos) break;
    bodies.push_back(code.substr(i, close - i + 1));
    i = close;
  }
  return bodies;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: kit_no_solution KIT_ROOT FOLDER\n";
    return 2;
  }
  const fs::path kit = argv[1], folder = argv[2];
  struct Needle {
    std::string text, origin;
  };
  std::vector<Needle> needles;
  for (const auto& e : fs::recursive_directory_iterator(kit / "solutions"))
    if (e.path().extension() == ".cpp")
      for (const std::string& body : function_bodies(normalise(labkit::read_file(e.path()))))
        if (body.size() >= 40) needles.push_back({body, fs::relative(e.path(), kit).string()});
  std::string oracle;
  for (const auto& e : fs::recursive_directory_iterator(kit / "common" / "oracle"))
    oracle += normalise(labkit::read_file(e.path()));
  needles.erase(std::remove_if(needles.begin(), needles.end(),
                               [&](const Needle& n) { return oracle.find(n.text) != std::string::npos; }),
                needles.end());
  if (needles.size() < 5) {
    std::cerr << "kit_no_solution: found only " << needles.size() << " pieces of reference code to look for\n";
    return 2;
  }

  int files = 0, found = 0;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    if (!e.is_regular_file()) continue;
    ++files;
    const std::string text = normalise(labkit::read_file(e.path()));
    for (const Needle& n : needles)
      if (text.find(n.text) != std::string::npos) {
        if (++found <= 10)
          std::cout << fs::relative(e.path(), folder).string() << " holds reference code from " << n.origin << ": "
                    << n.text.substr(0, 70) << "...\n";
        break;
      }
  }
  std::cout << "looked for " << needles.size() << " reference function bodies in " << files << " files: " << found
            << " files hold some\n";
  return found == 0 ? 0 : 1;
}
