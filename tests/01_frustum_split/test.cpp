// Lab 01 tests. Each step: the hand-worked examples of handouts/01_frustum_split.md,
// then random cases against the exact oracle (tests/01_frustum_split/judge.cpp).
#include "01_frustum_split/judge.h"
#include "common/oracle/clipping.h"
#include "frustum_split.h"

#include <algorithm>
#include <cmath>

using namespace labkit;
using namespace labkit::lab01;
using check::Expect;
using check::Outcome;
using check::rejects;
using judge::Rules;

// The header's input domain (every non-zero coordinate and normal component from 2^-130
// to 2^130, offsets up to 2^130: judge.h's header_in_domain): shrinking a failing case
// stays in it.
const bool kDomain = [] {
  check::domain({check::Domain::Of::each, 0x1p-130, 0x1p130});
  return true;
}();

namespace {

const double kHalfRoot2 = std::sqrt(0.5);

// The handout's plane z = 0, its normal pointing up: the kept side is z >= 0.
const Plane kFloor{{0, 0, 1}, 0};

// The handout's camera: at the origin, looking down -z, 90 degrees, square, near 1, far 3.
// Its frustum is |x| <= -z, |y| <= -z, 1 <= -z <= 3.
Camera square_camera() {
  Camera c;
  c.fov_y = M_PI / 2;
  c.near = 1;
  c.far = 3;
  return c;
}

// The same frustum with integer normals (not unit), for exact input.
Frustum integer_pyramid() {
  Frustum f;
  f.planes = {Plane{{1, 0, -1}, 0},  Plane{{-1, 0, -1}, 0}, Plane{{0, 1, -1}, 0},
              Plane{{0, -1, -1}, 0}, Plane{{0, 0, -1}, -1}, Plane{{0, 0, 1}, 3}};
  return f;
}

bool has_point(const std::vector<Triangle>& pieces, const Vec3& p) {
  for (const Triangle& t : pieces)
    for (int i = 0; i < 3; ++i)
      if ((t[i] - p).norm() <= 1e-12) return true;
  return false;
}

// The pieces of the polygon with these corners: m - 2 triangles covering its area, with
// exactly its corners (any triangulation passes), then every rule of the judge.
template <class Input, class Run, class Judge>
auto expect_polygon(std::vector<Vec3> corners, double area, Run run, Judge judge) {
  return [=](const Input& in) {
    const std::vector<Triangle> got = run(in);
    // The contract's rules first, with their reasons; then exactly these corners.
    const Outcome judged = judge(in, got);
    if (judged.verdict == Outcome::Verdict::fail) return judged;
    Expect e("the pieces are the kept polygon split into triangles, each corner a corner of the polygon");
    const int expected = corners.size() >= 3 ? int(corners.size()) - 2 : 0;
    e.that("triangles", int(got.size()) == expected, std::to_string(got.size()), std::to_string(expected),
           corners.empty()
               ? "nothing is left, so no triangle is expected"
               : "the polygon left has " + std::to_string(corners.size()) + " corners, so " + std::to_string(expected) +
                     (expected == 1 ? " triangle is" : " triangles are") + " expected");
    double total = 0;
    for (const Triangle& t : got) total += t.area();
    e.that("area", std::abs(total - area) <= 1e-12 * std::max(1.0, area), fmt(total), fmt(area),
           "the pieces must cover the kept polygon exactly once: its area is " + fmt(area) + ", yours sum to " +
               fmt(total));
    // The same corners, no more and no fewer (within 1e-12).
    bool same = true;
    for (const Vec3& c : corners) same = same && has_point(got, c);
    for (const Triangle& t : got)
      for (int i = 0; i < 3; ++i)
        same = same &&
               std::any_of(corners.begin(), corners.end(), [&](const Vec3& c) { return (t[i] - c).norm() <= 1e-12; });
    e.that("corners", same, describe(got), describe(corners),
           "the pieces' vertices must be the clipped polygon's corners");
    return e.outcome();
  };
}

std::vector<Triangle> run_split(const TrianglePlane& in) { return answerer::split_triangle(in.triangle, in.plane); }
std::vector<Triangle> run_clip(const TriangleFrustum& in) { return answerer::clip_triangle(in.triangle, in.frustum); }
Outcome judge_split(const TrianglePlane& in, const std::vector<Triangle>& got) {
  return judge::split_triangle(in, got, Rules::exact);
}
Outcome judge_clip(const TriangleFrustum& in, const std::vector<Triangle>& got) {
  return judge::clip_triangle(in, got, Rules::exact);
}

auto split_gives(std::vector<Vec3> corners, double area) {
  return expect_polygon<TrianglePlane>(std::move(corners), area, run_split, judge_split);
}
auto clip_gives(std::vector<Vec3> corners, double area) {
  return expect_polygon<TriangleFrustum>(std::move(corners), area, run_clip, judge_clip);
}

Outcome expect_planes(const Frustum& got, const std::array<Plane, 6>& expected, const Outcome& judged) {
  if (judged.verdict == Outcome::Verdict::fail) return judged;  // the contract's rules first, with their reasons
  static const char* names[6] = {"left", "right", "bottom", "top", "near", "far"};
  Expect e("each plane is the worked example's normal and offset, within 1e-12");
  for (int i = 0; i < 6; ++i) {
    const Plane &g = got.planes[std::size_t(i)], &x = expected[std::size_t(i)];
    const bool ok = (g.normal - x.normal).norm() <= 1e-12 && std::abs(g.offset - x.offset) <= 1e-12;
    e.that(std::string(names[i]), ok, describe(g), describe(x),
           std::string("the ") + names[i] + " plane of this worked example is normal " + fmt(x.normal) + ", offset " +
               fmt(x.offset) + " (within 1e-12): yours is normal " + fmt(g.normal) + ", offset " + fmt(g.offset));
  }
  return e.outcome();
}

// The planes of the square camera's frustum, unit normals.
std::array<Plane, 6> square_frustum_planes() {
  const double h = kHalfRoot2;
  return {Plane{{h, 0, -h}, 0},  Plane{{-h, 0, -h}, 0}, Plane{{0, h, -h}, 0},
          Plane{{0, -h, -h}, 0}, Plane{{0, 0, -1}, -1}, Plane{{0, 0, 1}, 3}};
}

Outcome run_split_random(const TrianglePlane& in) { return judge::split_triangle(in, run_split(in)); }
Outcome run_clip_random(const TriangleFrustum& in) { return judge::clip_triangle(in, run_clip(in)); }

ColoredMesh colored(const MeshFrustum& in) { return {in.mesh, in.colors}; }

// ---- Decisive random cases -------------------------------------------------------------
// Steps 1 to 5 must decide their random cases (at most 15% ambiguous), so the
// generators' exactly degenerate families (a vertex on a plane, an edge through the
// line where two planes meet, a triangle lying in a plane) are moved just outside the
// ambiguity band, 16 to 1024 tol off: still near-degenerate, but with one right answer.
// The exactly degenerate ones are step 6's.

// S as the header defines it: the points' largest |coordinate| and the planes'
// distances from the origin.
double scale_with(double points, const Plane* planes, int count) {
  double s = points;
  for (int i = 0; i < count; ++i)
    if (planes[i].normal.norm() > 0) s = std::max(s, std::abs(planes[i].offset) / planes[i].normal.norm());
  return std::max(s, 1e-300);
}

// 16 to 1024, a few bits of mantissa: how many tol off the band's edge.
double band_outside() {
  return std::ldexp(1 + *rc::gen::inRange(0, 16) / 16.0, *rc::gen::inRange(4, 10)) * *rc::gen::element(-1.0, 1.0);
}

// A vertex within 16 tol of the plane moves along its normal to 16 to 1024 tol off it
// (on its own side when it has one): the triangle tilts a little.
rc::Gen<TrianglePlane> decisive(rc::Gen<TrianglePlane> base) {
  return rc::gen::exec([base] {
    TrianglePlane c = *base;
    const double length = c.plane.normal.norm();
    const double tol = 1e-9 * scale_with(scale_of({c.triangle.v0, c.triangle.v1, c.triangle.v2}), &c.plane, 1);
    for (int i = 0; i < 3; ++i) {
      const double d = c.plane.value(c.triangle[i]) / length, off = band_outside();
      if (!(std::abs(d) <= 16 * tol)) continue;
      const double to = d == 0 ? off : std::copysign(off, d);
      c.triangle[i] += ((to * tol - d) / length) * c.plane.normal;
    }
    return c;
  });
}

// Several planes: while some sign of the clipping rule is in doubt, every plane moves
// by 16 to 1024 tol (each its own amount and way), from where it was.
template <class Case, class InDoubt> Case moved_until_decisive(const Case& base, double points, InDoubt&& in_doubt) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    Case c = base;
    const double tol = 1e-9 * scale_with(points, c.frustum.planes.data(), 6);
    if (attempt > 0)
      for (Plane& p : c.frustum.planes) p.offset += band_outside() * tol * p.normal.norm();
    if (!in_doubt(c, tol)) return c;
  }
  return base;
}

rc::Gen<TriangleFrustum> decisive(rc::Gen<TriangleFrustum> base) {
  return rc::gen::exec([base] {
    const TriangleFrustum c = *base;
    return moved_until_decisive(c, scale_of({c.triangle.v0, c.triangle.v1, c.triangle.v2}),
                                [](const TriangleFrustum& x, double tol) {
      return oracle::clip_in_doubt(x.triangle, {x.frustum.planes.begin(), x.frustum.planes.end()}, tol);
    });
  });
}

rc::Gen<MeshFrustum> decisive(rc::Gen<MeshFrustum> base) {
  return rc::gen::exec([base] {
    const MeshFrustum c = *base;
    return moved_until_decisive(c, scale_of(c.mesh), [](const MeshFrustum& x, double tol) {
      const std::vector<Plane> planes(x.frustum.planes.begin(), x.frustum.planes.end());
      for (std::size_t k = 0; k < x.mesh.size(); ++k)
        if (oracle::clip_in_doubt(x.mesh.triangle(k), planes, tol)) return true;
      return false;
    });
  });
}

}  // namespace

// ---- Step 1 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L01S1) ": worked examples", "[lab01][step1]") {
  // z = 1 written with a normal of length 2: value = 2 z - 2, distance = z - 1.
  const Plane z1{{0, 0, 2}, -2};
  const auto distance = [](const Vec3& x, double expected) {
    return [=](const TrianglePlane& in) {
      const double got = answerer::signed_distance(in.plane, x), value = in.plane.value(x),
                   length = in.plane.normal.norm();
      Expect e("the signed distance is (n . x + offset) / |n|");
      e.that("signed_distance", std::abs(got - expected) <= 1e-12, fmt(got), fmt(expected),
             "the signed distance is (n . x + offset) / |n| = " + fmt(value) + " / " + fmt(length) + " = " +
                 fmt(expected) +
                 (got == value && length != 1
                      ? ": yours is the value, |n| = " + fmt(length) + " times too large: divide by |n|"
                      : ""));
      return e.outcome();
    };
  };
  const TrianglePlane on_z1{{{0, 0, 0}, {2, 0, 2}, {0, 2, 1}}, z1};
  check::example(query::signed_distance, "3 above z = 1 (normal of length 2)", on_z1, distance({3, 4, 4}, 3));
  check::example(query::signed_distance, "1 below z = 1", on_z1, distance({1, 1, 0}, -1));
  check::example(query::signed_distance, "a tilted plane: (1, 2, 2) . x - 3 at (1, 1, 1) is 2, over |n| = 3",
                 TrianglePlane{{}, Plane{{1, 2, 2}, -3}}, distance({1, 1, 1}, 2.0 / 3.0));
  const auto sides = [](const TrianglePlane& in) {
    return judge::classify(in, answerer::classify(in.plane, in.triangle), Rules::exact);
  };
  check::example(query::classify, "out, in, on", on_z1, sides);
  check::example(query::classify, "2^-40 above the plane is in",
                 TrianglePlane{{{0, 0, 1 + std::ldexp(1.0, -40)}, {1, 0, 1}, {0, 1, -3}}, z1}, sides);
}

TEST_CASE(LABKIT_STEP(L01S1) ": random cases", "[lab01][step1][oracle]") {
  check::random_cases(query::signed_distance, decisive(gen::triangle_plane()), [](const TrianglePlane& in) {
    std::array<double, 3> got{};
    for (int i = 0; i < 3; ++i) got[std::size_t(i)] = answerer::signed_distance(in.plane, in.triangle[i]);
    return judge::signed_distance(in, got);
  });
  check::random_cases(query::classify, decisive(gen::triangle_plane()), [](const TrianglePlane& in) {
    return judge::classify(in, answerer::classify(in.plane, in.triangle));
  });
}

// ---- Step 2 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L01S2) ": the four configurations", "[lab01][step2]") {
  const double full = 8 * std::sqrt(3.0);  // the area of (0,0,-1), (4,0,3), (0,4,3)
  check::example(query::split_triangle, "all in: keep", TrianglePlane{{{0, 0, 1}, {4, 0, 1}, {0, 4, 3}}, kFloor},
                 split_gives({{0, 0, 1}, {4, 0, 1}, {0, 4, 3}}, 4 * std::sqrt(5.0)));
  check::example(query::split_triangle, "none in: cull", TrianglePlane{{{0, 0, -1}, {4, 0, -1}, {0, 4, -3}}, kFloor},
                 split_gives({}, 0));
  check::example(query::split_triangle, "one in: one triangle",
                 TrianglePlane{{{0, 0, -1}, {4, 0, -1}, {0, 4, 3}}, kFloor},
                 split_gives({{3, 1, 0}, {0, 4, 3}, {0, 1, 0}}, 4.5 * std::sqrt(2.0)));
  check::example(query::split_triangle, "two in: a quadrilateral, two triangles",
                 TrianglePlane{{{0, 0, -1}, {4, 0, 3}, {0, 4, 3}}, kFloor},
                 split_gives({{1, 0, 0}, {4, 0, 3}, {0, 4, 3}, {0, 1, 0}}, full - std::sqrt(3.0) / 2));
}

TEST_CASE(LABKIT_STEP(L01S2) ": vertices on the plane", "[lab01][step2]") {
  check::example(query::split_triangle, "a vertex on the plane, the others in: keep",
                 TrianglePlane{{{0, 0, 0}, {4, 0, 1}, {0, 4, 1}}, kFloor},
                 split_gives({{0, 0, 0}, {4, 0, 1}, {0, 4, 1}}, 6 * std::sqrt(2.0)));
  check::example(query::split_triangle, "a vertex on the plane, one in, one out",
                 TrianglePlane{{{0, 0, 0}, {4, 0, -2}, {0, 4, 2}}, kFloor},
                 split_gives({{0, 0, 0}, {2, 2, 0}, {0, 4, 2}}, 2 * std::sqrt(6.0)));
  check::example(query::split_triangle, "touching at a vertex from below: cull",
                 TrianglePlane{{{0, 0, 0}, {4, 0, -1}, {0, 4, -1}}, kFloor}, split_gives({}, 0));
  check::example(query::split_triangle, "an edge on the plane, the third vertex below: cull",
                 TrianglePlane{{{0, 0, 0}, {4, 0, 0}, {0, 4, -1}}, kFloor}, split_gives({}, 0));
  check::example(query::split_triangle, "lying in the plane: keep",
                 TrianglePlane{{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, kFloor},
                 split_gives({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, 8));
}

TEST_CASE(LABKIT_STEP(L01S2) ": random cases", "[lab01][step2][oracle]") {
  check::random_cases(query::split_triangle, decisive(gen::triangle_plane()), run_split_random);
}

// ---- Step 3 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L01S3) ": worked examples", "[lab01][step3]") {
  check::example(query::frustum_from_camera, "at the origin, looking down -z, 90 degrees, near 1, far 3",
                 square_camera(), [](const Camera& in) {
                   const Frustum got = answerer::frustum_from_camera(in);
                   return expect_planes(got, square_frustum_planes(), judge::frustum_from_camera(in, got));
                 });
  Camera wide = square_camera();
  wide.eye = {0, 0, 5};
  wide.aspect = 2;
  check::example(query::frustum_from_camera, "eye (0, 0, 5), twice as wide as high", wide, [](const Camera& in) {
    const double a = 1 / std::sqrt(5.0), h = kHalfRoot2;
    const Frustum got = answerer::frustum_from_camera(in);
    return expect_planes(
        got,
        {Plane{{a, 0, -2 * a}, 2 * std::sqrt(5.0)}, Plane{{-a, 0, -2 * a}, 2 * std::sqrt(5.0)},
         Plane{{0, h, -h}, 5 * h}, Plane{{0, -h, -h}, 5 * h}, Plane{{0, 0, -1}, 4}, Plane{{0, 0, 1}, -2}},
        judge::frustum_from_camera(in, got));
  });
  Mat4 perspective;
  perspective << 1, 0, 0, 0,  //
      0, 1, 0, 0,             //
      0, 0, -2, -3,           //
      0, 0, -1, 0;
  check::example(query::frustum_from_matrix, "the square camera's perspective matrix", perspective, [](const Mat4& in) {
    const Frustum got = answerer::frustum_from_matrix(in);
    return expect_planes(got, square_frustum_planes(), judge::frustum_from_matrix(in, got));
  });
  check::example(query::frustum_from_matrix, "the same matrix times 2: the same planes", Mat4(2 * perspective),
                 [](const Mat4& in) {
    const Frustum got = answerer::frustum_from_matrix(in);
    return expect_planes(got, square_frustum_planes(), judge::frustum_from_matrix(in, got));
  });
  Mat4 ortho;
  ortho << 0.5, 0, 0, 0,  //
      0, 1, 0, 0,         //
      0, 0, -0.5, -1.5,   //
      0, 0, 0, 1;
  check::example(query::frustum_from_matrix, "glOrtho(-2, 2, -1, 1, 1, 5): a box", ortho, [](const Mat4& in) {
    const Frustum got = answerer::frustum_from_matrix(in);
    return expect_planes(got,
                         {Plane{{1, 0, 0}, 2}, Plane{{-1, 0, 0}, 2}, Plane{{0, 1, 0}, 1}, Plane{{0, -1, 0}, 1},
                          Plane{{0, 0, -1}, -1}, Plane{{0, 0, 1}, 5}},
                         judge::frustum_from_matrix(in, got));
  });
}

TEST_CASE(LABKIT_STEP(L01S3) ": random cases", "[lab01][step3][oracle]") {
  check::random_cases(query::frustum_from_camera, gen::lab_camera(), [](const Camera& in) {
    return judge::frustum_from_camera(in, answerer::frustum_from_camera(in));
  });
  check::random_cases(query::frustum_from_matrix, gen::view_projection_matrix(),
                      [](const Mat4& in) { return judge::frustum_from_matrix(in, answerer::frustum_from_matrix(in)); });
}

// ---- Step 4 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L01S4) ": worked examples", "[lab01][step4]") {
  const Frustum f = [] {
    Frustum x;
    const auto planes = square_frustum_planes();
    std::copy(planes.begin(), planes.end(), x.planes.begin());
    return x;
  }();
  check::example(query::clip_triangle, "inside: keep", TriangleFrustum{{{0, 0, -2}, {0.5, 0, -2}, {0, 0.5, -2}}, f},
                 clip_gives({{0, 0, -2}, {0.5, 0, -2}, {0, 0.5, -2}}, 0.125));
  check::example(query::clip_triangle, "behind the camera: cull", TriangleFrustum{{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, f},
                 clip_gives({}, 0));
  check::example(query::clip_triangle, "from the eye: the near plane cuts off the tip",
                 TriangleFrustum{{{0, 0, 0}, {1, 0, -2}, {-1, 0, -2}}, f},
                 clip_gives({{0.5, 0, -1}, {1, 0, -2}, {-1, 0, -2}, {-0.5, 0, -1}}, 1.5));
  check::example(query::clip_triangle, "across the whole view at z = -2: the square |x|, |y| <= 2",
                 TriangleFrustum{{{-10, -10, -2}, {10, -10, -2}, {0, 10, -2}}, f},
                 clip_gives({{-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}}, 16));
}

TEST_CASE(LABKIT_STEP(L01S4) ": random cases", "[lab01][step4][oracle]") {
  check::random_cases(query::clip_triangle, decisive(gen::triangle_frustum()), run_clip_random);
}

// ---- Step 5 ------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L01S5) ": worked examples", "[lab01][step5]") {
  // The rectangle [-3, 1] x [-1, 1] at z = -2, red on its left side and green on its
  // right; the left plane x = -2 cuts it a quarter of the way across, where the colour is
  // (0.75, 0.25, 0). (Not halfway: at t = 1/2, t measured from the other end gives the
  // same colour, and the example could not catch it.)
  MeshFrustum in;
  in.mesh.vertices = {{-3, -1, -2}, {1, -1, -2}, {1, 1, -2}, {-3, 1, -2}};
  in.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  in.colors = {{1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {1, 0, 0}};
  in.frustum = integer_pyramid();
  check::example(query::clip_mesh, "a rectangle cut a quarter of the way across by the left plane", in,
                 [](const MeshFrustum& in) {
    const ClippedMesh got = answerer::clip_mesh(colored(in), in.frustum);
    // The contract's rules first (sizes, pieces, colours), with their reasons.
    const Outcome judged = judge::clip_mesh(in, got, Rules::exact);
    if (judged.verdict == Outcome::Verdict::fail) return judged;
    Expect e(
        "clip_mesh cuts each triangle by the planes and keeps its pieces, each listing its source triangle, each new "
        "vertex coloured by the t of its cut");
    e.equal("triangles", int(got.mesh.size()), 3);
    double area = 0;
    for (std::size_t k = 0; k < got.mesh.size(); ++k) area += got.mesh.triangle(k).area();
    e.near("area", area, 6, 1e-12);
    e.equal("pieces of triangle 0", int(std::count(got.source.begin(), got.source.end(), 0)), 2);
    e.equal("pieces of triangle 1", int(std::count(got.source.begin(), got.source.end(), 1)), 1);
    for (const auto& face : got.mesh.triangles)
      for (int i : face)
        if (got.mesh.vertices[std::size_t(i)].x() == -2)
          e.that("colour at " + fmt(got.mesh.vertices[std::size_t(i)]),
                 (got.colors[std::size_t(i)] - Vec3(0.75, 0.25, 0)).norm() <= 1e-12, fmt(got.colors[std::size_t(i)]),
                 fmt(Vec3(0.75, 0.25, 0)),
                 "a cut point's colour is interpolated with the same t as its position: a quarter of the way from red "
                 "to green");
    return e.outcome();
  });
}

TEST_CASE(LABKIT_STEP(L01S5) ": random cases", "[lab01][step5][oracle]") {
  check::random_cases(query::clip_mesh, decisive(gen::mesh_frustum()), [](const MeshFrustum& in) {
    return judge::clip_mesh(in, answerer::clip_mesh(colored(in), in.frustum));
  });
}

// ---- Step 6: robustness --------------------------------------------------------------
// Exact input: integer coordinates and plane coefficients. The header's rules hold exactly.

TEST_CASE(LABKIT_STEP(L01S6) ": vertices, edges and triangles on frustum planes", "[lab01][step6]") {
  const Frustum f = integer_pyramid();
  constexpr auto q = query::robust_clip_triangle;
  check::example(q, "an edge through the line where the left and near planes meet",
                 TriangleFrustum{{{-2, 0, 0}, {0, 0, -2}, {0, 1, -2}}, f},
                 clip_gives({{-1, 0, -1}, {0, 0, -2}, {0, 1, -2}, {-1, 0.5, -1}}, 0.75 * std::sqrt(2.0)));
  check::example(q, "touching that line from outside: cull",
                 TriangleFrustum{{{-1, -0.5, -1}, {-1, 0.5, -1}, {-2, 0, 0}}, f}, clip_gives({}, 0));
  check::example(q, "touching the corner (1, 1, -1) from outside: cull",
                 TriangleFrustum{{{1, 1, -1}, {2, 2, 0}, {2, 0, 0}}, f}, clip_gives({}, 0));
  check::example(q, "lying in the near plane: the part in the face",
                 TriangleFrustum{{{0, 0, -1}, {3, 0, -1}, {0, 3, -1}}, f},
                 clip_gives({{0, 0, -1}, {1, 0, -1}, {1, 1, -1}, {0, 1, -1}}, 1));
  check::example(q, "in the near plane, beside the face: cull",
                 TriangleFrustum{{{2, 2, -1}, {5, 2, -1}, {2, 5, -1}}, f}, clip_gives({}, 0));
  check::example(q, "a cut point that no double holds, exactly on the bottom plane",
                 TriangleFrustum{{{-2, -2, -1}, {0, 0, -2}, {0, 1, -3}}, f},
                 clip_gives({{-4.0 / 3, -4.0 / 3, -4.0 / 3}, {0, 0, -2}, {0, 1, -3}, {-1.5, -1.25, -1.5}}, 1.375));
  // Worked example 1 at the edge of the header's exact domain: normals 16 times longer
  // (components up to 16), coordinates 256 times larger, the far offset 12288 <= 2^14,
  // values up to 2^14: every sign still exact.
  Frustum edge = f;
  for (Plane& p : edge.planes) p = Plane{16 * p.normal, 16 * 256 * p.offset};
  check::example(q, "worked example 1 at the edge of the exact domain: normals times 16, coordinates times 256",
                 TriangleFrustum{{{-512, -512, -256}, {0, 0, -512}, {0, 256, -768}}, edge},
                 clip_gives({{-1024.0 / 3, -1024.0 / 3, -1024.0 / 3}, {0, 0, -512}, {0, 256, -768}, {-384, -320, -384}},
                            1.375 * 256 * 256));
  check::example(q, "crossing the left plane a third of the way along, exactly on the near plane",
                 TriangleFrustum{{{-2, 0, 0}, {1, 0, -3}, {1, 1, -3}}, f},
                 clip_gives({{-1, 0, -1}, {1, 0, -3}, {1, 1, -3}, {-1, 1.0 / 3, -1}}, 4 * std::sqrt(2.0) / 3));
}

TEST_CASE(LABKIT_STEP(L01S6) ": random exact degenerate cases", "[lab01][step6][oracle]") {
  check::random_cases(query::robust_classify, gen::exact_triangle_plane(), [](const TrianglePlane& in) {
    return judge::classify(in, answerer::classify(in.plane, in.triangle), Rules::exact);
  });
  check::random_cases(query::robust_split_triangle, gen::exact_triangle_plane(),
                      [](const TrianglePlane& in) { return judge::split_triangle(in, run_split(in), Rules::exact); });
  check::random_cases(query::robust_clip_triangle, gen::exact_triangle_frustum(),
                      [](const TriangleFrustum& in) { return judge::clip_triangle(in, run_clip(in), Rules::exact); });
  check::random_cases(query::robust_clip_mesh, gen::exact_mesh_frustum(), [](const MeshFrustum& in) {
    return judge::clip_mesh(in, answerer::clip_mesh(colored(in), in.frustum), Rules::exact);
  });
}

// ---- The contract: preconditions, and step 6's exact domain ------------------------------
// Run with the reference only (tag [contract], in no step): students are not graded on
// invalid input. Every kind of invalid input must throw std::invalid_argument whose
// message names the argument.

namespace {

const double kNaN = std::nan(""), kInf = HUGE_VAL;

}  // namespace

TEST_CASE("L01 preconditions: invalid input is named, not answered", "[lab01][contract]") {
  const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Plane zero{{0, 0, 0}, 1}, nan_normal{{kNaN, 0, 1}, 0}, inf_offset{{0, 0, 1}, kInf};
  rejects("a zero normal", "plane.normal", [&] { return answerer::signed_distance(zero, {0, 0, 0}); });
  rejects("a NaN normal", "plane.normal", [&] { return answerer::signed_distance(nan_normal, {0, 0, 0}); });
  rejects("an infinite offset", "plane.offset", [&] { return answerer::signed_distance(inf_offset, {0, 0, 0}); });
  rejects("a NaN point", "x", [&] { return answerer::signed_distance(kFloor, {kNaN, 0, 0}); });
  rejects("classify, a zero normal", "plane.normal", [&] { return answerer::classify(zero, t); });
  rejects("classify, an infinite vertex", "triangle.v1", [&] {
    return answerer::classify(kFloor, Triangle{{0, 0, 0}, {kInf, 0, 0}, {0, 1, 0}});
  });
  rejects("split, a NaN vertex", "triangle.v2", [&] {
    return answerer::split_triangle(Triangle{{0, 0, 0}, {1, 0, 0}, {0, kNaN, 0}}, kFloor);
  });
  rejects("split, a zero normal", "plane.normal", [&] { return answerer::split_triangle(t, zero); });

  const auto camera_with = [](auto&& change) {
    Camera c = square_camera();
    change(c);
    return c;
  };
  const std::vector<std::pair<std::string, Camera>> cameras = {
      {"camera.eye", camera_with([](Camera& c) { c.eye.x() = kNaN; })},
      {"camera.forward", camera_with([](Camera& c) { c.forward = Vec3::Zero(); })},
      {"camera.forward", camera_with([](Camera& c) { c.forward.z() = kInf; })},
      {"camera.up", camera_with([](Camera& c) { c.up = Vec3::Zero(); })},
      {"camera.up", camera_with([](Camera& c) {
         c.up = {0, 0, 2};
       })},  // parallel to forward
      {"camera.fov_y", camera_with([](Camera& c) { c.fov_y = 0; })},
      {"camera.fov_y", camera_with([](Camera& c) { c.fov_y = M_PI; })},
      {"camera.fov_y", camera_with([](Camera& c) { c.fov_y = kNaN; })},
      {"camera.aspect", camera_with([](Camera& c) { c.aspect = 0; })},
      {"camera.aspect", camera_with([](Camera& c) { c.aspect = kInf; })},
      {"camera.near", camera_with([](Camera& c) { c.near = 0; })},
      {"camera.near", camera_with([](Camera& c) { c.near = kNaN; })},
      {"camera.far", camera_with([](Camera& c) { c.far = c.near; })},
      {"camera.far", camera_with([](Camera& c) { c.far = kInf; })},
  };
  for (const auto& [argument, camera] : cameras)
    rejects("frustum_from_camera: " + argument, argument, [&] { return answerer::frustum_from_camera(camera); });

  Mat4 m = Mat4::Identity();
  m(1, 2) = kNaN;
  rejects("a NaN matrix entry", "view_projection", [&] { return answerer::frustum_from_matrix(m); });
  Mat4 flat = Mat4::Identity();
  flat.row(3) = flat.row(0);  // r3 - r0 = 0: no right plane
  rejects("a row combination with a zero normal", "right r3 - r0", [&] { return answerer::frustum_from_matrix(flat); });

  Frustum f = integer_pyramid();
  rejects("clip, a NaN vertex", "triangle.v0", [&] {
    return answerer::clip_triangle(Triangle{{kNaN, 0, 0}, {1, 0, 0}, {0, 1, 0}}, f);
  });
  f.planes[4].normal = Vec3::Zero();
  rejects("clip, a zero normal", "frustum.planes[4] (near)", [&] { return answerer::clip_triangle(t, f); });
  f = integer_pyramid();
  f.planes[5].offset = kNaN;
  rejects("clip, a NaN offset", "frustum.planes[5] (far).offset", [&] { return answerer::clip_triangle(t, f); });

  ColoredMesh mesh;
  mesh.mesh.vertices = {{0, 0, -2}, {1, 0, -2}, {0, 1, -2}};
  mesh.mesh.triangles = {{0, 1, 2}};
  mesh.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  ColoredMesh bad = mesh;
  bad.colors.pop_back();
  rejects("a vertex without a colour", "mesh.colors", [&] { return answerer::clip_mesh(bad, integer_pyramid()); });
  bad = mesh;
  bad.mesh.triangles[0][2] = 3;
  rejects("an index out of range", "mesh.mesh.triangles[0]",
          [&] { return answerer::clip_mesh(bad, integer_pyramid()); });
  bad = mesh;
  bad.mesh.vertices[1].y() = kInf;
  rejects("an infinite vertex", "mesh.mesh.vertices[1]", [&] { return answerer::clip_mesh(bad, integer_pyramid()); });
  bad = mesh;
  bad.colors[2].x() = kNaN;
  rejects("a NaN colour", "mesh.colors[2]", [&] { return answerer::clip_mesh(bad, integer_pyramid()); });
  Frustum g = integer_pyramid();
  g.planes[0].normal = Vec3::Zero();
  rejects("clip_mesh, a zero normal", "frustum.planes[0] (left)", [&] { return answerer::clip_mesh(mesh, g); });
}

namespace {

// The largest power of two that divides every number (0 when all are zero).
double common_power_of_two(const std::vector<double>& numbers) {
  int low = 2000;
  for (double x : numbers)
    if (x != 0) {
      int e = 0;
      std::frexp(x, &e);
      double m = x;
      int k = e - 53;  // x = integer * 2^k with a 53-bit integer: lower k while it stays one
      while (std::ldexp(m, -(k + 1)) == std::floor(std::ldexp(m, -(k + 1)))) ++k;
      low = std::min(low, k);
    }
  return low == 2000 ? 0.0 : std::ldexp(1.0, low);
}

// The header's exact domain (step 6): integer coordinates |x| <= 1024 and offsets
// |offset| <= 2^14, times one power of two, and integer normal components |n_i| <= 16.
// Then every plane value |d| <= 3 * 16 * 1024 + 2^14 = 2^16 (in units of that power of
// two), and the rule's largest sign, a 3x3 determinant of values, is below 6 * 2^48:
// an integer under 2^53, exact in doubles. (The handout's step 6 argument.)
void within_exact_domain(const std::vector<Vec3>& points, const std::vector<Plane>& planes) {
  std::vector<double> lengths;
  for (const Vec3& p : points) lengths.insert(lengths.end(), {p.x(), p.y(), p.z()});
  for (const Plane& p : planes) lengths.push_back(p.offset);
  const double unit = common_power_of_two(lengths);
  if (unit == 0) return;
  for (const Vec3& p : points) REQUIRE(p.cwiseAbs().maxCoeff() / unit <= 1024);
  for (const Plane& p : planes) {
    REQUIRE(std::abs(p.offset) / unit <= 16384);
    for (int i = 0; i < 3; ++i) REQUIRE((p.normal[i] == std::round(p.normal[i]) && std::abs(p.normal[i]) <= 16));
    for (const Vec3& x : points) REQUIRE(std::abs(p.value(x)) / unit <= 65536);
  }
}

}  // namespace

TEST_CASE("L01 step 6's input lies in the header's exact domain, where every sign is exact", "[lab01][contract]") {
  for (std::uint64_t i = 0; i < 2000; ++i) {
    const auto plane = gen::exact_triangle_plane()(rc::Random(3 * i + 1), 100).value();
    within_exact_domain({plane.triangle.v0, plane.triangle.v1, plane.triangle.v2}, {plane.plane});
    const auto frustum = gen::exact_triangle_frustum()(rc::Random(3 * i + 2), 100).value();
    within_exact_domain({frustum.triangle.v0, frustum.triangle.v1, frustum.triangle.v2},
                        {frustum.frustum.planes.begin(), frustum.frustum.planes.end()});
    const auto mesh = gen::exact_mesh_frustum()(rc::Random(3 * i + 3), 100).value();
    within_exact_domain(mesh.mesh.vertices, {mesh.frustum.planes.begin(), mesh.frustum.planes.end()});
  }
}
