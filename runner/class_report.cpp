#include "class_report.h"

#include "process.h"
#include "untrusted.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace runner {

namespace fs = std::filesystem;

namespace {

std::string html(const std::string& text) { return xml_escape(text); }

// A relative link to a submission's file: every byte but letters, digits and "._-"
// percent-encoded, so that no name can leave the folder or break the attribute.
std::string link_to(const std::string& name, const std::string& file) {
  static const char* const hex = "0123456789ABCDEF";
  std::string out;
  for (const unsigned char c : name) {
    if (std::isalnum(c) || c == '.' || c == '_' || c == '-')
      out += char(c);
    else
      out += std::string("%") + hex[c >> 4] + hex[c & 15];
  }
  if (out == "." || out == "..") out = "%2E" + out.substr(1);
  return out + "/" + file;
}

// The first line of a text, when a table's cell has room for one.
std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

std::string percent(double fraction) {
  std::ostringstream s;
  s << std::lround(fraction * 100) << "%";
  return s.str();
}

std::string step_label(const LabGrade& l, const StepGrade& s) {
  return std::to_string(std::stoi(l.lab->id)) + "." + std::to_string(s.step->number);
}

// What happened to a step that ended abnormally: its feedback's "what" line.
std::string what_happened(const StepGrade& s) {
  std::istringstream lines(s.feedback);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("what", 0) == 0) return line.substr(std::min(line.size(), line.find_first_not_of(' ', 4)));
  return "";
}

// A failing step whose first failure is a call its code never answered (the judge's
// words, common/protocol/calls.cpp): the step went on, but the code crashed, looped or
// ran out of memory. "" for a wrong answer.
std::string call_trouble(const StepGrade& s) {
  static const std::pair<const char*, const char*> kinds[] = {
      {"your code crashed during this call", "crashed during a call"},
      {"your code did not finish this call", "did not finish a call"},
      {"your code ran out of memory during this call", "out of memory during a call"}};
  for (const auto& [words, kind] : kinds)
    if (s.status == Status::failing && s.why.rfind(words, 0) == 0) return kind;
  return "";
}

struct Figure {
  std::string file;  // beside the page; "" when it could not be drawn
  std::string why_not;
};

// Runs gnuplot on `script` in `scratch`; the SVG it writes there is copied beside the page.
Figure plot(const std::string& scratch, const std::string& name, const std::string& script, const std::string& data,
            const std::string& out) {
  fs::create_directories(scratch);
  std::ofstream(scratch + "/" + name + ".dat") << data;
  std::ofstream(scratch + "/" + name + ".gp")
      << "set terminal svg size 900,380 dynamic font 'sans,12' background '#ffffff'\n"
      << "set output '" << name << ".svg'\n"
      << script;
  Limits limits;
  limits.seconds = 60;
  const Run r = run({"gnuplot", name + ".gp"}, {}, limits, scratch);
  if (!r.started) return {"", "the plots need gnuplot (apt-get install gnuplot-nox), then grade again"};
  if (!r.ok() || !fs::exists(scratch + "/" + name + ".svg"))
    return {"", "gnuplot could not draw it: " + r.output.substr(0, 300)};
  fs::copy_file(scratch + "/" + name + ".svg", fs::path(out) / (name + ".svg"), fs::copy_options::overwrite_existing);
  return {name + ".svg", ""};
}

std::string figure_html(const Figure& f, const std::string& alt) {
  if (f.file.empty()) return "<p class=\"note\">(No plot: " + html(f.why_not) + ".)</p>\n";
  return "<img src=\"" + f.file + "\" alt=\"" + html(alt) + "\">\n";
}

// The totals in twenty bins from 0 to the maximum (the last bin holds the maximum).
Figure totals_plot(const std::vector<SubmissionGrade>& all, double max, const std::string& scratch,
                   const std::string& out) {
  const int bins = 20;
  const double width = max > 0 ? max / bins : 1;
  std::vector<int> count(bins, 0);
  for (const SubmissionGrade& s : all) ++count[std::clamp(int(s.score / width), 0, bins - 1)];
  std::ostringstream data;
  for (int b = 0; b < bins; ++b) data << (b + 0.5) * width << " " << count[b] << "\n";
  const int most = *std::max_element(count.begin(), count.end());
  std::ostringstream script;
  script << "set title 'Totals: " << all.size() << " submissions, out of " << max << " points'\n"
         << "set xlabel 'total points'\nset ylabel 'submissions'\n"
         << "set xrange [0:" << max << "]\nset yrange [0:" << most + 1 << "]\n"
         << "set ytics " << std::max(1, (most + 9) / 10) << "\nset xtics " << width * 2 << "\n"
         << "set boxwidth " << width * 0.9 << "\nset style fill solid 0.85 border -1\nset grid ytics\n"
         << "plot 'class-totals.dat' using 1:2 with boxes lc rgb '#3b6ea8' notitle\n";
  return plot(scratch, "class-totals", script.str(), data.str(), out);
}

// Each step's share of submissions that pass it, a colour per lab.
Figure steps_plot(const std::vector<SubmissionGrade>& all, const std::string& scratch, const std::string& out) {
  std::ostringstream data, tics;
  int x = 0;
  const SubmissionGrade& first = all.front();
  for (std::size_t l = 0; l < first.labs.size(); ++l, ++x) {  // a gap between labs
    for (std::size_t k = 0; k < first.labs[l].steps.size(); ++k, ++x) {
      int passed = 0;
      for (const SubmissionGrade& s : all) passed += s.labs[l].steps[k].status == Status::passed;
      data << x << " " << 100.0 * passed / all.size() << " " << l + 1 << "\n";
      tics << (tics.tellp() > 0 ? ", " : "") << "'" << step_label(first.labs[l], first.labs[l].steps[k]) << "' " << x;
    }
  }
  std::ostringstream script;
  script << "set title 'Each step: the share of submissions that pass it'\n"
         << "set ylabel '% of submissions'\nset yrange [0:100]\nset xrange [-1:" << x - 1 << "]\n"
         << "set xtics (" << tics.str() << ") rotate by 90 right font ',10'\n"
         << "set boxwidth 0.8\nset style fill solid 0.85 border -1\nset grid ytics\n"
         << "set palette maxcolors 8\nset palette defined (0 '#3b6ea8', 1 '#e07b39', 2 '#4b9c5a', 3 '#b94a48', "
            "4 '#8064a2', 5 '#8c6d46', 6 '#d46aa6', 7 '#5f6b73')\nunset colorbox\nset cbrange [0.5:8.5]\n"
         << "plot 'class-steps.dat' using 1:2:3 with boxes lc palette notitle\n";
  return plot(scratch, "class-steps", script.str(), data.str(), out);
}

struct Concept {
  std::string lab, step, rule, example;
  std::set<std::string> who;
};

// A submission's problems that cost more than a wrong answer: (kind, lab, what).
struct Trouble {
  std::string name, kind, where, what;
};

}  // namespace

std::vector<std::string> class_files() {
  return {"class.csv", "gradebook.csv", kClassPage, "class-totals.svg", "class-steps.svg"};
}

std::string concept_of(const std::string& why) {
  const std::string line = why.substr(0, why.find('\n'));
  // Each number becomes "#"; a name with digits in it (n1, v0, t_2) stays as it is.
  std::string rule;
  for (std::size_t i = 0; i < line.size();) {
    const auto at = [&](std::size_t k) { return k < line.size() ? line[k] : '\0'; };
    const auto digit = [&](std::size_t k) { return std::isdigit(static_cast<unsigned char>(at(k))) != 0; };
    const auto word = [&](std::size_t k) { return std::isalnum(static_cast<unsigned char>(at(k))) || at(k) == '_'; };
    if (std::isalpha(static_cast<unsigned char>(at(i))) || at(i) == '_') {
      std::size_t end = i;
      while (word(end)) ++end;
      const std::string name = line.substr(i, end - i);
      rule += name == "inf" || name == "nan" ? "#" : name;
      i = end;
    } else if (digit(i) || ((at(i) == '-' || at(i) == '+' || at(i) == '.') &&
                            (digit(i + 1) || (at(i + 1) == '.' && digit(i + 2))))) {
      std::size_t end = i + 1;
      while (digit(end) || at(end) == '.') ++end;
      if ((at(end) == 'e' || at(end) == 'E') &&
          (digit(end + 1) || ((at(end + 1) == '-' || at(end + 1) == '+') && digit(end + 2)))) {
        end += 2;
        while (digit(end)) ++end;
      }
      rule += '#';
      i = end;
    } else {
      rule += line[i++];
    }
  }
  // What the rule was about, not which one: "input triangle #: " or "triangle #: " (a
  // few words naming one thing by its number) goes.
  for (int k = 0; k < 3; ++k) {
    const std::size_t colon = rule.find(": ");
    if (colon == std::string::npos || colon > 40) break;
    const std::string prefix = rule.substr(0, colon);
    const bool names_one = prefix.size() > 2 && prefix.compare(prefix.size() - 2, 2, " #") == 0 &&
                           prefix.find_first_not_of("abcdefghijklmnopqrstuvwxyz_ ") == prefix.size() - 1;
    if (!names_one) break;
    rule.erase(0, colon + 2);
  }
  if (rule.size() > 160) rule = rule.substr(0, 157) + "...";
  return rule;
}

namespace {

// The totals: a line of figures and a histogram.
void totals_section(std::ostream& body, const std::vector<SubmissionGrade>& all, const std::string& scratch,
                    const std::string& out) {
  const double max = all.empty() ? 0 : all.front().max_score;
  std::vector<double> totals;
  for (const SubmissionGrade& s : all) totals.push_back(s.score);
  std::sort(totals.begin(), totals.end());
  double mean = 0;
  for (double t : totals) mean += t;
  if (!totals.empty()) mean /= totals.size();
  const auto median = [&] {
    if (totals.empty()) return 0.0;
    const std::size_t n = totals.size();
    return n % 2 ? totals[n / 2] : (totals[n / 2 - 1] + totals[n / 2]) / 2;
  };
  body << "<h2>Totals</h2>\n<p>" << all.size() << " submissions; mean " << points(mean) << ", median "
       << points(median()) << ", lowest " << points(totals.empty() ? 0 : totals.front()) << ", highest "
       << points(totals.empty() ? 0 : totals.back()) << " of " << points(max) << "; "
       << std::count(totals.begin(), totals.end(), max) << " with full marks.</p>\n";
  if (!all.empty()) body << figure_html(totals_plot(all, max, scratch, out), "a histogram of the submissions' totals");
}

// Each step's pass rate, as a plot and as a table.
void steps_section(std::ostream& body, const std::vector<SubmissionGrade>& all, const std::string& scratch,
                   const std::string& out) {
  if (!all.empty()) {
    body << "<h2>Each step</h2>\n" << figure_html(steps_plot(all, scratch, out), "each step's pass rate");
    body << "<table>\n<tr><th>step</th><th>title</th><th>passed</th><th>failing</th><th>not implemented</th>"
            "<th>ended abnormally</th><th>not compiled or missing</th><th>mean points</th></tr>\n";
    const SubmissionGrade& first = all.front();
    for (std::size_t l = 0; l < first.labs.size(); ++l) {
      body << "<tr class=\"lab\"><td colspan=\"8\">Lab " << html(first.labs[l].lab->id) << " "
           << html(first.labs[l].lab->title) << "</td></tr>\n";
      for (std::size_t k = 0; k < first.labs[l].steps.size(); ++k) {
        int passed = 0, failing = 0, stub = 0, abnormal_runs = 0, unbuilt = 0;
        double sum = 0;
        for (const SubmissionGrade& s : all) {
          const LabGrade& lab = s.labs[l];
          const StepGrade& step = lab.steps[k];
          sum += step.score;
          if (lab.state != LabGrade::State::graded)
            ++unbuilt;
          else if (step.status == Status::passed)
            ++passed;
          else if (step.status == Status::failing)
            ++failing;
          else if (step.status == Status::not_implemented)
            ++stub;
          else
            ++abnormal_runs;
        }
        const double n = double(all.size());
        body << "<tr><td>" << step_label(first.labs[l], first.labs[l].steps[k]) << "</td><td>"
             << html(first.labs[l].steps[k].step->title) << "</td><td>" << percent(passed / n) << "</td><td>"
             << percent(failing / n) << "</td><td>" << percent(stub / n) << "</td><td>" << percent(abnormal_runs / n)
             << "</td><td>" << percent(unbuilt / n) << "</td><td>" << points(sum / n) << " / "
             << points(first.labs[l].steps[k].step->points) << "</td></tr>\n";
      }
    }
    body << "</table>\n";
  }
}

// The concepts most often broken: the rules of the first failures, counted by submission.
void concepts_section(std::ostream& body, const std::vector<SubmissionGrade>& all) {
  std::map<std::string, Concept> concepts;
  for (const SubmissionGrade& s : all)
    for (const LabGrade& l : s.labs)
      for (const StepGrade& step : l.steps) {
        if (step.why.empty() || !call_trouble(step).empty()) continue;  // listed with the crashes
        const std::string rule = concept_of(step.why);
        Concept& c = concepts[l.lab->id + "." + std::to_string(step.step->number) + "\n" + rule];
        c.lab = l.lab->id + " " + l.lab->title;
        c.step = std::to_string(step.step->number) + " " + step.step->title;
        c.rule = rule;
        if (c.example.empty()) c.example = step.why.substr(0, step.why.find('\n'));
        c.who.insert(s.name);
      }
  std::vector<const Concept*> ranked;
  for (const auto& [key, c] : concepts) ranked.push_back(&c);
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const Concept* a, const Concept* b) { return a->who.size() > b->who.size(); });
  body << "<h2>Concepts most often broken</h2>\n<p>A failing step's first failure names the rule the answer broke; "
          "the same rule on other numbers counts as one concept. The most common first; calls that crashed, "
          "did not finish or ran out of memory are in the next section.</p>\n";
  if (ranked.empty()) {
    body << "<p>None: no step failed on a wrong answer.</p>\n";
  } else {
    body << "<table>\n<tr><th>submissions</th><th>lab</th><th>step</th><th>the rule broken</th><th>one of them, with "
            "its numbers</th></tr>\n";
    for (std::size_t r = 0; r < ranked.size() && r < 15; ++r)
      body << "<tr><td>" << ranked[r]->who.size() << "</td><td>" << html(ranked[r]->lab) << "</td><td>"
           << html(ranked[r]->step) << "</td><td>" << html(ranked[r]->rule) << "</td><td class=\"example\">"
           << html(ranked[r]->example) << "</td></tr>\n";
    body << "</table>\n";
  }
}

// What cost more than a wrong answer: one row per submission, lab and kind, with its steps.
void trouble_section(std::ostream& body, const std::vector<SubmissionGrade>& all) {
  std::vector<Trouble> trouble;
  for (const SubmissionGrade& s : all) {
    if (!s.error.empty()) trouble.push_back({s.name, "could not be read", "", quoted_lines(first_line(s.error))});
    for (const LabGrade& l : s.labs) {
      if (l.state == LabGrade::State::not_built)
        trouble.push_back({s.name, "does not compile", "lab " + l.lab->id, quoted_lines(first_line(l.build_output))});
      if (l.state != LabGrade::State::graded) continue;
      std::map<std::string, Trouble> kinds;  // by kind, in this lab
      for (const StepGrade& step : l.steps) {
        const bool no_time = step.status == Status::out_of_time;
        std::string kind = abnormal(step.status) ? status_word(step.status)
                           : no_time             ? "its time budget ran out"
                                                 : call_trouble(step);
        if (kind.empty()) continue;
        auto [it, fresh] = kinds.try_emplace(kind, Trouble{s.name, kind, "lab " + l.lab->id + " step", ""});
        it->second.where += (fresh ? " " : ", ") + std::to_string(step.step->number);
        if (fresh)
          it->second.what = abnormal(step.status) ? what_happened(step)
                            : no_time             ? s.budget_note
                                                  : step.why.substr(0, std::min<std::size_t>(160, step.why.find('\n')));
      }
      for (auto& [kind, t] : kinds) {
        if (t.where.find(',') != std::string::npos) t.where.replace(t.where.find(" step "), 6, " steps ");
        trouble.push_back(t);
      }
    }
  }
  body << "<h2>Crashed, timed out or not compiled</h2>\n<p>A step that ended abnormally scores 0; a call that "
          "crashed, did not finish or ran out of memory costs its case, and the step goes on.</p>\n";
  if (trouble.empty()) {
    body << "<p>None.</p>\n";
  } else {
    body << "<table>\n<tr><th>submission</th><th>what</th><th>where</th><th>details</th></tr>\n";
    for (const Trouble& t : trouble)
      body << "<tr><td><a href=\"" << html(link_to(t.name, "report.txt")) << "\">" << html(t.name) << "</a></td><td>"
           << html(t.kind) << "</td><td>" << html(t.where) << "</td><td class=\"example\">" << html(t.what)
           << "</td></tr>\n";
    body << "</table>\n";
  }
}

// Every submission, a row each: its labs' points and its total.
void submissions_section(std::ostream& body, const std::vector<SubmissionGrade>& all) {
  body << "<h2>Submissions</h2>\n<table>\n<tr><th>submission</th>";
  if (!all.empty())
    for (const LabGrade& l : all.front().labs) body << "<th>lab " << html(l.lab->id) << "</th>";
  body << "<th>total</th><th>graded in</th></tr>\n";
  for (const SubmissionGrade& s : all) {
    body << "<tr><td><a href=\"" << html(link_to(s.name, "report.txt")) << "\">" << html(s.name) << "</a></td>";
    for (const LabGrade& l : s.labs) {
      const bool short_of = l.state != LabGrade::State::graded;
      body << "<td"
           << (short_of ? " class=\"bad\" title=\"" +
                              html(l.state == LabGrade::State::missing       ? "not submitted"
                                   : l.state == LabGrade::State::out_of_time ? "its time budget ran out"
                                                                             : "does not compile") +
                              "\""
                        : "")
           << ">" << points(l.score)
           << (!short_of                                 ? ""
               : l.state == LabGrade::State::missing     ? " (missing)"
               : l.state == LabGrade::State::out_of_time ? " (no time)"
                                                         : " (not compiled)")
           << "</td>";
    }
    body << "<td><b>" << points(s.score) << "</b> / " << points(s.max_score) << "</td><td>" << points(s.seconds)
         << " s</td></tr>\n";
  }
  body << "</table>\n";
}

}  // namespace

std::string write_class_page(const std::vector<SubmissionGrade>& all, const GradingRun& run, const std::string& out,
                             double seconds, const std::string& scratch) {
  fs::create_directories(out);
  const fs::path page = fs::path(out) / kClassPage;
  std::ostringstream body;
  totals_section(body, all, scratch, out);
  steps_section(body, all, scratch, out);
  concepts_section(body, all);
  trouble_section(body, all);
  submissions_section(body, all);
  char when[64] = "";
  const std::time_t now = std::time(nullptr);
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M", std::localtime(&now));
  const std::string title = run.assignment.empty() ? "Class report" : "Class report: " + html(run.assignment);
  std::ofstream file(page, std::ios::binary);
  file << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << title
       << "</title>\n<style>\n"
       << "body { font-family: sans-serif; max-width: 1000px; margin: 2em auto; color: #222; }\n"
       << "table { border-collapse: collapse; margin: 1em 0; font-size: 0.9em; }\n"
       << "th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }\n"
       << "th { background: #eef2f7; } tr.lab td { background: #f6f6f6; font-weight: bold; }\n"
       << "td.bad { color: #a00; } td.example { font-family: monospace; font-size: 0.85em; }\n"
       << ".note { color: #666; } img { max-width: 100%; }\n</style>\n</head>\n<body>\n"
       << "<h1>" << title << "</h1>\n<p>" << all.size() << " submissions graded on " << when << " in "
       << points(seconds) << " s; seed: " << html(run.seed_kind) << ", " << run.cases
       << " random cases per query; limits: " << html(run.limits)
       << ". Each submission's name links to its report; class.csv has the same totals, gradebook.csv them in the form "
          "Canvas and Moodle import.</p>\n"
       << body.str() << "</body>\n</html>\n";
  if (!file) throw std::runtime_error("cannot write " + page.string());
  return page.string();
}

}  // namespace runner
