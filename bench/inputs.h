// Seeded inputs shared by the benchmarks, and the exact verdict on each answer: every
// implementation is measured on the same inputs, and its disagreements with the exact
// answer (outside the ambiguous cases) are counted beside its speed.
#pragma once

#include "common/generators/generators.h"

#include <cstddef>
#include <vector>

namespace bench {

using namespace labkit;

// n segment-triangle pairs, zero-area triangles left out: `typical` ones (random, about
// half crossing), or the tests' `hard` mix (touching, coplanar, near-parallel, ...).
enum class Mix { typical, hard };
std::vector<SegmentTrianglePair> segment_triangle_inputs(std::size_t n, Mix mix);

// For each pair: the exact answer, and whether it is in doubt (ambiguous).
struct Exact {
  std::vector<bool> hit;
  std::vector<bool> doubt;
};
Exact exact_segment_triangle(const std::vector<SegmentTrianglePair>& inputs);

// How many answers differ from the exact ones where the exact answer is not in doubt.
int disagreements(const std::vector<bool>& answers, const Exact& exact);
int ambiguous(const Exact& exact);

}  // namespace bench
