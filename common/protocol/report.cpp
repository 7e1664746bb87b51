#include "common/protocol/report.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace labkit::report {

using nlohmann::json;

namespace {

// The field `key` of `object`, or an error that names it (`where` says whose it is).
template <class T>
T field(const json& object, const char* key, const std::string& where) {
  if (!object.is_object()) throw std::runtime_error(where + " is not an object");
  const auto it = object.find(key);
  if (it == object.end()) throw std::runtime_error(where + " has no \"" + key + "\"");
  try {
    return it->get<T>();
  } catch (const json::exception&) {
    throw std::runtime_error(where + "'s \"" + key + "\" has the wrong type (" + it->type_name() + ")");
  }
}

json to_json(const Failure& f) {
  return {{"title", f.title}, {"input", f.input},   {"expected", f.expected}, {"got", f.got},
          {"why", f.why},     {"replay", f.replay}, {"shrinks", f.shrinks}};
}

Failure failure_from_json(const json& j, const std::string& where) {
  return {field<std::string>(j, "title", where),  field<std::string>(j, "input", where),
          field<std::string>(j, "expected", where), field<std::string>(j, "got", where),
          field<std::string>(j, "why", where),    field<std::string>(j, "replay", where),
          field<int>(j, "shrinks", where)};
}

json to_json(const Query& q) {
  json j = {{"test_case", q.test_case}, {"query", q.query},   {"kind", q.kind},
            {"cases", q.cases},         {"passed", q.passed}, {"ambiguous", q.ambiguous},
            {"failed", q.failed},       {"not_implemented", q.not_implemented}, {"error", q.error}};
  j["failure"] = q.failure ? to_json(*q.failure) : json(nullptr);
  return j;
}

Query query_from_json(const json& j, const std::string& where) {
  Query q;
  q.test_case = field<std::string>(j, "test_case", where);
  q.query = field<std::string>(j, "query", where);
  q.kind = field<std::string>(j, "kind", where);
  q.cases = field<int>(j, "cases", where);
  q.passed = field<int>(j, "passed", where);
  q.ambiguous = field<int>(j, "ambiguous", where);
  q.failed = field<int>(j, "failed", where);
  q.not_implemented = field<std::string>(j, "not_implemented", where);
  q.error = field<std::string>(j, "error", where);
  const json failure = field<json>(j, "failure", where);
  if (!failure.is_null()) q.failure = failure_from_json(failure, where + "'s failure");
  return q;
}

json to_json(const TestCase& t) {
  return {{"name", t.name},         {"tags", t.tags},
          {"passed", t.passed},     {"ended", t.ended},
          {"failures", t.failures}, {"not_implemented", t.not_implemented}};
}

TestCase test_case_from_json(const json& j, const std::string& where) {
  return {field<std::string>(j, "name", where),     field<std::vector<std::string>>(j, "tags", where),
          field<bool>(j, "passed", where),          field<bool>(j, "ended", where),
          field<std::vector<std::string>>(j, "failures", where), field<std::string>(j, "not_implemented", where)};
}

// `text` with each line after the first starting with `prefix`.
std::string indented(const std::string& text, const std::string& prefix) {
  std::string out;
  for (char c : text) {
    out += c;
    if (c == '\n') out += prefix;
  }
  return out;
}

}  // namespace

json to_json(const Step& step) {
  json j = {{"seed", step.seed}, {"cases_per_query", step.cases_per_query}, {"finished", step.finished}};
  j["test_cases"] = json::array();
  for (const TestCase& t : step.test_cases) j["test_cases"].push_back(to_json(t));
  j["queries"] = json::array();
  for (const Query& q : step.queries) j["queries"].push_back(to_json(q));
  return j;
}

Step step_from_json(const json& j) {
  Step step;
  step.seed = field<std::string>(j, "seed", "the report");
  step.cases_per_query = field<int>(j, "cases_per_query", "the report");
  step.finished = field<bool>(j, "finished", "the report");
  const auto test_cases = field<std::vector<json>>(j, "test_cases", "the report");
  for (std::size_t i = 0; i < test_cases.size(); ++i)
    step.test_cases.push_back(test_case_from_json(test_cases[i], "test case " + std::to_string(i)));
  const auto queries = field<std::vector<json>>(j, "queries", "the report");
  for (std::size_t i = 0; i < queries.size(); ++i) step.queries.push_back(query_from_json(queries[i], "query " + std::to_string(i)));
  return step;
}

std::string format(const Failure& f, const std::string& query, const std::string& indent) {
  const std::string under = indent + std::string(10, ' ');
  std::string text = indent + "query     " + query + (f.title.empty() ? "" : ", " + f.title);
  if (f.shrinks > 0) text += " (shrunk " + std::to_string(f.shrinks) + " times)";
  text += "\n" + indent + "input     " + indented(f.input, under);
  text += "\n" + indent + "expected  " + indented(f.expected, under);
  text += "\n" + indent + "got       " + indented(f.got, under);
  text += "\n" + indent + "why       " + indented(f.why, under) + "\n";
  return text;
}

}  // namespace labkit::report
