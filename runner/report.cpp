#include "report.h"
#include "terminal.h"
#include "untrusted.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

namespace runner {

namespace fs = std::filesystem;

namespace {

struct Rows {
  std::string lines;  // one per query
  long cases = 0, ambiguous = 0, failed = 0;
};

// A report's rows; none when it is not a report the harness wrote. The test binaries
// wrote these with the code under test inside: a FIFO, a link, a flood, JSON cut short
// or of another shape must not stop the command.
std::optional<Rows> rows_of(const fs::path& file) {
  const UntrustedRead read = read_untrusted_file(file.string(), std::uintmax_t(64) << 20);
  if (!read.error.empty()) return std::nullopt;  // not a regular file of a sane size
  const std::string stem = safe_text(file.stem().string());
  Rows rows;
  try {
    const nlohmann::json j = nlohmann::json::parse(read.text);
    for (const auto& q : j.value("queries", nlohmann::json::array())) {
      const int cases = q.value("cases", 0), amb = q.value("ambiguous", 0), bad = q.value("failed", 0);
      rows.lines += "  " + term::pad(stem, 14) + term::pad(safe_text(q.value("query", "")), 34) +
                    term::pad(safe_text(q.value("kind", "")), 10) + term::pad(std::to_string(cases), 9) +
                    term::pad(std::to_string(amb), 11) + (bad ? term::red(std::to_string(bad)) : "0") + "\n";
      rows.cases += cases;
      rows.ambiguous += amb;
      rows.failed += bad;
    }
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // cut short, or a field of another type than the harness writes
  }
  return rows;
}

}  // namespace

int report(const std::string& directory) {
  std::vector<fs::path> files;
  if (fs::is_directory(directory))
    for (const auto& entry : fs::directory_iterator(directory))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::cerr << "labkit report: no reports in " << directory << " (run the suite first)\n";
    return 2;
  }
  std::cout << term::bold("Oracle cases per query") << term::dim("  (from " + directory + ")") << "\n";
  std::cout << "  " << term::pad("step", 14) << term::pad("query", 34) << term::pad("kind", 10) << term::pad("cases", 9)
            << term::pad("ambiguous", 11) << "failed\n";
  long total = 0, ambiguous = 0, failed = 0;
  for (const fs::path& file : files) {
    const std::optional<Rows> rows = rows_of(file);
    if (!rows) {
      std::cout << "  " << safe_text(file.stem().string()) << ": unreadable report\n";
      continue;
    }
    std::cout << rows->lines;
    total += rows->cases;
    ambiguous += rows->ambiguous;
    failed += rows->failed;
  }
  std::cout << "  " << term::bold(std::to_string(total) + " cases, " + std::to_string(ambiguous) + " ambiguous, " +
                                  std::to_string(failed) + " failed")
            << "\n";
  return failed ? 1 : 0;
}

}  // namespace runner
