// Lab 03's queries: the name of each question its tests ask (a replay token's prefix,
// `./labkit replay project_box:...`) and the input it takes. The tests, the viewer's scene and
// its presets read this table (common/harness/query.h); a query is added or renamed here.
#pragma once

#include "common/harness/query.h"
#include "common/inputs/03_separating_axes.h"

#define LABKIT_LAB03_QUERIES(X) \
  X(project_box, "project_box", BoxOnAxis)                            \
  X(separated_on_axis, "separated_on_axis", BoxPairOnAxis)            \
  X(box_axis, "box_axis", BoxPair)                                    \
  X(test_boxes, "test_boxes", BoxPair)                                \
  X(find_boxes, "find_boxes", BoxPair)                                \
  X(triangles_by_intervals, "triangles_by_intervals", TrianglePair)   \
  X(test_triangles, "test_triangles", TrianglePair)                   \
  X(test_moving_boxes, "test_moving_boxes", MovingBoxes)              \
  X(find_moving_boxes, "find_moving_boxes", MovingBoxes)              \
  X(robust_boxes, "robust.boxes", BoxPair)                            \
  X(robust_triangles, "robust.triangles", TrianglePair)               \
  X(robust_moving_boxes, "robust.moving_boxes", MovingBoxes)         

namespace labkit::lab03::query {
LABKIT_LAB03_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB03_QUERIES)
}  // namespace labkit::lab03::query
