// Lab 01 tests. Each step: the hand-worked examples of handouts/01_frustum_split.md,
// then random cases against the exact oracle (tests/01_frustum_split.judge.cpp).
#include "01_frustum_split.judge.h"
#include "common/oracle/clipping.h"
#include "frustum_split.h"

#include <algorithm>
#include <cmath>

using namespace labkit;
using namespace labkit::lab01;
using check::Expect;
using check::Outcome;
using judge::Rules;

namespace {

const double kHalfRoot2 = std::sqrt(0.5);

// The handout's plane z = 0, its normal pointing up: "in" is z >= 0.
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
  f.planes = {Plane{{1, 0, -1}, 0}, Plane{{-1, 0, -1}, 0}, Plane{{0, 1, -1}, 0},
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
    Expect e;
    const int expected = corners.size() >= 3 ? int(corners.size()) - 2 : 0;
    e.that("triangles", int(got.size()) == expected, std::to_string(got.size()), std::to_string(expected),
           corners.empty() ? "nothing is left, so no triangle is expected"
                           : "the polygon left has " + std::to_string(corners.size()) + " corners, so " +
                                 std::to_string(expected) + (expected == 1 ? " triangle is" : " triangles are") + " expected");
    double total = 0;
    for (const Triangle& t : got) total += t.area();
    e.near("area", total, area, 1e-12);
    // The same corners, no more and no fewer (within 1e-12).
    bool same = true;
    for (const Vec3& c : corners) same = same && has_point(got, c);
    for (const Triangle& t : got)
      for (int i = 0; i < 3; ++i)
        same = same && std::any_of(corners.begin(), corners.end(), [&](const Vec3& c) { return (t[i] - c).norm() <= 1e-12; });
    e.that("corners", same, describe(got), describe(corners), "the pieces' vertices must be the clipped polygon's corners");
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : judge(in, got);
  };
}

std::vector<Triangle> run_split(const TrianglePlane& in) { return split_triangle(in.triangle, in.plane); }
std::vector<Triangle> run_clip(const TriangleFrustum& in) { return clip_triangle(in.triangle, in.frustum); }
Outcome judge_split(const TrianglePlane& in, const std::vector<Triangle>& got) { return judge::split_triangle(in, got, Rules::exact); }
Outcome judge_clip(const TriangleFrustum& in, const std::vector<Triangle>& got) { return judge::clip_triangle(in, got, Rules::exact); }

auto split_gives(std::vector<Vec3> corners, double area) {
  return expect_polygon<TrianglePlane>(std::move(corners), area, run_split, judge_split);
}
auto clip_gives(std::vector<Vec3> corners, double area) {
  return expect_polygon<TriangleFrustum>(std::move(corners), area, run_clip, judge_clip);
}

Outcome expect_planes(const Frustum& got, const std::array<Plane, 6>& expected) {
  static const char* names[6] = {"left", "right", "bottom", "top", "near", "far"};
  Expect e;
  for (int i = 0; i < 6; ++i) {
    e.near(std::string(names[i]) + " normal", got.planes[std::size_t(i)].normal, expected[std::size_t(i)].normal, 1e-12);
    e.near(std::string(names[i]) + " offset", got.planes[std::size_t(i)].offset, expected[std::size_t(i)].offset, 1e-12);
  }
  return e.outcome();
}

// The planes of the square camera's frustum, unit normals.
std::array<Plane, 6> square_frustum_planes() {
  const double h = kHalfRoot2;
  return {Plane{{h, 0, -h}, 0}, Plane{{-h, 0, -h}, 0}, Plane{{0, h, -h}, 0},
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
template <class Case, class InDoubt>
Case moved_until_decisive(const Case& base, double points, InDoubt&& in_doubt) {
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
    return moved_until_decisive(c, scale_of({c.triangle.v0, c.triangle.v1, c.triangle.v2}), [](const TriangleFrustum& x, double tol) {
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

TEST_CASE("L01S1 signed distance and vertex classes: worked examples", "[lab01][step1]") {
  // z = 1 written with a normal of length 2: value = 2 z - 2, distance = z - 1.
  const Plane z1{{0, 0, 2}, -2};
  const auto distance = [](const Vec3& x, double expected) {
    return [=](const TrianglePlane& in) {
      Expect e;
      e.near("signed_distance", signed_distance(in.plane, x), expected, 1e-12);
      return e.outcome();
    };
  };
  const TrianglePlane on_z1{{{0, 0, 0}, {2, 0, 2}, {0, 2, 1}}, z1};
  check::example("signed_distance", "3 above z = 1 (normal of length 2)", on_z1, distance({3, 4, 4}, 3));
  check::example("signed_distance", "1 below z = 1", on_z1, distance({1, 1, 0}, -1));
  check::example("signed_distance", "a tilted plane: (1, 2, 2) . x - 3 at (1, 1, 1) is 2, over |n| = 3",
                 TrianglePlane{{}, Plane{{1, 2, 2}, -3}}, distance({1, 1, 1}, 2.0 / 3.0));
  check::example("classify", "out, in, on", on_z1, [](const TrianglePlane& in) {
    Expect e;
    e.equal("sides", classify(in.plane, in.triangle), std::array<Side, 3>{Side::out, Side::in, Side::on});
    return e.outcome();
  });
  check::example("classify", "2^-40 above the plane is in", TrianglePlane{{{0, 0, 1 + std::ldexp(1.0, -40)}, {1, 0, 1}, {0, 1, -3}}, z1},
                 [](const TrianglePlane& in) {
                   Expect e;
                   e.equal("sides", classify(in.plane, in.triangle), std::array<Side, 3>{Side::in, Side::on, Side::out});
                   return e.outcome();
                 });
}

TEST_CASE("L01S1 signed distance and vertex classes: random cases", "[lab01][step1][oracle]") {
  check::random_cases("signed_distance", decisive(gen::triangle_plane()), [](const TrianglePlane& in) {
    std::array<double, 3> got{};
    for (int i = 0; i < 3; ++i) got[std::size_t(i)] = signed_distance(in.plane, in.triangle[i]);
    return judge::signed_distance(in, got);
  });
  check::random_cases("classify", decisive(gen::triangle_plane()), [](const TrianglePlane& in) {
    return judge::classify(in, classify(in.plane, in.triangle));
  });
}

// ---- Step 2 ------------------------------------------------------------------------

TEST_CASE("L01S2 split a triangle by one plane: the four configurations", "[lab01][step2]") {
  const double full = 8 * std::sqrt(3.0);  // the area of (0,0,-1), (4,0,3), (0,4,3)
  check::example("split_triangle", "all in: keep", TrianglePlane{{{0, 0, 1}, {4, 0, 1}, {0, 4, 3}}, kFloor},
                 split_gives({{0, 0, 1}, {4, 0, 1}, {0, 4, 3}}, 4 * std::sqrt(5.0)));
  check::example("split_triangle", "none in: cull", TrianglePlane{{{0, 0, -1}, {4, 0, -1}, {0, 4, -3}}, kFloor}, split_gives({}, 0));
  check::example("split_triangle", "one in: one triangle", TrianglePlane{{{0, 0, -1}, {4, 0, -1}, {0, 4, 3}}, kFloor},
                 split_gives({{3, 1, 0}, {0, 4, 3}, {0, 1, 0}}, 4.5 * std::sqrt(2.0)));
  check::example("split_triangle", "two in: a quadrilateral, two triangles", TrianglePlane{{{0, 0, -1}, {4, 0, 3}, {0, 4, 3}}, kFloor},
                 split_gives({{1, 0, 0}, {4, 0, 3}, {0, 4, 3}, {0, 1, 0}}, full - std::sqrt(3.0) / 2));
}

TEST_CASE("L01S2 split a triangle by one plane: vertices on the plane", "[lab01][step2]") {
  check::example("split_triangle", "a vertex on the plane, the others in: keep",
                 TrianglePlane{{{0, 0, 0}, {4, 0, 1}, {0, 4, 1}}, kFloor}, split_gives({{0, 0, 0}, {4, 0, 1}, {0, 4, 1}}, 6 * std::sqrt(2.0)));
  check::example("split_triangle", "a vertex on the plane, one in, one out",
                 TrianglePlane{{{0, 0, 0}, {4, 0, -2}, {0, 4, 2}}, kFloor}, split_gives({{0, 0, 0}, {2, 2, 0}, {0, 4, 2}}, 2 * std::sqrt(6.0)));
  check::example("split_triangle", "touching at a vertex from below: cull",
                 TrianglePlane{{{0, 0, 0}, {4, 0, -1}, {0, 4, -1}}, kFloor}, split_gives({}, 0));
  check::example("split_triangle", "an edge on the plane, the third vertex below: cull",
                 TrianglePlane{{{0, 0, 0}, {4, 0, 0}, {0, 4, -1}}, kFloor}, split_gives({}, 0));
  check::example("split_triangle", "lying in the plane: keep", TrianglePlane{{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, kFloor},
                 split_gives({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, 8));
}

TEST_CASE("L01S2 split a triangle by one plane: random cases", "[lab01][step2][oracle]") {
  check::random_cases("split_triangle", decisive(gen::triangle_plane()), run_split_random);
}

// ---- Step 3 ------------------------------------------------------------------------

TEST_CASE("L01S3 the six frustum planes: worked examples", "[lab01][step3]") {
  check::example("frustum_from_camera", "at the origin, looking down -z, 90 degrees, near 1, far 3", square_camera(),
                 [](const Camera& in) { return expect_planes(frustum_from_camera(in), square_frustum_planes()); });
  Camera wide = square_camera();
  wide.eye = {0, 0, 5};
  wide.aspect = 2;
  check::example("frustum_from_camera", "eye (0, 0, 5), twice as wide as high", wide, [](const Camera& in) {
    const double a = 1 / std::sqrt(5.0), h = kHalfRoot2;
    return expect_planes(frustum_from_camera(in), {Plane{{a, 0, -2 * a}, 2 * std::sqrt(5.0)}, Plane{{-a, 0, -2 * a}, 2 * std::sqrt(5.0)},
                                                   Plane{{0, h, -h}, 5 * h}, Plane{{0, -h, -h}, 5 * h}, Plane{{0, 0, -1}, 4},
                                                   Plane{{0, 0, 1}, -2}});
  });
  Mat4 perspective;
  perspective << 1, 0, 0, 0,  //
      0, 1, 0, 0,             //
      0, 0, -2, -3,           //
      0, 0, -1, 0;
  check::example("frustum_from_matrix", "the square camera's perspective matrix", perspective,
                 [](const Mat4& in) { return expect_planes(frustum_from_matrix(in), square_frustum_planes()); });
  check::example("frustum_from_matrix", "the same matrix times 2: the same planes", Mat4(2 * perspective),
                 [](const Mat4& in) { return expect_planes(frustum_from_matrix(in), square_frustum_planes()); });
  Mat4 ortho;
  ortho << 0.5, 0, 0, 0,  //
      0, 1, 0, 0,         //
      0, 0, -0.5, -1.5,   //
      0, 0, 0, 1;
  check::example("frustum_from_matrix", "glOrtho(-2, 2, -1, 1, 1, 5): a box", ortho, [](const Mat4& in) {
    return expect_planes(frustum_from_matrix(in), {Plane{{1, 0, 0}, 2}, Plane{{-1, 0, 0}, 2}, Plane{{0, 1, 0}, 1},
                                                   Plane{{0, -1, 0}, 1}, Plane{{0, 0, -1}, -1}, Plane{{0, 0, 1}, 5}});
  });
}

TEST_CASE("L01S3 the six frustum planes: random cases", "[lab01][step3][oracle]") {
  check::random_cases("frustum_from_camera", judge::camera(), [](const Camera& in) {
    return judge::frustum_from_camera(in, frustum_from_camera(in));
  });
  check::random_cases("frustum_from_matrix", gen::view_projection_matrix(), [](const Mat4& in) {
    return judge::frustum_from_matrix(in, frustum_from_matrix(in));
  });
}

// ---- Step 4 ------------------------------------------------------------------------

TEST_CASE("L01S4 clip a triangle to the frustum: worked examples", "[lab01][step4]") {
  const Frustum f = [] {
    Frustum x;
    const auto planes = square_frustum_planes();
    std::copy(planes.begin(), planes.end(), x.planes.begin());
    return x;
  }();
  check::example("clip_triangle", "inside: keep", TriangleFrustum{{{0, 0, -2}, {0.5, 0, -2}, {0, 0.5, -2}}, f},
                 clip_gives({{0, 0, -2}, {0.5, 0, -2}, {0, 0.5, -2}}, 0.125));
  check::example("clip_triangle", "behind the camera: cull", TriangleFrustum{{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, f}, clip_gives({}, 0));
  check::example("clip_triangle", "from the eye: the near plane cuts off the tip",
                 TriangleFrustum{{{0, 0, 0}, {1, 0, -2}, {-1, 0, -2}}, f},
                 clip_gives({{0.5, 0, -1}, {1, 0, -2}, {-1, 0, -2}, {-0.5, 0, -1}}, 1.5));
  check::example("clip_triangle", "across the whole view at z = -2: the square |x|, |y| <= 2",
                 TriangleFrustum{{{-10, -10, -2}, {10, -10, -2}, {0, 10, -2}}, f},
                 clip_gives({{-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}}, 16));
}

TEST_CASE("L01S4 clip a triangle to the frustum: random cases", "[lab01][step4][oracle]") {
  check::random_cases("clip_triangle", decisive(gen::triangle_frustum()), run_clip_random);
}

// ---- Step 5 ------------------------------------------------------------------------

TEST_CASE("L01S5 clip a mesh, interpolate colours: worked examples", "[lab01][step5]") {
  // The square [-4, 0] x [-1, 1] at z = -2, red on its left side and green on its right;
  // the left plane x = -2 cuts it in half, where the colour is (0.5, 0.5, 0).
  MeshFrustum in;
  in.mesh.vertices = {{-4, -1, -2}, {0, -1, -2}, {0, 1, -2}, {-4, 1, -2}};
  in.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  in.colors = {{1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {1, 0, 0}};
  in.frustum = integer_pyramid();
  check::example("clip_mesh", "a square cut in half by the left plane", in, [](const MeshFrustum& in) {
    const ClippedMesh got = clip_mesh(colored(in), in.frustum);
    Expect e;
    e.equal("triangles", int(got.mesh.size()), 3);
    e.that("colours", got.colors.size() == got.mesh.vertices.size(), std::to_string(got.colors.size()),
           std::to_string(got.mesh.vertices.size()), "every vertex needs a colour, the new cut points included");
    double area = 0;
    for (std::size_t k = 0; k < got.mesh.size(); ++k) area += got.mesh.triangle(k).area();
    e.near("area", area, 4, 1e-12);
    if (got.source.size() == got.mesh.size()) {
      e.equal("pieces of triangle 0", int(std::count(got.source.begin(), got.source.end(), 0)), 2);
      e.equal("pieces of triangle 1", int(std::count(got.source.begin(), got.source.end(), 1)), 1);
    }
    for (const auto& face : got.mesh.triangles)
      for (int i : face)
        if (i >= 0 && std::size_t(i) < got.mesh.vertices.size() && got.mesh.vertices[std::size_t(i)].x() == -2 &&
            std::size_t(i) < got.colors.size())
          e.near("colour at " + fmt(got.mesh.vertices[std::size_t(i)]), got.colors[std::size_t(i)], Vec3(0.5, 0.5, 0), 1e-12);
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : judge::clip_mesh(in, got, Rules::exact);
  });
}

TEST_CASE("L01S5 clip a mesh, interpolate colours: random cases", "[lab01][step5][oracle]") {
  check::random_cases("clip_mesh", decisive(gen::mesh_frustum()), [](const MeshFrustum& in) {
    return judge::clip_mesh(in, clip_mesh(colored(in), in.frustum));
  });
}

// ---- Step 6: robustness --------------------------------------------------------------
// Exact input: integer coordinates and plane coefficients. The header's rules hold exactly.

TEST_CASE("L01S6 robustness: vertices, edges and triangles on frustum planes", "[lab01][step6]") {
  const Frustum f = integer_pyramid();
  const std::string q = "robust.clip_triangle";
  check::example(q, "an edge through the line where the left and near planes meet",
                 TriangleFrustum{{{-2, 0, 0}, {0, 0, -2}, {0, 1, -2}}, f},
                 clip_gives({{-1, 0, -1}, {0, 0, -2}, {0, 1, -2}, {-1, 0.5, -1}}, 0.75 * std::sqrt(2.0)));
  check::example(q, "touching that line from outside: cull", TriangleFrustum{{{-1, -0.5, -1}, {-1, 0.5, -1}, {-2, 0, 0}}, f},
                 clip_gives({}, 0));
  check::example(q, "touching the corner (1, 1, -1) from outside: cull", TriangleFrustum{{{1, 1, -1}, {2, 2, 0}, {2, 0, 0}}, f},
                 clip_gives({}, 0));
  check::example(q, "lying in the near plane: the part in the face", TriangleFrustum{{{0, 0, -1}, {3, 0, -1}, {0, 3, -1}}, f},
                 clip_gives({{0, 0, -1}, {1, 0, -1}, {1, 1, -1}, {0, 1, -1}}, 1));
  check::example(q, "in the near plane, beside the face: cull", TriangleFrustum{{{2, 2, -1}, {5, 2, -1}, {2, 5, -1}}, f},
                 clip_gives({}, 0));
  check::example(q, "a cut point that no double holds, exactly on the bottom plane",
                 TriangleFrustum{{{-2, -2, -1}, {0, 0, -2}, {0, 1, -3}}, f},
                 clip_gives({{-4.0 / 3, -4.0 / 3, -4.0 / 3}, {0, 0, -2}, {0, 1, -3}, {-1.5, -1.25, -1.5}}, 1.375));
  check::example(q, "crossing the left plane a third of the way along, exactly on the near plane",
                 TriangleFrustum{{{-2, 0, 0}, {1, 0, -3}, {1, 1, -3}}, f},
                 clip_gives({{-1, 0, -1}, {1, 0, -3}, {1, 1, -3}, {-1, 1.0 / 3, -1}}, 4 * std::sqrt(2.0) / 3));
}

TEST_CASE("L01S6 robustness: random exact degenerate cases", "[lab01][step6][oracle]") {
  check::random_cases("robust.classify", gen::exact_triangle_plane(), [](const TrianglePlane& in) {
    return judge::classify(in, classify(in.plane, in.triangle), Rules::exact);
  });
  check::random_cases("robust.split_triangle", gen::exact_triangle_plane(), [](const TrianglePlane& in) {
    return judge::split_triangle(in, run_split(in), Rules::exact);
  });
  check::random_cases("robust.clip_triangle", gen::exact_triangle_frustum(), [](const TriangleFrustum& in) {
    return judge::clip_triangle(in, run_clip(in), Rules::exact);
  });
  check::random_cases("robust.clip_mesh", gen::exact_mesh_frustum(), [](const MeshFrustum& in) {
    return judge::clip_mesh(in, clip_mesh(colored(in), in.frustum), Rules::exact);
  });
}
