#include "lab_build.h"
#include "common/text.h"
#include "includes.h"

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace runner {

namespace fs = std::filesystem;

namespace {

// A compile command as compile_commands.json writes it: words split by spaces, with
// double quotes and backslashes as a POSIX shell reads them.
std::vector<std::string> split_command(const std::string& command) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false, quoted = false;
  for (std::size_t i = 0; i < command.size(); ++i) {
    const char c = command[i];
    if (c == '\\' && i + 1 < command.size()) {
      word += command[++i];
      in_word = true;
    } else if (c == '"') {
      quoted = !quoted;
      in_word = true;
    } else if (c == ' ' && !quoted) {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

std::string absolute_in(const std::string& directory, const std::string& path) {
  return fs::path(path).is_absolute() ? path : (fs::path(directory) / path).lexically_normal().string();
}

std::set<std::string> defined_symbols(const std::vector<std::string>& files, bool dynamic) {
  std::set<std::string> symbols;
  for (const std::string& file : files) {
    std::vector<std::string> argv = {"nm", "-g", "-p", "--defined-only"};
    if (dynamic) argv.push_back("-D");
    argv.push_back(file);
    Limits limits;
    limits.seconds = 60;
    limits.kept_bytes = std::size_t(256) << 20;
    limits.flood_bytes = std::size_t(512) << 20;
    std::istringstream lines(run(argv, {}, limits).output);
    for (std::string line; std::getline(lines, line);) {
      std::istringstream words(line);
      std::string address, type, name;
      if (words >> address >> type >> name) symbols.insert(name);
    }
  }
  return symbols;
}

struct Symbol {
  char type;
  std::string name, readable;
};

// The global symbols of an object, mangled and demangled (nm -p keeps both in one order).
std::vector<Symbol> symbols_of(const std::string& object) {
  Limits limits;
  limits.seconds = 60;
  limits.kept_bytes = std::size_t(64) << 20;
  const auto lines_of = [&](bool demangle) {
    std::vector<std::string> argv = {"nm", "-g", "-p"};
    if (demangle) argv.push_back("-C");
    argv.push_back(object);
    std::vector<std::string> lines;
    std::istringstream in(run(argv, {}, limits).output);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  };
  const std::vector<std::string> mangled = lines_of(false), readable = lines_of(true);
  std::vector<Symbol> symbols;
  for (std::size_t i = 0; i < mangled.size() && i < readable.size(); ++i) {
    // "0000000000000000 T name" or "                 U name"
    const std::string& m = mangled[i];
    if (m.size() < 20) continue;
    const std::string& r = readable[i];
    symbols.push_back({m[17], m.substr(19), r.size() > 19 ? r.substr(19) : r});
  }
  return symbols;
}

// What a student file may not define or use: the kit's judging machinery, and the given
// tools where its lab's header does not offer them (`given`: it does).
std::string audit(const std::vector<Symbol>& symbols, const Lab& lab, const std::set<std::string>& kit, bool given) {
  static const std::regex judging(
      R"((^|[^A-Za-z0-9_:])(labkit::check|labkit::gen|labkit::lab[0-9]+::judge|labkit::remote|oracle|Catch|rc)::)");
  static const std::regex given_tools(R"((^|[^A-Za-z0-9_:])labkit::given::)");
  // Loading a library at run time would bring in what the compile refuses (GMP, MPFR).
  static const std::set<std::string> loading{"dlopen",      "dlmopen", "dlsym", "dlvsym", "__libc_dlopen_mode",
                                             "__libc_dlsym"};
  std::string problems;
  int count = 0;
  const auto problem = [&](const std::string& text) {
    if (++count <= 5) problems += "  " + text + "\n";
  };
  for (const Symbol& s : symbols) {
    const bool defined = s.type != 'U' && s.type != 'w' && s.type != 'v';
    const bool strong = defined && std::string("TDBRGSCi").find(s.type) != std::string::npos;
    if (defined && (s.name == "main" || s.name == "_start"))
      problem("defines " + s.readable + "(): the kit's tests have their own");
    else if (std::regex_search(s.readable, judging))
      problem((defined ? "defines " : "uses ") + s.readable + ", which belongs to the kit's tests, judge or oracle");
    else if (!defined && loading.count(s.name))
      problem("uses " + s.readable +
              "(): a lab's file loads no library at run time (exact arithmetic is the judge's alone)");
    else if (!given && std::regex_search(s.readable, given_tools))
      problem((defined ? "defines " : "uses ") + s.readable +
              ", a given tool of other labs: this lab's header does not offer it, so write your own");
    else if (strong && kit.count(s.name))
      problem("defines " + s.readable + ", which the kit already defines (it would replace the kit's)");
    else if (strong && runtime_symbols().count(s.name))
      problem("defines " + s.readable + ", which the C or C++ runtime defines (it would replace it)");
  }
  if (count > 5) problems += "  ... and " + std::to_string(count - 5) + " more\n";
  if (problems.empty()) return "";
  return "The lab's file may define only its own functions (namespace labkit::lab" + lab.id +
         ", or helpers of its own), and use only the lab's header and common/:\n" + problems;
}

// Constructors with a priority run before the kit's own (the harness reads its settings
// at priority 101): a student file has no use for them.
std::string audit_sections(const std::string& object) {
  Limits limits;
  limits.seconds = 60;
  const std::string sections = run({"objdump", "-h", object}, {}, limits).output;
  static const std::regex prioritised(R"(\.(init_array|ctors|preinit_array)\.[0-9]+)");
  if (!std::regex_search(sections, prioritised)) return "";
  return "The lab's file uses a constructor priority (__attribute__((constructor(N))) or init_priority): "
         "its code would run before the kit's own.\n";
}

std::string strip(std::string text, const std::vector<std::string>& prefixes) {
  for (const std::string& prefix : prefixes)
    for (std::size_t at; !prefix.empty() && (at = text.find(prefix)) != std::string::npos;)
      text.erase(at, prefix.size());
  return text;
}

// A folder the graded uid owned, made the grader's again (readable by others: each step
// runs its program under a uid of its own).
void reclaim(const fs::path& folder) {
  if (geteuid() != 0) return;
  std::error_code ignored;
  const auto own = [](const fs::path& p) {
    if (lchown(p.c_str(), 0, 0) == 0)
      chmod(p.c_str(), fs::is_directory(p) ? 0755 : (access(p.c_str(), X_OK) == 0 ? 0755 : 0644));
  };
  own(folder);
  for (auto it = fs::recursive_directory_iterator(folder, ignored); it != fs::recursive_directory_iterator();
       it.increment(ignored))
    if (!it->is_symlink(ignored)) own(it->path());
}

Limits build_limits(double seconds) {
  Limits limits;
  limits.seconds = seconds;
  limits.memory_bytes = std::size_t(4) << 30;
  limits.file_bytes = std::size_t(512) << 20;
  limits.kept_bytes = 64 * 1024;
  limits.flood_bytes = 16u << 20;
  return limits;
}

}  // namespace

std::string recipe_record(const Paths& paths, const Lab& lab) {
  return paths.build + "/grading/" + lab.stem() + ".json";
}

LabRecipe load_recipe(const Paths& paths, const Lab& lab) {
  LabRecipe recipe;
  const std::string record_path = recipe_record(paths, lab);
  if (!fs::exists(record_path))
    throw std::runtime_error("the kit's build has no " + record_path + " (reconfigure the build)");
  const nlohmann::json record = nlohmann::json::parse(labkit::read_file(record_path));
  recipe.student_library = record.at("student_library").get<std::string>();
  const std::string link_record = record.at("link_record").get<std::string>();

  // The link command, as the kit last ran it.
  const std::string link = labkit::read_file(link_record);
  std::vector<std::string> words;
  for (std::size_t at = 0; at < link.size();) {
    const std::size_t end = link.find('\0', at);
    words.push_back(link.substr(at, end - at));
    at = end == std::string::npos ? link.size() : end + 1;
  }
  if (words.size() < 3)
    throw std::runtime_error("the kit has not linked " + lab.answerer("student") + " yet (" + link_record + ")");
  recipe.link.directory = words.front();
  recipe.link.argv.assign(words.begin() + 1, words.end());

  // The compile command of each student file, as the kit compiles the stub.
  const nlohmann::json database = nlohmann::json::parse(labkit::read_file(paths.build + "/compile_commands.json"));
  for (const std::string& file : lab.student_files) {
    if (fs::path(file).extension() != ".cpp") continue;
    const std::string source = (fs::path(paths.source) / file).lexically_normal().string();
    for (const auto& entry : database)
      if (absolute_in(entry.value("directory", ""), entry.value("file", "")) == source) {
        Command c;
        c.directory = entry.value("directory", "");
        c.argv = entry.contains("arguments") ? entry["arguments"].get<std::vector<std::string>>()
                                             : split_command(entry.value("command", ""));
        recipe.compile[file] = c;
      }
    if (!recipe.compile.count(file)) throw std::runtime_error("compile_commands.json has no command for " + file);
  }

  std::vector<std::string> inputs;
  for (const std::string& word : recipe.link.argv) {
    const std::string path = absolute_in(recipe.link.directory, word);
    const std::string ext = fs::path(path).extension().string();
    if ((ext == ".a" || ext == ".o") && path != recipe.student_library && fs::exists(path)) inputs.push_back(path);
  }
  recipe.kit_symbols = defined_symbols(inputs, false);
  return recipe;
}

const std::set<std::string>& runtime_symbols() {
  static const std::set<std::string> symbols = [] {
    std::vector<std::string> libraries;
    for (const char* name : {"libc.so.6", "libm.so.6", "libstdc++.so.6", "libgcc_s.so.1"}) {
      Limits limits;
      limits.seconds = 30;
      std::string path = run({"c++", "-print-file-name=" + std::string(name)}, {}, limits).output;
      while (!path.empty() && (path.back() == '\n' || path.back() == ' ')) path.pop_back();
      if (fs::path(path).is_absolute() && fs::exists(path)) libraries.push_back(fs::canonical(path).string());
    }
    return defined_symbols(libraries, true);
  }();
  return symbols;
}

namespace {

// One compile of the student's file, as the recipe's command gives it, rewritten: its
// source the submission's copy, its object in `out`, no dependency files, and `-H` (the
// headers it reads, for the audit). `readable`: what the sandbox lets the compiler read.
struct CompileCommand {
  std::vector<std::string> argv, readable;
};
CompileCommand compile_command(const Paths& paths, const std::string& lab_folder, const Command& command,
                               const std::string& source, const std::string& copy, const std::string& object,
                               const includes::Rule& rule, const std::string& src) {
  CompileCommand c;
  c.readable = {src};
  for (std::size_t i = 0; i < command.argv.size(); ++i) {
    std::string word = command.argv[i];
    if (word == "-o" && i + 1 < command.argv.size()) {
      c.argv.insert(c.argv.end(), {"-o", object});
      ++i;
      continue;
    }
    if ((word == "-MF" || word == "-MT" || word == "-MQ") && i + 1 < command.argv.size()) {
      ++i;
      continue;
    }
    if (word == "-MD" || word == "-MMD") continue;
    if (absolute_in(command.directory, word) == source) word = copy;
    c.argv.push_back(word);
    // What the compiler reads: include folders and forced includes (the precompiled
    // header beside them). The kit's root stands for common/ and labs/ only.
    std::string path = word;
    if (word.rfind("-I", 0) == 0) path = word.substr(2);
    if (path.empty() || path[0] != '/' || !fs::exists(path)) continue;
    if (fs::equivalent(path, paths.source)) {
      const std::vector<std::string> allowed = includes::kit_paths(rule, lab_folder);
      c.readable.insert(c.readable.end(), allowed.begin(), allowed.end());
    } else if (fs::is_directory(path)) {
      if (path.rfind(paths.source + "/", 0) == 0 || path.rfind(paths.build + "/", 0) == 0) c.readable.push_back(path);
    } else if (path.rfind(paths.build + "/", 0) == 0) {
      c.readable.push_back(fs::path(path).parent_path().string());
    }
  }
  c.argv.push_back("-H");
  return c;
}

// The link, as the recipe's command gives it: the student library replaced by the
// compiled objects, the program written to `binary`.
CompileCommand link_command(const LabRecipe& recipe, const std::vector<std::string>& objects,
                            const std::string& binary) {
  CompileCommand c;
  for (std::size_t i = 0; i < recipe.link.argv.size(); ++i) {
    const std::string& word = recipe.link.argv[i];
    if (word == "-o" && i + 1 < recipe.link.argv.size()) {
      c.argv.insert(c.argv.end(), {"-o", binary});
      ++i;
      continue;
    }
    const std::string path = absolute_in(recipe.link.directory, word);
    if (path == recipe.student_library) {
      c.argv.insert(c.argv.end(), objects.begin(), objects.end());
      // No debug sections: a graded binary is run, never debugged, and this makes it
      // 4 MB instead of 50 (a class of twenty writes a gigabyte less) and links faster.
      c.argv.push_back("-Wl,--strip-debug");
      continue;
    }
    const bool file = word[0] != '-' && fs::is_regular_file(path);
    c.argv.push_back(file ? path : word);
    if (file) c.readable.push_back(path);
  }
  return c;
}

}  // namespace

LabBuild build_lab(const Paths& paths, const Lab& lab, const LabRecipe& recipe,
                   const std::map<std::string, std::string>& files, const std::string& folder, const Sandbox& sandbox,
                   double seconds) {
  const auto start = std::chrono::steady_clock::now();
  // The commands share `seconds`: each gets what the ones before it left.
  const auto left = [&] {
    return std::max(1.0, seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  };
  LabBuild b;
  const fs::path src = fs::path(folder) / "src", out = fs::path(folder) / "build";
  fs::create_directories(out);
  // The student's files alone, at their manifest paths: `#include "x.h"` finds the kit's
  // header, never one the submission brought.
  for (const auto& [manifest_path, file] : files) {
    fs::create_directories((src / manifest_path).parent_path());
    fs::copy_file(file, src / manifest_path, fs::copy_options::overwrite_existing);
    fs::permissions(src / manifest_path, fs::perms(0644));
  }
  const std::vector<std::string> noise = {src.string() + "/", paths.source + "/", paths.build + "/"};

  std::vector<std::string> objects;
  const std::string lab_folder = paths.source + "/labs/" + lab.stem();
  for (const auto& [manifest_path, command] : recipe.compile) {
    const std::string source = (fs::path(paths.source) / manifest_path).lexically_normal().string();
    const std::string object = (out / (fs::path(manifest_path).stem().string() + ".o")).string();
    // What the file may include (runner/includes.h): the compile sees only that of the
    // kit's tree, and the headers it read are audited against it.
    includes::Rule rule = includes::rule_for(paths.source, lab_folder, command.argv);
    rule.folders.push_back((src / manifest_path).parent_path().string());  // the submission's own files
    const CompileCommand compile =
        compile_command(paths, lab_folder, command, source, (src / manifest_path).string(), object, rule, src.string());
    Limits limits = build_limits(left());
    limits.kept_bytes = limits.flood_bytes = std::size_t(64) << 20;  // every header it read, or no build
    const Confined c = sandbox.confine(compile.argv, out.string(), compile.readable, limits);
    const Run r = run(c.argv, {}, c.limits, out.string());
    std::string output;
    const std::vector<includes::Header> headers = includes::split_output(r.output, &output);
    std::string refused = includes::audit(rule, headers, output, (src / manifest_path).string());
    if (!refused.empty()) {
      refused[0] = char(std::toupper(static_cast<unsigned char>(refused[0])));
      b.errors = strip(refused, noise) + ".\n";
      if (!r.ok()) b.errors += "\n" + strip(first_errors(output, paths.source), noise);
      return b;
    }
    if (!r.ok()) {
      b.timed_out = r.timed_out;
      b.errors = r.timed_out ? "the compiler did not finish within " + std::to_string(int(seconds)) + " s\n"
                             : strip(first_errors(output, paths.source), noise);
      if (b.errors.empty()) b.errors = strip(output.substr(0, 2000), noise);
      return b;
    }
    const bool given = std::any_of(rule.kit_files.begin(), rule.kit_files.end(),
                                   [](const std::string& f) { return f.find("/common/given/") != std::string::npos; });
    const std::string problems = audit(symbols_of(object), lab, recipe.kit_symbols, given) + audit_sections(object);
    if (!problems.empty()) {
      b.errors = problems;
      return b;
    }
    objects.push_back(object);
  }

  const std::string binary = (out / lab.answerer("submission")).string();
  const CompileCommand link = link_command(recipe, objects, binary);
  const Confined c = sandbox.confine(link.argv, out.string(), link.readable, build_limits(left()));
  const Run r = run(c.argv, {}, c.limits, out.string());
  if (!r.ok()) {
    b.timed_out = r.timed_out;
    b.errors = strip(r.output.substr(0, 3000), noise);
    return b;
  }
  // Back to the grader: the uid that built it is leased to other runs next, and must
  // never be able to change this submission's program.
  reclaim(out);
  b.ok = true;
  b.binary = binary;
  b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return b;
}

}  // namespace runner
