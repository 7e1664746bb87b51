#include "manifest.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

namespace runner {

int Lab::core_minutes() const {
  int sum = 0;
  for (const Step& s : steps)
    if (s.core) sum += s.minutes;
  return sum;
}

const Lab* Manifest::find(const std::string& id) const {
  for (const Lab& lab : labs)
    if (lab.id == id || lab.stem() == id || lab.name == id) return &lab;
  return nullptr;
}

Manifest load_manifest(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  nlohmann::json j;
  try {
    in >> j;
    Manifest m;
    for (const auto& l : j.at("labs")) {
      Lab lab;
      lab.id = l.at("id").get<std::string>();
      lab.name = l.at("name").get<std::string>();
      lab.title = l.value("title", lab.name);
      lab.student_files = l.at("student_files").get<std::vector<std::string>>();
      for (const auto& s : l.at("steps")) {
        Step step{s.at("step").get<int>(), s.at("tag").get<std::string>(), s.at("title").get<std::string>(),
                  s.value("points", 0.0),  s.value("partial", false),      s.value("robustness", false)};
        const std::string tier = s.value("tier", "core");
        if (tier != "core" && tier != "extension")
          throw std::runtime_error(path + ": step " + step.tag + " has tier '" + tier +
                                   "'; a tier is core or extension");
        step.core = tier == "core";
        step.minutes = s.value("minutes", 0);
        const std::string handout = s.value("handout", "main");
        if (handout != "main" && handout != "extensions")
          throw std::runtime_error(path + ": step " + step.tag + " has handout '" + handout +
                                   "'; a step's section is in the main handout or the extensions one");
        step.in_extensions_handout = handout == "extensions";
        lab.steps.push_back(step);
      }
      m.labs.push_back(lab);
    }
    return m;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + " is not a valid manifest: " + e.what());
  }
}

}  // namespace runner
