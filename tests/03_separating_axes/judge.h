// Lab 03's checker: the generators that draw each query's input, then the verdicts.
//
// Lab 03's verdicts: each judge compares one answer with the exact oracle, following
// the tolerances and degenerate rules of labs/03_separating_axes/separating_axes.h.
// The tests and the viewer both use them, so a red mark in the viewer and a failing
// case in `./labkit check` always agree.
//
// The generators, first in this file (gen::):
// Seeded inputs for separating axes (lab 03): boxes on an axis, box pairs, triangle
// pairs and moving boxes, on the dyadic lattice of common/generators/generators.h.
//
// Boxes turn by rotations from small integer quaternions (orthonormal to rounding), by
// signed permutations (exact), and by tiny rotations of each other, so that edges are
// exactly parallel, parallel to rounding, or 2^-k apart. The families place boxes
// face to face, edge across edge and corner on face, touching or a power-of-two gap
// apart or into each other (2^-4 to 2^-60 of the scale), flatten them (zero half
// extents), nest them, and move them far from the origin, at every scale from 2^-20 to
// 2^20. Triangle pairs cross through each other, touch at vertices and edges, lie in one
// plane (overlapping, touching or apart), sit in nearly parallel or parallel planes, and
// include zero-area triangles. Moving boxes meet at a dyadic time, head on, at an angle
// or grazing, slide along each other, miss, start in contact, move together, or pass
// through a thin box within one step.
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
bool in_interval_domain(const TrianglePair& p);
// Exactly degenerate triangle pairs on integer coordinates: through vertices and edges,
// touching, coplanar, zero area.
rc::Gen<TrianglePair> exact_triangle_pair();

rc::Gen<MovingBoxes> moving_boxes();
// Exact boxes meeting at dyadic times with lattice velocities.
rc::Gen<MovingBoxes> exact_moving_boxes();

}  // namespace labkit::gen

namespace labkit::lab03 {

namespace judge {

using check::Outcome;

using check::Rules;  // random cases, or a robustness step's exact input

Outcome project_box(const BoxOnAxis& in, const Projection& got);
Outcome separated_on_axis(const BoxPairOnAxis& in, bool got, Rules rules = Rules::random);
// got[k] = box_axis(a, b, k) for k = 0..14.
Outcome box_axes(const BoxPair& in, const std::array<Vec3, 15>& got);
Outcome test_boxes(const BoxPair& in, bool got, Rules rules = Rules::random);
Outcome find_boxes(const BoxPair& in, const BoxContact& got, Rules rules = Rules::random);
// The interval method, on its domain (gen::in_interval_domain); outside it any answer
// passes.
Outcome triangles_by_intervals(const TrianglePair& in, const LineIntervals& got, Rules rules = Rules::random);
Outcome test_triangles(const TrianglePair& in, bool got, Rules rules = Rules::random);
Outcome test_moving_boxes(const MovingBoxes& in, bool got, Rules rules = Rules::random);
Outcome find_moving_boxes(const MovingBoxes& in, const ContactInterval& got, Rules rules = Rules::random);

}  // namespace judge
}  // namespace labkit::lab03
