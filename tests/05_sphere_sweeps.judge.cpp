#include "05_sphere_sweeps.judge.h"

#include "common/generators/generators.h"
#include "common/oracle/oracle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <vector>

namespace labkit::lab05 {

std::string describe(SweepStatus s) {
  switch (s) {
    case SweepStatus::none: return "none";
    case SweepStatus::overlapping: return "overlapping";
    case SweepStatus::contact: return "contact";
  }
  return "an invalid status";
}

namespace judge {

namespace {

using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;

constexpr double kRelative = 1e-9;  // tol = 1e-9 S (the header's tolerances)

// How far the exact answer of a test can move when every length moves by tol and every
// direction component by 1e-9. A point of a rectangle c + s u + t v moves by at most
// sqrt(3) tol (c) + |s| sqrt(3) 1e-9 + |t| sqrt(3) 1e-9 (u, v; |s|, |t| <= S) + 2 tol
// (the half-sizes) < 7.3 tol; a segment's end or a centre by sqrt(3) tol; each radius
// by tol. So the distance minus r0 - r1 moves by less than 2 * 7.3 + 2 = 16.6 tol:
// 20 tol is a conservative bound (never too small, so no student is failed on a case
// that a perturbation could flip; a bug smaller than 20 tol may pass).
constexpr double kTestDoubt = 20.0;
// The same for a sweep: a centre at time t moves by sqrt(3) tol (itself) + sqrt(3) tol
// (the displacement v t, |v T| <= S) + sqrt(3) tol (T itself, relative 1e-9), a box's
// corner by 3 sqrt(3) tol + 3 tol more (axes, half-sizes), a plane near the shapes by
// tol (offset) + 1e-9 |x| sqrt(3) (normal, |x| <= 2 sqrt(3) S) < 7 tol. Sphere-sphere
// 2 (5.2 + 1) = 12.4 tol, sphere-plane 5.2 + 1 + 7 = 13.2 tol, box-plane 5.2 + 8.2 + 7
// = 20.4 tol: 24 tol bounds them all.
constexpr double kSweepDoubt = 24.0;

double largest(std::initializer_list<Vec3> points, std::initializer_list<double> lengths = {}) {
  double s = scale_of(points);
  for (double x : lengths) s = std::max(s, std::abs(x));
  return std::max(s, 1e-300);
}

// The plane with its normal scaled by a power of two (largest component in [1, 2)): the
// same plane, whose |n|^2 neither overflows nor underflows.
Plane scaled(const Plane& p) {
  const int e = std::ilogb(p.normal.cwiseAbs().maxCoeff());
  return {Vec3(std::ldexp(p.normal.x(), -e), std::ldexp(p.normal.y(), -e), std::ldexp(p.normal.z(), -e)),
          std::ldexp(p.offset, -e)};
}

double plane_distance(const Plane& p) {
  if (p.normal == Vec3::Zero() || !p.normal.allFinite()) return 0.0;
  const Plane q = scaled(p);
  return std::abs(q.offset) / q.normal.norm();
}
// The distance of x from the plane, rounded (for reports).
double from_plane(const Plane& p, const Vec3& x) {
  const Plane q = scaled(p);
  return std::abs(q.value(x)) / q.normal.norm();
}

std::string parameter_range_problem(double t, double low, double high, const char* name) {
  if (std::isfinite(t) && t >= low && t <= high) return "";
  return std::string(name) + " = " + fmt(t) + " is outside [" + fmt(low) + ", " + fmt(high) + "]";
}

// The checks every distance answer must pass: the reported distance within tol of the
// exact one, each point on its shape and reproduced by its parameters (the caller's
// `shape_checks`), and the pair as far apart as the exact distance, within tol.
template <class ShapeChecks>
Outcome distance_verdict(const oracle::SquaredDistance& exact, double got_squared, const Vec3& p0, const Vec3& p1,
                         double tol, ShapeChecks&& shape_checks) {
  const double d = exact.distance();
  const std::string expected = "distance " + fmt(d) + " (squared " + fmt(exact.value()) + ")";
  if (!(got_squared >= 0) || !std::isfinite(got_squared))
    return fail(expected, "squared_distance = " + fmt(got_squared), "the squared distance must be a finite number >= 0");
  const double got = std::sqrt(got_squared);
  if (exact.compare(got, -tol) < 0)  // larger than the minimum: a nearer pair was missed
    return fail(expected, "distance " + fmt(got) + " (squared " + fmt(got_squared) + ")",
                "the distance is the smallest over all pairs of points of the two shapes: yours, " + fmt(got) +
                    ", is " + fmt(got - d) + " above it (tolerance " + fmt(tol) +
                    "), so a nearer pair was missed (a parameter clamped into range must be re-projected onto the "
                    "other shape; every candidate counts: the ends, and for a rectangle its four sides)");
  if (exact.compare(got, tol) > 0)  // smaller than any pair of the shapes can be
    return fail(expected, "distance " + fmt(got) + " (squared " + fmt(got_squared) + ")",
                "the distance is the smallest over all pairs of points of the two shapes: yours, " + fmt(got) +
                    ", is " + fmt(d - got) + " below it (tolerance " + fmt(tol) +
                    "), so no pair of their points is that close (a point outside its shape? clamp t to [0, 1], "
                    "s and t to the half-sizes)");
  Expect e;
  shape_checks(e);
  const oracle::SquaredDistance pair = oracle::squared_distance(p0, p1);
  e.that("closest pair", pair.compare(d, tol) <= 0, fmt(p0) + " and " + fmt(p1) + ", " + fmt(pair.distance()) + " apart",
         "a pair " + fmt(d) + " apart",
         "your closest points are " + fmt(pair.distance()) + " apart, the shapes only " + fmt(d) + " (tolerance " +
             fmt(tol) + ")");
  return e.outcome();
}

void check_segment_point(Expect& e, const char* name, const Segment& s, double t, const char* t_name, const Vec3& p,
                         double tol) {
  const std::string range = parameter_range_problem(t, 0.0, 1.0, t_name);
  e.that(t_name, range.empty(), fmt(t), "a parameter in [0, 1]", range);
  e.that(name, oracle::parameter_reproduces(s, t, p, tol), fmt(p), std::string("a + ") + t_name + " (b - a)",
         std::string("a + ") + t_name + " (b - a) is " + fmt((s.point(t) - p).norm()) + " away from " + name);
}

void check_rectangle_point(Expect& e, const char* name, const Rectangle& r, double s, double t, const Vec3& p, double tol) {
  const std::string range = parameter_range_problem(s, -r.half_u, r.half_u, "s") + parameter_range_problem(t, -r.half_v, r.half_v, "t");
  e.that("s, t", range.empty(), fmt(s) + ", " + fmt(t), "|s| <= half_u and |t| <= half_v", range);
  e.that(name, oracle::rectangle_point_reproduces(r, s, t, p, tol), fmt(p), "center + s u + t v",
         "center + s u + t v is " + fmt((r.center + s * r.u + t * r.v - p).norm()) + " away from " + name);
}

void check_on_rectangle(Expect& e, const char* name, const Rectangle& r, const Vec3& p, double tol) {
  const oracle::SquaredDistance d = oracle::squared_distance(p, r);
  e.that(name, d.compare(tol) <= 0, fmt(p), "a point of the rectangle",
         std::string(name) + " is " + fmt(d.distance()) + " from the rectangle (tolerance " + fmt(tol) + ")");
}

using check::verdict;

// A test of table 6.1: the cores' exact distance against r0 + r1. The why states the
// rule with the numbers, then a likely cause where the numbers point at one: r0^2 + r1^2
// in place of (r0 + r1)^2, or (`missed`) the candidates a "no" most often forgets.
Outcome test_verdict(const oracle::SquaredDistance& cores, double r0, double r1, double tol, bool got, Rules rules,
                     const char* missed, const char* parallel_note) {
  const bool expected = cores.compare(r0, r1) <= 0;
  const double margin = kTestDoubt * tol;
  const bool doubt = rules == Rules::random && cores.compare(r0, r1, margin) <= 0 && cores.compare(r0, r1, -margin) >= 0;
  if (got == expected) return doubt ? ambiguous() : pass();
  if (doubt) return ambiguous();
  const double d = cores.distance();
  std::string why = "two sphere-swept volumes meet exactly when their cores are within r0 + r1: the cores are " + fmt(d) +
                    " apart and r0 + r1 = " + fmt(r0 + r1) + ", so they " + (expected ? "meet" : "do not meet") +
                    ", your answer says they " + (got ? "meet" : "do not");
  if (expected) {
    // The likely causes, most telling first: the sum not squared, the exact touch decided
    // on a rounded distance, a candidate of steps 1 and 2 forgotten.
    std::vector<std::string> causes;
    if (d * d > r0 * r0 + r1 * r1)
      causes.push_back("is it (r0 + r1)^2 you compare with? r0^2 + r1^2 = " + fmt(r0 * r0 + r1 * r1) + " is smaller");
    if (cores.compare(r0, r1) == 0)
      causes.push_back("they touch exactly, and touching counts: a rounded distance can come out a hair above r0 + r1, "
                       "so decide on exact products of the input (num <= (r0 + r1)^2 den), then construct");
    causes.push_back(missed);
    why += " (";
    for (std::size_t i = 0; i < causes.size(); ++i) why += (i ? "; or " : "") + causes[i];
    why += ")";
  } else if (d * d <= r0 + r1) {
    why += " (is it d^2 <= r0 + r1 you test? Square the sum: d^2 <= (r0 + r1)^2)";
  } else if (parallel_note) {
    why += parallel_note;
  }
  const auto yes_no = [](bool b) { return std::string(b ? "they meet" : "they do not meet"); };
  return fail(yes_no(expected) + " (the cores are " + fmt(d) + " apart, r0 + r1 = " + fmt(r0 + r1) + ")", yes_no(got), why);
}

double scale_of_shapes(const Sphere& s) { return largest({s.center}, {s.radius}); }
double scale_of_shapes(const Capsule& c) { return largest({c.axis.a, c.axis.b}, {c.radius}); }
double scale_of_shapes(const Lozenge& l) {
  return largest({l.rectangle.center}, {l.rectangle.half_u, l.rectangle.half_v, l.radius});
}

// The exact distance between the cores of a pair (table 6.1's distance calculator).
oracle::SquaredDistance core_distance(const SpherePair& p) { return oracle::squared_distance(p.a.center, p.b.center); }
oracle::SquaredDistance core_distance(const SphereCapsule& p) { return oracle::squared_distance(p.a.center, p.b.axis); }
oracle::SquaredDistance core_distance(const SphereLozenge& p) { return oracle::squared_distance(p.a.center, p.b.rectangle); }
oracle::SquaredDistance core_distance(const CapsulePair& p) { return oracle::squared_distance(p.a.axis, p.b.axis); }
oracle::SquaredDistance core_distance(const CapsuleLozenge& p) { return oracle::squared_distance(p.a.axis, p.b.rectangle); }
oracle::SquaredDistance core_distance(const LozengePair& p) {
  return oracle::squared_distance(p.a.rectangle, p.b.rectangle);
}

// Where a "no" most often goes wrong, per pair: the candidates of steps 1 and 2.
const char* missed(const SpherePair&) { return "the centres' distance is the cores' distance"; }
const char* missed(const SphereCapsule&) { return "the centre's nearest point of the axis is its projection, clamped to the segment"; }
const char* missed(const SphereLozenge&) { return "the nearest point of the rectangle clamps s and t to the half-sizes"; }
const char* missed(const CapsulePair&) {
  return "the lines' closest pair when it lies inside both segments, else an end against the other segment; "
         "for nearly parallel axes measure the pair itself, the rounded cross product says nothing";
}
const char* missed(const CapsuleLozenge&) {
  return "the crossing, the ends against the rectangle, the segment against its four sides; "
         "for a side nearly parallel to the axis measure the pair itself, the rounded cross product says nothing";
}
const char* missed(const LozengePair&) {
  return "a closest pair of two rectangles has a point on a side of either one: the sides of both, each against the "
         "other rectangle";
}

// Where a "yes" most often goes wrong for cores with segments: the division-free recipe
// on lines that are parallel only up to rounding.
constexpr const char* kParallelNote =
    " (where two of the lines are nearly parallel, the rounded n = d0 x d1 is mostly noise and (w . n)^2 <= R^2 |n|^2 "
    "says nothing about their distance: measure the pair itself there)";
template <class Pair>
const char* parallel_note(const Pair&) { return nullptr; }
const char* parallel_note(const CapsulePair&) { return kParallelNote; }
const char* parallel_note(const CapsuleLozenge&) { return kParallelNote; }
const char* parallel_note(const LozengePair&) { return kParallelNote; }

template <class Pair>
Outcome test_pair_verdict(const Pair& p, bool got, Rules rules) {
  const double tol = kRelative * std::max(scale_of_shapes(p.a), scale_of_shapes(p.b));
  return test_verdict(core_distance(p), p.a.radius, p.b.radius, tol, got, rules, missed(p), parallel_note(p));
}

// ---- Sweeps -----------------------------------------------------------------------------

template <class Motion>
std::string expected_sweep(const Motion& m, double duration) {
  const double t = oracle::first_contact(m, duration);
  if (t < 0) return "none";
  if (oracle::gap_sign(m, 0.0, 0.0) <= 0) return "overlapping (at t = 0)";
  return "contact at t = " + fmt(t) + " (rounded)";
}

std::string describe_sweep(const Sweep& s) {
  if (s.status != SweepStatus::contact) return describe(s.status);
  return "contact at t = " + fmt(s.time) + ", point " + fmt(s.point);
}

// What a report says about a sweep beyond the exact signs, in doubles (rounded, for the
// words only): the gap at a time, the later root, and the likely causes of a wrong
// status or time that the numbers of this input point at.
struct Facts {
  std::function<double(double)> gap;  // the gap at time t
  double later = -1;                   // the later root (they part again), if any
  std::string wrong_status;            // a likely cause of a wrong status, or ""
  std::string wrong_time;              // a likely cause of a time past the first contact, or ""
};

// A shape whose value f0 + g t against the plane (|n| times the centre's signed distance)
// must come within reach (|n| times its radius): the facts of steps 4 and 6.
Facts plane_facts(const Plane& given, const Vec3& c, const Vec3& v, double reach_unit, double signed_reach_unit,
                  const Sweep& got, double duration) {
  const Plane p = scaled(given);
  const double n = p.normal.norm(), f0 = p.value(c), g = p.normal.dot(v), sigma = f0 >= 0 ? 1.0 : -1.0;
  Facts f;
  f.gap = [=](double t) { return std::abs(f0 + g * t) / n - reach_unit; };
  if (sigma * g < 0) f.later = (std::abs(f0) + reach_unit * n) / std::abs(g);
  const double length = given.normal.norm();
  const bool unit_mistake = std::isfinite(length) && std::abs(length - 1) > 1e-6;
  // A normal taken as unit: |value| compared with the reach itself.
  const double value0 = std::abs(given.value(c)), rate = std::abs(given.normal.dot(v));
  if (unit_mistake) {  // what that mistake answers, against what was answered
    const bool toward = sigma * given.normal.dot(v) < 0;
    const double would_time = rate > 0 ? (value0 - reach_unit) / rate : -1;
    const SweepStatus would = value0 <= reach_unit                      ? SweepStatus::overlapping
                              : toward && would_time <= duration ? SweepStatus::contact
                                                                 : SweepStatus::none;
    const std::string unit = " (is n unit? n . c + offset is |n| = " + fmt(length) +
                             " times the centre's distance: compare it with the reach times |n|)";
    if (got.status == would) f.wrong_status = unit;
    if (got.status == SweepStatus::contact && std::abs(got.time - would_time) <= 1e-6 * std::max(1.0, would_time))
      f.wrong_time = unit;
  }
  if (f.wrong_status.empty() && sigma < 0 && got.status == SweepStatus::none)
    f.wrong_status = " (the centre starts behind the plane, n . c + offset < 0: the plane is two-sided, and it is "
                     "reached from either side)";
  if (f.wrong_status.empty() && sigma * g >= 0 && got.status == SweepStatus::contact)
    f.wrong_status = " (it moves away from the plane or along it, sign(f0) (n . v) >= 0: the lecture's \"T < 0\")";
  if (f.wrong_time.empty() && signed_reach_unit < reach_unit * (1 - 1e-9))
    f.wrong_time = " (the box reaches rho = sum_i h_i |n . axis_i| / |n| = " + fmt(reach_unit) +
                   " toward the plane: each term counts with its absolute value; signed, they cancel to " +
                   fmt(signed_reach_unit) + ")";
  return f;
}

Facts facts(const SpherePlaneMotion& in, const Sweep& got) {
  return plane_facts(in.plane, in.sphere.center, in.velocity, in.sphere.radius, in.sphere.radius, got, in.duration);
}

Facts facts(const BoxPlaneMotion& in, const Sweep& got) {
  const Vec3 unit = scaled(in.plane).normal.normalized();
  double reach = 0, signed_reach = 0;
  for (int i = 0; i < 3; ++i) {
    reach += in.box.half_extents[i] * std::abs(unit.dot(in.box.axes.col(i)));
    signed_reach += in.box.half_extents[i] * unit.dot(in.box.axes.col(i));
  }
  return plane_facts(in.plane, in.box.center, in.velocity, reach, std::abs(signed_reach), got, in.duration);
}

Facts facts(const SphereSphereMotion& in, const Sweep& got) {
  const Vec3 A = in.s0.center - in.s1.center, B = in.v0 - in.v1;
  const double R = in.s0.radius + in.s1.radius, a = B.squaredNorm(), b = A.dot(B), c = A.squaredNorm() - R * R;
  const double disc = a * R * R - A.cross(B).squaredNorm();
  Facts f;
  f.gap = [=](double t) { return (A + t * B).norm() - R; };
  if (a > 0 && disc >= 0) f.later = (-b + std::sqrt(disc)) / a;
  if (got.status == SweepStatus::contact && b >= 0 && c > 0)
    f.wrong_status = " (they move apart or sideways, b = A . B = " + fmt(b) +
                     " >= 0: the distance only grows, so both roots lie before t = 0)";
  if (got.status == SweepStatus::none && disc == 0 && b < 0)
    f.wrong_status = " (an exact graze, b^2 - ac = 0, is a contact: touching counts)";
  if (got.status == SweepStatus::none && c == 0)
    f.wrong_status = " (c = |A|^2 - R^2 = 0: touching at t = 0 counts as overlapping, sets are closed)";
  return f;
}

// A sphere against a static capsule, in doubles (words only): the distance from the
// centre to the axis, the pieces' later roots, and the classic mistakes' times (the side's
// root outside the slab, the capsule grown by one radius only, the caps left out).
double axis_distance(const Capsule& k, const Vec3& x) {
  const Vec3 d = k.axis.b - k.axis.a;
  const double dd = d.squaredNorm();
  const double t = dd > 0 ? std::clamp((x - k.axis.a).dot(d) / dd, 0.0, 1.0) : 0.0;
  return (x - k.axis.a - t * d).norm();
}

Facts facts(const SphereCapsuleMotion& in, const Sweep& got) {
  const Capsule k = in.capsule;
  const Vec3 c = in.sphere.center, v = in.velocity, a = k.axis.a, d = k.axis.b - a;
  const double r = in.sphere.radius, R = r + k.radius, dd = d.squaredNorm();
  Facts f;
  f.gap = [=](double t) { return axis_distance(k, c + t * v) - R; };
  // The roots of |m + t v| = rho (an end sphere) and |(m + t v) x d| = rho |d| (the side).
  const auto roots = [](double qa, double qb, double qc, double& first, double& later) {
    const double disc = qb * qb - qa * qc;
    if (!(qa > 0 && disc >= 0)) return false;
    first = (-qb - std::sqrt(disc)) / qa;
    later = (-qb + std::sqrt(disc)) / qa;
    return true;
  };
  const auto side = [&](double rho, double& first, double& later) {
    if (dd == 0) return false;
    const Vec3 md = (c - a).cross(d), vd = v.cross(d);
    return roots(vd.squaredNorm(), md.dot(vd), md.squaredNorm() - rho * rho * dd, first, later);
  };
  const auto cap = [&](const Vec3& end, double rho, double& first, double& later) {
    const Vec3 m = c - end;
    return roots(v.squaredNorm(), m.dot(v), m.squaredNorm() - rho * rho, first, later);
  };
  if (got.status != SweepStatus::contact || !std::isfinite(got.time)) return f;
  const double t = got.time, S = std::max(scale(in), 1e-300);
  const auto near = [&](double x) { return std::abs(x - t) <= 1e-6 * std::max({std::abs(x), std::abs(t), 1e-300}); };
  double first = 0, later = 0;
  // The later roots: of whichever piece's later root the answer matches.
  for (int piece = 0; piece < 3; ++piece) {
    const bool ok = piece == 0 ? side(R, first, later) : cap(piece == 1 ? a : k.axis.b, R, first, later);
    if (ok && near(later)) f.later = later;
  }
  const Vec3 at = c + t * v;
  const double to_line = dd > 0 ? (at - a).cross(d).norm() / std::sqrt(dd) : (at - a).norm();
  const double along = dd > 0 ? (at - a).dot(d) / dd : 0.0;
  const double dist = axis_distance(k, at);
  if (dd > 0 && std::abs(to_line - R) <= 1e-6 * S && (along < -1e-9 || along > 1 + 1e-9) && dist > R + 1e-9 * S)
    f.wrong_time = " (at your time the centre is R = r + rc from the axis's infinite line, but beyond the end " +
                   std::string(along < 0 ? "a" : "b") + " (axial fraction " + fmt(along) +
                   "): the side's root counts only inside the slab 0 <= (c(t) - a) . d <= d . d; beyond it, the "
                   "end sphere (cap) decides)";
  else if (R > 0 && (std::abs(dist - k.radius) <= 1e-6 * S || std::abs(dist - r) <= 1e-6 * S) && std::abs(dist - R) > 1e-6 * S)
    f.wrong_time = " (at your time the centre is " + fmt(dist) + " from the axis: that is the capsule grown by one radius "
                   "only; the Minkowski sum grows it by both, R = r + rc = " + fmt(R) + ")";
  else {
    // The first contact on a cap while the answer came later: the caps left out?
    const double exact_first = oracle::first_contact(oracle::SphereCapsuleSweep{in.sphere, v, k}, in.duration);
    if (exact_first >= 0 && t > exact_first) {
      const Vec3 there = c + exact_first * v;
      const double s = dd > 0 ? (there - a).dot(d) / dd : 0.0;
      if (dd == 0 || s <= 1e-9 || s >= 1 - 1e-9)
        f.wrong_time = " (the first contact is on the end cap at " + std::string(s <= 0.5 ? "a" : "b") +
                       ": the grown capsule is the side and the two end spheres (caps) of radius R; did you leave out "
                       "the caps?)";
    }
  }
  return f;
}

// The status against the exact one, then a reported contact certified exactly: at its
// time the gap is at most tol, before it never below -tol, and its point within tol of
// both shapes. Ambiguous statuses get the slack of the doubt margin in those checks.
// Each why states the header's rule, the numbers, then a likely cause when one shows.
template <class Motion, class Input, class PointCheck>
Outcome sweep_verdict(const Motion& m, const Input& in, const Sweep& got, double tol, Rules rules, PointCheck&& point_ok) {
  const double duration = in.duration;
  const bool overlapping_now = oracle::gap_sign(m, 0.0, 0.0) <= 0;
  const bool touches = oracle::min_gap_sign(m, duration, 0.0) <= 0;
  const SweepStatus exact = overlapping_now ? SweepStatus::overlapping : (touches ? SweepStatus::contact : SweepStatus::none);
  const double margin = kSweepDoubt * tol;
  bool doubt_now = false, doubt_ever = false;
  if (rules == Rules::random) {
    doubt_now = oracle::gap_sign(m, 0.0, margin) <= 0 && oracle::gap_sign(m, 0.0, -margin) >= 0;
    doubt_ever = oracle::min_gap_sign(m, duration, margin) <= 0 && oracle::min_gap_sign(m, duration, -margin) >= 0;
  }
  const bool doubt = doubt_now || doubt_ever;
  const std::string expected = expected_sweep(m, duration);
  const bool accepted = got.status == exact ||
                        (doubt_now && (got.status == SweepStatus::overlapping || got.status == SweepStatus::contact)) ||
                        (doubt_ever && (got.status == SweepStatus::contact || got.status == SweepStatus::none));
  const Facts f = facts(in, got);
  if (!accepted) {
    if (got.status != SweepStatus::none && got.status != SweepStatus::overlapping && got.status != SweepStatus::contact)
      return fail(expected, describe_sweep(got), "the status is not one of none, overlapping, contact");
    const double first = oracle::first_contact(m, duration);
    std::string why;
    if (exact == SweepStatus::overlapping)
      why = "at t = 0 they already touch or overlap (gap " + fmt(f.gap(0)) +
            " <= 0): the status is overlapping, whatever the motion";
    else if (exact == SweepStatus::contact)
      why = "they are apart at t = 0 (gap " + fmt(f.gap(0)) + ") and first touch at t = " + fmt(first) +
            ", within [0, T = " + fmt(duration) + "]: the status is contact";
    else
      why = "they never touch during [0, T = " + fmt(duration) + "] (the gap at t = 0 is " + fmt(f.gap(0)) +
            (got.status == SweepStatus::contact && std::isfinite(got.time) ? ", at your time " + fmt(f.gap(got.time)) : "") +
            "): the status is none";
    return fail(expected, describe_sweep(got), why + f.wrong_status);
  }
  if (got.status == SweepStatus::contact) {
    const double slack = doubt ? margin : tol;
    const double t = got.time, first = oracle::first_contact(m, duration);
    if (!(std::isfinite(t) && t >= 0 && t <= duration))
      return fail(expected, describe_sweep(got), "the time of contact must be in [0, T], T = " + fmt(duration));
    if (oracle::gap_sign(m, t, slack) > 0)
      return fail(expected, describe_sweep(got),
                  "contact is the first time the gap reaches 0: at your t = " + fmt(t) + " the gap is still " +
                      fmt(f.gap(t)) + " (tolerance " + fmt(slack) + "); they first touch at t = " + fmt(first) +
                      f.wrong_time);
    if (oracle::min_gap_sign(m, t, -slack) < 0) {
      const bool later = f.later >= 0 && std::abs(t - f.later) <= 1e-6 * std::max(f.later, 1e-300);
      return fail(expected, describe_sweep(got),
                  "contact is the first time the gap reaches 0: they touch already at t = " + fmt(first) +
                      " and overlap before your t = " + fmt(t) + " (tolerance " + fmt(slack) + ")" +
                      (later ? ": your time is the later root, when they part again; the first contact is the "
                               "smaller root"
                             : f.wrong_time));
    }
    const std::string point = point_ok(t, got.point, slack);
    if (!point.empty())
      return fail(expected, describe_sweep(got),
                  "the point must lie on both shapes at your time of contact (within " + fmt(slack) + "): " + point);
  }
  return doubt ? ambiguous() : pass();
}

}  // namespace

// ---- Scales -------------------------------------------------------------------------------

double scale(const PointSegmentPair& in) { return largest({in.p, in.segment.a, in.segment.b}); }
double scale(const SegmentPair& in) { return largest({in.first.a, in.first.b, in.second.a, in.second.b}); }
double scale(const PointRectanglePair& in) {
  return largest({in.p, in.rectangle.center}, {in.rectangle.half_u, in.rectangle.half_v});
}
double scale(const SegmentRectanglePair& in) {
  return largest({in.segment.a, in.segment.b, in.rectangle.center}, {in.rectangle.half_u, in.rectangle.half_v});
}
double scale(const RectanglePair& in) {
  return largest({in.first.center, in.second.center},
                 {in.first.half_u, in.first.half_v, in.second.half_u, in.second.half_v});
}
double scale(const SpherePlaneMotion& in) {
  return largest({in.sphere.center, in.velocity * in.duration}, {in.sphere.radius, plane_distance(in.plane)});
}
double scale(const SphereSphereMotion& in) {
  return largest({in.s0.center, in.s1.center, in.v0 * in.duration, in.v1 * in.duration}, {in.s0.radius, in.s1.radius});
}
double scale(const SphereCapsuleMotion& in) {
  return largest({in.sphere.center, in.velocity * in.duration, in.capsule.axis.a, in.capsule.axis.b},
                 {in.sphere.radius, in.capsule.radius});
}
double scale(const BoxPlaneMotion& in) {
  return largest({in.box.center, in.velocity * in.duration, in.box.half_extents}, {plane_distance(in.plane)});
}

// ---- Step 1 -------------------------------------------------------------------------------

Outcome point_segment(const PointSegmentPair& in, const PointSegmentDistance& got) {
  const double tol = kRelative * scale(in);
  return distance_verdict(oracle::squared_distance(in.p, in.segment), got.squared_distance, in.p, got.closest, tol,
                          [&](Expect& e) { check_segment_point(e, "closest", in.segment, got.t, "t", got.closest, tol); });
}

Outcome segment_segment(const SegmentPair& in, const SegmentSegmentDistance& got) {
  const double tol = kRelative * scale(in);
  Outcome o = distance_verdict(oracle::squared_distance(in.first, in.second), got.squared_distance, got.closest0,
                               got.closest1, tol, [&](Expect& e) {
                                 check_segment_point(e, "closest0", in.first, got.s, "s", got.closest0, tol);
                                 check_segment_point(e, "closest1", in.second, got.t, "t", got.closest1, tol);
                               });
  const Vec3 d0 = in.first.b - in.first.a, d1 = in.second.b - in.second.a;
  const double nn = d0.cross(d1).squaredNorm(), scale2 = d0.squaredNorm() * d1.squaredNorm();
  if (o.verdict == Outcome::Verdict::fail && nn > 0 && nn < 1e-8 * scale2)
    o.why += " (the segments are nearly parallel, sin^2 of their angle " + fmt(nn / scale2) +
             ": the textbook denominator a c - b^2 cancels there; |d0 x d1|^2 is the same number without the cancellation)";
  return o;
}

// ---- Step 2 -------------------------------------------------------------------------------

Outcome point_rectangle(const PointRectanglePair& in, const PointRectangleDistance& got) {
  const double tol = kRelative * scale(in);
  return distance_verdict(oracle::squared_distance(in.p, in.rectangle), got.squared_distance, in.p, got.closest, tol,
                          [&](Expect& e) { check_rectangle_point(e, "closest", in.rectangle, got.s, got.t, got.closest, tol); });
}

Outcome segment_rectangle(const SegmentRectanglePair& in, const SegmentRectangleDistance& got) {
  const double tol = kRelative * scale(in);
  return distance_verdict(oracle::squared_distance(in.segment, in.rectangle), got.squared_distance, got.closest0,
                          got.closest1, tol, [&](Expect& e) {
                            check_segment_point(e, "closest0", in.segment, got.r, "r", got.closest0, tol);
                            check_rectangle_point(e, "closest1", in.rectangle, got.s, got.t, got.closest1, tol);
                          });
}

Outcome rectangle_rectangle(const RectanglePair& in, const RectangleRectangleDistance& got) {
  const double tol = kRelative * scale(in);
  return distance_verdict(oracle::squared_distance(in.first, in.second), got.squared_distance, got.closest0,
                          got.closest1, tol, [&](Expect& e) {
                            check_on_rectangle(e, "closest0", in.first, got.closest0, tol);
                            check_on_rectangle(e, "closest1", in.second, got.closest1, tol);
                          });
}

// ---- Step 3 -------------------------------------------------------------------------------

Outcome test_pair(const SpherePair& in, bool got, Rules rules) { return test_pair_verdict(in, got, rules); }
Outcome test_pair(const SphereCapsule& in, bool got, Rules rules) { return test_pair_verdict(in, got, rules); }
Outcome test_pair(const SphereLozenge& in, bool got, Rules rules) { return test_pair_verdict(in, got, rules); }
Outcome test_pair(const CapsulePair& in, bool got, Rules rules) { return test_pair_verdict(in, got, rules); }
Outcome test_pair(const CapsuleLozenge& in, bool got, Rules rules) { return test_pair_verdict(in, got, rules); }
Outcome test_pair(const LozengePair& in, bool got, Rules rules) { return test_pair_verdict(in, got, rules); }

// ---- Steps 4 to 6 -------------------------------------------------------------------------

Outcome sweep_sphere_plane(const SpherePlaneMotion& in, const Sweep& got, Rules rules) {
  const oracle::SpherePlaneSweep m{in.sphere, in.velocity, in.plane};
  return sweep_verdict(m, in, got, kRelative * scale(in), rules, [&](double t, const Vec3& p, double slack) {
    if (oracle::within_moving_sphere(in.sphere, in.velocity, t, p, slack) && oracle::within_plane(in.plane, p, slack))
      return std::string();
    return "yours is " + fmt((p - in.sphere.center - t * in.velocity).norm()) + " from the centre (r = " +
           fmt(in.sphere.radius) + ") and " + fmt(from_plane(in.plane, p)) +
           " from the plane; the sphere's point nearest the plane is c(t) - sign(s(0)) r n / |n|";
  });
}

Outcome sweep_sphere_sphere(const SphereSphereMotion& in, const Sweep& got, Rules rules) {
  const oracle::SphereSphereSweep m{in.s0, in.s1, in.v0, in.v1};
  const Outcome o = sweep_verdict(m, in, got, kRelative * scale(in), rules, [&](double t, const Vec3& p, double slack) {
    if (oracle::within_moving_sphere(in.s0, in.v0, t, p, slack) && oracle::within_moving_sphere(in.s1, in.v1, t, p, slack))
      return std::string();
    return "yours is " + fmt((p - in.s0.center - t * in.v0).norm()) + " from c0(t) (r0 = " + fmt(in.s0.radius) +
           ") and " + fmt((p - in.s1.center - t * in.v1).norm()) + " from c1(t) (r1 = " + fmt(in.s1.radius) +
           "); the point is r0 / R of the way from c0(t) to c1(t)";
  });
  if (o.verdict != Outcome::Verdict::pass || got.status != SweepStatus::contact) return o;
  // Exact coefficients and a steep approach: the time must be right relative to itself,
  // t_exact in [t (1 - 1e-9), t (1 + 1e-9)] (the header's rule for stable roots).
  if (!oracle::sphere_sweep_exact_and_steep(m)) return o;
  const double low = got.time * (1 - kRelative), high = std::min(got.time * (1 + kRelative), in.duration);
  if (oracle::min_gap_sign(m, low, 0.0) > 0 && oracle::min_gap_sign(m, high, 0.0) <= 0) return o;
  const double exact = oracle::first_contact(m, in.duration);
  return fail(expected_sweep(m, in.duration), describe_sweep(got),
              "with exact coefficients and a steep approach the first root must be within a relative 1e-9 of the exact "
              "one; yours is off by a relative " + fmt(std::abs(got.time - exact) / exact) +
                  " (does your root formula cancel? -b - sqrt(b^2 - ac) subtracts nearly equal numbers when contact "
                  "comes very soon: use q = -b + sqrt(b^2 - ac), t = c / q)");
}

Outcome sweep_sphere_capsule(const SphereCapsuleMotion& in, const Sweep& got, Rules rules) {
  const oracle::SphereCapsuleSweep m{in.sphere, in.velocity, in.capsule};
  return sweep_verdict(m, in, got, kRelative * scale(in), rules, [&](double t, const Vec3& p, double slack) {
    if (oracle::within_moving_sphere(in.sphere, in.velocity, t, p, slack) && oracle::within_capsule(in.capsule, p, slack))
      return std::string();
    return "yours is " + fmt((p - in.sphere.center - t * in.velocity).norm()) + " from c(t) (r = " +
           fmt(in.sphere.radius) + ") and " + fmt(axis_distance(in.capsule, p)) + " from the axis (rc = " +
           fmt(in.capsule.radius) + "); the point is r / R of the way from c(t) to its nearest point of the axis";
  });
}

Outcome sweep_box_plane(const BoxPlaneMotion& in, const Sweep& got, Rules rules) {
  const oracle::BoxPlaneSweep m{in.box, in.velocity, in.plane};
  return sweep_verdict(m, in, got, kRelative * scale(in), rules, [&](double t, const Vec3& p, double slack) {
    const bool in_box = oracle::within_moving_box(in.box, in.velocity, t, p, slack);
    if (in_box && oracle::within_plane(in.plane, p, slack)) return std::string();
    return std::string("yours is ") + (in_box ? "in the box" : "outside the box") + " and " +
           fmt(from_plane(in.plane, p)) +
           " from the plane; any point of the box within tol of the plane passes (the corner nearest the plane is "
           "c(t) - sign(s(0)) sum_i sign(n . axis_i) h_i axis_i)";
  });
}

// ---- Step 3's generators --------------------------------------------------------------------

namespace {

// A hair just outside the doubt band of the tests (20 tol = 20e-9 S): m * 1e-9 S for m
// from 24 to 2^24, log-uniform. The near cases stay decisive; exactly touching radii
// belong to step 7.
double decisive_hair(double S) {
  return 24 * std::ldexp(1.0, *rc::gen::inRange(0, 20)) * (1 + *rc::gen::inRange(0, 8) / 8.0) * 1e-9 * S;
}

// Radii around the cores' exact distance d (S: the pair's scale without the radii): a
// hair inside or outside, clearly apart or overlapping, or a plain lattice length.
double radius_total(double d, double size) {
  switch (*rc::gen::weightedElement<int>({{4, 1}, {2, 2}, {2, 3}})) {
    case 1: {
      const double hair = decisive_hair(std::max(size, d) * 1.01);
      return d > hair && *rc::gen::arbitrary<bool>() ? d - hair : d + hair;
    }
    // Cores that meet (d = 0) with radii 0 touch exactly: step 7's; here they overlap.
    case 2: return d > 0 ? d * *rc::gen::element(0.5, 0.875, 1.125, 2.0) : decisive_hair(size);
    default: return *rc::gen::inRange(1, 9) / 4.0 * std::max(size, 1e-300);
  }
}

// Exact families: radii that sum to an integer (times the scale) at or next to d.
double exact_radius_total(double d, double unit) {
  const double k = std::floor(d / unit);
  return std::max(0.0, *rc::gen::element(k - 1, k, k + 1, k + 2) * unit);
}

// The unit of an exact family's lattice: the largest power of two dividing every
// coordinate (so integers times it).
double lattice_unit(const std::vector<double>& numbers) {
  double unit = std::ldexp(1.0, 30);
  for (double x : numbers) {
    if (x == 0) continue;
    int e = 0;
    std::frexp(x, &e);
    double low = std::ldexp(1.0, e);  // halve until it divides x: x's lowest set bit
    while (std::fmod(std::abs(x), low) != 0) low /= 2;
    unit = std::min(unit, low);
  }
  return unit;
}

// Exactly touching cores: both in parallel planes h apart (z = 0 and z = h in a
// canonical frame), each through a common point P of the xy-plane, so their distance is
// exactly h; then a signed permutation of the axes and an integer shift.
struct Canonical {
  Mat3 frame = Mat3::Identity();
  Vec3 shift = Vec3::Zero();
  double s = 1.0, h = 1.0;
  Vec3 P = Vec3::Zero();
  Vec3 at(const Vec3& x) const { return frame * x + shift; }
};

Canonical canonical() {
  Canonical c;
  c.s = *gen::scale();
  c.h = *rc::gen::inRange(0, 5) * c.s;
  c.P = Vec3(*gen::integer(8), *gen::integer(8), 0) * c.s;
  std::array<int, 3> order{0, 1, 2};
  std::rotate(order.begin(), order.begin() + *rc::gen::inRange(0, 3), order.end());
  c.frame = Mat3::Zero();
  for (int i = 0; i < 3; ++i) c.frame(order[i], i) = *rc::gen::element(-1.0, 1.0);
  c.shift = *gen::lattice_point(c.s, 16);
  return c;
}

Vec3 in_plane(const Canonical& c, double z) { return Vec3(*gen::integer(4), *gen::integer(4), 0) * c.s + Vec3(0, 0, z); }

Vec3 canonical_point(const Canonical& c, double z) { return c.at(c.P + Vec3(0, 0, z)); }
Segment canonical_segment(const Canonical& c, double z) {
  const Vec3 d = in_plane(c, 0);
  const int k = *rc::gen::inRange(0, 3);
  return {c.at(c.P + Vec3(0, 0, z) + k * d), c.at(c.P + Vec3(0, 0, z) - d)};
}
Rectangle canonical_rectangle(const Canonical& c, double z) {
  const double hu = *rc::gen::inRange(0, 5) * c.s, hv = *rc::gen::inRange(0, 5) * c.s;
  const Vec3 offset(*rc::gen::inRange(-int(hu / c.s), int(hu / c.s) + 1) * c.s,
                    *rc::gen::inRange(-int(hv / c.s), int(hv / c.s) + 1) * c.s, 0);
  return {c.at(c.P + Vec3(0, 0, z) + offset), c.frame.col(0) * *rc::gen::element(-1.0, 1.0),
          c.frame.col(1) * *rc::gen::element(-1.0, 1.0), hu, hv};
}

template <class Pair>
Pair with_radii(Pair p, double total) {
  const auto [r0, r1] = *gen::split_radius(total);
  p.a.radius = r0;
  p.b.radius = r1;
  return p;
}

// The numbers of a shape's core (coordinates and half-sizes), for the exact families'
// lattice unit and for the scale of the near-touching radii.
void core_numbers(const Sphere& x, std::vector<double>& out) { out.insert(out.end(), x.center.data(), x.center.data() + 3); }
void core_numbers(const Capsule& x, std::vector<double>& out) {
  out.insert(out.end(), x.axis.a.data(), x.axis.a.data() + 3);
  out.insert(out.end(), x.axis.b.data(), x.axis.b.data() + 3);
}
void core_numbers(const Lozenge& x, std::vector<double>& out) {
  out.insert(out.end(), x.rectangle.center.data(), x.rectangle.center.data() + 3);
  out.push_back(x.rectangle.half_u);
  out.push_back(x.rectangle.half_v);
}

// One generator per pair type: the distance steps' cores with radii around their exact
// distance, or (more often in the exact families) canonical cores exactly h apart with
// radii summing to h.
template <class Pair, class Cores, class FromCores, class Canon>
rc::Gen<Pair> pair_generator(const rc::Gen<Cores>& cores, bool exact, FromCores from_cores, Canon canon) {
  const rc::Gen<Pair> around = rc::gen::exec([=] {
    const Pair p = from_cores(*cores);
    std::vector<double> numbers;
    core_numbers(p.a, numbers);
    core_numbers(p.b, numbers);
    double size = 0;
    for (double x : numbers) size = std::max(size, std::abs(x));
    const double d = core_distance(p).distance();
    return with_radii(p, exact ? exact_radius_total(d, lattice_unit(numbers)) : radius_total(d, size));
  });
  // Cores exactly h apart: radii summing to h (exact, step 7), or a decisive hair off it.
  const rc::Gen<Pair> touching = rc::gen::exec([=] {
    const Canonical k = canonical();
    const Pair p = canon(k);
    if (exact) return with_radii(p, k.h);
    std::vector<double> numbers;
    core_numbers(p.a, numbers);
    core_numbers(p.b, numbers);
    double size = k.h;
    for (double x : numbers) size = std::max(size, std::abs(x));
    return with_radii(p, radius_total(k.h, size));
  });
  return rc::gen::weightedOneOf<Pair>({{exact ? 1 : 6, around}, {1, touching}});
}

}  // namespace

rc::Gen<SpherePair> sphere_pair(bool exact) {
  return pair_generator<SpherePair>(
      gen::point_segment(exact), exact, [](const PointSegmentPair& c) { return SpherePair{{c.p, 0}, {c.segment.b, 0}}; },
      [](const Canonical& k) { return SpherePair{{canonical_point(k, 0), 0}, {canonical_point(k, k.h), 0}}; });
}
rc::Gen<SphereCapsule> sphere_capsule(bool exact) {
  return pair_generator<SphereCapsule>(
      gen::point_segment(exact), exact, [](const PointSegmentPair& c) { return SphereCapsule{{c.p, 0}, {c.segment, 0}}; },
      [](const Canonical& k) { return SphereCapsule{{canonical_point(k, k.h), 0}, {canonical_segment(k, 0), 0}}; });
}
rc::Gen<SphereLozenge> sphere_lozenge(bool exact) {
  return pair_generator<SphereLozenge>(
      gen::point_rectangle(exact), exact,
      [](const PointRectanglePair& c) { return SphereLozenge{{c.p, 0}, {c.rectangle, 0}}; },
      [](const Canonical& k) { return SphereLozenge{{canonical_point(k, k.h), 0}, {canonical_rectangle(k, 0), 0}}; });
}
// Parallel axes exactly n apart where finding the closest pair needs a division: the
// first axis runs along an integer d, the second starts at an integer w whose projection
// onto the first, t = (w . d) / |d|^2, lies inside it but is not a dyadic fraction, and
// |w|^2 |d|^2 - (w . d)^2 = n^2 |d|^2 for an integer n. The constructed closest points
// are rounded, so a rounded distance can come out a hair above r0 + r1 = n: only exact
// products of the input decide it. (The small table of such d and w is searched once.)
CapsulePair parallel_touching() {
  struct Triple {
    Vec3 d, w;
    double n;
  };
  static const std::vector<Triple> table = [] {
    std::vector<Triple> out;
    for (int i = 0; i < 9 * 9 * 9 * 9 * 9 * 9; ++i) {
      int c[6], k = i;
      for (int& x : c) x = k % 9 - 4, k /= 9;
      const long dd = c[0] * c[0] + c[1] * c[1] + c[2] * c[2], ww = c[3] * c[3] + c[4] * c[4] + c[5] * c[5];
      const long wd = c[0] * c[3] + c[1] * c[4] + c[2] * c[5];
      if (dd == 0 || (dd & (dd - 1)) == 0 || wd <= 0 || wd >= dd || (ww * dd - wd * wd) % dd != 0) continue;
      const long n2 = (ww * dd - wd * wd) / dd, n = std::lround(std::sqrt(double(n2)));
      if (n > 0 && n * n == n2) out.push_back({Vec3(c[0], c[1], c[2]), Vec3(c[3], c[4], c[5]), double(n)});
    }
    return out;
  }();
  const Triple& x = *rc::gen::elementOf(table);
  const double s = *gen::scale();
  const Vec3 a = *gen::lattice_point(s, 8);
  const double along = *rc::gen::element(-2.0, -1.0, 1.0, 2.0);
  const CapsulePair p{{{a, a + s * x.d}, 0}, {{a + s * x.w, a + s * (x.w + along * x.d)}, 0}};
  return with_radii(p, x.n * s);
}

rc::Gen<CapsulePair> capsule_pair(bool exact) {
  const rc::Gen<CapsulePair> families = pair_generator<CapsulePair>(
      gen::segment_pair(exact), exact, [](const SegmentPair& c) { return CapsulePair{{c.first, 0}, {c.second, 0}}; },
      [](const Canonical& k) { return CapsulePair{{canonical_segment(k, 0), 0}, {canonical_segment(k, k.h), 0}}; });
  if (!exact) return families;
  return rc::gen::weightedOneOf<CapsulePair>({{4, families}, {1, rc::gen::exec(parallel_touching)}});
}
rc::Gen<CapsuleLozenge> capsule_lozenge(bool exact) {
  return pair_generator<CapsuleLozenge>(
      gen::segment_rectangle(exact), exact,
      [](const SegmentRectanglePair& c) { return CapsuleLozenge{{c.segment, 0}, {c.rectangle, 0}}; },
      [](const Canonical& k) { return CapsuleLozenge{{canonical_segment(k, k.h), 0}, {canonical_rectangle(k, 0), 0}}; });
}
rc::Gen<LozengePair> lozenge_pair(bool exact) {
  return pair_generator<LozengePair>(
      gen::rectangle_pair(exact), exact, [](const RectanglePair& c) { return LozengePair{{c.first, 0}, {c.second, 0}}; },
      [](const Canonical& k) { return LozengePair{{canonical_rectangle(k, 0), 0}, {canonical_rectangle(k, k.h), 0}}; });
}

}  // namespace judge
}  // namespace labkit::lab05
