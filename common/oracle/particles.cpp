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

}  // namespace oracle
