#include "02_segment_triangle/queries.h"

#include "common/generators/needles.h"
#include "common/harness/check.h"

#include <cmath>

namespace labkit::gen {

rc::Gen<lab02::PointTriangle> point_triangle() {
  return rc::gen::exec([] {
    const double s = *wide_scale();
    const Triangle t = *any_triangle(s);
    // x = v0 + alpha e1 + beta e2 with dyadic alpha, beta: exactly in the plane. Near an
    // edge, a few units of 2^-bits off it (2^-20 of a height: far outside the band, unless
    // the triangle is a needle); exactly on one only now and then (the robustness step's).
    const int bits = *rc::gen::element(3, 10, 20);
    const double unit = std::ldexp(1.0, -bits);
    const auto off = [] { return *rc::gen::weightedElement<int>({{1, 0}, {3, 1}, {3, -1}, {2, 2}, {2, -2}}); };
    const auto near = [&](int base) { return base * std::ldexp(1.0, bits - 3) + off(); };
    const auto weight = [&] {
      return *rc::gen::oneOf(rc::gen::just(near(*rc::gen::inRange(-4, 13))), rc::gen::just(double(*integer(1 << 12)))) *
             unit;
    };
    const double alpha = weight();
    // Sometimes near the edge v1 v2 (alpha + beta = 1).
    const double beta = *rc::gen::element(0, 1) ? 1.0 - alpha + off() * unit : weight();
    return lab02::PointTriangle{t.v0 + alpha * (t.v1 - t.v0) + beta * (t.v2 - t.v0), t};
  });
}

rc::Gen<lab02::PointTriangle> exact_point_triangle() {
  return rc::gen::exec([] {
    const double s = 8 * *scale();
    const Triangle t{*lattice_point(s), *lattice_point(s), *lattice_point(s)};
    // (p v0 + q v1 + r v2) / 8 with p + q + r = 8: vertices, edges and inside, plus
    // points just outside an edge (one weight -1/8).
    const int p = *rc::gen::inRange(-1, 10);
    const int q = *rc::gen::inRange(-1, 10 - p);
    const int r = 8 - p - q;
    return lab02::PointTriangle{(p * t.v0 + q * t.v1 + r * t.v2) / 8.0, t};
  });
}

rc::Gen<lab02::MovingMesh> moving_mesh() {
  return rc::gen::exec([] {
    const SegmentMeshPair base = *decisive_segment_mesh();
    const double s = check::scale_of_input(base);
    const RigidTransform m0 = *rigid_transform(s);
    const RigidTransform m1 = *rc::gen::oneOf(rc::gen::just(m0), rigid_transform(s));
    // The segment was aimed at the mesh in its own frame; place it in the world at m0/m1.
    return lab02::MovingMesh{{m0 * base.segment.a, m1 * base.segment.b}, base.mesh, m0, m1};
  });
}

namespace {

// A point of the unit-ish cube [-1, 1]^3 on a 1/8 lattice.
rc::Gen<Vec3> eighth_point() {
  return rc::gen::exec([]() -> Vec3 { return Vec3(*integer(8), *integer(8), *integer(8)) / 8.0; });
}

// A small mesh within distance sqrt(3) of the origin: a tetrahedron, a tent (two
// triangles on a shared edge) or one triangle; its faces have non-zero area.
Mesh small_mesh() {
  const int shape = *rc::gen::weightedElement<int>({{5, 0}, {3, 1}, {2, 2}});
  const int count = shape == 0 ? 4 : shape == 1 ? 4 : 3;
  Mesh m;
  for (;;) {
    m.vertices.clear();
    for (int i = 0; i < count; ++i) m.vertices.push_back(*eighth_point());
    const Vec3 e1 = m.vertices[1] - m.vertices[0], e2 = m.vertices[2] - m.vertices[0];
    const bool flat = e1.cross(e2).squaredNorm() < 1.0 / 64;
    const bool thin = count == 4 && std::abs(e1.cross(e2).dot(m.vertices[3] - m.vertices[0])) < 1.0 / 16;
    if (!flat && !thin) break;
  }
  if (shape == 0)
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  else if (shape == 1)
    m.triangles = {{0, 1, 2}, {0, 3, 1}};
  else
    m.triangles = {{0, 1, 2}};
  return m;
}

// A point of the mesh: a vertex, a point inside an edge, or inside a face, and the
// feature's kind (0 vertex, 1 edge, 2 face).
Vec3 feature_point(const Mesh& m, int kind) {
  const auto& tri = m.triangles[std::size_t(*rc::gen::inRange<int>(0, int(m.triangles.size())))];
  const Vec3 v0 = m.vertices[std::size_t(tri[0])], v1 = m.vertices[std::size_t(tri[1])],
             v2 = m.vertices[std::size_t(tri[2])];
  if (kind == 0) return v0;
  // On an edge at an odd sixteenth, 3/16 to 13/16 from either end: never at a time t0 of
  // the aim below, since the swept parallelogram's diagonal (u = t) is an exact
  // degeneracy, the robustness step's.
  if (kind == 1) return v0 + (2 * *rc::gen::inRange(1, 7) + 1) / 16.0 * (v1 - v0);
  const double u = *rc::gen::inRange(1, 8) / 8.0;
  const double w = *rc::gen::inRange(1, 9 - int(8 * u)) / 8.0 * (1 - u);
  return v0 + u * (v1 - v0) + w * (v2 - v0);
}

// A point of a feature of the mesh for exact aims: a vertex (0), a point of an edge at a
// sixteenth of its length, ends and middle included (1), or a point of a face (2).
Vec3 exact_feature_point(const Mesh& m, int kind) {
  const auto& tri = m.triangles[std::size_t(*rc::gen::inRange<int>(0, int(m.triangles.size())))];
  const int first = *rc::gen::inRange(0, 3);
  const Vec3 v0 = m.vertices[std::size_t(tri[std::size_t(first)])],
             v1 = m.vertices[std::size_t(tri[std::size_t((first + 1) % 3)])],
             v2 = m.vertices[std::size_t(tri[std::size_t((first + 2) % 3)])];
  if (kind == 0) return v0;
  if (kind == 1) return v0 + *rc::gen::element(0, 1, 8, 8, 16, *rc::gen::inRange(1, 16)) / 16.0 * (v1 - v0);
  const int u = *rc::gen::inRange(0, 9), w = *rc::gen::inRange(0, 9 - u);
  return v0 + u / 8.0 * (v1 - v0) + w / 8.0 * (v2 - v0);
}

// One triangle in the plane z = 0 with integer corners within 8 of the origin, not thin.
Mesh flat_triangle() {
  Mesh m;
  m.triangles = {{0, 1, 2}};
  for (;;) {
    m.vertices.clear();
    for (int i = 0; i < 3; ++i) m.vertices.emplace_back(*integer(8), *integer(8), 0);
    const Vec3 e1 = m.vertices[1] - m.vertices[0], e2 = m.vertices[2] - m.vertices[0];
    if (std::abs(e1.cross(e2).z()) >= 8) return m;
  }
}

}  // namespace

rc::Gen<lab02::MovingMeshes> exact_moving_meshes() {
  return rc::gen::exec([] {
    lab02::MovingMeshes in;
    // Both within 8 sqrt(3) < 14 of their centres; B's centre an integer vector at least
    // 32 from A's: apart at t = 0, as the header requires.
    const bool flat = *rc::gen::element(0, 0, 0, 1);
    const auto mesh = [flat] {
      if (flat) return flat_triangle();
      Mesh m = small_mesh();
      for (Vec3& v : m.vertices) v *= 8;  // the 1/8 lattice, on integers
      return m;
    };
    in.a = mesh();
    in.b = mesh();
    Vec3 dir(*integer(4), *integer(4), flat ? 0 : *integer(4));
    if (dir == Vec3::Zero()) dir = Vec3(1, 0, 0);
    const Vec3 offset = dir * std::ceil(32 / dir.norm());
    for (Vec3& v : in.b.vertices) v += offset;
    // A feature of A aimed at a feature of B, to meet exactly at t0 (t0 = 1: at the end
    // of the frame; t0 = 2: exactly stopping short); a face onto a face only rarely.
    const int kind_a = *rc::gen::element(0, 0, 1, 1, 2), kind_b = *rc::gen::element(0, 1, 1, 2, 2);
    const Vec3 x_a = exact_feature_point(in.a, kind_a), x_b = exact_feature_point(in.b, kind_b);
    const double t0 = *rc::gen::weightedElement<double>({{3, 0.25}, {4, 0.5}, {4, 1.0}, {1, 2.0}});
    in.velocity_b = *rc::gen::element(0, 1) ? Vec3::Zero() : Vec3(*integer(8), *integer(8), flat ? 0 : *integer(8));
    in.velocity_a = *rc::gen::element(0, 0, 0, 0, 0, 0, 0, 0, 0, 1) ? in.velocity_b  // no relative motion
                                                                    : Vec3((x_b - x_a) / t0 + in.velocity_b);
    if (*rc::gen::element(0, 1)) {  // B moves onto A instead
      std::swap(in.a, in.b);
      std::swap(in.velocity_a, in.velocity_b);
    }
    const double s = *scale();
    for (Vec3& v : in.a.vertices) v *= s;
    for (Vec3& v : in.b.vertices) v *= s;
    in.velocity_a *= s, in.velocity_b *= s;
    return in;
  });
}

rc::Gen<lab02::MovingMeshes> moving_meshes() {
  return rc::gen::exec([] {
    const double s = *wide_scale();
    lab02::MovingMeshes in;
    in.a = small_mesh();
    in.b = small_mesh();
    // B sits 4 to 6 units away in a random direction: apart at t = 0.
    Vec3 dir(*integer(4), *integer(4), *integer(4));
    if (dir == Vec3::Zero()) dir = Vec3(1, 0, 0);
    const Vec3 centre = dir.normalized() * (4 + *rc::gen::inRange(0, 3));
    for (Vec3& v : in.b.vertices) v += centre;
    // Aim: a vertex of A at a face of B, a vertex of B at a face of A, or an edge at an
    // edge, to meet at t0; t0 > 1 stops short. Sometimes the aim is nudged a little
    // beside the feature (1e-6 to 1e-3 of the size: far outside the ambiguity band).
    const int family = *rc::gen::inRange(0, 3);
    const Vec3 x_a = feature_point(in.a, family == 0 ? 0 : family == 1 ? 2 : 1);
    const Vec3 x_b = feature_point(in.b, family == 0 ? 2 : family == 1 ? 0 : 1);
    const double t0 =
        *rc::gen::weightedElement<double>({{6, 0.25}, {6, 0.5}, {6, 0.75}, {3, 0.9375}, {3, 1.25}, {2, 2.0}});
    Vec3 nudge = Vec3::Zero();
    if (*rc::gen::element(0, 0, 1)) nudge = Vec3(*integer(4), *integer(4), *integer(4)) * *tiny(10, 20);
    const Vec3 d = (x_b + nudge - x_a) / t0;
    const Vec3 velocity_b = *rc::gen::element(0, 1) ? Vec3::Zero() : Vec3(*integer(8), *integer(8), *integer(8));
    in.velocity_b = velocity_b;
    in.velocity_a = *rc::gen::element(0, 0, 0, 0, 0, 0, 0, 0, 0, 1)
                        ? velocity_b
                        : Vec3(d + velocity_b);  // now and then: no relative motion
    for (Vec3& v : in.a.vertices) v *= s;
    for (Vec3& v : in.b.vertices) v *= s;
    in.velocity_a *= s, in.velocity_b *= s;
    return in;
  });
}

}  // namespace labkit::gen
