// Builds one lab of one submission in seconds, without configuring anything: the
// student's file(s) are compiled with exactly the command the kit's build uses for the
// stub (from compile_commands.json), then linked with exactly the kit's own link command
// for the lab's student answer program (recorded at build time by cmake/record-command.sh),
// the stub's library swapped for the student's objects. That program holds the student's
// code, the geometry types and the answerer's loop, nothing else of the kit's; the tests,
// judges and oracle stay in the kit's own test program (common/protocol/answerer.h).
#pragma once

#include "kit.h"
#include "manifest.h"
#include "sandbox.h"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace runner {

struct Command {
  std::string directory;
  std::vector<std::string> argv;
};

// How the kit builds lab NN's student answer program.
struct LabRecipe {
  std::map<std::string, Command> compile;  // student file (manifest path) -> its compile command
  Command link;
  std::string student_library;        // the stub's library in `link`, replaced by the objects
  std::set<std::string> kit_symbols;  // every symbol the kit's link inputs define
};

// Reads the recipe from the kit's build tree; throws with the reason when it is missing.
LabRecipe load_recipe(const Paths& paths, const Lab& lab);

// The paths ./labkit grade has the kit build before grading (the records need them).
std::string recipe_record(const Paths& paths, const Lab& lab);

struct LabBuild {
  bool ok = false;
  std::string binary;      // the answer program, when ok
  std::string errors;      // the first compiler, linker or audit errors, when not
  bool timed_out = false;  // a compile or the link ran out of its `seconds`
  double seconds = 0;
};

// Compiles `files` (manifest path -> file) and links them into `folder`'s answer program,
// each command confined by `sandbox` and given at most `seconds` (the grader gives less
// when a submission's time budget has less left).
LabBuild build_lab(const Paths& paths, const Lab& lab, const LabRecipe& recipe,
                   const std::map<std::string, std::string>& files, const std::string& folder, const Sandbox& sandbox,
                   double seconds = 300);

// The defined symbols of a system's C and C++ runtime: a student file may not replace them.
const std::set<std::string>& runtime_symbols();

}  // namespace runner
