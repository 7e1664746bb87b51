// Lab 05 reference: sphere-swept volumes, static and moving.
//
// Two ideas carry the lab.
//  - Table 6.1: two sphere-swept volumes meet exactly when their cores (point, segment,
//    rectangle) are within r0 + r1. So the work is distances between cores, and each
//    distance is a small convex minimisation whose minimum sits at a few candidate
//    places: the interior critical point when it is inside, else on the border.
//  - Decide, then construct (as in lab 02). A yes/no is decided by comparing a squared
//    distance written as num / den without dividing (num <= R^2 den): on small-integer
//    input every such product is exact, so "exactly touching" comes out exactly. Points
//    and times are built afterwards and carry the rounding.
// For moving spheres the quadratic's roots are taken in the form that never subtracts
// nearly equal numbers, and the closest approach in the form that never subtracts two
// big squares (the cross product), so nearly-grazing cases keep their accuracy.
#include "sphere_sweeps.h"

#include "common/preconditions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace labkit::lab05 {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double square(double x) { return x * x; }

// ---- The header's preconditions: std::invalid_argument naming the argument and the rule --

using namespace preconditions;
using preconditions::require_valid;  // beside the overloads for this lab's shapes below

void require_valid(const char* query, const std::string& name, const Rectangle& r) {
  require_finite(query, name + ".center", r.center);
  require_unit(query, name + ".u", r.u);
  require_unit(query, name + ".v", r.v);
  require_perpendicular(query, name + ".u and " + name + ".v", r.u, r.v);
  require_size(query, name + ".half_u", r.half_u);
  require_size(query, name + ".half_v", r.half_v);
}
void require_valid(const char* query, const std::string& name, const Capsule& c) {
  require_valid(query, name + ".axis", c.axis);
  require_size(query, name + ".radius", c.radius);
}
void require_valid(const char* query, const std::string& name, const Lozenge& l) {
  require_valid(query, name + ".rectangle", l.rectangle);
  require_size(query, name + ".radius", l.radius);
}
void require_valid(const char* query, const std::string& name, const Plane& p) {
  require_finite(query, name + ".normal", p.normal);
  require_finite(query, name + ".offset", p.offset);
  require(p.normal != Vec3::Zero(), query, name + ".normal", "be non-zero", p.normal);
}
void require_motion(const char* query, const Vec3& velocity, const char* velocity_name, double duration) {
  require_finite(query, velocity_name, velocity);
  require_size(query, "duration", duration);
}

// The same plane with its normal scaled by a power of two so that the largest component
// lies in [1, 2): n . n can then neither overflow (|n| above ~1e154) nor underflow (|n|
// below ~1e-162), and because the factor is a power of two every product stays exactly
// what it was, only shifted: on small integers the decisions stay exact.
Plane scaled(const Plane& plane) {
  const int e = std::ilogb(plane.normal.cwiseAbs().maxCoeff());
  return {Vec3(std::ldexp(plane.normal.x(), -e), std::ldexp(plane.normal.y(), -e), std::ldexp(plane.normal.z(), -e)),
          std::ldexp(plane.offset, -e)};
}

// a + t (b - a), landing exactly on b at t = 1.
Vec3 point_at(const Segment& s, double t) { return t == 1.0 ? s.b : Vec3(s.a + t * (s.b - s.a)); }

// ---- Division-free "within" tests (the decisions of step 3) ----------------------------

// Is p within sqrt(r2) of the closed segment? The regions of point_segment, compared
// without dividing: the squared distance to the line is |w x d|^2 / |d|^2.
bool point_segment_within(const Vec3& p, const Segment& s, double r2) {
  const Vec3 d = s.b - s.a, w = p - s.a;
  const double wd = w.dot(d);
  if (wd <= 0) return w.squaredNorm() <= r2;  // a is nearest (also when a == b)
  const double dd = d.squaredNorm();
  if (wd >= dd) return (p - s.b).squaredNorm() <= r2;  // b is nearest
  return w.cross(d).squaredNorm() <= r2 * dd;
}

// Are the segments within sqrt(r2)? Either an end is (the border of the (s, t) square),
// or the lines' closest points lie inside both segments and the lines are that close:
// with n = d0 x d1, the lines' distance is |w . n| / |n|, and the closest points have
// s = ((w x d1) . n) / |n|^2, t = ((w x d0) . n) / |n|^2.
bool segment_segment_within(const Segment& s0, const Segment& s1, double r2) {
  if (point_segment_within(s0.a, s1, r2) || point_segment_within(s0.b, s1, r2) || point_segment_within(s1.a, s0, r2) ||
      point_segment_within(s1.b, s0, r2))
    return true;
  const Vec3 d0 = s0.b - s0.a, d1 = s1.b - s1.a, w = s1.a - s0.a;
  const Vec3 n = d0.cross(d1);
  const double nn = n.squaredNorm();
  if (nn == 0) return false;  // parallel (or a zero-length segment): the ends decided
  const double s = w.cross(d1).dot(n), t = w.cross(d0).dot(n);
  if (s < 0 || s > nn || t < 0 || t > nn) return false;  // the lines meet nearest outside: the ends decided
  // Nearly parallel (sin^2 of the angle below 1e-10): n is then mostly rounding, and w . n
  // picks up w's long component along the lines, so it no longer measures their distance.
  // Measure the pair itself: any pair of points is at least the true distance apart, and
  // when the segments really cross at such an angle the pair found is accurate.
  // Step 3 (the step 8 recipe read alone): (w . n)^2 <= R^2 |n|^2 for lines that are parallel
  // only up to rounding, where the rounded n says nothing about their distance.
  // mutant parallel_in_floating_point (step 3, "nearly parallel", "measure the pair"):
  //   `if (nn < 1e-10 * d0.squaredNorm() * d1.squaredNorm()) return point_segment_within(point_at(s0, s / nn), s1,
  //     r2);`
  //   -> ``
  if (nn < 1e-10 * d0.squaredNorm() * d1.squaredNorm()) return point_segment_within(point_at(s0, s / nn), s1, r2);
  return square(w.dot(n)) <= r2 * nn;
}

// The rectangle's corner k: signs (k & 1 ? + : -) along u and (k & 2 ? + : -) along v.
//
//    c2 ------- c3        side 0: c0 c1, side 1: c1 c3,
//    |     v ^   |        side 2: c3 c2, side 3: c2 c0
//    |       +-> u
//    c0 ------- c1
Vec3 corner(const Rectangle& r, int k) {
  return r.center + (k & 1 ? r.half_u : -r.half_u) * r.u + (k & 2 ? r.half_v : -r.half_v) * r.v;
}
Segment side(const Rectangle& r, int i) {
  static const int from[4] = {0, 1, 3, 2}, to[4] = {1, 3, 2, 0};
  return {corner(r, from[i]), corner(r, to[i])};
}
// Rectangle coordinates (s, t) of the point `tau` of the way along side i.
Vec2 side_coordinates(const Rectangle& r, int i, double tau) {
  static const int from[4] = {0, 1, 3, 2}, to[4] = {1, 3, 2, 0};
  const auto at = [&](int k) { return Vec2(k & 1 ? r.half_u : -r.half_u, k & 2 ? r.half_v : -r.half_v); };
  return at(from[i]) + tau * (at(to[i]) - at(from[i]));
}

// Where the segment crosses the rectangle's plane, as a fraction num / den of the way
// from a to b, if that point is inside the closed rectangle. With f = (x - c) . (u x v)
// the heights of the ends, the crossing is (f_a b - f_b a) / (f_a - f_b); its rectangle
// coordinates times (f_a - f_b) are f_a s_b - f_b s_a and f_a t_b - f_b t_a, compared
// with the half-sizes times |f_a - f_b|: no division.
struct Crossing {
  bool inside = false;
  double num = 0.0, den = 1.0;  // the crossing is a + (num / den) (b - a)
};
Crossing crossing(const Segment& seg, const Rectangle& r) {
  const Vec3 n = r.u.cross(r.v);
  const Vec3 wa = seg.a - r.center, wb = seg.b - r.center;
  const double fa = wa.dot(n), fb = wb.dot(n);
  if ((fa > 0 && fb > 0) || (fa < 0 && fb < 0)) return {};  // both ends strictly on one side
  if (fa == 0 && fb == 0) return {};                        // in the plane: the ends and the sides decide
  const double den = fa - fb;
  const double s = fa * wb.dot(r.u) - fb * wa.dot(r.u), t = fa * wb.dot(r.v) - fb * wa.dot(r.v);
  if (std::abs(s) > r.half_u * std::abs(den) || std::abs(t) > r.half_v * std::abs(den)) return {};  // beside it
  return {true, fa, den};
}

bool point_rectangle_within(const Vec3& p, const Rectangle& r, double r2) {
  return point_rectangle(p, r).squared_distance <= r2;  // no division: exact on small integers
}

// The segment meets the rectangle, or an end is within reach of it, or the segment is
// within reach of one of its sides: the same candidates as segment_rectangle.
bool segment_rectangle_within(const Segment& seg, const Rectangle& r, double r2) {
  if (crossing(seg, r).inside) return true;
  if (point_rectangle_within(seg.a, r, r2) || point_rectangle_within(seg.b, r, r2)) return true;
  for (int i = 0; i < 4; ++i)
    if (segment_segment_within(seg, side(r, i), r2)) return true;
  return false;
}

// ---- Sweeps -----------------------------------------------------------------------------

Sweep overlapping() { return {SweepStatus::overlapping, 0.0, Vec3::Zero()}; }

// A shape whose value f(t) = f0 + g t against the plane (|normal| times the signed
// distance of its centre) must come within `reach` (|normal| times its radius):
// the lecture's |N . C(t) - d| = r, solved from the side it starts on.
struct PlaneApproach {
  bool contact = false;
  double side = 1.0;  // the side the centre starts on: sign(f0)
  double time = 0.0;
};
PlaneApproach approach_plane(double f0, double g, double reach, double reach2, double duration) {
  PlaneApproach a;
  // A one-sided plane: only the front side is ever approached.
  // mutant one_sided_plane (step 4, "two-sided"): `a.side = f0 > 0 ? 1.0 : -1.0;` -> `a.side = 1.0;`
  a.side = f0 > 0 ? 1.0 : -1.0;
  // Moving away from the plane, or along it (the lecture's "T < 0"): never.
  if (a.side * g >= 0) return a;
  // Still clear at the end of the step: |f(T)| > reach on the starting side.
  const double end = a.side * (f0 + g * duration);
  if (end > 0 && square(end) > reach2) return a;
  a.contact = true;
  // side * f(t) falls from side * f0 to reach at t = (side f0 - reach) / (-side g).
  // The later root: the time the sphere leaves the plane on the far side.
  // mutant plane_later_root (step 4, "later root"): `f0 - reach` -> `f0 + reach`
  a.time = std::clamp((a.side * f0 - reach) / (-a.side * g), 0.0, duration);
  return a;
}

}  // namespace

// ---- Step 1 --------------------------------------------------------------------------------

PointSegmentDistance point_segment(const Vec3& p, const Segment& segment) {
  require_finite("point_segment", "p", p);
  require_valid("point_segment", "segment", segment);
  // Minimise |a + t d - p|^2 over t: the derivative vanishes at t = (p - a) . d / (d . d);
  // the function is a parabola, so outside [0, 1] the nearer end wins.
  const Vec3 d = segment.b - segment.a;
  const double wd = (p - segment.a).dot(d), dd = d.squaredNorm();
  PointSegmentDistance r;
  if (wd <= 0 || dd == 0)
    r.t = 0.0;  // behind a, or a zero-length segment
  else if (wd >= dd)
    r.t = 1.0;  // beyond b
  else
    r.t = wd / dd;
  r.closest = point_at(segment, r.t);
  r.squared_distance = (p - r.closest).squaredNorm();
  return r;
}

//   Derivation. F(s, t) = |a0 + s d0 - a1 - t d1|^2 is a convex quadratic on the square
//   [0, 1]^2. Its minimum is the lines' closest pair when that pair lies inside the
//   square; otherwise it is on the square's border, where one parameter is 0 or 1: an
//   end against the other segment, which point_segment solves exactly. The lines'
//   pair, with w = a1 - a0 and n = d0 x d1 (crossing a0 + s d0 + h n = a1 + t d1 with
//   d1, then d0, and dotting with n):
//
//       s = ((w x d1) . n) / |n|^2,   t = ((w x d0) . n) / |n|^2.
//
//   The textbook form s = (b e - c d) / (a c - b^2) divides by a c - b^2, which cancels
//   catastrophically for nearly parallel segments; |n|^2 is the same number (Lagrange's
//   identity) computed without that cancellation.
//
//   Parallel segments (n = 0) have no single lines' pair: the border candidates hold a
//   closest pair, and we return the first minimal one.
SegmentSegmentDistance segment_segment(const Segment& first, const Segment& second) {
  require_valid("segment_segment", "first", first);
  require_valid("segment_segment", "second", second);
  SegmentSegmentDistance best;
  best.squared_distance = kInfinity;
  const auto consider = [&](double s, double t, const Vec3& p, const Vec3& q) {
    const double d2 = (p - q).squaredNorm();
    if (d2 < best.squared_distance) best = {d2, s, t, p, q};
  };

  const Vec3 d0 = first.b - first.a, d1 = second.b - second.a;
  const Vec3 n = d0.cross(d1);
  // The textbook denominator a c - b^2, which cancels for nearly parallel segments
  // (caught by the family of segments crossing at an angle of 2^-20 to 2^-27).
  // mutant textbook_denominator (step 1, "nearly parallel", "|d0 x d1|^2"):
  //   `n.squaredNorm(`
  //   -> `d0.squaredNorm() * d1.squaredNorm() - square(d0.dot(d1)`
  const double nn = n.squaredNorm();
  if (nn > 0) {
    const Vec3 w = second.a - first.a;
    // Clamping the lines' closest pair into [0, 1]^2 instead of re-projecting an end.
    // mutant clamp_not_reproject (step 1, "re-projected", "nearer pair"):
    //   `const double s = w.cross(d1).dot(n) / nn, t = w.cross(d0).dot(n) / nn; if (s >= 0 && s <= 1 && t >= 0 && t <=
    //     1) {`
    //   -> `const double s = std::clamp(w.cross(d1).dot(n) / nn, 0.0, 1.0), t = std::clamp(w.cross(d0).dot(n) / nn,
    //     0.0, 1.0); { consider(s, t, point_at(first, s), point_at(second, t)); if (nn > 0) return best;`
    const double s = w.cross(d1).dot(n) / nn, t = w.cross(d0).dot(n) / nn;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
      // The point at s, then its projection onto the second segment. For nearly parallel
      // segments s and t each carry a rounding error along the lines (a small error of
      // the numerators over a tiny |n|^2), and the two errors do not cancel: the pair
      // would lie farther apart than the segments. Projecting ties q to p, so the pair is
      // as far apart as p from the second segment: the true distance, to rounding.
      const Vec3 p = point_at(first, s);
      const PointSegmentDistance q = point_segment(p, second);
      consider(s, q.t, p, q.closest);
      // Clearly not parallel (sin^2 of the angle above 1e-4): this pair is accurate and,
      // being the unconstrained minimum, no border point beats it.
      if (nn > 1e-4 * d0.squaredNorm() * d1.squaredNorm()) return best;
    }
  }
  // The border: each end against the other segment.
  for (double s : {0.0, 1.0}) {
    const Vec3 p = s == 0 ? first.a : first.b;
    const PointSegmentDistance e = point_segment(p, second);
    consider(s, e.t, p, e.closest);
  }
  for (double t : {0.0, 1.0}) {
    const Vec3 q = t == 0 ? second.a : second.b;
    const PointSegmentDistance e = point_segment(q, first);
    consider(e.t, t, e.closest, q);
  }
  return best;
}

// ---- Step 2 --------------------------------------------------------------------------------

PointRectangleDistance point_rectangle(const Vec3& p, const Rectangle& rectangle) {
  require_finite("point_rectangle", "p", p);
  require_valid("point_rectangle", "rectangle", rectangle);
  // In the rectangle's frame the squared distance is (s - s_p)^2 + (t - t_p)^2 + h^2,
  // with s_p = (p - c) . u, t_p = (p - c) . v: each coordinate is minimised on its own,
  // by clamping to the half-size. h, the height above the plane, is whatever it is.
  const Vec3 w = p - rectangle.center;
  PointRectangleDistance r;
  // Projecting onto the plane and forgetting to clamp to the rectangle.
  // mutant no_clamp_to_rectangle (step 2, "clamp", "half-sizes"):
  //   `r.s = std::clamp(w.dot(rectangle.u), -rectangle.half_u, rectangle.half_u);`
  //   -> `r.s = w.dot(rectangle.u);`
  r.s = std::clamp(w.dot(rectangle.u), -rectangle.half_u, rectangle.half_u);
  r.t = std::clamp(w.dot(rectangle.v), -rectangle.half_v, rectangle.half_v);
  r.closest = rectangle.center + r.s * rectangle.u + r.t * rectangle.v;
  r.squared_distance = (p - r.closest).squaredNorm();
  return r;
}

//   Both shapes are convex. If the segment pierces the rectangle the distance is 0, at
//   the crossing. Otherwise a closest pair has an end of the segment in it, or a point of
//   the rectangle's border (if both points were interior, the segment would run parallel
//   to the rectangle there and could slide to an end or the border without getting
//   farther). So: two ends against the rectangle, the segment against four sides.
SegmentRectangleDistance segment_rectangle(const Segment& segment, const Rectangle& rectangle) {
  require_valid("segment_rectangle", "segment", segment);
  require_valid("segment_rectangle", "rectangle", rectangle);
  SegmentRectangleDistance best;
  const Crossing x = crossing(segment, rectangle);
  if (x.inside) {
    best.r = std::clamp(x.num / x.den, 0.0, 1.0);
    best.closest0 = point_at(segment, best.r);
    const PointRectangleDistance on = point_rectangle(best.closest0, rectangle);
    best.s = on.s;
    best.t = on.t;
    best.closest1 = on.closest;
    best.squared_distance = on.squared_distance;
    return best;
  }
  best.squared_distance = kInfinity;
  for (double r : {0.0, 1.0}) {
    const Vec3 p = r == 0 ? segment.a : segment.b;
    const PointRectangleDistance e = point_rectangle(p, rectangle);
    if (e.squared_distance < best.squared_distance) best = {e.squared_distance, r, e.s, e.t, p, e.closest};
  }
  // Segment-rectangle from the ends alone, forgetting the four sides.
  // mutant ends_only (step 2, "nearer pair", "four sides"): `i < 4` -> `i < 0`
  for (int i = 0; i < 4; ++i) {
    const SegmentSegmentDistance e = segment_segment(segment, side(rectangle, i));
    if (e.squared_distance >= best.squared_distance) continue;  // not nearer
    const Vec2 st = side_coordinates(rectangle, i, e.t);
    best = {e.squared_distance, e.s, st.x(), st.y(), e.closest0, e.closest1};
  }
  return best;
}

//   The same argument once more: a closest pair of two rectangles has a point of some
//   side of one of them, and a side that meets the other rectangle is at distance 0. So
//   the nearest of the eight sides, each against the other rectangle.
RectangleRectangleDistance rectangle_rectangle(const Rectangle& first, const Rectangle& second) {
  require_valid("rectangle_rectangle", "first", first);
  require_valid("rectangle_rectangle", "second", second);
  RectangleRectangleDistance best;
  best.squared_distance = kInfinity;
  for (int i = 0; i < 4; ++i) {
    const SegmentRectangleDistance e = segment_rectangle(side(first, i), second);
    if (e.squared_distance < best.squared_distance) best = {e.squared_distance, e.closest0, e.closest1};
  }
  for (int i = 0; i < 4; ++i) {
    const SegmentRectangleDistance e = segment_rectangle(side(second, i), first);
    // rectangle_rectangle asks segment_rectangle with B's side first (B against A) and
    // keeps its points as they come: closest0 lands on the second rectangle, closest1 on the first.
    // mutant swapped_call_not_swapped_back (step 2, "closest0", "swapped"):
    //   `closest1, e.closest0`
    //   -> `closest0, e.closest1`
    if (e.squared_distance < best.squared_distance) best = {e.squared_distance, e.closest1, e.closest0};
  }
  return best;
}

// ---- Step 3 --------------------------------------------------------------------------------
// Table 6.1: the distance between the cores against r0 + r1, squared, decided without
// dividing. (Comparing the constructed squared_distance with R^2 would round: exactly
// touching capsules could come out a hair apart.)

bool test_sphere_sphere(const Sphere& a, const Sphere& b) {
  require_valid("test_sphere_sphere", "a", a);
  require_valid("test_sphere_sphere", "b", b);
  return (a.center - b.center).squaredNorm() <= square(a.radius + b.radius);
}

bool test_sphere_capsule(const Sphere& a, const Capsule& b) {
  require_valid("test_sphere_capsule", "a", a);
  require_valid("test_sphere_capsule", "b", b);
  return point_segment_within(a.center, b.axis, square(a.radius + b.radius));
}

bool test_sphere_lozenge(const Sphere& a, const Lozenge& b) {
  require_valid("test_sphere_lozenge", "a", a);
  require_valid("test_sphere_lozenge", "b", b);
  return point_rectangle_within(a.center, b.rectangle, square(a.radius + b.radius));
}

bool test_capsule_capsule(const Capsule& a, const Capsule& b) {
  require_valid("test_capsule_capsule", "a", a);
  require_valid("test_capsule_capsule", "b", b);
  // r0^2 + r1^2 instead of (r0 + r1)^2.
  // mutant sum_of_squares (step 3, "(r0 + r1)^2"):
  //   `square(a.radius + b.radius)`
  //   -> `square(a.radius) + square(b.radius)`
  // Deciding on the constructed (rounded) distance instead of division-free products.
  // mutant decide_on_rounded_distance (step 9, "exact products"):
  //   `return segment_segment_within(a.axis, b.axis, square(a.radius + b.radius));`
  //   -> `return segment_segment(a.axis, b.axis).squared_distance <= square(a.radius + b.radius);`
  return segment_segment_within(a.axis, b.axis, square(a.radius + b.radius));
}

bool test_capsule_lozenge(const Capsule& a, const Lozenge& b) {
  require_valid("test_capsule_lozenge", "a", a);
  require_valid("test_capsule_lozenge", "b", b);
  return segment_rectangle_within(a.axis, b.rectangle, square(a.radius + b.radius));
}

bool test_lozenge_lozenge(const Lozenge& a, const Lozenge& b) {
  require_valid("test_lozenge_lozenge", "a", a);
  require_valid("test_lozenge_lozenge", "b", b);
  const double r2 = square(a.radius + b.radius);
  for (int i = 0; i < 4; ++i)
    if (segment_rectangle_within(side(a.rectangle, i), b.rectangle, r2)) return true;
  // Two lozenges by the sides of the first one only.
  // mutant one_lozenges_sides (step 3, "the sides of both"):
  //   `for (int i = 0; i < 4; ++i) if (segment_rectangle_within(side(b.rectangle, i), a.rectangle, r2)) return true;`
  //   -> ``
  for (int i = 0; i < 4; ++i)
    if (segment_rectangle_within(side(b.rectangle, i), a.rectangle, r2)) return true;
  return false;
}

// ---- Step 4 --------------------------------------------------------------------------------

Sweep sweep_sphere_plane(const Sphere& sphere, const Vec3& velocity, const Plane& given, double duration) {
  require_valid("sweep_sphere_plane", "sphere", sphere);
  require_motion("sweep_sphere_plane", velocity, "velocity", duration);
  require_valid("sweep_sphere_plane", "plane", given);
  // With f(t) = normal . c(t) + offset = f0 + g t, the signed distance is f / |normal|:
  // compare f with r |normal| rather than normalising (the normal need not be unit).
  // First the plane is rescaled by a power of two, so that n . n is a normal double. A
  // sphere touching or cutting the plane now is overlapping.
  // A plane whose normal is not unit length, used as if it were.
  // mutant unnormalised_normal (step 4, "is n unit"):
  //   `const Plane plane = scaled(given); const double f0 = plane.value(sphere.center), g = plane.normal.dot(velocity);
  //     const double nn = plane.normal.squaredNorm(), r = sphere.radius; if (square(f0) <= square(r) * nn) return
  //     overlapping(); const PlaneApproach a = approach_plane(f0, g, r * std::sqrt(nn), square(r) * nn, duration);`
  //   -> `const Plane plane = given; const double f0 = plane.value(sphere.center), g = plane.normal.dot(velocity);
  //     const double nn = plane.normal.squaredNorm(), r = sphere.radius; if (std::abs(f0) <= r) return overlapping();
  //     const PlaneApproach a = approach_plane(f0, g, r, square(r), duration);`
  // The plane not offset by the radius: the time the centre reaches the plane itself,
  // after the sphere has already cut into it.
  // mutant centre_reaches_plane (step 4, "gap reaches 0", "centre itself reaches the plane"):
  //   `r * std::sqrt(nn), square(r) * nn`
  //   -> `0.0, 0.0`
  const Plane plane = scaled(given);
  const double f0 = plane.value(sphere.center), g = plane.normal.dot(velocity);
  const double nn = plane.normal.squaredNorm(), r = sphere.radius;
  if (square(f0) <= square(r) * nn) return overlapping();
  const PlaneApproach a = approach_plane(f0, g, r * std::sqrt(nn), square(r) * nn, duration);
  if (!a.contact) return {};  // moving away, along it, or not there yet at T
  const Vec3 center = sphere.center + a.time * velocity;
  return {SweepStatus::contact, a.time, center - a.side * r * plane.normal / std::sqrt(nn)};
}

// ---- Step 5 --------------------------------------------------------------------------------

//   Derivation (lecture 002). In relative motion sphere 1 stands still and the centre of
//   sphere 0 moves along A + t B, A = c0 - c1, B = v0 - v1. They touch when
//   |A + t B| = R = r0 + r1:
//
//       a t^2 + 2 b t + c = 0,   a = B.B,  b = A.B,  c = A.A - R^2,
//       t = (-b -+ sqrt(b^2 - a c)) / a.
//
//   Special cases first: c <= 0 (touching now); a = 0 (no relative motion: the distance
//   never changes); b >= 0 (the distance grows from the start); b^2 - a c < 0 (the
//   closest approach, d^2 = A.A - b^2 / a, stays above R). b^2 - a c = a R^2 - |A x B|^2
//   (Lagrange's identity): the cross product gives it without subtracting two large
//   squares when the spheres start far apart compared with their size.
//
//   The first root, stably. With b < 0, -b + sqrt(b^2 - ac) adds two positive numbers:
//   q = -b + sqrt(b^2 - ac) is accurate, and the two roots are c / q (the first) and q / a.
//   The textbook (-b - sqrt(b^2 - ac)) / a subtracts two nearly equal numbers when a c is
//   small against b^2 (the spheres start a hair apart): its time is then mostly noise.
Sweep sweep_sphere_sphere(const Sphere& s0, const Vec3& v0, const Sphere& s1, const Vec3& v1, double duration) {
  require_valid("sweep_sphere_sphere", "s0", s0);
  require_valid("sweep_sphere_sphere", "s1", s1);
  require_motion("sweep_sphere_sphere", v0, "v0", duration);
  require_finite("sweep_sphere_sphere", "v1", v1);
  const Vec3 A = s0.center - s1.center, B = v0 - v1;
  const double R = s0.radius + s1.radius;
  const double c = A.squaredNorm() - R * R;
  // Touching at t = 0 not counted as overlapping (a strict comparison).
  // mutant touching_not_overlapping (step 5, "touching", "overlapping"): `<=` -> `<`
  if (c <= 0) return overlapping();  // touching or overlapping at t = 0
  const double a = B.squaredNorm();
  if (a == 0) return {};  // no relative motion: the gap stays what it is
  const double b = A.dot(B);
  // Forgetting that spheres moving apart never meet (a negative root is reported).
  // mutant moving_apart_forgotten (step 5, "move apart"): `if (b >= 0) return {};` -> ``
  if (b >= 0) return {};  // moving apart or sideways: the gap only grows
  const double disc = a * R * R - A.cross(B).squaredNorm();
  // An exact graze (b^2 = ac) dismissed as a miss.
  // mutant graze_is_a_miss (step 5, "graze"): `disc <` -> `disc <=`
  if (disc < 0) return {};  // the closest approach misses
  // The distance falls until t = -b / a. If that is after T, contact needs |A + T B| <= R.
  if (-b > a * duration && (A + duration * B).squaredNorm() > R * R) return {};  // not there yet at T
  const double q = -b + std::sqrt(disc);
  // The textbook root (-b - sqrt(b^2 - ac)) / a, which cancels when contact is soon.
  // mutant cancelling_root (step 5, "cancel"): `c / q, duration)` -> `(-b - std::sqrt(disc)) / a, duration); (void)q`
  // The later root q / a (when the spheres part again) for the first contact.
  // mutant sphere_later_root (step 5, "later root"): `c / q` -> `q / a`
  const double t = std::min(c / q, duration);
  // The point of contact: on the segment between the centres, r0 / R of the way.
  const Vec3 p = s0.center + t * v0, relative = A + t * B;
  return {SweepStatus::contact, t, R > 0 ? Vec3(p - (s0.radius / R) * relative) : p};
}

// ---- Step 6 --------------------------------------------------------------------------------

namespace {

// The first time a point moving along m + t v (m relative to the sphere's centre) comes
// within sqrt(R2) of it, given that it starts outside: step 5's quadratic with a stable
// root, or infinity when it never does (no motion, moving away, or the line misses).
double first_time_sphere(const Vec3& m, const Vec3& v, double R2) {
  const double a = v.squaredNorm(), b = m.dot(v), c = m.squaredNorm() - R2;
  if (a == 0 || b >= 0) return kInfinity;
  const double disc = a * R2 - m.cross(v).squaredNorm();  // b^2 - ac, Lagrange's identity
  if (disc < 0) return kInfinity;
  return c / (-b + std::sqrt(disc));
}

// The first time the point m + t v (m relative to the axis's end a) comes within sqrt(R2)
// of the axis's infinite line, if it does so between the two end planes (the slab
// 0 <= x . d <= d . d); else infinity. Distances to the line are |x x d| / |d|, so the
// quadratic is step 5's with every vector crossed with d:
//   |(m + t v) x d|^2 = R^2 |d|^2:  a = |v x d|^2, b = (m x d) . (v x d), c = |m x d|^2 - R^2 |d|^2,
// and b^2 - ac = |d|^2 (a R^2 - ((m x d) . v)^2): the triple product is the lines'
// distance times |v x d|, taken without subtracting two big squares.
double first_time_cylinder(const Vec3& m, const Vec3& v, const Vec3& d, double R2) {
  const double dd = d.squaredNorm();
  if (dd == 0) return kInfinity;  // a zero-length axis: only the end spheres
  const Vec3 md = m.cross(d), vd = v.cross(d);
  const double a = vd.squaredNorm(), b = md.dot(vd), c = md.squaredNorm() - R2 * dd;
  // Parallel to the axis (a = 0) the distance to the line never changes; moving away from
  // the line (b >= 0), or starting inside the infinite cylinder (c <= 0; outside the
  // capsule, so beyond an end: the end sphere is met first), the side is never entered.
  if (a == 0 || b >= 0 || c <= 0) return kInfinity;
  // b^2 - ac = dd * disc, and its root is |d| sqrt(disc): disc is of degree 6 in the
  // lengths, the header's bound; the product dd * disc, of degree 8, underflows to
  // subnormals when S is near 1e-40.
  const double disc = a * R2 - square(md.dot(v));
  if (disc < 0) return kInfinity;  // the line of motion passes the cylinder by
  // The later root of the side (when the centre leaves the grown capsule).
  // mutant capsule_later_root (step 6, "later root"):
  //   `const double t = c / (-b + std::sqrt(dd) * std::sqrt(disc));`
  //   -> `const double t = (-b + std::sqrt(dd) * std::sqrt(disc)) / a;`
  const double t = c / (-b + std::sqrt(dd) * std::sqrt(disc));
  // Clip to the slab: a root beyond an end plane hits the infinite cylinder where the
  // capsule has no side; there the end sphere decides.
  const double along = (m + t * v).dot(d);
  // The infinite cylinder's root taken without clipping it to the slab.
  // mutant unclipped_cylinder (step 6, "slab"):
  //   `return along >= 0 && along <= dd ? t : kInfinity;`
  //   -> `(void)along; return t;`
  return along >= 0 && along <= dd ? t : kInfinity;
}

}  // namespace

//   Derivation (lecture 000's table 6.6, lecture 002's swept sphere). A sphere of radius
//   r touches the capsule (axis, rc) exactly when its centre touches the Minkowski sum of
//   the capsule and the sphere: the capsule (axis, R = r + rc). So the centre is a point
//   moving on the ray c + t v, and the grown capsule is the union of three pieces: the
//   side (the infinite cylinder of radius R, clipped to the slab between the end planes)
//   and two end spheres of radius R at a and b. The first contact with a union is the
//   earliest first contact with its pieces. The side's own first root is taken only when
//   it lies in the slab: outside, the ray met the cylinder where the capsule has a cap,
//   and the cap's sphere is met first (crossing an end plane within R of the axis is being
//   within R of that end). The later roots are when the centre leaves a piece, never
//   the first contact.
//
//   Decide, then construct. Whether contact happens in [0, T] is step 3's question: the
//   sphere's path over [0, T] is the capsule (c, c + T v; r), and it meets this capsule
//   exactly when the segments are within R, decided without dividing. Only then are the
//   roots built; if rounding loses all three at an exact graze, the path's closest
//   approach is the contact.
Sweep sweep_sphere_capsule(const Sphere& sphere, const Vec3& velocity, const Capsule& capsule, double duration) {
  require_valid("sweep_sphere_capsule", "sphere", sphere);
  require_motion("sweep_sphere_capsule", velocity, "velocity", duration);
  require_valid("sweep_sphere_capsule", "capsule", capsule);
  const Segment& axis = capsule.axis;
  // The capsule grown by its own radius only (the sphere's radius forgotten).
  // mutant grown_by_one_radius (step 6, "Minkowski"):
  //   `const double R = sphere.radius + capsule.radius, R2 = square(R);`
  //   -> `const double R = capsule.radius, R2 = square(R);`
  const double R = sphere.radius + capsule.radius, R2 = square(R);
  if (point_segment_within(sphere.center, axis, R2)) return overlapping();  // touching or inside now
  const Segment path{sphere.center, sphere.center + duration * velocity};
  if (!segment_segment_within(path, axis, R2)) return {};  // the swept sphere misses it
  const Vec3 d = axis.b - axis.a;
  double t = std::min({first_time_cylinder(sphere.center - axis.a, velocity, d, R2),
                       // The grown capsule without its caps: only the side's root (and the fallback).
                       // mutant forgotten_caps (step 6, "caps"):
                       //   `first_time_sphere(sphere.center - axis.a, velocity, R2), first_time_sphere(sphere.center -
                       //     axis.b, velocity, R2)});`
                       //   -> `kInfinity});`
                       first_time_sphere(sphere.center - axis.a, velocity, R2),
                       first_time_sphere(sphere.center - axis.b, velocity, R2)});
  if (!(t <= duration)) t = segment_segment(path, axis).s * duration;  // a graze lost to rounding
  t = std::clamp(t, 0.0, duration);
  // The point: the sphere's point nearest the axis, r / R of the way from c(t) to q(t).
  const Vec3 center = sphere.center + t * velocity;
  const Vec3 q = point_segment(center, axis).closest;
  return {SweepStatus::contact, t, R > 0 ? Vec3(center + (sphere.radius / R) * (q - center)) : center};
}

// ---- Step 7 --------------------------------------------------------------------------------

Sweep sweep_box_plane(const Box& box, const Vec3& velocity, const Plane& given, double duration) {
  require_valid("sweep_box_plane", "box", box);
  require_motion("sweep_box_plane", velocity, "velocity", duration);
  require_valid("sweep_box_plane", "plane", given);
  const Plane plane = scaled(given);  // as in step 4: any normal length, no overflow
  // The box reaches sum_i h_i |n . axis_i| / |n| from its centre along the unit normal
  // (project each half-size on the normal line; the corner that reaches farthest takes
  // every term with its own sign). Multiply through by |n|: then f and the reach are
  // compared without a square root.
  double reach = 0.0;
  // The projected radius without absolute values.
  // mutant signed_projection (step 7, "absolute value"):
  //   `reach += box.half_extents[i] * std::abs(plane.normal.dot(box.axes.col(i)));`
  //   -> `reach += box.half_extents[i] * plane.normal.dot(box.axes.col(i));`
  // A box's reach toward the plane taken as its bounding sphere's radius |h|: it
  // meets the plane too early.
  // mutant box_bounding_sphere (step 7, "bounding sphere"):
  //   `for (int i = 0; i < 3; ++i) reach += box.half_extents[i] * std::abs(plane.normal.dot(box.axes.col(i)));`
  //   -> `reach = box.half_extents.norm() * plane.normal.norm();`
  for (int i = 0; i < 3; ++i) reach += box.half_extents[i] * std::abs(plane.normal.dot(box.axes.col(i)));
  const double f0 = plane.value(box.center), g = plane.normal.dot(velocity);
  if (std::abs(f0) <= reach) return overlapping();  // resting on it or cutting it now
  const PlaneApproach a = approach_plane(f0, g, reach, square(reach), duration);
  if (!a.contact) return {};
  // The point: the corner nearest the plane, on the side the box comes from; an axis
  // parallel to the plane (n . axis = 0) keeps the middle of that face or edge.
  Vec3 point = box.center + a.time * velocity;
  for (int i = 0; i < 3; ++i) {
    const double along = plane.normal.dot(box.axes.col(i));
    const double sign = along > 0 ? 1.0 : (along < 0 ? -1.0 : 0.0);
    point -= a.side * sign * box.half_extents[i] * box.axes.col(i);
  }
  return {SweepStatus::contact, a.time, point};
}

}  // namespace labkit::lab05
