#include "04_bisection.judge.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <vector>

namespace labkit::lab04 {

StandardMotion motion_of(const MotionParameters& m) { return {m.start, m.velocity, m.acceleration, m.axis, m.spin}; }

Shape shape_of(const MovingBody& b) { return b.is_box ? shape_of(b.box) : shape_of(b.sphere); }

MovingPair pair_of(const MovingPairCase& c) {
  return {c.a.sphere, motion_of(c.a.motion), shape_of(c.b), motion_of(c.b.motion)};
}

namespace {

double reach_of(const MovingBody& b) { return b.is_box ? reach(b.box) : reach(b.sphere); }
double size_of(const MovingBody& b) { return b.is_box ? 2 * b.box.half_extents.minCoeff() : 2 * b.sphere.radius; }

double body_speed(const MovingBody& b, double t0, double t1) {
  return max_speed(motion_of(b.motion), reach_of(b), t0, t1);
}

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

constexpr double kRelative = 1e-9;  // the header's relative tolerance and ambiguity

// A few units in the last place of x: the slack of comparisons between times that two
// correct programs may round differently.
double ulps(double x) { return 8 * DBL_EPSILON * std::abs(x); }

std::string summary(const TimeOfImpact& r) {
  std::string s;
  if (r.overlapping_at_start) s = "overlapping at the start, t = " + fmt(r.t) + ", t_contact = " + fmt(r.t_contact);
  else if (r.hit) s = "a hit: t = " + fmt(r.t) + ", t_contact = " + fmt(r.t_contact);
  else s = "no hit, t = " + fmt(r.t);
  if (!r.hit && r.overlapping_at_start) s += " (but hit = false)";
  return s + " (steps " + std::to_string(r.steps) + ", iterations " + std::to_string(r.iterations) + ")";
}

// Whether the bodies overlap at a time, exactly, and whether that answer is in doubt.
struct Status {
  bool overlap = false;
  bool doubt = false;
};

// One case, ready to pose at any time.
class Scene {
 public:
  Scene(const MovingPairCase& c, Rules rules)
      : case_(c), pair_(pair_of(c)), rules_(rules), delta_(kRelative * check::scale_of_input(c)) {}

  Status at(double t) const {
    const RigidTransform pa = pair_.motion_a(t), pb = pair_.motion_b(t);
    Status s;
    s.overlap = case_.b.is_box ? oracle::sphere_box_overlap(case_.a.sphere, pa, case_.b.box, pb)
                               : oracle::spheres_overlap(case_.a.sphere, pa, case_.b.sphere, pb);
    s.doubt = rules_ == Rules::random && std::abs(signed_gap(pa, pb)) <= margin(t);
    return s;
  }

  // Do the bodies overlap by at least `depth` (their signed gap <= -depth), exactly?
  // Shrinks the sphere by depth (rounded down); no claim when it is thinner than that.
  bool deep_at(double t, double depth) const {
    const RigidTransform pa = pair_.motion_a(t), pb = pair_.motion_b(t);
    const double reach = case_.a.sphere.radius + (case_.b.is_box ? 0.0 : case_.b.sphere.radius);
    const double shrunk = (reach - depth) * (1 - 4 * DBL_EPSILON);
    if (!(shrunk >= 0)) return false;
    const Sphere a{case_.a.sphere.center, shrunk};
    if (case_.b.is_box) return oracle::sphere_box_overlap(a, pa, case_.b.box, pb);
    return oracle::spheres_overlap(a, pa, Sphere{case_.b.sphere.center, 0.0}, pb);
  }

  double distance(double t) const {
    const RigidTransform pa = pair_.motion_a(t), pb = pair_.motion_b(t);
    return case_.b.is_box ? oracle::sphere_box_distance(case_.a.sphere, pa, case_.b.box, pb)
                          : oracle::spheres_distance(case_.a.sphere, pa, case_.b.sphere, pb);
  }

  // The signed gap in doubles (negative: how deep they overlap), and the margin by which
  // the input's perturbation could move it, at time t.
  double signed_gap(double t) const { return signed_gap(pair_.motion_a(t), pair_.motion_b(t)); }
  double margin(double t) const { return 2 * (move(case_.a, t) + move(case_.b, t)) + 1e-12 * scale_at(t); }

  // The header's S at time t: the largest absolute coordinate of the posed bodies.
  double scale_at(double t) const {
    const RigidTransform pa = pair_.motion_a(t), pb = pair_.motion_b(t);
    double s = std::max((pa * case_.a.sphere.center).cwiseAbs().maxCoeff(), case_.a.sphere.radius);
    if (case_.b.is_box)
      s = std::max({s, (pb * case_.b.box.center).cwiseAbs().maxCoeff(), case_.b.box.half_extents.cwiseAbs().maxCoeff()});
    else
      s = std::max({s, (pb * case_.b.sphere.center).cwiseAbs().maxCoeff(), case_.b.sphere.radius});
    return s;
  }

  const MovingPair& pair() const { return pair_; }

 private:
  double signed_gap(const RigidTransform& pa, const RigidTransform& pb) const {
    const Vec3 q = pa * case_.a.sphere.center;
    const double r = case_.a.sphere.radius;
    if (!case_.b.is_box) return (q - pb * case_.b.sphere.center).norm() - r - case_.b.sphere.radius;
    const Box& b = case_.b.box;
    const Vec3 d = q - pb * b.center;
    const Mat3 axes = pb.linear() * b.axes;
    double outside = 0.0, inside = -INFINITY;
    for (int k = 0; k < 3; ++k) {
      const double excess = std::abs(d.dot(axes.col(k))) - b.half_extents[k];
      if (excess > 0) outside += excess * excess;
      inside = std::max(inside, excess);
    }
    return (outside > 0 ? std::sqrt(outside) : inside) - r;
  }

  // How far one body's points can move when every length of the input moves by
  // delta = 1e-9 S and every unit-free number (axis, spin, box axes, times) by 1e-9:
  //   its origin, start + velocity t + acceleration t^2/2:  sqrt(3) delta (1 + |t| + t^2/2)
  //   its turn: the angle moves by 1e-9 |t|, the unit axis by at most 2e-9, which moves
  //     a point at distance reach by at most reach 1e-9 (|t| + 4)
  //   its shape: centre sqrt(3) delta, radius delta or a corner sqrt(3) delta, a box's
  //     axes 3e-9 |h|
  //   the time itself (t0 and t1 move a sample time by 1e-9): its speed times 2e-9.
  // The gap between two convex bodies moves by at most what their points move, so the
  // margin is the sum for both bodies; doubled, and with room for the rounding of the
  // gap computed in doubles.
  double move(const MovingBody& b, double t) const {
    const double reach = reach_of(b), at = std::abs(t);
    const double shape = b.is_box ? 2 * std::sqrt(3.0) * delta_ + 3 * kRelative * b.box.half_extents.norm()
                                  : (std::sqrt(3.0) + 1) * delta_;
    return std::sqrt(3.0) * delta_ * (1 + at + 0.5 * t * t) + kRelative * reach * (at + 4) + shape +
           2 * kRelative * max_speed(motion_of(b.motion), reach, t, t);
  }

  MovingPairCase case_;
  MovingPair pair_;
  Rules rules_;
  double delta_;
};

// ---- Shared checks ----------------------------------------------------------------------

using Check = std::optional<Outcome>;  // a failure, or nothing

// Overlap at t0: the answer must be overlapping_at_start exactly when the bodies overlap
// there. Returns the final verdict when the answer says overlapping_at_start.
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
    return fail("overlapping_at_start (the bodies overlap at t0 = " + fmt(t0) + ")", summary(got),
                "the bodies already overlap at t0 (signed gap " + fmt(sc.signed_gap(t0)) +
                    "): there is no last clear time to search for; report overlapping_at_start, hit, t = t_contact = t0");
  return std::nullopt;
}

// A reported bracket [t, t_contact]: inside [lo, hi] (give or take rounding), no longer
// than the tolerance, clear at t and overlapping at t_contact, exactly.
Check certify(const Scene& sc, const TimeOfImpact& got, double lo, double hi, double tolerance, bool& doubt) {
  const std::string bracket = "t = " + fmt(got.t) + ", t_contact = " + fmt(got.t_contact);
  const std::string within = "lo <= t < t_contact <= hi with [lo, hi] = [" + fmt(lo) + ", " + fmt(hi) + "]";
  if (!(got.t < got.t_contact))
    return fail(within, bracket,
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
                      fmt(sc.signed_gap(got.t)) + "): bisection keeps the half whose ends differ, clear at lo and "
                      "overlapping at hi, and returns t = lo");
    doubt = true;
  }
  const Status contact = sc.at(got.t_contact);
  if (!contact.overlap) {
    if (!contact.doubt)
      return fail("overlapping at t_contact", bracket,
                  "t_contact must be a time of overlap, but the bodies are clear at your t_contact = " + fmt(got.t_contact) +
                      " (distance " + fmt(sc.distance(got.t_contact)) +
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
              const std::string& cause = "") {
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

// ---- Point sampling ---------------------------------------------------------------------

// The header's sample times and the exact status at each, walked up to the first sample
// that certainly overlaps.
struct Samples {
  std::vector<double> times;    // times[k] = t_k, k = 0..n
  std::vector<Status> status;   // status[k] for k = 1..walked
  int first_overlap = -1;       // the first k that certainly overlaps, or -1
};

Samples walk(const Scene& sc, const SearchTimes& T, int n) {
  Samples s;
  s.times.resize(std::size_t(n) + 1);
  s.status.resize(std::size_t(n) + 1);
  for (int k = 0; k <= n; ++k) s.times[std::size_t(k)] = k == n ? T.t1 : T.t0 + (T.t1 - T.t0) * k / n;
  for (int k = 1; k <= n; ++k) {
    s.status[std::size_t(k)] = sc.at(s.times[std::size_t(k)]);
    if (s.status[std::size_t(k)].overlap && !s.status[std::size_t(k)].doubt) {
      s.first_overlap = k;
      break;
    }
  }
  return s;
}

Outcome judge_sampled(const Scene& sc, const SearchTimes& T, int n, const Samples& s, const TimeOfImpact& got,
                      Rules rules) {
  bool doubt = false;
  if (const Check o = start_rule(sc, got, T.t0, doubt)) return *o;
  const int walked = s.first_overlap > 0 ? s.first_overlap : n;
  if (!got.hit) {
    if (s.first_overlap > 0)
      return fail("a hit: sample " + std::to_string(s.first_overlap) + " at t = " + fmt(s.times[std::size_t(s.first_overlap)]) +
                      " overlaps",
                  summary(got), "point sampling tests every sample t_1, ..., t_n in order and stops at the first that "
                                "overlaps: sample " + std::to_string(s.first_overlap) + " does");
    if (got.t != T.t1 || got.steps != n)
      return fail("no hit with t = t1 = " + fmt(T.t1) + " and steps = " + std::to_string(n), summary(got),
                  "with no overlapping sample, t = t1 and every sample counts as a step");
    for (int k = 1; k <= n; ++k) doubt = doubt || s.status[std::size_t(k)].doubt;
    return settle(doubt);
  }
  const int k = got.steps;
  const std::string first = s.first_overlap > 0 ? "the first overlapping sample is " + std::to_string(s.first_overlap) +
                                                      ", at t = " + fmt(s.times[std::size_t(s.first_overlap)])
                                                : "no sample overlaps: no hit";
  if (k < 1 || k > walked) return fail(first, summary(got), "steps must name the first sample that overlaps");
  for (int j = 1; j < k; ++j) doubt = doubt || s.status[std::size_t(j)].doubt;
  const Status& at_k = s.status[std::size_t(k)];
  if (!at_k.overlap && !at_k.doubt)
    return fail(first, summary(got), "sample " + std::to_string(k) + " at t = " + fmt(s.times[std::size_t(k)]) + " is clear");
  doubt = doubt || at_k.doubt;
  const double lo = s.times[std::size_t(k - 1)], hi = s.times[std::size_t(k)];
  if (const Check o = certify(sc, got, lo, hi, T.tolerance, doubt)) return *o;
  int from_t0 = 0;  // the halvings of [t0, t_k]: what bisecting from the start costs
  while (std::ldexp(hi - T.t0, -from_t0) > T.tolerance && from_t0 < 4096) ++from_t0;
  const std::string cause = k > 1 && got.iterations == from_t0
                                ? " (you bisected [t0, t_" + std::to_string(k) + "]: bisect only the first overlapping "
                                  "sub-step [t_" + std::to_string(k - 1) + ", t_" + std::to_string(k) + "])"
                                : "";
  if (const Check o = halvings(got, hi - lo, lo, hi, T.tolerance, rules, cause)) return *o;
  return settle(doubt);
}

// The lecture's rule, exactly: the smallest n >= 1 with speed * step < n * size, and
// whether rounding could make a careful program answer one more or one fewer (the ratio
// within a relative 1e-12 of a whole number).
struct Rule {
  long long n = 0;  // 0: none up to kMaxSubsteps
  bool borderline = false;
};

Rule rule_for(double speed, double step, double size) {
  if (!(size > 0)) return {};
  const long double ratio = (long double)speed * step / size;
  if (!(ratio < kMaxSubsteps)) return {0, std::abs(ratio - kMaxSubsteps) <= 1e-12L * ratio};
  const long double whole = std::nearbyint(ratio);
  return {(long long)std::floor(ratio) + 1, std::abs(ratio - whole) <= 1e-12L * std::max(1.0L, ratio)};
}

}  // namespace

// ---- Step 1 ---------------------------------------------------------------------------------

Outcome closest_point(const PointBox& in, const Vec3& got, Rules rules) {
  const double tol = kRelative * check::scale_of_input(in);
  const RigidTransform identity = RigidTransform::Identity();
  const double exact = oracle::sphere_box_distance(Sphere{in.point, 0.0}, identity, in.box, identity);
  const double off_box = oracle::sphere_box_distance(Sphere{got, 0.0}, identity, in.box, identity);
  const double reach = (got - in.point).norm();
  (void)rules;  // a closest point is a construction: the same tolerance for every input
  if (off_box > tol)
    return fail("a point of the box", fmt(got), "your point is " + fmt(off_box) + " outside the box (tolerance " + fmt(tol) + ")");
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
      if (in.b.is_box) why += ". Is the box posed (centre moved, axes turned) and the sphere's centre clamped in the box's own axes?";
    } else {
      why = "the posed bodies are apart at t = " + fmt(t) + ", by " + fmt(gap) + ": they are clear (only a gap of 0 counts as touching)";
      // A near miss, relative to the bodies or in absolute units: where a fixed epsilon bites.
      if (gap < 1e-6 * sc.scale_at(t) || gap < 1e-3)
        why += "; a fixed epsilon in the comparison (any tolerance in absolute units) turns this near miss into a contact";
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

// ---- Step 3 ---------------------------------------------------------------------------------

Outcome substeps_for(const SubstepRule& in, int got, Rules rules) {
  Rule r = rule_for(in.max_speed, in.step, in.smallest_size);
  if (rules == Rules::exact) r.borderline = false;
  if (got == r.n) return r.borderline ? ambiguous() : pass();
  if (r.borderline && std::abs(got - r.n) <= 1) return ambiguous();
  const double ratio = in.max_speed * in.step / in.smallest_size;
  std::string why =
      r.n == 0 ? (in.smallest_size > 0 ? "no n up to kMaxSubsteps = 2^20 makes speed * step / n < size: return 0"
                                       : "a size of zero can always be missed: return 0")
               : "the rule is strict, speed * step / n < size: n = " + std::to_string(r.n) +
                     " is the smallest n, since speed * step / size = " + fmt(ratio);
  if (r.n > 0 && got == r.n - 1 && !r.borderline && std::nearbyint(ratio) == got)
    why += "; with n = " + std::to_string(got) + " a sub-step moves exactly the size, which is not smaller (floor + 1, not ceil)";
  return fail(std::to_string(r.n), std::to_string(got), why);
}

Outcome sample_then_bisect(const SampledPair& in, const TimeOfImpact& got, Rules rules) {
  const Scene sc(in.pair, rules);
  const int n = std::max(1, in.substeps);
  return judge_sampled(sc, in.pair.times, n, walk(sc, in.pair.times, n), got, rules);
}

Outcome closing_speed(const MovingPairCase& in, double got) {
  const double va = body_speed(in.a, in.times.t0, in.times.t1), vb = body_speed(in.b, in.times.t0, in.times.t1);
  const double exact = va + vb, tol = 1e-9 * exact;
  if (std::abs(got - exact) <= tol) return pass();
  std::string why = "two moving bodies close on each other at most at their relative speed, bounded by the sum of "
                    "their max_speeds (each over its reach): " + fmt(va) + " + " + fmt(vb) + " = " + fmt(exact);
  if (std::abs(got - std::max(va, vb)) <= tol) why += "; yours is the faster body's speed alone";
  return fail(fmt(exact), fmt(got), why);
}

Outcome tunnelling(const MovingPairCase& in, double got_speed, int got_substeps, const TimeOfImpact& frame_only,
                   const TimeOfImpact& substepped) {
  const Outcome bound = closing_speed(in, got_speed);
  if (bound.verdict == Outcome::Verdict::fail)
    return fail("closing_speed = " + bound.expected, bound.got, "the sub-step rule's speed: " + bound.why);
  const double speed = lab04::closing_speed_of(in), span = in.times.t1 - in.times.t0, size = smallest_size_of(in);
  const Outcome count = substeps_for(SubstepRule{speed, span, size}, got_substeps);
  if (count.verdict == Outcome::Verdict::fail)
    return fail("substeps_for(" + fmt(speed) + ", " + fmt(span) + ", " + fmt(size) + ") = " + count.expected,
                std::to_string(got_substeps), count.why);
  const Scene sc(in, Rules::random);
  const Samples ends = walk(sc, in.times, 1);
  const Outcome frame = judge_sampled(sc, in.times, 1, ends, frame_only, Rules::random);
  if (frame.verdict == Outcome::Verdict::fail)
    return fail(frame.expected, frame.got, "sampling only the frame's ends (1 sub-step): " + frame.why);
  const int n = std::max(1, got_substeps);
  const Samples fine = walk(sc, in.times, n);
  const Outcome sub = judge_sampled(sc, in.times, n, fine, substepped, Rules::random);
  if (sub.verdict == Outcome::Verdict::fail)
    return fail(sub.expected, sub.got, "sampling with " + std::to_string(n) + " sub-steps: " + sub.why);
  // The demonstration itself: clear at both ends for certain, so the frame's samples
  // miss; a sample of the rule's sub-steps overlaps for certain, so they find it.
  const Status start = sc.at(in.times.t0);
  const bool tunnels = !start.overlap && !start.doubt && ends.first_overlap < 0 && !ends.status[1].doubt &&
                       fine.first_overlap > 0;
  // (A sub-step count on the rule's boundary, one more or one fewer, does not make the
  // demonstration doubtful: the sampling it leads to is judged on its own.)
  if (!tunnels) return ambiguous();
  return frame.verdict == Outcome::Verdict::ambiguous || sub.verdict == Outcome::Verdict::ambiguous ? ambiguous() : pass();
}

// ---- Step 4 ---------------------------------------------------------------------------------

Outcome distance_at(const MovingPairCase& in, double got_t0, double got_t1) {
  const Scene sc(in, Rules::random);
  for (const auto& [t, got] : {std::pair<double, double>{in.times.t0, got_t0}, {in.times.t1, got_t1}}) {
    const double exact = sc.distance(t), tol = kRelative * sc.scale_at(t);
    if (std::abs(got - exact) <= tol) continue;
    const double radii = in.a.sphere.radius + (in.b.is_box ? 0.0 : in.b.sphere.radius);
    std::string why = "the distance between the closed bodies is the gap between their surfaces, " + fmt(exact) +
                      " at t = " + fmt(t) + " (0 when they overlap); yours is off by " + fmt(std::abs(got - exact)) +
                      " (tolerance 1e-9 S = " + fmt(tol) + ")";
    if (radii > 0 && std::abs(got - exact - radii) <= tol + 1e-9 * radii)
      why += ": that is the radii " + fmt(radii) + ", as if measured between centres";
    else if (exact == 0 && got < 0) why += ": overlapping bodies are at distance 0, never negative";
    return fail(fmt(exact) + " at t = " + fmt(t), fmt(got), why);
  }
  return pass();
}

double closing_speed_of(const AdvancedPair& in) { return in.speed_factor * lab04::closing_speed_of(in.pair); }

Outcome advance(const AdvancedPair& in, const TimeOfImpact& got, Rules rules) {
  const Scene sc(in.pair, rules);
  const SearchTimes& T = in.pair.times;
  bool doubt = false;
  if (const Check o = start_rule(sc, got, T.t0, doubt)) return *o;
  if (got.hit) {
    // The advances divide a distance by a speed, so even on exact input the poses at t
    // and t_contact are rounded: near a touch there, the ambiguity margin applies.
    const Scene rounded(in.pair, Rules::random);
    if (const Check o = certify(rounded, got, T.t0, T.t1, T.tolerance, doubt)) return *o;
  } else {
    if (got.t != T.t1) return fail("no hit with t = t1 = " + fmt(T.t1), summary(got), "with no hit, t is t1");
    const Status end = sc.at(T.t1);
    if (end.overlap && !end.doubt)
      return fail("a hit (the bodies overlap at t1 = " + fmt(T.t1) + ")", summary(got), "the advance to t1 lands in overlap");
    doubt = doubt || end.doubt;
  }
  // Conservative: no contact that lasts longer than the tolerance may lie before t. The
  // signed gap changes at most at the closing speed v, so where the bodies overlap by
  // depth they overlap for depth / v before and after; with depth = 2 v tolerance (plus
  // the ambiguity margin) that contact lasts 4 tolerances, and neither a safe advance
  // nor a forced one of one tolerance can pass it. Witnesses are looked for at the
  // lecture's sub-step times (at most 512); the doubles only suggest them, the oracle
  // confirms each one exactly.
  const double true_speed = lab04::closing_speed_of(in.pair), speed = closing_speed_of(in);
  if (!(speed >= true_speed)) return settle(doubt);  // not a bound: no claim
  const double span = T.t1 - T.t0, limit = got.hit ? got.t : T.t1;
  const Rule rule = rule_for(true_speed, span, smallest_size_of(in.pair));
  const int m = int(std::clamp<long long>(rule.n == 0 ? 512 : rule.n, 1, 512));
  for (int k = 1; k <= m; ++k) {
    const double s = k == m ? T.t1 : T.t0 + span * k / m;
    if (got.hit ? s >= limit : s > limit) break;
    const double depth = 2 * speed * T.tolerance + sc.margin(s);
    if (sc.signed_gap(s) > -depth) continue;  // not deep, as far as the doubles can tell
    if (sc.deep_at(s, depth))
      return fail("a contact no later than t = " + fmt(s), summary(got),
                  "at t = " + fmt(s) + " the bodies overlap by " + fmt(-sc.signed_gap(s)) +
                      ", more than 2 x speed x tolerance: that contact lasts longer than the tolerance, and the "
                      "advancement passed it");
  }
  return settle(doubt);
}

}  // namespace judge
}  // namespace labkit::lab04
