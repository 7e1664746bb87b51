#include "common/generators/generators.h"
#include "01_frustum_split/judge.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

namespace labkit::gen {

namespace {

Triangle wound(Triangle t);

// An exponent for the scale extremes: 2^-100 to 2^-60 or 2^60 to 2^100 (about 1e-30 to
// 1e-18 and 1e18 to 1e30), toward the ends of the header's domain.
int signed_extreme() { return *rc::gen::element(-1, 1) * *rc::gen::inRange(60, 101); }

// The exponent e, moved toward 0 as far as needed for every non-zero value times 2^e to
// stay inside 2^-100 to 2^100, the scale families' ends (the header's domain reaches
// 2^-130 and 2^130: room for what a case builds on them). Values spread wider (an offset
// left near 0 by rounding) are not scaled at all.
int inside_domain(int e, const std::vector<double>& values) {
  int low = -100000, high = 100000;
  for (double v : values)
    if (v != 0 && std::isfinite(v)) {
      low = std::max(low, -100 - std::ilogb(v));
      high = std::min(high, 99 - std::ilogb(v));
    }
  return low > high ? 0 : std::clamp(e, low, high);
}
std::vector<double> components(std::initializer_list<Vec3> vs, std::initializer_list<double> xs = {}) {
  std::vector<double> out(xs);
  for (const Vec3& v : vs) out.insert(out.end(), {v.x(), v.y(), v.z()});
  return out;
}

// The same plane with its coefficients times k: normals up to 2 become up to 16, the
// edge of lab 01's exact domain (|n_i| <= 16, |offset| <= 2^14 times the lattice unit).
Plane longer(const Plane& p, int k) { return {double(k) * p.normal, double(k) * p.offset}; }

// ---- One plane ---------------------------------------------------------------------
// A plane with an integer normal n through a lattice point o, and two lattice vectors
// u, w spanning it: every o + i u + j w with dyadic i, j lies exactly on it, and
// o + i u + j w + h n is h |n|^2 away in value.
struct PlaneFrame {
  Plane plane;
  Vec3 origin, u, w, n;
};

rc::Gen<PlaneFrame> plane_frame(double s, bool exact) {
  return rc::gen::exec([s, exact] {
    const Vec3 n = *direction(1, exact ? 2 : 8);
    const Vec3 a =
        *rc::gen::suchThat(direction(1, exact ? 2 : 4), [n](const Vec3& v) { return n.cross(v) != Vec3::Zero(); });
    const Vec3 u = n.cross(a), w = n.cross(u);
    const Vec3 origin = exact ? *lattice_point(8 * s, 16) : *point(s);
    return PlaneFrame{Plane{n, -n.dot(origin)}, origin, u * s, w * s, n * s};
  });
}

// A coefficient: small integers for exact input, integers plus a 20-bit fraction else.
rc::Gen<double> coefficient(bool exact, int magnitude) {
  if (exact) return rc::gen::map(integer(magnitude), [](int k) { return double(k); });
  return rc::gen::exec(
      [magnitude] { return *integer(magnitude) + std::ldexp(double(*rc::gen::inRange(0, 1 << 20)), -20); });
}

// How far each vertex sits off the plane, in units of |n|^2 s: exactly 0 for the
// degenerate families, a tiny amount for their near-degenerate twins.
enum class Heights { generic, one_on, two_on, all_on, touch_vertex, touch_edge };

rc::Gen<TrianglePlane> plane_case(bool exact, Heights kind, bool nudge) {
  return rc::gen::exec([=] {
    const double s = *scale();
    const PlaneFrame f = *plane_frame(s, exact);
    const auto off = [&] { return double(*rc::gen::suchThat(integer(8), [](int k) { return k != 0; })); };
    const double side = *rc::gen::element(-1.0, 1.0);
    std::array<double, 3> h{};
    switch (kind) {
      case Heights::generic: h = {*coefficient(exact, 4), *coefficient(exact, 4), *coefficient(exact, 4)}; break;
      case Heights::one_on: h = {0, off(), off()}; break;
      case Heights::two_on: h = {0, 0, off()}; break;
      case Heights::all_on: h = {0, 0, 0}; break;
      case Heights::touch_vertex: h = {0, side * std::abs(off()), side * std::abs(off())}; break;
      case Heights::touch_edge: h = {0, 0, side * std::abs(off())}; break;
    }
    if (nudge)
      for (double& x : h)
        if (x == 0) x = *integer(4) * *tiny(20, 50) * 16;
    Triangle t;
    for (int i = 0; i < 3; ++i)
      t[i] = f.origin + *coefficient(exact, 3) * f.u + *coefficient(exact, 3) * f.w + h[std::size_t(i)] * f.n;
    // Which vertex is special, and both windings.
    const int turn = *rc::gen::inRange(0, 3);
    Triangle r{t[turn], t[(turn + 1) % 3], t[(turn + 2) % 3]};
    if (*rc::gen::element(false, true)) std::swap(r.v1, r.v2);
    return TrianglePlane{r, f.plane};
  });
}

// The same plane with a rounded unit normal: vertices "on" it are only near it.
TrianglePlane unit_normal(TrianglePlane c) {
  const double length = c.plane.normal.norm();
  c.plane.normal /= length;
  c.plane.offset /= length;
  return c;
}

// Moved far from the origin (far_away), the plane with it (exactly: its normal is an
// integer one), by multiples of the triangle's size, at least 1.
void move_with_plane(TrianglePlane& c, const Vec3& offset) {
  for (int i = 0; i < 3; ++i) c.triangle[i] += offset;
  c.plane.offset -= c.plane.normal.dot(offset);
}
double triangle_size(const TrianglePlane& c) {
  return std::max(1.0, scale_of({c.triangle.v0, c.triangle.v1, c.triangle.v2}));
}

// A needle: long along a lattice direction of the plane's frame (in it, steep to it, or
// anything between), as thin as 1 / aspect of its length, aspects 2^10 to 2^27 (about
// 1e3 to 1.3e8), its middle anywhere near the plane.
rc::Gen<TrianglePlane> needle_plane_case() {
  return rc::gen::exec([] {
    const double s = *scale();
    const PlaneFrame f = *plane_frame(s, false);
    const auto along = [&] {
      return double(*integer(4)) * f.u + double(*integer(4)) * f.w + double(*integer(4)) * f.n;
    };
    Vec3 d = along();
    if (d == Vec3::Zero()) d = f.u;
    const Vec3 across = *rc::gen::suchThat(direction(1, 4), [d](const Vec3& v) { return d.cross(v) != Vec3::Zero(); });
    const Vec3 thin = d.cross(across).normalized() * (d.norm() * std::ldexp(1.0, -*rc::gen::inRange(10, 28)));
    const Vec3 middle =
        f.origin + *coefficient(false, 2) * f.u + *coefficient(false, 2) * f.w + *coefficient(false, 1) * f.n;
    const double lambda = *rc::gen::inRange(0, 9) / 8.0;
    const Triangle t{middle - d, middle + d, middle - d + 2 * lambda * d + thin};
    return TrianglePlane{wound(t), f.plane};
  });
}

// The same case with its coordinates times 2^e and its normal times 2^g: every
// degeneracy stays exact, and the coordinates reach the header's extremes.
TrianglePlane scaled(TrianglePlane c, int e, int g) {
  e = inside_domain(e, components({c.triangle.v0, c.triangle.v1, c.triangle.v2}));
  g = inside_domain(g, components({c.plane.normal}, {std::ldexp(c.plane.offset, e)}));
  for (int i = 0; i < 3; ++i) c.triangle[i] = std::ldexp(1.0, e) * c.triangle[i];
  c.plane.normal *= std::ldexp(1.0, g);
  c.plane.offset = std::ldexp(c.plane.offset, e + g);
  return c;
}

rc::Gen<TrianglePlane> zero_area_plane_case() {
  return rc::gen::exec([] {
    TrianglePlane c = *plane_case(false, Heights::generic, false);
    c.triangle.v2 = c.triangle.v0 + (*rc::gen::inRange(-8, 17) / 8.0) * (c.triangle.v1 - c.triangle.v0);
    return c;
  });
}

// Exact degenerate families; random input mixes in more generic triangles.
rc::Gen<TrianglePlane> plane_families(bool exact) {
  return rc::gen::weightedOneOf<TrianglePlane>({
      {exact ? 1 : 8, plane_case(exact, Heights::generic, false)},
      {2, plane_case(exact, Heights::one_on, false)},
      {2, plane_case(exact, Heights::two_on, false)},
      {1, plane_case(exact, Heights::all_on, false)},
      {1, plane_case(exact, Heights::touch_vertex, false)},
      {1, plane_case(exact, Heights::touch_edge, false)},
  });
}

// ---- Frustums -------------------------------------------------------------------------
// An exact frustum in its own frame: X right, Y up, Z forward (depth), all integers
// times a power of two. At depth Z its half-width is wx + tx Z and its half-height
// wy + ty Z (tx = px / qx, ty = py / qy): a box when tx = ty = 0, a pyramid from the
// eye when wx = wy = 0. The frame's axes are signed world axes, so world points and
// planes stay integers.
struct ExactFrustum {
  Vec3 eye, right, up, forward;
  double px, qx, py, qy, wx, wy;  // integers
  double near, far;
  double s;  // the lattice unit

  Vec3 world(double x, double y, double z) const { return eye + x * right + y * up + z * forward; }
  double half_width(double z) const { return wx + px / qx * z; }
  double half_height(double z) const { return wy + py / qy * z; }
  // Plane i (left, right, bottom, top, near, far) as a local normal and offset.
  Plane local_plane(int i) const {
    switch (i) {
      case 0: return {Vec3(qx, 0, px), qx * wx};  // qx (X + wx) + px Z >= 0
      case 1: return {Vec3(-qx, 0, px), qx * wx};
      case 2: return {Vec3(0, qy, py), qy * wy};
      case 3: return {Vec3(0, -qy, py), qy * wy};
      case 4: return {Vec3(0, 0, 1), -near};
      default: return {Vec3(0, 0, -1), far};
    }
  }
  Plane plane(int i) const {
    const Plane p = local_plane(i);
    const Vec3 n = p.normal.x() * right + p.normal.y() * up + p.normal.z() * forward;
    return {n, p.offset - n.dot(eye)};
  }
  Frustum frustum() const {
    Frustum f;
    for (int i = 0; i < 6; ++i) f.planes[std::size_t(i)] = plane(i);
    return f;
  }
};

rc::Gen<ExactFrustum> exact_frustum() {
  return rc::gen::exec([] {
    ExactFrustum f;
    f.s = *scale();
    const int axis = *rc::gen::inRange(0, 3);
    const double sign_f = *rc::gen::element(-1.0, 1.0), sign_r = *rc::gen::element(-1.0, 1.0);
    f.forward = sign_f * Vec3::Unit(axis);
    f.right = sign_r * Vec3::Unit((axis + 1 + *rc::gen::inRange(0, 2)) % 3);
    f.up = f.right.cross(f.forward);
    f.eye = *lattice_point(8 * f.s, 8);
    const bool box = *rc::gen::inRange(0, 3) == 0;
    f.px = box ? 0 : *rc::gen::inRange(1, 3);
    f.qx = box ? 1 : *rc::gen::inRange(1, 3);
    f.py = box ? 0 : *rc::gen::inRange(1, 3);
    f.qy = box ? 1 : *rc::gen::inRange(1, 3);
    f.wx = box ? 8 * f.s * *rc::gen::inRange(1, 5) : 0;
    f.wy = box ? 8 * f.s * *rc::gen::inRange(1, 5) : 0;
    f.near = 8 * f.s * *rc::gen::inRange(box ? -4 : 1, 3);
    f.far = f.near + 8 * f.s * *rc::gen::inRange(1, 5);
    return f;
  });
}

// A point exactly on some feature of an exact frustum: a corner, an edge line, or a face
// plane (inside the face or beyond it). Depths are multiples of 8 s and the widths'
// slopes have denominators 1 or 2, so every coordinate stays an integer times s.
enum class Feature { corner, edge, face };

struct FeaturePoint {
  Vec3 point;
  std::array<int, 2> planes;  // the planes it lies on (-1: none)
  Vec3 along = Vec3::Zero();  // on an edge line: a lattice step along it
};

FeaturePoint feature_point(const ExactFrustum& f, Feature kind, bool side_edge = false) {
  const double unit = 8 * f.s;
  const int steps = int((f.far - f.near) / unit);
  const auto depth = [&] { return f.near + unit * *rc::gen::inRange(-1, steps + 2); };
  const auto across = [&](double half) {
    const int reach = int(1.5 * std::abs(half) / f.s) + 1;
    return f.s * *rc::gen::inRange(-reach, reach + 1);
  };
  const double sx = *rc::gen::element(-1.0, 1.0), sy = *rc::gen::element(-1.0, 1.0);
  const int side_x = sx < 0 ? 0 : 1, side_y = sy < 0 ? 2 : 3;
  if (kind == Feature::corner) {
    const bool far = *rc::gen::element(false, true);
    const double z = far ? f.far : f.near;
    return {f.world(sx * f.half_width(z), sy * f.half_height(z), z), {side_x, far ? 5 : 4}};
  }
  const int which = side_edge ? 0 : *rc::gen::inRange(0, 3);
  if (kind == Feature::edge) {
    if (which == 0) {  // a side edge: two side planes meet along it
      const double z = depth();
      const Vec3 along = f.s * (sx * f.px * f.qy * f.right + sy * f.py * f.qx * f.up + f.qx * f.qy * f.forward);
      return {f.world(sx * f.half_width(z), sy * f.half_height(z), z), {side_x, side_y}, along};
    }
    const bool far = which == 2;
    const double z = far ? f.far : f.near;
    if (*rc::gen::element(false, true))
      return {f.world(sx * f.half_width(z), across(f.half_height(z)), z), {side_x, far ? 5 : 4}, f.s * f.up};
    return {f.world(across(f.half_width(z)), sy * f.half_height(z), z), {side_y, far ? 5 : 4}, f.s * f.right};
  }
  if (which == 0) {
    const double z = depth();
    return {f.world(sx * f.half_width(z), across(f.half_height(z)), z), {side_x, -1}};
  }
  if (which == 1) {
    const double z = depth();
    return {f.world(across(f.half_width(z)), sy * f.half_height(z), z), {side_y, -1}};
  }
  const bool far = *rc::gen::element(false, true);
  const double z = far ? f.far : f.near;
  return {f.world(across(f.half_width(z)), across(f.half_height(z)), z), {far ? 5 : 4, -1}};
}

// Any lattice point in a box somewhat larger than the frustum.
Vec3 around(const ExactFrustum& f) {
  const double z = f.near + 8 * f.s * *rc::gen::inRange(-2, int((f.far - f.near) / (8 * f.s)) + 3);
  const double hw = f.half_width(std::max(std::abs(f.near), std::abs(f.far))) + 8 * f.s;
  const double hh = f.half_height(std::max(std::abs(f.near), std::abs(f.far))) + 8 * f.s;
  const auto coordinate = [&](double half) { return f.s * *rc::gen::inRange(-int(half / f.s), int(half / f.s) + 1); };
  return f.world(coordinate(hw), coordinate(hh), z);
}

// A lattice vector that points strictly out of both planes a and b (b may be -1).
Vec3 outward(const ExactFrustum& f, int a, int b) {
  const Vec3 na = f.plane(a).normal, nb = b < 0 ? Vec3::Zero() : f.plane(b).normal;
  for (const Vec3& d : {Vec3(-na - nb), Vec3(-2 * na - nb), Vec3(-na - 2 * nb), Vec3(-na)})
    if (d.dot(na) < 0 && (b < 0 || d.dot(nb) < 0)) return d * *rc::gen::inRange(1, 4);
  return -na;
}

// A lattice vector along both planes a and b (along a alone when b is -1): moving by it
// changes neither value.
Vec3 sideways(const ExactFrustum& f, int a, int b) {
  const Vec3 na = f.plane(a).normal;
  const Vec3 other =
      b < 0 ? *rc::gen::suchThat(direction(1, 2), [na](const Vec3& d) { return na.cross(d) != Vec3::Zero(); })
            : f.plane(b).normal;
  return na.cross(other) * (f.s * *rc::gen::inRange(1, 3));
}

Triangle wound(Triangle t) {
  if (*rc::gen::element(false, true)) std::swap(t.v1, t.v2);
  const int turn = *rc::gen::inRange(0, 3);
  return {t[turn], t[(turn + 1) % 3], t[(turn + 2) % 3]};
}

// Exact degenerate triangles 0 to 3: a vertex or an edge on a feature of the frustum, or
// the triangle in a face plane, touching from outside.
Triangle on_a_feature(const ExactFrustum& f, int kind) {
  const auto feature = [&] {
    return feature_point(f, *rc::gen::element(Feature::corner, Feature::edge, Feature::face));
  };
  switch (kind) {
    case 0: {  // a vertex on a feature, the others anywhere around
      return {feature().point, around(f), around(f)};
    }
    case 1: {  // an edge in a face plane, the third vertex anywhere
      const FeaturePoint p = feature_point(f, Feature::face);
      FeaturePoint q = feature_point(f, Feature::face);
      for (int tries = 0; tries < 8 && q.planes[0] != p.planes[0]; ++tries) q = feature_point(f, Feature::face);
      if (q.planes[0] != p.planes[0]) q = p;
      return {p.point, q.point, around(f)};
    }
    case 2: {  // lying in a face plane
      const FeaturePoint p = feature_point(f, Feature::face);
      std::array<Vec3, 3> v{p.point, p.point, p.point};
      for (int i = 1; i < 3; ++i)
        for (int tries = 0; tries < 16; ++tries) {
          const FeaturePoint q = feature_point(f, Feature::face);
          if (q.planes[0] == p.planes[0]) {
            v[std::size_t(i)] = q.point;
            break;
          }
        }
      return {v[0], v[1], v[2]};
    }
    case 3: {  // touching a face, an edge or a corner from outside at one vertex
      const FeaturePoint p = feature();
      const Vec3 out = outward(f, p.planes[0], p.planes[1]) * f.s;
      return {p.point, p.point + out, p.point + 2 * out + sideways(f, p.planes[0], p.planes[1])};
    }
  }
  return {};
}

// Exact degenerate triangles 4 to 8: edges through the frustum's edge lines and corners,
// zero area, and cut points no double can hold.
Triangle through_an_edge_line(const ExactFrustum& f, int kind) {
  const auto feature = [&] {
    return feature_point(f, *rc::gen::element(Feature::corner, Feature::edge, Feature::face));
  };
  switch (kind) {
    case 4: {  // an edge through an edge line (or a corner) of the frustum
      const FeaturePoint p = feature_point(f, *rc::gen::element(Feature::corner, Feature::edge));
      const Vec3 d = *direction(8 * f.s, 4);
      return {p.point + d, p.point - *rc::gen::inRange(1, 4) * d, around(f)};
    }
    case 5: {  // touching along an edge line from outside
      const FeaturePoint p = feature_point(f, Feature::edge);
      FeaturePoint q = p;
      for (int tries = 0; tries < 8 && (q.point == p.point || q.planes != p.planes); ++tries)
        q = feature_point(f, Feature::edge);
      return {p.point, q.point, p.point + outward(f, p.planes[0], p.planes[1]) * f.s};
    }
    case 6: {  // a zero-area triangle through a feature
      const Vec3 a = feature().point, b = around(f);
      return {a, b, a + *rc::gen::inRange(-2, 3) * (b - a)};
    }
    case 7: {  // an edge through a side edge line a third of the way along: a cut point
               // that no double can hold, exactly on a second plane (for a pyramid)
      const FeaturePoint p = feature_point(f, Feature::edge, true);
      const Vec3 v0 = around(f);
      const double m = *rc::gen::element(1.0, 2.0, 4.0, 5.0);
      return {v0, 3 * p.point + m * p.along - 2 * v0, around(f)};  // crosses p + m/3 along at t = 1/3
    }
    case 8: {  // in a plane through a side edge line, outside the frustum on both sides of
               // it: only a segment of the line is left, and the crossings are at t = 1/3
      const FeaturePoint p = feature_point(f, Feature::edge, true);
      // e points out of the first plane and into the second; -e the other way round.
      const Vec3 e = f.s * (f.plane(p.planes[1]).normal - f.plane(p.planes[0]).normal);
      const auto on_line = [&] { return p.point + double(*integer(2)) * p.along; };
      return {on_line() + e, on_line() - 2 * e, on_line() + e};
    }
  }
  return {};
}

rc::Gen<TriangleFrustum> exact_case() {
  return rc::gen::exec([] {
    const ExactFrustum f = *exact_frustum();
    const int kind = *rc::gen::inRange(0, 11);
    const Triangle t = kind <= 3   ? on_a_feature(f, kind)
                       : kind <= 8 ? through_an_edge_line(f, kind)
                                   : Triangle{around(f), around(f), around(f)};
    Frustum planes = f.frustum();
    const int k = *rc::gen::inRange(1, 9);
    for (Plane& p : planes.planes) p = longer(p, k);
    return TriangleFrustum{wound(t), planes};
  });
}

// ---- Frustums from cameras ------------------------------------------------------------

struct CameraFrustum {
  CameraParameters camera;
  Frustum frustum;
  std::array<Vec3, 8> corners;
  Vec3 center;
  double size;  // the distance from the center to the farthest corner
};

CameraFrustum camera_frustum(const CameraParameters& c) {
  CameraFrustum cf{c, frustum_of(c), frustum_corners(c), Vec3::Zero(), 0.0};
  cf.center = c.eye + c.forward.normalized() * ((c.near + c.far) / 2);
  for (const Vec3& k : cf.corners) cf.size = std::max(cf.size, (k - cf.center).norm());
  return cf;
}

// A point of interest of the frustum: a corner, the center, the eye, the middle of an
// edge or of a face (the last ones only near the planes, after rounding).
Vec3 anchor(const CameraFrustum& cf) {
  const auto& k = cf.corners;
  const int i = *rc::gen::inRange(0, 8), j = *rc::gen::inRange(0, 8), l = *rc::gen::inRange(0, 8);
  switch (*rc::gen::inRange(0, 5)) {
    case 0: return k[std::size_t(i)];
    case 1: return cf.center;
    case 2: return cf.camera.eye;
    case 3: return (k[std::size_t(i)] + k[std::size_t(i ^ (1 << (j % 3)))]) / 2;  // an edge's middle
    default:
      return (k[std::size_t(i)] + k[std::size_t(i ^ (1 << (j % 3)))] + k[std::size_t(i ^ (1 << (l % 3)))] +
              k[std::size_t(i ^ (1 << (j % 3)) ^ (1 << (l % 3)))]) /
             4;
  }
}

// An offset of the frustum's size, a lattice direction times a dyadic length.
Vec3 jitter(const CameraFrustum& cf) {
  const double unit = std::ldexp(1.0, std::ilogb(cf.size) - 3);
  return *lattice_point(unit, 12);
}

rc::Gen<TriangleFrustum> camera_case() {
  return rc::gen::exec([] {
    const CameraFrustum cf = camera_frustum(*camera());
    Triangle t;
    switch (*rc::gen::inRange(0, 6)) {
      case 5: {  // a needle through a point of interest, in any direction, aspect 2^10 to 2^27
        const Vec3 d = *direction(std::ldexp(1.0, std::ilogb(cf.size) - 2), 8);
        const Vec3 across =
            *rc::gen::suchThat(direction(1, 4), [d](const Vec3& v) { return d.cross(v) != Vec3::Zero(); });
        const Vec3 thin = d.cross(across).normalized() * (d.norm() * std::ldexp(1.0, -*rc::gen::inRange(10, 28)));
        const Vec3 middle = anchor(cf) + jitter(cf) / 4;
        t = {middle - d, middle + d, middle - d + (*rc::gen::inRange(0, 9) / 4.0) * d + thin};
        break;
      }
      case 0:  // anchored at points of interest, spread by the frustum's size
        t = {anchor(cf) + jitter(cf), anchor(cf) + jitter(cf), anchor(cf) + jitter(cf)};
        break;
      case 1: {  // one vertex at (or a hair off) a point of interest
        const Vec3 a = anchor(cf);
        const double hair = *integer(4) * *tiny(25, 52) * std::max(cf.size, scale_of({a}));
        t = {a + hair * Vec3(*integer(2), *integer(2), *integer(2)), anchor(cf) + jitter(cf), anchor(cf) + jitter(cf)};
        break;
      }
      case 2: {  // a big triangle across the view at some depth: cut by all four sides
        const CameraParameters& c = cf.camera;
        const Vec3 f = c.forward.normalized(), r = f.cross(c.up).normalized(), u = r.cross(f);
        const double depth = c.near + (c.far - c.near) * *rc::gen::inRange(-1, 10) / 8.0;
        const Vec3 middle = c.eye + depth * f;
        const double reach = 4 * cf.size;
        t = {middle - reach * (r + u) + jitter(cf) / 8, middle + reach * (r - u) + jitter(cf) / 8,
             middle + reach * u + jitter(cf) / 8};
        break;
      }
      case 3: {  // through the eye: where every side plane meets
        t = {cf.camera.eye, anchor(cf) + jitter(cf), anchor(cf) + jitter(cf)};
        break;
      }
      default:  // anything in a box around the frustum
        t = {cf.center + 2 * jitter(cf), cf.center + 2 * jitter(cf), cf.center + 2 * jitter(cf)};
    }
    return TriangleFrustum{wound(t), cf.frustum};
  });
}

}  // namespace

rc::Gen<TrianglePlane> triangle_plane() {
  const rc::Gen<TrianglePlane> exactly = plane_families(false);
  const rc::Gen<TrianglePlane> nearly = rc::gen::weightedOneOf<TrianglePlane>({
      {2, plane_case(false, Heights::one_on, true)},
      {1, plane_case(false, Heights::two_on, true)},
      {1, plane_case(false, Heights::all_on, true)},
      {1, plane_case(false, Heights::touch_vertex, true)},
  });
  const rc::Gen<TrianglePlane> families =
      rc::gen::weightedOneOf<TrianglePlane>({{6, exactly},
                                             {3, nearly},
                                             {1, zero_area_plane_case()},
                                             {2, rc::gen::map(exactly, unit_normal)},
                                             {2, needle_plane_case()}});
  const rc::Gen<TrianglePlane> extremes =
      rc::gen::exec([families] { return scaled(*families, signed_extreme(), *rc::gen::inRange(-100, 101)); });
  return rc::gen::weightedOneOf<TrianglePlane>(
      {{12, families}, {2, far_away(families, move_with_plane, triangle_size)}, {2, extremes}});
}

rc::Gen<TrianglePlane> exact_triangle_plane() {
  return rc::gen::exec([] {
    TrianglePlane c = *plane_families(true);
    c.plane = longer(c.plane, *rc::gen::inRange(1, 9));
    return c;
  });
}

rc::Gen<CameraParameters> camera() {
  return rc::gen::exec([] {
    CameraParameters c;
    // Mostly the usual scales; one in 16 at the ends of the header's domain.
    const double s = *rc::gen::inRange(0, 16) == 0 ? std::ldexp(1.0, signed_extreme()) : *scale();
    c.eye = *point(s);
    if (*rc::gen::inRange(0, 8) == 0) c.eye += *lattice_point(s * 1024.0, 64);
    c.forward = *direction(1, 8);
    const Vec3 f = c.forward;
    c.up = *rc::gen::suchThat(direction(1, 8), [f](const Vec3& u) {
      return f.cross(u).norm() >= std::sin(15 * M_PI / 180) * f.norm() * u.norm();
    });
    if (*rc::gen::inRange(0, 16) == 0) {  // forward and up of any length
      c.forward *= std::ldexp(1.0, inside_domain(*rc::gen::inRange(-100, 101), components({c.forward})));
      c.up *= std::ldexp(1.0, inside_domain(*rc::gen::inRange(-100, 101), components({c.up})));
    }
    c.fov_y = *rc::gen::inRange(20, 121) * M_PI / 180;
    c.aspect = *rc::gen::element(0.5, 0.75, 1.0, 4.0 / 3.0, 16.0 / 9.0, 2.0);
    c.near = s * std::ldexp(1.0, *rc::gen::inRange(-3, 2));
    c.far = c.near * *rc::gen::inRange(2, 65);
    // At the ends of the domain, every length kept inside it (a similar camera).
    const int e = inside_domain(0, components({c.eye}, {c.near, c.far}));
    c.eye *= std::ldexp(1.0, e), c.near = std::ldexp(c.near, e), c.far = std::ldexp(c.far, e);
    return c;
  });
}

rc::Gen<lab01::Camera> lab_camera() {
  return rc::gen::map(camera(), [](const CameraParameters& p) {
    return lab01::Camera{p.eye, p.forward, p.up, p.fov_y, p.aspect, p.near, p.far};
  });
}

rc::Gen<Mat4> view_projection_matrix() {
  return rc::gen::exec([] {
    const CameraParameters c = *camera();
    Mat4 m = view_projection(c);
    if (*rc::gen::inRange(0, 3) == 0) {
      // An orthographic view instead: glOrtho(l, r, b, t, near, far) times the same view.
      const double half = c.far * std::tan(c.fov_y / 2);
      const double l = -half * c.aspect * *rc::gen::inRange(1, 5) / 4,
                   r = half * c.aspect * *rc::gen::inRange(1, 5) / 4;
      const double b = -half * *rc::gen::inRange(1, 5) / 4, t = half * *rc::gen::inRange(1, 5) / 4;
      Mat4 ortho = Mat4::Identity();
      ortho(0, 0) = 2 / (r - l);
      ortho(0, 3) = -(r + l) / (r - l);
      ortho(1, 1) = 2 / (t - b);
      ortho(1, 3) = -(t + b) / (t - b);
      ortho(2, 2) = -2 / (c.far - c.near);
      ortho(2, 3) = -(c.far + c.near) / (c.far - c.near);
      m = ortho * view_matrix(c);
    }
    if (*rc::gen::inRange(0, 3) == 0) m *= std::ldexp(1.0, *rc::gen::inRange(-4, 5));
    return m;
  });
}

rc::Gen<TriangleFrustum> triangle_frustum() {
  return rc::gen::exec([] {
    TriangleFrustum c = *rc::gen::weightedOneOf<TriangleFrustum>({{3, camera_case()}, {1, exact_case()}});
    if (*rc::gen::inRange(0, 8) == 0)  // each plane's coefficients times 2^-100 to 2^100: normals of any length
      for (Plane& p : c.frustum.planes) {
        const int g = inside_domain(*rc::gen::inRange(-100, 101), components({p.normal}, {p.offset}));
        p = {std::ldexp(1.0, g) * p.normal, std::ldexp(p.offset, g)};
      }
    return c;
  });
}

rc::Gen<TriangleFrustum> exact_triangle_frustum() { return exact_case(); }

namespace {

// A small mesh (gen::mesh) with lattice step `unit`, centred on `center` by a lattice
// step, with colours. `exact`: every vertex snapped to the lattice (integer input).
MeshFrustum mesh_across(const Frustum& frustum, const Vec3& center, double unit, bool exact) {
  MeshFrustum out{*mesh(unit), {}, frustum};
  Vec3 low = Vec3::Constant(1e300), high = Vec3::Constant(-1e300);
  for (Vec3& v : out.mesh.vertices) {
    if (exact) v = (v / unit).array().round().matrix() * unit;
    low = low.cwiseMin(v);
    high = high.cwiseMax(v);
  }
  const Vec3 shift = ((center - (low + high) / 2) / unit).array().round().matrix() * unit;
  for (Vec3& v : out.mesh.vertices) v += shift;
  for (std::size_t i = 0; i < out.mesh.vertices.size(); ++i) out.colors.push_back(*lattice_point(1.0 / 16, 16));
  return out;
}

MeshFrustum exact_mesh_case() {
  const ExactFrustum f = *exact_frustum();
  Frustum planes = f.frustum();
  const int k = *rc::gen::inRange(1, 9);
  for (Plane& p : planes.planes) p = longer(p, k);
  return mesh_across(planes, f.world(0, 0, f.near), 4 * f.s, true);
}

}  // namespace

rc::Gen<MeshFrustum> mesh_frustum() {
  return rc::gen::exec([] {
    if (*rc::gen::inRange(0, 4) == 0) return exact_mesh_case();
    const CameraFrustum cf = camera_frustum(*camera());
    MeshFrustum m = mesh_across(cf.frustum, cf.center, std::ldexp(1.0, std::ilogb(cf.size) - 3), false);
    if (*rc::gen::inRange(0, 6) == 0) {  // squashed along an axis by 2^-10 to 2^-27: needles
      const int axis = *rc::gen::inRange(0, 3);
      const double by = std::ldexp(1.0, -*rc::gen::inRange(10, 28)), middle = cf.center[axis];
      for (Vec3& v : m.mesh.vertices) v[axis] = middle + (v[axis] - middle) * by;
    }
    return m;
  });
}

rc::Gen<MeshFrustum> exact_mesh_frustum() {
  return rc::gen::exec([] { return exact_mesh_case(); });
}

}  // namespace labkit::gen
