// Lab 02 tests. Each step: the hand-worked examples of handouts/02_segment_triangle.md,
// then random cases against the exact oracle (tests/02_segment_triangle.judge.cpp).
#include "02_segment_triangle.judge.h"
#include "segment_triangle.h"

#include <cmath>

using namespace labkit;
using namespace labkit::lab02;
using check::Expect;
using check::Outcome;
using judge::Rules;

namespace {

// The handout's triangle: the right triangle with legs 4 on the x and y axes, z = 0.
const Triangle kFloor{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
const Triangle kFlat{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};  // zero area

SegmentTrianglePair pair(Vec3 a, Vec3 b, const Triangle& t = kFloor) { return {{a, b}, t}; }

// The square [0, 4] x [0, 4] at height z, as two triangles split along its diagonal.
void add_square(Mesh& m, double z) {
  const int base = int(m.vertices.size());
  m.vertices.insert(m.vertices.end(), {{0, 0, z}, {4, 0, z}, {4, 4, z}, {0, 4, z}});
  m.triangles.push_back({base, base + 1, base + 2});
  m.triangles.push_back({base, base + 2, base + 3});
}

Mesh floor_and_shelf() {
  Mesh m;
  add_square(m, 0);  // triangles 0 and 1
  add_square(m, 2);  // triangles 2 and 3
  return m;
}

// Judges that run the code under test, by query name.
Outcome run_segment_plane(const SegmentTrianglePair& in) {
  return judge::segment_plane(in, segment_plane(in.segment, in.triangle));
}
Outcome run_find(const SegmentTrianglePair& in) {
  return judge::find_segment_triangle(in, find_segment_triangle(in.segment, in.triangle));
}
Outcome run_test(const SegmentTrianglePair& in) {
  return judge::test_segment_triangle(in, test_segment_triangle(in.segment, in.triangle));
}

}  // namespace

// ---- Step 1 ------------------------------------------------------------------------

TEST_CASE("L02S1 signed distances and the crossing point: worked examples", "[lab02][step1]") {
  check::example("segment_plane", "a above, b below: crosses at t = 3/4", pair({1, 1, 3}, {1, 1, -1}),
                 [](const SegmentTrianglePair& in) {
                   const PlaneCrossing got = segment_plane(in.segment, in.triangle);
                   Expect e;
                   e.near("d_a", got.d_a, 3, 1e-12);
                   e.near("d_b", got.d_b, -1, 1e-12);
                   e.equal("crosses", got.crosses, true);
                   e.near("t", got.t, 0.75, 1e-12);
                   e.near("point", got.point, Vec3(1, 1, 0), 1e-12);
                   return e.outcome();
                 });
  check::example("segment_plane", "both ends above: no crossing", pair({1, 1, 2}, {3, 3, 5}),
                 [](const SegmentTrianglePair& in) {
                   const PlaneCrossing got = segment_plane(in.segment, in.triangle);
                   Expect e;
                   e.near("d_a", got.d_a, 2, 1e-12);
                   e.near("d_b", got.d_b, 5, 1e-12);
                   e.equal("crosses", got.crosses, false);
                   return e.outcome();
                 });
  check::example("segment_plane", "a on the plane: crosses at t = 0", pair({1, 1, 0}, {2, 2, 2}),
                 [](const SegmentTrianglePair& in) {
                   const PlaneCrossing got = segment_plane(in.segment, in.triangle);
                   Expect e;
                   e.equal("crosses", got.crosses, true);
                   e.near("t", got.t, 0, 1e-12);
                   e.near("point", got.point, Vec3(1, 1, 0), 1e-12);
                   return e.outcome();
                 });
  check::example("segment_plane", "the normal follows the winding", pair({1, 1, 3}, {1, 1, -1}, {{0, 0, 0}, {0, 4, 0}, {4, 0, 0}}),
                 [](const SegmentTrianglePair& in) {
                   const PlaneCrossing got = segment_plane(in.segment, in.triangle);
                   Expect e;
                   e.near("d_a", got.d_a, -3, 1e-12);
                   e.near("d_b", got.d_b, 1, 1e-12);
                   e.near("t", got.t, 0.75, 1e-12);
                   return e.outcome();
                 });
}

TEST_CASE("L02S1 signed distances and the crossing point: random cases", "[lab02][step1][oracle]") {
  check::random_cases("segment_plane", gen::decisive_segment_triangle(), run_segment_plane);
}

// ---- Step 2 ------------------------------------------------------------------------

TEST_CASE("L02S2 point in triangle by edge tests: worked examples", "[lab02][step2]") {
  const auto expect = [](bool inside) {
    return [inside](const PointTriangle& in) {
      Expect e;
      e.equal("inside", point_in_triangle_edges(in.x, in.triangle), inside);
      return e.outcome();
    };
  };
  check::example("point_in_triangle_edges", "inside", PointTriangle{{1, 1, 0}, kFloor}, expect(true));
  check::example("point_in_triangle_edges", "beyond the long edge", PointTriangle{{3, 3, 0}, kFloor}, expect(false));
  check::example("point_in_triangle_edges", "left of v0", PointTriangle{{-1, 1, 0}, kFloor}, expect(false));
  check::example("point_in_triangle_edges", "on the long edge counts", PointTriangle{{2, 2, 0}, kFloor}, expect(true));
  check::example("point_in_triangle_edges", "a vertex counts", PointTriangle{{0, 0, 0}, kFloor}, expect(true));
  check::example("point_in_triangle_edges", "clockwise triangle", PointTriangle{{1, 1, 0}, {{0, 0, 0}, {0, 4, 0}, {4, 0, 0}}}, expect(true));
  check::example("point_in_triangle_edges", "zero-area triangle", PointTriangle{{1, 1, 1}, kFlat}, expect(false));
}

TEST_CASE("L02S2 point in triangle by edge tests: random cases", "[lab02][step2][oracle]") {
  check::random_cases("point_in_triangle_edges", judge::point_triangle(), [](const PointTriangle& in) {
    return judge::point_in_triangle(in, point_in_triangle_edges(in.x, in.triangle));
  });
}

// ---- Step 3 ------------------------------------------------------------------------

TEST_CASE("L02S3 barycentric coordinates in the dropped-axis plane: worked examples", "[lab02][step3]") {
  const auto expect = [](int axis, double alpha, double beta) {
    return [=](const PointTriangle& in) {
      const Barycentric got = barycentric(in.x, in.triangle);
      Expect e;
      e.equal("dropped_axis", got.dropped_axis, axis);
      e.near("alpha", got.alpha, alpha, 1e-12);
      e.near("beta", got.beta, beta, 1e-12);
      return e.outcome();
    };
  };
  check::example("barycentric", "the floor triangle: drop z", PointTriangle{{1, 2, 0}, kFloor}, expect(2, 0.25, 0.5));
  check::example("barycentric", "a tilted triangle: drop x", PointTriangle{{0.25, 0.5, 1.5}, {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}},
                 expect(0, 0.25, 0.5));
  check::example("barycentric", "x = v2 gives beta = 1", PointTriangle{{0, 4, 0}, kFloor}, expect(2, 0, 1));
  check::example("barycentric", "zero area: no axis", PointTriangle{{1, 1, 1}, kFlat}, [](const PointTriangle& in) {
    Expect e;
    e.equal("dropped_axis", barycentric(in.x, in.triangle).dropped_axis, -1);
    return e.outcome();
  });
  const auto inside = [](bool expected) {
    return [expected](const PointTriangle& in) {
      Expect e;
      e.equal("inside", point_in_triangle_barycentric(in.x, in.triangle), expected);
      return e.outcome();
    };
  };
  check::example("point_in_triangle_barycentric", "inside", PointTriangle{{1, 1, 0}, kFloor}, inside(true));
  check::example("point_in_triangle_barycentric", "alpha + beta > 1", PointTriangle{{3, 3, 0}, kFloor}, inside(false));
  check::example("point_in_triangle_barycentric", "on the long edge: alpha + beta = 1", PointTriangle{{1, 3, 0}, kFloor}, inside(true));
  check::example("point_in_triangle_barycentric", "beta < 0", PointTriangle{{1, -1, 0}, kFloor}, inside(false));
}

TEST_CASE("L02S3 barycentric coordinates: random cases", "[lab02][step3][oracle]") {
  check::random_cases("barycentric", judge::point_triangle(), [](const PointTriangle& in) {
    return judge::barycentric(in, barycentric(in.x, in.triangle));
  });
  check::random_cases("point_in_triangle_barycentric", judge::point_triangle(), [](const PointTriangle& in) {
    return judge::point_in_triangle(in, point_in_triangle_barycentric(in.x, in.triangle));
  });
}

// ---- Step 4 ------------------------------------------------------------------------

TEST_CASE("L02S4 test and find segment-triangle: worked examples", "[lab02][step4]") {
  check::example("find_segment_triangle", "through the inside at t = 3/4", pair({1, 1, 3}, {1, 1, -1}),
                 [](const SegmentTrianglePair& in) {
                   const SegmentTriangleHit got = find_segment_triangle(in.segment, in.triangle);
                   Expect e;
                   e.equal("hit", got.hit, true);
                   e.near("t", got.t, 0.75, 1e-12);
                   e.near("point", got.point, Vec3(1, 1, 0), 1e-12);
                   e.near("barycentric", got.barycentric, Vec3(0.5, 0.25, 0.25), 1e-12);
                   e.near("normal", got.normal, Vec3(0, 0, 1), 1e-12);
                   return e.outcome();
                 });
  check::example("find_segment_triangle", "from below: same normal, t = 1/4", pair({1, 1, -1}, {1, 1, 3}),
                 [](const SegmentTrianglePair& in) {
                   const SegmentTriangleHit got = find_segment_triangle(in.segment, in.triangle);
                   Expect e;
                   e.equal("hit", got.hit, true);
                   e.near("t", got.t, 0.25, 1e-12);
                   e.near("normal", got.normal, Vec3(0, 0, 1), 1e-12);
                   return e.outcome();
                 });
  const auto miss = [](const SegmentTrianglePair& in) {
    Expect e;
    e.equal("hit", find_segment_triangle(in.segment, in.triangle).hit, false);
    e.equal("test", test_segment_triangle(in.segment, in.triangle), false);
    return e.outcome();
  };
  check::example("find_segment_triangle", "crosses the plane beside the triangle", pair({3, 3, 1}, {3, 3, -1}), miss);
  check::example("find_segment_triangle", "parallel, above", pair({1, 1, 1}, {2, 1, 1}), miss);
  check::example("find_segment_triangle", "stops short of the plane", pair({1, 1, 3}, {1, 1, 1}), miss);
  // The floor triangle shrunk by 2^-22 (legs of 9.5e-7): its normal is 9.1e-13 long, below
  // the 1e-12 of Eigen's fuzzy isZero(), and still not zero.
  const double tiny = std::ldexp(1.0, -22);
  check::example("find_segment_triangle", "a triangle a millionth the size",
                 pair(Vec3(1, 1, 3) * tiny, Vec3(1, 1, -1) * tiny, {{0, 0, 0}, Vec3(4 * tiny, 0, 0), Vec3(0, 4 * tiny, 0)}),
                 [tiny](const SegmentTrianglePair& in) {
                   const SegmentTriangleHit got = find_segment_triangle(in.segment, in.triangle);
                   Expect e;
                   e.equal("hit", got.hit, true);
                   e.near("t", got.t, 0.75, 1e-12);
                   e.near("point", got.point, Vec3(tiny, tiny, 0), 1e-18);
                   return e.outcome();
                 });
  check::example("test_segment_triangle", "through the inside", pair({1, 1, 3}, {1, 1, -1}), [](const SegmentTrianglePair& in) {
    Expect e;
    e.equal("test", test_segment_triangle(in.segment, in.triangle), true);
    return e.outcome();
  });
}

TEST_CASE("L02S4 test and find segment-triangle: random cases", "[lab02][step4][oracle]") {
  // Found by a class run: a starts exactly on the plane, near an edge, and b is 5e-8
  // off it, so the rounding of d_a alone moves the crossing 2.5e-7 along the plane and
  // off the triangle. The judge allows what the tolerance of t allows.
  check::example("find_segment_triangle", "almost in the plane, from a point on it",
                 pair({-1.383425235748291, 4.109798431396484, 6.50537109375},
                      {-6.671734802378595, -8.144360497256555, -16.96777346270255},
                      {{-2, 0.01881122589111328, -0.9892578125},
                       {-0.766850471496582, 8.200785636901855, 14},
                       {1.4385852813720703, 8.58306884765625e-06, 0}}),
                 run_find);
  check::random_cases("test_segment_triangle", gen::decisive_segment_triangle(), run_test);
  check::random_cases("find_segment_triangle", gen::decisive_segment_triangle(), run_find);
}

// ---- Step 5 ------------------------------------------------------------------------

TEST_CASE("L02S5 segment against a mesh: worked examples", "[lab02][step5]") {
  const Mesh mesh = floor_and_shelf();
  check::example("first_hit", "the shelf before the floor", SegmentMeshPair{{{1, 3, 5}, {1, 3, -1}}, mesh},
                 [](const SegmentMeshPair& in) {
                   const MeshHit got = first_hit(in.segment, in.mesh);
                   Expect e;
                   e.equal("hit", got.hit, true);
                   e.equal("triangle", got.triangle, 3);
                   e.near("t", got.t, 0.5, 1e-12);
                   e.near("point", got.point, Vec3(1, 3, 2), 1e-12);
                   return e.outcome();
                 });
  check::example("all_hits", "shelf, then floor", SegmentMeshPair{{{1, 3, 5}, {1, 3, -1}}, mesh},
                 [](const SegmentMeshPair& in) {
                   const std::vector<MeshHit> got = all_hits(in.segment, in.mesh);
                   Expect e;
                   e.equal("count", int(got.size()), 2);
                   if (got.size() == 2) {
                     e.equal("first triangle", got[0].triangle, 3);
                     e.near("first t", got[0].t, 0.5, 1e-12);
                     e.equal("second triangle", got[1].triangle, 1);
                     e.near("second t", got[1].t, 5.0 / 6.0, 1e-12);
                   }
                   return e.outcome();
                 });
  check::example("any_hit", "beside the squares", SegmentMeshPair{{{5, 5, 5}, {5, 5, -1}}, mesh},
                 [](const SegmentMeshPair& in) {
                   Expect e;
                   e.equal("any_hit", any_hit(in.segment, in.mesh), false);
                   e.equal("first_hit.hit", first_hit(in.segment, in.mesh).hit, false);
                   e.equal("all_hits.size()", int(all_hits(in.segment, in.mesh).size()), 0);
                   return e.outcome();
                 });
}

TEST_CASE("L02S5 segment against a mesh: random cases", "[lab02][step5][oracle]") {
  check::random_cases("any_hit", gen::decisive_segment_mesh(), [](const SegmentMeshPair& in) {
    return judge::any_hit(in, any_hit(in.segment, in.mesh));
  });
  check::random_cases("first_hit", gen::decisive_segment_mesh(), [](const SegmentMeshPair& in) {
    return judge::first_hit(in, first_hit(in.segment, in.mesh));
  });
  check::random_cases("all_hits", gen::decisive_segment_mesh(), [](const SegmentMeshPair& in) {
    return judge::all_hits(in, all_hits(in.segment, in.mesh));
  });
}

// ---- Step 6 ------------------------------------------------------------------------

TEST_CASE("L02S6 segment against a moving mesh: worked examples", "[lab02][step6]") {
  Mesh floor;
  add_square(floor, 0);
  RigidTransform up = RigidTransform::Identity();
  up.translation() = Vec3(0, 0, 2);
  check::example("first_hit_moving", "a resting particle, a rising floor",
                 MovingMesh{{{1, 1, 1}, {1, 1, 1}}, floor, RigidTransform::Identity(), up}, [](const MovingMesh& in) {
                   const MeshHit got = first_hit_moving(in.segment, in.mesh, in.m0, in.m1);
                   Expect e;
                   e.equal("hit", got.hit, true);
                   e.near("t", got.t, 0.5, 1e-12);
                   e.near("point", got.point, Vec3(1, 1, 2), 1e-12);
                   e.near("normal", got.normal, Vec3(0, 0, 1), 1e-12);
                   return e.outcome();
                 });
  check::example("first_hit_moving", "the rising floor stops short of a falling particle",
                 MovingMesh{{{1, 1, 3}, {1, 1, 2.5}}, floor, RigidTransform::Identity(), up}, [](const MovingMesh& in) {
                   // In the floor's frame the particle goes from z = 3 to z = 0.5: no hit.
                   Expect e;
                   e.equal("hit", first_hit_moving(in.segment, in.mesh, in.m0, in.m1).hit, false);
                   return e.outcome();
                 });
}

TEST_CASE("L02S6 segment against a moving mesh: random cases", "[lab02][step6][oracle]") {
  check::random_cases("first_hit_moving", judge::moving_mesh(), [](const MovingMesh& in) {
    return judge::first_hit_moving(in, first_hit_moving(in.segment, in.mesh, in.m0, in.m1));
  });
}

// ---- Step 7: robustness --------------------------------------------------------------
// Exact degenerate input on integer coordinates: the header's rules hold exactly.

namespace {

const Triangle kSmall{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}};

Outcome exact_find(const SegmentTrianglePair& in) {
  const Outcome o = judge::find_segment_triangle(in, find_segment_triangle(in.segment, in.triangle), Rules::exact);
  if (o.verdict == Outcome::Verdict::fail) return o;
  return judge::test_segment_triangle(in, test_segment_triangle(in.segment, in.triangle), Rules::exact);
}

// A hit with the given t, and the find query's other checks.
auto expect_hit(double t) {
  return [t](const SegmentTrianglePair& in) {
    const SegmentTriangleHit got = find_segment_triangle(in.segment, in.triangle);
    Expect e;
    e.equal("hit", got.hit, true);
    if (got.hit) e.near("t", got.t, t, 1e-12);
    const Outcome rules = exact_find(in);
    return e.outcome().verdict == Outcome::Verdict::fail ? e.outcome() : rules;
  };
}

Outcome expect_miss(const SegmentTrianglePair& in) {
  Expect e;
  e.equal("hit", find_segment_triangle(in.segment, in.triangle).hit, false);
  e.equal("test", test_segment_triangle(in.segment, in.triangle), false);
  return e.outcome();
}

}  // namespace

TEST_CASE("L02S7 robustness: touching, edges, vertices, coplanar, zero size", "[lab02][step7]") {
  const std::string q = "robust.find_segment_triangle";
  check::example(q, "an end exactly on the long edge", pair({1, 2, 0}, {1, 2, 5}, kSmall), expect_hit(0));
  check::example(q, "through vertex v0 at t = 1/3", pair({0, 0, 1}, {0, 0, -2}, kSmall), expect_hit(1.0 / 3));
  check::example(q, "through the edge v0 v1 at t = 1/3", pair({1, 0, 1}, {1, 0, -2}, kSmall), expect_hit(1.0 / 3));
  check::example(q, "through the long edge at t = 1/3", pair({1, 2, 1}, {1, 2, -2}, kSmall), expect_hit(1.0 / 3));
  // Slanted: the crossing point (4/3, 5/3, 0) is not a double, so a test on the rounded
  // point may land outside the edge; a test on signs of input products cannot.
  check::example(q, "slanted through the long edge at t = 1/3", pair({2, 2, 1}, {0, 1, -2}, kSmall), expect_hit(1.0 / 3));
  check::example(q, "in the plane, entering at t = 1/6", pair({-1, 1, 0}, {5, 1, 0}, kSmall), expect_hit(1.0 / 6));
  check::example(q, "in the plane, starting inside", pair({1, 1, 0}, {5, 1, 0}, kSmall), expect_hit(0));
  check::example(q, "in the plane, touching only v1", pair({3, -1, 0}, {3, 1, 0}, kSmall), expect_hit(0.5));
  check::example(q, "in the plane, along the long edge's line", pair({4, -1, 0}, {2, 1, 0}, kSmall), expect_hit(0.5));
  check::example(q, "in the plane, missing", pair({2, 2, 0}, {4, 0, 0}, kSmall), expect_miss);
  check::example(q, "zero length, on an edge", pair({1, 0, 0}, {1, 0, 0}, kSmall), expect_hit(0));
  check::example(q, "zero length, off the triangle", pair({1, 1, 1}, {1, 1, 1}, kSmall), expect_miss);
  check::example(q, "a zero-area triangle is never hit", pair({1, 0, 1}, {1, 2, 1}, kFlat), expect_miss);

  const std::string edges = "robust.point_in_triangle";
  const auto on_boundary = [](const PointTriangle& in) {
    Expect e;
    e.equal("point_in_triangle_edges", point_in_triangle_edges(in.x, in.triangle), true);
    e.equal("point_in_triangle_barycentric", point_in_triangle_barycentric(in.x, in.triangle), true);
    return e.outcome();
  };
  check::example(edges, "on the long edge, a third of the way", PointTriangle{{1, 2, 0}, kSmall}, on_boundary);
  check::example(edges, "a tilted triangle's edge midpoint", PointTriangle{{1, 3, 5}, {{0, 2, 4}, {2, 4, 6}, {0, 0, 9}}},
                 on_boundary);
}

TEST_CASE("L02S7 robustness: shared edges and vertices in a mesh", "[lab02][step7]") {
  Mesh floor;
  add_square(floor, 0);
  const std::string q = "robust.all_hits";
  check::example(q, "through the shared diagonal: both triangles", SegmentMeshPair{{{2, 2, 1}, {2, 2, -1}}, floor},
                 [](const SegmentMeshPair& in) {
                   const std::vector<MeshHit> got = all_hits(in.segment, in.mesh);
                   Expect e;
                   e.equal("count", int(got.size()), 2);
                   if (got.size() == 2) {
                     e.equal("order by index on a tie", got[0].triangle, 0);
                     e.near("t", got[1].t, 0.5, 1e-12);
                   }
                   e.equal("first_hit.hit", first_hit(in.segment, in.mesh).hit, true);
                   return e.outcome();
                 });
  check::example(q, "through the shared corner (4, 4, 0): both triangles", SegmentMeshPair{{{4, 4, 3}, {4, 4, -3}}, floor},
                 [](const SegmentMeshPair& in) {
                   Expect e;
                   e.equal("count", int(all_hits(in.segment, in.mesh).size()), 2);
                   return e.outcome();
                 });
}

TEST_CASE("L02S7 robustness: random exact degenerate cases", "[lab02][step7][oracle]") {
  check::random_cases("robust.find_segment_triangle", gen::exact_segment_triangle(), exact_find);
  check::random_cases("robust.point_in_triangle", judge::exact_point_triangle(), [](const PointTriangle& in) {
    const Outcome o = judge::point_in_triangle(in, point_in_triangle_edges(in.x, in.triangle), Rules::exact);
    if (o.verdict == Outcome::Verdict::fail) return o;
    return judge::point_in_triangle(in, point_in_triangle_barycentric(in.x, in.triangle), Rules::exact);
  });
  check::random_cases("robust.all_hits", gen::exact_segment_mesh(), [](const SegmentMeshPair& in) {
    const Outcome o = judge::all_hits(in, all_hits(in.segment, in.mesh), Rules::exact);
    if (o.verdict == Outcome::Verdict::fail) return o;
    return judge::first_hit(in, first_hit(in.segment, in.mesh), Rules::exact);
  });
}
