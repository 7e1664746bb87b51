// Lab 04's judge, steps 3 and 4, the searches by sub-steps: the sub-step rule, point
// sampling then bisection, the tunnelling demonstration, and conservative advancement.
#include "04_bisection/judge.h"
#include "04_bisection/judge_internal.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace labkit::lab04::judge {

namespace {

using check::ambiguous;
using check::fail;
using check::pass;

// The header's sample times and the exact status at each, walked up to the first sample
// that certainly overlaps.
struct Samples {
  std::vector<double> times;   // times[k] = t_k, k = 0..n
  std::vector<Status> status;  // status[k] for k = 1..walked
  int first_overlap = -1;      // the first k that certainly overlaps, or -1
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
      return fail("a hit: sample " + std::to_string(s.first_overlap) +
                      " at t = " + fmt(s.times[std::size_t(s.first_overlap)]) + " overlaps",
                  summary(got),
                  "point sampling tests every sample t_1, ..., t_n in order and stops at the first that "
                  "overlaps: sample " +
                      std::to_string(s.first_overlap) + " does");
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
    return fail(first, summary(got),
                "sample " + std::to_string(k) + " at t = " + fmt(s.times[std::size_t(k)]) + " is clear");
  doubt = doubt || at_k.doubt;
  const double lo = s.times[std::size_t(k - 1)], hi = s.times[std::size_t(k)];
  if (const Check o = certify(sc, got, lo, hi, T.tolerance, doubt)) return *o;
  int from_t0 = 0;  // the halvings of [t0, t_k]: what bisecting from the start costs
  while (std::ldexp(hi - T.t0, -from_t0) > T.tolerance && from_t0 < 4096) ++from_t0;
  const std::string cause = k > 1 && got.iterations == from_t0
                                ? " (you bisected [t0, t_" + std::to_string(k) +
                                      "]: bisect only the first overlapping "
                                      "sub-step [t_" +
                                      std::to_string(k - 1) + ", t_" + std::to_string(k) + "])"
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
    why += "; with n = " + std::to_string(got) +
           " a sub-step moves exactly the size, which is not smaller (floor + 1, not ceil)";
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
  std::string why =
      "two moving bodies close on each other at most at their relative speed, bounded by the sum of "
      "their max_speeds (each over its reach): " +
      fmt(va) + " + " + fmt(vb) + " = " + fmt(exact);
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
  const bool tunnels =
      !start.overlap && !start.doubt && ends.first_overlap < 0 && !ends.status[1].doubt && fine.first_overlap > 0;
  // (A sub-step count on the rule's boundary, one more or one fewer, does not make the
  // demonstration doubtful: the sampling it leads to is judged on its own.)
  if (!tunnels) return ambiguous();
  return frame.verdict == Outcome::Verdict::ambiguous || sub.verdict == Outcome::Verdict::ambiguous ? ambiguous()
                                                                                                    : pass();
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
    else if (exact == 0 && got < 0)
      why += ": overlapping bodies are at distance 0, never negative";
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
      return fail("a hit (the bodies overlap at t1 = " + fmt(T.t1) + ")", summary(got),
                  "the advance to t1 lands in overlap");
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

}  // namespace labkit::lab04::judge
