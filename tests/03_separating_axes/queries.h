// Lab 03's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), and the table of the queries (last). Both processes include it.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too.
#pragma once

#include "separating_axes.h"

#include "common/fields.h"
#include "common/harness/query.h"
#include "common/protocol/calls.h"

namespace labkit::lab03 {

LABKIT_FIELDS(Projection, center, radius)
LABKIT_FIELDS(BoxContact, intersecting, axis_index, axis, depth)
LABKIT_FIELDS(LineIntervals, crossing, axis, low0, high0, low1, high1, overlap)
LABKIT_FIELDS(ContactInterval, contact, first, last)

}  // namespace labkit::lab03

// clang-format off
#define LABKIT_LAB03_CALLS(CALL, METHOD)                                                            \
  CALL(Projection, project_box, (const Box&, const Vec3&))                                          \
  CALL(bool, separated_on_axis, (const Box&, const Box&, const Vec3&))                              \
  CALL(Vec3, box_axis, (const Box&, const Box&, int))                                               \
  CALL(bool, test_boxes, (const Box&, const Box&))                                                  \
  CALL(BoxContact, find_boxes, (const Box&, const Box&))                                            \
  CALL(LineIntervals, triangles_by_intervals, (const Triangle&, const Triangle&))                   \
  CALL(bool, test_triangles, (const Triangle&, const Triangle&))                                    \
  CALL(bool, test_moving_boxes, (const Box&, const Vec3&, const Box&, const Vec3&, double))         \
  CALL(ContactInterval, find_moving_boxes, (const Box&, const Vec3&, const Box&, const Vec3&, double))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab03, LABKIT_LAB03_CALLS)

// ---- The inputs ------------------------------------------------------------------------
// Lab 03's inputs: what each query of separating_axes.h is given, one struct per query,
// and their fields() (the names a report prints and a replay token reads). The generators
// (gen:: in tests/03_separating_axes/judge.h) draw them, the judge and the viewer read
// them.
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
