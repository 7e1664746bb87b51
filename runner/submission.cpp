#include "submission.h"

#include <algorithm>
#include <filesystem>

namespace runner {

namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t kLargestStudentFile = 1 << 20;
constexpr int kMostEntries = 20000;  // a submission folder is walked this far, no further

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

enum class Format { folder, zip, tar_gz, tar, unknown };

Format format_of(const std::string& path) {
  std::error_code e;
  if (fs::is_directory(path, e)) return Format::folder;
  if (ends_with(path, ".zip")) return Format::zip;
  if (ends_with(path, ".tar.gz") || ends_with(path, ".tgz")) return Format::tar_gz;
  if (ends_with(path, ".tar")) return Format::tar;
  return Format::unknown;
}

// Unpacks only the files named like a student file, confined to `into`.
std::string unpack(const std::string& archive, Format format, const std::vector<std::string>& wanted,
                   const std::string& into, const Sandbox& sandbox) {
  std::vector<std::string> argv;
  if (format == Format::zip) {
    argv = {"unzip", "-qq", "-o", archive};
    for (const std::string& w : wanted) argv.push_back("*" + fs::path(w).filename().string());
    argv.insert(argv.end(), {"-d", into});
  } else {
    argv = {"tar", format == Format::tar_gz ? "-xzf" : "-xf", archive, "-C", into, "--no-same-owner",
            "--no-same-permissions", "--wildcards"};
    for (const std::string& w : wanted) argv.push_back("*" + fs::path(w).filename().string());
  }
  Limits limits;
  limits.seconds = 60;
  limits.memory_bytes = std::size_t(1) << 30;
  limits.file_bytes = 8 << 20;
  const Confined c = sandbox.confine(argv, into, {fs::absolute(archive).string()}, limits);
  const Run r = run(c.argv, {}, c.limits, into);
  // "nothing matched" (unzip 11, tar 2) is an empty submission, not a broken one.
  if (r.ok() || (r.started && !r.timed_out && r.signal == 0 && (r.exit_code == 11 || r.exit_code == 2))) return "";
  return "could not unpack " + fs::path(archive).filename().string() + ": " + r.output.substr(0, 300);
}

// Regular files under `root`, by path relative to it; symlinks are never followed.
std::vector<std::string> regular_files(const fs::path& root) {
  std::vector<std::string> files;
  std::error_code e;
  int seen = 0;
  for (auto it = fs::recursive_directory_iterator(root, fs::directory_options::skip_permission_denied, e);
       !e && it != fs::recursive_directory_iterator() && ++seen < kMostEntries; it.increment(e)) {
    const fs::file_status s = it->symlink_status(e);
    if (!e && fs::is_regular_file(s)) files.push_back(fs::relative(it->path(), root, e).generic_string());
  }
  return files;
}

// The submission's file for manifest path `wanted`: at that path; else at a path ending
// with it (a zipped folder); else the one file with its name.
std::string find(const std::vector<std::string>& files, const std::string& wanted, std::string* note) {
  const std::string name = fs::path(wanted).filename().string();
  std::vector<std::string> by_path, by_name;
  for (const std::string& f : files) {
    if (f == wanted) return f;
    if (ends_with(f, "/" + wanted)) by_path.push_back(f);
    if (f == name || ends_with(f, "/" + name)) by_name.push_back(f);
  }
  const auto shortest = [](std::vector<std::string>& v) {
    std::sort(v.begin(), v.end(), [](const std::string& a, const std::string& b) {
      return a.size() != b.size() ? a.size() < b.size() : a < b;
    });
    return v.front();
  };
  if (!by_path.empty()) return shortest(by_path);
  if (by_name.empty()) return "";
  const std::string chosen = shortest(by_name);
  if (by_name.size() > 1) *note = "several files are named " + name + "; graded " + chosen;
  return chosen;
}

}  // namespace

std::string submission_name(const std::string& path) {
  std::string name = fs::path(path).lexically_normal().filename().string();
  if (name.empty()) name = fs::path(path).lexically_normal().parent_path().filename().string();
  for (const char* suffix : {".tar.gz", ".tgz", ".zip", ".tar"})
    if (ends_with(name, suffix)) name.resize(name.size() - std::string(suffix).size());
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return name.empty() || name[0] == '.' ? "submission" + name : name;
}

std::vector<std::string> class_members(const std::string& path, const std::vector<const Lab*>& labs) {
  std::error_code e;
  if (!fs::is_directory(path, e) || fs::exists(fs::path(path) / "labs", e)) return {};
  std::vector<std::string> names;
  for (const Lab* lab : labs)
    for (const std::string& f : lab->student_files) names.push_back(fs::path(f).filename().string());
  const auto is_student_file = [&](const fs::path& p) {
    return std::find(names.begin(), names.end(), p.filename().string()) != names.end();
  };
  std::vector<std::string> archives, folders, all_folders;  // folders: those with a student file
  for (const fs::directory_entry& entry : fs::directory_iterator(path, e)) {
    const fs::file_status s = entry.symlink_status(e);
    if (fs::is_regular_file(s) && is_student_file(entry.path())) return {};  // files uploaded one by one
    if (fs::is_regular_file(s) && format_of(entry.path().string()) != Format::unknown) archives.push_back(entry.path().string());
    if (!fs::is_directory(s) || entry.path().filename().string()[0] == '.') continue;
    all_folders.push_back(entry.path().string());
    const std::vector<std::string> inside = regular_files(entry.path());
    if (std::any_of(inside.begin(), inside.end(), [&](const std::string& f) { return is_student_file(f); }))
      folders.push_back(entry.path().string());
  }
  if (archives.empty() && folders.size() < 2) return {};
  // A class: every archive and folder in it is a student's, an empty one too (it scores 0).
  std::vector<std::string> members = archives;
  members.insert(members.end(), all_folders.begin(), all_folders.end());
  std::sort(members.begin(), members.end());
  return members;
}

Submission read_submission(const std::string& path, const std::vector<const Lab*>& labs, const std::string& work,
                           const Sandbox& sandbox) {
  Submission s;
  s.name = submission_name(path);
  s.source = path;
  std::vector<std::string> wanted;
  for (const Lab* lab : labs) wanted.insert(wanted.end(), lab->student_files.begin(), lab->student_files.end());

  fs::path root = path;
  const Format format = format_of(path);
  std::error_code e;
  if (!fs::exists(path, e)) {
    s.error = "no such file or folder: " + path;
    return s;
  }
  if (format == Format::unknown) {
    s.error = path + " is neither a folder nor a .zip, .tar.gz or .tar file";
    return s;
  }
  if (format != Format::folder) {
    // A copy the confined unpacker can read, wherever the original lies.
    const fs::path archive = fs::path(work) / ("submission" + fs::path(path).extension().string());
    fs::copy_file(path, archive, fs::copy_options::overwrite_existing, e);
    if (e) {
      s.error = "cannot read " + path + ": " + e.message();
      return s;
    }
    fs::permissions(archive, fs::perms(0644));
    root = fs::path(work) / "unpacked";
    fs::create_directories(root);
    s.error = unpack(archive.string(), format, wanted, root.string(), sandbox);
    if (!s.error.empty()) return s;
  }

  const std::vector<std::string> files = regular_files(root);
  for (const std::string& w : wanted) {
    std::string note;
    const std::string found = find(files, w, &note);
    if (found.empty()) continue;
    const fs::path file = root / found;
    if (fs::file_size(file, e) > kLargestStudentFile) {
      s.notes.push_back(found + " is larger than 1 MB and was not graded");
      continue;
    }
    s.files[w] = file.string();
    if (!note.empty()) s.notes.push_back(note);
    else if (found != w) s.notes.push_back("graded " + found + " as " + w);
  }
  return s;
}

}  // namespace runner
