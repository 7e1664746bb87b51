// Lab 05's judge, steps 1 to 3: the distances between cores and the tests of two
// sphere-swept volumes, and the header's S of every input (the sweeps: judge.sweeps.cpp).
#include "05_sphere_sweeps/judge.h"
#include "05_sphere_sweeps/judge_internal.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

namespace labkit::lab05 {

oracle::SquaredDistance core_distance(const SpherePair& p) { return oracle::squared_distance(p.a.center, p.b.center); }
oracle::SquaredDistance core_distance(const SphereCapsule& p) { return oracle::squared_distance(p.a.center, p.b.axis); }
oracle::SquaredDistance core_distance(const SphereLozenge& p) {
  return oracle::squared_distance(p.a.center, p.b.rectangle);
}
oracle::SquaredDistance core_distance(const CapsulePair& p) { return oracle::squared_distance(p.a.axis, p.b.axis); }
oracle::SquaredDistance core_distance(const CapsuleLozenge& p) {
  return oracle::squared_distance(p.a.axis, p.b.rectangle);
}
oracle::SquaredDistance core_distance(const LozengePair& p) {
  return oracle::squared_distance(p.a.rectangle, p.b.rectangle);
}

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

// How far the exact answer of a test can move when every length moves by tol and every
// direction component by 1e-9. A point of a rectangle c + s u + t v moves by at most
// sqrt(3) tol (c) + |s| sqrt(3) 1e-9 + |t| sqrt(3) 1e-9 (u, v; |s|, |t| <= S) + 2 tol
// (the half-sizes) < 7.3 tol; a segment's end or a centre by sqrt(3) tol; each radius
// by tol. So the distance minus r0 - r1 moves by less than 2 * 7.3 + 2 = 16.6 tol:
// 20 tol is a conservative bound (never too small, so no student is failed on a case
// that a perturbation could flip; a bug smaller than 20 tol may pass).
constexpr double kTestDoubt = 20.0;

double largest(std::initializer_list<Vec3> points, std::initializer_list<double> lengths = {}) {
  double s = scale_of(points);
  for (double x : lengths) s = std::max(s, std::abs(x));
  return std::max(s, 1e-300);
}

double plane_distance(const Plane& p) {
  if (p.normal == Vec3::Zero() || !p.normal.allFinite()) return 0.0;
  const Plane q = scaled(p);
  return std::abs(q.offset) / q.normal.norm();
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
    return fail(expected, "squared_distance = " + fmt(got_squared),
                "the squared distance must be a finite number >= 0");
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
  Expect e("the closest pair is the pair of points, one on each shape, with the least distance");
  shape_checks(e);
  const oracle::SquaredDistance pair = oracle::squared_distance(p0, p1);
  e.that("closest pair", pair.compare(d, tol) <= 0,
         fmt(p0) + " and " + fmt(p1) + ", " + fmt(pair.distance()) + " apart", "a pair " + fmt(d) + " apart",
         "your closest points are " + fmt(pair.distance()) + " apart, the shapes only " + fmt(d) + " (tolerance " +
             fmt(tol) + ")");
  return e.outcome();
}

void check_segment_point(Expect& e, const char* name, const Segment& s, double t, const char* t_name, const Vec3& p,
                         double tol) {
  const std::string range = parameter_range_problem(t, 0.0, 1.0, t_name);
  e.that(t_name, range.empty(), fmt(t), "a parameter in [0, 1]", range);
  e.that(name, oracle::parameter_reproduces(s, t, p, tol), fmt(p), std::string("a + ") + t_name + " (b - a)",
         std::string(name) + " must be the segment's point a + " + t_name + " (b - a) at your " + t_name + ": it is " +
             fmt((s.point(t) - p).norm()) + " away from it");
}

void check_rectangle_point(Expect& e, const char* name, const Rectangle& r, double s, double t, const Vec3& p,
                           double tol) {
  const std::string range =
      parameter_range_problem(s, -r.half_u, r.half_u, "s") + parameter_range_problem(t, -r.half_v, r.half_v, "t");
  e.that("s, t", range.empty(), fmt(s) + ", " + fmt(t), "|s| <= half_u and |t| <= half_v", range);
  e.that(name, oracle::rectangle_point_reproduces(r, s, t, p, tol), fmt(p), "center + s u + t v",
         std::string(name) + " must be the rectangle's point center + s u + t v at your s and t: it is " +
             fmt((r.center + s * r.u + t * r.v - p).norm()) + " away from it");
}

void check_on_rectangle(Expect& e, const char* name, const Rectangle& r, const Vec3& p, double tol) {
  const oracle::SquaredDistance d = oracle::squared_distance(p, r);
  e.that(name, d.compare(tol) <= 0, fmt(p), "a point of the rectangle",
         std::string(name) +
             " must be a point of its rectangle (a closest pair is one point on each shape): yours "
             "is " +
             fmt(d.distance()) + " from it (tolerance " + fmt(tol) + ")");
}

// closest0 on the second shape and closest1 on the first: the roles swapped, as after a
// call made with the shapes the other way round whose points were not swapped back.
template <class Shape>
void check_not_swapped(Expect& e, const Shape& first, const Shape& second, const Vec3& closest0, const Vec3& closest1,
                       double tol) {
  const auto on = [tol](const Vec3& p, const Shape& shape) {
    return oracle::squared_distance(p, shape).compare(tol) <= 0;
  };
  const bool swapped = !on(closest0, first) && !on(closest1, second) && on(closest0, second) && on(closest1, first);
  e.that("closest0, closest1", !swapped, fmt(closest0) + ", " + fmt(closest1), "a point of the first, of the second",
         "closest0 is the point on the first shape and closest1 the point on the second: yours are swapped (after "
         "a call with the shapes the other way round, swap its points back)");
}

using check::verdict;

// A test of table 6.1: the cores' exact distance against r0 + r1. The why states the
// rule with the numbers, then a likely cause where the numbers point at one: r0^2 + r1^2
// in place of (r0 + r1)^2, or (`missed`) the candidates a "no" most often forgets.
Outcome test_verdict(const oracle::SquaredDistance& cores, double r0, double r1, double tol, bool got, Rules rules,
                     const char* missed, const char* parallel_note) {
  const bool expected = cores.compare(r0, r1) <= 0;
  const double margin = kTestDoubt * tol;
  const bool doubt =
      rules == Rules::random && cores.compare(r0, r1, margin) <= 0 && cores.compare(r0, r1, -margin) >= 0;
  if (got == expected) return doubt ? ambiguous() : pass();
  if (doubt) return ambiguous();
  const double d = cores.distance();
  std::string why = "two sphere-swept volumes meet exactly when their cores are within r0 + r1: the cores are " +
                    fmt(d) + " apart and r0 + r1 = " + fmt(r0 + r1) + ", so they " +
                    (expected ? "meet" : "do not meet") + ", your answer says they " + (got ? "meet" : "do not");
  if (expected) {
    // The likely causes, most telling first: the sum not squared, the exact touch decided
    // on a rounded distance, a candidate of steps 1 and 2 forgotten.
    std::vector<std::string> causes;
    if (d * d > r0 * r0 + r1 * r1)
      causes.push_back("is it (r0 + r1)^2 you compare with? r0^2 + r1^2 = " + fmt(r0 * r0 + r1 * r1) + " is smaller");
    if (cores.compare(r0, r1) == 0)
      causes.push_back(
          "they touch exactly, and touching counts: a rounded distance can come out a hair above r0 + r1, "
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
  return fail(yes_no(expected) + " (the cores are " + fmt(d) + " apart, r0 + r1 = " + fmt(r0 + r1) + ")", yes_no(got),
              why);
}

double scale_of_shapes(const Sphere& s) { return largest({s.center}, {s.radius}); }
double scale_of_shapes(const Capsule& c) { return largest({c.axis.a, c.axis.b}, {c.radius}); }
double scale_of_shapes(const Lozenge& l) {
  return largest({l.rectangle.center}, {l.rectangle.half_u, l.rectangle.half_v, l.radius});
}

// Where a "no" most often goes wrong, per pair: the candidates of steps 1 and 2.
const char* missed(const SpherePair&) { return "the centres' distance is the cores' distance"; }
const char* missed(const SphereCapsule&) {
  return "the centre's nearest point of the axis is its projection, clamped to the segment";
}
const char* missed(const SphereLozenge&) {
  return "the nearest point of the rectangle clamps s and t to the half-sizes";
}
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
template <class Pair> const char* parallel_note(const Pair&) { return nullptr; }
const char* parallel_note(const CapsulePair&) { return kParallelNote; }
const char* parallel_note(const CapsuleLozenge&) { return kParallelNote; }
const char* parallel_note(const LozengePair&) { return kParallelNote; }

template <class Pair> Outcome test_pair_verdict(const Pair& p, bool got, Rules rules) {
  const double tol = kRelative * std::max(scale_of_shapes(p.a), scale_of_shapes(p.b));
  return test_verdict(core_distance(p), p.a.radius, p.b.radius, tol, got, rules, missed(p), parallel_note(p));
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
  return distance_verdict(
      oracle::squared_distance(in.p, in.segment), got.squared_distance, in.p, got.closest, tol,
      [&](Expect& e) { check_segment_point(e, "closest", in.segment, got.t, "t", got.closest, tol); });
}

Outcome segment_segment(const SegmentPair& in, const SegmentSegmentDistance& got) {
  const double tol = kRelative * scale(in);
  Outcome o = distance_verdict(oracle::squared_distance(in.first, in.second), got.squared_distance, got.closest0,
                               got.closest1, tol, [&](Expect& e) {
                                 check_not_swapped(e, in.first, in.second, got.closest0, got.closest1, tol);
                                 check_segment_point(e, "closest0", in.first, got.s, "s", got.closest0, tol);
                                 check_segment_point(e, "closest1", in.second, got.t, "t", got.closest1, tol);
                               });
  const Vec3 d0 = in.first.b - in.first.a, d1 = in.second.b - in.second.a;
  const double nn = d0.cross(d1).squaredNorm(), scale2 = d0.squaredNorm() * d1.squaredNorm();
  if (o.verdict == Outcome::Verdict::fail && nn > 0 && nn < 1e-8 * scale2)
    o.why +=
        " (the segments are nearly parallel, sin^2 of their angle " + fmt(nn / scale2) +
        ": the textbook denominator a c - b^2 cancels there; |d0 x d1|^2 is the same number without the cancellation)";
  return o;
}

// ---- Step 2 -------------------------------------------------------------------------------

Outcome point_rectangle(const PointRectanglePair& in, const PointRectangleDistance& got) {
  const double tol = kRelative * scale(in);
  return distance_verdict(
      oracle::squared_distance(in.p, in.rectangle), got.squared_distance, in.p, got.closest, tol,
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
                            check_not_swapped(e, in.first, in.second, got.closest0, got.closest1, tol);
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

}  // namespace judge
}  // namespace labkit::lab05
