#include "02_segment_triangle.judge.h"

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

using check::verdict;

// The same, with doubt found by perturbing the input (`exact` recomputes the answer).
template <class Input, class Exact>
Outcome yes_no(const Input& in, bool got, Rules rules, Exact&& exact, const std::string& yes, const std::string& no) {
  const bool doubt = rules == Rules::random && check::flips_under_perturbation(in, exact);
  return verdict(got, exact(in), doubt, rules, yes, no);
}

// How loosely a crossing fixes t: tol / |d_a - d_b|, or tol / |b - a| in the plane.
double t_tolerance(const Segment& s, const Triangle& tri, double tol) {
  const oracle::PlaneCrossing c = oracle::segment_plane(s, tri);
  const double change = std::abs(c.d_a - c.d_b);
  if (change > 0) return tol / change;
  const double length = (s.b - s.a).norm();
  return length > 0 ? tol / length : std::numeric_limits<double>::infinity();
}

bool triangle_hit(const SegmentTrianglePair& p) { return oracle::segment_hits_triangle(p.segment, p.triangle); }

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
Outcome mesh_yes_no(const std::vector<Status>& all, bool got, Rules rules, const std::string& yes, const std::string& no) {
  bool expected = false, stable_hit = false, doubt = false;
  for (const Status& st : all) {
    expected = expected || st.hit;
    stable_hit = stable_hit || (st.hit && !st.unstable);
    doubt = doubt || st.unstable;
  }
  return verdict(got, expected, !stable_hit && doubt, rules, yes, no);
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
  e.that("point on segment", oracle::within(point, s, tol), fmt(point), "a point of the segment",
         "the point is " + fmt(oracle::distance(point, s)) + " from the segment (tolerance " + fmt(tol) + ")");
  e.that("t", oracle::parameter_reproduces(s, t, point, tol), fmt(t), "a + t (b - a) = point",
         "a + t (b - a) is " + fmt((s.point(t) - point).norm()) + " away from the point");
  e.that("barycentric", std::abs(weights.sum() - 1) <= kRelative && oracle::weights_reproduce(tri, weights, point, tol),
         fmt(weights), "weights summing to 1 that reproduce the point",
         "w0 v0 + w1 v1 + w2 v2 is " + fmt((weights[0] * tri.v0 + weights[1] * tri.v1 + weights[2] * tri.v2 - point).norm()) +
             " away from the point, and the weights sum to " + fmt(weights.sum()));
  const Vec3 n = oracle::unit_normal(tri);
  e.that("normal", (normal - n).norm() <= kRelative, fmt(normal), fmt(n),
         "the normal must be the triangle's unit normal (v1 - v0) x (v2 - v0) / |...|");
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
  Expect e;
  e.near("d_a", got.d_a, exact.d_a, tol);
  e.near("d_b", got.d_b, exact.d_b, tol);
  const auto crosses = [](const SegmentTrianglePair& p) { return oracle::segment_crosses_plane(p.segment, p.triangle); };
  const Outcome decision = yes_no(in, got.crosses, rules, crosses, "crosses", "does not cross");
  if (decision.verdict == Outcome::Verdict::fail) return fail("crosses = " + describe(exact.crosses), "crosses = " + describe(got.crosses), decision.why);
  if (exact.crosses && got.crosses) {
    const double t_tol = tol / std::abs(exact.d_a - exact.d_b);
    e.near("t", got.t, exact.t, t_tol);
    e.that("point", oracle::parameter_reproduces(in.segment, got.t, got.point, tol), fmt(got.point),
           "a + t (b - a) with your t", "a + t (b - a) is " + fmt((in.segment.point(got.t) - got.point).norm()) +
                                            " away from your point (tolerance " + fmt(tol) + ")");
  }
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

Outcome point_in_triangle(const PointTriangle& in, bool got, Rules rules) {
  const auto inside = [](const PointTriangle& p) { return oracle::point_in_triangle_projected(p.x, p.triangle); };
  return yes_no(in, got, rules, inside, "inside (or on the boundary)", "outside");
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
  e.that("alpha, beta", oracle::alpha_beta_reproduce(in.triangle, got.alpha, got.beta, in.x, tol),
         fmt(got.alpha) + ", " + fmt(got.beta), "v0 + alpha (v1 - v0) + beta (v2 - v0) = x",
         "v0 + alpha (v1 - v0) + beta (v2 - v0) is " +
             fmt((in.triangle.v0 + got.alpha * (in.triangle.v1 - in.triangle.v0) +
                  got.beta * (in.triangle.v2 - in.triangle.v0) - in.x).norm()) +
             " away from x (tolerance " + fmt(tol) + ")");
  return e.outcome();
}

Outcome test_segment_triangle(const SegmentTrianglePair& in, bool got, Rules rules) {
  const bool doubt = unstable(in.segment, in.triangle, tolerance_of(in), rules);
  return verdict(got, triangle_hit(in), doubt, rules, "hit", "miss");
}

Outcome find_segment_triangle(const SegmentTrianglePair& in, const SegmentTriangleHit& got, Rules rules) {
  const bool doubt = unstable(in.segment, in.triangle, tolerance_of(in), rules);
  const Outcome decision = verdict(got.hit, triangle_hit(in), doubt, rules, "hit", "miss");
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
  return mesh_yes_no(statuses(in.segment, in.mesh, tolerance_of(in), rules), got, rules, "hit", "miss");
}

Outcome first_hit(const SegmentMeshPair& in, const MeshHit& got, Rules rules) {
  const double tol = tolerance_of(in);
  const std::vector<Status> all = statuses(in.segment, in.mesh, tol, rules);
  const Outcome decision = mesh_yes_no(all, got.hit, rules, "a hit", "no hit");
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
           "a nearer hit exists: triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t));
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
      if (got[k + 1].t + slack < h.t) return fail(expected, answer, "the hits are not sorted by t");
    }
  }
  for (const oracle::SegmentHit& h : hits) {
    if (reported.count(h.triangle)) continue;
    const Triangle tri = mesh_triangle(in.mesh, h.triangle);
    if (unstable(in.segment, tri, tol, rules)) {
      doubt = true;
      continue;
    }
    return fail(expected, answer, "triangle " + std::to_string(h.triangle) + " (hit at t = " + fmt(h.t) + ") is missing");
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
  const Outcome decision = mesh_yes_no(all, got.hit, Rules::random, "a hit", "no hit");
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !expected) return decision;
  const std::vector<oracle::SegmentHit> hits = oracle::moving_mesh_hits(in.segment, in.mesh, in.m0, in.m1);
  const std::string problem =
      oracle::check_moving_hit(in.segment, in.mesh, in.m0, in.m1, got.triangle, got.t, got.point, tol);
  if (!problem.empty())
    return fail(describe_hits(hits), "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t) + ", point " + fmt(got.point),
                problem);
  // In the mesh's frame the path is m0^-1 a -> m1^-1 b; t is compared there, against
  // the first hit whose existence is not in doubt.
  for (const oracle::SegmentHit& h : hits) {
    if (all[std::size_t(h.triangle)].unstable) continue;
    const double slack = t_tolerance(local, mesh_triangle(in.mesh, h.triangle), tol) +
                         t_tolerance(local, mesh_triangle(in.mesh, got.triangle), tol);
    if (got.t > h.t + slack)
      return fail(describe_hits(hits), "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t),
                  "a nearer hit exists: triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t));
    break;
  }
  const Vec3 n = in.m1.linear() * oracle::unit_normal(mesh_triangle(in.mesh, got.triangle));
  if ((got.normal - n).norm() > 1e-8)
    return fail(fmt(n), fmt(got.normal), "the normal must be the triangle's unit normal, turned by m1");
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

}  // namespace labkit::lab02::judge
