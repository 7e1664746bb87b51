#include "common/oracle/sphere_sweeps.h"
#include "common/oracle/kernel.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace oracle {

using namespace kernel;

struct SquaredDistance::Exact {
  FT value;
};

namespace {

using Point = Epeck::Point_3;
using Vector = Epeck::Vector_3;
using ExactSegment = Epeck::Segment_3;
using ExactTriangle = Epeck::Triangle_3;

SquaredDistance make(const FT& value) { return SquaredDistance(std::make_shared<SquaredDistance::Exact>(SquaredDistance::Exact{value})); }

Vector exact_vector(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

FT squared(const FT& x) { return x * x; }

FT distance2(const Point& p, const ExactSegment& s) {
  return s.is_degenerate() ? CGAL::squared_distance(p, s.source()) : CGAL::squared_distance(p, s);
}

FT distance2(const ExactSegment& s0, const ExactSegment& s1) {
  if (s0.is_degenerate()) return distance2(s0.source(), s1);
  if (s1.is_degenerate()) return distance2(s1.source(), s0);
  return CGAL::squared_distance(s0, s1);
}

// The rectangle as the exact parallelogram of its numbers: corner k has signs
// (k & 1 ? + : -) half_u along u and (k & 2 ? + : -) half_v along v.
//
//    c2 ------- c3        sides, in order: c0 c1, c1 c3, c3 c2, c2 c0
//    |     v ^   |        triangles: c0 c1 c3 and c0 c3 c2
//    |       +-> u
//    c0 ------- c1
struct ExactRectangle {
  std::array<Point, 4> corner;
  bool flat = false;  // half_u == 0 or half_v == 0: a segment (or a point)

  explicit ExactRectangle(const Rectangle& r) {
    const Point c = exact(r.center);
    const Vector u = exact_vector(r.u) * FT(r.half_u), v = exact_vector(r.v) * FT(r.half_v);
    for (int k = 0; k < 4; ++k) corner[k] = c + (k & 1 ? u : -u) + (k & 2 ? v : -v);
    flat = r.half_u == 0 || r.half_v == 0;
  }
  // A flat rectangle is the segment between opposite corners.
  ExactSegment diagonal() const { return {corner[0], corner[3]}; }
  ExactSegment side(int i) const {
    static const int from[4] = {0, 1, 3, 2}, to[4] = {1, 3, 2, 0};
    return {corner[from[i]], corner[to[i]]};
  }
  ExactTriangle triangle(int i) const {
    return i == 0 ? ExactTriangle(corner[0], corner[1], corner[3]) : ExactTriangle(corner[0], corner[3], corner[2]);
  }
};

FT distance2(const Point& p, const ExactRectangle& r) {
  if (r.flat) return distance2(p, r.diagonal());
  return CGAL::min(CGAL::squared_distance(p, r.triangle(0)), CGAL::squared_distance(p, r.triangle(1)));
}

// A segment and a rectangle that do not meet: a closest pair has an end of the segment
// or a point of the rectangle's border in it (both are convex), so the ends against the
// two triangles and the segment against the four sides cover it.
FT distance2(const ExactSegment& s, const ExactRectangle& r) {
  if (s.is_degenerate()) return distance2(s.source(), r);
  if (r.flat) return distance2(s, r.diagonal());
  if (CGAL::do_intersect(s, r.triangle(0)) || CGAL::do_intersect(s, r.triangle(1))) return FT(0);
  FT best = CGAL::min(distance2(s.source(), r), distance2(s.target(), r));
  for (int i = 0; i < 4; ++i) best = CGAL::min(best, distance2(s, r.side(i)));
  return best;
}

// Two rectangles: a closest pair has a point of some side of one of them (if both points
// were inside, the rectangles would be parallel there, and a side gets as close), and a
// side that meets the other rectangle has distance 0. So: eight sides.
FT distance2(const ExactRectangle& r0, const ExactRectangle& r1) {
  FT best = distance2(r0.side(0), r1);
  for (int i = 1; i < 4; ++i) best = CGAL::min(best, distance2(r0.side(i), r1));
  for (int i = 0; i < 4; ++i) best = CGAL::min(best, distance2(r1.side(i), r0));
  return best;
}

int sign_of_compare(const FT& a, const FT& b) { return CGAL::compare(a, b) == CGAL::SMALLER ? -1 : (a == b ? 0 : 1); }

// sign(sqrt(d2) - length), exactly.
int distance_sign(const FT& d2, const FT& length) {
  if (CGAL::is_negative(length)) return 1;
  return sign_of_compare(d2, length * length);
}

// sign(x - e sqrt(nn)), exactly (nn > 0).
int sign_minus_root(const FT& x, const FT& e, const FT& nn) {
  if (!CGAL::is_negative(e)) {
    if (!CGAL::is_positive(x)) return CGAL::is_zero(x) && CGAL::is_zero(e) ? 0 : -1;
    return sign_of_compare(x * x, e * e * nn);
  }
  if (!CGAL::is_negative(x)) return 1;
  return sign_of_compare(e * e * nn, x * x);
}

FT sum(double a, double b, double c = 0.0) { return FT(a) + FT(b) + FT(c); }

// ---- Sweeps ---------------------------------------------------------------------------

struct Relative {  // A + t B, R
  Vector A, B;
  FT R;
};
Relative relative(const SphereSphereSweep& in) {
  return {exact(in.s0.center) - exact(in.s1.center), exact_vector(in.v0) - exact_vector(in.v1),
          FT(in.s0.radius) + FT(in.s1.radius)};
}

FT plane_value(const Plane& plane, const Point& x) {
  return exact_vector(plane.normal) * (x - CGAL::ORIGIN) + FT(plane.offset);
}
FT normal2(const Plane& plane) { return exact_vector(plane.normal).squared_length(); }

// The plane's value at the moving centre: f(t) = f0 + t g.
struct Linear {
  FT f0, g;
  FT at(const FT& t) const { return f0 + t * g; }
  // The smallest |f| over [0, t_end].
  FT smallest_abs(const FT& t_end) const {
    const FT f1 = at(t_end);
    if (sign_of(CGAL::sign(f0)) * sign_of(CGAL::sign(f1)) <= 0) return FT(0);
    return CGAL::min(CGAL::abs(f0), CGAL::abs(f1));
  }
};
Linear linear(const Plane& plane, const Vec3& center, const Vec3& velocity) {
  return {plane_value(plane, exact(center)), exact_vector(plane.normal) * exact_vector(velocity)};
}

// |normal| times the box's radius along the normal: sum_i h_i |n . axis_i|.
FT projected_radius(const Box& box, const Plane& plane) {
  const Vector n = exact_vector(plane.normal);
  FT rho = 0;
  for (int i = 0; i < 3; ++i) rho += FT(box.half_extents[i]) * CGAL::abs(n * exact_vector(box.axes.col(i)));
  return rho;
}

// The first root of a t^2 + 2 b t + c = 0 in doubles (reports only).
double first_root(double a, double b, double c) {
  const double disc = std::max(0.0, b * b - a * c);
  const double q = -b + std::sqrt(disc);
  return q > 0 ? c / q : 0.0;
}

bool exact_double(const FT& x, double d) { return std::isfinite(d) && x == FT(d); }

// Are x . y's products and partial sums exact in double, so that any order of summing
// gives the exact value?
bool dot_exact(const Vec3& x, const Vec3& y) {
  const double p[3] = {x[0] * y[0], x[1] * y[1], x[2] * y[2]};
  for (int i = 0; i < 3; ++i)
    if (!exact_double(FT(x[i]) * FT(y[i]), p[i])) return false;
  return exact_double(FT(p[0]) + FT(p[1]), p[0] + p[1]) && exact_double(FT(p[0]) + FT(p[2]), p[0] + p[2]) &&
         exact_double(FT(p[1]) + FT(p[2]), p[1] + p[2]) &&
         exact_double(FT(p[0]) + FT(p[1]) + FT(p[2]), p[0] + p[1] + p[2]);
}

}  // namespace

// ---- Distances --------------------------------------------------------------------------

double SquaredDistance::value() const { return rounded(exact_->value); }
double SquaredDistance::distance() const { return std::sqrt(value()); }
int SquaredDistance::compare(double l0, double l1, double l2) const { return distance_sign(exact_->value, sum(l0, l1, l2)); }

SquaredDistance squared_distance(const Vec3& p, const Vec3& q) { return make(CGAL::squared_distance(exact(p), exact(q))); }
SquaredDistance squared_distance(const Vec3& p, const Segment& s) { return make(distance2(exact(p), exact(s))); }
SquaredDistance squared_distance(const Segment& s0, const Segment& s1) { return make(distance2(exact(s0), exact(s1))); }
SquaredDistance squared_distance(const Vec3& p, const Rectangle& r) { return make(distance2(exact(p), ExactRectangle(r))); }
SquaredDistance squared_distance(const Segment& s, const Rectangle& r) { return make(distance2(exact(s), ExactRectangle(r))); }
SquaredDistance squared_distance(const Rectangle& r0, const Rectangle& r1) {
  return make(distance2(ExactRectangle(r0), ExactRectangle(r1)));
}

bool rectangle_point_reproduces(const Rectangle& r, double s, double t, const Vec3& x, double tolerance) {
  const Point p = exact(r.center) + exact_vector(r.u) * FT(s) + exact_vector(r.v) * FT(t);
  return CGAL::squared_distance(p, exact(x)) <= squared(FT(tolerance));
}

// ---- Sweeps -------------------------------------------------------------------------------

int gap_sign(const SphereSphereSweep& in, double t, double extra) {
  const Relative m = relative(in);
  return distance_sign((m.A + m.B * FT(t)).squared_length(), m.R + FT(extra));
}

int min_gap_sign(const SphereSphereSweep& in, double t_end, double extra) {
  // |A + t B|^2 = a t^2 + 2 b t + |A|^2 is smallest at t = -b / a, clamped to [0, t_end].
  const Relative m = relative(in);
  const FT a = m.B.squared_length(), b = m.A * m.B;
  FT t = 0;
  if (CGAL::is_positive(a)) t = CGAL::min(CGAL::max(-b / a, FT(0)), FT(t_end));
  return distance_sign((m.A + m.B * t).squared_length(), m.R + FT(extra));
}

int gap_sign(const SpherePlaneSweep& in, double t, double extra) {
  const FT f = linear(in.plane, in.sphere.center, in.velocity).at(FT(t));
  return distance_sign(f * f / normal2(in.plane), FT(in.sphere.radius) + FT(extra));
}

int min_gap_sign(const SpherePlaneSweep& in, double t_end, double extra) {
  const FT f = linear(in.plane, in.sphere.center, in.velocity).smallest_abs(FT(t_end));
  return distance_sign(f * f / normal2(in.plane), FT(in.sphere.radius) + FT(extra));
}

int gap_sign(const BoxPlaneSweep& in, double t, double extra) {
  const FT f = linear(in.plane, in.box.center, in.velocity).at(FT(t));
  return sign_minus_root(CGAL::abs(f) - projected_radius(in.box, in.plane), FT(extra), normal2(in.plane));
}

int min_gap_sign(const BoxPlaneSweep& in, double t_end, double extra) {
  const FT f = linear(in.plane, in.box.center, in.velocity).smallest_abs(FT(t_end));
  return sign_minus_root(f - projected_radius(in.box, in.plane), FT(extra), normal2(in.plane));
}

double first_contact(const SphereSphereSweep& in, double t_end) {
  if (gap_sign(in, 0.0, 0.0) <= 0) return 0.0;
  if (min_gap_sign(in, t_end, 0.0) > 0) return -1.0;
  const Relative m = relative(in);
  const double a = rounded(m.B.squared_length()), b = rounded(m.A * m.B), c = rounded(m.A.squared_length() - m.R * m.R);
  return std::clamp(first_root(a, b, c), 0.0, t_end);
}

double first_contact(const SpherePlaneSweep& in, double t_end) {
  if (gap_sign(in, 0.0, 0.0) <= 0) return 0.0;
  if (min_gap_sign(in, t_end, 0.0) > 0) return -1.0;
  const Linear f = linear(in.plane, in.sphere.center, in.velocity);
  const double reach = std::abs(rounded(f.f0)) - in.sphere.radius * std::sqrt(rounded(normal2(in.plane)));
  return std::clamp(reach / std::abs(rounded(f.g)), 0.0, t_end);
}

double first_contact(const BoxPlaneSweep& in, double t_end) {
  if (gap_sign(in, 0.0, 0.0) <= 0) return 0.0;
  if (min_gap_sign(in, t_end, 0.0) > 0) return -1.0;
  const Linear f = linear(in.plane, in.box.center, in.velocity);
  return std::clamp(rounded((CGAL::abs(f.f0) - projected_radius(in.box, in.plane)) / CGAL::abs(f.g)), 0.0, t_end);
}

bool sphere_sweep_exact_and_steep(const SphereSphereSweep& in) {
  const Vec3 A = in.s0.center - in.s1.center, B = in.v0 - in.v1;
  const double R = in.s0.radius + in.s1.radius;
  for (int i = 0; i < 3; ++i) {
    if (!exact_double(FT(in.s0.center[i]) - FT(in.s1.center[i]), A[i])) return false;
    if (!exact_double(FT(in.v0[i]) - FT(in.v1[i]), B[i])) return false;
  }
  if (!exact_double(FT(in.s0.radius) + FT(in.s1.radius), R) || !exact_double(FT(R) * FT(R), R * R)) return false;
  if (!dot_exact(A, A) || !dot_exact(A, B) || !dot_exact(B, B)) return false;
  if (!exact_double(FT(A.dot(A)) - FT(R * R), A.dot(A) - R * R)) return false;
  const FT a = FT(B.dot(B)), b = FT(A.dot(B)), c = FT(A.dot(A)) - FT(R * R);
  return CGAL::is_positive(c) && CGAL::is_negative(b) && CGAL::is_positive(a) && 3 * b * b >= 4 * a * c;
}

bool within_moving_sphere(const Sphere& s, const Vec3& v, double t, const Vec3& x, double tolerance) {
  const Point c = exact(s.center) + exact_vector(v) * FT(t);
  return distance_sign(CGAL::squared_distance(c, exact(x)), FT(s.radius) + FT(tolerance)) <= 0;
}

bool within_plane(const Plane& plane, const Vec3& x, double tolerance) {
  return squared(plane_value(plane, exact(x))) <= squared(FT(tolerance)) * normal2(plane);
}

bool within_moving_box(const Box& box, const Vec3& v, double t, const Vec3& x, double tolerance) {
  const Vector d = exact(x) - (exact(box.center) + exact_vector(v) * FT(t));
  for (int i = 0; i < 3; ++i) {
    const Vector axis = exact_vector(box.axes.col(i));
    if (CGAL::abs(d * axis) > (FT(box.half_extents[i]) + FT(tolerance)) * axis.squared_length()) return false;
  }
  return true;
}

}  // namespace oracle
