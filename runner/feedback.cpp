#include "feedback.h"
#include "terminal.h"
#include "untrusted.h"

#include <algorithm>
#include <sstream>

namespace runner {

namespace {

// The secret never appears in what is written, even if the code under test found it.
std::string redact(std::string text, const std::string& secret) {
  if (secret.size() < 6) return text;
  for (std::size_t at; (at = text.find(secret)) != std::string::npos;) text.replace(at, secret.size(), "[secret]");
  return text;
}

// The last `n` bytes of `text`, from the start of a character: a tail cut in the middle
// of one would begin with a broken character.
std::string tail(const std::string& text, std::size_t n) {
  if (text.size() <= n) return text;
  std::size_t from = text.size() - n;
  for (int k = 0; k < 3 && from < text.size() && (static_cast<unsigned char>(text[from]) & 0xC0) == 0x80; ++k) ++from;
  return "..." + text.substr(from);
}

// Where a value's further lines start, under the labels ("why       ").
const std::string kUnder(10, ' ');

// A failure as the student reads it, one field a line under a label column, as
// labkit::report::format lays it out; the judge's fields may carry what the code under
// test said (an exception's message, what it printed before it crashed), so each
// field's further lines are quoted (untrusted.h): none can pass for a line of the kit's.
// The input is the kit's own description of a case the kit drew.
std::string failure_text(const Failure& f, const std::string& query) {
  std::string text = "query     " + safe_line(query) + (f.title.empty() ? "" : ", " + safe_line(f.title));
  if (f.shrinks > 0) text += " (shrunk " + std::to_string(f.shrinks) + " times)";
  text += "\ninput     " + term::indent(safe_text(f.input), kUnder);
  text += "\nexpected  " + quoted_after_label(f.expected, kUnder);
  text += "\ngot       " + quoted_after_label(f.got, kUnder);
  text += "\nwhy       " + quoted_after_label(f.why, kUnder) + "\n";
  return text;
}

// The command that replays a case, or why there is none: a token the harness never
// writes (the code under test printed or wrote it) never becomes a command.
std::string replay_line(const Lab& lab, const std::string& token) {
  const std::string command = replay_command("check", lab.id, token);
  return "replay    " +
         (command.empty() ? "none (the case it reported is not a replay token the kit writes)" : command) + "\n";
}

}  // namespace

void make_presentable(SubmissionGrade& g, const std::vector<std::string>& secrets) {
  const auto presentable = [&](std::string& text) {
    for (const std::string& secret : secrets) text = redact(text, secret);
    text = safe_text(text);
  };
  presentable(g.name);
  presentable(g.source);
  presentable(g.error);
  for (std::string& note : g.notes) presentable(note);
  for (LabGrade& l : g.labs) {
    presentable(l.build_output);
    for (StepGrade& s : l.steps) {
      presentable(s.feedback);
      presentable(s.why);
    }
  }
}

std::string feedback(const StepResult& r, const Lab& lab, const Programs& programs, const StepOptions& graded,
                     Budget& budget) {
  std::ostringstream out;
  int cases = 0, passed = 0;
  for (const QueryResult& q : r.queries) {
    cases += q.cases;
    passed += q.passed + q.ambiguous;
  }
  out << status_word(r.status);
  if (r.status == Status::passed || r.status == Status::failing)
    out << ": " << passed << " of " << cases << " cases pass"
        << (r.ambiguous ? " (" + std::to_string(r.ambiguous) + " of them ambiguous: any answer is accepted there)"
                        : "");
  out << "\n";
  if (abnormal(r.status)) {
    out << "what      " << quoted_after_label(r.detail, kUnder) << "\n";
    if (!r.inflight.empty() && !is_replay_token(r.inflight)) {
      out << replay_line(lab, r.inflight);  // its output faked the marker: no input to describe
    } else if (!r.inflight.empty()) {
      // Describing runs no code under test; it keeps the graded limits all the same, and
      // takes its time from the submission's budget (none left: the token alone).
      std::string input = r.inflight;
      if (const double seconds = budget.take(30); seconds > 0) {
        StepOptions describe = graded;
        describe.replay = r.inflight;
        describe.describe_only = true;
        describe.count_all = false;
        describe.limits.seconds = seconds;
        const StepResult d = run_step(programs, lab, *r.step, describe);
        budget.spend(seconds, d.run.seconds, "lab " + lab.id + " step " + std::to_string(r.step->number));
        for (const QueryResult& q : d.queries)
          if (q.failure && !q.failure->input.empty()) input = q.failure->input;
      }
      out << "on input  " << term::indent(input, kUnder) << "\n";
      out << replay_line(lab, r.inflight);
    }
    if (r.status == Status::crashed || r.status == Status::exited_early || r.status == Status::out_of_memory) {
      const std::string last = tail(r.run.output, 800);
      if (!last.empty()) out << "its last output:\n" << quoted_lines(last) << "\n";
    }
    return out.str();
  }
  for (const QueryResult& q : r.queries) {
    if (!q.error.empty()) {
      out << safe_line(q.query) << ": " << quoted_after_label(q.error, kUnder) << "\n";
      break;
    }
    if (q.failure && q.not_implemented.empty()) {
      const Failure& f = *q.failure;
      out << failure_text(f, q.query);
      if (!f.replay.empty()) out << replay_line(lab, f.replay);
      break;
    }
  }
  return out.str();
}

std::string first_why(const StepResult& r) {
  if (r.status != Status::failing) return "";
  for (const QueryResult& q : r.queries)
    if (q.failure && q.not_implemented.empty()) return q.failure->why;
  return "";
}

}  // namespace runner
