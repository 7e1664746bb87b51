// Lab and step titles come from grading/manifest.json alone. The tests' names and the
// viewer's list read them from it (common/harness/titles.h); the handouts and the banners
// of the contract headers, stubs and references are prose, so this test holds them to it:
// change a title in the manifest and this names every line to change with it. The same
// holds for each step's tier and minutes (the handouts' core path, the hints' marks).
#define CATCH_CONFIG_MAIN  // Catch2 2: main() is here; Catch2 3: it is Catch2::Catch2WithMain's
#include "common/harness/catch.h"
#include "common/text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string source_dir() {
  const char* dir = std::getenv("LABKIT_SOURCE_DIR");
  REQUIRE(dir);
  return dir;
}

nlohmann::json manifest() {
  return nlohmann::json::parse(labkit::read_file(fs::path(source_dir()) / "grading/manifest.json"));
}

std::string stem_of(const nlohmann::json& lab) {
  return lab["id"].get<std::string>() + "_" + lab["name"].get<std::string>();
}

// A step's section is in the lab's handout, or (the manifest's "handout": "extensions") in
// its companion for the extension steps a one-session handout has no room for.
bool in_extensions_handout(const nlohmann::json& step) { return step.value("handout", "main") == "extensions"; }

fs::path handout_of(const nlohmann::json& lab, const nlohmann::json& step) {
  return fs::path(source_dir()) / "handouts" /
         (stem_of(lab) + (in_extensions_handout(step) ? ".extensions.md" : ".md"));
}

}  // namespace

TEST_CASE("each handout's headings give the manifest's lab and step titles", "[kit]") {
  const nlohmann::json all = manifest();
  for (const auto& lab : all["labs"]) {
    const fs::path handout = fs::path(source_dir()) / "handouts" / (stem_of(lab) + ".md");
    INFO(handout.string());
    const std::string text = labkit::read_file(handout);
    const std::string title = "# Lab " + lab["id"].get<std::string>() + ": " + lab["title"].get<std::string>();
    CHECK(text.substr(0, text.find('\n')) == title);
    for (const auto& step : lab["steps"]) {
      INFO(handout_of(lab, step).string());
      const std::string holder = labkit::read_file(handout_of(lab, step));
      if (in_extensions_handout(step)) CHECK(holder.substr(0, holder.find('\n')) == title + ", extensions");
      const std::string tag = step["tag"], heading_start = "## Step " + std::to_string(step["step"].get<int>()) + ": ";
      const std::regex heading("^## Step [0-9]+: (.*) \\(" + tag + "\\)$", std::regex::multiline);
      std::smatch m;
      INFO(tag << ": the handout needs the heading \"" << heading_start << step["title"].get<std::string>() << " ("
               << tag << ")\"");
      REQUIRE(std::regex_search(holder, m, heading));
      CHECK(m[0].str().rfind(heading_start, 0) == 0);
      CHECK(m[1].str() == step["title"].get<std::string>());
    }
  }
}

TEST_CASE("the step banners of contracts, stubs and references give the manifest's step titles", "[kit]") {
  const std::regex banner("^// ---- Step [0-9]+ \\((L[0-9]{2}S[0-9]+)\\): (.*?) -+$", std::regex::multiline);
  int banners = 0;
  const nlohmann::json all = manifest();
  for (const auto& lab : all["labs"]) {
    std::map<std::string, std::string> titles;
    for (const auto& step : lab["steps"]) titles[step["tag"]] = step["title"];
    for (const char* top : {"labs", "solutions"}) {
      const fs::path dir = fs::path(source_dir()) / top / stem_of(lab);
      if (!fs::exists(dir)) continue;  // a student release has no solutions/
      for (const auto& file : fs::directory_iterator(dir)) {
        const std::string text = labkit::read_file(file.path());
        for (auto it = std::sregex_iterator(text.begin(), text.end(), banner); it != std::sregex_iterator(); ++it) {
          const std::string tag = (*it)[1], title = (*it)[2];
          INFO(file.path().string() << ": " << it->str());
          REQUIRE(titles.count(tag) == 1);
          CHECK(title == titles[tag]);
          ++banners;
        }
      }
    }
  }
  CHECK(banners > 0);
}

// README, "Fitting a course": each lab's core path fits one 3-hour session and keeps a
// core part of its robustness lesson; every step has a tier and an estimate.
TEST_CASE("each lab's core steps fit one 3-hour session, robustness included", "[kit]") {
  const nlohmann::json all = manifest();  // kept: a loop over a temporary's member dangles
  for (const auto& lab : all["labs"]) {
    int core_minutes = 0;
    bool core_robustness = false;
    for (const auto& step : lab["steps"]) {
      INFO("lab " << lab["id"] << " step " << step["step"]);
      REQUIRE(step.contains("tier"));
      const std::string tier = step["tier"].get<std::string>();
      CHECK((tier == "core" || tier == "extension"));
      REQUIRE(step.contains("minutes"));
      CHECK(step["minutes"].get<int>() > 0);
      if (tier == "core") core_minutes += step["minutes"].get<int>();
      if (tier == "core" && step.value("robustness", false)) core_robustness = true;
    }
    INFO("lab " << lab["id"] << ": its core steps take " << core_minutes << " minutes");
    CHECK(core_minutes <= 180);
    CHECK(core_minutes >= 60);
    CHECK(core_robustness);
  }
}

namespace {

// Runs of spaces and line breaks as one space: prose wraps wherever it likes.
std::string one_line(std::string text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') c = ' ';
    if (c != ' ' || out.empty() || out.back() != ' ') out += c;
  }
  return out;
}

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i)
    out += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  return out;
}

}  // namespace

TEST_CASE("each handout gives its core path and each step's tier and minutes from the manifest", "[kit]") {
  const nlohmann::json all = manifest();
  for (const auto& lab : all["labs"]) {
    const std::string id = lab["id"];
    const fs::path handout = fs::path(source_dir()) / "handouts" / (stem_of(lab) + ".md");
    INFO(handout.string());
    const std::string text = labkit::read_file(handout);
    int core_minutes = 0;
    std::vector<std::string> core_steps, extensions;
    for (const auto& step : lab["steps"]) {
      const std::string tag = step["tag"], number = std::to_string(step["step"].get<int>()),
                        minutes = std::to_string(step["minutes"].get<int>());
      const bool core = step["tier"] == "core";
      if (core) {
        core_minutes += step["minutes"].get<int>();
        core_steps.push_back(number + (core_steps.empty() ? " (about " + minutes + " min)" : " (" + minutes + ")"));
      } else {
        extensions.push_back(number);
      }
      // The step's text starts with its tier and minutes: "*Core, about 25 min.*". A step in
      // the extensions handout is an extension.
      CHECK((!in_extensions_handout(step) || !core));
      const std::string holder = labkit::read_file(handout_of(lab, step));
      const std::string mark = std::string(core ? "*Core" : "*Extension") + ", about " + minutes + " min.*";
      const std::string heading_end = " (" + tag + ")\n";
      const std::size_t at = holder.find(heading_end);
      REQUIRE(at != std::string::npos);
      std::size_t from = at + heading_end.size();
      while (from < holder.size() && holder[from] == '\n') ++from;
      const std::string first = holder.substr(from, holder.find('\n', from) - from);
      INFO(tag << ": the step's text must start with \"" << mark << "\"; it starts \"" << first << "\"");
      CHECK(first.rfind(mark, 0) == 0);
    }
    // One 3-hour session for the core (the manifest's comment), said near the top.
    CHECK(core_minutes <= 180);
    const std::size_t section_at = text.find("\n## Core path\n");
    REQUIRE(section_at != std::string::npos);
    CHECK(section_at < text.find("\n## Step "));
    const std::string section = one_line(text.substr(section_at, text.find("\n## ", section_at + 1) - section_at));
    const std::string steps = "steps " + joined(core_steps) + ", " + std::to_string(core_minutes) + " minutes";
    const std::string extension_list =
        extensions.empty() ? "no extension"
                           : std::string(extensions.size() > 1 ? "steps " : "step ") + joined(extensions) + ".";
    const std::string check = "`./labkit check " + id + "`";
    INFO("the core path section must say \"" << steps << "\", \"" << extension_list << "\" and " << check);
    CHECK(section.find(steps) != std::string::npos);
    CHECK(section.find(extension_list) != std::string::npos);
    CHECK(section.find(check) != std::string::npos);
  }
}

TEST_CASE("each hints file marks its extension steps' sections, and only those", "[kit]") {
  const nlohmann::json all = manifest();
  for (const auto& lab : all["labs"]) {
    const fs::path hints = fs::path(source_dir()) / "handouts" / "hints" / (stem_of(lab) + ".md");
    if (!fs::exists(hints)) continue;
    INFO(hints.string());
    const std::string text = labkit::read_file(hints);
    for (const auto& step : lab["steps"]) {
      const std::string heading = "\n## Step " + std::to_string(step["step"].get<int>());
      const bool core = step["tier"] == "core";
      INFO("step " << step["step"] << " is " << (core ? "core: \"" : "an extension: \"") << heading.substr(1)
                   << (core ? "\"" : " (extension)\""));
      CHECK(text.find(heading + (core ? " (extension)\n" : "\n")) == std::string::npos);
    }
  }
}
