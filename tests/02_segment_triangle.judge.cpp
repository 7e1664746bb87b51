#include "02_segment_triangle.judge.h"

#include "common/oracle/moving_meshes.h"
#include "common/oracle/oracle.h"
#include "common/harness/segment_doubt.h"

#include <cmath>
#include <limits>
#include <algorithm>
#include <set>

namespace labkit::lab02::judge {

namespace {

using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;

constexpr double kRelative = 1e-9;  // tol = 1e-9 S (the header's tolerances)

template <class Input>
double tolerance_of(const Input& in) {
  return kRelative * check::scale_of_input(in);
}

// check::verdict, with the rule the answer broke as its why (the exact answer, not in
// doubt: no input within tol answers otherwise).
Outcome verdict(bool got, bool expected, bool doubt, Rules rules, const std::string& yes, const std::string& no,
                const std::string& why) {
  Outcome o = check::verdict(got, expected, doubt, rules, yes, no);
  if (o.verdict == Outcome::Verdict::fail) o.why = why;
  return o;
}

// The same, with doubt found by perturbing the input (`exact` recomputes the answer).
template <class Input, class Exact>
Outcome yes_no(const Input& in, bool got, Rules rules, Exact&& exact, const std::string& yes, const std::string& no,
               const std::string& why) {
  const bool doubt = rules == Rules::random && check::flips_under_perturbation(in, exact);
  return verdict(got, exact(in), doubt, rules, yes, no, why);
}

// A needle's plane is known in doubles only to about 1e-16 times its aspect ratio:
// rounding its edges alone tilts it that much (the header's rule for needles). kappa is
// longest edge^2 / |n|, the aspect ratio of a needle (about 1 for a fat triangle).
double tilt_of(const Triangle& tri) {
  const double n = tri.normal().norm();
  if (n == 0) return 0;
  const double longest = std::max({(tri.v1 - tri.v0).squaredNorm(), (tri.v2 - tri.v1).squaredNorm(), (tri.v0 - tri.v2).squaredNorm()});
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
                 : "a zero-length segment hits only when its point is on the closed triangle, and " + fmt(s.a) + " is not";
  if (c.side_a * c.side_b > 0)
    return "both ends are strictly on the same side of the triangle's plane (d_a = " + fmt(c.d_a) + ", d_b = " + fmt(c.d_b) +
           "): the segment never reaches the plane, a miss";
  if (c.side_a == 0 && c.side_b == 0)
    return h.hit ? "the segment lies in the triangle's plane, and a segment in the plane hits where the two meet: first at " + at
                 : "the segment lies in the triangle's plane but stays outside the triangle: a miss";
  if (h.hit) return "the segment crosses the plane at " + at + ", a point of the closed triangle (its boundary counts): a hit";
  const Vec3 x = c.point;
  for (int i = 0; i < 3; ++i) {
    const Vec3 inward = tri.normal().cross(tri[(i + 1) % 3] - tri[i]);
    if ((x - tri[i]).dot(inward) < 0)
      return "the segment crosses the plane at t = " + fmt(c.t) + ", point " + fmt(x) + ", outside the triangle beyond its edge v" +
             std::to_string(i) + " v" + std::to_string((i + 1) % 3) + ": a miss";
  }
  return "the segment crosses the plane at t = " + fmt(c.t) + ", point " + fmt(x) + ", just outside the triangle: a miss";
}

std::string yours(bool hit) { return std::string(", but your answer says ") + (hit ? "hit" : "miss"); }

// Could a perturbation of tol change whether the segment meets this triangle?
bool unstable(const Segment& s, const Triangle& tri, double tol, Rules rules) {
  return rules == Rules::random && check::segment_triangle_in_doubt(s, tri, tol, triangle_hit);
}

// Is this triangle of the mesh hit, or is its hit ambiguous?
bool hit_or_ambiguous(const Segment& s, const Triangle& tri, double tol, Rules rules) {
  return triangle_hit({s, tri}) || unstable(s, tri, tol, rules);
}

// Each triangle of a mesh: exactly hit or not, and whether that is in doubt.
struct Status {
  bool hit = false;
  bool unstable = false;
};

std::vector<Status> statuses(const Segment& s, const Mesh& mesh, double tol, Rules rules) {
  std::vector<Status> all(mesh.size());
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle tri = mesh.triangle(i);
    all[i] = {triangle_hit({s, tri}), unstable(s, tri, tol, rules)};
  }
  return all;
}

// The verdict on "does the segment hit the mesh at all": the exact answer stands when
// some hit is not in doubt, or when no triangle is in doubt.
Outcome mesh_yes_no(const std::vector<Status>& all, bool got, Rules rules, const std::string& yes, const std::string& no,
                    const Segment& s, const Mesh& mesh) {
  bool expected = false, stable_hit = false, doubt = false;
  for (const Status& st : all) {
    expected = expected || st.hit;
    stable_hit = stable_hit || (st.hit && !st.unstable);
    doubt = doubt || st.unstable;
  }
  std::string why = "no triangle of the mesh is hit: the segment misses each one" + yours(got);
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].hit && (!all[i].unstable || !stable_hit)) {
      why = "triangle " + std::to_string(i) + " is hit: " + hit_rule(s, mesh.triangle(i)) + yours(got);
      break;
    }
  return verdict(got, expected, !stable_hit && doubt, rules, yes, no, why);
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
  if (t < 0 || t > 1) beyond = ": t = " + fmt(t) + " is beyond an end, where the segment does not reach (both ends on the same side?)";
  e.that("point on segment", oracle::within(point, s, tol), fmt(point), "a point of the segment",
         "the point must be on the segment, a + t (b - a) with 0 <= t <= 1, and it is " + fmt(oracle::distance(point, s)) +
             " from it (tolerance " + fmt(tol) + ")" + beyond);
  e.that("t", oracle::parameter_reproduces(s, t, point, tol), fmt(t), "a + t (b - a) = point",
         "a + t (b - a) is " + fmt((s.point(t) - point).norm()) + " away from the point");
  e.that("barycentric", std::abs(weights.sum() - 1) <= kRelative && oracle::weights_reproduce(tri, weights, point, tol),
         fmt(weights), "weights summing to 1 that reproduce the point",
         "w0 v0 + w1 v1 + w2 v2 is " + fmt((weights[0] * tri.v0 + weights[1] * tri.v1 + weights[2] * tri.v2 - point).norm()) +
             " away from the point, and the weights sum to " + fmt(weights.sum()));
  const Vec3 n = oracle::unit_normal(tri);
  e.that("normal", (normal - n).norm() <= kRelative + tilt_of(tri), fmt(normal), fmt(n),
         (normal + n).norm() <= 1e-6 ? "the normal is the triangle's unit normal as wound, (v1 - v0) x (v2 - v0) / |...|, "
                                       "whichever side a comes from: yours is flipped"
                                     : "the normal must be the triangle's unit normal as wound, (v1 - v0) x (v2 - v0) / |...|");
}

Triangle mesh_triangle(const Mesh& mesh, int index) { return mesh.triangle(std::size_t(index)); }
bool valid_index(const Mesh& mesh, int index) { return index >= 0 && std::size_t(index) < mesh.size(); }

std::string describe_hits(const std::vector<oracle::SegmentHit>& hits) {
  std::string s;
  for (const auto& h : hits) s += (s.empty() ? "" : ", ") + ("triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t));
  return s.empty() ? "no hit" : s;
}

std::string describe_hits(const std::vector<MeshHit>& hits) {
  std::string s;
  for (const auto& h : hits) s += (s.empty() ? "" : ", ") + ("triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t));
  return s.empty() ? "no hit" : s;
}

}  // namespace

Outcome segment_plane(const SegmentTrianglePair& in, const PlaneCrossing& got, Rules rules) {
  const double tol = tolerance_of(in);
  const oracle::PlaneCrossing exact = oracle::segment_plane(in.segment, in.triangle);
  const double n_length = in.triangle.normal().norm();
  Expect e;
  const auto distance = [&](const std::string& name, const Vec3& p, double mine, double d) {
    const double d_tol = distance_tolerance(p, in.triangle, tol);
    std::string why = name + " must be the signed distance of " + name.substr(2) + " to the plane, along the unit normal: " +
                      fmt(d) + ", not " + fmt(mine) + " (tolerance " + fmt(d_tol) + ")";
    if (d != 0 && std::abs(mine - n_length * d) <= 1e-6 * std::abs(n_length * d))
      why += "; " + fmt(mine) + " is |n| = " + fmt(n_length) + " times it: is n unit?";
    else if (d != 0 && std::abs(mine + d) <= d_tol)
      why += "; the sign is flipped: the normal is (v1 - v0) x (v2 - v0), as wound";
    e.that(name, std::abs(mine - d) <= d_tol, fmt(mine), fmt(d), why);
  };
  distance("d_a", in.segment.a, got.d_a, exact.d_a);
  distance("d_b", in.segment.b, got.d_b, exact.d_b);
  const auto crosses = [](const SegmentTrianglePair& p) { return oracle::segment_crosses_plane(p.segment, p.triangle); };
  const std::string sides = "(d_a = " + fmt(exact.d_a) + ", d_b = " + fmt(exact.d_b) + ")";
  const std::string rule =
      exact.crosses ? "the ends are on opposite sides of the plane, or one is on it " + sides + ": the segment crosses it in one point"
      : exact.side_a == 0 && exact.side_b == 0 && n_length > 0
          ? "both ends are on the plane " + sides + ": the segment lies in it, no single crossing point"
          : n_length == 0 ? "a zero-area triangle has no plane to cross"
                          : "both ends are strictly on the same side of the plane " + sides + ": no crossing";
  const Outcome decision = yes_no(in, got.crosses, rules, crosses, "crosses", "does not cross",
                                  rule + std::string(", but your answer says it ") + (got.crosses ? "crosses" : "does not"));
  if (decision.verdict == Outcome::Verdict::fail) return fail("crosses = " + describe(exact.crosses), "crosses = " + describe(got.crosses), decision.why);
  if (exact.crosses && got.crosses) {
    const double t_tol = t_tolerance(in.segment, in.triangle, tol);
    std::string why = "the crossing is at t = d_a / (d_a - d_b) = " + fmt(exact.t) + ", not " + fmt(got.t) + " (tolerance " + fmt(t_tol) + ")";
    if (std::abs(got.t + exact.t) <= t_tol) why += "; yours has the opposite sign: is the denominator d_b - d_a?";
    else if (std::abs(got.t - (1 - exact.t)) <= t_tol) why += "; yours is measured from b: t runs from a (t = 0) to b";
    e.that("t", std::abs(got.t - exact.t) <= t_tol, fmt(got.t), fmt(exact.t), why);
    e.that("point", oracle::parameter_reproduces(in.segment, got.t, got.point, tol), fmt(got.point),
           "a + t (b - a) with your t", "the point must be a + t (b - a), and it is " + fmt((in.segment.point(got.t) - got.point).norm()) +
                                            " away from it (tolerance " + fmt(tol) + ")");
  }
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

Outcome point_in_triangle(const PointTriangle& in, bool got, Rules rules) {
  const auto inside = [](const PointTriangle& p) { return oracle::point_in_triangle_projected(p.x, p.triangle); };
  const Triangle& t = in.triangle;
  std::string rule = "x is in the closed triangle (a point on an edge or a vertex counts as inside)";
  if (oracle::unit_normal(t) == Vec3::Zero()) rule = "a zero-area triangle contains no point";
  else if (!inside(in))
    for (int i = 0; i < 3; ++i)
      if ((in.x - t[i]).dot(t.normal().cross(t[(i + 1) % 3] - t[i])) < 0) {
        rule = "x is outside the triangle, beyond its edge v" + std::to_string(i) + " v" + std::to_string((i + 1) % 3) +
               " (E_" + std::to_string(i) + " < 0)";
        break;
      }
  return yes_no(in, got, rules, inside, "inside (or on the boundary)", "outside",
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
  Expect e;
  const bool axis_ok = got.dropped_axis >= 0 && got.dropped_axis <= 2 && m[got.dropped_axis] >= m.maxCoeff() - kRelative;
  int best = 0;
  m.maxCoeff(&best);
  e.that("dropped_axis", axis_ok, describe(got.dropped_axis), describe(best),
         "drop the axis of the normal's largest |component|: the normal is " + fmt(n));
  const double tol = tolerance_of(in);
  const Triangle& t = in.triangle;
  std::string hint;
  if (oracle::alpha_beta_reproduce(t, got.alpha, -got.beta, in.x, tol)) hint = "; with -beta it would: the sign of beta is flipped";
  if (oracle::alpha_beta_reproduce(t, -got.alpha, got.beta, in.x, tol)) hint = "; with -alpha it would: the sign of alpha is flipped";
  if (oracle::alpha_beta_reproduce(t, got.beta, got.alpha, in.x, tol)) hint = "; swapped, they would: alpha weighs e1 = v1 - v0";
  e.that("alpha, beta", oracle::alpha_beta_reproduce(in.triangle, got.alpha, got.beta, in.x, tol),
         fmt(got.alpha) + ", " + fmt(got.beta), "v0 + alpha (v1 - v0) + beta (v2 - v0) = x",
         "alpha and beta must describe x as v0 + alpha e1 + beta e2, and yours miss it by " +
             fmt((in.triangle.v0 + got.alpha * (in.triangle.v1 - in.triangle.v0) +
                  got.beta * (in.triangle.v2 - in.triangle.v0) - in.x).norm()) +
             " (tolerance " + fmt(tol) + ")" + hint);
  return e.outcome();
}

Outcome test_segment_triangle(const SegmentTrianglePair& in, bool got, Rules rules) {
  const bool doubt = unstable(in.segment, in.triangle, tolerance_of(in), rules);
  return verdict(got, triangle_hit(in), doubt, rules, "hit", "miss", hit_rule(in.segment, in.triangle) + yours(got));
}

Outcome find_segment_triangle(const SegmentTrianglePair& in, const SegmentTriangleHit& got, Rules rules) {
  const bool doubt = unstable(in.segment, in.triangle, tolerance_of(in), rules);
  const Outcome decision =
      verdict(got.hit, triangle_hit(in), doubt, rules, "hit", "miss", hit_rule(in.segment, in.triangle) + yours(got.hit));
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !triangle_hit(in)) return decision;
  const double tol = tolerance_of(in);
  const oracle::SegmentHit exact = oracle::segment_triangle(in.segment, in.triangle);
  Expect e;
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

Outcome any_hit(const SegmentMeshPair& in, bool got, Rules rules) {
  return mesh_yes_no(statuses(in.segment, in.mesh, tolerance_of(in), rules), got, rules, "hit", "miss", in.segment, in.mesh);
}

Outcome first_hit(const SegmentMeshPair& in, const MeshHit& got, Rules rules) {
  const double tol = tolerance_of(in);
  const std::vector<Status> all = statuses(in.segment, in.mesh, tol, rules);
  const Outcome decision = mesh_yes_no(all, got.hit, rules, "a hit", "no hit", in.segment, in.mesh);
  const bool expected = std::any_of(all.begin(), all.end(), [](const Status& st) { return st.hit; });
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !expected) return decision;
  const std::vector<oracle::SegmentHit> hits = oracle::segment_mesh_hits(in.segment, in.mesh);
  if (!valid_index(in.mesh, got.triangle))
    return fail(describe_hits(hits), "triangle " + std::to_string(got.triangle), "that triangle index is out of range");
  const Triangle tri = mesh_triangle(in.mesh, got.triangle);
  if (!hit_or_ambiguous(in.segment, tri, tol, rules))
    return fail(describe_hits(hits), "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t),
                "the segment does not meet triangle " + std::to_string(got.triangle));
  Expect e;
  check_hit(e, in.segment, tri, got.t, got.point, got.barycentric, got.normal, tol);
  // The first hit whose existence is not in doubt bounds t from above.
  for (const oracle::SegmentHit& h : hits) {
    if (all[std::size_t(h.triangle)].unstable) continue;
    const Triangle first = mesh_triangle(in.mesh, h.triangle);
    const double slack = t_tolerance(in.segment, first, tol) + t_tolerance(in.segment, tri, tol);
    e.that("first", got.t <= h.t + slack, "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t),
           "triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t),
           "first_hit is the hit with the smallest t: triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t) +
               " comes before yours");
    break;
  }
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

Outcome all_hits(const SegmentMeshPair& in, const std::vector<MeshHit>& got, Rules rules) {
  const double tol = tolerance_of(in);
  const std::vector<oracle::SegmentHit> hits = oracle::segment_mesh_hits(in.segment, in.mesh);
  const std::string expected = describe_hits(hits), answer = describe_hits(got);
  bool doubt = false;
  std::set<int> reported;
  for (std::size_t k = 0; k < got.size(); ++k) {
    const MeshHit& h = got[k];
    if (!h.hit) return fail(expected, answer, "entry " + std::to_string(k) + " has hit = false");
    if (!valid_index(in.mesh, h.triangle)) return fail(expected, answer, "a triangle index is out of range");
    if (!reported.insert(h.triangle).second)
      return fail(expected, answer, "triangle " + std::to_string(h.triangle) + " is reported twice");
    const Triangle tri = mesh_triangle(in.mesh, h.triangle);
    if (!triangle_hit({in.segment, tri})) {
      if (!hit_or_ambiguous(in.segment, tri, tol, rules))
        return fail(expected, answer, "the segment does not meet triangle " + std::to_string(h.triangle));
      doubt = true;
    }
    Expect e;
    check_hit(e, in.segment, tri, h.t, h.point, h.barycentric, h.normal, tol);
    const Outcome o = e.outcome();
    if (o.verdict == Outcome::Verdict::fail)
      return fail(o.expected, o.got, "triangle " + std::to_string(h.triangle) + ": " + o.why);
    if (k + 1 < got.size() && valid_index(in.mesh, got[k + 1].triangle)) {
      const double slack = t_tolerance(in.segment, tri, tol) +
                           t_tolerance(in.segment, mesh_triangle(in.mesh, got[k + 1].triangle), tol);
      if (got[k + 1].t + slack < h.t)
        return fail(expected, answer, "all_hits must be sorted by t: triangle " + std::to_string(got[k + 1].triangle) + " (t = " +
                                          fmt(got[k + 1].t) + ") comes before triangle " + std::to_string(h.triangle) + " (t = " + fmt(h.t) + ")");
    }
  }
  for (const oracle::SegmentHit& h : hits) {
    if (reported.count(h.triangle)) continue;
    const Triangle tri = mesh_triangle(in.mesh, h.triangle);
    if (unstable(in.segment, tri, tol, rules)) {
      doubt = true;
      continue;
    }
    std::string why = "triangle " + std::to_string(h.triangle) + " (hit at t = " + fmt(h.t) + ") is missing";
    for (const MeshHit& other : got)
      if (std::abs(other.t - h.t) <= t_tolerance(in.segment, tri, tol))
        why += ": it is met at the same t as triangle " + std::to_string(other.triangle) +
               ", and every triangle met is listed once (a segment through a shared edge or face meets each)";
    return fail(expected, answer, why);
  }
  return doubt ? ambiguous() : pass();
}

Outcome first_hit_moving(const MovingMesh& in, const MeshHit& got) {
  // Doubt is judged in the mesh's frame, on the particle's path there.
  const double tol = tolerance_of(in);
  const Segment local = oracle::moving_local_path(in.segment, in.m0, in.m1);
  std::vector<Status> all = statuses(local, in.mesh, tol, Rules::random);
  const bool expected = oracle::moving_mesh_hit_any(in.segment, in.mesh, in.m0, in.m1);
  if (!expected) for (Status& st : all) st.hit = false;  // the rounded path must not overrule the exact one
  const Outcome decision = mesh_yes_no(all, got.hit, Rules::random, "a hit", "no hit", local, in.mesh);
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !expected) return decision;
  const std::vector<oracle::SegmentHit> hits = oracle::moving_mesh_hits(in.segment, in.mesh, in.m0, in.m1);
  std::string problem = oracle::check_moving_hit(in.segment, in.mesh, in.m0, in.m1, got.triangle, got.t, got.point, tol);
  if (!problem.empty() && valid_index(in.mesh, got.triangle)) {
    // The header's rule for points, in the mesh's frame: within tol of the path, and
    // within tol + |path| (t's tolerance) of the triangle (a needle's plane, or a path
    // nearly along it, fixes the crossing only that well).
    const Triangle tri = mesh_triangle(in.mesh, got.triangle);
    const Vec3 p = in.m1.inverse() * got.point;
    const double along = tol + (local.b - local.a).norm() * t_tolerance(local, tri, tol);
    if (oracle::within(p, tri, along) && oracle::within(p, local, tol) && oracle::parameter_reproduces(local, got.t, p, 2 * tol))
      problem.clear();
  }
  if (!problem.empty())
    return fail(describe_hits(hits), "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t) + ", point " + fmt(got.point),
                "the point must be the contact on the mesh at its end pose (m1 times the point found in the mesh's frame, "
                "on the path m0^-1 a -> m1^-1 b there): " + problem);
  // In the mesh's frame the path is m0^-1 a -> m1^-1 b; t is compared there, against
  // the first hit whose existence is not in doubt.
  for (const oracle::SegmentHit& h : hits) {
    if (all[std::size_t(h.triangle)].unstable) continue;
    const double slack = t_tolerance(local, mesh_triangle(in.mesh, h.triangle), tol) +
                         t_tolerance(local, mesh_triangle(in.mesh, got.triangle), tol);
    if (got.t > h.t + slack)
      return fail(describe_hits(hits), "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t),
                  "first_hit is the hit with the smallest t: triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t) +
               " comes before yours");
    break;
  }
  const Vec3 n = in.m1.linear() * oracle::unit_normal(mesh_triangle(in.mesh, got.triangle));
  if ((got.normal - n).norm() > 1e-8)
    return fail(fmt(n), fmt(got.normal), "the normal must be the triangle's unit normal as wound, turned by m1 (the mesh at its end pose)");
  return decision;
}

// ---- Step 7: two meshes moving by translations -----------------------------------------

namespace {

// The exact first contact, in the header's words: which family, which features, when.
std::string contact_rule(const MovingMeshes& in, const oracle::MeshContact& c) {
  const Vec3 d = in.velocity_a - in.velocity_b;
  const std::string seen = " (seen from B, A moves by va - vb = " + fmt(d) + ")";
  if (!c.hit) return "the meshes never touch during the frame, 0 <= t <= 1" + seen;
  const std::string at = " at t = " + fmt(c.t) + ", point " + fmt(c.point);
  if (c.kind == 0)
    return "the meshes first touch" + at + ": vertex " + std::to_string(c.feature_a) + " of A, on its path p -> p + d, meets face " +
           std::to_string(c.feature_b) + " of B" + seen;
  if (c.kind == 1)
    return "the meshes first touch" + at + ": vertex " + std::to_string(c.feature_b) +
           " of B, on its path q -> q - d (the other delta matrix), meets face " + std::to_string(c.feature_a) + " of A" + seen;
  const auto ea = oracle::mesh_edges(in.a)[std::size_t(c.feature_a)], eb = oracle::mesh_edges(in.b)[std::size_t(c.feature_b)];
  return "the meshes first touch" + at + ": edge-edge, edge (" + std::to_string(ea[0]) + ", " + std::to_string(ea[1]) +
         ") of A, sweeping its quad (two triangles), meets edge (" + std::to_string(eb[0]) + ", " + std::to_string(eb[1]) +
         ") of B" + seen;
}

}  // namespace

Outcome first_contact_moving_meshes(const MovingMeshes& in, const MeshContact& got, Rules rules) {
  const double tol = tolerance_of(in);
  const oracle::MeshContact exact = oracle::first_contact_translating(in.a, in.velocity_a, in.b, in.velocity_b);
  const auto touches = [](const MovingMeshes& m) {
    return oracle::touch_during_frame_fast(m.a, m.velocity_a, m.b, m.velocity_b);
  };
  const bool doubt = rules == Rules::random && check::flips_under_perturbation(in, touches, 4);
  // What A's motion alone would give (the mistake of moving A by va, not by va - vb):
  // computed only for a failure's message.
  const auto telltale = [&](bool hit, double t) {
    if (in.velocity_b == Vec3::Zero()) return std::string();
    const oracle::MeshContact absolute = oracle::first_contact_translating(in.a, in.velocity_a, in.b, Vec3::Zero());
    if (hit != absolute.hit || (hit && std::abs(t - absolute.t) > 1e-6)) return std::string();
    return std::string("; yours is what A's own motion va gives against a still B: B moves too, so use the relative motion va - vb");
  };
  Outcome decision = verdict(got.hit, exact.hit, doubt, rules, "contact", "no contact", contact_rule(in, exact) + yours(got.hit));
  if (decision.verdict == Outcome::Verdict::fail) decision.why += telltale(got.hit, got.t);
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !exact.hit) return decision;
  // t, certified: no contact before t - dt, contact by t + dt. dt = tol over the closing
  // speed along the contact's normal; exact input is held to 1e-9.
  const Vec3 d = in.velocity_a - in.velocity_b;
  const double dt = rules == Rules::exact ? 1e-9 : exact.approach > 0 ? tol / exact.approach : 1.0;
  const std::string got_t = "t = " + fmt(got.t) + ", point " + fmt(got.point);
  const std::string exact_t = "t = " + fmt(exact.t) + ", point " + fmt(exact.point);
  // Whether a perturbation of tol changes "touching by time x": then either side passes
  // (a near miss earlier than the exact first contact, or a contact that a hair removes).
  const auto in_doubt = [&](double x) {
    return rules == Rules::random && check::flips_under_perturbation(in, [x](const MovingMeshes& m) {
             return oracle::contact_by(m.a, m.velocity_a, m.b, m.velocity_b, x);
           });
  };
  if (oracle::contact_by(in.a, in.velocity_a, in.b, in.velocity_b, got.t - dt)) {
    if (in_doubt(got.t - dt)) return ambiguous();
    return fail(exact_t, got_t,
                contact_rule(in, exact) + ": the meshes already touch before your t = " + fmt(got.t) +
                    " (tolerance " + fmt(dt) + "): report the first contact, the smallest t of all three families" +
                    telltale(true, got.t));
  }
  if (!oracle::contact_by(in.a, in.velocity_a, in.b, in.velocity_b, got.t + dt)) {
    if (in_doubt(got.t + dt)) return ambiguous();
    return fail(exact_t, got_t,
                contact_rule(in, exact) + ": the meshes do not touch yet at your t = " + fmt(got.t) + " (tolerance " + fmt(dt) +
                    ")" + telltale(true, got.t));
  }
  const double reach = 2 * tol + d.norm() * std::min(dt, 1.0);
  const bool on_a = oracle::within_translated(got.point, in.a, got.t * in.velocity_a, reach);
  const bool on_b = oracle::within_translated(got.point, in.b, got.t * in.velocity_b, reach);
  if (!on_a || !on_b)
    return fail(exact_t, got_t,
                std::string("the point must be where the meshes touch, in the world at your t: on A moved by t va and on B "
                            "moved by t vb (within ") + fmt(reach) + "), and yours is off " + (on_a ? "B" : "A") +
                    " (a point found in B's frame moves on by t vb; in A's frame by t va)");
  return decision;
}

rc::Gen<PointTriangle> point_triangle() {
  return rc::gen::exec([] {
    const double s = *gen::wide_scale();
    const Triangle t = *gen::any_triangle(s);
    // x = v0 + alpha e1 + beta e2 with dyadic alpha, beta: exactly in the plane. Near an
    // edge, a few units of 2^-bits off it (2^-20 of a height: far outside the band, unless
    // the triangle is a needle); exactly on one only now and then (the robustness step's).
    const int bits = *rc::gen::element(3, 10, 20);
    const double unit = std::ldexp(1.0, -bits);
    const auto off = [] { return *rc::gen::weightedElement<int>({{1, 0}, {3, 1}, {3, -1}, {2, 2}, {2, -2}}); };
    const auto near = [&](int base) { return base * std::ldexp(1.0, bits - 3) + off(); };
    const auto weight = [&] {
      return *rc::gen::oneOf(rc::gen::just(near(*rc::gen::inRange(-4, 13))), rc::gen::just(double(*gen::integer(1 << 12)))) * unit;
    };
    const double alpha = weight();
    // Sometimes near the edge v1 v2 (alpha + beta = 1).
    const double beta = *rc::gen::element(0, 1) ? 1.0 - alpha + off() * unit : weight();
    return PointTriangle{t.v0 + alpha * (t.v1 - t.v0) + beta * (t.v2 - t.v0), t};
  });
}

rc::Gen<PointTriangle> exact_point_triangle() {
  return rc::gen::exec([] {
    const double s = 8 * *gen::scale();
    const Triangle t{*gen::lattice_point(s), *gen::lattice_point(s), *gen::lattice_point(s)};
    // (p v0 + q v1 + r v2) / 8 with p + q + r = 8: vertices, edges and inside, plus
    // points just outside an edge (one weight -1/8).
    const int p = *rc::gen::inRange(-1, 10);
    const int q = *rc::gen::inRange(-1, 10 - p);
    const int r = 8 - p - q;
    return PointTriangle{(p * t.v0 + q * t.v1 + r * t.v2) / 8.0, t};
  });
}

rc::Gen<MovingMesh> moving_mesh() {
  return rc::gen::exec([] {
    const SegmentMeshPair base = *gen::decisive_segment_mesh();
    const double s = check::scale_of_input(base);
    const RigidTransform m0 = *gen::rigid_transform(s);
    const RigidTransform m1 = *rc::gen::oneOf(rc::gen::just(m0), gen::rigid_transform(s));
    // The segment was aimed at the mesh in its own frame; place it in the world at m0/m1.
    return MovingMesh{{m0 * base.segment.a, m1 * base.segment.b}, base.mesh, m0, m1};
  });
}

// ---- Step 7's random meshes ------------------------------------------------------------

namespace {

// A point of the unit-ish cube [-1, 1]^3 on a 1/8 lattice.
rc::Gen<Vec3> eighth_point() {
  return rc::gen::exec([]() -> Vec3 { return Vec3(*gen::integer(8), *gen::integer(8), *gen::integer(8)) / 8.0; });
}

// A small mesh within distance sqrt(3) of the origin: a tetrahedron, a tent (two
// triangles on a shared edge) or one triangle; its faces have non-zero area.
Mesh small_mesh() {
  const int shape = *rc::gen::weightedElement<int>({{5, 0}, {3, 1}, {2, 2}});
  const int count = shape == 0 ? 4 : shape == 1 ? 4 : 3;
  Mesh m;
  for (;;) {
    m.vertices.clear();
    for (int i = 0; i < count; ++i) m.vertices.push_back(*eighth_point());
    const Vec3 e1 = m.vertices[1] - m.vertices[0], e2 = m.vertices[2] - m.vertices[0];
    const bool flat = e1.cross(e2).squaredNorm() < 1.0 / 64;
    const bool thin = count == 4 && std::abs(e1.cross(e2).dot(m.vertices[3] - m.vertices[0])) < 1.0 / 16;
    if (!flat && !thin) break;
  }
  if (shape == 0) m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  else if (shape == 1) m.triangles = {{0, 1, 2}, {0, 3, 1}};
  else m.triangles = {{0, 1, 2}};
  return m;
}

// A point of the mesh: a vertex, a point inside an edge, or inside a face, and the
// feature's kind (0 vertex, 1 edge, 2 face).
Vec3 feature_point(const Mesh& m, int kind) {
  const auto& tri = m.triangles[std::size_t(*rc::gen::inRange<int>(0, int(m.triangles.size())))];
  const Vec3 v0 = m.vertices[std::size_t(tri[0])], v1 = m.vertices[std::size_t(tri[1])], v2 = m.vertices[std::size_t(tri[2])];
  if (kind == 0) return v0;
  // On an edge at an odd sixteenth, 3/16 to 13/16 from either end: never at a time t0 of
  // the aim below, since the swept parallelogram's diagonal (u = t) is an exact
  // degeneracy, the robustness step's.
  if (kind == 1) return v0 + (2 * *rc::gen::inRange(1, 7) + 1) / 16.0 * (v1 - v0);
  const double u = *rc::gen::inRange(1, 8) / 8.0;
  const double w = *rc::gen::inRange(1, 9 - int(8 * u)) / 8.0 * (1 - u);
  return v0 + u * (v1 - v0) + w * (v2 - v0);
}

}  // namespace

rc::Gen<MovingMeshes> moving_meshes() {
  return rc::gen::exec([] {
    const double s = *gen::wide_scale();
    MovingMeshes in;
    in.a = small_mesh();
    in.b = small_mesh();
    // B sits 4 to 6 units away in a random direction: apart at t = 0.
    Vec3 dir(*gen::integer(4), *gen::integer(4), *gen::integer(4));
    if (dir == Vec3::Zero()) dir = Vec3(1, 0, 0);
    const Vec3 centre = dir.normalized() * (4 + *rc::gen::inRange(0, 3));
    for (Vec3& v : in.b.vertices) v += centre;
    // Aim: a vertex of A at a face of B, a vertex of B at a face of A, or an edge at an
    // edge, to meet at t0; t0 > 1 stops short. Sometimes the aim is nudged a little
    // beside the feature (1e-6 to 1e-3 of the size: far outside the ambiguity band).
    const int family = *rc::gen::inRange(0, 3);
    const Vec3 x_a = feature_point(in.a, family == 0 ? 0 : family == 1 ? 2 : 1);
    const Vec3 x_b = feature_point(in.b, family == 0 ? 2 : family == 1 ? 0 : 1);
    const double t0 = *rc::gen::weightedElement<double>({{6, 0.25}, {6, 0.5}, {6, 0.75}, {3, 0.9375}, {3, 1.25}, {2, 2.0}});
    Vec3 nudge = Vec3::Zero();
    if (*rc::gen::element(0, 0, 1)) nudge = Vec3(*gen::integer(4), *gen::integer(4), *gen::integer(4)) * *gen::tiny(10, 20);
    const Vec3 d = (x_b + nudge - x_a) / t0;
    const Vec3 velocity_b = *rc::gen::element(0, 1) ? Vec3::Zero() : Vec3(*gen::integer(8), *gen::integer(8), *gen::integer(8));
    in.velocity_b = velocity_b;
    in.velocity_a = *rc::gen::element(0, 0, 0, 0, 0, 0, 0, 0, 0, 1) ? velocity_b : Vec3(d + velocity_b);  // now and then: no relative motion
    for (Vec3& v : in.a.vertices) v *= s;
    for (Vec3& v : in.b.vertices) v *= s;
    in.velocity_a *= s, in.velocity_b *= s;
    return in;
  });
}

}  // namespace labkit::lab02::judge
