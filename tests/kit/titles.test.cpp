// Lab and step titles come from grading/manifest.json alone. The tests' names and the
// viewer's list read them from it (common/harness/titles.h); the handouts and the banners
// of the contract headers, stubs and references are prose, so this test holds them to it:
// change a title in the manifest and this names every line to change with it.
#define CATCH_CONFIG_MAIN  // Catch2 2: main() is here; Catch2 3: it is Catch2::Catch2WithMain's
#include "common/harness/catch.h"
#include "common/text.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <string>

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
      const std::string tag = step["tag"], heading_start = "## Step " + std::to_string(step["step"].get<int>()) + ": ";
      const std::regex heading("^## Step [0-9]+: (.*) \\(" + tag + "\\)$", std::regex::multiline);
      std::smatch m;
      INFO(tag << ": the handout needs the heading \"" << heading_start << step["title"].get<std::string>() << " ("
               << tag << ")\"");
      REQUIRE(std::regex_search(text, m, heading));
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
