#include "gradebook.h"

#include "results.h"
#include "untrusted.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace runner {

namespace {

// RFC 4180 records: quoted fields may hold commas, doubled quotes and line breaks.
std::vector<std::vector<std::string>> read_csv(const std::string& text, const std::string& path) {
  std::vector<std::vector<std::string>> records(1, std::vector<std::string>(1));
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    std::string& field = records.back().back();
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"' && field.empty()) {
      quoted = true;
    } else if (c == ',') {
      records.back().emplace_back();
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      records.emplace_back(1);
    } else {
      field += c;
    }
  }
  if (quoted) throw std::runtime_error(path + ": a quoted field is never closed");
  // Blank lines (and the one after the last line break) are no records.
  records.erase(
      std::remove_if(records.begin(), records.end(), [](const auto& r) { return r.size() == 1 && r[0].empty(); }),
      records.end());
  return records;
}

std::string lower(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

Roster load_roster(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read the roster " + path);
  std::ostringstream text;
  text << in.rdbuf();
  std::string content = text.str();
  if (content.rfind("\xEF\xBB\xBF", 0) == 0) content.erase(0, 3);  // a spreadsheet's byte-order mark
  const auto records = read_csv(content, path);
  if (records.empty()) throw std::runtime_error("the roster " + path + " is empty");
  const std::vector<std::string>& header = records.front();
  const auto at =
      std::find_if(header.begin(), header.end(), [](const std::string& h) { return lower(h) == "submission"; });
  if (at == header.end())
    throw std::runtime_error("the roster " + path +
                             " has no \"submission\" column: its header names the column holding each student's "
                             "submission name, beside the columns the gradebook matches on (e.g. Student, ID, SIS "
                             "User ID)");
  const std::size_t key = std::size_t(at - header.begin());
  if (header.size() < 2)
    throw std::runtime_error("the roster " + path +
                             " has only the submission column: add the columns your "
                             "gradebook matches students on (e.g. Student, ID, SIS User ID, or Email address)");
  Roster roster;
  for (std::size_t i = 0; i < header.size(); ++i)
    if (i != key) roster.columns.push_back(header[i]);
  std::map<std::string, std::size_t> seen;
  for (std::size_t r = 1; r < records.size(); ++r) {
    std::vector<std::string> record = records[r];
    if (record.size() != header.size())
      throw std::runtime_error("the roster " + path + ", record " + std::to_string(r + 1) + ": " +
                               std::to_string(record.size()) + " fields, the header has " +
                               std::to_string(header.size()));
    const std::string name = record[key];
    if (name.empty()) continue;  // a student with no submission name (or Canvas's "Points Possible" row)
    if (const auto [it, fresh] = seen.emplace(name, r + 1); !fresh)
      throw std::runtime_error("the roster " + path + " gives submission \"" + safe_line(name) +
                               "\" to two students (records " + std::to_string(it->second) + " and " +
                               std::to_string(r + 1) + ")");
    record.erase(record.begin() + std::ptrdiff_t(key));
    roster.names.push_back(name);
    roster.rows.push_back(record);
  }
  return roster;
}

Gradebook gradebook_csv(const std::vector<SubmissionGrade>& all, const std::string& assignment, const Roster* roster) {
  Gradebook book;
  const std::string column = assignment.empty() ? "Lab kit, all labs" : assignment;
  const auto row = [](const std::vector<std::string>& cells) {
    std::string line;
    for (std::size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + csv_field(cells[i]);
    return line + "\n";
  };
  if (!roster) {
    book.csv = row({"Student", column});
    for (const SubmissionGrade& s : all) book.csv += row({safe_line(s.name), points(s.score)});
    return book;
  }
  std::vector<std::string> header = roster->columns;
  header.push_back(column);
  book.csv = row(header);
  std::map<std::string, const SubmissionGrade*> by_name;
  for (const SubmissionGrade& s : all) by_name[s.name] = &s;
  std::vector<std::string> missing;
  for (std::size_t i = 0; i < roster->names.size(); ++i) {
    std::vector<std::string> cells = roster->rows[i];
    const auto found = by_name.find(roster->names[i]);
    cells.push_back(found == by_name.end() ? "" : points(found->second->score));
    if (found == by_name.end())
      missing.push_back(roster->names[i]);
    else
      by_name.erase(found);
    book.csv += row(cells);
  }
  if (!missing.empty()) {
    std::string names;
    for (std::size_t i = 0; i < missing.size() && i < 10; ++i) names += (i ? ", " : "") + safe_line(missing[i]);
    book.notes.push_back(std::to_string(missing.size()) + " student(s) of the roster have no submission (" + names +
                         (missing.size() > 10 ? ", ..." : "") +
                         "): their grade cells are empty, which Canvas and Moodle leave as they are");
  }
  for (const auto& [name, s] : by_name)
    book.notes.push_back("submission \"" + safe_line(name) + "\" (" + points(s->score) +
                         " points) is not on the roster: it is not in gradebook.csv; add it to the roster");
  return book;
}

}  // namespace runner
