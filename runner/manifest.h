// grading/manifest.json: the labs, their steps, points, and the files a student edits.
#pragma once

#include <string>
#include <vector>

namespace runner {

struct Step {
  int number = 0;
  std::string tag;  // "L02S3": the tag in the stub, the handout and the test names
  std::string title;
  double points = 0;
  bool partial = false;  // partial credit by the fraction of cases passed
  // The lab's robustness step: exactly degenerate input, judged by the header's exact rules.
  // Only its random families may be mostly ambiguous; every other step's must be decisive.
  bool robustness = false;
  // Its tier: core (the lab's path for one 3-hour session) or extension (the deeper work).
  bool core = true;
  int minutes = 0;  // an estimate of the time a second-year student needs for it
  // Where its section is: the lab's handout, or (the manifest's "handout": "extensions")
  // the handout's companion for extension steps a one-session handout has no room for.
  bool in_extensions_handout = false;
};

struct Lab {
  std::string id;    // "02"
  std::string name;  // "segment_triangle"
  std::string title;
  std::vector<std::string> student_files;
  std::vector<Step> steps;
  int core_minutes() const;  // the core path's estimate

  std::string stem() const { return id + "_" + name; }
  // A step runs two programs (common/protocol/answerer.h): the judge's, the kit's own
  // (tests, judges, exact oracle), and the answerer, the lab's functions from one
  // implementation (student, reference, mutant_NAME, or a graded submission) and nothing
  // of the judge's.
  std::string judge_binary() const { return "test_" + stem(); }
  std::string answerer(const std::string& implementation) const { return "answer_" + stem() + "_" + implementation; }
  std::string handout() const { return "handouts/" + stem() + ".md"; }
  std::string extensions_handout() const { return "handouts/" + stem() + ".extensions.md"; }
  std::string handout_of(const Step& s) const { return s.in_extensions_handout ? extensions_handout() : handout(); }
  std::string hints() const { return "handouts/hints/" + stem() + ".md"; }
};

struct Manifest {
  std::vector<Lab> labs;
  const Lab* find(const std::string& id) const;
};

// Throws std::runtime_error with a one-line reason.
Manifest load_manifest(const std::string& path);

}  // namespace runner
