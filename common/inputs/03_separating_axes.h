// Lab 03's inputs: what each query of separating_axes.h is given, one struct per query,
// and their fields() (the names a report prints and a replay token reads). The generators
// (common/generators/03_separating_axes.h) draw them, the judge and the viewer read them.
#pragma once

#include "separating_axes.h"

#include "common/harness/query.h"

namespace labkit {

struct BoxOnAxis {
  Box box;
  Vec3 axis = Vec3::UnitX();
};
template <class Visit> void fields(BoxOnAxis& p, Visit&& visit) {
  visit("box", p.box);
  visit("axis", p.axis);
}

struct BoxPair {
  Box a;
  Box b;
};
template <class Visit> void fields(BoxPair& p, Visit&& visit) {
  visit("a", p.a);
  visit("b", p.b);
}

struct BoxPairOnAxis {
  Box a;
  Box b;
  Vec3 axis = Vec3::UnitX();
};
template <class Visit> void fields(BoxPairOnAxis& p, Visit&& visit) {
  visit("a", p.a);
  visit("b", p.b);
  visit("axis", p.axis);
}

struct TrianglePair {
  Triangle t0;
  Triangle t1;
};
template <class Visit> void fields(TrianglePair& p, Visit&& visit) {
  visit("t0", p.t0);
  visit("t1", p.t1);
}

// Box a moves with velocity_a, box b with velocity_b, for t in [0, duration].
struct MovingBoxes {
  Box a;
  Vec3 velocity_a = Vec3::Zero();
  Box b;
  Vec3 velocity_b = Vec3::Zero();
  double duration = 1.0;
};
template <class Visit> void fields(MovingBoxes& p, Visit&& visit) {
  visit("a", p.a);
  visit("velocity_a", p.velocity_a);
  visit("b", p.b);
  visit("velocity_b", p.velocity_b);
  visit("duration", p.duration);
}

}  // namespace labkit

// ---- The queries -------------------------------------------------------------------------
// The name of each question the tests ask (a replay token's prefix) and the input it takes,
// by the step that asks it first. The tests, the viewer's scene and its presets read this
// table (common/harness/query.h): a query is added or renamed here and nowhere else.
#define LABKIT_LAB03_QUERIES(X)                                     \
  /* step 1 */                                                      \
  X(project_box, "project_box", BoxOnAxis)                          \
  X(separated_on_axis, "separated_on_axis", BoxPairOnAxis)          \
  /* step 2 */                                                      \
  X(box_axis, "box_axis", BoxPair)                                  \
  X(test_boxes, "test_boxes", BoxPair)                              \
  /* step 3 */                                                      \
  X(find_boxes, "find_boxes", BoxPair)                              \
  /* step 4 */                                                      \
  X(triangles_by_intervals, "triangles_by_intervals", TrianglePair) \
  X(test_triangles, "test_triangles", TrianglePair)                 \
  /* step 5 */                                                      \
  X(test_moving_boxes, "test_moving_boxes", MovingBoxes)            \
  X(find_moving_boxes, "find_moving_boxes", MovingBoxes)            \
  /* step 6 */                                                      \
  X(robust_boxes, "robust.boxes", BoxPair)                          \
  X(robust_triangles, "robust.triangles", TrianglePair)             \
  X(robust_moving_boxes, "robust.moving_boxes", MovingBoxes)

namespace labkit::lab03::query {
LABKIT_LAB03_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB03_QUERIES)
}  // namespace labkit::lab03::query
