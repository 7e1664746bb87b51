#include "common/oracle/particles.h"
#include "common/oracle/kernel.h"
#include "common/oracle/predicates.h"
#include "common/oracle/segment_triangle.h"

#include <cmath>

namespace oracle {

using namespace kernel;

namespace {

// Exact vectors, as three exact numbers.
struct V3 {
  FT x, y, z;
};
V3 exact_vector(const Vec3& v) { return {ft(v.x()), ft(v.y()), ft(v.z())}; }
V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(const FT& k, const V3& a) { return {k * a.x, k * a.y, k * a.z}; }
FT dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(const V3& a, const V3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3 rounded(const V3& a) { return {kernel::rounded(a.x), kernel::rounded(a.y), kernel::rounded(a.z)}; }

// A length: the exact square, rounded, rooted in double (relative error about 1e-16).
FT length(const V3& a) { return ft(std::sqrt(kernel::rounded(dot(a, a)))); }

FT value(const Plane& p, const Vec3& x) { return dot(exact_vector(p.normal), exact_vector(x)) + ft(p.offset); }

}  // namespace

bool plane_hit(const Segment& s, const Plane& p) {
  if (p.normal == Vec3::Zero()) return false;
  return plane_side(p, s.a) >= 0 && plane_side(p, s.b) < 0;
}

double plane_hit_t(const Segment& s, const Plane& p) {
  const FT va = value(p, s.a), vb = value(p, s.b);
  if (va == vb) return 0.0;
  return kernel::rounded(va / (va - vb));
}

double plane_distance(const Plane& p, const Vec3& x) {
  const V3 n = exact_vector(p.normal);
  const FT n2 = dot(n, n);
  if (n2 == 0) return 0.0;
  const FT v = value(p, x);
  return sign_of(CGAL::sign(v)) * std::sqrt(kernel::rounded(v * v / n2));
}

int plane_side(const Plane& p, const Vec3& x) {
  if (p.normal == Vec3::Zero()) return p.offset > 0 ? 1 : (p.offset < 0 ? -1 : 0);
  const Epick::Plane_3 plane(p.normal.x(), p.normal.y(), p.normal.z(), p.offset);
  const CGAL::Oriented_side s = plane.oriented_side(fast(x));
  return s == CGAL::ON_POSITIVE_SIDE ? 1 : (s == CGAL::ON_NEGATIVE_SIDE ? -1 : 0);
}

double triangle_plane_distance(const Triangle& t, const Vec3& x) {
  const V3 v0 = exact_vector(t.v0);
  const V3 n = cross(exact_vector(t.v1) - v0, exact_vector(t.v2) - v0);
  const FT n2 = dot(n, n);
  if (n2 == 0) return 0.0;
  const FT v = dot(exact_vector(x) - v0, n);
  return sign_of(CGAL::sign(v)) * std::sqrt(kernel::rounded(v * v / n2));
}

bool sheet_hit(const Segment& s, const Triangle& t) {
  if (is_degenerate(t)) return false;
  if (orientation(t.v0, t.v1, t.v2, s.a) == 0) return false;  // starts on the plane: leaving
  return segment_hits_triangle(s, t);
}

Impulse impulse(const Vec3& velocity, const Vec3& object_velocity, const Vec3& normal, double mass, double e,
                double mu) {
  Impulse r;
  const V3 v = exact_vector(velocity), n = exact_vector(normal);
  const V3 relative = v - exact_vector(object_velocity);
  const FT v_close = dot(relative, n);
  r.v_close = kernel::rounded(v_close);
  r.velocity = velocity;
  if (!CGAL::is_negative(v_close)) return r;
  r.closing = true;
  const FT m(mass);
  const FT j = -(ft(1) + ft(e)) * m * v_close;
  const V3 normal_impulse = j * n;
  const V3 tangential = relative - v_close * n;
  V3 friction{0, 0, 0};
  if (!CGAL::is_zero(dot(tangential, tangential))) {
    const FT slide = length(tangential);
    const FT f = CGAL::min(ft(mu) * j, m * slide);
    friction = (-f / slide) * tangential;
  }
  r.normal_impulse = rounded(normal_impulse);
  r.friction = rounded(friction);
  r.velocity = rounded(v + (ft(1) / m) * (normal_impulse + friction));
  return r;
}

namespace {

V3 acceleration(const V3& velocity, const FT& mass, const Forces& f) {
  const V3 drag = (ft(f.drag) + ft(f.air_drag) * length(velocity)) * velocity;
  return exact_vector(f.gravity) - (ft(1) / mass) * drag;
}

}  // namespace

Vec3 force(const Vec3& velocity, double mass, const Forces& f) {
  return rounded(ft(mass) * acceleration(exact_vector(velocity), ft(mass), f));
}

State euler_step(const State& s, double mass, const Forces& f, double dt) {
  const V3 p = exact_vector(s.position), v = exact_vector(s.velocity);
  const FT h(dt);
  return {rounded(p + h * v), rounded(v + h * acceleration(v, ft(mass), f)), s.previous};
}

State verlet_step(const State& s, double mass, const Forces& f, double dt) {
  const V3 p = exact_vector(s.position), previous = exact_vector(s.previous);
  const FT h(dt);
  const V3 next = ft(2) * p - previous + (h * h) * acceleration(exact_vector(s.velocity), ft(mass), f);
  return {rounded(next), rounded((ft(1) / h) * (next - p)), s.position};
}

State start_verlet(const State& s, double mass, const Forces& f, double dt) {
  const V3 p = exact_vector(s.position), v = exact_vector(s.velocity);
  const FT h(dt);
  const V3 previous = p - h * v + (h * h / ft(2)) * acceleration(v, ft(mass), f);
  return {s.position, s.velocity, rounded(previous)};
}

namespace {

FT discriminant(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity) {
  const V3 d = exact_vector(target) - exact_vector(from), g = exact_vector(gravity);
  const FT v2 = ft(speed) * ft(speed);
  const V3 c = cross(d, g);
  return v2 * v2 + ft(2) * v2 * dot(d, g) - dot(c, c);
}

}  // namespace

int launch_sign(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity) {
  return sign_of(CGAL::sign(discriminant(from, target, speed, gravity)));
}

double launch_discriminant(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity) {
  return kernel::rounded(discriminant(from, target, speed, gravity));
}

double launch_radicand(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity) {
  const V3 d = exact_vector(target) - exact_vector(from), g = exact_vector(gravity);
  const V3 c = cross(d, g);
  const FT gx2 = dot(c, c), g2 = dot(g, g), v2 = ft(speed) * ft(speed);
  if (gx2 == 0 || g2 == 0 || v2 == 0) return 0.0;
  return kernel::rounded(gx2 * discriminant(from, target, speed, gravity) / (g2 * v2 * v2));
}

bool launch_vertical(const Vec3& from, const Vec3& target, const Vec3& gravity) {
  const V3 c = cross(exact_vector(target) - exact_vector(from), exact_vector(gravity));
  return CGAL::is_zero(c.x) && CGAL::is_zero(c.y) && CGAL::is_zero(c.z);
}

bool trajectory_reaches(const Vec3& from, const Vec3& velocity, double t, const Vec3& gravity, const Vec3& target,
                        double tolerance) {
  const FT h(t);
  const V3 p = exact_vector(from) + h * exact_vector(velocity) + (h * h / ft(2)) * exact_vector(gravity);
  const V3 miss = p - exact_vector(target);
  return dot(miss, miss) <= ft(tolerance) * ft(tolerance);
}

bool squared_speed_at_most(const Vec3& v, const Vec3& reference, double factor) {
  const V3 a = exact_vector(v), b = exact_vector(reference);
  return dot(a, a) <= ft(factor) * dot(b, b);
}

bool squared_speed_at_least(const Vec3& v, const Vec3& reference, double factor) {
  const V3 a = exact_vector(v), b = exact_vector(reference);
  return dot(a, a) >= ft(factor) * dot(b, b);
}

// ---- Springs -----------------------------------------------------------------------

Vec3 spring_force(const Vec3& position_a, const Vec3& velocity_a, const Vec3& position_b, const Vec3& velocity_b,
                  double stiffness, double damping, double rest_length) {
  const V3 d = exact_vector(position_a) - exact_vector(position_b);
  if (CGAL::is_zero(dot(d, d))) return Vec3::Zero();
  const FT l = length(d);
  const FT closing = dot(exact_vector(velocity_a) - exact_vector(velocity_b), d) / l;  // (v_a - v_b) . u
  const FT size = ft(stiffness) * (l - ft(rest_length)) + ft(damping) * closing;
  return rounded((-size / l) * d);
}

// ---- Rigid bodies ------------------------------------------------------------------

namespace {

V3 times(const labkit::Mat3& m, const V3& v) {
  V3 r;
  FT* out[3] = {&r.x, &r.y, &r.z};
  for (int i = 0; i < 3; ++i) *out[i] = ft(m(i, 0)) * v.x + ft(m(i, 1)) * v.y + ft(m(i, 2)) * v.z;
  return r;
}

// The velocity of the body's material point at `point`: v + w x r.
V3 point_velocity(const Body& body, const V3& point) {
  const V3 r = point - exact_vector(body.centre);
  return exact_vector(body.velocity) + cross(exact_vector(body.angular_velocity), r);
}

FT normal_velocity(const Body& a, const Body& b, const Vec3& point, const Vec3& normal) {
  const V3 p = exact_vector(point);
  return dot(exact_vector(normal), point_velocity(a, p) - point_velocity(b, p));
}

}  // namespace

RigidImpulse rigid_impulse(const Body& a, const Body& b, const Vec3& point, const Vec3& normal, double e) {
  RigidImpulse out;
  const V3 p = exact_vector(point), n = exact_vector(normal);
  const V3 ra = p - exact_vector(a.centre), rb = p - exact_vector(b.centre);
  const V3 turn_a = times(a.inverse_inertia, cross(ra, n)), turn_b = times(b.inverse_inertia, cross(rb, n));
  const FT denominator =
      ft(1) / ft(a.mass) + ft(1) / ft(b.mass) + dot(n, cross(turn_a, ra)) + dot(n, cross(turn_b, rb));
  const FT v_rel = normal_velocity(a, b, point, normal);
  out.v_rel = kernel::rounded(v_rel);
  out.denominator = kernel::rounded(denominator);
  out.velocity_a = a.velocity, out.angular_velocity_a = a.angular_velocity;
  out.velocity_b = b.velocity, out.angular_velocity_b = b.angular_velocity;
  if (!CGAL::is_negative(v_rel)) return out;
  out.closing = true;
  const FT j = -(ft(1) + ft(e)) * v_rel / denominator;
  out.j = kernel::rounded(j);
  out.velocity_a = rounded(exact_vector(a.velocity) + (j / ft(a.mass)) * n);
  out.velocity_b = rounded(exact_vector(b.velocity) - (j / ft(b.mass)) * n);
  out.angular_velocity_a = rounded(exact_vector(a.angular_velocity) + j * turn_a);  // I_a^-1 (r_a x j n)
  out.angular_velocity_b = rounded(exact_vector(b.angular_velocity) - j * turn_b);
  return out;
}

Vec3 momentum_change(const Body& a, const Body& b, const Vec3& velocity_a, const Vec3& velocity_b) {
  return rounded(ft(a.mass) * (exact_vector(velocity_a) - exact_vector(a.velocity)) +
                 ft(b.mass) * (exact_vector(velocity_b) - exact_vector(b.velocity)));
}

double restitution_defect(const Body& a, const Body& b, const Body& a_after, const Body& b_after, const Vec3& point,
                          const Vec3& normal, double e) {
  return kernel::rounded(normal_velocity(a_after, b_after, point, normal) +
                         ft(e) * normal_velocity(a, b, point, normal));
}

}  // namespace oracle
