#include "case_counts.h"
#include "terminal.h"
#include "untrusted.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <vector>

namespace runner {

namespace fs = std::filesystem;

namespace {

struct Rows {
  std::string lines;  // one per query
  long cases = 0, ambiguous = 0, failed = 0;
  std::vector<std::string> too_ambiguous;  // "lab02.step4 find_segment_triangle: 52%"
};

// The manifest's step behind a report's name, "lab02.step4"; null when there is none.
const Step* step_of(const Manifest& manifest, const std::string& stem) {
  const auto dot = stem.find(".step");
  if (stem.rfind("lab", 0) != 0 || dot == std::string::npos) return nullptr;
  const Lab* lab = manifest.find(stem.substr(3, dot - 3));
  if (!lab) return nullptr;
  for (const Step& s : lab->steps)
    if (std::to_string(s.number) == stem.substr(dot + 5)) return &s;
  return nullptr;
}

// A report's rows; none when it is not a report the harness wrote. The test binaries
// wrote these with the code under test inside: a FIFO, a link, a flood, JSON cut short
// or of another shape must not stop the command.
std::optional<Rows> rows_of(const fs::path& file, const Step* step, double max_ambiguous) {
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
      if (step && !step->robustness && q.value("kind", "") == "random" && cases > 0 && amb > max_ambiguous * cases)
        rows.too_ambiguous.push_back(stem + " " + safe_text(q.value("query", "")) + ": " +
                                     std::to_string((100 * amb + cases / 2) / cases) + "%");
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

int report(const std::string& directory, const Manifest* manifest, double max_ambiguous) {
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
  std::vector<std::string> too_ambiguous;
  for (const fs::path& file : files) {
    const Step* step = manifest ? step_of(*manifest, file.stem().string()) : nullptr;
    const std::optional<Rows> rows = rows_of(file, step, max_ambiguous);
    if (!rows) {
      std::cout << "  " << safe_text(file.stem().string()) << ": unreadable report\n";
      continue;
    }
    std::cout << rows->lines;
    total += rows->cases;
    ambiguous += rows->ambiguous;
    failed += rows->failed;
    too_ambiguous.insert(too_ambiguous.end(), rows->too_ambiguous.begin(), rows->too_ambiguous.end());
  }
  std::cout << "  "
            << term::bold(std::to_string(total) + " cases, " + std::to_string(ambiguous) + " ambiguous, " +
                          std::to_string(failed) + " failed")
            << "\n";
  if (!too_ambiguous.empty()) {
    std::cout << term::red("Random families with more than " + std::to_string(int(100 * max_ambiguous + 0.5)) +
                           "% ambiguous cases")
              << " (any answer passes those; only a robustness step may have them):\n";
    for (const std::string& row : too_ambiguous) std::cout << "  " << row << "\n";
    return 1;
  }
  return failed ? 1 : 0;
}

}  // namespace runner
