// A submission's time budget while it is graded (runner/grade.cpp).
#pragma once

#include "grade.h"
#include "results.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace runner {

// A submission's time budget: the wall clock of the processes the grader runs for it
// (compiles, links, steps and the descriptions of their failing cases), measured by the
// grader alone. A process may run for the least of its own limit and what is left, less
// what the submission's other processes running meanwhile may still take, so that
// together they never pass the budget.
class Budget {
 public:
  // The shortest time worth starting a process for.
  static constexpr double kLeast = 1;

  void set(double seconds) { total_ = seconds; }

  // Up to `wanted` seconds for one process: what it may run for, or 0 when less than
  // kLeast is left (the budget ran out).
  double take(double wanted) {
    std::lock_guard<std::mutex> lock(mutex_);
    const double left = total_ - used_ - held_;
    if (left < kLeast) {
      ran_out_ = true;
      return 0;
    }
    const double given = std::min(wanted, left);
    held_ += given;
    return given;
  }

  // A process given `taken` seconds ended after `seconds`, spent on `what` ("lab 02
  // step 3"); `taken` 0 for time charged without a process of its own (a build shared
  // with another submission).
  void spend(double taken, double seconds, const std::string& what) {
    std::lock_guard<std::mutex> lock(mutex_);
    held_ -= taken;
    used_ += seconds;
    if (seconds > 0) spent_.push_back({what, seconds});
  }

  void ran_out() {
    std::lock_guard<std::mutex> lock(mutex_);
    ran_out_ = true;
  }

  double total() const { return total_; }
  double used() {
    std::lock_guard<std::mutex> lock(mutex_);
    return used_;
  }

  // When it ran out: what used it, the slowest labs first, each with its slowest parts.
  std::string note() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!ran_out_) return "";
    std::map<std::string, std::vector<std::pair<double, std::string>>> labs;  // "lab 02" -> (seconds, part)
    for (const auto& [what, seconds] : spent_) {
      const std::size_t space = what.find(' ', 4);
      labs[what.substr(0, space)].push_back({seconds, space == std::string::npos ? what : what.substr(space + 1)});
    }
    std::vector<std::pair<double, std::string>> ranked;
    for (auto& [lab, parts] : labs) {
      std::sort(parts.rbegin(), parts.rend());
      double sum = 0;
      for (const auto& part : parts) sum += part.first;
      std::string text = lab + " " + points(sum) + " s (";
      for (std::size_t k = 0; k < parts.size() && k < 3; ++k)
        text += (k ? ", " : "") + parts[k].second + " " + points(parts[k].first) + " s";
      ranked.push_back({sum, text + (parts.size() > 3 ? ", ...)" : ")")});
    }
    std::sort(ranked.rbegin(), ranked.rend());
    std::string text = "the submission's time budget ran out: its compiles and steps may take " + points(total_) +
                       " s of wall time together (--budget), and they took " + points(used_) +
                       " s; what used it, the slowest first: ";
    for (std::size_t k = 0; k < ranked.size() && k < 4; ++k) text += (k ? "; " : "") + ranked[k].second;
    return text;
  }

 private:
  std::mutex mutex_;
  double total_ = kGradingBudget, used_ = 0, held_ = 0;
  std::vector<std::pair<std::string, double>> spent_;
  bool ran_out_ = false;
};

}  // namespace runner
