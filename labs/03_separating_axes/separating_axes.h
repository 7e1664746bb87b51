// Lab 03: separating axes: oriented boxes, triangle pairs, moving boxes.
// Handout: handouts/03_separating_axes.md. Lectures 000 (collision handling part 1:
// separating axes, oriented bounding boxes, table 6.7 for two moving boxes) and 003
// (narrow phase: triangle against triangle, intervals on the planes' common line).
//
// You write labs/03_separating_axes/separating_axes.cpp; this header is the contract.
//
// The separating axis test. Project both shapes onto a line with direction L: each
// becomes an interval. If the intervals do not overlap, a plane perpendicular to L
// passes between the shapes: L separates them. A box projects to the interval with
// centre c . L and radius r = sum_k h_k |A_k . L| (A_k its axes, h_k its half extents):
//
//        +--------+
//        |   A    |         +------+            T = c_B - c_A
//        |   c_A  |        /  c_B /             separated along L when
//        +--------+       +------+                |T . L| > r_A + r_B
//   ---[-----*-----]---------[--*--]----->  L
//            |<-r_A->|     |<r_B>|
//            |<---- |T . L| ---->|               (L need not have unit length:
//                                                 both sides scale with |L|)
//
// Two convex polyhedra are apart exactly when some face normal of either, or some cross
// product of an edge of one with an edge of the other, separates them. For two boxes
// those are the 15 axes, numbered
//
//    0, 1, 2   A_0, A_1, A_2            (A's face normals: A's columns)
//    3, 4, 5   B_0, B_1, B_2            (B's face normals)
//    6 + 3 i + j   A_i x B_j            (i, j = 0, 1, 2: 6 is A_0 x B_0, 14 is A_2 x B_2)
//
// Boxes. A box is center + sum_k s_k half_extents[k] axes.col(k), |s_k| <= 1: closed.
// Its axes are orthonormal (to rounding; right- or left-handed). Half extents are >= 0;
// zero ones are allowed (a rectangle, a segment, a point).
//  - Touching counts: boxes that share only a face, an edge or a corner intersect, and
//    separated_on_axis is strict (intervals that touch are not separated).
//  - Parallel edges. When A_i and B_j are parallel, A_i x B_j = 0 is no axis at all: it
//    must never report a separation (the face axes decide those cases). When they are
//    nearly parallel, A_i x B_j is tiny and its direction is mostly rounding error; it
//    must still never report a separation that exact arithmetic along your computed
//    direction would not (handout, step 2: test along the computed vector itself).
//
// Triangles are closed: touching at a vertex or along an edge counts. Coplanar
// triangles intersect when they overlap in their plane (sharing a single point is
// enough). A zero-area triangle (collinear or coincident vertices) has no plane and
// never intersects anything.
//
// Input domain: where answers must match the exact ones (within the tolerances below).
// S (below) from 1e-50 to 1e50; boxes and triangles in any orientation and position,
// also far from the origin; an axis L of any non-zero length within the same range;
// triangles of zero area or whose smallest height is at least 1e-8 of their longest
// edge (needles up to aspect ratio 1e8 included); velocities and durations whose
// displacement duration * velocity stays within the range.
//
// Preconditions (the reference checks them and throws std::invalid_argument naming the
// argument and the rule; the check never grades them): every coordinate, half extent,
// axis entry, velocity and the duration finite; half extents >= 0; box axes orthonormal
// to 1e-6; duration >= 0; box_axis's index 0 to 14. Not errors, with their results
// defined above and below: zero half extents, a zero axis L, zero-area triangles, a zero
// duration.
//
// Tolerances. S is the largest absolute coordinate of the input's positions: box
// centers and half extents (for moving boxes also each box's center at the end,
// center + duration * velocity), triangle vertices. tol = 1e-9 S.
//  - Yes/no answers must equal the exact answer, except on ambiguous inputs: those
//    whose exact answer changes when every position moves by tol and every axis entry
//    by 1e-9 (and the duration by 1e-9 of itself). There either answer passes.
//  - Projections (step 1): center and radius within tol |L|.
//  - Axes (step 2): within 1e-12 of the exact A_i x B_j.
//  - find_boxes (step 3): the axis has unit length (within 1e-9) and is parallel to the
//    numbered axis (within 1e-9, plus 1e-15 / |A_i x B_j| for an edge axis, whose
//    direction rounding fixes only that well); depth is within tol of the exact depth
//    along your axis; see step 3 for which axis.
//  - Interval ends (step 4, triangles_by_intervals): within tol of the exact ends.
//  - Moving boxes (step 5): times are checked on the boxes' positions at those times,
//    not against the exact times (see step 5).
#pragma once

#include "common/geometry.h"

namespace labkit::lab03 {

// ---- Step 1 (L03S1): project a box on an axis ----------------------------------------

// The box projected onto the line through the origin with direction L: the interval
// [center - radius, center + radius], in units of |L| (for a unit L, true lengths).
struct Projection {
  double center = 0.0;  // c . L
  double radius = 0.0;  // sum_k h_k |A_k . L|, >= 0
};
Projection project_box(const Box& box, const Vec3& axis);

// Do the two projections onto L miss each other: |(c_B - c_A) . L| > r_A + r_B?
// Strict: touching intervals are not separated. A zero axis separates nothing.
bool separated_on_axis(const Box& a, const Box& b, const Vec3& axis);

// ---- Step 2 (L03S2): the 15 axes; the test query -------------------------------------

// Axis number `index` (0 to 14, numbered as at the top), not normalised: A_i, B_j, or
// the cross product A_i x B_j.
Vec3 box_axis(const Box& a, const Box& b, int index);

// Do the closed boxes intersect? True when no axis separates them.
bool test_boxes(const Box& a, const Box& b);

// ---- Step 3 (L03S3): the find query: separating axis, or least penetration -----------

struct BoxContact {
  bool intersecting = false;  // the closed boxes share a point
  int axis_index = -1;        // 0..14: separated: an axis that separates them;
                              // intersecting: the axis of least penetration
  Vec3 axis = Vec3::Zero();   // that axis with unit length, pointing from A toward B:
                              // (c_B - c_A) . axis >= 0 (either way when it is 0)
  double depth = 0.0;         // r_A + r_B - |(c_B - c_A) . axis| along the unit axis:
                              // how far B must move along `axis` for the projections
                              // to just touch; negative when separated (minus the gap)
};

// Separated: any one of the 15 axes that separates them (the first found is fine; one
// along which the projections overlap by at most tol, rounding, passes too).
// Intersecting: the axis with the smallest depth among the face axes and the edge axes
// with |A_i x B_j| >= 1e-6; nearly parallel edges (below 1e-6) are left out, as their
// direction is not known well enough (between 0.5e-6 and 2e-6 either choice passes).
// Ties: any of the tied axes. The depth must be the least within tol, plus, for an
// edge axis it is compared with, 1e-15 (|c_B - c_A| + the six half extents) /
// |A_i x B_j| (how much rounding may turn that axis).
BoxContact find_boxes(const Box& a, const Box& b);

// ---- Step 4 (L03S4): triangle against triangle ---------------------------------------
// First the lecture's method as it stands (triangles_by_intervals), then the test that
// replaces it (test_triangles).

// The lecture's interval method (lecture 003). n0, n1 are the normals
// (v1 - v0) x (v2 - v0), and d_i = n . (v_i - v0) the signed volumes of one triangle's
// vertices against the other's plane. When each triangle has vertices strictly on both
// sides of the other's plane, each meets that plane in a segment, both segments lie on
// the line of the two planes (direction D = n0 x n1), and the triangles intersect
// exactly when the segments overlap. With p the vertex alone on its side, the segment's
// ends are where edges p q and p r cross the plane, x = p + (q - p) d_p / (d_p - d_q).
// The line is read on one coordinate, the one where |D_k| is largest (any coordinate
// with D_k != 0 keeps the order along the line; the largest keeps it best).
struct LineIntervals {
  bool crossing = false;  // each triangle has vertices strictly on both sides of the other's
                          // plane (every d_i != 0); false: the fields below stay 0 and -1
  int axis = -1;          // k, the coordinate where |D_k| is largest (ties: either)
  double low0 = 0.0;      // t0's segment in t1's plane, read on coordinate k: low0 <= high0
  double high0 = 0.0;
  double low1 = 0.0;  // t1's segment in t0's plane: low1 <= high1
  double high1 = 0.0;
  bool overlap = false;  // the intervals share a point (ends that touch count)
};
// Its domain (where it is checked, and where it is exact): both triangles with a smallest
// height at least 1/100 of their longest edge, every vertex at least S/100 away from the
// other's plane, on both sides. There its rounding moves each end by far less than tol,
// the ends are checked within tol of the exact ones, and overlap must be the exact answer
// (but on ambiguous input, as for test_triangles).
// Outside it, it is not exact and not complete: a vertex in (or within rounding of) the
// other's plane leaves p undefined or its sign noise, coplanar triangles give D = 0, nearly
// parallel planes or needles make the ends ratios of rounding noise, and a zero-area
// triangle has no plane. Each needs a case of its own, and every comparison of two
// constructed ends can flip within rounding. That is why test_triangles replaces it:
// it decides each comparison by the sign of one volume of input points, and never
// builds an end.
LineIntervals triangles_by_intervals(const Triangle& t0, const Triangle& t1);

// Do the closed triangles intersect (coplanar ones included; see the rules above)?
//
// Sides and zeros. Each vertex of one triangle is on the positive (+) or negative (-)
// side of the other's plane, or in it (0: its signed volume is zero, or within the
// rounding of how you computed it; on exact input, exactly zero). All + or all -: apart.
// All 0: coplanar (the rule above). Otherwise the triangle meets the plane in a segment
// (maybe a single point), and is rotated to (p, q, r) with p alone on its side:
//  - p on one side, q and r on the other or in the plane (+ - -, + - 0, + 0 0, ...):
//    the segment runs from edge p q to edge p r; a vertex in the plane is its own end;
//  - p in the plane, q and r strictly on one side (0 - -): it touches the plane at p only.
// (Flip the other triangle's plane so that p's side is +.) Touching counts: a segment
// that is one point still intersects the other triangle's segment when it lies on it.
bool test_triangles(const Triangle& t0, const Triangle& t1);

// ---- Step 5 (L03S5): two moving boxes: first and last contact ------------------------

// Box a moves with constant velocity velocity_a, box b with velocity_b (no rotation),
// for times t in [0, duration]: at time t box a is centered at a.center + t velocity_a.
// The times at which the closed boxes touch or overlap form one interval (or none).
struct ContactInterval {
  bool contact = false;  // they touch at some time in [0, duration]
  double first = 0.0;    // the first such time (0 when they touch already at t = 0)
  double last = 0.0;     // the last such time (duration when they still touch at the end)
};

// Do the boxes touch at any time in [0, duration]? A test on the swept boxes: the 15
// axes, each swept by the motion, and the 6 axes W x A_i, W x B_j of the lecture's
// table 6.7 (W = velocity_b - velocity_a).
bool test_moving_boxes(const Box& a, const Vec3& velocity_a, const Box& b, const Vec3& velocity_b, double duration);

// When do they touch? Equal velocities: [0, duration] if they touch at all. Boxes that
// touch at a single instant: first == last. duration >= 0 (0: a test at t = 0).
//
// Times are checked on the boxes' positions, with m(t) the largest separation of the
// projections over the 15 axes at time t (> 0: apart by that much along that axis;
// <= 0: overlapping). Your first time passes when m(first) <= tol and m >= -tol on
// [0, first] (no earlier overlap deeper than tol); first = 0 needs only m(0) <= tol.
// Likewise last, on [last, duration]. This accepts any time within tol / |W| of the
// exact one, and more when the boxes meet at a grazing angle, where the time is
// sensitive to the input but the positions are not.
ContactInterval find_moving_boxes(const Box& a, const Vec3& velocity_a, const Box& b, const Vec3& velocity_b,
                                  double duration);

// ---- Step 6 (L03S6): robustness: touching and parallel -------------------------------
// No new function: steps 1 to 3 must follow the rules at the top of this file exactly on
// exact input (integer coordinates up to 1024 times a power of two, axes that are signed
// permutations of the coordinate axes): boxes touching along a face, an edge or at a
// corner, edges exactly parallel, zero half extents.

// ---- Step 7 (L03S7): robustness: triangles and moving boxes --------------------------
// No new function (an extension, as steps 4 and 5 are): steps 4 and 5 must follow the
// same rules on exact input: triangles touching at vertices and edges or lying in one
// plane, zero-area triangles, moving boxes that touch at one instant, slide along each
// other, or start in contact.

}  // namespace labkit::lab03
