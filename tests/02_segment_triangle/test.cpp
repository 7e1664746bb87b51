// Lab 02 tests. Each step: the hand-worked examples of handouts/02_segment_triangle.md,
// then random cases against the exact oracle (tests/02_segment_triangle/judge.cpp).
#include "02_segment_triangle/queries.h"
#include "common/generators/needles.h"
#include "common/harness/check.h"
#include "segment_triangle.h"

#include "common/generators/meshes.h"
#include "common/oracle/segment_triangle.h"

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace labkit;
using namespace labkit::lab02;
using check::Expect;
using check::Outcome;
using check::rejects;
using judge::Rules;

// The header's input domain (S, the largest absolute coordinate, from 1e-50 to 1e50): each
// case is drawn in it (scaled by a power of two, which keeps it the same case) and
// shrinking a failing case stays in it.
const bool kDomain = [] {
  check::domain({check::Domain::Of::scale, 1e-50, 1e50, true});
  return true;
}();

// What keeps each query's calls well defined, in the header's words: a crash in that
// query says it first (check::rule).
const bool kRules = [] {
  check::rule(query::barycentric,
              "a zero-area triangle has no weights: its 2D denominator is 0, so answer "
              "dropped_axis = -1 before dividing");
  check::rule(query::point_in_triangle_barycentric,
              "a zero-area triangle contains no point: answer false before "
              "dividing by its zero denominator");
  return true;
}();

namespace {

// The handout's triangle: the right triangle with legs 4 on the x and y axes, z = 0.
const Triangle kFloor{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
const Triangle kFlat{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};  // zero area

SegmentTrianglePair pair(Vec3 a, Vec3 b, const Triangle& t = kFloor) { return {{a, b}, t}; }

Mesh floor_and_shelf() {
  Mesh m;
  gen::add_square(m, 4, 0);  // triangles 0 and 1
  gen::add_square(m, 4, 2);  // triangles 2 and 3
  return m;
}

// Judges that run the code under test, by query name.
Outcome run_segment_plane(const SegmentTrianglePair& in) {
  return judge::segment_plane(in, answerer::segment_plane(in.segment, in.triangle));
}
Outcome run_find(const SegmentTrianglePair& in) {
  return judge::find_segment_triangle(in, answerer::find_segment_triangle(in.segment, in.triangle));
}
Outcome run_test(const SegmentTrianglePair& in) {
  return judge::test_segment_triangle(in, answerer::test_segment_triangle(in.segment, in.triangle));
}

// The examples' checks, each naming the rule of the header it checks.
void expect_distance(Expect& e, const std::string& name, double got, double expected, double n_length) {
  std::string why = name + " must be the signed distance of " + name.substr(2) +
                    " to the plane, along the unit normal: " + fmt(expected);
  if (expected != 0 && std::abs(got - n_length * expected) <= 1e-9 * std::abs(got))
    why += "; " + fmt(got) + " is |n| = " + fmt(n_length) + " times it: is n unit?";
  e.that(name, std::abs(got - expected) <= 1e-12, fmt(got), fmt(expected), why);
}
void expect_t(Expect& e, double got, double expected) {
  std::string why =
      "the crossing is at t = d_a / (d_a - d_b) = " + fmt(expected) + ", the fraction of the way from a to b";
  if (std::abs(got + expected) <= 1e-12) why += "; yours has the opposite sign: is the denominator d_b - d_a?";
  e.that("t", std::abs(got - expected) <= 1e-12, fmt(got), fmt(expected), why);
}
void expect_normal(Expect& e, const Vec3& got, const Vec3& expected) {
  e.that(
      "normal", (got - expected).norm() <= 1e-12, fmt(got), fmt(expected),
      "the normal is the triangle's unit normal as wound, (v1 - v0) x (v2 - v0) / |...|, whichever side a comes from");
}

}  // namespace

// ---- Step 1 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L02S1) ": worked examples", "[lab02][step1]") {
  check::example(query::segment_plane, "a above, b below: crosses at t = 3/4", pair({1, 1, 3}, {1, 1, -1}),
                 [](const SegmentTrianglePair& in) {
    const PlaneCrossing got = answerer::segment_plane(in.segment, in.triangle);
    Expect e(
        "segment_plane: d_a and d_b are the ends' signed distances along the unit normal, and the crossing is at t = "
        "d_a / (d_a - d_b), point a + t (b - a)");
    expect_distance(e, "d_a", got.d_a, 3, 16);
    expect_distance(e, "d_b", got.d_b, -1, 16);
    e.equal("crosses", got.crosses, true);
    expect_t(e, got.t, 0.75);
    e.near("point", got.point, Vec3(1, 1, 0), 1e-12);
    return e.outcome();
  });
  check::example(query::segment_plane, "both ends above: no crossing", pair({1, 1, 2}, {3, 3, 5}),
                 [](const SegmentTrianglePair& in) {
    const PlaneCrossing got = answerer::segment_plane(in.segment, in.triangle);
    Expect e(
        "segment_plane: d_a and d_b are the ends' signed distances along the unit normal; both on one side, no "
        "crossing");
    expect_distance(e, "d_a", got.d_a, 2, 16);
    expect_distance(e, "d_b", got.d_b, 5, 16);
    e.equal("crosses", got.crosses, false);
    return e.outcome();
  });
  check::example(query::segment_plane, "a on the plane: crosses at t = 0", pair({1, 1, 0}, {2, 2, 2}),
                 [](const SegmentTrianglePair& in) {
    const PlaneCrossing got = answerer::segment_plane(in.segment, in.triangle);
    Expect e("segment_plane: an end on the plane (d = 0) is a crossing at that end");
    e.equal("crosses", got.crosses, true);
    expect_t(e, got.t, 0);
    e.near("point", got.point, Vec3(1, 1, 0), 1e-12);
    return e.outcome();
  });
  check::example(query::segment_plane, "the normal follows the winding",
                 pair({1, 1, 3}, {1, 1, -1}, {{0, 0, 0}, {0, 4, 0}, {4, 0, 0}}), [](const SegmentTrianglePair& in) {
                   const PlaneCrossing got = answerer::segment_plane(in.segment, in.triangle);
                   Expect e(
                       "segment_plane: the distances are measured along the triangle's own normal (v1 - v0) x (v2 - "
                       "v0), so they follow its winding");
                   expect_distance(e, "d_a", got.d_a, -3, 16);
                   expect_distance(e, "d_b", got.d_b, 1, 16);
                   expect_t(e, got.t, 0.75);
                   return e.outcome();
                 });
}

TEST_CASE(LABKIT_STEP(L02S1) ": random cases", "[lab02][step1][oracle]") {
  check::random_cases(query::segment_plane, gen::decisive_segment_triangle(), run_segment_plane);
}

// ---- Step 2 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L02S2) ": worked examples", "[lab02][step2]") {
  // Each expected answer is the exact one; the judge says which rule a wrong one breaks.
  const auto expect = [](bool inside) {
    return [inside](const PointTriangle& in) {
      const bool got = answerer::point_in_triangle_edges(in.x, in.triangle);
      return got == inside ? Outcome{} : judge::point_in_triangle(in, got, Rules::exact);
    };
  };
  check::example(query::point_in_triangle_edges, "inside", PointTriangle{{1, 1, 0}, kFloor}, expect(true));
  check::example(query::point_in_triangle_edges, "beyond the long edge", PointTriangle{{3, 3, 0}, kFloor},
                 expect(false));
  check::example(query::point_in_triangle_edges, "left of v0", PointTriangle{{-1, 1, 0}, kFloor}, expect(false));
  check::example(query::point_in_triangle_edges, "on the long edge counts", PointTriangle{{2, 2, 0}, kFloor},
                 expect(true));
  check::example(query::point_in_triangle_edges, "a vertex counts", PointTriangle{{0, 0, 0}, kFloor}, expect(true));
  check::example(query::point_in_triangle_edges, "clockwise triangle",
                 PointTriangle{{1, 1, 0}, {{0, 0, 0}, {0, 4, 0}, {4, 0, 0}}}, expect(true));
  check::example(query::point_in_triangle_edges, "zero-area triangle", PointTriangle{{1, 1, 1}, kFlat}, expect(false));
}

TEST_CASE(LABKIT_STEP(L02S2) ": random cases", "[lab02][step2][oracle]") {
  check::random_cases(query::point_in_triangle_edges, gen::point_triangle(), [](const PointTriangle& in) {
    return judge::point_in_triangle(in, answerer::point_in_triangle_edges(in.x, in.triangle));
  });
}

// ---- Step 3 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L02S3) ": worked examples in the dropped-axis plane", "[lab02][step3]") {
  const auto expect = [](int axis, double alpha, double beta) {
    return [=](const PointTriangle& in) {
      const Barycentric got = answerer::barycentric(in.x, in.triangle);
      Expect e(
          "barycentric drops the axis of the normal's largest component and solves x = v0 + alpha e1 + beta e2 in the "
          "two axes left");
      e.equal("dropped_axis", got.dropped_axis, axis);
      const auto weight = [&e](const std::string& name, double mine, double exact) {
        std::string why = "x = v0 + alpha e1 + beta e2 needs " + name + " = " + fmt(exact);
        if (exact != 0 && std::abs(mine + exact) <= 1e-12)
          why += "; yours has the wrong sign: " + name + " = " + (name == "beta" ? "(e1 x p)" : "(p x e2)") +
                 " / (e1 x e2)";
        e.that(name, std::abs(mine - exact) <= 1e-12, fmt(mine), fmt(exact), why);
      };
      weight("alpha", got.alpha, alpha);
      weight("beta", got.beta, beta);
      return e.outcome();
    };
  };
  check::example(query::barycentric, "the floor triangle: drop z", PointTriangle{{1, 2, 0}, kFloor},
                 expect(2, 0.25, 0.5));
  check::example(query::barycentric, "a tilted triangle: drop x",
                 PointTriangle{{0.25, 0.5, 1.5}, {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}}, expect(0, 0.25, 0.5));
  check::example(query::barycentric, "x = v2 gives beta = 1", PointTriangle{{0, 4, 0}, kFloor}, expect(2, 0, 1));
  check::example(query::barycentric, "zero area: no axis", PointTriangle{{1, 1, 1}, kFlat},
                 [](const PointTriangle& in) {
    Expect e("a triangle of zero area has no plane to drop an axis from: dropped_axis = -1");
    e.equal("dropped_axis", answerer::barycentric(in.x, in.triangle).dropped_axis, -1);
    return e.outcome();
  });
  const auto inside = [](bool expected) {
    return [expected](const PointTriangle& in) {
      const bool got = answerer::point_in_triangle_barycentric(in.x, in.triangle);
      return got == expected ? Outcome{} : judge::point_in_triangle(in, got, Rules::exact);
    };
  };
  check::example(query::point_in_triangle_barycentric, "inside", PointTriangle{{1, 1, 0}, kFloor}, inside(true));
  check::example(query::point_in_triangle_barycentric, "alpha + beta > 1", PointTriangle{{3, 3, 0}, kFloor},
                 inside(false));
  check::example(query::point_in_triangle_barycentric, "on the long edge: alpha + beta = 1",
                 PointTriangle{{1, 3, 0}, kFloor}, inside(true));
  check::example(query::point_in_triangle_barycentric, "beta < 0", PointTriangle{{1, -1, 0}, kFloor}, inside(false));
}

TEST_CASE(LABKIT_STEP(L02S3) ": random cases", "[lab02][step3][oracle]") {
  check::random_cases(query::barycentric, gen::point_triangle(), [](const PointTriangle& in) {
    return judge::barycentric(in, answerer::barycentric(in.x, in.triangle));
  });
  check::random_cases(query::point_in_triangle_barycentric, gen::point_triangle(), [](const PointTriangle& in) {
    return judge::point_in_triangle(in, answerer::point_in_triangle_barycentric(in.x, in.triangle));
  });
}

// ---- Step 4 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L02S4) ": worked examples", "[lab02][step4]") {
  check::example(query::find_segment_triangle, "through the inside at t = 3/4", pair({1, 1, 3}, {1, 1, -1}),
                 [](const SegmentTrianglePair& in) {
    const SegmentTriangleHit got = answerer::find_segment_triangle(in.segment, in.triangle);
    Expect e(
        "find_segment_triangle reports the crossing with the triangle: t along a to b, point a + t (b - a), "
        "barycentric the weights of v0, v1, v2 there, normal the unit normal as wound");
    e.equal("hit", got.hit, true);
    e.near("t", got.t, 0.75, 1e-12);
    e.near("point", got.point, Vec3(1, 1, 0), 1e-12);
    e.near("barycentric", got.barycentric, Vec3(0.5, 0.25, 0.25), 1e-12);
    expect_normal(e, got.normal, Vec3(0, 0, 1));
    return e.outcome();
  });
  check::example(query::find_segment_triangle, "from below: same normal, t = 1/4", pair({1, 1, -1}, {1, 1, 3}),
                 [](const SegmentTrianglePair& in) {
    const SegmentTriangleHit got = answerer::find_segment_triangle(in.segment, in.triangle);
    Expect e(
        "find_segment_triangle reports the crossing with the triangle: t along a to b, and the normal as wound, "
        "whichever side a comes from");
    e.equal("hit", got.hit, true);
    expect_t(e, got.t, 0.25);
    expect_normal(e, got.normal, Vec3(0, 0, 1));
    return e.outcome();
  });
  const auto miss = [](const SegmentTrianglePair& in) {
    Expect e("a segment that misses the closed triangle is a miss for find and test alike");
    e.equal("hit", answerer::find_segment_triangle(in.segment, in.triangle).hit, false);
    e.equal("test", answerer::test_segment_triangle(in.segment, in.triangle), false);
    return e.outcome();
  };
  check::example(query::find_segment_triangle, "crosses the plane beside the triangle", pair({3, 3, 1}, {3, 3, -1}),
                 miss);
  check::example(query::find_segment_triangle, "parallel, above", pair({1, 1, 1}, {2, 1, 1}), miss);
  check::example(query::find_segment_triangle, "stops short of the plane", pair({1, 1, 3}, {1, 1, 1}), miss);
  // In the plane and beside the triangle: a miss, graded (no lift makes it a hit). Only
  // a coplanar hit is ambiguous in this step's random cases.
  check::example(query::find_segment_triangle, "in the plane, beside the triangle: a miss", pair({5, 1, 0}, {5, 3, 0}),
                 [](const SegmentTrianglePair& in) {
    const Outcome o =
        judge::find_segment_triangle(in, answerer::find_segment_triangle(in.segment, in.triangle), Rules::exact);
    if (o.verdict == Outcome::Verdict::fail) return o;
    return judge::test_segment_triangle(in, answerer::test_segment_triangle(in.segment, in.triangle), Rules::exact);
  });
  // The floor triangle shrunk by 2^-22 (legs of 9.5e-7): its normal is 9.1e-13 long, below
  // the 1e-12 of Eigen's fuzzy isZero(), and still not zero.
  const double tiny = std::ldexp(1.0, -22);
  check::example(
      query::find_segment_triangle, "a triangle a millionth the size",
      pair(Vec3(1, 1, 3) * tiny, Vec3(1, 1, -1) * tiny, {{0, 0, 0}, Vec3(4 * tiny, 0, 0), Vec3(0, 4 * tiny, 0)}),
      [tiny](const SegmentTrianglePair& in) {
    const SegmentTriangleHit got = answerer::find_segment_triangle(in.segment, in.triangle);
    Expect e(
        "find_segment_triangle reports the crossing with the triangle at any scale: t along a to b, point a + t (b - "
        "a)");
    e.that("hit", got.hit, describe(got.hit), "true",
           "the triangle's area |n| / 2 = " + fmt(in.triangle.area()) +
               " is not zero: only an exactly zero normal means zero area (a fuzzy test such as "
               "isZero() drops small triangles)");
    e.near("t", got.t, 0.75, 1e-12);
    e.near("point", got.point, Vec3(tiny, tiny, 0), 1e-18);
    return e.outcome();
      });
  check::example(query::test_segment_triangle, "through the inside", pair({1, 1, 3}, {1, 1, -1}),
                 [](const SegmentTrianglePair& in) {
    Expect e("test_segment_triangle says yes exactly when the segment meets the closed triangle");
    e.equal("test", answerer::test_segment_triangle(in.segment, in.triangle), true);
    return e.outcome();
  });
}

TEST_CASE(LABKIT_STEP(L02S4) ": random cases", "[lab02][step4][oracle]") {
  // Found by a class run: a starts exactly on the plane, near an edge, and b is 5e-8
  // off it, so the rounding of d_a alone moves the crossing 2.5e-7 along the plane and
  // off the triangle. The judge allows what the tolerance of t allows.
  check::example(query::find_segment_triangle, "almost in the plane, from a point on it",
                 pair({-1.383425235748291, 4.109798431396484, 6.50537109375},
                      {-6.671734802378595, -8.144360497256555, -16.96777346270255},
                      {{-2, 0.01881122589111328, -0.9892578125},
                       {-0.766850471496582, 8.200785636901855, 14},
                       {1.4385852813720703, 8.58306884765625e-06, 0}}),
                 run_find);
  check::random_cases(query::test_segment_triangle, gen::decisive_segment_triangle(), run_test);
  check::random_cases(query::find_segment_triangle, gen::decisive_segment_triangle(), run_find);
}

// ---- Step 5 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L02S5) ": worked examples", "[lab02][step5]") {
  const Mesh mesh = floor_and_shelf();
  check::example(query::first_hit, "the shelf before the floor", SegmentMeshPair{{{1, 3, 5}, {1, 3, -1}}, mesh},
                 [](const SegmentMeshPair& in) {
    const MeshHit got = answerer::first_hit(in.segment, in.mesh);
    Expect e("first_hit is the hit with the smallest t, with that hit's triangle, t, point and normal");
    e.equal("hit", got.hit, true);
    e.that("triangle", got.triangle == 3, std::to_string(got.triangle), "3",
           "first_hit is the hit with the smallest t: the shelf (triangle 3, t = 0.5) before the floor "
           "(triangle 1, t = 5/6)");
    e.near("t", got.t, 0.5, 1e-12);
    e.near("point", got.point, Vec3(1, 3, 2), 1e-12);
    return e.outcome();
  });
  // So nearly along the floor (a slope of 2^-20) that the volumes cannot give the
  // weights: they must be measured on the point (handout, step 3's barycentric).
  check::example(
      query::first_hit, "nearly along the floor", SegmentMeshPair{{{0.5, 1, 0x1p-20}, {2.5, 1.5, -0x1p-20}}, mesh},
      [](const SegmentMeshPair& in) { return judge::first_hit(in, answerer::first_hit(in.segment, in.mesh)); });
  check::example(query::all_hits, "shelf, then floor", SegmentMeshPair{{{1, 3, 5}, {1, 3, -1}}, mesh},
                 [](const SegmentMeshPair& in) {
    const std::vector<MeshHit> got = answerer::all_hits(in.segment, in.mesh);
    Expect e("all_hits lists every triangle the segment meets, once each, sorted by t");
    e.equal("count", int(got.size()), 2);
    if (got.size() == 2) {
      e.that("first triangle", got[0].triangle == 3, std::to_string(got[0].triangle), "3",
             "all_hits must be sorted by t: the shelf (triangle 3, t = 0.5) before the floor (triangle 1, t = 5/6)");
      e.near("first t", got[0].t, 0.5, 1e-12);
      e.equal("second triangle", got[1].triangle, 1);
      e.near("second t", got[1].t, 5.0 / 6.0, 1e-12);
    }
    return e.outcome();
  });
  // The floor's two triangles share the diagonal (0,0)-(4,4): both are met, at one t.
  check::example(query::all_hits, "through the shared diagonal: both triangles, at the same t",
                 SegmentMeshPair{{{1, 1, 1}, {3, 3, -1}}, mesh}, [](const SegmentMeshPair& in) {
                   return judge::all_hits(in, answerer::all_hits(in.segment, in.mesh), Rules::exact);
                 });
  check::example(query::any_hit, "beside the squares", SegmentMeshPair{{{5, 5, 5}, {5, 5, -1}}, mesh},
                 [](const SegmentMeshPair& in) {
    Expect e("a segment that meets no triangle: any_hit is false, first_hit has no hit, all_hits is empty");
    e.equal("any_hit", answerer::any_hit(in.segment, in.mesh), false);
    e.equal("first_hit.hit", answerer::first_hit(in.segment, in.mesh).hit, false);
    e.equal("all_hits.size()", int(answerer::all_hits(in.segment, in.mesh).size()), 0);
    return e.outcome();
  });
}

TEST_CASE(LABKIT_STEP(L02S5) ": random cases", "[lab02][step5][oracle]") {
  check::random_cases(query::any_hit, gen::decisive_segment_mesh(), [](const SegmentMeshPair& in) {
    return judge::any_hit(in, answerer::any_hit(in.segment, in.mesh));
  });
  check::random_cases(query::first_hit, gen::decisive_segment_mesh(), [](const SegmentMeshPair& in) {
    return judge::first_hit(in, answerer::first_hit(in.segment, in.mesh));
  });
  check::random_cases(query::all_hits, gen::decisive_segment_mesh(), [](const SegmentMeshPair& in) {
    return judge::all_hits(in, answerer::all_hits(in.segment, in.mesh));
  });
}

// ---- Step 6 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L02S6) ": worked examples", "[lab02][step6]") {
  Mesh floor;
  gen::add_square(floor, 4, 0);
  RigidTransform up = RigidTransform::Identity();
  up.translation() = Vec3(0, 0, 2);
  check::example(query::first_hit_moving, "a resting particle, a rising floor",
                 MovingMesh{{{1, 1, 1}, {1, 1, 1}}, floor, RigidTransform::Identity(), up},
                 [](const MovingMesh& in) {
    const MeshHit got = answerer::first_hit_moving(in.segment, in.mesh, in.m0, in.m1);
    Expect e(
        "first_hit_moving reports the hit in the world at time t: the point on the mesh at its pose then, the normal "
        "turned by that pose's rotation only (a normal is a direction: no translation)");
    e.that("hit", got.hit, describe(got.hit), "true",
           "in the floor's own frame the particle goes from m0^-1 a = (1, 1, 1) to m1^-1 b = (1, 1, -1), "
           "through the floor: each end goes through its own pose");
    e.near("t", got.t, 0.5, 1e-12);
    e.near("point", got.point, Vec3(1, 1, 2), 1e-12);
    e.near("normal", got.normal, Vec3(0, 0, 1), 1e-12);
    return e.outcome();
  });
  // The point is the contact on the mesh at its end pose m1: in the floor's frame the
  // path (2,2,1) -> (2,2,-1) meets it at (2,2,0), which m1 (a shift by 1 in x) puts at
  // (3,2,0); not (2,2,0) (the mesh at m0) and not a + t (b - a) = (2.5,2,0).
  RigidTransform aside = RigidTransform::Identity();
  aside.translation() = Vec3(1, 0, 0);
  check::example(query::first_hit_moving, "a sliding floor: the point is on the mesh at its end pose",
                 MovingMesh{{{2, 2, 1}, {3, 2, -1}}, floor, RigidTransform::Identity(), aside},
                 [](const MovingMesh& in) {
    const MeshHit got = answerer::first_hit_moving(in.segment, in.mesh, in.m0, in.m1);
    Expect e("first_hit_moving reports the hit in the world at time t: the point on the mesh at its pose then");
    e.equal("hit", got.hit, true);
    e.near("t", got.t, 0.5, 1e-12);
    e.that("point", (got.point - Vec3(3, 2, 0)).norm() <= 1e-12, fmt(got.point), fmt(Vec3(3, 2, 0)),
           "the point is the contact on the mesh at its end pose: m1 times the point found in its frame");
    return e.outcome();
  });
  check::example(query::first_hit_moving, "the rising floor stops short of a falling particle",
                 MovingMesh{{{1, 1, 3}, {1, 1, 2.5}}, floor, RigidTransform::Identity(), up},
                 [](const MovingMesh& in) {
    // In the floor's frame the particle goes from z = 3 to z = 0.5: no hit.
    Expect e("first_hit_moving follows the particle in the mesh's own frame, each end through its own pose");
    e.equal("hit", answerer::first_hit_moving(in.segment, in.mesh, in.m0, in.m1).hit, false);
    return e.outcome();
  });
}

TEST_CASE(LABKIT_STEP(L02S6) ": random cases", "[lab02][step6][oracle]") {
  check::random_cases(query::first_hit_moving, gen::moving_mesh(), [](const MovingMesh& in) {
    return judge::first_hit_moving(in, answerer::first_hit_moving(in.segment, in.mesh, in.m0, in.m1));
  });
}

// ---- Step 7 ------------------------------------------------------------------------

namespace {

// The handout's meshes for step 7 (all apart at t = 0).
// A small tetrahedron whose lowest vertex, the tip (1, 2, 2), points down at the floor.
Mesh spike(const Vec3& tip = {1, 2, 2}) {
  Mesh m;
  m.vertices = {tip, tip + Vec3(1, 0, 1), tip + Vec3(0, 1, 1), tip + Vec3(0, 0, 2)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return m;
}
Mesh floor_square() {
  Mesh m;
  gen::add_square(m, 4, 0);
  return m;
}
// Two upright triangles, crossed: A in the plane y = 0 with its lowest edge at z = 1
// from x = -2 to 2; B in the plane x = 1 with its top edge at z = 0 from y = -2 to 2.
Mesh upright_a() {
  Mesh m;
  m.vertices = {{-2, 0, 1}, {2, 0, 1}, {0, 0, 3}};
  m.triangles = {{0, 1, 2}};
  return m;
}
Mesh upright_b() {
  Mesh m;
  m.vertices = {{1, -2, 0}, {1, 2, 0}, {1, 0, -2}};
  m.triangles = {{0, 1, 2}};
  return m;
}

MeshContact run_contact(const MovingMeshes& in) {
  return answerer::first_contact_moving_meshes(in.a, in.velocity_a, in.b, in.velocity_b);
}

// An example's check: the judge's rules (exact input), then the expected contact; its
// normal where only one will do (a contact in one plane may point either way).
auto expect_contact(bool hit, double t = 0, Vec3 point = Vec3::Zero(), Vec3 normal = Vec3::Zero()) {
  return [=](const MovingMeshes& in) {
    const MeshContact got = run_contact(in);
    const Outcome rules = judge::first_contact_moving_meshes(in, got, Rules::exact);
    if (rules.verdict == Outcome::Verdict::fail) return rules;
    Expect e(
        "the first contact is the earliest time the moving triangles touch, with the point where they touch then "
        "and the contact's unit normal, from B toward A");
    e.equal("hit", got.hit, hit);
    if (hit && got.hit) {
      e.near("t", got.t, t, 1e-12);
      e.near("point", got.point, point, 1e-12);
      if (normal != Vec3::Zero()) e.near("normal", got.normal, normal, 1e-12);  // else: either sign, the judge's
    }
    return e.outcome();
  };
}

}  // namespace

TEST_CASE(LABKIT_STEP(L02S7) ": worked examples", "[lab02][step7]") {
  constexpr auto q = query::first_contact_moving_meshes;
  check::example(q, "a vertex of A falls on B's face: t = 1/2",
                 MovingMeshes{spike(), {0, 0, -4}, floor_square(), {0, 0, 0}},
                 expect_contact(true, 0.5, {1, 2, 0}, {0, 0, 1}));
  check::example(q, "both move: A falls by 2, the floor rises by 2, t = 1/2",
                 MovingMeshes{spike(), {0, 0, -2}, floor_square(), {0, 0, 2}},
                 expect_contact(true, 0.5, {1, 2, 1}, {0, 0, 1}));
  check::example(
      q, "a vertex of B meets A's face: the rising floor lifts into the spike; the normal points from B down to A",
      MovingMeshes{floor_square(), {0, 0, 4}, spike(), {0, 0, 0}}, expect_contact(true, 0.5, {1, 2, 2}, {0, 0, -1}));
  check::example(q, "edge against edge: crossed triangles, t = 1/2, normal e x f = (0, 0, 16) turned to unit length",
                 MovingMeshes{upright_a(), {0, 0, -2}, upright_b(), {0, 0, 0}},
                 expect_contact(true, 0.5, {1, 0, 0}, {0, 0, 1}));
  check::example(q, "stops short: the spike falls only 1.5",
                 MovingMeshes{spike(), {0, 0, -1.5}, floor_square(), {0, 0, 0}}, expect_contact(false));
  check::example(q, "the same velocity: never closer", MovingMeshes{spike(), {0, 0, -4}, floor_square(), {0, 0, -4}},
                 expect_contact(false));
}

TEST_CASE(LABKIT_STEP(L02S7) ": random cases", "[lab02][step7][oracle]") {
  check::random_cases(query::first_contact_moving_meshes, gen::moving_meshes(),
                      [](const MovingMeshes& in) { return judge::first_contact_moving_meshes(in, run_contact(in)); });
}

// ---- Step 8: robustness --------------------------------------------------------------
// Exact degenerate input on integer coordinates: the header's rules hold exactly.

namespace {

const Triangle kSmall{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}};

Outcome exact_find(const SegmentTrianglePair& in) {
  const Outcome o =
      judge::find_segment_triangle(in, answerer::find_segment_triangle(in.segment, in.triangle), Rules::exact);
  if (o.verdict == Outcome::Verdict::fail) return o;
  return judge::test_segment_triangle(in, answerer::test_segment_triangle(in.segment, in.triangle), Rules::exact);
}

// A hit with the given t, and the find query's other checks.
auto expect_hit(double t) {
  return [t](const SegmentTrianglePair& in) {
    const SegmentTriangleHit got = answerer::find_segment_triangle(in.segment, in.triangle);
    Expect e("a segment that meets the closed triangle hits it: t along a to b, point a + t (b - a)");
    const bool coplanar = oracle::segment_triangle(in.segment, in.triangle).coplanar;
    e.that("hit", got.hit, describe(got.hit), "true",
           coplanar ? "the segment lies in the triangle's plane, and in the plane it hits where the two meet"
                    : "the segment touches the triangle exactly on its boundary (an edge, a vertex, or an end on it), "
                      "and the closed triangle's boundary counts");
    if (got.hit)
      e.that("t", std::abs(got.t - t) <= 1e-12, fmt(got.t), fmt(t),
             coplanar ? "in the plane, t is the first common point from a"
                      : "t is where the segment first touches the triangle");
    const Outcome rules = exact_find(in);
    return e.outcome().verdict == Outcome::Verdict::fail ? e.outcome() : rules;
  };
}

Outcome expect_miss(const SegmentTrianglePair& in) {
  Expect e("a segment that misses the closed triangle is a miss for find and test alike");
  e.equal("hit", answerer::find_segment_triangle(in.segment, in.triangle).hit, false);
  e.equal("test", answerer::test_segment_triangle(in.segment, in.triangle), false);
  return e.outcome();
}

}  // namespace

TEST_CASE(LABKIT_STEP(L02S8) ": touching, edges, vertices, coplanar, zero size", "[lab02][step8]") {
  constexpr auto q = query::robust_find_segment_triangle;
  check::example(q, "an end exactly on the long edge", pair({1, 2, 0}, {1, 2, 5}, kSmall), expect_hit(0));
  check::example(q, "through vertex v0 at t = 1/3", pair({0, 0, 1}, {0, 0, -2}, kSmall), expect_hit(1.0 / 3));
  check::example(q, "through the edge v0 v1 at t = 1/3", pair({1, 0, 1}, {1, 0, -2}, kSmall), expect_hit(1.0 / 3));
  check::example(q, "through the long edge at t = 1/3", pair({1, 2, 1}, {1, 2, -2}, kSmall), expect_hit(1.0 / 3));
  // Slanted: the crossing point (4/3, 5/3, 0) is not a double, so a test on the rounded
  // point may land outside the edge; a test on signs of input products cannot.
  check::example(q, "slanted through the long edge at t = 1/3", pair({2, 2, 1}, {0, 1, -2}, kSmall),
                 expect_hit(1.0 / 3));
  check::example(q, "in the plane, entering at t = 1/6", pair({-1, 1, 0}, {5, 1, 0}, kSmall), expect_hit(1.0 / 6));
  check::example(q, "in the plane, starting inside", pair({1, 1, 0}, {5, 1, 0}, kSmall), expect_hit(0));
  check::example(q, "in the plane, touching only v1", pair({3, -1, 0}, {3, 1, 0}, kSmall), expect_hit(0.5));
  check::example(q, "in the plane, along the long edge's line", pair({4, -1, 0}, {2, 1, 0}, kSmall), expect_hit(0.5));
  check::example(q, "in the plane, missing", pair({2, 2, 0}, {4, 0, 0}, kSmall), expect_miss);
  check::example(q, "zero length, on an edge", pair({1, 0, 0}, {1, 0, 0}, kSmall), expect_hit(0));
  check::example(q, "zero length, off the triangle", pair({1, 1, 1}, {1, 1, 1}, kSmall), expect_miss);
  check::example(q, "a zero-area triangle is never hit", pair({1, 0, 1}, {1, 2, 1}, kFlat), expect_miss);

  constexpr auto edges = query::robust_point_in_triangle;
  const auto on_boundary = [](const PointTriangle& in) {
    Expect e("a point on an edge or a vertex is in the closed triangle: both point-in-triangle tests say yes");
    e.equal("point_in_triangle_edges", answerer::point_in_triangle_edges(in.x, in.triangle), true);
    e.equal("point_in_triangle_barycentric", answerer::point_in_triangle_barycentric(in.x, in.triangle), true);
    return e.outcome();
  };
  check::example(edges, "on the long edge, a third of the way", PointTriangle{{1, 2, 0}, kSmall}, on_boundary);
  check::example(edges, "a tilted triangle's edge midpoint",
                 PointTriangle{{1, 3, 5}, {{0, 2, 4}, {2, 4, 6}, {0, 0, 9}}}, on_boundary);
}

TEST_CASE(LABKIT_STEP(L02S8) ": shared edges and vertices in a mesh", "[lab02][step8]") {
  Mesh floor;
  gen::add_square(floor, 4, 0);
  constexpr auto q = query::robust_all_hits;
  check::example(q, "through the shared diagonal: both triangles", SegmentMeshPair{{{2, 2, 1}, {2, 2, -1}}, floor},
                 [](const SegmentMeshPair& in) {
    const std::vector<MeshHit> got = answerer::all_hits(in.segment, in.mesh);
    Expect e(
        "all_hits lists every triangle the segment meets once, even through a shared edge or corner; equal t go by "
        "triangle index");
    e.equal("count", int(got.size()), 2);
    if (got.size() == 2) {
      e.equal("order by index on a tie", got[0].triangle, 0);
      e.near("t", got[1].t, 0.5, 1e-12);
    }
    e.equal("first_hit.hit", answerer::first_hit(in.segment, in.mesh).hit, true);
    return e.outcome();
  });
  check::example(q, "through the shared corner (4, 4, 0): both triangles",
                 SegmentMeshPair{{{4, 4, 3}, {4, 4, -3}}, floor},
                 [](const SegmentMeshPair& in) {
    Expect e("all_hits lists every triangle the segment meets once, even through a shared edge or corner");
    e.equal("count", int(answerer::all_hits(in.segment, in.mesh).size()), 2);
    return e.outcome();
  });
}

TEST_CASE(LABKIT_STEP(L02S8) ": random exact degenerate cases", "[lab02][step8][oracle]") {
  check::random_cases(query::robust_find_segment_triangle, gen::exact_segment_triangle(), exact_find);
  check::random_cases(query::robust_point_in_triangle, gen::exact_point_triangle(), [](const PointTriangle& in) {
    const Outcome o = judge::point_in_triangle(in, answerer::point_in_triangle_edges(in.x, in.triangle), Rules::exact);
    if (o.verdict == Outcome::Verdict::fail) return o;
    return judge::point_in_triangle(in, answerer::point_in_triangle_barycentric(in.x, in.triangle), Rules::exact);
  });
  check::random_cases(query::robust_all_hits, gen::exact_segment_mesh(), [](const SegmentMeshPair& in) {
    const Outcome o = judge::all_hits(in, answerer::all_hits(in.segment, in.mesh), Rules::exact);
    if (o.verdict == Outcome::Verdict::fail) return o;
    return judge::first_hit(in, answerer::first_hit(in.segment, in.mesh), Rules::exact);
  });
  // The thinnest needles, crossed steeply near their long edge: many yes/no answers are in
  // doubt there, but t, the point and the weights are checked all the same.
  check::random_cases(query::needle_find_segment_triangle, gen::needle_crossed_steeply(),
                      [](const SegmentTrianglePair& in) {
    const Outcome o = run_find(in);
    return o.verdict == Outcome::Verdict::fail ? o : run_test(in);
  });
}

// ---- Step 9: robustness of the moving meshes (an extension, as step 7 is) -------------
// Step 7 on exact input: contacts exactly at a vertex, on an edge, at t = 1, in one plane.

TEST_CASE(LABKIT_STEP(L02S9) ": worked examples", "[lab02][step9]") {
  constexpr auto q = query::robust_first_contact_moving_meshes;
  // The spike's vertex (1, 1, 2) falls onto the floor's shared diagonal (0,0)-(4,4).
  check::example(q, "a vertex onto the shared diagonal at t = 1/2",
                 MovingMeshes{spike({1, 1, 2}), {0, 0, -4}, floor_square(), {0, 0, 0}},
                 expect_contact(true, 0.5, {1, 1, 0}, {0, 0, 1}));
  // The contact happens exactly at the end of the frame: closed, it counts.
  check::example(q, "touching exactly at t = 1", MovingMeshes{spike(), {0, 0, -2}, floor_square(), {0, 0, 0}},
                 expect_contact(true, 1, {1, 2, 0}, {0, 0, 1}));
  // The end (2, 0, 1) of A's lowest edge lands exactly on B's top edge.
  Mesh b = upright_b();
  b.vertices = {{2, -2, 0}, {2, 2, 0}, {2, 0, -2}};
  check::example(q, "the end of an edge onto an edge: (2, 0, 0) at t = 1/2",
                 MovingMeshes{upright_a(), {0, 0, -2}, b, {0, 0, 0}}, expect_contact(true, 0.5, {2, 0, 0}));
  // Coplanar: two triangles in the plane z = 0 slide into each other.
  Mesh flat_a, flat_b;
  flat_a.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  flat_a.triangles = {{0, 1, 2}};
  flat_b.vertices = {{4, 0, 0}, {6, 0, 0}, {4, 2, 0}};
  flat_b.triangles = {{0, 1, 2}};
  check::example(q, "in one plane: sliding into each other, t = 1/2",
                 MovingMeshes{flat_a, {4, 0, 0}, flat_b, {0, 0, 0}}, expect_contact(true, 0.5, {4, 0, 0}));
}

TEST_CASE(LABKIT_STEP(L02S9) ": random exact degenerate cases", "[lab02][step9][oracle]") {
  check::random_cases(
      query::robust_first_contact_moving_meshes, gen::exact_moving_meshes(),
      [](const MovingMeshes& in) { return judge::first_contact_moving_meshes(in, run_contact(in), Rules::exact); });
}

// ---- Preconditions: the reference rejects invalid input (not graded) -------------------
// Tagged [contract], in no step: students are not graded on invalid input. Each kind of
// invalid argument must throw std::invalid_argument whose message names the argument.

TEST_CASE("L02 preconditions: invalid input throws std::invalid_argument naming the argument", "[lab02][contract]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  Mesh floor;
  gen::add_square(floor, 4, 0);
  for (double bad : {nan, inf, -inf}) {
    INFO("bad number " << bad);
    const Vec3 p(1, bad, 0);
    const Segment bad_a{p, {1, 1, -1}}, bad_b{{1, 1, 3}, p}, good{{1, 1, 3}, {1, 1, -1}};
    for (int i = 0; i < 3; ++i) {
      Triangle t = kFloor;
      t[i] = p;
      const std::string v = "triangle.v" + std::to_string(i);
      rejects(v, [&] { answerer::segment_plane(good, t); });
      rejects(v, [&] { answerer::point_in_triangle_edges({1, 1, 0}, t); });
      rejects(v, [&] { answerer::barycentric({1, 1, 0}, t); });
      rejects(v, [&] { answerer::point_in_triangle_barycentric({1, 1, 0}, t); });
      rejects(v, [&] { answerer::test_segment_triangle(good, t); });
      rejects(v, [&] { answerer::find_segment_triangle(good, t); });
    }
    for (const auto& [name, s] :
         {std::pair{std::string("segment.a"), bad_a}, std::pair{std::string("segment.b"), bad_b}}) {
      rejects(name, [&] { answerer::segment_plane(s, kFloor); });
      rejects(name, [&] { answerer::test_segment_triangle(s, kFloor); });
      rejects(name, [&] { answerer::find_segment_triangle(s, kFloor); });
      rejects(name, [&] { answerer::first_hit(s, floor); });
      rejects(name, [&] { answerer::any_hit(s, floor); });
      rejects(name, [&] { answerer::all_hits(s, floor); });
      rejects(name,
              [&] { answerer::first_hit_moving(s, floor, RigidTransform::Identity(), RigidTransform::Identity()); });
    }
    rejects("x", [&] { answerer::point_in_triangle_edges(p, kFloor); });
    rejects("x", [&] { answerer::barycentric(p, kFloor); });
    rejects("x", [&] { answerer::point_in_triangle_barycentric(p, kFloor); });
    Mesh bad_vertex = floor;
    bad_vertex.vertices[2] = p;
    rejects("mesh.vertices[2]", [&] { answerer::first_hit(good, bad_vertex); });
    rejects("mesh.vertices[2]", [&] { answerer::any_hit(good, bad_vertex); });
    rejects("mesh.vertices[2]", [&] { answerer::all_hits(good, bad_vertex); });
    RigidTransform pose = RigidTransform::Identity();
    pose.translation() = p;
    rejects("m0", [&] { answerer::first_hit_moving(good, floor, pose, RigidTransform::Identity()); });
    rejects("m1", [&] { answerer::first_hit_moving(good, floor, RigidTransform::Identity(), pose); });
  }
  const Segment good{{1, 1, 3}, {1, 1, -1}};
  for (int index : {-1, 4}) {
    Mesh bad_index = floor;
    bad_index.triangles[1][2] = index;
    rejects("mesh.triangles[1]", [&] { answerer::first_hit(good, bad_index); });
    rejects("mesh.triangles[1]", [&] { answerer::any_hit(good, bad_index); });
    rejects("mesh.triangles[1]", [&] { answerer::all_hits(good, bad_index); });
  }
  for (double bad : {nan, inf}) {
    const Vec3 p(bad, 0, 0);
    Mesh bad_vertex = floor;
    bad_vertex.vertices[1] = p;
    rejects("velocity_a", [&] { answerer::first_contact_moving_meshes(floor, p, floor, Vec3::Zero()); });
    rejects("velocity_b", [&] { answerer::first_contact_moving_meshes(floor, Vec3::Zero(), floor, p); });
    rejects("a.vertices[1]",
            [&] { answerer::first_contact_moving_meshes(bad_vertex, Vec3::Zero(), floor, Vec3::Zero()); });
    rejects("b.vertices[1]",
            [&] { answerer::first_contact_moving_meshes(floor, Vec3::Zero(), bad_vertex, Vec3::Zero()); });
  }
  {
    Mesh bad_index = floor;
    bad_index.triangles[0][1] = 7;
    rejects("a.triangles[0]",
            [&] { answerer::first_contact_moving_meshes(bad_index, Vec3::Zero(), floor, Vec3::Zero()); });
  }
  RigidTransform stretched = RigidTransform::Identity();
  stretched.linear() *= 2;
  rejects("m1", [&] { answerer::first_hit_moving(good, floor, RigidTransform::Identity(), stretched); });
  // Not invalid: the documented results of zero length and zero area.
  CHECK_FALSE(answerer::test_segment_triangle({{1, 1, 1}, {1, 1, 1}}, kFloor));
  CHECK_FALSE(answerer::test_segment_triangle(good, kFlat));
}

// ---- The header's tolerance for step 7's normal (the judge, on hand-made answers) -----
// "Where several features touch at once (or within tol of it), any of their normals will
// do." A's floor triangle rises by 2 into B, whose lowest vertex q passes 1e-12 outside
// A's edge along x while A's edge meets B's two edges from q, at t = 1/2 + 2.5e-13: the
// edges' normal and A's face normal are both right; a wrong axis or a turned normal is not.

TEST_CASE("L02 step 7's judge takes the normal of any feature within tol of touching", "[lab02][contract]") {
  Mesh a, b;
  a.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  a.triangles = {{0, 1, 2}};
  b.vertices = {{1, -1e-12, 1}, {0.5, 1, 1.5}, {0.8, 1, 1.5}};
  b.triangles = {{0, 1, 2}};
  const MovingMeshes in{a, {0, 0, 2}, b, Vec3::Zero()};
  const auto verdict = [&](const Vec3& normal) {
    const Outcome o = judge::first_contact_moving_meshes(in, MeshContact{true, 0.5, {1, 0, 1}, normal});
    INFO("normal " << normal.transpose() << ": " << o.why);
    return o.verdict;
  };
  using V = Outcome::Verdict;
  CHECK(verdict(Vec3(0, 1, -2).normalized()) == V::pass);  // A's edge x B's edges from q
  CHECK(verdict({0, 0, -1}) == V::pass);                   // A's face, which q misses by 1e-12
  CHECK(verdict({0, 0, 1}) == V::fail);                    // the face's, turned from A toward B
  CHECK(verdict({1, 0, 0}) == V::fail);                    // no feature's
}

// Step 2's yes/no at a needle's sharp vertex: x lies 4.4e-16 outside v2, beyond the edge
// v1 v2. The inside near v2 is a wedge of about 5 degrees, which sampled moves of all
// the numbers missed (CI's sweep, seed 310); a move of x alone by tol reaches it, so
// either answer passes. Well outside the wedge, "inside" still fails.
TEST_CASE("L02 step 2's judge: a point within tol of an edge is ambiguous", "[lab02][contract]") {
  const Triangle needle{
      {-13, 0, 0}, {-0.6339359283447266, -9, 8}, {0.2922353074968522, -9.630142138885883, 8.732456870770896}};
  const PointTriangle hair{{0.29223530749685267, -9.630142138885883, 8.732456870770896}, needle};
  CHECK(judge::point_in_triangle(hair, true).verdict == Outcome::Verdict::ambiguous);
  CHECK(judge::point_in_triangle(hair, false).verdict != Outcome::Verdict::fail);
  const PointTriangle far{needle.v2 + Vec3(1e-3, 0, 0), needle};
  CHECK(judge::point_in_triangle(far, true).verdict == Outcome::Verdict::fail);
}
