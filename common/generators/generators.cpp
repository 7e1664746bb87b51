#include "common/generators/generators.h"
#include "common/generators/grid.h"
#include "common/generators/meshes.h"

#include <cmath>
#include <utility>

namespace labkit::gen {

namespace {

constexpr double kFraction = 1.0 / (1 << 20);

// Where a family draws its points: the fine dyadic lattice, or (exact) integers that
// are multiples of 8 with |x| <= 1024, times a power of two. Multiples of 8 keep every
// p/8 combination below an integer, and on such input a careful double computation
// decides every sign exactly.
rc::Gen<Vec3> grid_point(Grid g) { return g.exact ? lattice_point(8 * g.s, 16) : point(g.s); }
rc::Gen<Vec3> grid_direction(Grid g) { return direction(g.exact ? 8 * g.s : g.s, 8); }
rc::Gen<Triangle> grid_triangle(Grid g) {
  return rc::gen::suchThat(rc::gen::exec([g] {
                             return Triangle{*grid_point(g), *grid_point(g), *grid_point(g)};
                           }),
                           [](const Triangle& t) { return t.normal() != Vec3::Zero(); });
}

// p/8: every constructed point stays on a dyadic grid, so it is exact in doubles.
Vec3 eighths(const Vec3& origin, const Vec3& u, int p, const Vec3& v, int q) {
  return origin + (p / 8.0) * u + (q / 8.0) * v;
}

Vec3 triangle_normal(const Triangle& t) { return t.normal(); }

// A lattice vector lying in the triangle's plane, rotated a quarter turn from an edge:
// points across the edge (v_i, v_j), inward or outward.
Vec3 in_plane_across(const Triangle& t, int i) {
  const Vec3 edge = t[(i + 1) % 3] - t[i];
  return triangle_normal(t).cross(edge);
}

rc::Gen<SegmentTrianglePair> generic() {
  return rc::gen::exec([] {
    const Grid g = *grid(false);
    return SegmentTrianglePair{{*grid_point(g), *grid_point(g)}, *grid_triangle(g)};
  });
}

// The segment crosses the plane inside the triangle (or exactly on its boundary).
rc::Gen<SegmentTrianglePair> crossing(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Triangle t = *grid_triangle(g);
    const Vec3 x = *point_in_triangle(t);
    const Vec3 d = *grid_direction(g);
    const int k = *rc::gen::inRange(1, 17);
    return SegmentTrianglePair{{x + d, x - (k / 8.0) * d}, t};
  });
}

// A small triangle (edges of one or two units of the scale, so about 1e-6 at the smallest
// scale) crossed near its middle: areas near 1e-12 catch fuzzy zero tests.
rc::Gen<SegmentTrianglePair> small_crossing() {
  return rc::gen::exec([] {
    const double s = *scale();
    const Triangle t =
        *rc::gen::suchThat(rc::gen::exec([s] {
                             return Triangle{*lattice_point(s, 1), *lattice_point(s, 1), *lattice_point(s, 1)};
                           }),
                           [](const Triangle& tri) { return tri.normal() != Vec3::Zero(); });
    const Vec3 x = *point_in_triangle(t);
    const Vec3 d = *direction(s, 2);
    return SegmentTrianglePair{{x + d, x - d}, t};
  });
}

// Exactly through a vertex, or exactly through a point of an edge.
rc::Gen<SegmentTrianglePair> through_feature(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Triangle t = *grid_triangle(g);
    const int i = *rc::gen::inRange(0, 3);
    const int m = *rc::gen::inRange(0, 9);  // m = 0: the vertex itself
    const Vec3 x = eighths(t[i], t[(i + 1) % 3] - t[i], m, Vec3::Zero(), 0);
    const Vec3 d = *grid_direction(g);
    const int k = *rc::gen::inRange(1, 17);
    return SegmentTrianglePair{{x + d, x - (k / 8.0) * d}, t};
  });
}

// One end exactly on the closed triangle, the other anywhere.
rc::Gen<SegmentTrianglePair> touching(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Triangle t = *grid_triangle(g);
    const Vec3 x = *point_in_triangle(t);
    const Vec3 other = x + *grid_direction(g);
    return *rc::gen::element(SegmentTrianglePair{{x, other}, t}, SegmentTrianglePair{{other, x}, t});
  });
}

// Both ends in the triangle's plane: crossing it, inside it, along an edge's line, or
// missing it.
rc::Gen<SegmentTrianglePair> coplanar(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Triangle t = *grid_triangle(g);
    const Vec3 u = t.v1 - t.v0, v = t.v2 - t.v0;
    const bool along_edge = *rc::gen::inRange(0, 4) == 0;
    const int p0 = *rc::gen::inRange(-8, 17), q0 = along_edge ? 0 : *rc::gen::inRange(-8, 17);
    const int p1 = *rc::gen::inRange(-8, 17), q1 = along_edge ? 0 : *rc::gen::inRange(-8, 17);
    return SegmentTrianglePair{{eighths(t.v0, u, p0, v, q0), eighths(t.v0, u, p1, v, q1)}, t};
  });
}

// Coplanar, then lifted off the plane by a tiny amount at one or both ends.
rc::Gen<SegmentTrianglePair> near_parallel() {
  return rc::gen::exec([] {
    SegmentTrianglePair c = *coplanar(false);
    const Vec3 n = c.triangle.normal().normalized();
    const double size = scale_of({c.triangle.v0, c.triangle.v1, c.triangle.v2});
    c.segment.a += *integer(4) * *tiny(20, 50) * size * n;
    c.segment.b += *integer(4) * *tiny(20, 50) * size * n;
    return c;
  });
}

// Crossing the plane a tiny distance inside or outside an edge or a vertex.
rc::Gen<SegmentTrianglePair> near_edge() {
  return rc::gen::exec([] {
    SegmentTrianglePair c = *through_feature(false);
    const int i = *rc::gen::inRange(0, 3);
    const Vec3 across = in_plane_across(c.triangle, i).normalized();
    const double size = scale_of({c.triangle.v0, c.triangle.v1, c.triangle.v2});
    const Vec3 shift = *integer(4) * *tiny(20, 50) * size * across;
    c.segment.a += shift;
    c.segment.b += shift;
    return c;
  });
}

// a == b, on the triangle or not.
rc::Gen<SegmentTrianglePair> zero_length(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Triangle t = *grid_triangle(g);
    const Vec3 x = *rc::gen::oneOf(point_in_triangle(t), grid_point(g));
    return SegmentTrianglePair{{x, x}, t};
  });
}

rc::Gen<SegmentTrianglePair> zero_area(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Vec3 a = *grid_point(g), b = *grid_point(g);
    const Vec3 c = eighths(a, b - a, *rc::gen::inRange(-8, 17), Vec3::Zero(), 0);
    const Triangle t = *rc::gen::element(Triangle{a, b, c}, Triangle{a, a, b}, Triangle{a, a, a});
    const Vec3 x = eighths(t.v0, t.v1 - t.v0, *rc::gen::inRange(0, 9), Vec3::Zero(), 0);
    const Vec3 d = *grid_direction(g);
    return *rc::gen::element(SegmentTrianglePair{{x + d, x - d}, t}, SegmentTrianglePair{{x, x}, t},
                             SegmentTrianglePair{{*grid_point(g), *grid_point(g)}, t});
  });
}

// The size far_away() moves a case by multiples of: the triangle's, at least 1.
double triangle_size(const SegmentTrianglePair& c) {
  return std::max(1.0, scale_of({c.triangle.v0, c.triangle.v1, c.triangle.v2}));
}

// A lattice terrain of n x n cells: heights on the lattice, so segments through grid
// points cross shared edges and vertices exactly.
rc::Gen<Mesh> terrain(double s) {
  return rc::gen::exec([s] {
    const int n = *rc::gen::inRange(1, 5);
    Mesh m;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) m.vertices.push_back(s * Vec3(i, j, *integer(3)));
    m.triangles = grid_triangles(n);
    return m;
  });
}

rc::Gen<Mesh> soup(double s) {
  return rc::gen::exec([s] {
    const int n = *rc::gen::inRange(1, 13);
    Mesh m;
    for (int i = 0; i < n; ++i) {
      const Triangle t = *rc::gen::weightedOneOf<Triangle>({{9, triangle(s)}, {1, degenerate_triangle(s)}});
      const int base = int(m.vertices.size());
      m.vertices.insert(m.vertices.end(), {t.v0, t.v1, t.v2});
      m.triangles.push_back({base, base + 1, base + 2});
    }
    return m;
  });
}

rc::Gen<Mesh> octahedron(double s) {
  return rc::gen::exec([s] {
    const Vec3 c = *lattice_point(s, 4);
    const double r = s * *rc::gen::inRange(1, 9);
    Mesh m;
    m.vertices = {c + Vec3(r, 0, 0), c - Vec3(r, 0, 0), c + Vec3(0, r, 0),
                  c - Vec3(0, r, 0), c + Vec3(0, 0, r), c - Vec3(0, 0, r)};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
  });
}

}  // namespace

rc::Gen<int> integer(int magnitude) {
  // Zig-zag order 0, 1, -1, 2, -2, ...: shrinking the index shrinks toward zero.
  return rc::gen::map(rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 2 * magnitude + 1)),
                      [](int k) { return k % 2 == 1 ? (k + 1) / 2 : -(k / 2); });
}

rc::Gen<Grid> grid(bool exact) { return grid(exact, scale()); }
rc::Gen<Grid> grid(bool exact, rc::Gen<double> scales) {
  return rc::gen::map(std::move(scales), [exact](double s) { return Grid{s, exact}; });
}

void translate(SegmentTrianglePair& c, const Vec3& offset) {
  c.segment.a += offset;
  c.segment.b += offset;
  for (int i = 0; i < 3; ++i) c.triangle[i] += offset;
}

rc::Gen<double> scale() {
  return rc::gen::weightedElement<double>({{12, 1.0},
                                           {2, std::ldexp(1.0, -10)},
                                           {2, std::ldexp(1.0, 10)},
                                           {1, std::ldexp(1.0, -20)},
                                           {1, std::ldexp(1.0, 20)}});
}

rc::Gen<double> tiny(int kmin, int kmax) {
  return rc::gen::map(rc::gen::resize(rc::kNominalSize, rc::gen::inRange(kmin, kmax + 1)),
                      [](int k) { return std::ldexp(1.0, -k); });
}

rc::Gen<Vec3> lattice_point(double s, int magnitude) {
  return rc::gen::exec(
      [s, magnitude]() -> Vec3 { return Vec3(*integer(magnitude), *integer(magnitude), *integer(magnitude)) * s; });
}

rc::Gen<Vec3> point(double s) {
  return rc::gen::exec([s] {
    Vec3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = (*integer(16) + kFraction * *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 1 << 20))) * s;
    return p;
  });
}

rc::Gen<Vec3> direction(double s, int magnitude) {
  return rc::gen::suchThat(lattice_point(s, magnitude), [](const Vec3& d) { return d != Vec3::Zero(); });
}

rc::Gen<Vec3> point_in_triangle(const Triangle& t) {
  return rc::gen::exec([t] {
    const int p = *rc::gen::inRange(0, 9);
    const int q = *rc::gen::inRange(0, 9 - p);
    const int r = 8 - p - q;
    return Vec3((p * t.v0 + q * t.v1 + r * t.v2) / 8.0);
  });
}

rc::Gen<Triangle> triangle(double s) {
  return rc::gen::suchThat(rc::gen::exec([s] {
                             return Triangle{*point(s), *point(s), *point(s)};
                           }),
                           [](const Triangle& t) { return t.normal() != Vec3::Zero(); });
}

rc::Gen<Triangle> degenerate_triangle(double s) {
  return rc::gen::exec([s] {
    const Vec3 a = *point(s), b = *point(s);
    const int k = *rc::gen::inRange(-8, 17);
    const Vec3 c = eighths(a, b - a, k, Vec3::Zero(), 0);
    return *rc::gen::element(Triangle{a, b, c}, Triangle{a, a, b}, Triangle{a, a, a});
  });
}

rc::Gen<SegmentTrianglePair> segment_triangle() {
  const rc::Gen<SegmentTrianglePair> families = rc::gen::weightedOneOf<SegmentTrianglePair>({
      {3, generic()},
      {3, crossing(false)},
      {1, small_crossing()},
      {2, through_feature(false)},
      {1, touching(false)},
      {2, coplanar(false)},
      {2, near_parallel()},
      {2, near_edge()},
      {1, zero_length(false)},
      {1, zero_area(false)},
  });
  return rc::gen::weightedOneOf<SegmentTrianglePair>(
      {{7, families}, {1, far_away(families, translate, triangle_size)}});
}

rc::Gen<SegmentTrianglePair> typical_segment_triangle() {
  // Crossing through a random point inside (20-bit weights, never exactly on an edge).
  const rc::Gen<SegmentTrianglePair> through = rc::gen::exec([] {
    const double s = *scale();
    const Triangle t = *triangle(s);
    const int i = *rc::gen::inRange(1, (1 << 20) - 1);
    const int j = *rc::gen::inRange(1, (1 << 20) - i);
    const Vec3 x = t.v0 + std::ldexp(i, -20) * (t.v1 - t.v0) + std::ldexp(j, -20) * (t.v2 - t.v0);
    const Vec3 d = *point(s);
    return SegmentTrianglePair{{x + d, x - 0.5 * d}, t};
  });
  return rc::gen::weightedOneOf<SegmentTrianglePair>({{1, generic()}, {1, through}});
}

rc::Gen<SegmentTrianglePair> exact_segment_triangle() {
  return rc::gen::weightedOneOf<SegmentTrianglePair>({
      {2, crossing(true)},
      {3, through_feature(true)},
      {2, touching(true)},
      {3, coplanar(true)},
      {1, zero_length(true)},
      {1, zero_area(true)},
  });
}

rc::Gen<Mesh> mesh(double s) {
  return rc::gen::weightedOneOf<Mesh>({{2, soup(s)}, {2, terrain(s)}, {1, octahedron(s)}});
}

rc::Gen<SegmentMeshPair> exact_segment_mesh() {
  return rc::gen::exec([] {
    const double s = 8 * *scale();
    const Mesh m = *terrain(s);
    // Through a grid vertex, the middle of a grid edge, or a cell's diagonal, from above
    // or along the surface.
    const int n = int(m.size());
    const Triangle t = m.triangle(std::size_t(*rc::gen::inRange(0, n)));
    const int i = *rc::gen::inRange(0, 3);
    const int k = *rc::gen::inRange(0, 3);  // 0: vertex, 1: mid-edge, 2: a quarter along
    const Vec3 x = k == 0 ? t[i] : (k == 1 ? Vec3((t[i] + t[(i + 1) % 3]) / 2) : Vec3((3 * t[i] + t[(i + 1) % 3]) / 4));
    const Vec3 d = *rc::gen::oneOf(direction(8 * s, 4), rc::gen::just(Vec3(t[(i + 1) % 3] - t[i])));
    return SegmentMeshPair{{x + d, x - d}, m};
  });
}

rc::Gen<SegmentMeshPair> segment_mesh() {
  return rc::gen::exec([] {
    const double s = *scale();
    const Mesh m = *mesh(s);
    // Aim at a point of some triangle half the time: hits are rarer than misses otherwise.
    Segment seg{*point(s), *point(s)};
    if (*rc::gen::inRange(0, 2) == 0 && m.size() > 0) {
      const Triangle t = m.triangle(std::size_t(*rc::gen::inRange(0, int(m.size()))));
      const Vec3 x = *point_in_triangle(t);
      const Vec3 d = *direction(s);
      seg = {x + d, x - (*rc::gen::inRange(1, 17) / 8.0) * d};
    }
    return SegmentMeshPair{seg, m};
  });
}

rc::Gen<RigidTransform> rigid_transform(double s) {
  return rc::gen::exec([s] {
    Eigen::Quaterniond q(*integer(4), *integer(4), *integer(4), *integer(4));
    if (q.squaredNorm() == 0) q = Eigen::Quaterniond::Identity();
    RigidTransform m = RigidTransform::Identity();
    m.linear() = q.normalized().toRotationMatrix();
    m.translation() = *lattice_point(s, 8);
    return m;
  });
}

}  // namespace labkit::gen
