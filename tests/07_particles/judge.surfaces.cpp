// Lab 07's surfaces: when a step hits a one-sided plane or a two-sided triangle, in the
// header's rules, with the doubt around each; the first hit on a scene, which steps 4 to 7
// judge; step 4's judges; and the doubt tests the generators keep their families out of.
#include "07_particles/judge_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace labkit::lab07::judge {

namespace {

// S of a scene: its mesh vertices, and each plane's point nearest the origin.
double scene_scale(const Scene& scene) {
  double s = scale_of(scene.mesh);
  for (const Plane& p : scene.planes) {
    const double length = p.normal.norm();
    if (length > 0) s = std::max(s, std::abs(p.offset) / length);
  }
  return s;
}

}  // namespace

double scale_with(const Scene& scene, std::initializer_list<Vec3> points) {
  return std::max({scene_scale(scene), scale_of(points), 1e-300});
}

// Keeps the first failure of a sequence of checks, with a prefix saying where it was.
Outcome within(const std::string& where, const Outcome& o) {
  if (o.verdict != Outcome::Verdict::fail) return o;
  return fail(o.expected, o.got, where + ": " + o.why);
}

bool valid_plane(const Scene& scene, int i) { return i >= 0 && std::size_t(i) < scene.planes.size(); }
bool valid_triangle(const Scene& scene, int i) { return i >= 0 && std::size_t(i) < scene.mesh.size(); }

namespace {

// ---- Surfaces: exact hits and whether a perturbation could change them ----------------

// How much n . x + c can move when every coordinate moves by eps S, every normal
// component by eps and the offset by eps S: |n| sqrt(3) eps S + sqrt(3) eps |x| + eps S.
// A value within twice that of zero is in doubt.
bool plane_value_in_doubt(const Plane& p, const Vec3& x, double scale) {
  const double reach = kRelative * (p.normal.norm() * kRoot3 * scale + kRoot3 * x.norm() + scale);
  return std::abs(p.value(x)) <= 2 * reach;
}

// The hit is value(a) >= 0 and value(b) < 0. When b is clearly in front (value(b) > 0
// beyond doubt), no perturbation makes it a hit, whatever a does: a piece leaving the
// plane it just bounced off, with a a hair off it, is not in doubt. Otherwise a doubt on
// either end can flip it.
// value(x) = n . x + c as the header computes it, and its rounding bound.
struct Rounded {
  double value, error;
};
Rounded rounded_value(const Plane& p, const Vec3& x) {
  const Vec3 terms = p.normal.cwiseProduct(x);
  return {terms.x() + terms.y() + terms.z() + p.offset, 1e-15 * (terms.cwiseAbs().sum() + std::abs(p.offset))};
}

// Step 4's rule: b behind, exactly; a not behind, where a computed value(a) within its
// rounding bound counts as 0 (a particle resting on the plane).
bool plane_hit_by_rule(const Segment& s, const Plane& p) {
  if (oracle::plane_hit(s, p)) return true;
  if (p.normal == Vec3::Zero() || oracle::plane_side(p, s.b) >= 0) return false;
  const Rounded a = rounded_value(p, s.a);
  return std::abs(a.value) <= a.error;
}

// Why the step does or does not hit the plane, in the header's words.
std::string plane_rule(const Segment& s, const Plane& p) {
  if (p.normal == Vec3::Zero()) return "a plane with a zero normal is never hit";
  const std::string va = "value(a) = " + fmt(p.value(s.a)), vb = "value(b) = " + fmt(p.value(s.b));
  if (plane_hit_by_rule(s, p))
    return oracle::plane_side(p, s.a) < 0
               ? "a is on the plane to within value(a)'s rounding bound (" + va +
                     "), so it counts as on it, and b is behind it (" + vb + "): a hit at t = 0"
               : "the step starts on or in front of the plane (" + va + " >= 0) and ends behind it (" + vb +
                     " < 0): a hit";
  if (oracle::plane_side(p, s.a) < 0)
    return "planes are one-sided: the step starts behind the plane (" + va + " < 0), which is no hit";
  return "the step ends on or in front of the plane (" + vb +
         " >= 0): on the plane is not behind it, and only a step "
         "that ends behind a plane hits it";
}

bool plane_unstable(const Segment& s, const Plane& p, double scale, Rules rules) {
  if (rules == Rules::exact) return false;
  if (plane_value_in_doubt(p, s.b, scale)) return true;
  return p.value(s.b) < 0 && plane_value_in_doubt(p, s.a, scale);
}

bool sheet_hit(const SegmentTrianglePair& p) { return oracle::sheet_hit(p.segment, p.triangle); }

// Why the step does or does not hit the two-sided triangle, in the header's words.
std::string triangle_rule(const Segment& s, const Triangle& tri) {
  if (tri.normal() == Vec3::Zero()) return "a zero-area triangle is never hit";
  const int side = oracle::orientation(tri.v0, tri.v1, tri.v2, s.a);
  if (side == 0) return "a starts exactly on the triangle's plane: it is leaving the sheet, which is no hit";
  if (oracle::sheet_hit(s, tri))
    return "a is off the triangle's plane and the segment meets the closed triangle (edges and vertices count); "
           "triangles are two-sided: a hit from either side";
  if (oracle::orientation(tri.v0, tri.v1, tri.v2, s.b) == side)
    return "the segment stays on one side of the triangle's plane: no hit";
  return "the segment crosses the triangle's plane outside the closed triangle: no hit";
}

// A yes/no verdict whose failure says the rule, not only that the answer differs.
Outcome decide(bool got, bool expected, bool doubt, Rules rules, const std::string& rule) {
  const Outcome o = verdict(got, expected, doubt, rules, "a hit", "no hit");
  return o.verdict == Outcome::Verdict::fail ? fail(o.expected, o.got, rule) : o;
}

// Could a perturbation of tol change whether the segment hits this sheet?
bool triangle_unstable(const Segment& s, const Triangle& tri, double tol, Rules rules) {
  return judging::unstable(s, tri, tol, rules, sheet_hit);
}

// How loosely a crossing fixes t: tol / |d_a - d_b| with unit-normal distances.
double t_tolerance(double d_a, double d_b, double tol) {
  const double change = std::abs(d_a - d_b);
  return change > 0 ? tol / change : std::numeric_limits<double>::infinity();
}
double plane_t_tolerance(const Segment& s, const Plane& p, double tol) {
  return t_tolerance(oracle::plane_distance(p, s.a), oracle::plane_distance(p, s.b), tol);
}
double triangle_t_tolerance(const Segment& s, const Triangle& t, double tol) {
  return t_tolerance(oracle::triangle_plane_distance(t, s.a), oracle::triangle_plane_distance(t, s.b), tol);
}

// The checks every reported hit must pass: the point on the segment and the surface,
// t reproducing it and near the exact t, the unit normal facing the particle.
// A hit's numbers must be finite before the exact oracle reads them.
bool finite_hit(Expect& e, const SurfaceHit& got) {
  const bool ok = std::isfinite(got.t) && got.point.allFinite() && got.normal.allFinite();
  e.that("finite", ok, "t = " + fmt(got.t) + ", point " + fmt(got.point) + ", normal " + fmt(got.normal),
         "finite numbers",
         "a hit's t, point and normal must be finite numbers (a NaN: 0 / 0 from a step that does not cross?)");
  return ok;
}

void check_plane_hit(Expect& e, const Segment& s, const Plane& p, const SurfaceHit& got, double tol) {
  if (!finite_hit(e, got)) return;
  e.that("point", oracle::within(got.point, p, tol), fmt(got.point), "a point of the plane",
         "the hit point must lie on the plane: yours is " + fmt(std::abs(oracle::plane_distance(p, got.point))) +
             " from it (tolerance " + fmt(tol) + ")");
  e.that("point on segment", oracle::within(got.point, s, tol), fmt(got.point), "a point of the segment",
         "the hit point must lie on the step a -> b: yours is " + fmt(oracle::distance(got.point, s)) +
             " from it (tolerance " + fmt(tol) + ")");
  e.that("t", oracle::parameter_reproduces(s, got.t, got.point, tol), fmt(got.t), "a + t (b - a) = point",
         "the point must be a + t (b - a) for your t: it is " + fmt((s.point(got.t) - got.point).norm()) + " away");
  const double exact_t = oracle::plane_hit_t(s, p), slack = plane_t_tolerance(s, p, tol);
  e.that("t exact", std::abs(got.t - exact_t) <= slack, fmt(got.t), fmt(exact_t),
         "t must be where value changes sign, value(a) / (value(a) - value(b)) = " + fmt(exact_t) +
             ": yours is off by " + fmt(std::abs(got.t - exact_t)) + " (tolerance " + fmt(slack) + ")");
  const Vec3 n = p.normal.normalized();
  const double length = got.normal.norm();
  e.that("normal", (got.normal - n).norm() <= kRelative, fmt(got.normal), fmt(n),
         std::abs(length - 1) > kRelative ? "the normal must be unit length, n / |n|: yours has length " + fmt(length)
         : got.normal.dot(n) < 0
             ? "a plane's normal is its own direction, n / |n|, the side a particle comes from: yours points behind"
             : "a plane's normal is its own direction, made unit length: n / |n|");
}

void check_triangle_hit(Expect& e, const Segment& s, const Triangle& tri, const SurfaceHit& got, double tol) {
  if (!finite_hit(e, got)) return;
  e.that("point", oracle::within(got.point, tri, tol), fmt(got.point), "a point of the triangle",
         "the point is " + fmt(oracle::distance(got.point, tri)) + " from the triangle (tolerance " + fmt(tol) + ")");
  e.that("point on segment", oracle::within(got.point, s, tol), fmt(got.point), "a point of the segment",
         "the hit point must lie on the step a -> b: yours is " + fmt(oracle::distance(got.point, s)) +
             " from it (tolerance " + fmt(tol) + ")");
  e.that("t", oracle::parameter_reproduces(s, got.t, got.point, tol), fmt(got.t), "a + t (b - a) = point",
         "the point must be a + t (b - a) for your t: it is " + fmt((s.point(got.t) - got.point).norm()) + " away");
  // The exact t: of the first common point or, for a hit in doubt that is exactly a miss
  // (a hair outside an edge), of the crossing with the triangle's plane it rounds from.
  const oracle::SegmentHit exact = oracle::segment_triangle(s, tri);
  const oracle::PlaneCrossing crossing = exact.hit ? oracle::PlaneCrossing{} : oracle::segment_plane(s, tri);
  if (exact.hit || crossing.crosses) {
    const double exact_t = exact.hit ? exact.t : crossing.t, slack = triangle_t_tolerance(s, tri, tol);
    e.that("t exact", std::abs(got.t - exact_t) <= slack, fmt(got.t), fmt(exact_t),
           "t must be where the step meets the triangle, " + fmt(exact_t) + ": yours is off by " +
               fmt(std::abs(got.t - exact_t)) + " (tolerance " + fmt(slack) + ")");
  }
  // The side a is on: when a is a hair off the plane either side may be reported.
  const int side = oracle::orientation(tri.v0, tri.v1, tri.v2, s.a);
  const Vec3 n = oracle::unit_normal(tri);
  // A needle's plane is only as well defined as its width: moving the vertices by tol
  // turns it by up to 2 tol / h, h its smallest height (twice its area over its longest edge).
  const double longest = std::max({(tri.v1 - tri.v0).norm(), (tri.v2 - tri.v1).norm(), (tri.v0 - tri.v2).norm()});
  const double turn = kRelative + 2 * tol * longest / tri.normal().norm();
  const bool up = (got.normal - n).norm() <= turn, down = (got.normal + n).norm() <= turn;
  const bool near_plane = std::abs(oracle::triangle_plane_distance(tri, s.a)) <= 8 * tol;
  e.that("normal", (side > 0 && up) || (side < 0 && down) || (near_plane && (up || down)), fmt(got.normal),
         fmt(side < 0 ? Vec3(-n) : n),
         std::abs(got.normal.norm() - 1) > kRelative
             ? "the normal must be unit length: yours has length " + fmt(got.normal.norm())
             : "triangles are two-sided: the normal must be the triangle's unit normal turned to the side a is on (" +
                   std::string(side < 0 ? "behind e1 x e2" : "in front of e1 x e2") + ")");
}

using judging::Status;

struct SceneStatus {
  std::vector<Status> planes, triangles;
  judging::AnyHit any;  // over the planes and the triangles
};

// `left`: the hit the piece s starts from (collide), or none. A piece that starts strictly
// in front of the sheet it just bounced off and ends clearly in front of it does not hit
// it, whatever a perturbation of its start would do: its start is the answer's own point.
SceneStatus statuses(const Segment& s, const Scene& scene, double tol, Rules rules, const SurfaceHit* left = nullptr) {
  SceneStatus all;
  const double scale = tol / kRelative;
  for (const Plane& p : scene.planes)
    all.planes.push_back({plane_hit_by_rule(s, p), plane_unstable(s, p, scale, rules)});
  for (std::size_t i = 0; i < scene.mesh.size(); ++i) {
    const Triangle tri = scene.mesh.triangle(i);
    const int facing = left && left->triangle == int(i) && left->normal.dot(tri.normal()) < 0 ? -1 : 1;
    const bool leaving = left && left->triangle == int(i) &&
                         facing * oracle::orientation(tri.v0, tri.v1, tri.v2, s.a) > 0 &&
                         facing * oracle::triangle_plane_distance(tri, s.b) > 8 * tol;
    all.triangles.push_back({oracle::sheet_hit(s, tri), !leaving && triangle_unstable(s, tri, tol, rules)});
  }
  for (const auto* list : {&all.planes, &all.triangles})
    for (const Status& st : *list) all.any.add(st);
  return all;
}

std::string describe_hits(const Segment& s, const Scene& scene, const SceneStatus& all) {
  std::string text;
  for (std::size_t i = 0; i < all.planes.size(); ++i)
    if (all.planes[i].hit)
      text += (text.empty() ? "" : ", ") +
              ("plane " + std::to_string(i) + " at t = " + fmt(oracle::plane_hit_t(s, scene.planes[i])));
  for (std::size_t i = 0; i < all.triangles.size(); ++i)
    if (all.triangles[i].hit)
      text += (text.empty() ? "" : ", ") + ("triangle " + std::to_string(i) +
                                            " at t = " + fmt(oracle::segment_triangle(s, scene.mesh.triangle(i)).t));
  return text.empty() ? "no hit" : text;
}

std::string describe_hit(const SurfaceHit& h) {
  if (!h.hit) return "no hit";
  return (h.plane >= 0 ? "plane " + std::to_string(h.plane) : "triangle " + std::to_string(h.triangle)) +
         " at t = " + fmt(h.t);
}

// The rule that decides a scene's yes/no: that of a surface certainly hit, else of the
// surface the answer names.
std::string scene_rule(const Segment& s, const Scene& scene, const SceneStatus& all, const SurfaceHit& got) {
  for (std::size_t i = 0; i < all.planes.size(); ++i)
    if (all.planes[i].hit && !all.planes[i].unstable)
      return "plane " + std::to_string(i) + ": " + plane_rule(s, scene.planes[i]);
  for (std::size_t i = 0; i < all.triangles.size(); ++i)
    if (all.triangles[i].hit && !all.triangles[i].unstable)
      return "triangle " + std::to_string(i) + ": " + triangle_rule(s, scene.mesh.triangle(i));
  if (valid_plane(scene, got.plane))
    return "plane " + std::to_string(got.plane) + ": " + plane_rule(s, scene.planes[std::size_t(got.plane)]);
  if (valid_triangle(scene, got.triangle))
    return "triangle " + std::to_string(got.triangle) + ": " +
           triangle_rule(s, scene.mesh.triangle(std::size_t(got.triangle)));
  return "the step hits no plane (it starts behind, or does not end behind, each) and meets no triangle";
}

}  // namespace

// The first hit of a segment on a scene: lab 02's mesh verdict, with planes beside the triangles.
Outcome first_hit_on(const Segment& s, const Scene& scene, const SurfaceHit& got, Rules rules, const SurfaceHit* left) {
  const double tol = kRelative * scale_with(scene, {s.a, s.b});
  // An answer that hits the sheet it just left again (at t near 0: its start a hair
  // behind, unsettled before step 7) is in doubt as before.
  const bool again = left && got.hit && got.triangle >= 0 && got.triangle == left->triangle;
  const SceneStatus all = statuses(s, scene, tol, rules, again ? nullptr : left);
  const std::string expected = describe_hits(s, scene, all);
  const Outcome decision = decide(got.hit, all.any.hit, all.any.in_doubt(), rules, scene_rule(s, scene, all, got));
  if (decision.verdict == Outcome::Verdict::fail) return fail(expected, describe_hit(got), decision.why);
  if (!got.hit || !all.any.hit) return decision;

  const bool on_plane = valid_plane(scene, got.plane), on_triangle = valid_triangle(scene, got.triangle);
  if (on_plane == on_triangle)
    return fail(expected, "plane " + std::to_string(got.plane) + ", triangle " + std::to_string(got.triangle),
                "a hit names exactly one surface: a plane index or a triangle index (the other -1)");
  Expect e(
      "the first hit is the surface met at the smallest t, at a + t (b - a), with that surface's unit normal toward a");
  double slack = 0;
  if (on_plane) {
    const Plane& p = scene.planes[std::size_t(got.plane)];
    const Status& st = all.planes[std::size_t(got.plane)];
    if (!st.hit && !st.unstable)
      return fail(expected, describe_hit(got), "plane " + std::to_string(got.plane) + ": " + plane_rule(s, p));
    check_plane_hit(e, s, p, got, tol);
    slack = plane_t_tolerance(s, p, tol);
  } else {
    const Triangle tri = scene.mesh.triangle(std::size_t(got.triangle));
    const Status& st = all.triangles[std::size_t(got.triangle)];
    if (!st.hit && !st.unstable)
      return fail(expected, describe_hit(got),
                  "triangle " + std::to_string(got.triangle) + ": " + triangle_rule(s, tri));
    check_triangle_hit(e, s, tri, got, tol);
    slack = triangle_t_tolerance(s, tri, tol);
  }
  // No stable hit may come clearly before it.
  for (std::size_t i = 0; i < all.planes.size(); ++i) {
    if (!all.planes[i].hit || all.planes[i].unstable) continue;
    const double t = oracle::plane_hit_t(s, scene.planes[i]);
    if (got.t > t + slack + plane_t_tolerance(s, scene.planes[i], tol))
      return fail(expected, describe_hit(got),
                  "the first hit is the one with the smallest t: plane " + std::to_string(i) +
                      " is hit at t = " + fmt(t) + ", before yours");
  }
  for (std::size_t i = 0; i < all.triangles.size(); ++i) {
    if (!all.triangles[i].hit || all.triangles[i].unstable) continue;
    const Triangle tri = scene.mesh.triangle(i);
    const double t = oracle::segment_triangle(s, tri).t;
    if (got.t > t + slack + triangle_t_tolerance(s, tri, tol))
      return fail(expected, describe_hit(got),
                  "the first hit is the one with the smallest t: triangle " + std::to_string(i) +
                      " is hit at t = " + fmt(t) + ", before yours");
  }
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

// The exact unit normal of the surface a hit names, facing where the hit's normal faces.
Vec3 exact_normal(const Scene& scene, const SurfaceHit& h) {
  if (valid_plane(scene, h.plane)) return scene.planes[std::size_t(h.plane)].normal.normalized();
  const Vec3 n = oracle::unit_normal(scene.mesh.triangle(std::size_t(h.triangle)));
  return h.normal.dot(n) < 0 ? Vec3(-n) : n;
}

// ---- Step 4 ----------------------------------------------------------------------------

Outcome hit_plane(const SegmentScene& in, const SurfaceHit& got, Rules rules) {
  const Segment& s = in.segment;
  const Plane& p = in.scene.planes.front();
  const double scale = scale_with(in.scene, {s.a, s.b}), tol = kRelative * scale;
  const bool expected = plane_hit_by_rule(s, p);
  const Outcome decision = decide(got.hit, expected, plane_unstable(s, p, scale, rules), rules, plane_rule(s, p));
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !expected) return decision;
  Expect e(
      "a plane is hit where the step crosses to its back: t = value(a) / (value(a) - value(b)), the point a + t (b - "
      "a), the normal n / |n|");
  check_plane_hit(e, s, p, got, tol);
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

Outcome hit_triangle(const SegmentTrianglePair& in, const SurfaceHit& got) {
  const double tol = kRelative * check::scale_of_input(in);
  const bool expected = sheet_hit(in);
  const Outcome decision = decide(got.hit, expected, triangle_unstable(in.segment, in.triangle, tol, Rules::random),
                                  Rules::random, triangle_rule(in.segment, in.triangle));
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !expected) return decision;
  Expect e(
      "a triangle is hit from either side where the step meets it: the point a + t (b - a), the unit normal turned "
      "toward a");
  check_triangle_hit(e, in.segment, in.triangle, got, tol);
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

Outcome first_hit(const SegmentScene& in, const SurfaceHit& got, Rules rules) {
  return first_hit_on(in.segment, in.scene, got, rules);
}

// ---- Doubt, for the generators -------------------------------------------------------

bool plane_in_doubt(const Plane& p, const Vec3& x, double scale) { return plane_value_in_doubt(p, x, scale); }
bool sheet_in_doubt(const Segment& s, const Triangle& tri, double tol) {
  return triangle_unstable(s, tri, tol, Rules::random);
}
double closing_band(const ImpulseCase& in) {
  return 2 * kRelative * (in.velocity.norm() + in.object_velocity.norm()) * (kRoot3 + 1);
}

}  // namespace labkit::lab07::judge
