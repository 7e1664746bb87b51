// `labkit-runner fake`: the kit's own test of its scoring and of its judges. A lab is
// graded (every case judged, partial credit as `./labkit grade` gives it) with an
// answerer that does no geometry (tests/kit/fake_answerer.cpp), and what it earns must
// stay under the README's "Scoring" bounds:
//   nothing   (every call answers its default)            0 points on every step
//   random    (random values of each result type)         at most 1 point a lab
//   examples  (the worked examples right, the default elsewhere)  at most 5 points a lab
//   garbage   (NaN, infinities, huge sizes, indices out of range)  every step judged,
//             none of them a crash, a time-out or a failure of the kit's own judge
#pragma once

#include "kit.h"

#include <string>

namespace runner {

struct FakeOptions {
  std::string lab;      // "02"
  std::string answers;  // nothing, random, garbage or examples
  int cases = 1000;     // random cases per query
};

// 0 when the lab's bounds hold; else 1, with the steps that broke them.
int fake(const Paths& paths, const FakeOptions& options);

}  // namespace runner
