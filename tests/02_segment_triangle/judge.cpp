// Lab 02's judges of one segment against one triangle (steps 1 to 4: the plane crossing,
// the point in the triangle, its weights, test and find), and the helpers all of lab 02's
// judges share (tests/02_segment_triangle/judge_internal.h). The meshes: judge.meshes.cpp.
#include "02_segment_triangle/judge_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace labkit::lab02::judge {

// check::verdict, with the rule the answer broke as its why (the exact answer, not in
// doubt: no input within tol answers otherwise).
Outcome verdict(bool got, bool expected, bool doubt, Rules rules, const std::string& yes, const std::string& no,
                const std::string& why) {
  Outcome o = check::verdict(got, expected, doubt, rules, yes, no);
  if (o.verdict == Outcome::Verdict::fail) o.why = why;
  return o;
}

// A needle's plane is known in doubles only to about 1e-16 times its aspect ratio:
// rounding its edges alone tilts it that much (the header's rule for needles). kappa is
// longest edge^2 / |n|, the aspect ratio of a needle (about 1 for a fat triangle).
double tilt_of(const Triangle& tri) {
  const double n = tri.normal().norm();
  if (n == 0) return 0;
  const double longest =
      std::max({(tri.v1 - tri.v0).squaredNorm(), (tri.v2 - tri.v1).squaredNorm(), (tri.v0 - tri.v2).squaredNorm()});
  return 64 * std::numeric_limits<double>::epsilon() * longest / n;
}
// The tolerance of a signed distance of p: tol, plus what that tilt moves it.
double distance_tolerance(const Vec3& p, const Triangle& tri, double tol) {
  return tol + (p - tri.v0).norm() * tilt_of(tri);
}

// How loosely a crossing fixes t: tol / |d_a - d_b|, or tol / |b - a| in the plane.
double t_tolerance(const Segment& s, const Triangle& tri, double tol) {
  const oracle::PlaneCrossing c = oracle::segment_plane(s, tri);
  const double change = std::abs(c.d_a - c.d_b);
  if (change > 0) return std::max(distance_tolerance(s.a, tri, tol), distance_tolerance(s.b, tri, tol)) / change;
  const double length = (s.b - s.a).norm();
  return length > 0 ? tol / length : std::numeric_limits<double>::infinity();
}

bool triangle_hit(const SegmentTrianglePair& p) { return oracle::segment_hits_triangle(p.segment, p.triangle); }

// Why the exact answer is a hit or a miss, in the header's rules, with the numbers.
std::string hit_rule(const Segment& s, const Triangle& tri) {
  if (tri.normal() == Vec3::Zero() && oracle::unit_normal(tri) == Vec3::Zero())
    return "a zero-area triangle (collinear or coincident vertices) has no plane and is never hit";
  const oracle::PlaneCrossing c = oracle::segment_plane(s, tri);
  const oracle::SegmentHit h = oracle::segment_triangle(s, tri);
  const std::string at = "t = " + fmt(h.t) + ", point " + fmt(h.point);
  if (s.a == s.b)
    return h.hit ? "a zero-length segment hits when its point is on the closed triangle, and " + fmt(s.a) + " is"
                 : "a zero-length segment hits only when its point is on the closed triangle, and " + fmt(s.a) +
                       " is not";
  if (c.side_a * c.side_b > 0)
    return "both ends are strictly on the same side of the triangle's plane (d_a = " + fmt(c.d_a) +
           ", d_b = " + fmt(c.d_b) + "): the segment never reaches the plane, a miss";
  if (c.side_a == 0 && c.side_b == 0)
    return h.hit ? "the segment lies in the triangle's plane, and a segment in the plane hits where the two meet: "
                   "first at " +
                       at
                 : "the segment lies in the triangle's plane but stays outside the triangle: a miss";
  if (h.hit)
    return "the segment crosses the plane at " + at + ", a point of the closed triangle (its boundary counts): a hit";
  const Vec3 x = c.point;
  for (int i = 0; i < 3; ++i) {
    const Vec3 inward = tri.normal().cross(tri[(i + 1) % 3] - tri[i]);
    if ((x - tri[i]).dot(inward) < 0)
      return "the segment crosses the plane at t = " + fmt(c.t) + ", point " + fmt(x) +
             ", outside the triangle beyond its edge v" + std::to_string(i) + " v" + std::to_string((i + 1) % 3) +
             ": a miss";
  }
  return "the segment crosses the plane at t = " + fmt(c.t) + ", point " + fmt(x) +
         ", just outside the triangle: a miss";
}

std::string yours(bool hit) { return std::string(", but your answer says ") + (hit ? "hit" : "miss"); }

// Could a perturbation of tol change whether the segment meets this triangle?
bool unstable(const Segment& s, const Triangle& tri, double tol, Rules rules) {
  return judging::unstable(s, tri, tol, rules, triangle_hit);
}

// Is this triangle of the mesh hit, or is its hit ambiguous?
bool hit_or_ambiguous(const Segment& s, const Triangle& tri, double tol, Rules rules) {
  return triangle_hit({s, tri}) || unstable(s, tri, tol, rules);
}

std::vector<Status> statuses(const Segment& s, const Mesh& mesh, double tol, Rules rules) {
  return judging::statuses(s, mesh, tol, rules, triangle_hit);
}

// The verdict on "does the segment hit the mesh at all": the exact answer stands when
// some hit is not in doubt, or when no triangle is in doubt.
Outcome mesh_yes_no(const std::vector<Status>& all, bool got, Rules rules, const std::string& yes,
                    const std::string& no, const Segment& s, const Mesh& mesh) {
  const judging::AnyHit any = judging::any_hit(all);
  std::string why = "no triangle of the mesh is hit: the segment misses each one" + yours(got);
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].hit && (!all[i].unstable || !any.stable_hit)) {
      why = "triangle " + std::to_string(i) + " is hit: " + hit_rule(s, mesh.triangle(i)) + yours(got);
      break;
    }
  return verdict(got, any.hit, any.in_doubt(), rules, yes, no, why);
}

// The checks every reported hit on a triangle must pass (the header's tolerances).
// The point may leave the triangle by as much as a t within its tolerance moves it along
// the segment: for a segment almost parallel to the plane, rounding d_a alone moves the
// crossing far along the plane (the header's rule for points).
void check_hit(Expect& e, const Segment& s, const Triangle& tri, double t, const Vec3& point, const Vec3& weights,
               const Vec3& normal, double tol) {
  const double length = (s.b - s.a).norm();  // zero: a point, whose t is anything
  const double along = tol + (length > 0 ? length * t_tolerance(s, tri, tol) : 0.0);
  e.that("point", oracle::within(point, tri, along), fmt(point), "a point of the triangle",
         "the point is " + fmt(oracle::distance(point, tri)) + " from the triangle (tolerance " + fmt(along) + ")");
  std::string beyond;
  if (t < 0 || t > 1)
    beyond = ": t = " + fmt(t) + " is beyond an end, where the segment does not reach (both ends on the same side?)";
  e.that("point on segment", oracle::within(point, s, tol), fmt(point), "a point of the segment",
         "the point must be on the segment, a + t (b - a) with 0 <= t <= 1, and it is " +
             fmt(oracle::distance(point, s)) + " from it (tolerance " + fmt(tol) + ")" + beyond);
  e.that("t", oracle::parameter_reproduces(s, t, point, tol), fmt(t), "a + t (b - a) = point",
         "a + t (b - a) is " + fmt((s.point(t) - point).norm()) + " away from the point");
  e.that("barycentric", std::abs(weights.sum() - 1) <= kRelative && oracle::weights_reproduce(tri, weights, point, tol),
         fmt(weights), "weights summing to 1 that reproduce the point",
         "w0 v0 + w1 v1 + w2 v2 is " +
             fmt((weights[0] * tri.v0 + weights[1] * tri.v1 + weights[2] * tri.v2 - point).norm()) +
             " away from the point, and the weights sum to " + fmt(weights.sum()));
  const Vec3 n = oracle::unit_normal(tri);
  e.that("normal", (normal - n).norm() <= kRelative + tilt_of(tri), fmt(normal), fmt(n),
         (normal + n).norm() <= 1e-6
             ? "the normal is the triangle's unit normal as wound, (v1 - v0) x (v2 - v0) / |...|, "
               "whichever side a comes from: yours is flipped"
             : "the normal must be the triangle's unit normal as wound, (v1 - v0) x (v2 - v0) / |...|");
}

Triangle mesh_triangle(const Mesh& mesh, int index) { return mesh.triangle(std::size_t(index)); }
bool valid_index(const Mesh& mesh, int index) { return index >= 0 && std::size_t(index) < mesh.size(); }

std::string describe_hits(const std::vector<oracle::SegmentHit>& hits) {
  std::string s;
  for (const auto& h : hits)
    s += (s.empty() ? "" : ", ") + ("triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t));
  return s.empty() ? "no hit" : s;
}

std::string describe_hits(const std::vector<MeshHit>& hits) {
  std::string s;
  for (const auto& h : hits)
    s += (s.empty() ? "" : ", ") + ("triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t));
  return s.empty() ? "no hit" : s;
}

// ---- Steps 1 to 4: one segment, one triangle ------------------------------------------

Outcome segment_plane(const SegmentTrianglePair& in, const PlaneCrossing& got, Rules rules) {
  const double tol = tolerance_of(in);
  const oracle::PlaneCrossing exact = oracle::segment_plane(in.segment, in.triangle);
  const double n_length = in.triangle.normal().norm();
  Expect e(
      "segment_plane: d_a and d_b are the ends' signed distances along the unit normal, and the crossing is at t = d_a "
      "/ (d_a - d_b)");
  const auto distance = [&](const std::string& name, const Vec3& p, double mine, double d) {
    const double d_tol = distance_tolerance(p, in.triangle, tol);
    std::string why = name + " must be the signed distance of " + name.substr(2) +
                      " to the plane, along the unit normal: " + fmt(d) + ", not " + fmt(mine) + " (tolerance " +
                      fmt(d_tol) + ")";
    if (d != 0 && std::abs(mine - n_length * d) <= 1e-6 * std::abs(n_length * d))
      why += "; " + fmt(mine) + " is |n| = " + fmt(n_length) + " times it: is n unit?";
    else if (d != 0 && std::abs(mine + d) <= d_tol)
      why += "; the sign is flipped: the normal is (v1 - v0) x (v2 - v0), as wound";
    e.that(name, std::abs(mine - d) <= d_tol, fmt(mine), fmt(d), why);
  };
  distance("d_a", in.segment.a, got.d_a, exact.d_a);
  distance("d_b", in.segment.b, got.d_b, exact.d_b);
  const auto crosses = [](const SegmentTrianglePair& p) {
    return oracle::segment_crosses_plane(p.segment, p.triangle);
  };
  const std::string sides = "(d_a = " + fmt(exact.d_a) + ", d_b = " + fmt(exact.d_b) + ")";
  const std::string rule =
      exact.crosses ? "the ends are on opposite sides of the plane, or one is on it " + sides +
                          ": the segment crosses it in one point"
      : exact.side_a == 0 && exact.side_b == 0 && n_length > 0
          ? "both ends are on the plane " + sides + ": the segment lies in it, no single crossing point"
      : n_length == 0 ? "a zero-area triangle has no plane to cross"
                      : "both ends are strictly on the same side of the plane " + sides + ": no crossing";
  const Outcome decision =
      yes_no(in, got.crosses, rules, crosses, "crosses", "does not cross",
             rule + std::string(", but your answer says it ") + (got.crosses ? "crosses" : "does not"));
  if (decision.verdict == Outcome::Verdict::fail)
    return fail("crosses = " + describe(exact.crosses), "crosses = " + describe(got.crosses), decision.why);
  if (exact.crosses && got.crosses) {
    const double t_tol = t_tolerance(in.segment, in.triangle, tol);
    std::string why = "the crossing is at t = d_a / (d_a - d_b) = " + fmt(exact.t) + ", not " + fmt(got.t) +
                      " (tolerance " + fmt(t_tol) + ")";
    if (std::abs(got.t + exact.t) <= t_tol)
      why += "; yours has the opposite sign: is the denominator d_b - d_a?";
    else if (std::abs(got.t - (1 - exact.t)) <= t_tol)
      why += "; yours is measured from b: t runs from a (t = 0) to b";
    e.that("t", std::abs(got.t - exact.t) <= t_tol, fmt(got.t), fmt(exact.t), why);
    e.that("point", oracle::parameter_reproduces(in.segment, got.t, got.point, tol), fmt(got.point),
           "a + t (b - a) with your t",
           "the point must be a + t (b - a), and it is " + fmt((in.segment.point(got.t) - got.point).norm()) +
               " away from it (tolerance " + fmt(tol) + ")");
  }
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

Outcome point_in_triangle(const PointTriangle& in, bool got, Rules rules) {
  const auto inside = [](const PointTriangle& p) { return oracle::point_in_triangle_projected(p.x, p.triangle); };
  const Triangle& t = in.triangle;
  std::string rule = "x is in the closed triangle (a point on an edge or a vertex counts as inside)";
  if (oracle::unit_normal(t) == Vec3::Zero())
    rule = "a zero-area triangle contains no point";
  else if (!inside(in))
    for (int i = 0; i < 3; ++i)
      if ((in.x - t[i]).dot(t.normal().cross(t[(i + 1) % 3] - t[i])) < 0) {
        rule = "x is outside the triangle, beyond its edge v" + std::to_string(i) + " v" + std::to_string((i + 1) % 3) +
               " (E_" + std::to_string(i) + " < 0)";
        break;
      }
  // Within tol of an edge, a move of x alone flips the answer; sampled moves of all the
  // numbers can miss it near a sharp vertex, whose inside is a narrow wedge.
  const bool doubt = rules == Rules::random && (oracle::point_in_triangle_in_doubt(in.x, t, tolerance_of(in)) ||
                                                check::flips_under_perturbation(in, inside));
  return verdict(got, inside(in), doubt, rules, "inside (or on the boundary)", "outside",
                 rule + ", but your answer says " + (got ? "inside" : "outside"));
}

Outcome barycentric(const PointTriangle& in, const Barycentric& got) {
  const Vec3 n = oracle::unit_normal(in.triangle);
  if (n == Vec3::Zero()) {
    if (got.dropped_axis == -1) return pass();
    return fail("dropped_axis = -1 (zero-area triangle)", "dropped_axis = " + describe(got.dropped_axis),
                "a zero-area triangle has no plane to drop an axis from");
  }
  const Vec3 m = n.cwiseAbs();
  Expect e(
      "barycentric drops the axis of the normal's largest component and solves x = v0 + alpha e1 + beta e2 in the two "
      "axes left");
  const bool axis_ok =
      got.dropped_axis >= 0 && got.dropped_axis <= 2 && m[got.dropped_axis] >= m.maxCoeff() - kRelative;
  int best = 0;
  m.maxCoeff(&best);
  e.that("dropped_axis", axis_ok, describe(got.dropped_axis), describe(best),
         "drop the axis of the normal's largest |component|: the normal is " + fmt(n));
  const double tol = tolerance_of(in);
  const Triangle& t = in.triangle;
  std::string hint;
  if (oracle::alpha_beta_reproduce(t, got.alpha, -got.beta, in.x, tol))
    hint = "; with -beta it would: the sign of beta is flipped";
  if (oracle::alpha_beta_reproduce(t, -got.alpha, got.beta, in.x, tol))
    hint = "; with -alpha it would: the sign of alpha is flipped";
  if (oracle::alpha_beta_reproduce(t, got.beta, got.alpha, in.x, tol))
    hint = "; swapped, they would: alpha weighs e1 = v1 - v0";
  e.that("alpha, beta", oracle::alpha_beta_reproduce(in.triangle, got.alpha, got.beta, in.x, tol),
         fmt(got.alpha) + ", " + fmt(got.beta), "v0 + alpha (v1 - v0) + beta (v2 - v0) = x",
         "alpha and beta must describe x as v0 + alpha e1 + beta e2, and yours miss it by " +
             fmt((in.triangle.v0 + got.alpha * (in.triangle.v1 - in.triangle.v0) +
                  got.beta * (in.triangle.v2 - in.triangle.v0) - in.x)
                     .norm()) +
             " (tolerance " + fmt(tol) + ")" + hint);
  return e.outcome();
}

Outcome test_segment_triangle(const SegmentTrianglePair& in, bool got, Rules rules) {
  const bool doubt = unstable(in.segment, in.triangle, tolerance_of(in), rules);
  return verdict(got, triangle_hit(in), doubt, rules, "hit", "miss", hit_rule(in.segment, in.triangle) + yours(got));
}

Outcome find_segment_triangle(const SegmentTrianglePair& in, const SegmentTriangleHit& got, Rules rules) {
  const bool doubt = unstable(in.segment, in.triangle, tolerance_of(in), rules);
  const Outcome decision = verdict(got.hit, triangle_hit(in), doubt, rules, "hit", "miss",
                                   hit_rule(in.segment, in.triangle) + yours(got.hit));
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !triangle_hit(in)) return decision;
  const double tol = tolerance_of(in);
  const oracle::SegmentHit exact = oracle::segment_triangle(in.segment, in.triangle);
  Expect e(
      "a hit is where the segment meets the triangle: t along a to b, point a + t (b - a), weights of v0, v1, v2 that "
      "give the point");
  check_hit(e, in.segment, in.triangle, got.t, got.point, got.barycentric, got.normal, tol);
  // In the plane the common part is a piece of the segment: the answer is its first point.
  if (exact.coplanar && rules == Rules::exact) {
    const double slack = t_tolerance(in.segment, in.triangle, tol);
    e.that("first point", got.t <= exact.t + slack, "t = " + fmt(got.t), "t = " + fmt(exact.t),
           "the segment lies in the plane; the first common point from a is at t = " + fmt(exact.t));
  }
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

}  // namespace labkit::lab02::judge
