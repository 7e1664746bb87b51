#include "05_sphere_sweeps/judge.h"

#include "common/generators/generators.h"
#include "common/generators/grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace labkit::gen {

namespace {

// Where a family draws from (its Grid): the fine dyadic lattice at scale s, or (exact)
// integers |x| <= 64 times s, with multipliers kept small so that every combination
// stays an integer of that size.
Vec3 grid_point(const Grid& g) { return g.exact ? *lattice_point(g.s, 24) : *point(g.s); }
Vec3 grid_direction(const Grid& g) { return *direction(g.s, g.exact ? 4 : 8); }
// A length in [0, 8] s; the exact lattice has no fractions.
double grid_length(const Grid& g) {
  const double whole = *rc::gen::inRange(0, 9);
  if (g.exact) return whole * g.s;
  return (whole + *rc::gen::inRange(0, 1 << 20) / double(1 << 20)) * g.s;
}
// x + k/8 d on the fine lattice, x + k d (|k| <= 2) on the exact one.
Vec3 along(const Grid& g, const Vec3& x, const Vec3& d) {
  if (g.exact) return x + double(*rc::gen::inRange(-2, 3)) * d;
  return x + (*rc::gen::inRange(-16, 17) / 8.0) * d;
}
// A multiplier in (0, 1]: k / 8 on the fine lattice, 1 on the exact one.
double fraction(const Grid& g) { return g.exact ? 1.0 : *rc::gen::inRange(1, 9) / 8.0; }

// A tiny length: 2^-k (k in [10, 50]) of `size`, times a small integer (may be 0).
double hair(double size) { return *integer(4) * *tiny(10, 50) * size; }

double largest(std::initializer_list<Vec3> points) { return std::max(1e-300, scale_of(points)); }

// A near miss or a near hit that is still decisive: m * 1e-9 S for m from 30 to 2^24,
// log-uniform, either sign. The judges count a sweep as ambiguous within 24 tol = 24e-9 S
// of touching, so these stay just outside that band (the exact touch is step 7's).
double decisive_hair(double S, bool positive_only = false) {
  const double m = 30 * std::ldexp(1.0, *rc::gen::inRange(0, 20)) * (1 + *rc::gen::inRange(0, 8) / 8.0);
  const double sign = positive_only ? 1.0 : *rc::gen::element(-1.0, 1.0);
  return sign * m * 1e-9 * S;
}

// The judges' S for a moving sphere or box against a plane (sphere_sweeps.h).
double motion_scale(const Vec3& center, const Vec3& displacement, double size, const Plane& plane) {
  return std::max({scale_of({center, displacement}), size, std::abs(plane.offset) / plane.normal.norm(), 1e-300});
}

// Orthonormal axes: a rotation from a small integer quaternion (rounded), or, exactly, a
// signed permutation of the coordinate axes.
Mat3 axes(const Grid& g) {
  if (!g.exact) return (*rigid_transform(1.0)).linear();
  std::array<int, 3> order{0, 1, 2};
  const int shift = *rc::gen::inRange(0, 3);
  std::rotate(order.begin(), order.begin() + shift, order.end());
  if (*rc::gen::arbitrary<bool>()) std::swap(order[1], order[2]);
  Mat3 m = Mat3::Zero();
  for (int i = 0; i < 3; ++i) m(order[i], i) = *rc::gen::element(-1.0, 1.0);
  return m;
}

Rectangle rectangle(const Grid& g) {
  const Mat3 m = axes(g);
  Rectangle r{grid_point(g), m.col(0), m.col(1), grid_length(g), grid_length(g)};
  // Zero-size rectangles on purpose: a segment, or a point.
  const int flat = *rc::gen::weightedElement<int>({{8, 0}, {1, 1}, {1, 2}, {1, 3}});
  if (flat & 1) r.half_u = 0;
  if (flat & 2) r.half_v = 0;
  return r;
}

Vec3 normal_of(const Rectangle& r) { return r.u.cross(r.v); }

// A point of the rectangle's plane at rectangle coordinates: inside, exactly on a side or
// a corner, or outside.
Vec3 rectangle_point(const Grid& g, const Rectangle& r, bool inside) {
  const auto coordinate = [&](double half) {
    const int k = inside ? *rc::gen::inRange(-8, 9) : *rc::gen::inRange(-16, 17);
    return g.exact ? std::round(k / 8.0) * half : k / 8.0 * half;
  };
  return r.center + coordinate(r.half_u) * r.u + coordinate(r.half_v) * r.v;
}

// ---- Points and segments --------------------------------------------------------------

Segment segment(const Grid& g) {
  const Vec3 a = grid_point(g);
  const int kind = *rc::gen::weightedElement<int>({{8, 0}, {1, 1}});
  return {a, kind == 1 ? a : Vec3(a + grid_direction(g))};
}

rc::Gen<PointSegmentPair> point_segment_families(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Segment s = segment(g);
    switch (*rc::gen::inRange(0, 4)) {
      case 0: return PointSegmentPair{grid_point(g), s};             // anywhere
      case 1: return PointSegmentPair{along(g, s.a, s.b - s.a), s};  // on its line
      case 2: return PointSegmentPair{s.a + fraction(g) * (s.b - s.a) + grid_direction(g), s};
      default: {  // a hair off it
        if (exact) return PointSegmentPair{s.b, s};
        const Vec3 x = s.a + fraction(g) * (s.b - s.a);
        return PointSegmentPair{x + hair(largest({s.a, s.b})) * grid_direction(g) / g.s, s};
      }
    }
  });
}

rc::Gen<SegmentPair> segment_pair_families(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Segment first = segment(g);
    const Vec3 d0 = first.b - first.a;
    switch (*rc::gen::weightedElement<int>({{2, 0}, {2, 1}, {2, 2}, {3, 3}, {2, 4}, {1, 5}, {exact ? 0 : 2, 6}})) {
      case 0: return SegmentPair{first, segment(g)};
      case 6: {  // crossing (or a hair apart) at an angle of 2^-20 to 2^-27 inside both: only
                 // |d0 x d1|^2 keeps the lines' pair; a c - b^2 is then rounding noise (below
                 // about 2^-24, more than the tolerance)
        const Vec3 x = first.a + *rc::gen::inRange(1, 8) / 8.0 * d0 +
                       (*rc::gen::inRange(0, 2) ? 0.0 : hair(largest({first.a, first.b}))) * grid_direction(g) / g.s;
        const Vec3 d1 = d0 + *tiny(20, 27) * grid_direction(g) * (d0.norm() / g.s / 8);
        return SegmentPair{first, {x - *rc::gen::inRange(1, 8) / 8.0 * d1, x + *rc::gen::inRange(1, 8) / 8.0 * d1}};
      }
      case 1: {  // the lines cross (at a point of the first), then maybe lifted apart
        const Vec3 x = exact ? first.a : Vec3(first.a + fraction(g) * d0);
        const Vec3 d1 = grid_direction(g);
        const Vec3 lift = *rc::gen::element(0, 0, 1) ? grid_direction(g) : Vec3::Zero();
        return SegmentPair{first, {x + lift + d1, along(g, x + lift, d1)}};
      }
      case 2: {  // an end of the second on the first
        const Vec3 x = along(g, first.a, d0);
        return SegmentPair{first, {x, grid_point(g)}};
      }
      case 3: {  // parallel, collinear or overlapping
        const int m = *rc::gen::element(-2, -1, 1, 2);
        const Vec3 d1 = exact ? Vec3(m * d0) : Vec3(m / 2.0 * d0);
        const Vec3 offset = *rc::gen::element(0, 1) ? along(g, Vec3::Zero(), d0) : grid_direction(g);
        return SegmentPair{first, {first.a + offset, first.a + offset + d1}};
      }
      case 4: {  // nearly parallel: parallel, then one end moved by a hair
        const Vec3 offset = grid_direction(g);
        Segment second{first.a + offset, first.b + offset};
        if (!exact) second.b += hair(largest({first.a, first.b, second.a})) * grid_direction(g) / g.s;
        return SegmentPair{first, second};
      }
      default: {  // zero length
        const Vec3 x = grid_point(g);
        return SegmentPair{*rc::gen::element(first, Segment{first.a, first.a}), Segment{x, x}};
      }
    }
  });
}

void move_point_segment(PointSegmentPair& x, const Vec3& o) {
  x.p += o;
  x.segment.a += o;
  x.segment.b += o;
}
double size_point_segment(const PointSegmentPair& x) { return scale_of({x.p, x.segment.a, x.segment.b}); }
void move_segment_pair(SegmentPair& x, const Vec3& o) {
  x.first.a += o;
  x.first.b += o;
  x.second.a += o;
  x.second.b += o;
}
double size_segment_pair(const SegmentPair& x) { return scale_of({x.first.a, x.first.b, x.second.a, x.second.b}); }

// ---- Rectangles -----------------------------------------------------------------------

rc::Gen<PointRectanglePair> point_rectangle_families(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Rectangle r = rectangle(g);
    const Vec3 x = rectangle_point(g, r, *rc::gen::arbitrary<bool>());
    const Vec3 n = normal_of(r);
    switch (*rc::gen::inRange(0, 4)) {
      case 0: return PointRectanglePair{grid_point(g), r};
      case 1: return PointRectanglePair{x, r};  // in its plane
      case 2: return PointRectanglePair{x + grid_length(g) * n, r};
      default: return PointRectanglePair{exact ? x : Vec3(x + hair(largest({r.center})) * n), r};
    }
  });
}

rc::Gen<SegmentRectanglePair> segment_rectangle_families(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Rectangle r = rectangle(g);
    const Vec3 n = normal_of(r);
    const Vec3 x = rectangle_point(g, r, *rc::gen::arbitrary<bool>());
    const Vec3 y = rectangle_point(g, r, *rc::gen::arbitrary<bool>());
    switch (*rc::gen::weightedElement<int>({{2, 0}, {3, 1}, {2, 2}, {2, 3}, {2, 4}, {1, 5}})) {
      case 0: return SegmentRectanglePair{segment(g), r};
      case 1: {  // through the plane at x (inside, on a side, or outside)
        const Vec3 d = grid_direction(g);
        return SegmentRectanglePair{{x + d, x - fraction(g) * d}, r};
      }
      case 2: return SegmentRectanglePair{{x, y}, r};  // in the plane
      case 3: {                                        // parallel to the plane, above it
        const Vec3 lift = grid_length(g) * n;
        return SegmentRectanglePair{{x + lift, y + lift}, r};
      }
      case 4: {  // an end on the rectangle, or a hair above the plane
        const double h = exact ? 0.0 : hair(largest({r.center, x, y}));
        return SegmentRectanglePair{{x + h * n, y + grid_length(g) * n}, r};
      }
      default: return SegmentRectanglePair{{x, x}, r};  // zero length
    }
  });
}

rc::Gen<RectanglePair> rectangle_pair_families(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Rectangle first = rectangle(g);
    Rectangle second = rectangle(g);
    const Vec3 n = normal_of(first);
    switch (*rc::gen::weightedElement<int>({{2, 0}, {2, 1}, {2, 2}, {2, 3}})) {
      case 0: break;  // anywhere
      case 1:         // parallel: the same axes, stacked or side by side in one plane
        second.u = first.u;
        second.v = first.v;
        second.center = rectangle_point(g, first, false) + *rc::gen::element(0.0, 0.0, 1.0) * grid_length(g) * n;
        break;
      case 2:  // standing on the first: its u along the first's normal, an end on the first
        second.u = n;
        second.v = *rc::gen::element(first.u, first.v);
        second.center = rectangle_point(g, first, true) + second.half_u * n;
        break;
      default:  // crossing it, or a hair above
        second.u = n;
        second.v = first.u;
        second.center = rectangle_point(g, first, true) + (exact ? 0.0 : hair(largest({first.center}))) * n +
                        *rc::gen::element(0.0, 1.0) * second.half_u * n;
        break;
    }
    return RectanglePair{first, second};
  });
}

void move_point_rectangle(PointRectanglePair& x, const Vec3& o) {
  x.p += o;
  x.rectangle.center += o;
}
double size_point_rectangle(const PointRectanglePair& x) { return scale_of({x.p, x.rectangle.center}); }
void move_segment_rectangle(SegmentRectanglePair& x, const Vec3& o) {
  x.segment.a += o;
  x.segment.b += o;
  x.rectangle.center += o;
}
double size_segment_rectangle(const SegmentRectanglePair& x) {
  return scale_of({x.segment.a, x.segment.b, x.rectangle.center});
}
void move_rectangle_pair(RectanglePair& x, const Vec3& o) {
  x.first.center += o;
  x.second.center += o;
}
double size_rectangle_pair(const RectanglePair& x) { return scale_of({x.first.center, x.second.center}); }

// ---- Moving shapes --------------------------------------------------------------------

// A plane through x with an integer normal (not unit length), or, exactly, a multiple of
// a coordinate axis.
Plane plane_through(const Grid& g, const Vec3& x) {
  Vec3 n = g.exact ? Vec3(axes(g).col(0) * double(*rc::gen::inRange(1, 4))) : *direction(1.0, 4);
  return {n, -n.dot(x)};
}

// A velocity toward the plane (from the side of `center`), away from it, along it, zero,
// or anything.
Vec3 velocity_for(const Grid& g, const Plane& plane, const Vec3& center) {
  const Vec3 d = grid_direction(g);
  const double side = plane.value(center) >= 0 ? 1.0 : -1.0;
  const double rate = plane.normal.dot(d);
  switch (*rc::gen::weightedElement<int>({{4, 0}, {1, 1}, {1, 2}, {1, 3}, {1, 4}})) {
    case 0: return side * rate > 0 ? Vec3(-d) : d;  // toward
    case 1: return side * rate < 0 ? Vec3(-d) : d;  // away
    case 2: {                                       // along the plane
      Vec3 along = plane.normal.cross(d);
      if (!g.exact) along /= std::max(1.0, plane.normal.cwiseAbs().maxCoeff());
      return along;
    }
    case 3: return Vec3::Zero();
    default: return d;
  }
}

double duration(const Grid& g) {
  return g.exact ? *rc::gen::element(1.0, 2.0, 4.0) : *rc::gen::element(1.0, 1.0, 0.5, 2.0, 0.125, 8.0);
}

rc::Gen<SpherePlaneMotion> sphere_plane_families(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Vec3 x = grid_point(g);
    const Plane plane = plane_through(g, x);
    const double r = grid_length(g);
    const Vec3 unit = plane.normal.normalized();
    const double T = duration(g);
    const double side = *rc::gen::element(-1.0, 1.0);
    Vec3 center = grid_point(g);
    const int family =
        *rc::gen::weightedElement<int>({{exact ? 2 : 6, 0}, {2, 1}, {exact ? 2 : 1, 2}, {exact ? 0 : 3, 3}});
    switch (family) {
      case 0: break;  // anywhere
      case 1: {       // touching at t = 0 exactly (exact lattice), or decisively near it, beside x
        Vec3 beside = plane.normal.cross(grid_direction(g));
        if (!exact) beside /= plane.normal.cwiseAbs().maxCoeff();
        center = x + beside + side * r * unit;
        break;
      }
      case 2: {  // reaching the plane exactly at T (exact), or just before or after it
        const double gap = grid_length(g) + g.s;
        center = x + side * (r + gap) * unit;
        const double travel = exact ? gap : gap + decisive_hair(motion_scale(center, gap * unit, r, plane));
        return SpherePlaneMotion{{center, r}, -side * travel / T * unit, plane, T};
      }
      default:  // a hair from touching at 0, straight over x
        center = x + side * r * unit;
        break;
    }
    const Vec3 velocity = velocity_for(g, plane, center);
    // Cases 1 and 3 on the fine lattice: move off the exact touch, just outside the doubt band.
    if (!exact && family != 0) center += side * decisive_hair(motion_scale(center, velocity * T, r, plane)) * unit;
    return SpherePlaneMotion{{center, r}, velocity, plane, T};
  });
}

// Pythagorean quadruples (a, b, c, n): a^2 + b^2 + c^2 = n^2, so that distances are exact.
// The first `count` of them have n <= 9.
Vec3 pythagorean(int& norm, int count = 10) {
  static const int q[][4] = {{0, 3, 4, 5},  {1, 2, 2, 3},  {2, 3, 6, 7},   {1, 4, 8, 9},    {4, 4, 7, 9},
                             {2, 6, 9, 11}, {6, 6, 7, 11}, {3, 4, 12, 13}, {2, 10, 11, 15}, {1, 12, 12, 17}};
  const int* pick = q[*rc::gen::inRange(0, count)];
  norm = pick[3];
  std::array<double, 3> v{double(pick[0]), double(pick[1]), double(pick[2])};
  std::rotate(v.begin(), v.begin() + *rc::gen::inRange(0, 3), v.end());
  for (double& c : v) c *= *rc::gen::element(-1.0, 1.0);
  return {v[0], v[1], v[2]};
}

SphereSphereMotion place(const Grid& g, const Vec3& A, const Vec3& B, double R, double T) {
  const auto [r0, r1] = *split_radius(R);
  const Vec3 c1 = grid_point(g), v1 = g.exact ? Vec3::Zero() : *rc::gen::element(Vec3(Vec3::Zero()), grid_direction(g));
  return {{c1 + A, r0}, v1 + B, {c1, r1}, v1, T};
}

// The same, on the fine lattice with R moved off the exact touch (at t = 0, at the graze,
// at T) to just outside the judges' doubt band: decisive, and still very near.
SphereSphereMotion place_near(const Grid& g, const Vec3& A, const Vec3& B, double R, double T) {
  SphereSphereMotion m = place(g, A, B, R, T);
  if (g.exact) return m;
  const double S = std::max({scale_of({m.s0.center, m.s1.center, m.v0 * T, m.v1 * T}), R, 1e-300});
  const double hair = decisive_hair(S);
  const auto [r0, r1] = *split_radius(R + hair >= 0 ? R + hair : R - hair);
  m.s0.radius = r0;
  m.s1.radius = r1;
  return m;
}

rc::Gen<SphereSphereMotion> sphere_sphere_families(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const double T = duration(g);
    switch (*rc::gen::weightedElement<int>({{exact ? 3 : 6, 0}, {2, 1}, {exact ? 2 : 1, 2}, {1, 3}, {2, 4}})) {
      case 0: {  // anywhere, moving anyhow
        const Vec3 c0 = grid_point(g), c1 = grid_point(g);
        return SphereSphereMotion{{c0, grid_length(g)}, grid_direction(g), {c1, grid_length(g)}, grid_direction(g), T};
      }
      case 1: {  // touching (or overlapping) at t = 0 exactly, then toward, apart, sideways or still
        int n = 0;
        const Vec3 A = pythagorean(n) * g.s;
        const double R = n * g.s + *rc::gen::element(0.0, 0.0, g.s);
        const Vec3 sideways = A.cross(grid_direction(g)) / (exact ? 1.0 : double(n));
        const Vec3 B = *rc::gen::element(Vec3(-A), Vec3(A), sideways, Vec3(Vec3::Zero()), grid_direction(g));
        return place_near(g, A, B, R, T);
      }
      case 2: {  // head-on: |A| = n k, R = n (k - j), closing at j / T per unit of dir: contact at T
        int n = 0;
        const Vec3 dir = pythagorean(n);
        const int k = *rc::gen::inRange(1, 5), j = *rc::gen::inRange(1, k + 1);
        return place_near(g, dir * (k * g.s), -dir * (j * g.s / T), n * (k - j) * g.s, T);
      }
      case 3: {  // no relative motion
        SphereSphereMotion m{
            {grid_point(g), grid_length(g)}, grid_direction(g), {grid_point(g), grid_length(g)}, Vec3::Zero(), T};
        m.v1 = m.v0;
        return m;
      }
      default: return exact ? *soon_spheres(true) : *grazing_spheres();
    }
  });
}

// ---- A sphere against a static capsule ---------------------------------------------------

// The judges' S for it: centre, displacement, axis ends, radii.
double capsule_motion_scale(const SphereCapsuleMotion& m) {
  return std::max({scale_of({m.sphere.center, m.velocity * m.duration, m.capsule.axis.a, m.capsule.axis.b}),
                   m.sphere.radius, m.capsule.radius, 1e-300});
}

// Radii summing to `total` moved off the exact touch to just outside the judges' doubt band
// (either side): a near case that stays decisive.
void set_radii_near(SphereCapsuleMotion& m, double total) {
  m.sphere.radius = 0;
  m.capsule.radius = total;
  const double hair = decisive_hair(capsule_motion_scale(m));
  const auto [r, rc] = *split_radius(total + hair >= 0 ? total + hair : total - hair);
  m.sphere.radius = r;
  m.capsule.radius = rc;
}

rc::Gen<SphereCapsuleMotion> sphere_capsule_families() {
  return rc::gen::exec([] {
    const Grid g = *grid(false);
    const double T = duration(g);
    // A frame: the axis along e0 (length L), e1 and e2 across it (rounded, orthonormal).
    const Mat3 frame = axes(g);
    const Vec3 e0 = frame.col(0), e1 = frame.col(1), e2 = frame.col(2);
    const Vec3 a = grid_point(g);
    const double L = (*rc::gen::inRange(1, 17) / 4.0) * g.s;
    const Segment axis{a, a + L * e0};
    const double f = *rc::gen::inRange(1, 16) / 16.0;         // an axial fraction strictly inside
    const double D = (*rc::gen::inRange(1, 33) / 8.0) * g.s;  // a distance from the axis
    SphereCapsuleMotion m{{a, 0}, Vec3::Zero(), {axis, 0}, T};
    switch (*rc::gen::weightedElement<int>({{4, 0}, {2, 1}, {2, 2}, {2, 3}, {2, 4}, {1, 5}, {1, 6}})) {
      case 0: {  // anywhere, moving anyhow (a zero-length axis now and then)
        const auto [r, rc] = *split_radius(grid_length(g));
        return SphereCapsuleMotion{{grid_point(g), r}, grid_direction(g), {segment(g), rc}, T};
      }
      case 1: {  // aimed at a point near the axis, from anywhere, radii anyhow
        const Vec3 target = a + f * L * e0 + (*rc::gen::inRange(-8, 9) / 4.0) * g.s * e1;
        m.sphere.center = target + grid_direction(g);
        m.velocity = (target - m.sphere.center) * (*rc::gen::inRange(1, 17) / (8.0 * T));
        const auto [r, rc] = *split_radius(grid_length(g));
        m.sphere.radius = r;
        m.capsule.radius = rc;
        return m;
      }
      case 2: {  // grazing the side: the line of motion passes D from the axis at fraction f,
                 // across it (and perhaps along it): closest approach D, radii D +- a hair
        const double tc = *rc::gen::inRange(1, 16) / 16.0 * T;
        const Vec3 v = ((*rc::gen::inRange(1, 9) / 2.0) * e2 + (*rc::gen::inRange(-2, 3) / 4.0) * e0) * (g.s / T);
        m.sphere.center = a + f * L * e0 + D * e1 - tc * v;
        m.velocity = v;
        set_radii_near(m, D);
        return m;
      }
      case 3: {  // grazing a cap: beyond the end b, across the axis's direction, closest
                 // approach D from b (the nearest point of the axis stays b)
        const double k = *rc::gen::inRange(1, 5) / 4.0;
        const Vec3 off = (k * e0 + e1).normalized() * D;
        const double tc = *rc::gen::inRange(1, 16) / 16.0 * T;
        const Vec3 v = e2 * ((*rc::gen::inRange(1, 9) / 2.0) * g.s / T);
        m.sphere.center = axis.b + off - tc * v;
        m.velocity = v;
        set_radii_near(m, D);
        return m;
      }
      case 4: {  // sliding parallel to the axis toward the cap at a, D from its line
        const double start = (*rc::gen::inRange(1, 9) / 4.0) * g.s;
        m.sphere.center = a - start * e0 + D * e1;
        m.velocity = e0 * ((start + (*rc::gen::inRange(0, 9) / 4.0) * g.s) / (T * *rc::gen::element(0.5, 1.0)));
        set_radii_near(m, D * *rc::gen::element(1.0, 1.0, 1.25));
        return m;
      }
      case 5: {  // near touching at t = 0 (beside the side or beyond an end), moving anyhow
        const Vec3 out = *rc::gen::element(Vec3(e1), Vec3((e1 - e0).normalized()), Vec3((e2 + e0).normalized()));
        const Vec3 foot = out.dot(e0) < 0 ? axis.a : (out.dot(e0) > 0 ? axis.b : Vec3(a + f * L * e0));
        m.sphere.center = foot + D * out;
        m.velocity = grid_direction(g) * (1.0 / T);
        set_radii_near(m, D);
        return m;
      }
      default: {  // head-on to the side, reaching it at T (or a hair before or after)
        const double gap = (*rc::gen::inRange(1, 17) / 4.0) * g.s;
        m.sphere.center = a + f * L * e0 + (D + gap) * e1;
        m.velocity = -e1 * (gap / T);
        set_radii_near(m, D);
        return m;
      }
    }
  });
}

// The robustness step's: integers |x| <= 64 times s, axis-aligned capsules, exact touches.
rc::Gen<SphereCapsuleMotion> exact_sphere_capsule_families() {
  return rc::gen::exec([] {
    const Grid g = *grid(true);
    const double s = g.s, T = duration(g);
    const int k = *rc::gen::inRange(0, 3), j = (k + 1) % 3, l = (k + 2) % 3;
    const Vec3 ek = Vec3::Unit(k), ej = Vec3::Unit(j), el = Vec3::Unit(l);
    const Vec3 a = *lattice_point(s, 16);
    const int n = *rc::gen::inRange(0, 9);  // the axis's length in units of s (0: a sphere)
    const Segment axis{a, a + n * s * ek};
    const int D = *rc::gen::inRange(0, 9);
    const int inside = n > 0 ? *rc::gen::inRange(0, n + 1) : 0;  // a lattice point of the axis
    SphereCapsuleMotion m{{a, 0}, Vec3::Zero(), {axis, 0}, T};
    double R = D * s;
    switch (*rc::gen::inRange(0, 6)) {
      case 0: {  // sliding exactly parallel to the axis, D from its line, toward a
        const int start = *rc::gen::inRange(1, 9);
        m.sphere.center = a - start * s * ek + D * s * ej;
        m.velocity = ek * (*rc::gen::inRange(1, 17) * s);
        R = (D + *rc::gen::inRange(-1, 2)) * s;
        break;
      }
      case 1: {  // starting exactly touching (beside the axis, or beyond the end a)
        int norm = 0;
        Vec3 P = pythagorean(norm, 5);
        if (*rc::gen::arbitrary<bool>()) {
          P = D * ej;
          norm = D;
          m.sphere.center = a + inside * s * ek + P * s;
        } else {
          if (P.dot(ek) > 0) P[k] = -P[k];
          m.sphere.center = a + P * s;
        }
        m.velocity = *lattice_point(s, 4);
        R = norm * s;
        break;
      }
      case 2: {  // a zero-length capsule (a sphere), head-on: contact exactly at T, or near it
        int norm = 0;
        const Vec3 P = pythagorean(norm, 5);
        const int far = *rc::gen::inRange(2, 6), close = *rc::gen::inRange(1, far);
        m.capsule.axis = {a, a};
        m.sphere.center = a + far * s * P;
        m.velocity = -P * (close * s / T);
        R = (far - close + *rc::gen::inRange(-1, 2)) * norm * s;
        break;
      }
      case 3: {  // an exact graze of the side: across the axis at distance D
        const int before = *rc::gen::inRange(1, 5);
        m.sphere.center = a + inside * s * ek + D * s * ej - before * s * el;
        m.velocity = el * (*rc::gen::inRange(1, 9) * s / T);
        break;
      }
      case 4: {  // head-on to the side: contact exactly at T (or one unit either way)
        const int gap = *rc::gen::inRange(1, 9);
        m.sphere.center = a + inside * s * ek + (D + gap) * s * ej;
        m.velocity = -ej * ((gap + *rc::gen::inRange(-1, 2)) * s / T);
        break;
      }
      default: {  // anywhere on the lattice
        m.sphere.center = *lattice_point(s, 24);
        m.velocity = *lattice_point(s, 8);
        R = *rc::gen::inRange(0, 9) * s;
        break;
      }
    }
    const auto [r, rc] = *split_radius(std::max(R, 0.0));
    m.sphere.radius = r;
    m.capsule.radius = rc;
    return m;
  });
}

void move_sphere_capsule(SphereCapsuleMotion& x, const Vec3& o) {
  x.sphere.center += o;
  x.capsule.axis.a += o;
  x.capsule.axis.b += o;
}
double size_sphere_capsule(const SphereCapsuleMotion& x) {
  return scale_of({x.sphere.center, x.capsule.axis.a, x.capsule.axis.b});
}

void move_sphere_plane(SpherePlaneMotion& x, const Vec3& o) {
  x.sphere.center += o;
  x.plane.offset -= x.plane.normal.dot(o);
}
double size_sphere_plane(const SpherePlaneMotion& x) { return scale_of({x.sphere.center, x.velocity * x.duration}); }
void move_sphere_sphere(SphereSphereMotion& x, const Vec3& o) {
  x.s0.center += o;
  x.s1.center += o;
}
double size_sphere_sphere(const SphereSphereMotion& x) { return scale_of({x.s0.center, x.s1.center}); }
void move_box_plane(BoxPlaneMotion& x, const Vec3& o) {
  x.box.center += o;
  x.plane.offset -= x.plane.normal.dot(o);
}
double size_box_plane(const BoxPlaneMotion& x) { return scale_of({x.box.center, x.velocity * x.duration}); }

rc::Gen<BoxPlaneMotion> box_plane_families(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    const Vec3 x = grid_point(g);
    const Plane plane = plane_through(g, x);
    Box box{grid_point(g), axes(g), Vec3(grid_length(g), grid_length(g), grid_length(g))};
    if (*rc::gen::element(0, 0, 0, 1)) box.half_extents = Vec3::Zero();  // a point
    const double T = duration(g);
    // The box's reach along the unit normal, and its centre placed at a given gap.
    const Vec3 unit = plane.normal.normalized();
    double reach = 0;
    for (int i = 0; i < 3; ++i) reach += box.half_extents[i] * std::abs(unit.dot(box.axes.col(i)));
    const double side = *rc::gen::element(-1.0, 1.0);
    const double size = box.half_extents.maxCoeff();
    const int family =
        *rc::gen::weightedElement<int>({{exact ? 2 : 6, 0}, {2, 1}, {exact ? 2 : 1, 2}, {exact ? 0 : 3, 3}});
    switch (family) {
      case 0: break;
      case 1:  // resting on the plane at t = 0 exactly (exact lattice), or decisively near it
        box.center = x + side * reach * unit;
        break;
      case 2: {  // reaching the plane exactly at T (exact), or just before or after it
        const double gap = grid_length(g) + g.s;
        box.center = x + side * (reach + gap) * unit;
        const double travel = exact ? gap : gap + decisive_hair(motion_scale(box.center, gap * unit, size, plane));
        return BoxPlaneMotion{box, -side * travel / T * unit, plane, T};
      }
      default:  // a hair from resting, straight over x
        box.center = x + side * reach * unit;
        break;
    }
    const Vec3 velocity = velocity_for(g, plane, box.center);
    if (!exact && family != 0)
      box.center += side * decisive_hair(motion_scale(box.center, velocity * T, size, plane)) * unit;
    return BoxPlaneMotion{box, velocity, plane, T};
  });
}

// Every length of an input times k (a power of two: exact, so every family keeps its
// structure): the ends of the header's domain, S from about 1e-40 to 1e40.
void times(Vec3& x, double k) { x *= k; }
void times(double& x, double k) { x *= k; }
void times(Segment& x, double k) {
  times(x.a, k);
  times(x.b, k);
}
void times(Rectangle& x, double k) {
  times(x.center, k);
  times(x.half_u, k);
  times(x.half_v, k);
}
void times(Sphere& x, double k) {
  times(x.center, k);
  times(x.radius, k);
}
void times(Plane& x, double k) { times(x.offset, k); }
void times(Box& x, double k) {
  times(x.center, k);
  times(x.half_extents, k);
}
// The distance queries' inputs (steps 1 and 2) are shapes and points, all lengths: each
// field. A motion's duration is a time, not a length: the motions list their fields below.
template <class Pair, class = codec::HasFields<Pair>> void times(Pair& x, double k) {
  fields(x, [k](const char*, auto& field) { times(field, k); });
}
void times(SpherePlaneMotion& x, double k) {
  times(x.sphere, k);
  times(x.velocity, k);
  times(x.plane, k);
}
void times(SphereSphereMotion& x, double k) {
  times(x.s0, k);
  times(x.s1, k);
  times(x.v0, k);
  times(x.v1, k);
}
void times(SphereCapsuleMotion& x, double k) {
  times(x.sphere, k);
  times(x.velocity, k);
  times(x.capsule.axis, k);
  times(x.capsule.radius, k);
}
void times(BoxPlaneMotion& x, double k) {
  times(x.box, k);
  times(x.velocity, k);
  times(x.plane, k);
}

template <class T> rc::Gen<T> at_extreme_scale(rc::Gen<T> base) {
  return rc::gen::exec([base] {
    T x = *base;
    times(x, std::ldexp(1.0, *rc::gen::element(-110, -100, 90, 100)));
    return x;
  });
}

// A plane's normal of extreme length, 2^j for j from -1000 to 900, the offset with it:
// the same plane (when the offset stays a finite double), whose n . n overflows or
// underflows unless scaled first.
template <class T> rc::Gen<T> with_extreme_normal(rc::Gen<T> base) {
  return rc::gen::exec([base] {
    T x = *base;
    const double k = std::ldexp(1.0, *rc::gen::element(-1000, -700, -540, 500, 520, 700, 900));
    if (std::isfinite(x.plane.offset * k) && (x.plane.offset == 0 || x.plane.offset * k != 0)) {
      x.plane.normal *= k;
      x.plane.offset *= k;
    }
    return x;
  });
}

template <class T>
rc::Gen<T> with_far(rc::Gen<T> families, bool exact, void (*move)(T&, const Vec3&), double (*size)(const T&)) {
  if (exact) return families;
  return rc::gen::weightedOneOf<T>(
      {{14, families},
       {2, far_away(families, move, [size](const T& x) { return std::max(1.0, size(x)); })},
       {1, at_extreme_scale(families)}});
}

}  // namespace

rc::Gen<std::pair<double, double>> split_radius(double total) {
  return rc::gen::exec([total] {
    // r0 in [total / 2, total], so r1 = total - r0 is exact (Sterbenz) and r0 + r1 == total.
    const double r0 = total * (*rc::gen::inRange(4, 9) / 8.0);
    const double r1 = total - r0;
    return *rc::gen::arbitrary<bool>() ? std::make_pair(r0, r1) : std::make_pair(r1, r0);
  });
}

rc::Gen<SphereSphereMotion> grazing_spheres() {
  return rc::gen::exec([] {
    const double s = *scale();
    // The closest approach: the offset P (|P| = n exactly) at time t_c, with B
    // perpendicular to it; A = P - t_c B at t = 0.
    int n = 0;
    const Vec3 P = pythagorean(n);
    const Vec3 B = P.cross(*direction(1.0, 4)) * std::ldexp(1.0, *rc::gen::inRange(0, 10));
    if (B == Vec3::Zero()) return SphereSphereMotion{{P * s, n * s}, Vec3::Zero(), {}, Vec3::Zero(), 1.0};
    const double tc = *rc::gen::inRange(1, 16) / 16.0;
    const Vec3 A = P - tc * B;
    // R = n (1 + e): the closest approach is n, within a decisive hair of R (an exact
    // graze, e = 0, is step 7's).
    const Grid g{s, false};
    return place_near(g, A * s, B * s, n * s, *rc::gen::element(1.0, 1.0, 2.0));
  });
}

rc::Gen<SphereSphereMotion> soon_spheres(bool exact) {
  return rc::gen::exec([exact] {
    const Grid g = *grid(exact);
    // A = Q (|Q| = n <= 9) plus a hair 2^-j along its largest component, outward:
    // c = A.A - n^2 is about 2^-j |Q|, and A.A stays exact in double (2 j + 7 <= 52 bits).
    int n = 0;
    const Vec3 Q = pythagorean(n, 5);
    int axis = 0;
    Q.cwiseAbs().maxCoeff(&axis);
    Vec3 A = Q;
    A[axis] += (Q[axis] > 0 ? 1 : -1) * std::ldexp(1.0, -*rc::gen::inRange(18, 23));
    // Toward each other at a clear angle: B = -k Q + W with |W| small against |Q|.
    const Vec3 B = -Q * double(*rc::gen::inRange(1, 3)) + *lattice_point(1.0, 1);
    return place(g, A * g.s, B * g.s, double(n) * g.s, 1.0);
  });
}

rc::Gen<PointSegmentPair> point_segment(bool exact) {
  return with_far(point_segment_families(exact), exact, move_point_segment, size_point_segment);
}
rc::Gen<SegmentPair> segment_pair(bool exact) {
  return with_far(segment_pair_families(exact), exact, move_segment_pair, size_segment_pair);
}
rc::Gen<PointRectanglePair> point_rectangle(bool exact) {
  return with_far(point_rectangle_families(exact), exact, move_point_rectangle, size_point_rectangle);
}
rc::Gen<SegmentRectanglePair> segment_rectangle(bool exact) {
  return with_far(segment_rectangle_families(exact), exact, move_segment_rectangle, size_segment_rectangle);
}
rc::Gen<RectanglePair> rectangle_pair(bool exact) {
  return with_far(rectangle_pair_families(exact), exact, move_rectangle_pair, size_rectangle_pair);
}
rc::Gen<SpherePlaneMotion> sphere_plane_motion(bool exact) {
  const auto g = with_far(sphere_plane_families(exact), exact, move_sphere_plane, size_sphere_plane);
  return exact ? g : rc::gen::weightedOneOf<SpherePlaneMotion>({{7, g}, {1, with_extreme_normal(g)}});
}
rc::Gen<SphereSphereMotion> sphere_sphere_motion(bool exact) {
  return with_far(sphere_sphere_families(exact), exact, move_sphere_sphere, size_sphere_sphere);
}
rc::Gen<SphereCapsuleMotion> sphere_capsule_motion(bool exact) {
  if (exact) return exact_sphere_capsule_families();
  return with_far(sphere_capsule_families(), false, move_sphere_capsule, size_sphere_capsule);
}
rc::Gen<BoxPlaneMotion> box_plane_motion(bool exact) {
  const auto g = with_far(box_plane_families(exact), exact, move_box_plane, size_box_plane);
  return exact ? g : rc::gen::weightedOneOf<BoxPlaneMotion>({{7, g}, {1, with_extreme_normal(g)}});
}

}  // namespace labkit::gen
