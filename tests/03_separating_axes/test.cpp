// Lab 03 tests. Each step: the hand-worked examples of handouts/03_separating_axes.md,
// then random cases against the exact oracle (tests/03_separating_axes/judge.cpp).
#include "03_separating_axes/judge.h"
#include "separating_axes.h"

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace labkit;
using namespace labkit::lab03;
using check::Expect;
using check::Outcome;
using check::rejects;
using judge::Rules;

// The header's input domain (S from 1e-50 to 1e50): each case is drawn in it (scaled by a
// power of two, which keeps it the same case) and shrinking a failing case stays in it.
const bool kDomain = [] {
  check::domain({check::Domain::Of::scale, 1e-50, 1e50, true});
  return true;
}();

namespace {

// The handout's boxes. `turned` is the box whose axes are the columns of the rotation
//   (3 -2  6)
//   (6  3 -2) / 7,
//  (-2  6  3)
// and `quarter_turned` turns about z by the angle with cosine 3/5 and sine 4/5.
Box cube(Vec3 center, double half = 1) {
  Box b;
  b.center = center;
  b.half_extents = Vec3(half, half, half);
  return b;
}

Box box(Vec3 center, Vec3 half_extents, Mat3 axes = Mat3::Identity()) {
  Box b;
  b.center = center;
  b.axes = axes;
  b.half_extents = half_extents;
  return b;
}

Mat3 sevenths() {
  Mat3 m;
  m << 3, -2, 6, 6, 3, -2, -2, 6, 3;
  return m / 7.0;
}

Mat3 three_four_five() {
  Mat3 m;
  m << 0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1;
  return m;
}

Box turned(Vec3 center) { return box(center, Vec3(1, 1, 1), sevenths()); }

const Triangle kFloor{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};

Outcome expect_bool(const std::string& field, bool got, bool expected) {
  Expect e(field == "separated_on_axis"
               ? "an axis separates two boxes when their projections on it are apart, |c . L| > r_A + r_B: "
                 "touching intervals are not apart"
           : field == "test_boxes"
               ? "two boxes intersect unless one of the 15 axes separates them (sets are closed: touching intersects)"
               : "two triangles intersect when they share a point: touching counts, and coplanar ones meet where "
                 "they overlap in their plane");
  e.equal(field, got, expected);
  return e.outcome();
}

// An example's own expectation; when it fails, the judge's reason (the contract's rule
// the answer broke) replaces the field-by-field one.
template <class Judge> Outcome with_reason(Outcome own, Judge&& judge) {
  if (own.verdict != Outcome::Verdict::fail) return own;
  const Outcome o = judge();
  return o.verdict == Outcome::Verdict::fail ? o : own;
}

std::array<Vec3, 15> all_axes(const BoxPair& in) {
  std::array<Vec3, 15> axes;
  for (int k = 0; k < 15; ++k) axes[std::size_t(k)] = answerer::box_axis(in.a, in.b, k);
  return axes;
}

Outcome run_moving_find(const MovingBoxes& in, Rules rules = Rules::random) {
  return judge::find_moving_boxes(
      in, answerer::find_moving_boxes(in.a, in.velocity_a, in.b, in.velocity_b, in.duration), rules);
}
Outcome run_moving_test(const MovingBoxes& in, Rules rules = Rules::random) {
  return judge::test_moving_boxes(
      in, answerer::test_moving_boxes(in.a, in.velocity_a, in.b, in.velocity_b, in.duration), rules);
}

}  // namespace

// ---- Step 1 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L03S1) ": worked examples", "[lab03][step1]") {
  const Box b = box({1, 2, 0}, {5, 2.5, 1}, three_four_five());
  const auto expect = [](double center, double radius) {
    return [=](const BoxOnAxis& in) {
      const Projection got = answerer::project_box(in.box, in.axis);
      Expect e("a box projects on L to the interval centre c . L, radius sum_k h_k |A_k . L|");
      e.near("center", got.center, center, 1e-12);
      e.near("radius", got.radius, radius, 1e-12);
      return with_reason(e.outcome(), [&] { return judge::project_box(in, got); });
    };
  };
  check::example(query::project_box, "onto x: radius 5 * 0.6 + 2.5 * 0.8 = 5", BoxOnAxis{b, {1, 0, 0}}, expect(1, 5));
  check::example(query::project_box, "onto y: radius 5 * 0.8 + 2.5 * 0.6 = 5.5", BoxOnAxis{b, {0, 1, 0}},
                 expect(2, 5.5));
  check::example(query::project_box, "onto -x: the radius is never negative", BoxOnAxis{b, {-1, 0, 0}}, expect(-1, 5));
  check::example(query::project_box, "onto (2, 0, 0): everything scales with |L|", BoxOnAxis{b, {2, 0, 0}},
                 expect(2, 10));

  const Box a = cube({0, 0, 0});
  const auto separated = [](bool expected) {
    return [expected](const BoxPairOnAxis& in) {
      const bool got = answerer::separated_on_axis(in.a, in.b, in.axis);
      return with_reason(expect_bool("separated_on_axis", got, expected),
                         [&] { return judge::separated_on_axis(in, got, Rules::exact); });
    };
  };
  check::example(query::separated_on_axis, "apart along x: 7 > 1 + 5",
                 BoxPairOnAxis{a, box({7, 2, 0}, {5, 2.5, 1}, three_four_five()), {1, 0, 0}}, separated(true));
  check::example(query::separated_on_axis, "overlapping along y: 2 < 1 + 5.5",
                 BoxPairOnAxis{a, box({7, 2, 0}, {5, 2.5, 1}, three_four_five()), {0, 1, 0}}, separated(false));
  check::example(query::separated_on_axis, "touching along x: 6 = 1 + 5 is not separated",
                 BoxPairOnAxis{a, box({6, 2, 0}, {5, 2.5, 1}, three_four_five()), {1, 0, 0}}, separated(false));
  check::example(query::separated_on_axis, "a zero axis separates nothing",
                 BoxPairOnAxis{a, cube({9, 0, 0}), {0, 0, 0}}, separated(false));
}

TEST_CASE(LABKIT_STEP(L03S1) ": random cases", "[lab03][step1][oracle]") {
  check::random_cases(query::project_box, gen::box_on_axis(), [](const BoxOnAxis& in) {
    return judge::project_box(in, answerer::project_box(in.box, in.axis));
  });
  check::random_cases(query::separated_on_axis, gen::box_pair_on_axis(), [](const BoxPairOnAxis& in) {
    return judge::separated_on_axis(in, answerer::separated_on_axis(in.a, in.b, in.axis));
  });
}

// ---- Step 2 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L03S2) ": worked examples", "[lab03][step2]") {
  check::example(query::box_axis, "the numbering",
                 BoxPair{cube({0, 0, 0}), box({0, 0, 0}, {1, 1, 1}, three_four_five())},
                 [](const BoxPair& in) {
    Expect e(
        "the 15 axes are A's columns (axes 0-2), B's columns (3-5), then A_i x B_j (6-14), as computed, unnormalised");
    e.near("axis 0 = A_0", answerer::box_axis(in.a, in.b, 0), Vec3(1, 0, 0), 1e-15);
    e.near("axis 4 = B_1", answerer::box_axis(in.a, in.b, 4), Vec3(-0.8, 0.6, 0), 1e-15);
    e.near("axis 7 = A_0 x B_1", answerer::box_axis(in.a, in.b, 7), Vec3(0, 0, 0.6), 1e-15);
    e.near("axis 12 = A_2 x B_0", answerer::box_axis(in.a, in.b, 12), Vec3(-0.8, 0.6, 0), 1e-15);
    e.near("axis 14 = A_2 x B_2 (parallel: zero)", answerer::box_axis(in.a, in.b, 14), Vec3(0, 0, 0), 1e-15);
    return with_reason(e.outcome(), [&] { return judge::box_axes(in, all_axes(in)); });
  });
  const auto expect = [](bool intersecting) {
    return [intersecting](const BoxPair& in) {
      const bool got = answerer::test_boxes(in.a, in.b);
      return with_reason(expect_bool("test_boxes", got, intersecting),
                         [&] { return judge::test_boxes(in, got, Rules::exact); });
    };
  };
  check::example(query::test_boxes, "apart along A_0", BoxPair{cube({0, 0, 0}), cube({3, 0, 0})}, expect(false));
  check::example(query::test_boxes, "overlapping", BoxPair{cube({0, 0, 0}), turned({0, 0.25, 0.5})}, expect(true));
  // Every face axis overlaps; only A_0 x B_0 = (0, 2, 6) / 7 separates: 33/14 > 32/14.
  check::example(query::test_boxes, "apart along the edge axis A_0 x B_0 only",
                 BoxPair{cube({0, 0, 0}), turned({0, 0.75, 2.5})}, expect(false));
  // B is A turned by 2^-54 about y, and its axes are orthonormal only to rounding (as
  // every rotation in doubles is): R(2, 0) = -2^-53 while its cofactor is -2^-54. The
  // boxes overlap by 1/4 along y. The textbook radius b_1 |R(0, 2)| makes the tiny axis
  // A_0 x B_0 "separate" them: 1.75 * 2^-52 > 2^-52 + 2^-54.
  const double e = std::ldexp(1.0, -54);
  Mat3 tilted;
  tilted << 1, 0, e, 0, 1, 0, -2 * e, 0, 1;
  check::example(query::test_boxes, "nearly parallel edges never separate",
                 BoxPair{cube({0, 0, 0}), box({0, 1.75, 0}, {1, 1, 1}, tilted)}, expect(true));
  // A gap of 2^-23 (1.2e-7): an epsilon of 1e-6 added to |R|, the usual repair of the
  // above, hides it.
  check::example(query::test_boxes, "a gap of 2^-23 is a gap",
                 BoxPair{cube({0, 0, 0}), cube({2 + std::ldexp(1.0, -23), 0, 0})}, expect(false));
  // The turned box's corner (12 - 11, 1 - 1, -5 + 5) = (1, 0, 0) sits at the middle of A's
  // face x = 1, lifted by 2^-23: only A_0 separates (the handout's table), so an epsilon
  // on the face axes alone is caught too.
  check::example(query::test_boxes, "a corner 2^-23 above the middle of a face",
                 BoxPair{cube({0, 0, 0}), box({12 + std::ldexp(1.0, -23), 1, -5}, {7, 7, 7}, sevenths())},
                 expect(false));
}

TEST_CASE(LABKIT_STEP(L03S2) ": random cases", "[lab03][step2][oracle]") {
  check::random_cases(query::box_axis, gen::box_pair(),
                      [](const BoxPair& in) { return judge::box_axes(in, all_axes(in)); });
  check::random_cases(query::test_boxes, gen::box_pair(),
                      [](const BoxPair& in) { return judge::test_boxes(in, answerer::test_boxes(in.a, in.b)); });
}

// ---- Step 3 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L03S3) ": worked examples", "[lab03][step3]") {
  const auto expect = [](bool intersecting, int index, int other_index, Vec3 axis, double depth) {
    return [=](const BoxPair& in) {
      const BoxContact got = answerer::find_boxes(in.a, in.b);
      Expect e("intersecting boxes report the axis of least penetration, pointing from A toward B, with its depth");
      e.equal("intersecting", got.intersecting, intersecting);
      e.that("axis_index", got.axis_index == index || got.axis_index == other_index, describe(got.axis_index),
             other_index == index ? describe(index) : describe(index) + " or " + describe(other_index),
             other_index == index ? "the axis is axis " + describe(index)
                                  : "axes " + describe(index) + " and " + describe(other_index) + " tie: either index");
      e.near("axis", got.axis, axis, 1e-12);
      e.near("depth", got.depth, depth, 1e-12);
      return with_reason(e.outcome(), [&] { return judge::find_boxes(in, got, Rules::exact); });
    };
  };
  const Box a = box({0, 0, 0}, {2, 1, 1});
  check::example(query::find_boxes, "overlapping: least along x, depth 0.5", BoxPair{a, cube({2.5, 0.5, 0})},
                 expect(true, 0, 3, {1, 0, 0}, 0.5));
  check::example(query::find_boxes, "B on the other side: the axis points from A to B",
                 BoxPair{a, cube({-2.5, 0.5, 0})}, expect(true, 0, 3, {-1, 0, 0}, 0.5));
  check::example(query::find_boxes, "separated along A_0: depth -1 (a gap of 1)", BoxPair{a, cube({4, 0, 0})},
                 expect(false, 0, 0, {1, 0, 0}, -1));
  // Least along A_0 x B_0 = (0, 2, 6) / 7: depth (16/7 - 1/2) / (sqrt(40) / 7) = 25 / (4 sqrt(10)).
  check::example(query::find_boxes, "least along an edge axis", BoxPair{cube({0, 0, 0}), turned({0, 0.25, 0.5})},
                 expect(true, 6, 6, Vec3(0, 1, 3) / std::sqrt(10.0), 25 / (4 * std::sqrt(10.0))));
  check::example(query::find_boxes, "apart along the edge axis only: the gap along the unit axis",
                 BoxPair{cube({0, 0, 0}), turned({0, 0.75, 2.5})},
                 expect(false, 6, 6, Vec3(0, 1, 3) / std::sqrt(10.0), -1 / (4 * std::sqrt(10.0))));
}

TEST_CASE(LABKIT_STEP(L03S3) ": random cases", "[lab03][step3][oracle]") {
  check::random_cases(query::find_boxes, gen::box_pair(),
                      [](const BoxPair& in) { return judge::find_boxes(in, answerer::find_boxes(in.a, in.b)); });
}

// ---- Step 4 ------------------------------------------------------------------------

// First the lecture's interval method, then the sign-based test that replaces it.
TEST_CASE(LABKIT_STEP(L03S4) ": the lecture's interval method, worked examples", "[lab03][step4]") {
  const auto expect = [](int axis, double low0, double high0, double low1, double high1, bool overlap) {
    return [=](const TrianglePair& in) {
      const LineIntervals got = answerer::triangles_by_intervals(in.t0, in.t1);
      Expect e(
          "both triangles cross the line where their planes meet; each covers an interval of it, compared on the "
          "line's largest axis");
      e.equal("crossing", got.crossing, true);
      e.equal("axis", got.axis, axis);
      e.near("low0", got.low0, low0, 1e-12);
      e.near("high0", got.high0, high0, 1e-12);
      e.near("low1", got.low1, low1, 1e-12);
      e.near("high1", got.high1, high1, 1e-12);
      e.equal("overlap", got.overlap, overlap);
      return with_reason(e.outcome(), [&] { return judge::triangles_by_intervals(in, got, Rules::exact); });
    };
  };
  // t1 in the plane x = 1; d = 16 z for t1 against the floor (-32, 32, 16), d = 16 (x - 1)
  // for t0 against x = 1 (-16, 48, -16). D = (0, 256, 0): read on y.
  check::example(query::triangles_by_intervals, "crossing: [0, 3] and [-5/3, 1] on y overlap",
                 TrianglePair{kFloor, {{1, 1, -2}, {1, 1, 2}, {1, -3, 1}}}, expect(1, 0, 3, -5.0 / 3, 1, true));
  check::example(query::triangles_by_intervals, "planes cross, intervals apart: [0, 3] and [-20/3, -4]",
                 TrianglePair{kFloor, {{1, -4, -2}, {1, -4, 2}, {1, -8, 1}}}, expect(1, 0, 3, -20.0 / 3, -4, false));
  check::example(query::triangles_by_intervals, "ends that touch: [0, 3] and [-8/3, 0] share y = 0",
                 TrianglePair{kFloor, {{1, 0, -2}, {1, 0, 2}, {1, -4, 1}}}, expect(1, 0, 3, -8.0 / 3, 0, true));
  // t1 in the plane 2x + y = 3: n1 = (14, 7, 0), D = (-112, 224, 0): read on y, not x.
  check::example(query::triangles_by_intervals, "a slanted plane: D = (-112, 224, 0), read on y: [0, 3] and [-1/3, 2]",
                 TrianglePair{kFloor, {{1, 1, -2}, {0, 3, 2}, {2, -1, 1}}}, expect(1, 0, 3, -1.0 / 3, 2, true));
}

TEST_CASE(LABKIT_STEP(L03S4) ": the lecture's interval method, random cases", "[lab03][step4][oracle]") {
  check::random_cases(query::triangles_by_intervals, gen::crossing_triangle_pair(), [](const TrianglePair& in) {
    return judge::triangles_by_intervals(in, answerer::triangles_by_intervals(in.t0, in.t1));
  });
}

TEST_CASE(LABKIT_STEP(L03S4) ": worked examples", "[lab03][step4]") {
  const auto expect = [](bool intersecting) {
    return [intersecting](const TrianglePair& in) {
      const bool got = answerer::test_triangles(in.t0, in.t1);
      return with_reason(expect_bool("test_triangles", got, intersecting),
                         [&] { return judge::test_triangles(in, got, Rules::exact); });
    };
  };
  // T1 in the plane x = 1: T0's segment on the common line is y in [0, 3], T1's [-3, 1].
  check::example(query::test_triangles, "crossing: [0, 3] and [-3, 1] overlap",
                 TrianglePair{kFloor, {{1, 1, -2}, {1, 1, 2}, {1, -3, 0}}}, expect(true));
  check::example(query::test_triangles, "planes cross, segments do not: [0, 3] and [-8, -4]",
                 TrianglePair{kFloor, {{1, -4, -2}, {1, -4, 2}, {1, -8, 0}}}, expect(false));
  check::example(query::test_triangles, "segments touch at one point: [0, 3] and [-4, 0]",
                 TrianglePair{kFloor, {{1, 0, -2}, {1, 0, 2}, {1, -4, 0}}}, expect(true));
  check::example(query::test_triangles, "all of T1 above T0's plane",
                 TrianglePair{kFloor, {{0, 0, 1}, {4, 0, 1}, {0, 4, 3}}}, expect(false));
  check::example(query::test_triangles, "coplanar, overlapping",
                 TrianglePair{kFloor, {{1, 1, 0}, {5, 1, 0}, {1, 5, 0}}}, expect(true));
  check::example(query::test_triangles, "coplanar, apart beyond the long edge",
                 TrianglePair{kFloor, {{3, 3, 0}, {6, 3, 0}, {3, 6, 0}}}, expect(false));
  check::example(query::test_triangles, "coplanar, touching at a vertex",
                 TrianglePair{kFloor, {{4, 0, 0}, {6, 0, 0}, {4, 2, 0}}}, expect(true));
  check::example(query::test_triangles, "coplanar, sharing the long edge",
                 TrianglePair{kFloor, {{4, 0, 0}, {4, 4, 0}, {0, 4, 0}}}, expect(true));
  check::example(query::test_triangles, "a zero-area triangle never intersects",
                 TrianglePair{kFloor, {{1, 1, -1}, {1, 1, 1}, {1, 1, 0}}}, expect(false));
  // The header's zero signs: a vertex in the other's plane.
  check::example(query::test_triangles, "an edge in the other's plane, across it (signs 0 0 +)",
                 TrianglePair{kFloor, {{1, -1, 0}, {1, 3, 0}, {1, 1, 4}}}, expect(true));
  check::example(query::test_triangles, "an edge in the other's plane, beyond its long edge (signs 0 0 +)",
                 TrianglePair{kFloor, {{3, 3, 0}, {5, 1, 0}, {4, 2, 4}}}, expect(false));
  check::example(query::test_triangles, "touching the plane at one vertex, inside (signs 0 - -)",
                 TrianglePair{kFloor, {{1, 1, 0}, {1, 2, -2}, {2, 1, -3}}}, expect(true));
  check::example(query::test_triangles, "touching the plane at one vertex, outside (signs 0 - -)",
                 TrianglePair{kFloor, {{5, 5, 0}, {5, 6, -2}, {6, 5, -3}}}, expect(false));
  // A needle 2^-24 wide (aspect 6.7e7) and a triangle in the plane z = e (x - 2), turned
  // by e = 2^-22 against it: each crosses the other's plane, but where T1 passes over the
  // needle (x from 7/3 to 3) it is at least e/3 (20 tol) above it. Apart. A coplanarity
  // bound relative to the needle's two long edges instead of its area calls them coplanar.
  const double e = std::ldexp(1.0, -22);
  check::example(query::test_triangles, "a needle and a triangle turned by 2^-22 against it",
                 TrianglePair{{{0, 0, 0}, {4, 0, 0}, {4, e / 4, 0}}, {{1, 2, -e}, {3, 2, e}, {3, -1, e}}},
                 expect(false));
}

TEST_CASE(LABKIT_STEP(L03S4) ": random cases", "[lab03][step4][oracle]") {
  check::random_cases(query::test_triangles, gen::triangle_pair(), [](const TrianglePair& in) {
    return judge::test_triangles(in, answerer::test_triangles(in.t0, in.t1));
  });
}

// ---- Step 5 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L03S5) ": worked examples", "[lab03][step5]") {
  const auto expect = [](bool contact, double first, double last) {
    return [=](const MovingBoxes& in) {
      const ContactInterval got = answerer::find_moving_boxes(in.a, in.velocity_a, in.b, in.velocity_b, in.duration);
      const bool tested = answerer::test_moving_boxes(in.a, in.velocity_a, in.b, in.velocity_b, in.duration);
      Expect e(
          "moving boxes touch over the time interval [first, last] where the relative motion keeps every axis's "
          "intervals overlapping");
      e.equal("test_moving_boxes", tested, contact);
      e.equal("contact", got.contact, contact);
      if (contact && got.contact) {
        e.near("first", got.first, first, 1e-12);
        e.near("last", got.last, last, 1e-12);
      }
      return with_reason(e.outcome(), [&] {
        const Outcome o = judge::test_moving_boxes(in, tested, Rules::exact);
        return o.verdict == Outcome::Verdict::fail ? o : judge::find_moving_boxes(in, got, Rules::exact);
      });
    };
  };
  const Box a = cube({0, 0, 0});
  check::example(query::find_moving_boxes, "head on: x from 5 at speed -2 touches at 1.5, still at 2",
                 MovingBoxes{a, {0, 0, 0}, cube({5, 0, 0}), {-2, 0, 0}, 2}, expect(true, 1.5, 2));
  check::example(query::find_moving_boxes, "both moving: only the relative velocity counts",
                 MovingBoxes{a, {1, 0, 0}, cube({5, 0, 0}), {-1, 0, 0}, 2}, expect(true, 1.5, 2));
  check::example(query::find_moving_boxes, "passing beside: apart on y at every time",
                 MovingBoxes{a, {0, 0, 0}, cube({5, 3, 0}), {-2, 0, 0}, 4}, expect(false, 0, 0));
  check::example(query::find_moving_boxes, "touching at t = 0 and moving apart",
                 MovingBoxes{a, {0, 0, 0}, cube({2, 0, 0}), {1, 0, 0}, 1}, expect(true, 0, 0));
  check::example(query::find_moving_boxes, "through a thin plate within one step",
                 MovingBoxes{box({0, 0, 0}, {0.0625, 1, 1}), {0, 0, 0}, cube({-3, 0, 0}, 0.125), {6, 0, 0}, 1},
                 expect(true, 0.46875, 0.53125));
  check::example(query::find_moving_boxes, "past a corner: only W x A_2 separates the swept boxes",
                 MovingBoxes{a, {0, 0, 0}, cube({5, 0.5, 0}), {-6, 6, 0}, 1}, expect(false, 0, 0));
}

TEST_CASE(LABKIT_STEP(L03S5) ": random cases", "[lab03][step5][oracle]") {
  check::random_cases(query::test_moving_boxes, gen::moving_boxes(),
                      [](const MovingBoxes& in) { return run_moving_test(in); });
  check::random_cases(query::find_moving_boxes, gen::moving_boxes(),
                      [](const MovingBoxes& in) { return run_moving_find(in); });
}

// ---- Step 6: robustness --------------------------------------------------------------
// Exact degenerate input on integer coordinates: the header's rules hold exactly.

namespace {

Outcome exact_boxes(const BoxPair& in) {
  const Outcome o = judge::test_boxes(in, answerer::test_boxes(in.a, in.b), Rules::exact);
  if (o.verdict == Outcome::Verdict::fail) return o;
  return judge::find_boxes(in, answerer::find_boxes(in.a, in.b), Rules::exact);
}

Outcome exact_triangles(const TrianglePair& in) {
  return judge::test_triangles(in, answerer::test_triangles(in.t0, in.t1), Rules::exact);
}

Outcome exact_moving(const MovingBoxes& in) {
  const Outcome o = run_moving_test(in, Rules::exact);
  if (o.verdict == Outcome::Verdict::fail) return o;
  return run_moving_find(in, Rules::exact);
}

// The example's own expectation, then the judge's rules; a failure of the first shows
// the judge's reason when the judge fails it too.
template <class Input, class Own, class Rules> auto both(Own own, Rules rules) {
  return [=](const Input& in) {
    const Outcome o = own(in);
    return o.verdict == Outcome::Verdict::fail ? with_reason(o, [&] { return rules(in); }) : rules(in);
  };
}

}  // namespace

TEST_CASE(LABKIT_STEP(L03S6) ": touching and parallel boxes", "[lab03][step6]") {
  constexpr auto q = query::robust_boxes;
  const Box a = cube({0, 0, 0}, 2);
  const auto touching = [](int index, Vec3 axis) {
    return [=](const BoxPair& in) {
      const BoxContact got = answerer::find_boxes(in.a, in.b);
      Expect e("touching boxes intersect with depth 0 (sets are closed): no axis separates them");
      e.equal("test_boxes", answerer::test_boxes(in.a, in.b), true);
      e.equal("intersecting", got.intersecting, true);
      e.near("depth", got.depth, 0.0, 0.0);
      if (index >= 0) e.near("axis", got.axis, axis, 0.0);
      const Outcome own = e.outcome();
      return own.verdict == Outcome::Verdict::fail ? with_reason(own, [&] { return exact_boxes(in); })
                                                   : exact_boxes(in);
    };
  };
  check::example(q, "face to face: depth exactly 0", BoxPair{a, cube({3, 0, 0})}, touching(0, {1, 0, 0}));
  check::example(q, "edge to edge", BoxPair{a, cube({3, 3, 0})}, touching(-1, Vec3::Zero()));
  check::example(q, "corner to corner", BoxPair{a, cube({-3, 3, -3})}, touching(-1, Vec3::Zero()));
  Mat3 quarter;
  quarter << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  check::example(q, "a quarter turn: every edge parallel to one of A's", BoxPair{a, box({0, 4, 1}, {2, 1, 1}, quarter)},
                 touching(1, {0, 1, 0}));
  check::example(q, "a segment along A's edge", BoxPair{a, box({2, 2, 0}, {0, 0, 5})}, touching(-1, Vec3::Zero()));
  check::example(q, "a point on A's face", BoxPair{a, box({2, 1, 1}, {0, 0, 0})}, touching(0, {1, 0, 0}));
  check::example(q, "a gap of 1", BoxPair{a, cube({4, 0, 0})}, [](const BoxPair& in) {
    const Outcome o = expect_bool("test_boxes", answerer::test_boxes(in.a, in.b), false);
    return o.verdict == Outcome::Verdict::fail ? with_reason(o, [&] { return exact_boxes(in); }) : exact_boxes(in);
  });
}

TEST_CASE(LABKIT_STEP(L03S6) ": random exact degenerate cases", "[lab03][step6][oracle]") {
  check::random_cases(query::robust_boxes, gen::exact_box_pair(), exact_boxes);
}

// ---- Step 7: robustness of steps 4 and 5 (extensions, as they are) --------------------

TEST_CASE(LABKIT_STEP(L03S7) ": touching and coplanar triangles", "[lab03][step7]") {
  constexpr auto q = query::robust_triangles;
  const auto expect = [](bool intersecting) {
    return both<TrianglePair>(
        [intersecting](const TrianglePair& in) {
      return expect_bool("test_triangles", answerer::test_triangles(in.t0, in.t1), intersecting);
        },
        exact_triangles);
  };
  check::example(q, "a vertex on the other's face", TrianglePair{kFloor, {{1, 1, 0}, {1, 1, 3}, {2, 3, 4}}},
                 expect(true));
  check::example(q, "an edge through the other's edge", TrianglePair{kFloor, {{2, 2, -1}, {2, 2, 1}, {5, 5, 0}}},
                 expect(true));
  check::example(q, "a slanted edge through the other's edge",
                 TrianglePair{kFloor, {{3, 3, 1}, {1, 1, -1}, {4, 4, -2}}}, expect(true));
  check::example(q, "a vertex on the other's edge", TrianglePair{kFloor, {{2, 2, 0}, {4, 4, 3}, {4, 4, -3}}},
                 expect(true));
  check::example(q, "coplanar, one vertex on the other's edge", TrianglePair{kFloor, {{2, 2, 0}, {5, 2, 0}, {2, 5, 0}}},
                 expect(true));
  check::example(q, "coplanar, a unit apart", TrianglePair{kFloor, {{3, 2, 0}, {6, 2, 0}, {3, 5, 0}}}, expect(false));
  check::example(q, "zero area, through the middle", TrianglePair{kFloor, {{1, 1, -1}, {1, 1, 1}, {1, 1, 2}}},
                 expect(false));
}

TEST_CASE(LABKIT_STEP(L03S7) ": moving boxes that touch at an instant, slide, or start together", "[lab03][step7]") {
  constexpr auto q = query::robust_moving_boxes;
  const auto expect = [](bool contact, double first, double last) {
    return both<MovingBoxes>(
        [=](const MovingBoxes& in) {
      const ContactInterval got = answerer::find_moving_boxes(in.a, in.velocity_a, in.b, in.velocity_b, in.duration);
      Expect e(
          "moving boxes touch over the time interval [first, last] where the relative motion keeps every axis's "
          "intervals overlapping");
      e.equal("contact", got.contact, contact);
      if (contact && got.contact) {
        e.near("first", got.first, first, 0.0);
        e.near("last", got.last, last, 0.0);
      }
      return e.outcome();
        },
        exact_moving);
  };
  const Box a = cube({0, 0, 0});
  check::example(q, "corner past corner: one instant, t = 5",
                 MovingBoxes{a, {0, 0, 0}, cube({3, -7, 0}), {-1, 1, 0}, 8}, expect(true, 5, 5));
  check::example(q, "sliding along a face, touching all the way",
                 MovingBoxes{a, {0, 0, 0}, cube({2, 4, 0}), {0, -2, 0}, 4}, expect(true, 1, 3));
  check::example(q, "sliding a unit away", MovingBoxes{a, {0, 0, 0}, cube({3, 4, 0}), {0, -2, 0}, 4},
                 expect(false, 0, 0));
  check::example(q, "moving together, touching", MovingBoxes{a, {1, 2, 3}, cube({2, 2, 0}), {1, 2, 3}, 1},
                 expect(true, 0, 1));
  check::example(q, "no time at all: a test at t = 0", MovingBoxes{a, {5, 0, 0}, cube({2, 0, 0}), {0, 0, 0}, 0},
                 expect(true, 0, 0));
}

TEST_CASE(LABKIT_STEP(L03S7) ": random exact degenerate cases", "[lab03][step7][oracle]") {
  check::random_cases(query::robust_triangles, gen::exact_triangle_pair(), exact_triangles);
  check::random_cases(query::robust_moving_boxes, gen::exact_moving_boxes(), exact_moving);
}

// Step 5's single instant, from a fast axis and a slow one (CI's sweep, seed 803): a
// point passes a flat rectangle that lies almost along its path. The point crosses the
// rectangle's plane (B moves along B_1 by only 2e-12) just as it reaches the edge on
// A_1 (moving at 8), and rounding puts the two times 1e-3 apart in the wrong order. The
// slow axis's time is known to 3e-2, the fast one's to 1e-14: the reference reports the
// fast one. Halfway between them, the point is 6e-3 outside the edge, far beyond tol.
TEST_CASE("L03 step 5: one instant is timed by the faster axis", "[lab03][contract]") {
  Box point, flat;
  point.axes << -0.3333333333333337, -0.6666666666666669, -0.6666666666666669, -0.6666666666666669, -0.3333333333333337,
      0.6666666666666669, -0.6666666666666669, 0.6666666666666669, -0.3333333333333337;
  flat.center = {-1.5265246814716102, 3.59848510293977, 10.250019568824271};
  flat.axes << -0.666666666666633, -0.666666666666599, -0.33333333333353704, -0.3333333333332659, 0.6666666666668024,
      -0.6666666666665652, 0.6666666666667347, -0.33333333333319815, -0.6666666666666669;
  flat.half_extents = {1.6515369415283203, 0, 3.2979931831359863};
  const MovingBoxes in{point, {0, 0, 0}, flat, {2, -4, -12}, 1};
  const ContactInterval got = answerer::find_moving_boxes(in.a, in.velocity_a, in.b, in.velocity_b, in.duration);
  CHECK(got.contact);
  CHECK(got.first == got.last);
  CHECK(judge::find_moving_boxes(in, got, Rules::random).verdict != Outcome::Verdict::fail);  // touching: in doubt
  const ContactInterval halfway{true, 0.6242193444060393, 0.6242193444060393};  // the old reference's answer
  CHECK(judge::find_moving_boxes(in, halfway, Rules::random).verdict == Outcome::Verdict::fail);
}

// ---- The header's preconditions (not graded: tagged [contract], in no step) ----------
// The reference rejects every kind of invalid input with std::invalid_argument naming
// the argument; a NaN must never pass for "no axis separates them".

TEST_CASE("L03 preconditions: invalid input is rejected, naming the argument", "[lab03][contract]") {
  const double nan = std::nan(""), inf = HUGE_VAL;
  const Box good = cube({0, 0, 0});
  std::vector<std::pair<std::string, Box>> bad_boxes;
  for (const double x : {nan, inf, -inf}) {
    Box b = good;
    b.center.y() = x;
    bad_boxes.push_back({"center", b});
    b = good;
    b.half_extents.z() = x;
    bad_boxes.push_back({"half_extents", b});
    b = good;
    b.axes(1, 2) = x;
    bad_boxes.push_back({"axes", b});
  }
  Box negative = good;
  negative.half_extents.x() = -1;
  bad_boxes.push_back({"half_extents", negative});
  Box sheared = good;
  sheared.axes(0, 1) = 0.5;
  bad_boxes.push_back({"axes", sheared});
  Box zero_axes = good;
  zero_axes.axes = Mat3::Zero();
  bad_boxes.push_back({"axes", zero_axes});

  for (const auto& [field, bad] : bad_boxes) {
    rejects("box." + field, [&] { answerer::project_box(bad, {1, 0, 0}); });
    rejects("a." + field, [&] { answerer::separated_on_axis(bad, good, {1, 0, 0}); });
    rejects("b." + field, [&] { answerer::separated_on_axis(good, bad, {1, 0, 0}); });
    rejects("b." + field, [&] { answerer::box_axis(good, bad, 0); });
    rejects("a." + field, [&] { answerer::test_boxes(bad, good); });
    rejects("b." + field, [&] { answerer::find_boxes(good, bad); });
    rejects("a." + field, [&] { answerer::test_moving_boxes(bad, {0, 0, 0}, good, {0, 0, 0}, 1); });
    rejects("b." + field, [&] { answerer::find_moving_boxes(good, {0, 0, 0}, bad, {0, 0, 0}, 1); });
  }
  for (const double x : {nan, inf}) {
    rejects("axis", [&] { answerer::project_box(good, {x, 0, 0}); });
    rejects("axis", [&] { answerer::separated_on_axis(good, good, {0, x, 0}); });
    Triangle t = kFloor;
    t.v1.z() = x;
    rejects("t0.v1", [&] { answerer::test_triangles(t, kFloor); });
    rejects("t1.v1", [&] { answerer::test_triangles(kFloor, t); });
    rejects("t0.v1", [&] { answerer::triangles_by_intervals(t, kFloor); });
    rejects("t1.v1", [&] { answerer::triangles_by_intervals(kFloor, t); });
    rejects("velocity_a", [&] { answerer::test_moving_boxes(good, {x, 0, 0}, good, {0, 0, 0}, 1); });
    rejects("velocity_b", [&] { answerer::find_moving_boxes(good, {0, 0, 0}, good, {0, 0, x}, 1); });
    rejects("duration", [&] { answerer::test_moving_boxes(good, {0, 0, 0}, good, {0, 0, 0}, x); });
    rejects("duration", [&] { answerer::find_moving_boxes(good, {0, 0, 0}, good, {0, 0, 0}, x); });
  }
  rejects("duration", [&] { answerer::find_moving_boxes(good, {0, 0, 0}, good, {0, 0, 0}, -1); });
  rejects("duration", [&] { answerer::test_moving_boxes(good, {0, 0, 0}, good, {0, 0, 0}, -1); });
  rejects("index", [&] { answerer::box_axis(good, good, 15); });
  rejects("index", [&] { answerer::box_axis(good, good, -1); });
  // The documented results that are not rejections: zero half extents, a zero axis, a
  // zero-area triangle, a zero duration.
  CHECK_FALSE(answerer::separated_on_axis(good, cube({9, 0, 0}), {0, 0, 0}));
  CHECK(answerer::test_boxes(good, box({1, 1, 1}, {0, 0, 0})));
  CHECK_FALSE(answerer::test_triangles(kFloor, {{1, 1, -1}, {1, 1, 1}, {1, 1, 0}}));
  CHECK(answerer::find_moving_boxes(good, {5, 0, 0}, cube({2, 0, 0}), {0, 0, 0}, 0).contact);
}
