// Lab 03's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), the table of the queries, and how each input is drawn and each answer
// judged (last): a new query is written here, then defined in generators*.cpp and
// judge*.cpp. Both processes include it; the answerer uses only its first part.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too.
#pragma once

#include "separating_axes.h"

#include "common/fields.h"
#include "common/harness/outcome.h"
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
// (gen::, declared below) draw them, the judge and the viewer read
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

// ---- How each input is drawn, and the verdicts -----------------------------------------
// Declared here, beside the queries they serve; defined in generators*.cpp (gen::) and
// judge*.cpp (judge::). RapidCheck is included where the generators are called.
namespace rc {
template <typename T> class Gen;
}  // namespace rc

// Seeded inputs for separating axes (lab 03): boxes on an axis, box pairs, triangle pairs
// and moving boxes, on the dyadic lattice of common/generators/generators.h.
//
// Boxes turn by rotations from small integer quaternions (orthonormal to rounding), by
// signed permutations (exact), and by tiny rotations of each other, so that edges are
// exactly parallel, parallel to rounding, or 2^-k apart. The families place boxes face to
// face, edge across edge and corner on face, touching or a power-of-two gap apart or into
// each other (2^-4 to 2^-60 of the scale), flatten them (zero half extents), nest them,
// and move them far from the origin, at every scale from 2^-20 to 2^20. Triangle pairs
// cross through each other, touch at vertices and edges, lie in one plane (overlapping,
// touching or apart), sit in nearly parallel or parallel planes, and include zero-area
// triangles. Moving boxes meet at a dyadic time, head on, at an angle or grazing, slide
// along each other, miss, start in contact, move together, or pass through a thin box
// within one step.
namespace labkit::gen {

// A rotation from a small integer quaternion (rounded), or a signed permutation (exact).
rc::Gen<Mat3> rotation();
// An oriented box at every scale: lattice center, rotation, half extents of 1/2 to 8
// units of the scale with 20-bit fractions, sometimes zero.
rc::Gen<Box> box(double scale);

rc::Gen<BoxOnAxis> box_on_axis();
rc::Gen<BoxPairOnAxis> box_pair_on_axis();
rc::Gen<BoxPair> box_pair();
// Exactly degenerate pairs on integer coordinates (|x| <= 1024, times a power of two)
// with signed-permutation axes: touching faces, edges and corners, parallel edges,
// zero half extents, nested and coincident boxes. The robustness step's input.
rc::Gen<BoxPair> exact_box_pair();

rc::Gen<TrianglePair> triangle_pair();
// The interval method's domain (lab 03 step 4, triangles_by_intervals): fat triangles
// (smallest height >= 1/100 of the longest edge) crossing each other's planes, every
// vertex at least S/100 off the other's plane; often with two interval ends just apart
// or just overlapping (10 to 80 tol), and at every scale.
rc::Gen<TrianglePair> crossing_triangle_pair();
// Exactly degenerate triangle pairs on integer coordinates: through vertices and edges,
// touching, coplanar, zero area.
rc::Gen<TrianglePair> exact_triangle_pair();

rc::Gen<MovingBoxes> moving_boxes();
// Exact boxes meeting at dyadic times with lattice velocities.
rc::Gen<MovingBoxes> exact_moving_boxes();

}  // namespace labkit::gen

// Lab 03's verdicts: each judge compares one answer with the exact oracle, following the
// tolerances and degenerate rules of labs/03_separating_axes/separating_axes.h. The tests
// and the viewer both use them, so a red mark in the viewer and a failing case in
// `./labkit check` always agree.
namespace labkit::lab03::judge {

using check::Outcome;
using check::Rules;  // random cases, or a robustness step's exact input

Outcome project_box(const BoxOnAxis& in, const Projection& got);
Outcome separated_on_axis(const BoxPairOnAxis& in, bool got, Rules rules = Rules::random);
// got[k] = box_axis(a, b, k) for k = 0..14.
Outcome box_axes(const BoxPair& in, const std::array<Vec3, 15>& got);
Outcome test_boxes(const BoxPair& in, bool got, Rules rules = Rules::random);
Outcome find_boxes(const BoxPair& in, const BoxContact& got, Rules rules = Rules::random);
// The interval method's domain: fat triangles (smallest height >= 1/100 of the longest
// edge), every vertex at least S/100 off the other's plane, on both sides.
bool in_interval_domain(const TrianglePair& p);
// The interval method, on its domain; outside it any answer passes.
Outcome triangles_by_intervals(const TrianglePair& in, const LineIntervals& got, Rules rules = Rules::random);
Outcome test_triangles(const TrianglePair& in, bool got, Rules rules = Rules::random);
Outcome test_moving_boxes(const MovingBoxes& in, bool got, Rules rules = Rules::random);
Outcome find_moving_boxes(const MovingBoxes& in, const ContactInterval& got, Rules rules = Rules::random);

}  // namespace labkit::lab03::judge
