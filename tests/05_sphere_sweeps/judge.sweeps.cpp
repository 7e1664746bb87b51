// Lab 05's judge, steps 4 to 6: the sweeps of a sphere against a plane, a sphere and a
// capsule, and of a box against a plane, certified exactly with the oracle's gap signs.
#include "05_sphere_sweeps/judge.h"
#include "05_sphere_sweeps/judge_internal.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace labkit::lab05::judge {

namespace {

using check::ambiguous;
using check::fail;
using check::pass;

// How far the exact status of a sweep can move when every length moves by tol and every
// direction component by 1e-9 (kTestDoubt is the same bound for a test): a centre at time t
// moves by sqrt(3) tol (itself) + sqrt(3) tol
// (the displacement v t, |v T| <= S) + sqrt(3) tol (T itself, relative 1e-9), a box's
// corner by 3 sqrt(3) tol + 3 tol more (axes, half-sizes), a plane near the shapes by
// tol (offset) + 1e-9 |x| sqrt(3) (normal, |x| <= 2 sqrt(3) S) < 7 tol. Sphere-sphere
// 2 (5.2 + 1) = 12.4 tol, sphere-plane 5.2 + 1 + 7 = 13.2 tol, box-plane 5.2 + 8.2 + 7
// = 20.4 tol: 24 tol bounds them all.
constexpr double kSweepDoubt = 24.0;

// The distance of x from the plane, rounded (for reports).
double from_plane(const Plane& p, const Vec3& x) {
  const Plane q = scaled(p);
  return std::abs(q.value(x)) / q.normal.norm();
}

template <class Motion> std::string expected_sweep(const Motion& m, double duration) {
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
  double later = -1;                  // the later root (they part again), if any
  std::string wrong_status;           // a likely cause of a wrong status, or ""
  std::string wrong_time;             // a likely cause of a time past the first contact, or ""
};

// A shape whose value f0 + g t against the plane (|n| times the centre's signed distance)
// must come within reach (|n| times its radius): the facts of steps 4 and 6.
Facts plane_facts(const Plane& given, const Vec3& c, const Vec3& v, double reach_unit, double signed_reach_unit,
                  double bounding_unit, const Sweep& got, double duration) {
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
    const SweepStatus would = value0 <= reach_unit               ? SweepStatus::overlapping
                              : toward && would_time <= duration ? SweepStatus::contact
                                                                 : SweepStatus::none;
    const std::string unit = " (is n unit? n . c + offset is |n| = " + fmt(length) +
                             " times the centre's distance: compare it with the reach times |n|)";
    if (got.status == would) f.wrong_status = unit;
    if (got.status == SweepStatus::contact && std::abs(got.time - would_time) <= 1e-6 * std::max(1.0, would_time))
      f.wrong_time = unit;
  }
  // The reach the answered time implies: none (the centre's own time: the plane not
  // offset by the reach), or a box's bounding sphere |h| in place of its reach.
  if (f.wrong_time.empty() && got.status == SweepStatus::contact && std::isfinite(got.time)) {
    const double implied = std::abs(f0 + g * got.time) / n;
    const double close = 1e-6 * std::max({reach_unit, bounding_unit, std::abs(f0) / n});
    if (reach_unit > close && implied <= close)
      f.wrong_time =
          " (your time is when the centre itself reaches the plane: the shape touches it when its centre "
          "is its reach " +
          fmt(reach_unit) + " away, so offset the plane by the reach)";
    else if (bounding_unit > reach_unit * (1 + 1e-6) && std::abs(implied - bounding_unit) <= close)
      f.wrong_time =
          " (your time is when the box's bounding sphere, radius |h| = " + fmt(bounding_unit) +
          ", touches the plane: the box itself reaches only rho = sum_i h_i |n . axis_i| / |n| = " + fmt(reach_unit) +
          " toward it)";
  }
  if (f.wrong_status.empty() && sigma < 0 && got.status == SweepStatus::none)
    f.wrong_status =
        " (the centre starts behind the plane, n . c + offset < 0: the plane is two-sided, and it is "
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
  return plane_facts(in.plane, in.sphere.center, in.velocity, in.sphere.radius, in.sphere.radius, in.sphere.radius, got,
                     in.duration);
}

Facts facts(const BoxPlaneMotion& in, const Sweep& got) {
  const Vec3 unit = scaled(in.plane).normal.normalized();
  double reach = 0, signed_reach = 0;
  for (int i = 0; i < 3; ++i) {
    reach += in.box.half_extents[i] * std::abs(unit.dot(in.box.axes.col(i)));
    signed_reach += in.box.half_extents[i] * unit.dot(in.box.axes.col(i));
  }
  return plane_facts(in.plane, in.box.center, in.velocity, reach, std::abs(signed_reach), in.box.half_extents.norm(),
                     got, in.duration);
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
  else if (R > 0 && (std::abs(dist - k.radius) <= 1e-6 * S || std::abs(dist - r) <= 1e-6 * S) &&
           std::abs(dist - R) > 1e-6 * S)
    f.wrong_time = " (at your time the centre is " + fmt(dist) +
                   " from the axis: that is the capsule grown by one radius "
                   "only; the Minkowski sum grows it by both, R = r + rc = " +
                   fmt(R) + ")";
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
Outcome sweep_verdict(const Motion& m, const Input& in, const Sweep& got, double tol, Rules rules,
                      PointCheck&& point_ok) {
  const double duration = in.duration;
  const bool overlapping_now = oracle::gap_sign(m, 0.0, 0.0) <= 0;
  const bool touches = oracle::min_gap_sign(m, duration, 0.0) <= 0;
  const SweepStatus exact =
      overlapping_now ? SweepStatus::overlapping : (touches ? SweepStatus::contact : SweepStatus::none);
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
            (got.status == SweepStatus::contact && std::isfinite(got.time) ? ", at your time " + fmt(f.gap(got.time))
                                                                           : "") +
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

// ---- Steps 4 to 6 -------------------------------------------------------------------------

Outcome sweep_sphere_plane(const SpherePlaneMotion& in, const Sweep& got, Rules rules) {
  const oracle::SpherePlaneSweep m{in.sphere, in.velocity, in.plane};
  return sweep_verdict(m, in, got, kRelative * scale(in), rules, [&](double t, const Vec3& p, double slack) {
    if (oracle::within_moving_sphere(in.sphere, in.velocity, t, p, slack) && oracle::within_plane(in.plane, p, slack))
      return std::string();
    return "yours is " + fmt((p - in.sphere.center - t * in.velocity).norm()) +
           " from the centre (r = " + fmt(in.sphere.radius) + ") and " + fmt(from_plane(in.plane, p)) +
           " from the plane; the sphere's point nearest the plane is c(t) - sign(s(0)) r n / |n|";
  });
}

Outcome sweep_sphere_sphere(const SphereSphereMotion& in, const Sweep& got, Rules rules) {
  const oracle::SphereSphereSweep m{in.s0, in.s1, in.v0, in.v1};
  const Outcome o = sweep_verdict(m, in, got, kRelative * scale(in), rules, [&](double t, const Vec3& p, double slack) {
    if (oracle::within_moving_sphere(in.s0, in.v0, t, p, slack) &&
        oracle::within_moving_sphere(in.s1, in.v1, t, p, slack))
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
              "one; yours is off by a relative " +
                  fmt(std::abs(got.time - exact) / exact) +
                  " (does your root formula cancel? -b - sqrt(b^2 - ac) subtracts nearly equal numbers when contact "
                  "comes very soon: use q = -b + sqrt(b^2 - ac), t = c / q)");
}

Outcome sweep_sphere_capsule(const SphereCapsuleMotion& in, const Sweep& got, Rules rules) {
  const oracle::SphereCapsuleSweep m{in.sphere, in.velocity, in.capsule};
  return sweep_verdict(m, in, got, kRelative * scale(in), rules, [&](double t, const Vec3& p, double slack) {
    if (oracle::within_moving_sphere(in.sphere, in.velocity, t, p, slack) &&
        oracle::within_capsule(in.capsule, p, slack))
      return std::string();
    return "yours is " + fmt((p - in.sphere.center - t * in.velocity).norm()) +
           " from c(t) (r = " + fmt(in.sphere.radius) + ") and " + fmt(axis_distance(in.capsule, p)) +
           " from the axis (rc = " + fmt(in.capsule.radius) +
           "); the point is r / R of the way from c(t) to its nearest point of the axis";
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

}  // namespace labkit::lab05::judge
