#include "assignment.h"

#include "classroom.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace runner {

namespace {

bool is_number(const std::string& text) {
  return !text.empty() && text.size() < 4 &&
         std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(c); });
}

// "core", "extension", "all" or "1,2,6".
void read_which(Assignment::Part& part, const std::string& which, const std::string& item) {
  if (which == "core" || which == "extension" || which == "all") {
    part.which = which;
    return;
  }
  part.which.clear();
  std::istringstream in(which);
  for (std::string number; std::getline(in, number, ',');) {
    if (!is_number(number))
      throw std::runtime_error("assignment item '" + item + "': after the lab comes core, extension, all or step " +
                               "numbers such as 1,2,6; '" + number + "' is none of those");
    part.steps.push_back(std::stoi(number));
  }
  if (part.steps.empty()) throw std::runtime_error("assignment item '" + item + "' names no step");
}

Assignment from_file(const std::string& path) {
  std::ifstream in(path);
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + " is not JSON: " + e.what());
  }
  Assignment a;
  const auto fail = [&](const std::string& why) { throw std::runtime_error(path + ": " + why); };
  if (!j.is_object() || !j.contains("labs") || !j["labs"].is_array() || j["labs"].empty())
    fail("an assignment file is an object with \"labs\": [{\"lab\": \"03\", \"steps\": \"core\"}, ...]");
  if (j.contains("name")) {
    if (!j["name"].is_string()) fail("\"name\" is a string");
    a.name = j["name"].get<std::string>();
  }
  for (const auto& l : j["labs"]) {
    if (!l.is_object() || !l.contains("lab") || !l["lab"].is_string()) fail("each of \"labs\" has \"lab\": \"NN\"");
    Assignment::Part part;
    part.lab = l["lab"].get<std::string>();
    const std::string item = "lab " + part.lab;
    if (l.contains("steps")) {
      const auto& s = l["steps"];
      if (s.is_string()) {
        read_which(part, s.get<std::string>(), item);
      } else if (s.is_array() && !s.empty() &&
                 std::all_of(s.begin(), s.end(), [](const auto& n) { return n.is_number_integer(); })) {
        part.which.clear();
        for (const auto& n : s) part.steps.push_back(n.get<int>());
      } else {
        fail(item + ": \"steps\" is \"core\", \"extension\", \"all\" or a list of step numbers");
      }
    }
    if (l.contains("points")) {
      if (!l["points"].is_object()) fail(item + ": \"points\" maps step numbers to points, e.g. {\"1\": 20}");
      for (const auto& [step, points] : l["points"].items()) {
        if (!is_number(step) || !points.is_number() || points.get<double>() < 0)
          fail(item + ": \"points\" maps step numbers to points of at least 0; got \"" + step + "\": " + points.dump());
        part.points[std::stoi(step)] = points.get<double>();
      }
    }
    a.parts.push_back(part);
  }
  return a;
}

std::string two_digits(const std::string& id) { return id.size() == 1 ? "0" + id : id; }

}  // namespace

nlohmann::json Assignment::to_json() const {
  nlohmann::json labs = nlohmann::json::array();
  for (const Part& p : parts) {
    nlohmann::json l = {{"lab", p.lab}};
    if (p.which.empty())
      l["steps"] = p.steps;
    else
      l["steps"] = p.which;
    if (!p.points.empty()) {
      l["points"] = nlohmann::json::object();
      for (const auto& [step, points] : p.points) l["points"][std::to_string(step)] = points;
    }
    labs.push_back(l);
  }
  return {{"name", name}, {"labs", labs}};
}

Assignment parse_assignment(const std::vector<std::string>& items) {
  if (items.size() == 1 && items[0].find(':') == std::string::npos && !is_number(items[0]) &&
      std::filesystem::is_regular_file(items[0]))
    return from_file(items[0]);
  Assignment a;
  for (const std::string& item : items) {
    Assignment::Part part;
    const std::size_t colon = item.find(':');
    part.lab = item.substr(0, colon);
    if (part.lab.empty())
      throw std::runtime_error("assignment item '" + item + "': it starts with the lab, e.g. 03:core");
    if (colon != std::string::npos) read_which(part, item.substr(colon + 1), item);
    a.parts.push_back(part);
  }
  return a;
}

Manifest restrict_to(const Manifest& manifest, Assignment& assignment) {
  if (assignment.whole_kit()) return manifest;
  Manifest out;
  std::string names;
  for (const Assignment::Part& part : assignment.parts) {
    const Lab* lab = manifest.find(two_digits(part.lab));
    if (!lab) {
      std::string known;
      for (const Lab& l : manifest.labs) known += (known.empty() ? "" : ", ") + l.id;
      throw std::runtime_error("there is no lab '" + part.lab + "' in grading/manifest.json; the labs are " + known);
    }
    if (std::any_of(out.labs.begin(), out.labs.end(), [&](const Lab& l) { return l.id == lab->id; }))
      throw std::runtime_error("the assignment names lab " + lab->id + " twice; list its steps once");
    for (int step : part.steps)
      if (std::none_of(lab->steps.begin(), lab->steps.end(), [&](const Step& s) { return s.number == step; }))
        throw std::runtime_error("the assignment names step " + std::to_string(step) + " of lab " + lab->id +
                                 ", which has steps 1 to " + std::to_string(lab->steps.size()));
    for (const auto& [step, points] : part.points)
      if (std::none_of(lab->steps.begin(), lab->steps.end(), [&](const Step& s) { return s.number == step; }))
        throw std::runtime_error("the assignment gives points to step " + std::to_string(step) + " of lab " + lab->id +
                                 ", which has no such step");
    Lab kept = *lab;
    kept.steps.clear();
    for (Step s : lab->steps) {
      const bool wanted = part.which == "all" || (part.which == "core" && s.core) ||
                          (part.which == "extension" && !s.core) ||
                          std::find(part.steps.begin(), part.steps.end(), s.number) != part.steps.end();
      if (!wanted) continue;
      if (const auto p = part.points.find(s.number); p != part.points.end()) s.points = p->second;
      kept.steps.push_back(s);
    }
    for (const auto& [step, points] : part.points)
      if (std::none_of(kept.steps.begin(), kept.steps.end(), [&](const Step& s) { return s.number == step; }))
        throw std::runtime_error("the assignment gives points to step " + std::to_string(step) + " of lab " + lab->id +
                                 ", which is not among the assignment's steps of that lab");
    if (kept.steps.empty())
      throw std::runtime_error("the assignment's lab " + lab->id + " part (" + part.which + ") has no step");
    const std::string which = part.which.empty() ? "steps" : part.which == "all" ? "all steps" : part.which + " steps";
    std::string numbers;
    if (part.which.empty())
      for (const Step& s : kept.steps) numbers += (numbers.empty() ? " " : ", ") + std::to_string(s.number);
    names += (names.empty() ? "" : "; ") + ("Lab " + lab->id + ", " + which + numbers);
    out.labs.push_back(std::move(kept));
  }
  if (assignment.name.empty()) assignment.name = names;
  return out;
}

int freeze_assignment(const Paths& paths, const std::vector<std::string>& items, const std::string& out,
                      const std::string& workflow) {
  Assignment assignment;
  Manifest chosen;
  try {
    assignment = parse_assignment(items);
    chosen = restrict_to(load_manifest(paths.source + "/grading/manifest.json"), assignment);
  } catch (const std::exception& e) {
    std::cerr << "labkit: " << e.what() << "\n";
    return 2;
  }
  Assignment frozen;
  frozen.name = assignment.name;
  double total = 0;
  std::cout << "assignment \"" << frozen.name << "\":\n";
  for (const Lab& lab : chosen.labs) {
    Assignment::Part part;
    part.lab = lab.id;
    part.which.clear();
    for (const Step& s : lab.steps) {
      part.steps.push_back(s.number);
      part.points[s.number] = s.points;
      total += s.points;
      std::cout << "  lab " << lab.id << " step " << s.number << " (" << (s.core ? "core" : "extension")
                << "): " << s.title << ", " << s.points << " points\n";
    }
    frozen.parts.push_back(part);
  }
  std::cout << "  " << total << " points in all\n";
  std::ofstream file(out);
  file << frozen.to_json().dump(2) << "\n";
  if (!file.flush()) {
    std::cerr << "labkit: cannot write " << out << "\n";
    return 2;
  }
  if (workflow.empty()) return 0;
  std::ofstream yaml(workflow);
  yaml << classroom_workflow(chosen, frozen.name);
  if (!yaml.flush()) {
    std::cerr << "labkit: cannot write " << workflow << "\n";
    return 2;
  }
  return 0;
}

}  // namespace runner
