// labkit-bench: Google Benchmark's main, plus the build's compiler and flags in the
// context, so that RESULTS.md can say what was measured.
#include "build_flags.h"

#include <benchmark/benchmark.h>

#include <thread>

int main(int argc, char** argv) {
  benchmark::AddCustomContext("compiler", "g++ " __VERSION__);
  benchmark::AddCustomContext("flags", LABKIT_CXX_FLAGS);
  benchmark::AddCustomContext("cores", std::to_string(std::thread::hardware_concurrency()));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
