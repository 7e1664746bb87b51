// Lab 03's judge, the moving boxes (step 5): the swept test and the contact interval.
#include "03_separating_axes/judge.h"
#include "03_separating_axes/judge_internal.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab03::judge {

namespace {

// The contact times, for reports.
std::string describe_times(const oracle::ContactTimes& t) {
  return t.contact ? "contact from t = " + fmt(t.first) + " to t = " + fmt(t.last) : "no contact";
}
std::string describe_times(const ContactInterval& t) {
  return t.contact ? "contact from t = " + fmt(t.first) + " to t = " + fmt(t.last) : "no contact";
}

bool meet(const MovingBoxes& in, double from, double to, double slack) {
  return oracle::moving_boxes_meet(in.a, in.velocity_a, in.b, in.velocity_b, from, to, slack);
}

// An axis along which B barely moves relative to A (by less than 1e-12 S over the whole
// motion, but not at all would be exact): the classic source of noise times.
std::string noise_hint(const MovingBoxes& in) {
  const Vec3 w = in.velocity_b - in.velocity_a;
  for (int k = 0; k < 15; ++k) {
    const Vec3 axis = oracle::box_pair_axis(in.a, in.b, k);
    if (axis.norm() < kSurelyIncluded) continue;
    const double moved = std::abs(w.dot(axis)) / axis.norm() * in.duration;
    if (moved > 0 && moved <= 1e-3 * position_tolerance(in))
      return "; along " + axis_name(k) + " B moves by only " + fmt(moved) +
             " over the whole motion, below the rounding "
             "of s and r: times (r - s) / ds from it are rounding noise (test that axis as a static one)";
  }
  return "";
}

// An axis along which B does not move at all while the boxes touch exactly on it
// (|s| = r): a static test with >= for > calls them apart for the whole motion.
std::string touching_still_axis(const MovingBoxes& in) {
  const Vec3 w = in.velocity_b - in.velocity_a;
  for (int k = 0; k < 15; ++k) {
    const Vec3 axis = oracle::box_pair_axis(in.a, in.b, k);
    if (axis.isZero() || w.dot(axis) != 0) continue;
    for (const double sign : {1.0, -1.0})
      if (oracle::box_depth_along(in.a, in.b, sign * axis) == 0)
        return "; along " + axis_name(k) +
               " B does not move and the boxes touch exactly (|s| = r) all the while: touching is not apart, "
               "which takes |s| > r, strictly";
  }
  return "";
}

}  // namespace

Outcome test_moving_boxes(const MovingBoxes& in, bool got, Rules rules) {
  const bool expected = meet(in, 0.0, in.duration, 0.0);
  const bool doubt = rules == Rules::random &&
                     std::abs(oracle::moving_boxes_swept_margin(in.a, in.velocity_a, in.b, in.velocity_b,
                                                                in.duration)) <= kMovingDoubt * position_tolerance(in);
  Outcome o = verdict(got, expected, doubt, rules, "they touch at some time in [0, duration]", "they never touch");
  if (o.verdict != Outcome::Verdict::fail) return o;
  if (expected) {
    const oracle::ContactTimes t = oracle::moving_boxes_contact(in.a, in.velocity_a, in.b, in.velocity_b, in.duration);
    o.why = "the boxes touch while t runs from " + fmt(t.first) + " to " + fmt(t.last) +
            ": contact on all 15 axes at once; your answer says they never touch";
    const Vec3 w = in.velocity_b - in.velocity_a;
    const std::string still = touching_still_axis(in);
    if (t.last - t.first <= 1e-9 * std::max(in.duration, 1e-300))
      o.why += "; they touch for a single instant: first == last (to rounding) is a contact";
    else if (!still.empty())
      o.why += still;
    else if (w.dot(in.b.center - in.a.center) < 0)
      o.why += "; B approaches A: on an axis where ds = W . L < 0, (r - s) / ds is the entering time, not the leaving";
    return o;
  }
  // Never: which axis keeps the swept boxes apart?
  Box a_end = in.a, b_end = in.b;
  a_end.center += in.duration * in.velocity_a;
  b_end.center += in.duration * in.velocity_b;
  bool swept_15 = false;
  for (int k = 0; k < 15 && !swept_15; ++k) {
    const Vec3 axis = oracle::box_pair_axis(in.a, in.b, k);
    if (axis.isZero()) continue;
    for (const double sign : {1.0, -1.0})
      swept_15 = swept_15 || (oracle::box_depth_along(in.a, in.b, sign * axis) < 0 &&
                              oracle::box_depth_along(a_end, b_end, sign * axis) < 0);
  }
  o.why =
      "the boxes never touch: a separating axis keeps them apart at every time in [0, duration]; your answer "
      "says they touch";
  const double moved = (in.velocity_b - in.velocity_a).norm() * in.duration;
  if (moved <= 1e-3 * position_tolerance(in))
    o.why += "; B moves by only " + fmt(moved) +
             " relative to A over the whole motion, below the rounding of s and r: "
             "times (r - s) / ds from such motion are rounding noise (test that axis as a static one)";
  else if (!swept_15)
    o.why +=
        "; none of the 15 axes separates the swept boxes here: only one of table 6.7's axes W x A_i or W x B_j "
        "(W = v_B - v_A) does";
  return o;
}

Outcome find_moving_boxes(const MovingBoxes& in, const ContactInterval& got, Rules rules) {
  const Outcome decision = test_moving_boxes(in, got.contact, rules);
  if (decision.verdict == Outcome::Verdict::fail || !got.contact || !meet(in, 0.0, in.duration, 0.0)) return decision;

  const double tol = position_tolerance(in), end = in.duration;
  const oracle::ContactTimes exact = oracle::moving_boxes_contact(in.a, in.velocity_a, in.b, in.velocity_b, end);
  const std::string expected = describe_times(exact), answer = describe_times(got);
  if (!(0 <= got.first && got.first <= got.last && got.last <= end))
    return fail(expected, answer, "the times must satisfy 0 <= first <= last <= duration");
  const std::string within = " (tolerance " + fmt(tol) + ")";
  // At the reported times the boxes must be within tol of touching...
  if (!meet(in, got.first, got.first, tol))
    return fail(expected, answer,
                "first must be a time of contact: at your first = " + fmt(got.first) +
                    " the boxes are more than tol apart along some axis" + within + noise_hint(in));
  if (!meet(in, got.last, got.last, tol))
    return fail(expected, answer,
                "last must be a time of contact: at your last = " + fmt(got.last) +
                    " the boxes are more than tol apart along some axis" + within + noise_hint(in));
  // ...and outside [first, last] never overlap by more than tol.
  if (got.first > 0 && meet(in, 0.0, got.first, -tol))
    return fail(expected, answer,
                "first must be the first contact: before your first = " + fmt(got.first) +
                    " the boxes already overlap by more than tol" + within + noise_hint(in));
  if (got.last < end && meet(in, got.last, end, -tol))
    return fail(expected, answer,
                "last must be the last contact: after your last = " + fmt(got.last) +
                    " the boxes still overlap by more than tol" + within + noise_hint(in));
  return decision;
}

}  // namespace labkit::lab03::judge
