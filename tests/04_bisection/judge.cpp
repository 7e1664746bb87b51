// Lab 04's judge, steps 1 and 2: the closest point, overlap at a time and bisection, and
// the checks of a reported search that every step shares (steps 3 and 4, the searches by
// sub-steps: judge.substeps.cpp). First, what the generators and the viewer share with
// it (judge.h): the inputs' codec and descriptions, and a motion's pose at a time.
#include "04_bisection/judge.h"
#include "04_bisection/judge_internal.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace labkit {

namespace codec {
void encode(Writer& w, const MotionParameters& m) {
  encode(w, m.start);
  encode(w, m.velocity);
  encode(w, m.acceleration);
  for (int i = 0; i < 3; ++i) w.unit(m.axis[i]);
  w.unit(m.spin);
}
void decode(Reader& r, MotionParameters& m) {
  decode(r, m.start);
  decode(r, m.velocity);
  decode(r, m.acceleration);
  decode(r, m.axis);
  m.spin = r.real();
}
void encode(Writer& w, const SearchTimes& t) {
  w.unit(t.t0);
  w.unit(t.t1);
  w.unit(t.tolerance);
}
void decode(Reader& r, SearchTimes& t) {
  t.t0 = r.real();
  t.t1 = r.real();
  t.tolerance = r.real();
}
}  // namespace codec

std::string describe(const MotionParameters& m) {
  std::string s = "start=" + fmt(m.start);
  if (m.velocity != Vec3::Zero()) s += " velocity=" + fmt(m.velocity);
  if (m.acceleration != Vec3::Zero()) s += " acceleration=" + fmt(m.acceleration);
  if (m.spin != 0) s += " spin=" + fmt(m.spin) + " about axis=" + fmt(m.axis);
  return s;
}
std::string describe(const MovingBody& b) {
  return (b.is_box ? "box " + describe(b.box) : "sphere " + describe(b.sphere)) + "; motion " + describe(b.motion);
}
std::string describe(const SearchTimes& t) {
  return "t0=" + fmt(t.t0) + " t1=" + fmt(t.t1) + " tolerance=" + fmt(t.tolerance);
}

// The header's formula, written once there (StandardMotion).
RigidTransform pose_at(const MotionParameters& m, double t) { return lab04::motion_of(m)(t); }

}  // namespace labkit

namespace labkit::lab04 {

StandardMotion motion_of(const MotionParameters& m) { return {m.start, m.velocity, m.acceleration, m.axis, m.spin}; }

Shape shape_of(const MovingBody& b) { return b.is_box ? shape_of(b.box) : shape_of(b.sphere); }

MovingPair pair_of(const MovingPairCase& c) {
  return {c.a.sphere, motion_of(c.a.motion), shape_of(c.b), motion_of(c.b.motion)};
}

double reach_of(const MovingBody& b) { return b.is_box ? reach(b.box) : reach(b.sphere); }

double body_speed(const MovingBody& b, double t0, double t1) {
  return max_speed(motion_of(b.motion), reach_of(b), t0, t1);
}

namespace {

double size_of(const MovingBody& b) { return b.is_box ? 2 * b.box.half_extents.minCoeff() : 2 * b.sphere.radius; }

}  // namespace

double closing_speed_of(const MovingPairCase& c) {
  return body_speed(c.a, c.times.t0, c.times.t1) + body_speed(c.b, c.times.t0, c.times.t1);
}

double smallest_size_of(const MovingPairCase& c) { return std::min(size_of(c.a), size_of(c.b)); }

namespace judge {

namespace {

using check::ambiguous;
using check::fail;
using check::pass;

// A few units in the last place of x: the slack of comparisons between times that two
// correct programs may round differently.
double ulps(double x) { return 8 * DBL_EPSILON * std::abs(x); }

}  // namespace

std::string summary(const TimeOfImpact& r) {
  std::string s;
  if (r.overlapping_at_start)
    s = "overlapping at the start, t = " + fmt(r.t) + ", t_contact = " + fmt(r.t_contact);
  else if (r.hit)
    s = "a hit: t = " + fmt(r.t) + ", t_contact = " + fmt(r.t_contact);
  else
    s = "no hit, t = " + fmt(r.t);
  if (!r.hit && r.overlapping_at_start) s += " (but hit = false)";
  return s + " (steps " + std::to_string(r.steps) + ", iterations " + std::to_string(r.iterations) + ")";
}

// ---- Shared checks ----------------------------------------------------------------------

Check start_rule(const Scene& sc, const TimeOfImpact& got, double t0, bool& doubt) {
  const Status s = sc.at(t0);
  doubt = doubt || s.doubt;
  if (got.overlapping_at_start) {
    if (!s.overlap && !s.doubt)
      return fail("no overlap at t0 = " + fmt(t0), summary(got), "the bodies are clear at t0: search the interval");
    if (!got.hit || got.t != t0 || got.t_contact != t0)
      return fail("hit = true, t = t_contact = t0 = " + fmt(t0), summary(got),
                  "overlapping at the start reports hit = true and t = t_contact = t0");
    return doubt ? ambiguous() : pass();
  }
  if (s.overlap && !s.doubt)
    return fail(
        "overlapping_at_start (the bodies overlap at t0 = " + fmt(t0) + ")", summary(got),
        "the bodies already overlap at t0 (signed gap " + fmt(sc.signed_gap(t0)) +
            "): there is no last clear time to search for; report overlapping_at_start, hit, t = t_contact = t0");
  return std::nullopt;
}

Check certify(const Scene& sc, const TimeOfImpact& got, double lo, double hi, double tolerance, bool& doubt) {
  const std::string bracket = "t = " + fmt(got.t) + ", t_contact = " + fmt(got.t_contact);
  const std::string within = "lo <= t < t_contact <= hi with [lo, hi] = [" + fmt(lo) + ", " + fmt(hi) + "]";
  if (!(got.t < got.t_contact))
    return fail(
        within, bracket,
        "t is the last clear time and t_contact the first overlapping time found, so t < t_contact" +
            std::string(got.t == got.t_contact ? ": your t is the overlapping end; return t = lo, not hi" : ""));
  if (!(got.t >= lo - ulps(lo) && got.t_contact <= hi + ulps(hi)))
    return fail(within, bracket, "the bracket must lie in the interval the step searches");
  if (!(got.t_contact - got.t <= tolerance + ulps(got.t_contact) + ulps(got.t)))
    return fail("t_contact - t <= tolerance = " + fmt(tolerance), bracket,
                "the bracket is " + fmt(got.t_contact - got.t) +
                    " long, more than the tolerance: finish with bisection, halving while hi - lo > tolerance");
  const Status clear = sc.at(got.t);
  if (clear.overlap) {
    if (!clear.doubt)
      return fail("clear at t (the last clear time)", bracket,
                  "t must be the last clear time, but the bodies overlap at your t = " + fmt(got.t) + " (signed gap " +
                      fmt(sc.signed_gap(got.t)) +
                      "): bisection keeps the half whose ends differ, clear at lo and "
                      "overlapping at hi, and returns t = lo");
    doubt = true;
  }
  const Status contact = sc.at(got.t_contact);
  if (!contact.overlap) {
    if (!contact.doubt)
      return fail("overlapping at t_contact", bracket,
                  "t_contact must be a time of overlap, but the bodies are clear at your t_contact = " +
                      fmt(got.t_contact) + " (distance " + fmt(sc.distance(got.t_contact)) +
                      "): bisection keeps the half whose ends differ, clear at lo and overlapping at hi");
    doubt = true;
  }
  return std::nullopt;
}

// The number of halvings that takes a bracket of length `width` to `tolerance` or less.
// Within rounding of the boundary (the last bracket's length equal to the tolerance, up
// to how differently two programs may round their midpoints) one more or one fewer
// passes; never on exact input.
Check halvings(const TimeOfImpact& got, double width, double lo, double hi, double tolerance, Rules rules,
               const std::string& cause) {
  int k = 0;
  while (std::ldexp(width, -k) > tolerance && k < 4096) ++k;
  const double band = 64 * DBL_EPSILON * std::max(std::abs(lo), std::abs(hi)) + 1e-12 * tolerance;
  const bool borderline = rules == Rules::random && (std::abs(std::ldexp(width, -k) - tolerance) <= band ||
                                                     (k > 0 && std::abs(std::ldexp(width, 1 - k) - tolerance) <= band));
  if (got.iterations == k || (borderline && std::abs(got.iterations - k) <= 1)) return std::nullopt;
  const std::string rule = "halve while hi - lo > tolerance: a bracket " + fmt(width) + " long takes " +
                           std::to_string(k) + " halvings to reach the tolerance " + fmt(tolerance);
  if (got.iterations == k + 1 && std::ldexp(width, -k) == tolerance)
    return fail("iterations = " + std::to_string(k), "iterations = " + std::to_string(got.iterations),
                "one halving too many: " + rule + ", and a bracket exactly the tolerance long is done");
  return fail("iterations = " + std::to_string(k), "iterations = " + std::to_string(got.iterations), rule + cause);
}

Outcome settle(bool doubt) { return doubt ? ambiguous() : pass(); }

// ---- Step 1 ---------------------------------------------------------------------------------

Outcome closest_point(const PointBox& in, const Vec3& got, Rules rules) {
  const double tol = judging::tolerance_of(in);
  const RigidTransform identity = RigidTransform::Identity();
  const double exact = oracle::sphere_box_distance(Sphere{in.point, 0.0}, identity, in.box, identity);
  const double off_box = oracle::sphere_box_distance(Sphere{got, 0.0}, identity, in.box, identity);
  const double reach = (got - in.point).norm();
  (void)rules;  // a closest point is a construction: the same tolerance for every input
  if (off_box > tol)
    return fail("a point of the box", fmt(got),
                "your point is " + fmt(off_box) + " outside the box (tolerance " + fmt(tol) + ")");
  if (std::abs(reach - exact) > tol)
    return fail("a point at distance " + fmt(exact) + " from p", fmt(got),
                "your point is " + fmt(reach) + " from p; the nearest point of the box is " + fmt(exact) +
                    " away (tolerance " + fmt(tol) + ")");
  return pass();
}

Outcome overlap_at(const MovingPairCase& in, bool got_t0, bool got_t1, Rules rules) {
  const Scene sc(in, rules);
  bool doubt = false;
  for (const auto& [t, got] : {std::pair<double, bool>{in.times.t0, got_t0}, {in.times.t1, got_t1}}) {
    const Status s = sc.at(t);
    if (got == s.overlap) {
      doubt = doubt || s.doubt;
      continue;
    }
    if (s.doubt) {
      doubt = true;
      continue;
    }
    const std::string yes = "overlap at t = " + fmt(t), no = "clear at t = " + fmt(t);
    const double gap = sc.signed_gap(t);
    std::string why;
    if (s.overlap) {
      why = "the posed bodies have a point in common at t = " + fmt(t) + " (signed gap " + fmt(gap) +
            "; sets are closed, touching counts): they overlap";
      if (in.b.is_box)
        why += ". Is the box posed (centre moved, axes turned) and the sphere's centre clamped in the box's own axes?";
    } else {
      why = "the posed bodies are apart at t = " + fmt(t) + ", by " + fmt(gap) +
            ": they are clear (only a gap of 0 counts as touching)";
      // A near miss, relative to the bodies or in absolute units: where a fixed epsilon bites.
      if (gap < 1e-6 * sc.scale_at(t) || gap < 1e-3)
        why +=
            "; a fixed epsilon in the comparison (any tolerance in absolute units) turns this near miss into a contact";
    }
    return fail(s.overlap ? yes : no, got ? yes : no, why);
  }
  return settle(doubt);
}

// ---- Step 2 ---------------------------------------------------------------------------------

Outcome bisect(const MovingPairCase& in, const TimeOfImpact& got, Rules rules) {
  const Scene sc(in, rules);
  const SearchTimes& T = in.times;
  bool doubt = false;
  if (const Check o = start_rule(sc, got, T.t0, doubt)) return *o;
  const Status end = sc.at(T.t1);
  doubt = doubt || end.doubt;
  if (!got.hit) {
    if (end.overlap && !end.doubt)
      return fail("a hit (the bodies overlap at t1 = " + fmt(T.t1) + ")", summary(got),
                  "clear at t0 and overlapping at t1: bisect the bracket");
    if (got.t != T.t1) return fail("no hit with t = t1 = " + fmt(T.t1), summary(got), "with no hit, t is t1");
    return settle(doubt);
  }
  if (!end.overlap && !end.doubt)
    return fail("no hit (the bodies are clear at t1 = " + fmt(T.t1) + ")", summary(got),
                "bisect tests only the ends: clear at both, it sees no collision");
  if (const Check o = certify(sc, got, T.t0, T.t1, T.tolerance, doubt)) return *o;
  if (const Check o = halvings(got, T.t1 - T.t0, T.t0, T.t1, T.tolerance, rules)) return *o;
  if (got.steps != 0) return fail("steps = 0", summary(got), "bisect takes no sub-steps");
  return settle(doubt);
}

}  // namespace judge
}  // namespace labkit::lab04
