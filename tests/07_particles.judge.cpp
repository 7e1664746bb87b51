#include "07_particles.judge.h"

#include "common/oracle/oracle.h"
#include "common/harness/segment_doubt.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace labkit::lab07 {

// ---- Text and replay tokens ----------------------------------------------------------

void encode(codec::Writer& w, const Forces& f) {
  codec::encode(w, f.gravity);
  w.unit(f.drag);
  w.unit(f.air_drag);
}
void decode(codec::Reader& r, Forces& f) {
  codec::decode(r, f.gravity);
  f.drag = r.real();
  f.air_drag = r.real();
}
void encode(codec::Writer& w, const Material& m) {
  w.unit(m.restitution);
  w.unit(m.friction);
}
void decode(codec::Reader& r, Material& m) {
  m.restitution = r.real();
  m.friction = r.real();
}
void encode(codec::Writer& w, const Scene& s) {
  w.count(s.planes.size());
  for (const Plane& p : s.planes) {
    for (int i = 0; i < 3; ++i) w.unit(p.normal[i]);
    w.real(p.offset);
  }
  codec::encode(w, s.mesh);
  encode(w, s.material);
  w.count(std::size_t(std::max(0, s.bounce_cap)));
  codec::encode(w, s.velocity);
}
void decode(codec::Reader& r, Scene& s) {
  s.planes.resize(r.count(64));
  for (Plane& p : s.planes) {
    codec::decode(r, p.normal);
    p.offset = r.real();
  }
  codec::decode(r, s.mesh);
  decode(r, s.material);
  s.bounce_cap = int(r.count(kMaxBounceCap));
  codec::decode(r, s.velocity);
}

std::string describe(const Forces& f) {
  return "gravity=" + fmt(f.gravity) + " drag=" + fmt(f.drag) + " air_drag=" + fmt(f.air_drag);
}
std::string describe(const Material& m) { return "e=" + fmt(m.restitution) + " mu=" + fmt(m.friction); }
std::string describe(const Scene& s) {
  std::string text = describe(s.material) + ", bounce cap " + std::to_string(s.bounce_cap) + ", " +
                     std::to_string(s.planes.size()) + (s.planes.size() == 1 ? " plane" : " planes");
  if (s.velocity != Vec3::Zero()) text += ", moving at u = " + fmt(s.velocity) + " (given where it ends the step)";
  for (std::size_t i = 0; i < s.planes.size(); ++i) text += "\n    plane " + std::to_string(i) + ": " + describe(s.planes[i]);
  if (s.mesh.size() > 0) text += "\n    mesh: " + describe(s.mesh);
  return text;
}
std::string describe(const Collision& c) {
  std::string text = "position " + fmt(c.position) + ", velocity " + fmt(c.velocity) + ", " +
                     std::to_string(c.bounces) + (c.bounces == 1 ? " bounce" : " bounces") + (c.stopped ? ", stopped" : "");
  const int shown = std::clamp(c.bounces + (c.stopped ? 1 : 0), 0, kMaxBounceCap + 1);
  for (int k = 0; k < shown; ++k) {
    const Bounce& b = c.trace[std::size_t(k)];
    text += "\n    " + std::string(k == c.bounces ? "stop" : "bounce " + std::to_string(k)) + ": " +
            (b.hit.plane >= 0 ? "plane " + std::to_string(b.hit.plane) : "triangle " + std::to_string(b.hit.triangle)) +
            " at t = " + fmt(b.hit.t) + ", point " + fmt(b.hit.point) + ", normal " + fmt(b.hit.normal) +
            ", velocity after " + fmt(b.velocity) + ", from " + fmt(b.from);
  }
  return text;
}

System system_of(const SystemCase& c) {
  System s;
  s.emitter = c.emitter;
  s.scene = c.scene;
  s.forces = c.forces;
  s.integrator = c.verlet ? Integrator::verlet : Integrator::euler;
  s.random = Random(std::uint64_t(c.seed));
  return s;
}

namespace judge {

namespace {

using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;

constexpr double kRelative = 1e-9;  // tol = 1e-9 S (the header's tolerances)
constexpr double kEnergy = 1e-12;   // the energy invariants' relative tolerance
const double kRoot3 = std::sqrt(3.0);

double largest(const Vec3& v) { return v.cwiseAbs().maxCoeff(); }

// S of a scene: its mesh vertices, and each plane's point nearest the origin.
double scene_scale(const Scene& scene) {
  double s = scale_of(scene.mesh);
  for (const Plane& p : scene.planes) {
    const double length = p.normal.norm();
    if (length > 0) s = std::max(s, std::abs(p.offset) / length);
  }
  return s;
}

double scale_with(const Scene& scene, std::initializer_list<Vec3> points) {
  return std::max({scene_scale(scene), scale_of(points), 1e-300});
}

using check::verdict;

// Keeps the first failure of a sequence of checks, with a prefix saying where it was.
Outcome within(const std::string& where, const Outcome& o) {
  if (o.verdict != Outcome::Verdict::fail) return o;
  return fail(o.expected, o.got, where + ": " + o.why);
}

bool finite(const Vec3& v) { return v.allFinite(); }

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
    return oracle::plane_side(p, s.a) < 0 ? "a is on the plane to within value(a)'s rounding bound (" + va +
                                                "), so it counts as on it, and b is behind it (" + vb + "): a hit at t = 0"
                                          : "the step starts on or in front of the plane (" + va + " >= 0) and ends behind it (" +
                                                vb + " < 0): a hit";
  if (oracle::plane_side(p, s.a) < 0)
    return "planes are one-sided: the step starts behind the plane (" + va + " < 0), which is no hit";
  return "the step ends on or in front of the plane (" + vb + " >= 0): on the plane is not behind it, and only a step "
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
  if (oracle::orientation(tri.v0, tri.v1, tri.v2, s.b) == side) return "the segment stays on one side of the triangle's plane: no hit";
  return "the segment crosses the triangle's plane outside the closed triangle: no hit";
}

// A yes/no verdict whose failure says the rule, not only that the answer differs.
Outcome decide(bool got, bool expected, bool doubt, Rules rules, const std::string& rule) {
  const Outcome o = verdict(got, expected, doubt, rules, "a hit", "no hit");
  return o.verdict == Outcome::Verdict::fail ? fail(o.expected, o.got, rule) : o;
}

// Could a perturbation of tol change whether the segment hits this sheet?
bool triangle_unstable(const Segment& s, const Triangle& tri, double tol, Rules rules) {
  return rules == Rules::random && check::segment_triangle_in_doubt(s, tri, tol, sheet_hit);
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
  e.that("finite", ok, "t = " + fmt(got.t) + ", point " + fmt(got.point) + ", normal " + fmt(got.normal), "finite numbers",
         "a hit's t, point and normal must be finite numbers (a NaN: 0 / 0 from a step that does not cross?)");
  return ok;
}

void check_plane_hit(Expect& e, const Segment& s, const Plane& p, const SurfaceHit& got, double tol) {
  if (!finite_hit(e, got)) return;
  e.that("point", oracle::within(got.point, p, tol), fmt(got.point), "a point of the plane",
         "the hit point must lie on the plane: yours is " + fmt(std::abs(oracle::plane_distance(p, got.point))) +
             " from it (tolerance " + fmt(tol) + ")");
  e.that("point on segment", oracle::within(got.point, s, tol), fmt(got.point), "a point of the segment",
         "the hit point must lie on the step a -> b: yours is " + fmt(oracle::distance(got.point, s)) + " from it (tolerance " +
             fmt(tol) + ")");
  e.that("t", oracle::parameter_reproduces(s, got.t, got.point, tol), fmt(got.t), "a + t (b - a) = point",
         "the point must be a + t (b - a) for your t: it is " + fmt((s.point(got.t) - got.point).norm()) + " away");
  const double exact_t = oracle::plane_hit_t(s, p), slack = plane_t_tolerance(s, p, tol);
  e.that("t exact", std::abs(got.t - exact_t) <= slack, fmt(got.t), fmt(exact_t),
         "t must be where value changes sign, value(a) / (value(a) - value(b)) = " + fmt(exact_t) + ": yours is off by " +
             fmt(std::abs(got.t - exact_t)) + " (tolerance " + fmt(slack) + ")");
  const Vec3 n = p.normal.normalized();
  const double length = got.normal.norm();
  e.that("normal", (got.normal - n).norm() <= kRelative, fmt(got.normal), fmt(n),
         std::abs(length - 1) > kRelative ? "the normal must be unit length, n / |n|: yours has length " + fmt(length)
         : got.normal.dot(n) < 0          ? "a plane's normal is its own direction, n / |n|, the side a particle comes from: yours points behind"
                                          : "a plane's normal is its own direction, made unit length: n / |n|");
}

void check_triangle_hit(Expect& e, const Segment& s, const Triangle& tri, const SurfaceHit& got, double tol) {
  if (!finite_hit(e, got)) return;
  e.that("point", oracle::within(got.point, tri, tol), fmt(got.point), "a point of the triangle",
         "the point is " + fmt(oracle::distance(got.point, tri)) + " from the triangle (tolerance " + fmt(tol) + ")");
  e.that("point on segment", oracle::within(got.point, s, tol), fmt(got.point), "a point of the segment",
         "the hit point must lie on the step a -> b: yours is " + fmt(oracle::distance(got.point, s)) + " from it (tolerance " +
             fmt(tol) + ")");
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

struct Status {
  bool hit = false;
  bool unstable = false;
};

struct SceneStatus {
  std::vector<Status> planes, triangles;
  bool any_stable_hit = false, any_hit = false, any_unstable = false;
};

// `left`: the hit the piece s starts from (collide), or none. A piece that starts strictly
// in front of the sheet it just bounced off and ends clearly in front of it does not hit
// it, whatever a perturbation of its start would do: its start is the answer's own point.
SceneStatus statuses(const Segment& s, const Scene& scene, double tol, Rules rules, const SurfaceHit* left = nullptr) {
  SceneStatus all;
  const double scale = tol / kRelative;
  for (const Plane& p : scene.planes) all.planes.push_back({plane_hit_by_rule(s, p), plane_unstable(s, p, scale, rules)});
  for (std::size_t i = 0; i < scene.mesh.size(); ++i) {
    const Triangle tri = scene.mesh.triangle(i);
    const int facing = left && left->triangle == int(i) && left->normal.dot(tri.normal()) < 0 ? -1 : 1;
    const bool leaving = left && left->triangle == int(i) && facing * oracle::orientation(tri.v0, tri.v1, tri.v2, s.a) > 0 &&
                         facing * oracle::triangle_plane_distance(tri, s.b) > 8 * tol;
    all.triangles.push_back({oracle::sheet_hit(s, tri), !leaving && triangle_unstable(s, tri, tol, rules)});
  }
  for (const auto* list : {&all.planes, &all.triangles})
    for (const Status& st : *list) {
      all.any_hit = all.any_hit || st.hit;
      all.any_stable_hit = all.any_stable_hit || (st.hit && !st.unstable);
      all.any_unstable = all.any_unstable || st.unstable;
    }
  return all;
}

std::string describe_hits(const Segment& s, const Scene& scene, const SceneStatus& all) {
  std::string text;
  for (std::size_t i = 0; i < all.planes.size(); ++i)
    if (all.planes[i].hit) text += (text.empty() ? "" : ", ") + ("plane " + std::to_string(i) + " at t = " + fmt(oracle::plane_hit_t(s, scene.planes[i])));
  for (std::size_t i = 0; i < all.triangles.size(); ++i)
    if (all.triangles[i].hit)
      text += (text.empty() ? "" : ", ") + ("triangle " + std::to_string(i) + " at t = " + fmt(oracle::segment_triangle(s, scene.mesh.triangle(i)).t));
  return text.empty() ? "no hit" : text;
}

std::string describe_hit(const SurfaceHit& h) {
  if (!h.hit) return "no hit";
  return (h.plane >= 0 ? "plane " + std::to_string(h.plane) : "triangle " + std::to_string(h.triangle)) + " at t = " + fmt(h.t);
}

bool valid_plane(const Scene& scene, int i) { return i >= 0 && std::size_t(i) < scene.planes.size(); }
bool valid_triangle(const Scene& scene, int i) { return i >= 0 && std::size_t(i) < scene.mesh.size(); }

// The rule that decides a scene's yes/no: that of a surface certainly hit, else of the
// surface the answer names.
std::string scene_rule(const Segment& s, const Scene& scene, const SceneStatus& all, const SurfaceHit& got) {
  for (std::size_t i = 0; i < all.planes.size(); ++i)
    if (all.planes[i].hit && !all.planes[i].unstable) return "plane " + std::to_string(i) + ": " + plane_rule(s, scene.planes[i]);
  for (std::size_t i = 0; i < all.triangles.size(); ++i)
    if (all.triangles[i].hit && !all.triangles[i].unstable)
      return "triangle " + std::to_string(i) + ": " + triangle_rule(s, scene.mesh.triangle(i));
  if (valid_plane(scene, got.plane)) return "plane " + std::to_string(got.plane) + ": " + plane_rule(s, scene.planes[std::size_t(got.plane)]);
  if (valid_triangle(scene, got.triangle))
    return "triangle " + std::to_string(got.triangle) + ": " + triangle_rule(s, scene.mesh.triangle(std::size_t(got.triangle)));
  return "the step hits no plane (it starts behind, or does not end behind, each) and meets no triangle";
}

// The first hit of a segment on a scene: lab 02's mesh verdict, with planes beside the triangles.
Outcome first_hit_on(const Segment& s, const Scene& scene, const SurfaceHit& got, Rules rules, const SurfaceHit* left = nullptr) {
  const double tol = kRelative * scale_with(scene, {s.a, s.b});
  // An answer that hits the sheet it just left again (at t near 0: its start a hair
  // behind, unsettled before step 7) is in doubt as before.
  const bool again = left && got.hit && got.triangle >= 0 && got.triangle == left->triangle;
  const SceneStatus all = statuses(s, scene, tol, rules, again ? nullptr : left);
  const std::string expected = describe_hits(s, scene, all);
  const Outcome decision =
      decide(got.hit, all.any_hit, !all.any_stable_hit && all.any_unstable, rules, scene_rule(s, scene, all, got));
  if (decision.verdict == Outcome::Verdict::fail) return fail(expected, describe_hit(got), decision.why);
  if (!got.hit || !all.any_hit) return decision;

  const bool on_plane = valid_plane(scene, got.plane), on_triangle = valid_triangle(scene, got.triangle);
  if (on_plane == on_triangle)
    return fail(expected, "plane " + std::to_string(got.plane) + ", triangle " + std::to_string(got.triangle),
                "a hit names exactly one surface: a plane index or a triangle index (the other -1)");
  Expect e;
  double slack = 0;
  if (on_plane) {
    const Plane& p = scene.planes[std::size_t(got.plane)];
    const Status& st = all.planes[std::size_t(got.plane)];
    if (!st.hit && !st.unstable) return fail(expected, describe_hit(got), "plane " + std::to_string(got.plane) + ": " + plane_rule(s, p));
    check_plane_hit(e, s, p, got, tol);
    slack = plane_t_tolerance(s, p, tol);
  } else {
    const Triangle tri = scene.mesh.triangle(std::size_t(got.triangle));
    const Status& st = all.triangles[std::size_t(got.triangle)];
    if (!st.hit && !st.unstable)
      return fail(expected, describe_hit(got), "triangle " + std::to_string(got.triangle) + ": " + triangle_rule(s, tri));
    check_triangle_hit(e, s, tri, got, tol);
    slack = triangle_t_tolerance(s, tri, tol);
  }
  // No stable hit may come clearly before it.
  for (std::size_t i = 0; i < all.planes.size(); ++i) {
    if (!all.planes[i].hit || all.planes[i].unstable) continue;
    const double t = oracle::plane_hit_t(s, scene.planes[i]);
    if (got.t > t + slack + plane_t_tolerance(s, scene.planes[i], tol))
      return fail(expected, describe_hit(got), "the first hit is the one with the smallest t: plane " + std::to_string(i) + " is hit at t = " + fmt(t) + ", before yours");
  }
  for (std::size_t i = 0; i < all.triangles.size(); ++i) {
    if (!all.triangles[i].hit || all.triangles[i].unstable) continue;
    const Triangle tri = scene.mesh.triangle(i);
    const double t = oracle::segment_triangle(s, tri).t;
    if (got.t > t + slack + triangle_t_tolerance(s, tri, tol))
      return fail(expected, describe_hit(got), "the first hit is the one with the smallest t: triangle " + std::to_string(i) + " is hit at t = " + fmt(t) + ", before yours");
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

}  // namespace

// ---- Step 1 ----------------------------------------------------------------------------

Outcome emit(const EmitCase& in, const std::vector<Particle>& first, const std::vector<Particle>& second) {
  const Emitter& em = in.emitter;
  const Vec3 axis = em.direction.normalized();
  const double tol = kRelative * std::max({largest(em.position), largest(em.half_extents), 1e-300});
  const double tol_v = kRelative * (em.speed + em.speed_spread);
  const double tol_l = kRelative * (std::abs(em.lifetime) + em.lifetime_spread);
  const double cos_cone = std::cos(std::min(em.cone, M_PI));
  bool varied = false;
  for (std::size_t i = 0; i < first.size(); ++i) {
    const Particle& p = first[i];
    const std::string which = "particle " + std::to_string(i) + ": ";
    const Vec3 off = (p.position - em.position).cwiseAbs() - em.half_extents;
    if (!finite(p.position) || off.maxCoeff() > tol)
      return fail("a position within position +- half_extents", fmt(p.position),
                  which + "its position is " + fmt(off.maxCoeff()) + " outside the emitter's box");
    const double speed = p.velocity.norm();
    if (!(speed >= em.speed - em.speed_spread - tol_v && speed <= em.speed + em.speed_spread + tol_v))
      return fail("a speed in [" + fmt(em.speed - em.speed_spread) + ", " + fmt(em.speed + em.speed_spread) + "]",
                  fmt(speed), which + "its speed is out of the emitter's range");
    if (speed > 0 && p.velocity.dot(axis) / speed < cos_cone - 1e-9)
      return fail("a direction within " + fmt(em.cone) + " rad of " + fmt(axis), fmt(p.velocity),
                  which + "its direction is " + fmt(std::acos(std::clamp(p.velocity.dot(axis) / speed, -1.0, 1.0))) +
                      " rad from the cone's axis");
    if (!(p.lifetime >= em.lifetime - em.lifetime_spread - tol_l && p.lifetime <= em.lifetime + em.lifetime_spread + tol_l))
      return fail("a lifetime in [" + fmt(em.lifetime - em.lifetime_spread) + ", " + fmt(em.lifetime + em.lifetime_spread) + "]",
                  fmt(p.lifetime), which + "its lifetime is out of the emitter's range");
    Expect e;
    e.equal("mass", p.mass, em.mass);
    e.equal("age", p.age, 0.0);
    e.equal("alive", p.alive, true);
    e.equal("previous", p.previous, p.position);
    e.equal("bounces", p.bounces, 0);
    const Outcome o = e.outcome();
    if (o.verdict == Outcome::Verdict::fail) return fail(o.expected, o.got, which + "a newborn particle: " + o.why);
    const Particle& q = second[i];
    if (q.position != p.position || q.velocity != p.velocity || q.lifetime != p.lifetime)
      return fail(describe(p), describe(q),
                  which + "emitted again from the same seed it came out different: draw only from `random`");
    if (i > 0 && (p.position != first[0].position || p.velocity != first[0].velocity || p.lifetime != first[0].lifetime))
      varied = true;
  }
  // A spread only shows when it moves something: the cone turns nothing at zero speed.
  const bool moving = em.speed != 0 || em.speed_spread > 0;
  const bool spread = em.half_extents != Vec3::Zero() || (em.cone > 0 && moving) || em.speed_spread > 0 ||
                      em.lifetime_spread > 0;
  if (spread && first.size() >= 4 && !varied)
    return fail("particles that differ (the emitter has spreads)", "identical particles", "every particle came out the same");
  return pass();
}

Outcome births(const BirthsCase& in, const std::vector<Births>& got) {
  long double due = in.emitter.owed, total = 0;
  for (std::size_t k = 0; k < got.size(); ++k) {
    due += (long double)in.emitter.rate * in.dt;
    total += got[k].count;
    const long double slack = 1e-9L * (due + 1);
    const std::string which = "step " + std::to_string(k) + ": ";
    if (got[k].count < 0) return fail("a count >= 0", describe(got[k].count), which + "a negative number of births");
    if (!(got[k].owed >= 0 && got[k].owed < 1))
      return fail("owed in [0, 1)", fmt(got[k].owed), which + "what is owed must be the fraction left over");
    if (total < std::floor(due - slack) || total > std::floor(due + slack))
      return fail(std::to_string((long long)std::floor(due)) + " births so far", std::to_string((long long)total),
                  which + "after " + std::to_string(k + 1) + " steps the births must be owed + rate * time = " +
                      fmt(double(due)) + ", rounded down");
    if (std::abs((long double)got[k].owed + total - due) > slack + 1e-15L * due)
      return fail("births + owed = " + fmt(double(due)), fmt(double(got[k].owed + total)),
                  which + "the births so far plus what is owed must add up to owed + rate * time");
  }
  return pass();
}

Outcome age(const AgeCase& in, const std::vector<Particle>& got) {
  std::vector<Particle> expected;
  for (Particle p : in.particles) {
    p.age += in.dt;
    p.alive = p.age < p.lifetime;
    if (p.alive) expected.push_back(p);
  }
  std::string want, have;
  for (const Particle& p : expected) want += (want.empty() ? "" : ", ") + fmt(p.age) + "/" + fmt(p.lifetime);
  for (const Particle& p : got) have += (have.empty() ? "" : ", ") + fmt(p.age) + "/" + fmt(p.lifetime);
  want = "ages/lifetimes [" + want + "]";
  have = "ages/lifetimes [" + have + "]";
  if (got.size() != expected.size())
    return fail(want, have, std::to_string(expected.size()) + " particles survive (a new age >= the lifetime dies), not " +
                                std::to_string(got.size()));
  for (std::size_t i = 0; i < got.size(); ++i) {
    const Particle &g = got[i], &x = expected[i];
    if (g.position != x.position || g.velocity != x.velocity || g.lifetime != x.lifetime)
      return fail(want, have, "survivor " + std::to_string(i) + " is not the one expected there: keep their order");
    if (g.age != x.age) return fail(want, have, "survivor " + std::to_string(i) + "'s age must be age + dt = " + fmt(x.age));
    if (!g.alive) return fail(want, have, "survivor " + std::to_string(i) + " says alive = false");
  }
  return pass();
}

// ---- Step 2 ----------------------------------------------------------------------------

namespace {

oracle::Forces exact_forces(const Forces& f) { return {f.gravity, f.drag, f.air_drag}; }
oracle::State state_of(const Particle& p) { return {p.position, p.velocity, p.previous}; }

// The size of the acceleration's terms, for tolerances: |g| + (k1 |v| + k2 |v|^2) / m.
double acceleration_size(const MotionCase& in) {
  const double v = in.particle.velocity.norm();
  return largest(in.forces.gravity) + (std::abs(in.forces.drag) * v + std::abs(in.forces.air_drag) * v * v) / in.particle.mass;
}

Outcome compare_particle(const MotionCase& in, const oracle::State& exact, const Particle& got, double tol_p, double tol_v) {
  Expect e;
  e.near("position", got.position, exact.position, tol_p);
  e.near("velocity", got.velocity, exact.velocity, tol_v);
  e.near("previous", got.previous, exact.previous, tol_p);
  e.equal("mass", got.mass, in.particle.mass);
  e.equal("age", got.age, in.particle.age);
  e.equal("lifetime", got.lifetime, in.particle.lifetime);
  e.equal("alive", got.alive, in.particle.alive);
  return e.outcome();
}

double position_tolerance(const MotionCase& in) {
  const Particle& p = in.particle;
  return kRelative * (largest(p.position) + largest(p.previous) + in.dt * largest(p.velocity) +
                      in.dt * in.dt * acceleration_size(in) + 1e-300);
}

}  // namespace

Outcome force(const MotionCase& in, const Vec3& got) {
  const Vec3 exact = oracle::force(in.particle.velocity, in.particle.mass, exact_forces(in.forces));
  Expect e;
  e.near("force", got, exact, kRelative * in.particle.mass * acceleration_size(in) + 1e-300);
  return e.outcome();
}

Outcome euler_step(const MotionCase& in, const Particle& got) {
  const oracle::State exact = oracle::euler_step(state_of(in.particle), in.particle.mass, exact_forces(in.forces), in.dt);
  const double tol_v = kRelative * (largest(in.particle.velocity) + in.dt * acceleration_size(in) + 1e-300);
  return compare_particle(in, exact, got, position_tolerance(in), tol_v);
}

Outcome start_verlet(const MotionCase& in, const Particle& got) {
  const oracle::State exact = oracle::start_verlet(state_of(in.particle), in.particle.mass, exact_forces(in.forces), in.dt);
  return compare_particle(in, exact, got, position_tolerance(in), kRelative * largest(in.particle.velocity) + 1e-300);
}

Outcome verlet_step(const MotionCase& in, const Particle& got) {
  const oracle::State exact = oracle::verlet_step(state_of(in.particle), in.particle.mass, exact_forces(in.forces), in.dt);
  const double tol_p = position_tolerance(in);
  return compare_particle(in, exact, got, tol_p, tol_p / in.dt);
}

// ---- Step 3 ----------------------------------------------------------------------------

namespace {

// Could moving from and target by 1e-9 S, and speed and gravity by 1e-9 of themselves,
// change the sign of D = v^4 + 2 v^2 (d . g) - |d x g|^2, or move the target off (or
// onto) the vertical? Each term's change is bounded by its size times its relative
// change; twice the sum is the doubt.
bool launch_in_doubt(const LaunchCase& in) {
  const double eps = kRelative;
  const double S = std::max({largest(in.from), largest(in.target), 1e-300});
  const Vec3 d = in.target - in.from;
  const double dd = 2 * kRoot3 * eps * S;  // how far d may move
  const double v2 = in.speed * in.speed, g = in.gravity.norm(), dn = d.norm();
  const double cross = d.cross(in.gravity).norm();
  const double dg = std::abs(d.dot(in.gravity));
  const double change = 4.01 * eps * v2 * v2 + 2 * v2 * (2.01 * eps * dg + dd * g + dn * kRoot3 * eps * g) +
                        2 * cross * (dd * g + dn * kRoot3 * eps * g) + (dd * g + dn * kRoot3 * eps * g) * (dd * g + dn * kRoot3 * eps * g);
  const double D = oracle::launch_discriminant(in.from, in.target, in.speed, in.gravity);
  return std::abs(D) <= 2 * change || cross <= 4 * (dd * g + dn * kRoot3 * eps * g);
}

int expected_count(const LaunchCase& in) {
  if (in.speed == 0 || oracle::launch_vertical(in.from, in.target, in.gravity)) return 0;
  const int sign = oracle::launch_sign(in.from, in.target, in.speed, in.gravity);
  return sign > 0 ? 2 : (sign == 0 ? 1 : 0);
}

// A shot must have the speed, leave at its angle, and be at the target at its time.
void check_shot(Expect& e, const std::string& name, const LaunchCase& in, const Shot& s, double tol) {
  const Vec3 up = -in.gravity.normalized();
  e.that(name + ".velocity", std::abs(s.velocity.norm() - in.speed) <= kRelative * in.speed, fmt(s.velocity),
         "a velocity of length " + fmt(in.speed), "its length is " + fmt(s.velocity.norm()));
  e.that(name + ".angle", in.speed > 0 && std::abs(std::sin(s.angle) - s.velocity.dot(up) / in.speed) <= 1e-9, fmt(s.angle),
         "the elevation of the velocity", "sin(angle) does not match the velocity's upward part over the speed");
  e.that(name + ".time", s.time > 0 && oracle::trajectory_reaches(in.from, s.velocity, s.time, in.gravity, in.target, tol),
         fmt(s.time), "from + velocity t + g t^2 / 2 = target",
         "at t = " + fmt(s.time) + " the shot is at " +
             fmt(Vec3(in.from + s.velocity * s.time + 0.5 * s.time * s.time * in.gravity)) + ", not at the target (tolerance " +
             fmt(tol) + ")");
}

// The exact angles, and how far a relative perturbation of 1e-9 of the input moves them.
// Computed in long double (64-bit significands), each root in a form without
// cancellation: the high root adds sqrt(D) to v^2; the low root is the product of the
// roots, (g x^2 + 2 y v^2) / (g x^2), divided by the high one. Their errors, near 1e-19
// relative, are far below the tolerance.
//   To first order, with P(u) = g x u^2 - 2 v^2 u + g x + 2 y v^2 / x = 0 (the lecture's
//   quadratic times 2 v^2 / x) and P'(u) = 2 (g x u - v^2) = -+2 sqrt(D) at the roots:
//   |du| <= ((1 + u^2) |d(g x)| + 2 |u| |d(v^2)| + |d(2 y v^2 / x)|) / (2 sqrt(D)), and the
//   angle moves by du / (1 + u^2).
struct Angles {
  double low = 0, high = 0, low_tol = 0, high_tol = 0, fast = 0;  // fast: g x / v^2
};
Angles exact_angles(const LaunchCase& in, int count) {
  using Real = long double;
  const Vec3 d = in.target - in.from;
  const Real gx = in.gravity.x(), gy = in.gravity.y(), gz = in.gravity.z();
  const Real dx = d.x(), dy = d.y(), dz = d.z();
  const Real g = std::sqrt(gx * gx + gy * gy + gz * gz), v2 = Real(in.speed) * in.speed;
  const Real cx = dy * gz - dz * gy, cy = dz * gx - dx * gz, cz = dx * gy - dy * gx;
  const Real x = std::sqrt(cx * cx + cy * cy + cz * cz) / g, y = -(dx * gx + dy * gy + dz * gz) / g;
  const Real D = count == 1 ? 0 : std::max(Real(0), v2 * v2 - 2 * g * y * v2 - g * g * x * x), root = std::sqrt(D);
  const Real high = (v2 + root) / (g * x), low = (g * x * x + 2 * y * v2) / (x * (v2 + root));
  const Real eps = kRelative, S = std::max({largest(in.from), largest(in.target), 1e-300});
  const Real moved = 2 * kRoot3 * eps * S + kRoot3 * eps * std::sqrt(dx * dx + dy * dy + dz * dz);  // of x and y
  const Real d_gx = g * moved + kRoot3 * eps * g * x, d_v2 = 2 * eps * v2;
  const Real d_y_term = 2 * v2 * (moved / x + std::abs(y) * moved / (x * x) + 2 * eps * std::abs(y) / x);
  const auto tolerance = [&](Real u) {
    if (root == 0) return Real(1e-9) * std::abs(u);  // D = 0 exactly: one root, v^2 / (g x)
    return 2 * ((1 + u * u) * d_gx + 2 * std::abs(u) * d_v2 + d_y_term) / (2 * root) / (1 + u * u);
  };
  return {double(std::atan(low)), double(std::atan(high)), double(tolerance(low) + 1e-15), double(tolerance(high) + 1e-15),
          double(g * x / v2)};
}

void check_angles(Expect& e, const LaunchCase& in, const Aim& got, int count) {
  const Angles exact = exact_angles(in, count);
  const double low_off = std::abs(got.low.angle - exact.low), high_off = std::abs(got.high.angle - exact.high);
  const bool swapped = std::abs(got.low.angle - exact.high) <= exact.high_tol;
  std::string why = "low.angle must be the low root, atan((v^2 - sqrt(D)) / (g x)) = " + fmt(exact.low) + ": yours is off by " +
                    fmt(low_off) + " (tolerance " + fmt(exact.low_tol) + ")";
  if (swapped && count == 2) why += "; yours is the high root, the lobbed shot";
  else if (exact.fast < 1e-4)
    why += ". Here g x / v^2 = " + fmt(exact.fast) + ": v^2 - sqrt(D) cancels (subtracts two nearly equal numbers) and "
           "loses the low root's digits; take the product of the roots, (g x^2 + 2 y v^2) / (g x^2), divided by the high root";
  e.that("low.angle", low_off <= exact.low_tol, fmt(got.low.angle), fmt(exact.low), why);
  e.that("high.angle", high_off <= exact.high_tol, fmt(got.high.angle), fmt(exact.high),
         "high.angle must be the high root, atan((v^2 + sqrt(D)) / (g x)) = " + fmt(exact.high) + ": yours is off by " +
             fmt(high_off) + " (tolerance " + fmt(exact.high_tol) + ")" +
             (count == 1 ? "; with D = 0 there is one angle and high = low" : ""));
}

}  // namespace

Outcome aim(const LaunchCase& in, const Aim& got, Rules rules) {
  const int expected = expected_count(in);
  const bool doubt = rules == Rules::random && launch_in_doubt(in);
  if (got.count != expected) {
    if (doubt) return ambiguous();
    return fail("count = " + std::to_string(expected), "count = " + std::to_string(got.count),
                expected == 0 ? "the target is out of reach (D < 0), or straight above or below"
                              : (expected == 1 ? "D = 0 exactly: the target is just in reach, by one angle"
                                               : "D > 0: two angles reach the target"));
  }
  const Vec3 d = in.target - in.from;
  const double g = in.gravity.norm();
  Expect e;
  const bool vertical = in.speed == 0 || oracle::launch_vertical(in.from, in.target, in.gravity);
  const double radicand = oracle::launch_radicand(in.from, in.target, in.speed, in.gravity);
  if (!std::isfinite(got.radicand) || !std::isfinite(got.low.angle) || !std::isfinite(got.high.angle) || !finite(got.low.velocity) ||
      !finite(got.high.velocity) || !std::isfinite(got.low.time) || !std::isfinite(got.high.time))
    return fail("finite numbers", "radicand " + fmt(got.radicand) + ", angles " + fmt(got.low.angle) + ", " + fmt(got.high.angle),
                "an aim's radicand, angles, velocities and times must be finite numbers");
  if (vertical) {
    e.equal("radicand", got.radicand, 0.0);
  } else {
    const double x2 = d.cross(in.gravity).squaredNorm() / (g * g), y = -d.dot(in.gravity) / g;
    const double A = g * x2 / (2 * in.speed * in.speed);
    e.near("radicand", got.radicand, radicand, kRelative * (x2 + 4 * A * (A + std::abs(y))));
  }
  if (expected >= 1 && g > 0) {
    const double S = std::max({largest(in.from), largest(in.target), in.speed * in.speed / g});
    const double tol = kRelative * S;
    check_shot(e, "low", in, got.low, tol);
    check_shot(e, "high", in, got.high, tol);
    e.that("order", got.low.angle <= got.high.angle + 1e-12, fmt(got.low.angle) + " <= " + fmt(got.high.angle),
           "low.angle <= high.angle", "the low shot must have the lower angle");
    check_angles(e, in, got, expected);
  }
  const Outcome o = e.outcome();
  if (o.verdict == Outcome::Verdict::fail) return doubt && expected == 1 ? ambiguous() : o;
  return doubt ? ambiguous() : pass();
}

// ---- Step 4 ----------------------------------------------------------------------------

Outcome hit_plane(const SegmentScene& in, const SurfaceHit& got, Rules rules) {
  const Segment& s = in.segment;
  const Plane& p = in.scene.planes.front();
  const double scale = scale_with(in.scene, {s.a, s.b}), tol = kRelative * scale;
  const bool expected = plane_hit_by_rule(s, p);
  const Outcome decision = decide(got.hit, expected, plane_unstable(s, p, scale, rules), rules, plane_rule(s, p));
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !expected) return decision;
  Expect e;
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
  Expect e;
  check_triangle_hit(e, in.segment, in.triangle, got, tol);
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

Outcome first_hit(const SegmentScene& in, const SurfaceHit& got, Rules rules) {
  return first_hit_on(in.segment, in.scene, got, rules);
}

// ---- Step 5 ----------------------------------------------------------------------------

Outcome impulse(const ImpulseCase& in, const Impulse& got) {
  const double e_ = in.material.restitution, mu = in.material.friction;
  const oracle::Impulse exact = oracle::impulse(in.velocity, in.object_velocity, in.normal, in.mass, e_, mu);
  const double V = in.velocity.norm() + in.object_velocity.norm();
  const double tol_v = kRelative * V * (2 + e_ + mu * (1 + e_)) + 1e-300;
  // v_close's sign is in doubt when moving every velocity by 1e-9 V, and the normal by
  // 1e-9, could flip it.
  const bool doubt = std::abs(exact.v_close) <= closing_band(in);
  Expect e;
  if (got.closing != exact.closing && !doubt)
    return fail("closing = " + describe(exact.closing), "closing = " + describe(got.closing),
                "v_close = (v - v_obj) . n = " + fmt(exact.v_close) + ": the particle is " +
                    (exact.closing ? "closing (v_close < 0)" : "not closing (v_close >= 0)"));
  e.near("v_close", got.v_close, exact.v_close, tol_v);
  e.near("normal_impulse", got.normal_impulse, exact.normal_impulse, in.mass * tol_v);
  e.near("friction", got.friction, exact.friction, in.mass * tol_v);
  e.near("velocity", got.velocity, exact.velocity, tol_v);
  const Outcome o = e.outcome();
  if (o.verdict == Outcome::Verdict::fail) return o;
  return doubt ? ambiguous() : pass();
}

// ---- Step 6 ----------------------------------------------------------------------------

Outcome collide(const CollideCase& in, const Collision& got) {
  const Scene& scene = in.scene;
  const int cap = std::clamp(scene.bounce_cap, 0, kMaxBounceCap);
  const std::string answer = describe(got);
  if (got.bounces < 0 || got.bounces > cap)
    return fail("between 0 and " + std::to_string(cap) + " bounces", answer,
                "the bounce cap is " + std::to_string(cap) + ": at most that many impulses, then the next hit stops the particle");
  if (got.stopped && got.bounces != cap)
    return fail("no stop before the cap", answer,
                "the bounce cap: a particle stops only when it hits again after " + std::to_string(cap) + " bounces");
  if (!finite(got.position) || !finite(got.velocity)) return fail("a finite position and velocity", answer, "not finite");

  const double e_ = scene.material.restitution, mu = scene.material.friction;
  // A moving scene (u != 0): the loop runs in its frame, from the relative step a' -> b.
  const Vec3 u = scene.velocity;
  const bool moving = u != Vec3::Zero();
  const double tol_v = kRelative * (in.velocity.norm() + u.norm()) * (2 + e_ + mu * (1 + e_)) + 1e-300;
  Segment piece = {in.step.a + u * in.dt, in.step.b};
  Vec3 v = in.velocity;
  double remaining = in.dt;
  bool doubt = false;
  for (int k = 0;; ++k) {
    const std::string where =
        k == 0 ? (moving ? "the relative step a' -> b, a' = a + u dt = " + fmt(piece.a) +
                               " (the surfaces move at u and are given where they end the step: seen from them, the "
                               "particle starts at a + u dt)"
                         : std::string("the step a -> b"))
               : "the piece after bounce " + std::to_string(k - 1) +
                     (moving ? " (from -> from + (v' - u) r: the particle moves relative to the moving surfaces)" : "");
    const SurfaceHit* left = k == 0 ? nullptr : &got.trace[std::size_t(k - 1)].hit;
    const double tol = kRelative * scale_with(scene, {piece.a, piece.b, in.step.a, in.step.b});
    if (k == got.bounces && !got.stopped) {  // the last piece: clear to its end
      const Outcome o = within(where, first_hit_on(piece, scene, SurfaceHit{}, Rules::random, left));
      if (o.verdict == Outcome::Verdict::fail)
        return fail(o.expected, answer, o.why + " (a hit there is another bounce, or the stop when the cap is used up)");
      doubt = doubt || o.verdict == Outcome::Verdict::ambiguous;
      Expect e;
      e.that("position", (got.position - piece.b).norm() <= tol, fmt(got.position), fmt(piece.b),
             "the particle must end where " + where + " ends, " + fmt(piece.b) +
                 ": after each hit it moves on from the hit point for the remaining time (1 - t) r only (tolerance " + fmt(tol) + ")");
      e.near("velocity", got.velocity, v, tol_v);
      const Outcome end = e.outcome();
      if (end.verdict == Outcome::Verdict::fail) return end;
      break;
    }
    const Bounce& b = got.trace[std::size_t(k)];
    const Outcome o = within(where, first_hit_on(piece, scene, b.hit, Rules::random, left));
    if (o.verdict == Outcome::Verdict::fail) return fail(o.expected, answer, o.why);
    doubt = doubt || o.verdict == Outcome::Verdict::ambiguous;
    if (!b.hit.hit) return fail("a hit", answer, where + ": the trace records no hit");
    if (!finite(b.from) || !finite(b.velocity))
      return fail("a finite `from` and velocity", answer, "bounce " + std::to_string(k) + ": not finite");
    if ((b.from - b.hit.point).norm() > tol)
      return fail(fmt(b.hit.point), fmt(b.from), "bounce " + std::to_string(k) + ": `from` must be the hit point (settled by at most tol)");
    if (k == got.bounces) {  // the stop
      Expect e;
      e.that("position", (got.position - b.from).norm() <= tol, fmt(got.position), fmt(b.from),
             "a stopped particle stays at its stopping hit's `from`");
      e.that("velocity", (got.velocity - u).norm() <= tol_v, fmt(got.velocity), fmt(u),
             "a stopped particle is at rest on the surface: velocity zero, or the moving scene's u");
      return e.outcome().verdict == Outcome::Verdict::fail ? e.outcome() : (doubt ? ambiguous() : pass());
    }
    const oracle::Impulse exact = oracle::impulse(v, u, exact_normal(scene, b.hit), in.mass,
                                                  scene.material.restitution, scene.material.friction);
    if ((b.velocity - exact.velocity).norm() > tol_v)
      return fail(fmt(exact.velocity), fmt(b.velocity),
                  "bounce " + std::to_string(k) + ": the velocity after the impulse (e = " + fmt(scene.material.restitution) +
                      ", mu = " + fmt(scene.material.friction) + ") on " + fmt(v) +
                      (moving ? ", against surfaces moving at u = " + fmt(u) +
                                    ": the impulse takes the relative velocity v - u, impulse(v, u, n, ...)"
                              : std::string()));
    remaining *= 1 - b.hit.t;
    v = b.velocity;
    piece = {b.from, b.from + (v - u) * remaining};
  }
  return doubt ? ambiguous() : pass();
}

// ---- Step 7 ----------------------------------------------------------------------------

Outcome invariants(const CollideCase& in, const Collision& got) {
  const Scene& scene = in.scene;
  const std::string answer = describe(got);
  const int used = std::clamp(got.bounces + (got.stopped ? 1 : 0), 0, kMaxBounceCap + 1);
  if (!finite(got.position) || !finite(got.velocity)) return fail("a finite position and velocity", answer, "not finite");
  for (int k = 0; k < used; ++k)
    if (!finite(got.trace[std::size_t(k)].from))
      return fail("a finite `from`", answer, "bounce " + std::to_string(k) + "'s `from` is not finite");
  // (1) Never behind a plane the step began in front of (in the scene's frame: a' = a + u dt).
  const Vec3 u = scene.velocity;
  const Vec3 start = in.step.a + u * in.dt;
  for (std::size_t i = 0; i < scene.planes.size(); ++i) {
    const Plane& p = scene.planes[i];
    if (oracle::plane_side(p, start) < 0) continue;
    if (oracle::plane_side(p, got.position) < 0)
      return fail("a position not behind plane " + std::to_string(i), answer,
                  "the particle ends behind plane " + std::to_string(i) + ", by " +
                      fmt(-oracle::plane_distance(p, got.position)) + " (exactly: its n . x + c < 0)");
  }
  // Each `from`, strictly in front of the surface just hit; the end, not behind the last.
  const auto side_of = [&](const SurfaceHit& h, const Vec3& x) {
    if (valid_plane(scene, h.plane)) return oracle::plane_side(scene.planes[std::size_t(h.plane)], x);
    const Triangle tri = scene.mesh.triangle(std::size_t(h.triangle));
    const int facing = h.normal.dot(tri.normal()) < 0 ? -1 : 1;
    return facing * oracle::orientation(tri.v0, tri.v1, tri.v2, x);
  };
  for (int k = 0; k < used; ++k) {
    const Bounce& b = got.trace[std::size_t(k)];
    if (!b.hit.hit || valid_plane(scene, b.hit.plane) == valid_triangle(scene, b.hit.triangle))
      return fail("a hit on one surface", answer, "bounce " + std::to_string(k) + " names no valid surface");
    if (side_of(b.hit, b.from) <= 0)
      return fail("`from` strictly in front of the surface hit", answer,
                  "every `from` must be strictly in front of the surface it bounced off, exactly: bounce " + std::to_string(k) +
                      "'s " + fmt(b.from) + " is on or behind it (a rounded hit point: settle it)");
  }
  if (used > 0 && side_of(got.trace[std::size_t(used - 1)].hit, got.position) < 0)
    return fail("an end not behind the last surface hit", answer,
                "the particle ends behind the last surface it hit, seen from the side it came from (exactly)");
  // (3) and (4): energy.
  const double e = scene.material.restitution, mu = scene.material.friction;
  if (u == Vec3::Zero()) {
    if (e <= 1 && !oracle::squared_speed_at_most(got.velocity, in.velocity, 1 + kEnergy))
      return fail("|v_end|^2 <= (1 + 1e-12) |v|^2 = " + fmt(in.velocity.squaredNorm()), fmt(got.velocity.squaredNorm()),
                  "with e <= 1 against still surfaces, a bounce never adds energy");
    if (e == 1 && mu == 0 && !got.stopped && !oracle::squared_speed_at_least(got.velocity, in.velocity, 1 - kEnergy))
      return fail("|v_end|^2 = |v|^2 = " + fmt(in.velocity.squaredNorm()), fmt(got.velocity.squaredNorm()),
                  "with e = 1 and mu = 0 a bounce keeps the speed (within 1e-12)");
    return pass();
  }
  // A moving scene: the same, relative to it; v - u itself rounds, by about 1e-16 |u|.
  const double before = (in.velocity - u).squaredNorm(), after = (got.velocity - u).squaredNorm();
  const double slack = kEnergy * (before + std::sqrt(before) * u.norm());
  if (e <= 1 && after > before + slack)
    return fail("|v_end - u|^2 <= (1 + 1e-12) |v - u|^2 = " + fmt(before), fmt(after),
                "with e <= 1, a bounce never adds energy relative to the moving surfaces (u = " + fmt(u) + ")");
  if (e == 1 && mu == 0 && !got.stopped && after < before - slack)
    return fail("|v_end - u|^2 = |v - u|^2 = " + fmt(before), fmt(after),
                "with e = 1 and mu = 0 a bounce keeps the speed relative to the moving surfaces (u = " + fmt(u) + ")");
  return pass();
}

Outcome settle(const SettleCase& in, const Vec3& got) {
  const Scene& scene = in.scene;
  const double tol = kRelative * scale_with(scene, {in.x});
  if (!finite(got) || (got - in.x).norm() > tol)
    return fail("a point within " + fmt(tol) + " of x", fmt(got), "settle moved x by " + fmt((got - in.x).norm()));
  for (std::size_t i = 0; i < scene.planes.size(); ++i) {
    const Plane& p = scene.planes[i];
    const bool strict = in.last.hit && in.last.plane == int(i);
    // Clearly behind from the start (more than 1000 rounding errors): not settle's business.
    const Vec3 terms = p.normal.cwiseProduct(in.x);
    const double value = terms.x() + terms.y() + terms.z() + p.offset;
    if (!strict && (p.normal == Vec3::Zero() || value < -1000 * 1e-15 * (terms.cwiseAbs().sum() + std::abs(p.offset)))) continue;
    const int side = oracle::plane_side(p, got);
    if (strict ? side <= 0 : side < 0)
      return fail(strict ? "strictly in front of plane " + std::to_string(i) + " (the one just hit)"
                         : "not behind plane " + std::to_string(i),
                  fmt(got), "exactly, n . x + c is " + std::string(side < 0 ? "negative" : "zero") + " there");
  }
  if (in.last.hit && valid_triangle(scene, in.last.triangle)) {
    const Triangle tri = scene.mesh.triangle(std::size_t(in.last.triangle));
    const int facing = in.last.normal.dot(tri.normal()) < 0 ? -1 : 1;
    if (facing * oracle::orientation(tri.v0, tri.v1, tri.v2, got) <= 0)
      return fail("strictly in front of triangle " + std::to_string(in.last.triangle) + ", on last.normal's side", fmt(got),
                  "exactly, the point is on or behind the triangle's plane");
  }
  return pass();
}

Outcome system_step(const SystemCase& in, const System& after, int step) {
  const std::string which = "after step " + std::to_string(step + 1) + ", ";
  if (std::abs(after.time - (step + 1) * in.dt) > 1e-9 * (step + 1) * in.dt)
    return fail(fmt((step + 1) * in.dt), fmt(after.time), which + "time must have grown by dt each step");
  // With no particle old enough to die yet, the count is the births so far.
  const Emitter& em = in.emitter;
  if (em.lifetime - em.lifetime_spread > (step + 1) * in.dt) {
    const long double due = em.owed + (long double)em.rate * in.dt * (step + 1), slack = 1e-9L * (due + 1);
    const auto count = (long double)after.particles.size();
    if (count < std::floor(due - slack) || count > std::floor(due + slack))
      return fail(std::to_string((long long)std::floor(due)) + " particles (the births so far)",
                  std::to_string(after.particles.size()), which + "none can have died yet");
  }
  for (std::size_t i = 0; i < after.particles.size(); ++i) {
    const Particle& p = after.particles[i];
    const std::string who = which + "particle " + std::to_string(i);
    if (!finite(p.position) || !finite(p.velocity)) return fail("finite", describe(p), who + " is not finite");
    if (!p.alive || !(p.age < p.lifetime))
      return fail("alive, age < lifetime", "alive = " + describe(p.alive) + ", age " + fmt(p.age) + ", lifetime " + fmt(p.lifetime),
                  who + ": the dead are removed at the end of the step");
    for (std::size_t k = 0; k < in.scene.planes.size(); ++k)
      if (oracle::plane_side(in.scene.planes[k], p.position) < 0)
        return fail("not behind plane " + std::to_string(k), fmt(p.position),
                    who + " is behind plane " + std::to_string(k) + " by " +
                        fmt(-oracle::plane_distance(in.scene.planes[k], p.position)) + " (exactly)");
  }
  return pass();
}

// ---- Doubt, for the generators -------------------------------------------------------

bool plane_in_doubt(const Plane& p, const Vec3& x, double scale) { return plane_value_in_doubt(p, x, scale); }
bool sheet_in_doubt(const Segment& s, const Triangle& tri, double tol) { return triangle_unstable(s, tri, tol, Rules::random); }
double closing_band(const ImpulseCase& in) {
  return 2 * kRelative * (in.velocity.norm() + in.object_velocity.norm()) * (kRoot3 + 1);
}

}  // namespace judge
}  // namespace labkit::lab07
