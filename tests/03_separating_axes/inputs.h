// Lab 03's inputs: what each query of separating_axes.h is given, one struct per query,
// and their fields() (the names a report prints and a replay token reads). The generators
// (tests/03_separating_axes/generators.h) draw them, the judge and the viewer read them.
#pragma once

#include "separating_axes.h"

#include "common/fields.h"
#include "common/harness/query.h"

namespace labkit {

struct BoxOnAxis {
  Box box;
  Vec3 axis = Vec3::UnitX();
};
LABKIT_FIELDS(BoxOnAxis, box, axis)

struct BoxPair {
  Box a;
  Box b;
};
LABKIT_FIELDS(BoxPair, a, b)

struct BoxPairOnAxis {
  Box a;
  Box b;
  Vec3 axis = Vec3::UnitX();
};
LABKIT_FIELDS(BoxPairOnAxis, a, b, axis)

struct TrianglePair {
  Triangle t0;
  Triangle t1;
};
LABKIT_FIELDS(TrianglePair, t0, t1)

// Box a moves with velocity_a, box b with velocity_b, for t in [0, duration].
struct MovingBoxes {
  Box a;
  Vec3 velocity_a = Vec3::Zero();
  Box b;
  Vec3 velocity_b = Vec3::Zero();
  double duration = 1.0;
};
LABKIT_FIELDS(MovingBoxes, a, velocity_a, b, velocity_b, duration)

}  // namespace labkit

// ---- The queries -------------------------------------------------------------------------
// Each question the tests ask and the input it takes, by the step that asks it first:
// X(name, Input) is the query "name", X_IN(group, name, Input) the query "group.name"
// (common/harness/query.h). The tests, the viewer's scene and its presets read this table:
// a query is added or renamed here and nowhere else.
// clang-format off
#define LABKIT_LAB03_QUERIES(X, X_IN)                                                  \
  /* step 1 */ X(project_box, BoxOnAxis) X(separated_on_axis, BoxPairOnAxis)           \
  /* step 2 */ X(box_axis, BoxPair) X(test_boxes, BoxPair)                             \
  /* step 3 */ X(find_boxes, BoxPair)                                                  \
  /* step 4 */ X(triangles_by_intervals, TrianglePair) X(test_triangles, TrianglePair) \
  /* step 5 */ X(test_moving_boxes, MovingBoxes) X(find_moving_boxes, MovingBoxes)     \
  /* step 6 */ X_IN(robust, boxes, BoxPair)                                            \
  /* step 7 */ X_IN(robust, triangles, TrianglePair) X_IN(robust, moving_boxes, MovingBoxes)
// clang-format on

namespace labkit::lab03::query {
LABKIT_QUERIES(LABKIT_LAB03_QUERIES)
}  // namespace labkit::lab03::query
