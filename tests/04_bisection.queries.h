// Lab 04's queries: the name of each question its tests ask (a replay token's prefix,
// `./labkit replay placed:...`) and the input it takes. The tests, the viewer's scene and
// its presets read this table (common/harness/query.h); a query is added or renamed here.
#pragma once

#include "common/harness/query.h"
#include "common/inputs/04_bisection.h"

#define LABKIT_LAB04_QUERIES(X) \
  X(placed, "placed", Sphere)                                              \
  X(overlap_spheres, "overlap.spheres", Sphere)                            \
  X(overlap_sphere_box, "overlap.sphere_box", Sphere)                      \
  X(distance_spheres, "distance.spheres", Sphere)                          \
  X(distance_sphere_box, "distance.sphere_box", Sphere)                    \
  X(closest_point, "closest_point", PointBox)                              \
  X(overlap_at, "overlap_at", MovingPairCase)                              \
  X(distance_at, "distance_at", MovingPairCase)                            \
  X(bisect, "bisect", MovingPairCase)                                      \
  X(tunnelling, "tunnelling", MovingPairCase)                              \
  X(smallest_size, "smallest_size", MovingPairCase)                        \
  X(closing_speed, "closing_speed", MovingPairCase)                        \
  X(substeps_for, "substeps_for", SubstepRule)                             \
  X(sample_then_bisect, "sample_then_bisect", SampledPair)                 \
  X(advance, "advance", AdvancedPair)                                      \
  X(robust_closest_point, "robust.closest_point", PointBox)                \
  X(robust_overlap_at, "robust.overlap_at", MovingPairCase)                \
  X(robust_bisect, "robust.bisect", MovingPairCase)                        \
  X(robust_substeps_for, "robust.substeps_for", SubstepRule)               \
  X(robust_sample_then_bisect, "robust.sample_then_bisect", SampledPair)   \
  X(robust_advance, "robust.advance", AdvancedPair)                       

namespace labkit::lab04::query {
LABKIT_LAB04_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB04_QUERIES)
}  // namespace labkit::lab04::query
