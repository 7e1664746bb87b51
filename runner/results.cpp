#include "results.h"
#include "terminal.h"
#include "untrusted.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace runner {

namespace {

std::string lab_state(const LabGrade& l) {
  switch (l.state) {
    case LabGrade::State::missing: return "not submitted";
    case LabGrade::State::not_built: return "does not compile";
    case LabGrade::State::pending: return "not graded yet";
    case LabGrade::State::out_of_time: return "not graded: no time";
    case LabGrade::State::graded: break;
  }
  return "";
}

// A step the grader has not run yet: grading stopped first (a time-out of the whole run).
const char* const kNotRunYet = "not graded: grading stopped before this step ran (a time-out of the whole run?)";

std::string step_state(const LabGrade& l, const StepGrade& g) {
  if (l.state != LabGrade::State::graded) return lab_state(l);
  return g.graded ? status_word(g.status) : "not graded yet";
}

std::string lab_heading(const LabGrade& l) { return "Lab " + l.lab->id + "  " + l.lab->title; }

std::string step_name(const StepGrade& s) {
  return "step " + std::to_string(s.step->number) + " (" + s.step->tag + "): " + s.step->title;
}

// What a lab's build said, on lines of their own after `indent`: a compiler's errors
// (or the audit's, naming the file's symbols) are the student's text and are quoted;
// the kit's own reason (a missing file) is not.
std::string build_text(const LabGrade& l, const std::string& indent) {
  if (l.state == LabGrade::State::not_built) return quoted_lines(l.build_output, indent);
  return indent + term::indent(l.build_output, indent);
}

// Where the cases come from, never the seed itself.
std::string seed_text(const GradingRun& run) {
  if (run.seed_kind == "secret") return "secret, its own cases for each submission (from the secret and its files)";
  return run.seed_kind;
}

// Titles longer than this are cut in the table.
constexpr std::size_t kLongestTitle = 72;

// Columns of text on a terminal: one per character (UTF-8 continuation bytes add none).
std::size_t columns(const std::string& text) {
  std::size_t n = 0;
  for (const unsigned char c : text) n += (c & 0xC0) != 0x80;
  return n;
}

// A cell of the table, `width` columns: the text and at least two spaces, or the text cut
// with "…" to leave them, so that no cell ever touches the next.
std::string cell(const std::string& text, std::size_t width) {
  if (columns(text) + 2 <= width) return term::pad(text, width);
  if (width < 3) return text + "  ";
  std::string cut;
  std::size_t n = 0;
  for (const char c : text) {
    const bool starts = (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    if (starts && n++ == width - 3) break;
    cut += c;
  }
  return term::pad(cut + "\xE2\x80\xA6", width);  // U+2026 HORIZONTAL ELLIPSIS
}

std::string seconds_text(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", s);
  return buffer;
}

}  // namespace

std::string xml_escape(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      case '\n':
      case '\t':
      case '\r': out += char(c); break;
      default:
        if (c < 0x20)
          out += "?";  // not allowed in XML 1.0, even escaped
        else
          out += char(c);
    }
  }
  return out;
}

std::string points(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", std::floor(x * 100 + 0.5) / 100);
  std::string s = buffer;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string table(const SubmissionGrade& s, const GradingRun& run) {
  std::ostringstream out;
  out << "Submission " << safe_line(s.name) << "   (" << safe_line(s.source) << ")\n";
  if (!run.assignment.empty()) out << "  assignment: " << run.assignment << "\n";
  out << "  seed: " << seed_text(run) << ", " << (run.cases ? std::to_string(run.cases) : std::string("the default"))
      << " random cases per query; sandbox: " << run.sandbox << "\n";
  if (!run.regrade.empty())
    out << "  regrade: " << run.regrade << "   (the same files and secret draw the same cases)\n";
  if (!run.limits.empty()) out << "  limits: " << run.limits << "\n";
  if (s.budget > 0)
    out << "  time budget: " << points(s.budget_used) << " s of " << points(s.budget) << " s used"
        << (s.budget_note.empty() ? "" : "; " + s.budget_note) << "\n";
  if (!s.error.empty()) out << "  could not be read: " << quoted_after_label(s.error, "    ") << "\n";
  for (const std::string& note : s.notes) out << "  note: " << safe_line(note) << "\n";
  // The columns: each as wide as its widest cell and two spaces, titles cut with "…" past
  // kLongestTitle, so that no cell ever runs into the next.
  const auto build_cell = [](const LabGrade& l) {
    return l.state == LabGrade::State::graded ? "built in " + seconds_text(l.build_seconds) + " s" : lab_state(l);
  };
  const auto points_cell = [](double score, double max) { return points(score) + " / " + points(max); };
  std::size_t title = 0, heading = 0, state = 0, score = points_cell(s.score, s.max_score).size();
  for (const LabGrade& l : s.labs) {
    heading = std::max(heading, std::min(kLongestTitle, columns(lab_heading(l))));
    state = std::max(state, columns(build_cell(l)));
    score = std::max(score, points_cell(l.score, l.max_score).size());
    for (const StepGrade& g : l.steps) {
      title = std::max(title, std::min(kLongestTitle, columns(g.step->title)));
      state = std::max(state, columns(step_state(l, g)));
      score = std::max(score, points_cell(g.score, g.step->points).size());
    }
  }
  // A step's line is indented 2 more than its lab's, and starts with its number and tag.
  const std::size_t left = std::max(heading + 2, 2 + 4 + 8 + title + 2);
  state += 2;
  score += 2;
  for (const LabGrade& l : s.labs) {
    out << "\n  " << cell(lab_heading(l), left) << cell(build_cell(l), state) << points_cell(l.score, l.max_score)
        << "\n";
    for (const StepGrade& g : l.steps) {
      const bool ran = l.state == LabGrade::State::graded && g.graded && g.seconds > 0;
      out << "    " << cell(std::to_string(g.step->number), 4) << cell(g.step->tag, 8) << cell(g.step->title, left - 14)
          << cell(step_state(l, g), state) << (ran ? cell(points_cell(g.score, g.step->points), score) : "")
          << (ran ? seconds_text(g.seconds) + " s" : points_cell(g.score, g.step->points)) << "\n";
    }
  }
  out << "\n  " << cell("Total", left + state) << points_cell(s.score, s.max_score) << "   (" << seconds_text(s.seconds)
      << " s)\n";
  for (const LabGrade& l : s.labs) {
    if (l.state != LabGrade::State::graded)
      out << "\n" << lab_heading(l) << ": " << lab_state(l) << "\n" << build_text(l, "  ") << "\n";
    for (const StepGrade& g : l.steps)
      if (g.status != Status::passed && l.state == LabGrade::State::graded && g.graded)
        out << "\nLab " << l.lab->id << ", " << step_name(g) << "\n  " << term::indent(g.feedback, "  ") << "\n";
  }
  return out.str();
}

nlohmann::json gradescope_results(const SubmissionGrade& s, const GradingRun& run) {
  nlohmann::json tests = nlohmann::json::array();
  std::string summary;
  for (const LabGrade& l : s.labs) {
    const int lab_number = std::stoi(l.lab->id);
    const bool built = l.state == LabGrade::State::graded;
    const std::string build_output =
        built ? "It compiles."
        : l.state == LabGrade::State::pending
            ? "not graded: grading stopped before this lab was built (a time-out of the whole run?)"
            : lab_state(l) + ".\n" + build_text(l, "");
    tests.push_back({{"name", "Lab " + l.lab->id + " " + l.lab->title + ": build"},
                     {"number", std::to_string(lab_number) + ".0"},
                     {"status", built ? "passed" : "failed"},
                     {"output", build_output},
                     {"visibility", "visible"}});
    for (const StepGrade& g : l.steps)
      tests.push_back({{"name", "Lab " + l.lab->id + " " + step_name(g)},
                       {"number", std::to_string(lab_number) + "." + std::to_string(g.step->number)},
                       {"score", g.score},
                       {"max_score", g.step->points},
                       {"status", g.status == Status::passed ? "passed" : "failed"},
                       {"output", g.graded ? g.feedback : std::string(kNotRunYet)},
                       {"tags", {"lab" + l.lab->id, g.step->tag}},
                       {"visibility", "visible"}});
    summary += "Lab " + l.lab->id + " " + l.lab->title + ": " + points(l.score) + " / " + points(l.max_score) +
               (built ? "" : " (" + lab_state(l) + ")") + "\n";
  }
  if (!run.assignment.empty()) summary = "Assignment: " + run.assignment + "\n" + summary;
  if (!s.error.empty())
    summary = "The submission could not be read: " + quoted_after_label(s.error, "  ") + "\n" + summary;
  for (const std::string& note : s.notes) summary += "Note: " + safe_line(note) + "\n";
  if (!s.budget_note.empty()) summary += "Time: " + s.budget_note + "\n";
  if (!run.regrade.empty())
    summary += "Cases: this submission's own, drawn from the secret seed and its files; regrade: " + run.regrade + "\n";
  nlohmann::json extra = {{"seed", run.seed_kind}, {"sandbox", run.sandbox}, {"limits", run.limits}};
  if (run.cases > 0) extra["cases_per_query"] = run.cases;
  if (!run.assignment.empty()) extra["assignment"] = run.assignment;
  return {{"score", s.score},
          {"execution_time", int(std::ceil(s.seconds))},
          {"output", summary},
          {"tests", tests},
          {"extra_data", extra}};
}

std::string junit_xml(const SubmissionGrade& s) {
  int tests = 0, failures = 0, errors = 0;
  std::ostringstream suites;
  for (const LabGrade& l : s.labs) {
    int lab_failures = 0, lab_errors = 0;
    std::ostringstream cases;
    for (const StepGrade& g : l.steps) {
      cases << "    <testcase classname=\"lab" << l.lab->id << "\" name=\"" << xml_escape(step_name(g)) << "\">\n";
      const std::string message =
          status_word(g.status) + ": " + points(g.score) + " of " + points(g.step->points) + " points";
      const std::string body =
          l.state == LabGrade::State::graded ? g.feedback : lab_state(l) + "\n" + build_text(l, "");
      if (abnormal(g.status) || l.state == LabGrade::State::not_built) {
        ++lab_errors;
        cases << "      <error type=\"" << xml_escape(status_word(g.status)) << "\" message=\"" << xml_escape(message)
              << "\">" << xml_escape(body) << "</error>\n";
      } else if (g.status != Status::passed) {
        ++lab_failures;
        cases << "      <failure type=\"" << xml_escape(status_word(g.status)) << "\" message=\"" << xml_escape(message)
              << "\">" << xml_escape(body) << "</failure>\n";
      } else {
        cases << "      <system-out>" << xml_escape(message + "\n" + g.feedback) << "</system-out>\n";
      }
      cases << "    </testcase>\n";
    }
    tests += int(l.steps.size());
    failures += lab_failures;
    errors += lab_errors;
    suites << "  <testsuite name=\"lab" << l.lab->id << " " << xml_escape(l.lab->name) << "\" tests=\""
           << l.steps.size() << "\" failures=\"" << lab_failures << "\" errors=\"" << lab_errors
           << "\" skipped=\"0\">\n"
           << "    <properties>\n      <property name=\"score\" value=\"" << points(l.score) << "\"/>\n"
           << "      <property name=\"max_score\" value=\"" << points(l.max_score) << "\"/>\n    </properties>\n"
           << cases.str() << "  </testsuite>\n";
  }
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"labkit grade " << xml_escape(safe_line(s.name))
      << "\" tests=\"" << tests << "\" failures=\"" << failures << "\" errors=\"" << errors << "\" time=\""
      << seconds_text(s.seconds) << "\">\n"
      << suites.str() << "</testsuites>\n";
  return out.str();
}

std::string steps_tsv(const SubmissionGrade& s) {
  // seconds: the step's own process, wall clock.
  std::string out = "lab\tstep\ttag\tstatus\tscore\tmax\tseconds\n";
  for (const LabGrade& l : s.labs) {
    for (const StepGrade& g : l.steps)
      out += l.lab->id + "\t" + std::to_string(g.step->number) + "\t" + g.step->tag + "\t" + step_state(l, g) + "\t" +
             points(g.score) + "\t" + points(g.step->points) + "\t" + seconds_text(g.seconds) + "\n";
  }
  return out;
}

std::string csv_field(std::string text) {
  // RFC 4180, and never a formula: a spreadsheet evaluates a cell that starts with = + -
  // @, a tab or a CR ("-2-2" is -4, "=HYPERLINK(...)" a link), so such a cell starts with
  // an apostrophe, which spreadsheets show as text and do not display.
  if (!text.empty() && std::string_view("=+-@\t\r").find(text.front()) != std::string_view::npos) text = "'" + text;
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string class_csv(const std::vector<SubmissionGrade>& all) {
  if (all.empty()) return "submission,total,max\n";
  std::string out = "submission";
  for (const LabGrade& l : all.front().labs) out += ",lab" + l.lab->id;
  out += ",total,max\n";
  for (const SubmissionGrade& s : all) {
    out += csv_field(safe_line(s.name));
    for (const LabGrade& l : s.labs) out += "," + points(l.score);
    out += "," + points(s.score) + "," + points(s.max_score) + "\n";
  }
  return out;
}

}  // namespace runner
