// Lab 03's judge, the boxes: projections, the 15 axes and static boxes (moving boxes:
// judge.moving.cpp; the triangles: judge.triangles.cpp). First, S of each input
// (scale_of, judge.h), which the generators and the viewer share.
#include "03_separating_axes/judge.h"
#include "03_separating_axes/judge_internal.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cmath>

namespace labkit {

namespace {
double box_scale(const Box& b) {
  return std::max(b.center.cwiseAbs().maxCoeff(), b.half_extents.cwiseAbs().maxCoeff());
}
}  // namespace

double scale_of(const BoxOnAxis& in) { return box_scale(in.box); }
double scale_of(const BoxPair& in) { return std::max(box_scale(in.a), box_scale(in.b)); }
double scale_of(const BoxPairOnAxis& in) { return std::max(box_scale(in.a), box_scale(in.b)); }
double scale_of(const TrianglePair& in) {
  return scale_of({in.t0.v0, in.t0.v1, in.t0.v2, in.t1.v0, in.t1.v1, in.t1.v2});
}
double scale_of(const MovingBoxes& in) {
  const Vec3 end_a = in.a.center + in.duration * in.velocity_a, end_b = in.b.center + in.duration * in.velocity_b;
  return std::max({box_scale(in.a), box_scale(in.b), end_a.cwiseAbs().maxCoeff(), end_b.cwiseAbs().maxCoeff()});
}

}  // namespace labkit

namespace labkit::lab03::judge {

std::string axis_name(int index) {
  if (index < 0 || index > 14) return "axis " + std::to_string(index);
  static const char* names[] = {"A_0", "A_1", "A_2", "B_0", "B_1", "B_2"};
  if (index < 6) return "axis " + std::to_string(index) + " (" + names[index] + ")";
  return "axis " + std::to_string(index) + " (A_" + std::to_string((index - 6) / 3) + " x B_" +
         std::to_string((index - 6) % 3) + ")";
}

namespace {

bool boxes_in_doubt(const BoxPair& in, Rules rules) {
  return rules == Rules::random && std::abs(oracle::box_pair_margin(in.a, in.b)) <= kBoxDoubt * position_tolerance(in);
}

double sum_of_extents(const BoxPair& in) { return in.a.half_extents.sum() + in.b.half_extents.sum(); }

// How loosely rounding fixes the direction of the lab's axis `index`: 1e-15 / |A_i x B_j|
// for an edge axis (the header's allowance), next to nothing for a face axis.
double direction_slack(double length, int index) { return index < 6 ? 1e-15 : 1e-15 / length; }

// The exact depth along axis `index`, the smaller of the two directions.
double least_depth_along(const BoxPair& in, const Vec3& axis) {
  return std::min(oracle::box_depth_along(in.a, in.b, axis), oracle::box_depth_along(in.a, in.b, -axis));
}

// The answer of a test that takes the centres' offset c_B - c_A as if it were already in
// A's frame (the A^T left out): that of B moved to c_A + A (c_B - c_A). When it is the
// answer given, the likely cause is that frame.
bool offset_frame_mistake_agrees(const BoxPair& in, bool answer_intersecting) {
  if (in.a.axes.isIdentity(0)) return false;  // A's frame is the world's: no such mistake
  Box moved = in.b;
  moved.center = in.a.center + in.a.axes * (in.b.center - in.a.center);
  return oracle::boxes_intersect(in.a, moved) == answer_intersecting;
}
constexpr const char* kOffsetFrame =
    "; is the offset between the centres in A's frame, t = A^T (c_B - c_A)? Your answer is that of the offset "
    "taken as it is";

// Why a yes/no answer about two static boxes is wrong, in the contract's words: the axis
// that separates them and its gap, or that none does, and the likely cause.
std::string why_boxes(const BoxPair& in, bool expected_intersecting) {
  const double size = scale_of(in);
  int best = -1, shortest = -1;
  double gap = 0.0, least = 0.0, shortest_length = 1.0;
  bool face_separates = false;
  for (int k = 0; k < 15; ++k) {
    const Vec3 axis = oracle::box_pair_axis(in.a, in.b, k);
    const double length = axis.norm();
    if (k >= 6 && length < shortest_length) shortest_length = length, shortest = k;
    if (length == 0) continue;
    const double depth = least_depth_along(in, axis);
    if (-depth > gap) gap = -depth, best = k;
    if (depth < 0 && k < 6) face_separates = true;
    if (depth >= 0 && (k < 6 || length >= kSurelyIncluded) && (least == 0.0 || depth < least)) least = depth;
  }
  if (!expected_intersecting) {
    if (best < 0)
      return "the boxes are apart (flat boxes, beside each other in a plane), your answer says they intersect";
    std::string why = axis_name(best) + " is a separating axis: the boxes' projections on it are apart (gap " +
                      fmt(gap) + " along the unit axis); your answer says they intersect";
    if (offset_frame_mistake_agrees(in, true))
      why += kOffsetFrame;
    else if (best >= 6 && !face_separates)
      why += "; only an edge axis A_i x B_j separates them: are all 9 edge axes tested?";
    else if (gap < 1e-6 * size)
      why += "; a gap this small is lost to an epsilon added to the radii";
    return why;
  }
  std::string why = "no axis separates the boxes: their projections overlap on all 15 axes (least penetration " +
                    fmt(least) + "), your answer says separated";
  if (least <= 1e-9 * size)
    why += "; boxes that only touch intersect: separation is strict, |s| > r_A + r_B";
  else if (offset_frame_mistake_agrees(in, false))
    why += kOffsetFrame;
  else if (shortest >= 0 && shortest_length < 1e-6)
    why += "; if your answer came from " + axis_name(shortest) + ": it has length " + fmt(shortest_length) +
           " here (nearly parallel edges), and a zero axis separates nothing; compute its radius along the vector "
           "itself, B_m . L, not with R(i, n)";
  return why;
}

Outcome boxes_verdict(const BoxPair& in, bool got, bool doubt, Rules rules) {
  const bool expected = oracle::boxes_intersect(in.a, in.b);
  Outcome o = verdict(got, expected, doubt, rules, "intersecting", "separated");
  if (o.verdict == Outcome::Verdict::fail) o.why = why_boxes(in, expected);
  return o;
}

}  // namespace

Outcome project_box(const BoxOnAxis& in, const Projection& got) {
  const double tol = position_tolerance(in) * in.axis.norm();
  const oracle::BoxProjection exact = oracle::box_projection(in.box, in.axis);
  const std::string answer = "center " + fmt(got.center) + ", radius " + fmt(got.radius);
  const std::string expected = "center " + fmt(exact.center) + ", radius " + fmt(exact.radius);
  if (!(std::abs(got.center - exact.center) <= tol))
    return fail(expected, answer,
                "the centre of the interval is c . L = " + fmt(exact.center) + ", yours is off by " +
                    fmt(std::abs(got.center - exact.center)) + " (tolerance " + fmt(tol) + ")");
  if (!(std::abs(got.radius - exact.radius) <= tol)) {
    std::string why = "the radius is sum_k h_k |A_k . L| = " + fmt(exact.radius) + ", yours is off by " +
                      fmt(std::abs(got.radius - exact.radius)) + " (tolerance " + fmt(tol) + ")";
    if (got.radius < exact.radius) why += "; too small: is each term taken with its absolute value?";
    return fail(expected, answer, why);
  }
  return pass();
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
    doubt = kBoxDoubt * position_tolerance(pair) + 2 * std::sqrt(3.0) * 1e-9 * reach;
  }
  const double overlap = least_depth_along(pair, in.axis);
  Outcome o = verdict(got, expected, in.axis != Vec3::Zero() && std::abs(overlap) <= doubt, rules, "separated",
                      "not separated (the projections overlap or touch)");
  if (o.verdict != Outcome::Verdict::fail) return o;
  if (in.axis == Vec3::Zero())
    o.why = "a zero axis separates nothing (0 > 0 is false); your answer says separated";
  else if (expected)
    o.why = "the projections on L are apart by a gap of " + fmt(-overlap) +
            " (along the unit axis): "
            "|(c_B - c_A) . L| > r_A + r_B; your answer says not separated";
  else if (overlap <= position_tolerance(pair))
    o.why = "the projections on L touch (overlap " + fmt(overlap) +
            "): touching intervals are not separated, the test is strict (>)";
  else
    o.why = "the projections on L overlap by " + fmt(overlap) +
            " (along the unit axis): |(c_B - c_A) . L| <= r_A + "
            "r_B; your answer says separated (is each radius term h_k |A_k . L| with the absolute value?)";
  return o;
}

Outcome box_axes(const BoxPair& in, const std::array<Vec3, 15>& got) {
  Expect e("the 15 axes are A's columns, B's columns, then A_i x B_j, unnormalised");
  for (int k = 0; k < 15; ++k) {
    const Vec3 exact = oracle::box_pair_axis(in.a, in.b, k);
    if ((got[k] - exact).norm() > 1e-12) {
      std::string why = k < 3   ? axis_name(k) + " is A's column " + std::to_string(k)
                        : k < 6 ? axis_name(k) + " is B's column " + std::to_string(k - 3)
                                : axis_name(k) + " is that cross product as it is (not normalised)";
      why += ", " + fmt(exact) + "; yours is off by " + fmt((got[k] - exact).norm()) + " (tolerance 1e-12)";
      if (exact.norm() > 0 && (got[k] + exact).norm() <= 1e-12)
        why += ": the opposite vector (the order A_i x B_j?)";
      else if (k >= 6 && exact.norm() > 0 && std::abs(got[k].norm() - 1) <= 1e-12 &&
               got[k].cross(exact).norm() <= 1e-12 * exact.norm())
        why += ": normalised; box_axis returns it unnormalised";
      e.that(axis_name(k), false, fmt(got[k]), fmt(exact), why);
    }
  }
  return e.outcome();
}

Outcome test_boxes(const BoxPair& in, bool got, Rules rules) {
  return boxes_verdict(in, got, boxes_in_doubt(in, rules), rules);
}

Outcome find_boxes(const BoxPair& in, const BoxContact& got, Rules rules) {
  const bool doubt = boxes_in_doubt(in, rules);
  const Outcome decision = boxes_verdict(in, got.intersecting, doubt, rules);
  if (decision.verdict == Outcome::Verdict::fail) return decision;

  const double tol = position_tolerance(in);
  const std::string answer = (got.intersecting ? "intersecting, " : "separated, ") + axis_name(got.axis_index) + " = " +
                             fmt(got.axis) + ", depth " + fmt(got.depth);
  if (got.axis_index < 0 || got.axis_index > 14 || !got.axis.allFinite() || !std::isfinite(got.depth))
    return fail("an axis index from 0 to 14 with a finite axis and depth", answer, "the axis or the depth is missing");
  if (std::abs(got.axis.norm() - 1) > 1e-9)
    return fail("a unit axis", answer,
                "the reported axis is the unit vector L / |L| (a depth is measured along a unit axis): yours has "
                "length " +
                    fmt(got.axis.norm()));
  const Vec3 numbered = oracle::box_pair_axis(in.a, in.b, got.axis_index);
  const double length = numbered.norm();
  // The axis itself before the rules about short axes: a wrong axis (B's rows taken for
  // its columns, a frame left out) is the mistake, whatever its length would be.
  if (length > 0 && got.axis.cross(numbered / length).norm() > 1e-9 + direction_slack(length, got.axis_index))
    return fail(axis_name(got.axis_index) + " = +-" + fmt(Vec3(numbered / length)), answer,
                "the axis must be the one its index names, " + axis_name(got.axis_index) +
                    ", in world coordinates: yours is not parallel to it (B's axes are the columns of its matrix, "
                    "and A_i x B_j crosses the two world vectors)");
  if (got.intersecting && got.axis_index >= 6 && length < kShortest)
    return fail("a face axis or an edge axis with |A_i x B_j| >= 1e-6", answer,
                axis_name(got.axis_index) + " has length " + fmt(length) +
                    ": nearly parallel edges are left out of the least-penetration search");
  const double offset = (in.b.center - in.a.center).dot(got.axis);
  if (offset < -tol)
    return fail("the axis pointing from A toward B", answer,
                "the axis must point from A toward B: (c_B - c_A) . axis = " + fmt(offset) +
                    " < 0 (flip L when (c_B - c_A) . L < 0)");
  const double depth = oracle::box_depth_along(in.a, in.b, got.axis);
  if (std::abs(got.depth - depth) > tol) {
    std::string why = "the depth must be r_A + r_B - |(c_B - c_A) . u| along the unit axis u: " + fmt(depth) +
                      ", yours is off by " + fmt(std::abs(got.depth - depth)) + " (tolerance " + fmt(tol) + ")";
    if (got.axis_index >= 6 && std::abs(got.depth - depth * length) <= tol + 1e-12 * std::abs(depth))
      why += "; " + fmt(got.depth) + " is |L| = " + fmt(length) + " times it: divide by |L| (a unit axis)";
    return fail("depth " + fmt(depth) + " along your axis", answer, why);
  }

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
                  "intersecting boxes report the axis of least penetration: " + axis_name(k) + " = " +
                      fmt(Vec3(axis / n)) + " has depth " + fmt(least) + ", less than your " + fmt(got.depth));
  }
  return decision;
}

}  // namespace labkit::lab03::judge
