// labkit-bench-report BENCH.json TARGETS.json OUT.md [MORE.md...]
//
// Turns one run of labkit-bench into bench/RESULTS.md: a table per kernel (throughput,
// time per item, the reference's speed relative to each peer, disagreements with the
// exact answer), the targets met or missed, size scaling where a kernel was run at
// several sizes, then the other markdown files given (the student loop's timings, the
// hand-written notes that explain the misses), in order.
#include "common/text.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using nlohmann::json;

namespace {

struct Row {
  std::string implementation;
  double items_per_second = 0;
  double nanoseconds_per_item = 0;
  json counters = json::object();
};

std::string number(double x, int digits = 3) {
  if (!std::isfinite(x)) return "-";
  char buffer[64];
  const double a = std::abs(x);
  if (a >= 1e9)
    std::snprintf(buffer, sizeof buffer, "%.*gG", digits, x / 1e9);
  else if (a >= 1e6)
    std::snprintf(buffer, sizeof buffer, "%.*gM", digits, x / 1e6);
  else if (a >= 1e3)
    std::snprintf(buffer, sizeof buffer, "%.*gk", digits, x / 1e3);
  else
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

// "group/implementation" or "group/implementation/variant": the variant is a size
// (a number: the table shows the scaling) or the name of an input mix.
struct Name {
  std::string group, implementation, size;
};

bool is_number(const std::string& s) { return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos; }

// Rows of one group by variant, in the order the benchmarks ran.
using Variants = std::vector<std::pair<std::string, std::vector<Row>>>;

std::vector<Row>& rows_of(Variants& variants, const std::string& size) {
  for (auto& [s, rows] : variants)
    if (s == size) return rows;
  return variants.emplace_back(size, std::vector<Row>{}).second;
}
Name split(const std::string& name) {
  Name n;
  const auto a = name.find('/');
  n.group = name.substr(0, a);
  if (a == std::string::npos) return n;
  const auto b = name.find('/', a + 1);
  n.implementation = name.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
  if (b != std::string::npos) n.size = name.substr(b + 1);
  return n;
}

using Groups = std::map<std::string, Variants>;

// The benchmarks' rows by group and variant; `order`: the groups in the order they ran.
Groups rows_by_group(const json& run, std::vector<std::string>& order) {
  Groups groups;
  for (const json& b : run.value("benchmarks", json::array())) {
    if (b.value("run_type", "iteration") != "iteration") continue;
    const Name n = split(b.value("name", ""));
    Row r;
    r.implementation = n.implementation;
    r.items_per_second = b.value("items_per_second", 0.0);
    r.nanoseconds_per_item = r.items_per_second > 0 ? 1e9 / r.items_per_second : NAN;
    for (auto it = b.begin(); it != b.end(); ++it)
      if (it.key() == "disagree" || it.key() == "ambiguous" || it.key() == "bytes_per_triangle" ||
          it.key() == "tests_per_query")
        r.counters[it.key()] = it.value();
    if (!groups.count(n.group)) order.push_back(n.group);
    rows_of(groups[n.group], n.size).push_back(r);
  }
  return groups;
}

void write_header(std::ostream& md, const json& context) {
  md << "# Benchmark results\n\n"
     << "Written by `./labkit bench` (run it again to regenerate this file). Every kernel\n"
     << "runs on the same seeded inputs for every implementation, in one run.\n\n"
     << "- Date: " << context.value("date", "?") << "\n"
     << "- Machine: " << context.value("cores", std::string("?")) << " cores, " << context.value("mhz_per_cpu", 0)
     << " MHz, host " << context.value("host_name", "?") << "\n"
     << "- Compiler: " << context.value("compiler", "?") << "\n"
     << "- Flags: `" << context.value("flags", "?") << "`\n"
     << "- Google Benchmark " << context.value("library_build_type", "") << " library; CPU scaling "
     << (context.value("cpu_scaling_enabled", false) ? "on (numbers are noisier)" : "off") << "\n\n"
     << "\"vs\" columns give the reference's speed divided by the peer's: above 1, the\n"
     << "reference is faster. \"disagree\" counts answers that differ from the exact one where\n"
     << "the exact answer is not in doubt (the ambiguous cases are counted apart).\n";
}

// One variant's table: each implementation's speed, the reference against it, its counters.
void write_rows(std::ostream& md, const std::vector<Row>& rows) {
  const Row* reference = nullptr;
  for (const Row& r : rows)
    if (r.implementation == "reference") reference = &r;
  md << "\n| implementation | items/s | ns/item |" << (reference ? " reference vs it |" : "")
     << " disagree | ambiguous | other |\n|---|---|---|" << (reference ? "---|" : "") << "---|---|---|\n";
  for (const Row& r : rows) {
    md << "| " << r.implementation << " | " << number(r.items_per_second) << " | " << number(r.nanoseconds_per_item)
       << " |";
    if (reference)
      md << " " << (r.items_per_second > 0 ? number(reference->items_per_second / r.items_per_second) : "-") << " |";
    md << " " << (r.counters.contains("disagree") ? number(r.counters["disagree"].get<double>()) : "-") << " | "
       << (r.counters.contains("ambiguous") ? number(r.counters["ambiguous"].get<double>()) : "-") << " | ";
    for (const char* key : {"tests_per_query", "bytes_per_triangle"})
      if (r.counters.contains(key)) md << key << " " << number(r.counters[key].get<double>()) << " ";
    md << "|\n";
  }
}

// Whether a group ran at several sizes (numbers), so that its scaling can be fitted.
bool sized(const Variants& variants) {
  return variants.size() >= 2 && is_number(variants.front().first) && is_number(variants.back().first);
}

// The exponent k of size^k that takes the time per item from r0 (the smallest size) to r1.
double exponent(const Variants& variants, const Row& r0, const Row& r1) {
  return std::log(r1.nanoseconds_per_item / r0.nanoseconds_per_item) /
         std::log(std::stod(variants.back().first) / std::stod(variants.front().first));
}

void write_group(std::ostream& md, const std::string& group, const Variants& variants) {
  md << "\n## " << group << "\n";
  for (const auto& [size, rows] : variants) {
    if (is_number(size))
      md << "\n" << number(std::stod(size)) << " triangles or items:\n";
    else if (!size.empty())
      md << "\nOn the " << size << " inputs:\n";
    write_rows(md, rows);
  }
  if (!sized(variants)) return;
  md << "\nScaling of the time per item from the smallest to the largest size (exponent k in size^k):\n\n";
  for (const Row& r0 : variants.front().second)
    for (const Row& r1 : variants.back().second)
      if (r0.implementation == r1.implementation && r0.nanoseconds_per_item > 0 && r1.nanoseconds_per_item > 0)
        md << "- " << r0.implementation << ": k = " << number(exponent(variants, r0, r1), 2) << "\n";
}

// One target: what was measured, and whether it was met ("-" when it was not measured).
std::pair<std::string, std::string> judge_target(const json& t, Groups& groups) {
  const std::string group = t.value("group", ""), peer = t.value("peer", ""), size = t.value("size", "");
  const Row* ref = nullptr;
  const Row* other = nullptr;
  if (groups.count(group) && !size.empty())  // (rows_of adds the size it is asked for)
    for (const Row& r : rows_of(groups[group], size)) {
      if (r.implementation == "reference") ref = &r;
      if (r.implementation == peer) other = &r;
    }
  if (t.contains("counter")) {  // a counter of the reference's row: at most this much
    const std::string key = t.value("counter", "");
    if (!ref || !ref->counters.contains(key)) return {"not measured", "-"};
    const double value = ref->counters[key].get<double>();
    return {number(value) + " " + key, value <= t.value("at_most", 0.0) ? "yes" : "**no**"};
  }
  if (t.contains("exponent_at_most")) {  // the reference's time per item, size^k from the extremes
    const Variants variants = groups.count(group) ? groups[group] : Variants{};
    const Row* r0 = nullptr;
    const Row* r1 = nullptr;
    if (sized(variants)) {
      for (const Row& r : variants.front().second)
        if (r.implementation == "reference") r0 = &r;
      for (const Row& r : variants.back().second)
        if (r.implementation == "reference") r1 = &r;
    }
    if (!r0 || !r1 || r0->nanoseconds_per_item <= 0 || r1->nanoseconds_per_item <= 0) return {"not measured", "-"};
    const double k = exponent(variants, *r0, *r1);
    return {"time per item grows as size^" + number(k, 2) + " (" + variants.front().first + " to " +
                variants.back().first + ")",
            k <= t.value("exponent_at_most", 0.0) ? "yes" : "**no**"};
  }
  if (!ref || !other || other->items_per_second <= 0) return {"not measured", "-"};
  const double ratio = ref->items_per_second / other->items_per_second;
  const double disagree = ref->counters.value("disagree", 0.0);
  return {number(ratio) + "x" + (ref->counters.contains("disagree") ? ", " + number(disagree) + " disagreements" : ""),
          ratio >= t.value("at_least", 0.0) && disagree == 0 ? "yes" : "**no**"};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: labkit-bench-report BENCH.json TARGETS.json OUT.md [MORE.md...]\n";
    return 2;
  }
  json run, targets;
  try {
    run = json::parse(labkit::read_file(argv[1]));
    targets = json::parse(labkit::read_file(argv[2]));
  } catch (const json::exception& e) {
    std::cerr << "labkit-bench-report: " << e.what() << "\n";
    return 2;
  }
  std::vector<std::string> group_order;
  Groups groups = rows_by_group(run, group_order);
  std::ostringstream md;
  write_header(md, run.value("context", json::object()));
  for (const std::string& group : group_order) write_group(md, group, groups[group]);
  md << "\n## Targets\n\n| kernel | target | measured | met |\n|---|---|---|---|\n";
  for (const json& t : targets.value("targets", json::array())) {
    const auto [measured, met] = judge_target(t, groups);
    const std::string size = t.value("size", "");
    md << "| " << t.value("group", "") << (size.empty() ? "" : " (" + size + ")") << " | " << t.value("text", "")
       << " | " << measured << " | " << met << " |\n";
  }
  for (int i = 4; i < argc; ++i) {
    const std::string more = labkit::read_file(argv[i]);
    if (!more.empty()) md << "\n" << more;
  }
  std::ofstream out(argv[3]);
  out << md.str();
  if (!out) {
    std::cerr << "labkit-bench-report: cannot write " << argv[3] << "\n";
    return 1;
  }
  std::cout << "wrote " << argv[3] << "\n";
  return 0;
}
