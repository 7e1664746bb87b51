#include "03_separating_axes.judge.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab03::judge {

namespace {

using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;

// Edge axes shorter than this are left out of the least-penetration search (the
// header's 1e-6), and between these two bounds either choice passes.
constexpr double kShortest = 0.5e-6, kSurelyIncluded = 2e-6;

// How far the exact answer can be from flipping, in units of tol (the header's
// perturbation: positions by tol, axis entries by 1e-9).
//  - A corner c + sum_k s_k h_k A_k moves by at most sqrt(3) tol (the center) plus, on
//    each axis, tol (h_k) and h_k sqrt(3) 1e-9 <= sqrt(3) tol (A_k): (4 sqrt(3) + 3) tol,
//    under 10 tol. Both boxes: the distance or the penetration depth moves by at most
//    20 tol; 24 leaves room for the margin's own rounding (about 1e-15 S).
constexpr double kBoxDoubt = 24;
//  - Moving boxes add the relative displacement duration (v_B - v_A): each box's end
//    position moves by tol per coordinate (velocity and start together: at most
//    2 sqrt(3) tol per box) and the duration by 1e-9 of itself (at most 2 sqrt(3) tol
//    of displacement per box): 20 + 4 sqrt(3) + 4 sqrt(3), under 34; 40 with room.
constexpr double kMovingDoubt = 40;

using check::verdict;

bool boxes_in_doubt(const BoxPair& in, Rules rules) {
  return rules == Rules::random && std::abs(oracle::box_pair_margin(in.a, in.b)) <= kBoxDoubt * tolerance_of(in);
}

double sum_of_extents(const BoxPair& in) { return in.a.half_extents.sum() + in.b.half_extents.sum(); }

std::string axis_name(int index) {
  if (index < 0 || index > 14) return "axis " + std::to_string(index);
  static const char* names[] = {"A_0", "A_1", "A_2", "B_0", "B_1", "B_2"};
  if (index < 6) return "axis " + std::to_string(index) + " (" + names[index] + ")";
  return "axis " + std::to_string(index) + " (A_" + std::to_string((index - 6) / 3) + " x B_" +
         std::to_string((index - 6) % 3) + ")";
}

// How loosely rounding fixes the direction of the lab's axis `index`: 1e-15 / |A_i x B_j|
// for an edge axis (the header's allowance), next to nothing for a face axis.
double direction_slack(double length, int index) { return index < 6 ? 1e-15 : 1e-15 / length; }

// The exact depth along axis `index`, the smaller of the two directions.
double least_depth_along(const BoxPair& in, const Vec3& axis) {
  return std::min(oracle::box_depth_along(in.a, in.b, axis), oracle::box_depth_along(in.a, in.b, -axis));
}

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

}  // namespace

Outcome project_box(const BoxOnAxis& in, const Projection& got) {
  const double tol = tolerance_of(in) * in.axis.norm();
  const oracle::BoxProjection exact = oracle::box_projection(in.box, in.axis);
  Expect e;
  e.near("center", got.center, exact.center, tol);
  e.near("radius", got.radius, exact.radius, tol);
  return e.outcome();
}

Outcome separated_on_axis(const BoxPairOnAxis& in, bool got, Rules rules) {
  const BoxPair pair{in.a, in.b};
  const bool expected = oracle::boxes_separated_along(in.a, in.b, in.axis);
  // The gap (> 0) or overlap (< 0) along the unit axis can flip when it is within what
  // the corners' moves (20 tol) and the axis's turn by 1e-9 per component (sqrt(3) 1e-9
  // times the corners' distance from the origin, for each box) can do.
  double doubt = 0.0;
  if (rules == Rules::random && in.axis != Vec3::Zero()) {
    double reach = 0.0;
    for (const Box* box : {&in.a, &in.b}) {
      double farthest = 0.0;
      for (int i = 0; i < 8; ++i) farthest = std::max(farthest, box->corner(i).norm());
      reach += farthest;
    }
    doubt = kBoxDoubt * tolerance_of(pair) + 2 * std::sqrt(3.0) * 1e-9 * reach;
  }
  const double overlap = least_depth_along(pair, in.axis);
  return verdict(got, expected, in.axis != Vec3::Zero() && std::abs(overlap) <= doubt, rules, "separated",
                 "not separated (the projections overlap or touch)");
}

Outcome box_axes(const BoxPair& in, const std::array<Vec3, 15>& got) {
  Expect e;
  for (int k = 0; k < 15; ++k) {
    const Vec3 exact = oracle::box_pair_axis(in.a, in.b, k);
    if ((got[k] - exact).norm() > 1e-12)
      e.that(axis_name(k), false, fmt(got[k]), fmt(exact),
             axis_name(k) + " is off by " + fmt((got[k] - exact).norm()) + " (tolerance 1e-12)");
  }
  return e.outcome();
}

Outcome test_boxes(const BoxPair& in, bool got, Rules rules) {
  return verdict(got, oracle::boxes_intersect(in.a, in.b), boxes_in_doubt(in, rules), rules, "intersecting",
                 "separated");
}

Outcome find_boxes(const BoxPair& in, const BoxContact& got, Rules rules) {
  const bool expected = oracle::boxes_intersect(in.a, in.b);
  const bool doubt = boxes_in_doubt(in, rules);
  const Outcome decision = verdict(got.intersecting, expected, doubt, rules, "intersecting", "separated");
  if (decision.verdict == Outcome::Verdict::fail) return decision;

  const double tol = tolerance_of(in);
  const std::string answer = (got.intersecting ? "intersecting, " : "separated, ") + axis_name(got.axis_index) +
                             " = " + fmt(got.axis) + ", depth " + fmt(got.depth);
  if (got.axis_index < 0 || got.axis_index > 14 || !got.axis.allFinite() || !std::isfinite(got.depth))
    return fail("an axis index from 0 to 14 with a finite axis and depth", answer, "the axis or the depth is missing");
  if (std::abs(got.axis.norm() - 1) > 1e-9)
    return fail("a unit axis", answer, "the axis has length " + fmt(got.axis.norm()) + ", not 1");
  const Vec3 numbered = oracle::box_pair_axis(in.a, in.b, got.axis_index);
  const double length = numbered.norm();
  if (got.intersecting && got.axis_index >= 6 && length < kShortest)
    return fail("a face axis or an edge axis with |A_i x B_j| >= 1e-6", answer,
                axis_name(got.axis_index) + " has length " + fmt(length) +
                    ": nearly parallel edges are left out of the least-penetration search");
  if (length > 0 && got.axis.cross(numbered / length).norm() > 1e-9 + direction_slack(length, got.axis_index))
    return fail(axis_name(got.axis_index) + " = +-" + fmt(Vec3(numbered / length)), answer,
                "the axis is not parallel to the axis its index names");
  const double depth = oracle::box_depth_along(in.a, in.b, got.axis);
  if (std::abs(got.depth - depth) > tol)
    return fail("depth " + fmt(depth) + " along your axis", answer,
                "the depth is off by " + fmt(std::abs(got.depth - depth)) + " (tolerance " + fmt(tol) +
                    "); it is r_A + r_B - |(c_B - c_A) . axis|, with the axis pointing from A toward B");

  if (!got.intersecting) {
    // A separating axis must separate, with B on its positive side: exactly, or but for
    // an overlap within tol (the rounding of an axis along which the boxes only just
    // touch, while another separates them clearly).
    if (doubt || oracle::box_beyond_along(in.a, in.b, got.axis) || depth <= tol) return decision;
    if (oracle::box_beyond_along(in.b, in.a, got.axis))
      return fail("an axis pointing from A toward B", answer, "the axis separates the boxes but points from B to A");
    return fail("a separating axis", answer,
                "the boxes' projections onto this axis overlap by " + fmt(depth) + ": it does not separate them");
  }

  // Intersecting: no included axis may have a clearly smaller depth.
  const double spread = 1e-15 * ((in.b.center - in.a.center).norm() + sum_of_extents(in));
  for (int k = 0; k < 15; ++k) {
    const Vec3 axis = oracle::box_pair_axis(in.a, in.b, k);
    const double n = axis.norm();
    if (k >= 6 && n < kSurelyIncluded) continue;  // left out, or optional
    const double slack = tol + (k >= 6 ? spread / n : 0.0) + (doubt ? 2 * kBoxDoubt * tol : 0.0);
    const double least = least_depth_along(in, axis);
    if (got.depth > least + slack)
      return fail(axis_name(k) + " with depth " + fmt(least) + " (or another at most that deep)", answer,
                  "that is not the least penetration: " + axis_name(k) + " = " + fmt(Vec3(axis / n)) + " has depth " +
                      fmt(least));
  }
  return decision;
}

Outcome test_triangles(const TrianglePair& in, bool got, Rules rules) {
  const bool expected = oracle::triangles_intersect(in.t0, in.t1);
  bool doubt = false;
  if (rules == Rules::random) {
    const double tol = tolerance_of(in);
    doubt = oracle::triangle_pair_in_doubt(in.t0, in.t1, tol);
    // Sampling as well, for triangles whose boxes come near each other: a flip it finds
    // would mean the conservative test above missed one.
    if (!doubt) {
      const Vec3 low0 = in.t0.v0.cwiseMin(in.t0.v1).cwiseMin(in.t0.v2), high0 = in.t0.v0.cwiseMax(in.t0.v1).cwiseMax(in.t0.v2);
      const Vec3 low1 = in.t1.v0.cwiseMin(in.t1.v1).cwiseMin(in.t1.v2), high1 = in.t1.v0.cwiseMax(in.t1.v1).cwiseMax(in.t1.v2);
      const bool near = ((low0.array() - 8 * tol) <= high1.array()).all() && ((low1.array() - 8 * tol) <= high0.array()).all();
      if (near)
        doubt = check::flips_under_perturbation(in, [](const TrianglePair& p) { return oracle::triangles_intersect(p.t0, p.t1); });
    }
  }
  return verdict(got, expected, doubt, rules, "intersecting", "not intersecting");
}

Outcome test_moving_boxes(const MovingBoxes& in, bool got, Rules rules) {
  const bool expected = meet(in, 0.0, in.duration, 0.0);
  const bool doubt =
      rules == Rules::random &&
      std::abs(oracle::moving_boxes_swept_margin(in.a, in.velocity_a, in.b, in.velocity_b, in.duration)) <=
          kMovingDoubt * tolerance_of(in);
  return verdict(got, expected, doubt, rules, "they touch at some time in [0, duration]", "they never touch");
}

Outcome find_moving_boxes(const MovingBoxes& in, const ContactInterval& got, Rules rules) {
  const Outcome decision = test_moving_boxes(in, got.contact, rules);
  if (decision.verdict == Outcome::Verdict::fail || !got.contact || !meet(in, 0.0, in.duration, 0.0)) return decision;

  const double tol = tolerance_of(in), end = in.duration;
  const oracle::ContactTimes exact = oracle::moving_boxes_contact(in.a, in.velocity_a, in.b, in.velocity_b, end);
  const std::string expected = describe_times(exact), answer = describe_times(got);
  if (!(0 <= got.first && got.first <= got.last && got.last <= end))
    return fail(expected, answer, "the times must satisfy 0 <= first <= last <= duration");
  const std::string within = " (tolerance " + fmt(tol) + ")";
  // At the reported times the boxes must be within tol of touching...
  if (!meet(in, got.first, got.first, tol))
    return fail(expected, answer, "at t = first the boxes are more than tol apart along some axis" + within);
  if (!meet(in, got.last, got.last, tol))
    return fail(expected, answer, "at t = last the boxes are more than tol apart along some axis" + within);
  // ...and outside [first, last] never overlap by more than tol.
  if (got.first > 0 && meet(in, 0.0, got.first, -tol))
    return fail(expected, answer, "before t = first the boxes already overlap by more than tol" + within);
  if (got.last < end && meet(in, got.last, end, -tol))
    return fail(expected, answer, "after t = last the boxes still overlap by more than tol" + within);
  return decision;
}

}  // namespace labkit::lab03::judge
