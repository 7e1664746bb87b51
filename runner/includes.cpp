#include "includes.h"
#include "process.h"

#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <map>
#include <mutex>
#include <regex>
#include <sstream>

namespace runner::includes {

namespace fs = std::filesystem;

namespace {

std::string normal(const std::string& path, const std::string& directory = "") {
  fs::path p(path);
  if (p.is_relative()) p = fs::path(directory.empty() ? fs::current_path().string() : directory) / p;
  std::string s = p.lexically_normal().string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

bool under(const std::string& path, const std::string& folder) {
  return path == folder || (path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 &&
                            (folder.back() == '/' || path[folder.size()] == '/'));
}

bool exists(const std::string& path) {
  std::error_code e;
  return fs::is_regular_file(path, e);
}

// Headers a lab file may not use: other libraries', where the system's package lists
// cannot say which headers are the C library's (`system` then allows everything else),
// and the C library's dynamic loader, which would load at run time what the compile
// refuses (GMP, MPFR).
bool blocked(const std::string& relative) {
  static const std::regex names(
      R"(^(CGAL|boost|flint|mpfr|gmp|nlohmann|catch2|rapidcheck)/|^(gmp|mpfr|mpf2mpfr|mpc)[^/]*$|^dlfcn\.h$)");
  return std::regex_search(relative, names);
}

// The folders the compiler searches for <...> by itself, in its order.
std::vector<std::string> compiler_folders(const std::string& compiler) {
  static std::mutex mutex;
  static std::map<std::string, std::vector<std::string>> known;
  std::lock_guard<std::mutex> lock(mutex);
  if (const auto it = known.find(compiler); it != known.end()) return it->second;
  Limits limits;
  limits.seconds = 60;
  const Run r = run({compiler, "-xc++", "-E", "-v", "/dev/null"}, {}, limits);
  std::vector<std::string> folders;
  std::istringstream in(r.output);
  bool listing = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("search starts here:") != std::string::npos) {
      listing = true;
      continue;
    }
    if (line.rfind("End of search list", 0) == 0) break;
    if (listing && line.size() > 1 && line[0] == ' ') {
      std::string folder = line.substr(1);
      if (const auto at = folder.find(" (framework directory)"); at != std::string::npos) folder.resize(at);
      folders.push_back(normal(folder));
    }
  }
  return known[compiler] = folders;
}

// The C library's headers (glibc's and the kernel's), from the package lists of a
// Debian or Ubuntu system: empty where there are none.
const std::set<std::string>& c_library_headers() {
  static const std::set<std::string> files = [] {
    std::set<std::string> out;
    std::error_code e;
    for (const auto& entry : fs::directory_iterator("/var/lib/dpkg/info", e)) {
      const std::string name = entry.path().filename().string();
      const bool list = entry.path().extension() == ".list";
      if (!list || !(name.rfind("libc6-dev", 0) == 0 || name.rfind("linux-libc-dev", 0) == 0)) continue;
      std::ifstream in(entry.path());
      for (std::string line; std::getline(in, line);)
        if (line.rfind("/usr/include/", 0) == 0) out.insert(normal(line));
    }
    return out;
  }();
  return files;
}

// The #include lines of a kit file, resolved as the compiler would (beside the file,
// then from the kit's root).
std::vector<std::string> kit_includes(const std::string& file, const std::string& kit) {
  static const std::regex directive(R"(^\s*#\s*include\s*"([^"]+)\")");
  std::vector<std::string> out;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, directive)) continue;
    for (const std::string& base : {fs::path(file).parent_path().string(), kit}) {
      const std::string candidate = normal(base + "/" + m[1].str());
      if (exists(candidate)) {
        out.push_back(candidate);
        break;
      }
    }
  }
  return out;
}

bool allowed(const Rule& rule, const std::string& path) {
  for (const std::string& folder : rule.folders)
    if (under(path, folder)) return true;
  if (rule.files.count(path) || rule.kit_files.count(path)) return true;
  if (under(path, rule.kit)) return false;
  for (const std::string& folder : rule.system)
    if (under(path, folder)) return !rule.c_library_known && !blocked(path.substr(folder.size() + 1));
  return false;
}

// A header as a student would write it: "common/oracle/x.cpp", <CGAL/x.h>.
std::string shown(const Rule& rule, const std::string& path) {
  if (under(path, rule.kit)) return "\"" + path.substr(rule.kit.size() + 1) + "\"";
  std::string best;
  for (const std::string& folder : rule.search)
    if (under(path, folder) && path != folder && folder.size() > best.size()) best = folder;
  return best.empty() ? "\"" + path + "\"" : "<" + path.substr(best.size() + 1) + ">";
}

// Where `name`, as written in `source`, is found: beside the source, then in each folder.
std::vector<std::string> candidates(const Rule& rule, const std::string& source, const std::string& name) {
  if (!name.empty() && name[0] == '/') return {normal(name)};
  std::vector<std::string> out = {normal(fs::path(source).parent_path().string() + "/" + name)};
  for (const std::string& folder : rule.search) out.push_back(normal(folder + "/" + name));
  return out;
}

bool same_file(const std::string& a, const std::string& b) {
  if (a == b) return true;
  std::error_code e;
  return fs::equivalent(a, b, e);
}

// The line of `source` whose #include reads `path`; 0 when none does (a macro names it).
int line_of(const Rule& rule, const std::string& source, const std::string& path) {
  static const std::regex directive(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  std::ifstream in(source);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    std::smatch m;
    if (!std::regex_search(line, m, directive)) continue;
    for (const std::string& candidate : candidates(rule, source, m[1].str()))
      if (same_file(candidate, path)) return number;
  }
  return 0;
}

struct Offence {
  std::string top;   // what the file itself includes
  std::string path;  // the header not allowed (the same, or one `top` reads)
  int line = 0;
};

}  // namespace

Rule rule_for(const std::string& kit, const std::string& lab_folder, const std::vector<std::string>& command) {
  Rule rule;
  rule.kit = normal(kit);
  const std::string lab = normal(lab_folder);
  rule.folders.push_back(lab);

  // The kit headers: the lab's, the geometry types and what they include (the given
  // tools only where the lab's header includes them: lab 02 must not borrow lab 06's
  // ready segment-triangle test).
  std::vector<std::string> pending;
  std::error_code e;
  for (const auto& entry : fs::directory_iterator(lab, e))
    if (entry.path().extension() == ".h") pending.push_back(normal(entry.path().string()));
  for (const char* header : {"common/geometry.h", "common/not_implemented.h", "common/preconditions.h"})
    if (exists(rule.kit + "/" + header)) pending.push_back(rule.kit + "/" + header);
  while (!pending.empty()) {
    const std::string file = pending.back();
    pending.pop_back();
    if (!rule.kit_files.insert(file).second) continue;
    for (const std::string& next : kit_includes(file, rule.kit)) pending.push_back(next);
  }

  // The compiler's own folders: the C++ library and its built-in headers allowed
  // whole; the C library's folders only for the C library's headers.
  const std::vector<std::string> builtin = command.empty() ? std::vector<std::string>{} : compiler_folders(command[0]);
  for (const std::string& folder : builtin) {
    const bool own = folder.find("/c++/") != std::string::npos || folder.find("/lib/gcc/") != std::string::npos ||
                     folder.find("/lib64/gcc/") != std::string::npos || folder.find("/clang/") != std::string::npos;
    (own ? rule.folders : rule.system).push_back(folder);
  }
  rule.c_library_known = !c_library_headers().empty();
  for (const std::string& file : c_library_headers())
    for (const std::string& folder : rule.system)
      if (under(file, folder)) {
        std::string relative = file.substr(folder.size());
        if (!relative.empty() && relative[0] == '/') relative.erase(0, 1);
        if (!blocked(relative)) rule.files.insert(file);
        break;
      }

  // The command's own folders (Eigen's, beside the kit's) and its forced includes (the
  // precompiled geometry header): the kit wrote that command.
  std::vector<std::string> own;
  static const char* const kOptions[] = {"-include", "-isystem", "-iquote", "-idirafter", "-I"};
  for (std::size_t i = 1; i < command.size(); ++i) {
    const std::string& word = command[i];
    std::string value, option;
    for (const std::string o : kOptions) {
      if (word == o && i + 1 < command.size())
        value = command[++i];
      else if (o != "-include" && word.size() > o.size() && word.compare(0, o.size(), o) == 0)
        value = word.substr(o.size());
      else
        continue;
      option = o;
      break;
    }
    const bool forced = option == "-include";
    if (value.empty()) continue;
    value = normal(value);
    if (forced) {
      rule.files.insert(value);
      rule.files.insert(value + ".gch");
      continue;
    }
    own.push_back(value);
    const bool system = std::find(rule.system.begin(), rule.system.end(), value) != rule.system.end();
    if (!under(value, rule.kit) && !system) rule.folders.push_back(value);  // Eigen
  }
  rule.search = own;
  rule.search.insert(rule.search.end(), builtin.begin(), builtin.end());
  return rule;
}

std::vector<std::string> kit_paths(const Rule& rule, const std::string& lab_folder) {
  std::vector<std::string> out = {normal(lab_folder)};
  for (const std::string& file : rule.kit_files)
    if (!under(file, out.front())) out.push_back(file);
  return out;
}

std::vector<Header> split_output(const std::string& output, std::string* rest) {
  static const std::regex header(R"(^(\.+) (.+)$)");
  static const std::regex precompiled(R"(^[!x] /.*$)");
  std::vector<Header> headers;
  std::string kept;
  std::istringstream in(output);
  bool guards = false;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, header)) {
      headers.push_back({int(m[1].length()), m[2].str()});
      continue;
    }
    if (std::regex_match(line, precompiled)) continue;
    if (line == "Multiple include guards may be useful for:") {
      guards = true;
      continue;
    }
    if (guards && !line.empty() && line[0] == '/' && line.find(": ") == std::string::npos) continue;
    guards = false;
    kept += line + "\n";
  }
  if (rest) *rest = kept;
  return headers;
}

std::string audit(const Rule& rule, const std::vector<Header>& headers, const std::string& rest,
                  const std::string& source_path) {
  const std::string source = normal(source_path);
  std::vector<Offence> offences;
  const auto add = [&](const std::string& top, const std::string& path, int line) {
    for (const Offence& o : offences)
      if (o.top == top) return;
    offences.push_back({top, path, line ? line : line_of(rule, source, top)});
  };
  std::string top;
  for (const Header& h : headers) {
    const std::string path = normal(h.path);
    if (h.depth == 1) top = path;
    if (!allowed(rule, path)) add(top.empty() ? path : top, path, 0);
  }
  // A header the confined compiler could not see (the rest of the kit is hidden from
  // it): what it names is judged as if it had been read.
  static const std::regex hidden(
      R"(^(.+):([0-9]+):[0-9]+: fatal error: (.+): (No such file or directory|Permission denied)$)");
  std::istringstream in(rest);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, hidden) || !same_file(normal(m[1].str()), source)) continue;
    for (const std::string& candidate : candidates(rule, source, m[3].str()))
      if (exists(candidate)) {
        if (!allowed(rule, candidate)) add(candidate, candidate, std::stoi(m[2].str()));
        break;
      }
  }
  if (offences.empty()) return "";
  std::string text =
      "a lab file may include only its lab's header, the geometry types, Eigen and the standard library: "
      "yours includes ";
  for (std::size_t i = 0; i < offences.size() && i < 5; ++i) {
    const Offence& o = offences[i];
    text += (i ? "; " : "") + shown(rule, o.top);
    if (o.line) text += " (line " + std::to_string(o.line) + ")";
    if (o.path != o.top) text += ", which reads " + shown(rule, o.path);
  }
  if (offences.size() > 5) text += "; and " + std::to_string(offences.size() - 5) + " more";
  return text;
}

int compile_main(int argc, char** argv) {
  std::string kit, lab;
  int at = 2;  // after "labkit-runner lab-compile"
  for (; at + 1 < argc && std::string(argv[at]) != "--"; at += 2) {
    const std::string name = argv[at];
    if (name == "--kit")
      kit = argv[at + 1];
    else if (name == "--lab")
      lab = argv[at + 1];
    else
      break;
  }
  if (kit.empty() || lab.empty() || at + 1 >= argc || std::string(argv[at]) != "--") {
    std::fprintf(stderr, "usage: labkit-runner lab-compile --kit ROOT --lab FOLDER -- COMPILER ARGS...\n");
    return 2;
  }
  std::vector<std::string> command(argv + at + 1, argv + argc);
  std::string source, object;
  for (std::size_t i = 0; i + 1 < command.size(); ++i) {
    if (command[i] == "-c") source = command[i + 1];
    if (command[i] == "-o") object = command[i + 1];
  }
  // The rule (the compiler's folders, the C library's headers) is needed only for the
  // audit after the compile: it is worked out on the side while the compiler runs.
  std::future<Rule> rule = std::async(std::launch::async, rule_for, kit, lab, command);
  command.push_back("-H");
  Limits limits;
  limits.seconds = 3600;
  limits.kept_bytes = limits.flood_bytes = std::size_t(256) << 20;  // every header it read, or no build
  const Run r = run(command, {}, limits);
  std::string rest;
  const std::vector<Header> headers = split_output(r.output, &rest);
  std::fputs(rest.c_str(), stderr);
  const std::string problem = source.empty() ? "" : audit(rule.get(), headers, rest, source);
  if (!problem.empty()) {
    // FILE:LINE: error: as a compiler says it, so that an editor jumps to the include.
    std::smatch line;
    static const std::regex first_line(R"(\(line ([0-9]+)\))");
    const std::string at = std::regex_search(problem, line, first_line) ? ":" + line[1].str() : "";
    std::fprintf(stderr, "%s%s: error: %s\n", source.c_str(), at.c_str(), problem.c_str());
    if (!object.empty()) std::remove(object.c_str());
    return 1;
  }
  if (!r.started) std::fprintf(stderr, "labkit-runner lab-compile: cannot run %s\n", command[0].c_str());
  return r.ok() ? 0 : (r.exit_code > 0 ? r.exit_code : 1);
}

}  // namespace runner::includes
