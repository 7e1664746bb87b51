// Lab 03's checker beyond its queries (queries.h declares the queries, their generators
// and their verdicts): what the lab's generators, judges, tests and viewer scene share.
#pragma once

#include "03_separating_axes/queries.h"
#include "common/harness/check.h"
#include "common/harness/codec.h"

#include <rapidcheck.h>
#include <algorithm>
#include <array>

namespace labkit {

// The length scale of these inputs: the largest absolute coordinate of every position
// (centers, half extents, triangle vertices; for moving boxes also the centers at the
// end, center + duration * velocity). Axes are unit-free and do not count.
double scale_of(const BoxOnAxis& in);
double scale_of(const BoxPair& in);
double scale_of(const BoxPairOnAxis& in);
double scale_of(const TrianglePair& in);
double scale_of(const MovingBoxes& in);

}  // namespace labkit
