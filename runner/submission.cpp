#include "submission.h"
#include "archive.h"
#include "untrusted.h"

#include <algorithm>
#include <filesystem>

namespace runner {

namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t kLargestStudentFile = 1 << 20;
constexpr std::uintmax_t kLargestArchive = std::uintmax_t(1) << 30;  // copied whole for the confined unpacker
constexpr int kMostEntries = 20000;  // a submission folder is walked this far, no further
constexpr std::size_t kMostRefusalsShown = 10;

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

// Takes `file` (`found` in the submission) as the student file `wanted`: copied into the
// grader's own folder with checks (untrusted.h), so that what is built is what was
// checked, whatever the file's folder holds later.
void take(const std::string& wanted, const std::string& found, const std::string& file, const std::string& work,
          const std::string& note, Submission& s) {
  const fs::path copy = fs::path(work) / "taken" / wanted;
  fs::create_directories(copy.parent_path());
  const std::string why = copy_untrusted_file(file, copy.string(), kLargestStudentFile);
  if (!why.empty()) {  // a FIFO, a link or a file too large to be a student's: not built
    s.notes.push_back(safe_line(found) + " " + why + " and was not graded");
    return;
  }
  s.files[wanted] = copy.string();
  if (!note.empty())
    s.notes.push_back(note);
  else if (found != wanted)
    s.notes.push_back("graded " + safe_line(found) + " as " + wanted);
}

void read_folder(const std::string& root, const std::vector<std::string>& wanted, const std::string& work,
                 Submission& s) {
  const std::vector<std::string> files = regular_files(root);
  for (const std::string& w : wanted) {
    std::string note;
    const std::string found = find(files, w, &note);
    if (!found.empty()) take(w, found, root + "/" + found, work, note, s);
  }
}

bool named_like_a_student_file(const ArchiveMember& m, const std::vector<std::string>& wanted) {
  const std::string name = m.name.substr(m.name.find_last_of("/\\") + 1);
  return std::any_of(wanted.begin(), wanted.end(),
                     [&](const std::string& w) { return fs::path(w).filename() == name; });
}

// The files never unpacked, each with why (once, however many copies): those named like a
// student file first (they may be why a lab is missing), at most ten in all.
void note_refusals(const ArchiveListing& listing, const std::vector<std::string>& wanted, Submission& s) {
  std::vector<std::string> refusals;
  std::size_t named_like_ours = 0;
  for (const ArchiveMember& m : listing.members) {
    if (m.refused.empty() || m.kind == ArchiveMember::Kind::folder) continue;
    const std::string line = "not unpacked: " + safe_line(m.name) + " " + m.refused;
    if (std::find(refusals.begin(), refusals.end(), line) != refusals.end()) continue;
    if (named_like_a_student_file(m, wanted))
      refusals.insert(refusals.begin() + long(named_like_ours++), line);
    else
      refusals.push_back(line);
  }
  for (std::size_t i = 0; i < refusals.size() && i < kMostRefusalsShown; ++i) s.notes.push_back(refusals[i]);
  if (refusals.size() > kMostRefusalsShown)
    s.notes.push_back("... and " + std::to_string(refusals.size() - kMostRefusalsShown) + " more members not unpacked");
}

ArchiveFormat archive_format(Format format) {
  return format == Format::zip      ? ArchiveFormat::zip
         : format == Format::tar_gz ? ArchiveFormat::tar_gz
                                    : ArchiveFormat::tar;
}

// An archive: listed, its unsafe members refused (each named in a note, with why), and
// each student file found among the others unpacked on its own. One bad member costs
// only itself.
void read_archive(const std::string& path, Format format, const std::vector<std::string>& wanted,
                  const std::string& work, const Sandbox& sandbox, Submission& s) {
  const ArchiveFormat kind = archive_format(format);
  // A copy the confined unpacker can read, wherever the original lies, and the grader's own.
  const std::string archive = work + "/submission" +
                              (kind == ArchiveFormat::zip   ? ".zip"
                               : kind == ArchiveFormat::tar ? ".tar"
                                                            : ".tar.gz");
  std::error_code e;
  const std::string why = copy_untrusted_file(fs::canonical(path, e).string(), archive, kLargestArchive);
  if (!why.empty()) {  // not a regular file, or over 1 GB: nothing in it is read
    s.error = path + " " + why;
    return;
  }
  fs::create_directories(work + "/listing");
  const ArchiveListing listing = list_archive(archive, kind, kLargestStudentFile, work + "/listing", sandbox);
  if (!listing.error.empty() && listing.members.empty()) {  // not an archive, or one without a readable member
    s.error = "could not unpack " + fs::path(path).filename().string() + ": " + listing.error;
    return;
  }
  if (!listing.error.empty()) s.notes.push_back(listing.error);

  std::vector<std::string> paths;  // the members that may be unpacked
  std::map<std::string, const ArchiveMember*> by_path;
  for (const ArchiveMember& m : listing.members)
    if (m.refused.empty() && m.kind == ArchiveMember::Kind::file) {
      paths.push_back(m.path);
      by_path[m.path] = &m;
    }
  for (std::size_t i = 0; i < wanted.size(); ++i) {
    std::string note;
    const std::string found = find(paths, wanted[i], &note);
    if (found.empty()) continue;
    const std::string into = work + "/unpacked/" + std::to_string(i);
    fs::create_directories(into);
    const UnpackedMember u = unpack_member(archive, kind, *by_path.at(found), kLargestStudentFile, into, sandbox);
    if (!u.error.empty())
      s.notes.push_back("not unpacked: " + safe_line(found) + " " + u.error);
    else
      take(wanted[i], found, u.file, work, note, s);
  }
  note_refusals(listing, wanted, s);
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

std::string name_clashes(const std::vector<std::string>& submissions, const std::vector<std::string>& reserved) {
  std::map<std::string, std::vector<std::string>> by_name;
  for (const std::string& path : submissions) by_name[submission_name(path)].push_back(path);
  std::string clashes;
  for (const auto& [name, paths] : by_name) {
    const bool taken = std::find(reserved.begin(), reserved.end(), name) != reserved.end();
    if (paths.size() < 2 && !taken) continue;
    clashes += "  " + name + (taken ? " (the class's own " + name + ")" : "") + ":";
    for (const std::string& path : paths) clashes += " " + safe_line(path);
    clashes += "\n";
  }
  return clashes;
}

namespace {

// A student file at its place in the kit (labs/NN_name/file) under `folder`, or "".
std::string student_file_in_place(const fs::path& folder, const std::vector<const Lab*>& labs) {
  std::error_code e;
  for (const Lab* lab : labs)
    for (const std::string& f : lab->student_files)
      if (fs::is_regular_file(fs::symlink_status(folder / f, e))) return f;
  return "";
}

std::string listed(const std::vector<std::string>& paths) {
  std::string text;
  for (std::size_t i = 0; i < paths.size() && i < 3; ++i)
    text += (i ? ", " : "") + safe_line(fs::path(paths[i]).filename().string());
  return text + (paths.size() > 3 ? ", ..." : "");
}

}  // namespace

ClassFolder class_members(const std::string& path, const std::vector<const Lab*>& labs) {
  std::error_code e;
  if (!fs::is_directory(path, e)) return {};
  std::vector<std::string> names;
  for (const Lab* lab : labs)
    for (const std::string& f : lab->student_files) names.push_back(fs::path(f).filename().string());
  const auto is_student_file = [&](const fs::path& p) {
    return std::find(names.begin(), names.end(), p.filename().string()) != names.end();
  };
  // Its own labs/ (a student file at its place in the kit) makes a folder one student's;
  // a folder merely named labs may be one student's among a class.
  const std::string in_place = student_file_in_place(path, labs);
  const std::string own_labs = in_place.substr(0, in_place.find('/'));
  std::vector<std::string> archives, folders, all_folders;  // folders: those with a student file
  for (const fs::directory_entry& entry : fs::directory_iterator(path, e)) {
    const fs::file_status s = entry.symlink_status(e);
    const std::string name = entry.path().filename().string();
    if (fs::is_regular_file(s) && is_student_file(entry.path())) return {};  // files uploaded one by one
    if (fs::is_regular_file(s) && format_of(entry.path().string()) != Format::unknown)
      archives.push_back(entry.path().string());
    if (!fs::is_directory(s) || name[0] == '.') continue;
    all_folders.push_back(entry.path().string());
    const std::vector<std::string> inside = regular_files(entry.path());
    if (name != own_labs &&
        std::any_of(inside.begin(), inside.end(), [&](const std::string& f) { return is_student_file(f); }))
      folders.push_back(entry.path().string());
  }
  if (archives.empty() && folders.size() < 2) return {};
  // One student's labs/, and other students' work beside it: which is it? Not guessed.
  if (!in_place.empty()) {
    std::vector<std::string> others = archives;
    others.insert(others.end(), folders.begin(), folders.end());
    return {{},
            safe_line(path) + " holds " + in_place + ", as one student's submission does, and also " + listed(others) +
                ", as a class does: grade the submissions it holds by name (labkit grade " + safe_line(path) +
                "/*), or move its " + own_labs + "/ into a folder of its own"};
  }
  // A class: every archive and folder in it is a student's, an empty one too (it scores 0).
  std::vector<std::string> members = archives;
  members.insert(members.end(), all_folders.begin(), all_folders.end());
  std::sort(members.begin(), members.end());
  return {members, ""};
}

Submissions find_submissions(const std::vector<std::string>& named, const std::vector<const Lab*>& labs,
                             const std::vector<std::string>& class_files) {
  Submissions found;
  found.a_class = named.size() > 1;
  for (const std::string& path : named) {
    const ClassFolder folder = class_members(path, labs);
    if (!folder.error.empty()) {
      found.error = folder.error;
      return found;
    }
    if (folder.members.empty()) {
      found.paths.push_back(path);
      continue;
    }
    found.classes.push_back(safe_line(path) + " holds " + std::to_string(folder.members.size()) +
                            " submissions: graded one by one");
    found.paths.insert(found.paths.end(), folder.members.begin(), folder.members.end());
    found.a_class = true;
  }
  const std::string clashes = found.a_class ? name_clashes(found.paths, class_files) : "";
  if (!clashes.empty())
    found.error =
        "each submission's results go to OUT/<name>/, <name> being its file's name without .zip, .tar.gz "
        "or .tar; these names cannot be told apart, so nothing was graded (rename the files):\n" +
        clashes.substr(0, clashes.size() - 1);
  return found;
}

Submission read_submission(const std::string& path, const std::vector<const Lab*>& labs, const std::string& work,
                           const Sandbox& sandbox) {
  Submission s;
  s.name = submission_name(path);
  s.source = path;
  std::vector<std::string> wanted;
  for (const Lab* lab : labs) wanted.insert(wanted.end(), lab->student_files.begin(), lab->student_files.end());

  const Format format = format_of(path);
  std::error_code e;
  if (!fs::exists(path, e))
    s.error = "no such file or folder: " + path;
  else if (format == Format::unknown)
    s.error = path + " is neither a folder nor a .zip, .tar.gz or .tar file";
  else if (format == Format::folder)
    read_folder(path, wanted, work, s);
  else
    read_archive(path, format, wanted, work, sandbox, s);
  return s;
}

}  // namespace runner
