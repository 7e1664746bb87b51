#include "report.h"
#include "terminal.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

namespace runner {

namespace fs = std::filesystem;

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
    std::ifstream in(file);
    nlohmann::json j;
    try {
      in >> j;
    } catch (const nlohmann::json::exception&) {
      std::cout << "  " << file.stem().string() << ": unreadable report\n";
      continue;
    }
    for (const auto& q : j.value("queries", nlohmann::json::array())) {
      const int cases = q.value("cases", 0), amb = q.value("ambiguous", 0), bad = q.value("failed", 0);
      std::cout << "  " << term::pad(file.stem().string(), 14) << term::pad(q.value("query", ""), 34)
                << term::pad(q.value("kind", ""), 10) << term::pad(std::to_string(cases), 9)
                << term::pad(std::to_string(amb), 11) << (bad ? term::red(std::to_string(bad)) : "0") << "\n";
      total += cases;
      ambiguous += amb;
      failed += bad;
    }
  }
  std::cout << "  " << term::bold(std::to_string(total) + " cases, " + std::to_string(ambiguous) + " ambiguous, " +
                                  std::to_string(failed) + " failed")
            << "\n";
  return failed ? 1 : 0;
}

}  // namespace runner
