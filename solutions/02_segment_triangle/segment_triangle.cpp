// Lab 02 reference: segment against triangle and mesh.
//
// The one idea that makes it robust: decide with signs, then construct. Every yes/no
// below is the sign of a product of differences of input coordinates, never of a
// point we computed, so on small-integer input (the robustness step's) every decision
// is exact in double arithmetic. Points and parameters are built only after the
// decision, and only they carry rounding error.
#include "segment_triangle.h"

#include "common/preconditions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace labkit::lab02 {

namespace {

// ---- Preconditions (the header's): finite coordinates, mesh indices in range, poses rigid.
// All are the shared checks of common/preconditions.h.

using namespace preconditions;

// ---- Scale: one power of two for a whole query --------------------------------------

// Decisions multiply up to three coordinates (a volume), and the in-plane test squares
// that: at 1e-60 or 1e60 such products underflow to 0 or overflow to infinity, and a
// plain crossing becomes a miss. Multiplying every input point by 2^-k, with 2^k near
// the largest coordinate, is exact (only exponents change), keeps every product near 1,
// and changes no sign, no t and no weight; lengths are multiplied back by 2^k.
// (Multiplying by the power of two 2^-k rounds exactly as ldexp does, and costs one
// product instead of a library call per coordinate: this runs on every pair tested.)
struct Scale {
  int k = 0;
  double factor = 1.0;  // 2^-k
  Vec3 in(const Vec3& p) const { return p * factor; }
  double out(double length) const { return std::ldexp(length, k); }
  Segment in(const Segment& s) const { return {in(s.a), in(s.b)}; }
  Triangle in(const Triangle& t) const { return {in(t.v0), in(t.v1), in(t.v2)}; }
};

Scale scale_of(std::initializer_list<Vec3> points) {
  double largest = 0;
  for (const Vec3& p : points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  Scale s;
  if (largest > 0) std::frexp(largest, &s.k);
  s.k = std::clamp(s.k, -1000, 1000);  // 2^-k stays a normal double: the largest point still lands near 1
  s.factor = std::ldexp(1.0, -s.k);
  return s;
}
Scale scale_of(const Segment& s, const Triangle& t) { return scale_of({s.a, s.b, t.v0, t.v1, t.v2}); }

// ---- The normal, to full precision even for a needle ------------------------------------

// A needle's normal is the cross product of two long, nearly parallel edges. Each of its
// components is the difference of two products up to the aspect ratio times larger than
// itself, so plain doubles lose that factor of its digits: 1e-8 of its direction for an
// aspect ratio of 1e8, and a point S away then lands a few tol off the plane, on the
// wrong side of it or with weights that miss it (no choice of corner avoids it: at the
// middle vertex of a sliver the angle is nearly 180 degrees, as bad as the tip's). So
// nothing is rounded until the end: each edge is kept exactly, as its rounded difference
// plus what rounding dropped (TwoSum), and the products of the rounded parts exactly, as
// the product plus its error from one fma (TwoProduct). Only terms 1e-16 smaller than
// the result are rounded, whatever the triangle's shape: the normal's direction is good
// to a few units of 1e-16. (A zero-area triangle still gives exactly zero.)
struct Exact {
  double hi = 0.0, lo = 0.0;  // hi + lo, exactly
};

// a - b exactly (Knuth's TwoSum; hi is the rounded difference).
Exact difference(double a, double b) {
  const double hi = a - b;
  const double b_part = a - hi;  // the part of b that hi holds
  const double a_part = hi + b_part;
  return {hi, (a - a_part) + (b_part - b)};
}

// x0 y1 - x1 y0, rounded once (up to terms 1e-16 of the result smaller).
double minor(const Exact& x0, const Exact& y1, const Exact& x1, const Exact& y0) {
  const double p = x0.hi * y1.hi, q = x1.hi * y0.hi;
  const double p_error = std::fma(x0.hi, y1.hi, -p), q_error = std::fma(x1.hi, y0.hi, -q);
  const double small = (x0.hi * y1.lo + x0.lo * y1.hi) - (x1.hi * y0.lo + x1.lo * y0.hi);
  // p - q is exact when they nearly cancel (Sterbenz), and otherwise rounds only once.
  return (p - q) + ((p_error - q_error) + small);
}

// (v1 - v0) x (v2 - v0), to full precision.
Vec3 accurate_normal(const Triangle& t) {
  Exact e1[3], e2[3];
  for (int k = 0; k < 3; ++k) e1[k] = difference(t.v1[k], t.v0[k]), e2[k] = difference(t.v2[k], t.v0[k]);
  return {minor(e1[1], e2[2], e1[2], e2[1]), minor(e1[2], e2[0], e1[0], e2[2]), minor(e1[0], e2[1], e1[1], e2[0])};
}

// The axis of the normal's largest |component| (ties: the lower index). Dropping it
// projects the triangle onto the coordinate plane where it has the largest area.
int largest_axis(const Vec3& n) {
  const Vec3 m = n.cwiseAbs();
  if (m.x() >= m.y() && m.x() >= m.z()) return 0;
  return m.y() >= m.z() ? 1 : 2;
}

// Keeps the two coordinates after `axis`, in cyclic order, so that the 2D cross product
// of two projected edges equals the dropped component of their 3D cross product.
Vec2 drop(const Vec3& p, int axis) { return {p[(axis + 1) % 3], p[(axis + 2) % 3]}; }

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

// In the plane with `axis` dropped: is X in the closed triangle P0 P1 P2, which turns
// with sign `turn` (+1 counter-clockwise)? Each edge function is >= 0 inside.
bool inside_2d(const Vec2& x, const Vec2 (&p)[3], double turn) {
  for (int i = 0; i < 3; ++i) {
    const Vec2& from = p[i];
    const Vec2& to = p[(i + 1) % 3];
    if (turn * cross(to - from, x - from) < 0) return false;  // strictly outside edge i
  }
  return true;
}

// 2D orientation sign of (p, q, r): +1 left turn, -1 right turn, 0 collinear.
int turn_sign(const Vec2& p, const Vec2& q, const Vec2& r) {
  const double c = cross(q - p, r - p);
  return (c > 0) - (c < 0);
}

// The smallest s in [0, 1] where A + s (B - A) meets the closed segment P Q, or
// +infinity. The decision uses orientation signs only; s is computed after.
double first_contact_2d(const Vec2& a, const Vec2& b, const Vec2& p, const Vec2& q) {
  constexpr double none = std::numeric_limits<double>::infinity();
  const int pa = turn_sign(p, q, a), pb = turn_sign(p, q, b);
  const int ap = turn_sign(a, b, p), aq = turn_sign(a, b, q);
  const Vec2 d = b - a;
  if (pa == 0 && pb == 0) {
    // Collinear: a is not inside the triangle (the caller checked), so the first
    // contact is the nearer of P and Q that lies on the segment.
    const double length2 = d.squaredNorm();
    if (length2 == 0) return none;
    double best = none;
    for (const Vec2& end : {p, q}) {
      const double s = (end - a).dot(d) / length2;
      if (s >= 0 && s <= 1) best = std::min(best, s);
    }
    return best;
  }
  if (pa * pb > 0 || ap * aq > 0) return none;  // both ends on one side of the other
  // They meet. Solving a + s d on the line P Q divides two cross products that both
  // vanish when the segment runs nearly along the edge: noise over noise, anywhere on
  // the segment. Instead, find the meeting point on the edge, P + u (Q - P), from the
  // sides of P and Q relative to the segment's line (opposite signs: the denominator is
  // a sum of two magnitudes, never a cancellation), so it lies on the edge; then take
  // its place along the segment, clamped to it. When the two nearly run along one line
  // the clamped point is still common to both, to within rounding.
  const double side_p = cross(d, p - a), side_q = cross(d, q - a);
  const double u = side_p == side_q ? 0.0 : side_p / (side_p - side_q);
  const Vec2 x = p + u * (q - p);
  const double length2 = d.squaredNorm();
  if (length2 == 0) return 0.0;  // a itself is on the edge
  return std::clamp((x - a).dot(d) / length2, 0.0, 1.0);
}

// The answer of both queries, decided once.
struct Decision {
  bool hit = false;
  double t = 0.0;
  Vec3 n = Vec3::Zero();        // the triangle's normal, unnormalised (when hit)
  Vec3 weights = Vec3::Zero();  // barycentric weights of the crossing (zero: not known)
};

// The segment lies in the triangle's plane: a 2D problem. The first point is a itself
// when a is inside; otherwise the triangle is convex, so the first point is where the
// segment first meets an edge.
Decision decide_coplanar(const Segment& s, const Triangle& tri, const Vec3& n) {
  const int axis = largest_axis(n);
  const double turn = n[axis] > 0 ? 1.0 : -1.0;
  const Vec2 p[3] = {drop(tri.v0, axis), drop(tri.v1, axis), drop(tri.v2, axis)};
  const Vec2 a = drop(s.a, axis), b = drop(s.b, axis);
  Decision d;
  double t = std::numeric_limits<double>::infinity();
  if (inside_2d(a, p, turn))
    t = 0.0;
  else
    for (int i = 0; i < 3; ++i) t = std::min(t, first_contact_2d(a, b, p[i], p[(i + 1) % 3]));
  if (!std::isfinite(t)) return d;  // the segment misses the triangle in its plane
  d.hit = true;
  d.t = t;
  d.n = n;
  return d;  // no weights: hit_from measures them on the point
}

// Both ends on the plane, to within the rounding error of d_a and d_b: then the volumes
// below are all zero up to that same rounding, and their signs are pure noise; the 2D
// test decides instead. d = (p - v0) . n, with n accurate (accurate_normal), is rounded
// by a few units of 1e-16 |p - v0| |n|; the bound is 16 units (compared squared, to spare
// the roots): a slab 1e-15 of the distances thick, whatever the triangle's shape, so a
// short steep segment through a needle is never taken for one lying in its plane. On
// integer input (|x| <= 1024) it is far below 1, so such input is treated as coplanar
// only when it is.
bool in_plane(double d_a, double d_b, const Vec3& a_to_v, const Vec3& b_to_v, const Vec3& n) {
  constexpr double unit = 16 * std::numeric_limits<double>::epsilon();
  const double slab = unit * unit * n.squaredNorm();
  return d_a * d_a <= slab * a_to_v.squaredNorm() && d_b * d_b <= slab * b_to_v.squaredNorm();
}

//   Derivation (lecture 000, "segment vs. triangle"): with n = (v1 - v0) x (v2 - v0),
//   d_a = (a - v0) . n and d_b = (b - v0) . n, the segment crosses the plane at
//   x = a + t (b - a), t = d_a / (d_a - d_b). The edge test of step 2 at x,
//   E_i = (x - v_i) . (n x (v_{i+1} - v_i)), multiplied through by (d_a - d_b), is
//
//       (d_a - d_b) E_i = -|n|^2 V_i,   V_i = (b - a) . ((v_i - a) x (v_{i+1} - a)),
//
//   so x is inside exactly when every V_i has the sign opposite to (d_a - d_b) (or is
//   zero). V_i uses input points only: no rounded x enters any decision. Summed over
//   the three edges, the E_i make |n|^2, so V_0 + V_1 + V_2 = d_b - d_a: the third
//   volume costs one subtraction, and on integer input it is still exact. The other
//   two share one cross product: a triple product may be rotated, so with
//   m = (b - a) x (v0 - a), V_0 = m . (v1 - a) and V_2 = -m . (v2 - a).
//
//          v2
//         /  \        V_0 belongs to edge v0 -> v1,
//    V_2 /    \ V_1   V_1 to edge v1 -> v2,
//       /  x   \      V_2 to edge v2 -> v0.
//     v0 ------ v1
//          V_0
Decision decide(const Segment& input, const Triangle& input_tri) {
  const Scale scale = scale_of(input, input_tri);
  const Segment s = scale.in(input);
  const Triangle tri = scale.in(input_tri);
  const Vec3 n = accurate_normal(tri);
  // The vertices as seen from a, and where the segment goes.
  const Vec3 p0 = tri.v0 - s.a, p1 = tri.v1 - s.a, p2 = tri.v2 - s.a;
  const Vec3 direction = s.b - s.a;
  const Vec3 a_to_v = s.a - tri.v0, b_to_v = s.b - tri.v0;
  const double d_a = a_to_v.dot(n);  // (a - v0) . n
  const double d_b = b_to_v.dot(n);  // (b - v0) . n
  // mutant magic_epsilon (step 4, "same side"):
  //   `0 && d_b > 0) || (d_a < 0 && d_b < 0`
  //   -> `1e-9 && d_b > 1e-9) || (d_a < -1e-9 && d_b < -1e-9`
  if ((d_a > 0 && d_b > 0) || (d_a < 0 && d_b < 0)) return {};  // both ends strictly on one side
  // mutant fuzzy_zero_area (step 4, "zero area"): `n == Vec3::Zero` -> `input_tri.normal().isZero`
  if (n == Vec3::Zero()) return {};  // zero area: no plane, never hit
  // mutant coplanar_is_a_miss (step 8, "in the plane"): `decide_coplanar(s, tri, n)` -> `{}`
  if (d_a == 0 && d_b == 0) return decide_coplanar(s, tri, n);

  // A segment in the plane up to rounding: its volumes below are noise, in 2D.
  if (in_plane(d_a, d_b, a_to_v, b_to_v, n)) return decide_coplanar(s, tri, n);
  // The volumes sum to d_b - d_a, which is (b - a) . n: taken so, it is rounded relative
  // to itself, not to the two distances (much longer for a short segment far from v0).
  const double sum = direction.dot(n);
  // The volumes are rounded by a few units of 1e-16 |b - a| |p|^2 (p the longest v_i - a).
  // A segment so nearly parallel to the plane that this sum is
  // within that rounding has volumes whose signs are noise, even when one end is clearly
  // off the plane and the other within rounding of it. Its crossing is then fixed only
  // loosely anyway (the header's tolerance of t): build it, and test it in 2D. On
  // integer input (|x| <= 1024) the bound is below 1 and the volumes always decide.
  const double reach = std::max({p0.squaredNorm(), p1.squaredNorm(), p2.squaredNorm()});
  constexpr double unit = 16 * std::numeric_limits<double>::epsilon();
  if (std::abs(sum) <= unit * direction.norm() * reach) {
    if (d_a == d_b) return {};  // parallel to the plane and off it: no crossing
    const int axis = largest_axis(n);
    const Vec2 p[3] = {drop(tri.v0, axis), drop(tri.v1, axis), drop(tri.v2, axis)};
    const double t = d_a / (d_a - d_b);
    if (!inside_2d(drop(s.point(t), axis), p, n[axis] > 0 ? 1.0 : -1.0)) return {};
    return {true, t, n, Vec3::Zero()};
  }

  // mutant crossing_point_edge_tests (step 8, "boundary"):
  //   `const double side = d_a > d_b ? 1.0 : -1.0;`
  //   -> `if (!point_in_triangle_edges(s.point(d_a / (d_a - d_b)), tri)) return {}; const double side = 0;`
  const double side = d_a > d_b ? 1.0 : -1.0;
  const Vec3 m = direction.cross(p0);
  const double v0 = m.dot(p1);
  if (side * v0 > 0) return {};  // x is outside edge v0 -> v1
  const double v2 = -m.dot(p2);
  if (side * v2 > 0) return {};  // outside edge v2 -> v0
  const double v1 = sum - v0 - v2;
  if (side * v1 > 0) return {};  // outside edge v1 -> v2
  // The volumes are the crossing's barycentric weights, up to their sum: V_1 belongs to
  // the edge facing v0, and so weighs v0; V_2 weighs v1, V_0 weighs v2. Each V_i is
  // rounded by about 1e-16 |b - a| |p|^2 (p the longest v_i - a), so the weights are
  // good to 1e-11 while the sum is at least 1e-5 |b - a| |p|^2; a segment closer to
  // parallel than that leaves the weights to be measured on the point.
  const bool steep = sum * sum >= 1e-10 * direction.squaredNorm() * reach * reach;
  // Each volume V_i taken as the weight of v_i, the start of its edge; it weighs the
  // vertex facing that edge (V_1 weighs v0, V_2 v1, V_0 v2): the weights turn one place.
  // mutant weights_on_wrong_vertices (step 4, "weights of v0, v1, v2", "another order"): `v1, v2, v0` -> `v0, v1, v2`
  return {true, d_a / (d_a - d_b), n, steep ? Vec3(Vec3(v1, v2, v0) / sum) : Vec3(Vec3::Zero())};
}

// Only now build the point. Its weights come with the decision, unless the segment
// is in or nearly along the plane: then they are measured on the point itself (step 3).
SegmentTriangleHit hit_from(const Decision& d, const Segment& s, const Triangle& tri) {
  if (!d.hit) return {};
  SegmentTriangleHit h;
  h.hit = true;
  h.t = d.t;
  h.point = s.point(d.t);
  if (d.weights != Vec3::Zero()) {
    h.barycentric = d.weights;
  } else {
    const Barycentric b = barycentric(h.point, tri);
    h.barycentric = Vec3(1 - b.alpha - b.beta, b.alpha, b.beta);
  }
  // mutant normal_toward_a (step 4, "as wound"):
  //   `h.normal = d.n.normalized();`
  //   -> `h.normal = d.n.normalized(); if ((s.a - tri.v0).dot(h.normal) < 0) h.normal = -h.normal;`
  h.normal = d.n.normalized();
  return h;
}

MeshHit mesh_hit_from(const SegmentTriangleHit& h, int triangle) {
  return {h.hit, triangle, h.t, h.point, h.barycentric, h.normal};
}

// ---- A quick answer when plain doubles are already sure --------------------------------
//
// Most pairs are nowhere near a tie: both ends clearly on one side, or the crossing
// clearly inside or clearly outside an edge. For them the five signs that decide (d_a,
// d_b and the three volumes) can be read straight off the input, without scaling and
// without the needle's careful normal, provided the rounding cannot have flipped them.
// Each is a determinant of differences of input points; computed in doubles it is off
// by at most about 3.5 eps times its "permanent", the same sum with every product taken
// in absolute value (Shewchuk's static filter for orient3d; eps = 2^-52). The bound used
// here is 8 eps times the permanent, plus 1e-290 for products that underflow. Each
// triple product is formed as decide() forms it: a cross product, then a dot product. When a
// sign clears its bound it is the exact sign, so the answer below is the exact answer;
// otherwise (a tie, a needle, a nearly parallel segment, all zeros) decide() answers.
enum class Quick { hit, miss, unsure };

// The permanent's cross product: |y| x |z| with + in place of -.
inline Vec3 abs_cross(const Vec3& y, const Vec3& z) {
  const Vec3 a = y.cwiseAbs(), b = z.cwiseAbs();
  return {a.y() * b.z() + a.z() * b.y(), a.z() * b.x() + a.x() * b.z(), a.x() * b.y() + a.y() * b.x()};
}

// +1 or -1 when `value` (a triple product x . (y cross z), whose permanent is `permanent`)
// certainly has that sign, 0 when rounding could have changed it.
inline int sure_sign(double value, double permanent) {
  constexpr double relative = 8 * std::numeric_limits<double>::epsilon(), underflow = 1e-290;
  const double bound = relative * permanent + underflow;
  return value > bound ? 1 : value < -bound ? -1 : 0;
}

Quick quick_answer(const Segment& s, const Triangle& tri) {
  const Vec3 e1 = tri.v1 - tri.v0, e2 = tri.v2 - tri.v0;
  const Vec3 n = e1.cross(e2), n_abs = abs_cross(e1, e2);
  const Vec3 a_rel = s.a - tri.v0, b_rel = s.b - tri.v0;
  const int side_a = sure_sign(a_rel.dot(n), a_rel.cwiseAbs().dot(n_abs));  // the sign of d_a
  const int side_b = sure_sign(b_rel.dot(n), b_rel.cwiseAbs().dot(n_abs));  // the sign of d_b
  if (side_a == 0 || side_b == 0) return Quick::unsure;
  if (side_a == side_b) return Quick::miss;  // both ends strictly on one side
  // The segment crosses the plane strictly; the volumes say on which side of each edge's
  // line the crossing falls (as in decide(): all of sign -side_a inside, any of sign
  // side_a outside). V_0 and V_2 share m = (b - a) x p0, as in decide().
  const Vec3 direction = s.b - s.a, p0 = tri.v0 - s.a, p1 = tri.v1 - s.a, p2 = tri.v2 - s.a;
  const Vec3 m = direction.cross(p0), m_abs = abs_cross(direction, p0);
  const int v0 = sure_sign(m.dot(p1), m_abs.dot(p1.cwiseAbs()));
  if (v0 == side_a) return Quick::miss;  // strictly outside edge v0 -> v1
  const int v2 = sure_sign(-m.dot(p2), m_abs.dot(p2.cwiseAbs()));
  if (v2 == side_a) return Quick::miss;  // strictly outside edge v2 -> v0
  const int v1 = sure_sign(direction.cross(p1).dot(p2), abs_cross(direction, p1).dot(p2.cwiseAbs()));
  if (v1 == side_a) return Quick::miss;  // strictly outside edge v1 -> v2
  return v0 == -side_a && v1 == -side_a && v2 == -side_a ? Quick::hit : Quick::unsure;
}

}  // namespace

PlaneCrossing segment_plane(const Segment& segment, const Triangle& triangle) {
  require_valid("segment_plane", "segment", segment);
  require_valid("segment_plane", "triangle", triangle);
  const Scale scale = scale_of(segment, triangle);
  const Segment s = scale.in(segment);
  const Triangle tri = scale.in(triangle);
  const Vec3 n = accurate_normal(tri);
  const double length = n.norm();
  if (length == 0) return {};  // a zero-area triangle has no plane
  const Vec3 unit = n / length;
  PlaneCrossing c;
  const double d_a = (s.a - tri.v0).dot(unit), d_b = (s.b - tri.v0).dot(unit);
  // mutant distance_not_normalized (step 1, "distance", "unit"):
  //   `c.d_a = scale.out(d_a); c.d_b = scale.out(d_b);`
  //   -> `c.d_a = (segment.a - triangle.v0).dot(triangle.normal()); c.d_b = (segment.b -
  //     triangle.v0).dot(triangle.normal());`
  c.d_a = scale.out(d_a);
  c.d_b = scale.out(d_b);
  // Both ends strictly on one side: no crossing. Both on the plane: no single point.
  if ((d_a > 0 && d_b > 0) || (d_a < 0 && d_b < 0)) return c;
  if (d_a == 0 && d_b == 0) return c;
  c.crosses = true;
  // d_a and d_b have opposite signs (or one is 0): d_a - d_b never cancels.
  // mutant crossing_t_sign (step 1, "d_a / (d_a - d_b)", "denominator"): `d_a / (d_a - d_b` -> `d_a / (d_b - d_a`
  c.t = d_a / (d_a - d_b);
  c.point = (d_a * segment.b - d_b * segment.a) / (d_a - d_b);
  return c;
}

bool point_in_triangle_edges(const Vec3& point, const Triangle& input) {
  require_finite("point_in_triangle_edges", "x", point);
  require_valid("point_in_triangle_edges", "triangle", input);
  const Scale scale = scale_of({point, input.v0, input.v1, input.v2});
  const Vec3 x = scale.in(point);
  const Triangle triangle = scale.in(input);
  const Vec3 n = accurate_normal(triangle);
  if (n == Vec3::Zero()) return false;
  for (int i = 0; i < 3; ++i) {
    const Vec3& from = triangle[i];
    const Vec3& to = triangle[(i + 1) % 3];
    // n x (to - from) lies in the plane and points into the triangle.
    // mutant strict_edge_test (step 2, "closed"): `<` -> `<=`
    if ((x - from).dot(n.cross(to - from)) < 0) return false;  // strictly outside edge i
  }
  return true;
}

Barycentric barycentric(const Vec3& point, const Triangle& input) {
  require_finite("barycentric", "x", point);
  require_valid("barycentric", "triangle", input);
  const Scale scale = scale_of({point, input.v0, input.v1, input.v2});
  const Vec3 x = scale.in(point);
  const Triangle triangle = scale.in(input);
  const Vec3 n = accurate_normal(triangle);
  if (n == Vec3::Zero()) return {};
  Barycentric b;
  b.dropped_axis = largest_axis(n);
  const Vec2 e1 = drop(triangle.v1 - triangle.v0, b.dropped_axis);
  const Vec2 e2 = drop(triangle.v2 - triangle.v0, b.dropped_axis);
  const Vec2 p = drop(x - triangle.v0, b.dropped_axis);
  // p = alpha e1 + beta e2; alpha by Cramer's rule (cross with e2). The denominator is
  // n[axis], the largest component: never zero here.
  b.alpha = cross(p, e2) / cross(e1, e2);
  // beta by Cramer's rule too would divide a second noisy cross product by the same
  // small denominator: for a needle the two errors do not cancel, and alpha e1 + beta e2
  // misses p by the rounding times the aspect ratio. Projecting what alpha leaves onto
  // e2 instead keeps that residual at the rounding of p itself, however thin the
  // triangle (the weights still describe x, which is what they are for).
  // mutant beta_sign (step 3, "beta", "sign"):
  //   `b.beta = (p - b.alpha * e1).dot(e2) / e2.squaredNorm();`
  //   -> `b.beta = cross(p, e1) / cross(e1, e2);`
  b.beta = (p - b.alpha * e1).dot(e2) / e2.squaredNorm();
  return b;
}

bool point_in_triangle_barycentric(const Vec3& point, const Triangle& input) {
  require_finite("point_in_triangle_barycentric", "x", point);
  require_valid("point_in_triangle_barycentric", "triangle", input);
  const Scale scale = scale_of({point, input.v0, input.v1, input.v2});
  const Vec3 x = scale.in(point);
  const Triangle triangle = scale.in(input);
  const Vec3 n = accurate_normal(triangle);
  if (n == Vec3::Zero()) return false;
  const int axis = largest_axis(n);
  const Vec2 e1 = drop(triangle.v1 - triangle.v0, axis);
  const Vec2 e2 = drop(triangle.v2 - triangle.v0, axis);
  const Vec2 p = drop(x - triangle.v0, axis);
  // The tests alpha >= 0, beta >= 0, alpha + beta <= 1, multiplied through by the
  // denominator (made positive): no division, so a point exactly on an edge stays on it.
  const double sign = cross(e1, e2) > 0 ? 1.0 : -1.0;
  const double alpha = sign * cross(p, e2), beta = sign * cross(e1, p), whole = sign * cross(e1, e2);
  return alpha >= 0 && beta >= 0 && alpha + beta <= whole;
}

bool test_segment_triangle(const Segment& segment, const Triangle& triangle) {
  require_valid("test_segment_triangle", "segment", segment);
  require_valid("test_segment_triangle", "triangle", triangle);
  const Quick quick = quick_answer(segment, triangle);
  if (quick != Quick::unsure) return quick == Quick::hit;
  return decide(segment, triangle).hit;
}

SegmentTriangleHit find_segment_triangle(const Segment& segment, const Triangle& triangle) {
  require_valid("find_segment_triangle", "segment", segment);
  require_valid("find_segment_triangle", "triangle", triangle);
  return hit_from(decide(segment, triangle), segment, triangle);
}

MeshHit first_hit(const Segment& segment, const Mesh& mesh) {
  require_valid("first_hit", "segment", segment);
  require_valid("first_hit", "mesh", mesh);
  MeshHit best;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle tri = mesh.triangle(i);
    const Decision d = decide(segment, tri);
    // mutant first_found_not_nearest (step 5, "smallest t"): `(best.hit && d.t >= best.t)` -> `best.hit`
    if (!d.hit || (best.hit && d.t >= best.t)) continue;  // a miss, or not nearer
    best = mesh_hit_from(hit_from(d, segment, tri), int(i));
  }
  return best;
}

bool any_hit(const Segment& segment, const Mesh& mesh) {
  require_valid("any_hit", "segment", segment);
  require_valid("any_hit", "mesh", mesh);
  for (std::size_t i = 0; i < mesh.size(); ++i)
    if (decide(segment, mesh.triangle(i)).hit) return true;
  return false;
}

std::vector<MeshHit> all_hits(const Segment& segment, const Mesh& mesh) {
  require_valid("all_hits", "segment", segment);
  require_valid("all_hits", "mesh", mesh);
  std::vector<MeshHit> hits;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle tri = mesh.triangle(i);
    const Decision d = decide(segment, tri);
    if (d.hit) hits.push_back(mesh_hit_from(hit_from(d, segment, tri), int(i)));
  }
  std::sort(hits.begin(), hits.end(),
            // mutant hits_unsorted (step 5, "sorted by t"):
            //   `return x.t != y.t ? x.t < y.t : x.triangle < y.triangle;`
            //   -> `return x.triangle < y.triangle;`
            [](const MeshHit& x, const MeshHit& y) { return x.t != y.t ? x.t < y.t : x.triangle < y.triangle; });
  // mutant all_hits_drops_equal_t (step 5, "missing", "same t"):
  //   `return hits; }`
  //   -> `hits.erase(std::unique(hits.begin(), hits.end(), [](const MeshHit& x, const MeshHit& y) { return x.t == y.t;
  //     }), hits.end()); return hits; }`
  return hits;
}

// The lecture's delta matrix M_delta = M0^-1 M1 carries a to where it sits relative to
// the mesh at the end of the step. We go one step further and express the whole
// segment in the mesh's own frame, a' = M0^-1 a and b' = M1^-1 b: one transform per
// end instead of one per mesh vertex. The hit found there goes back to the world by M1.
MeshHit first_hit_moving(const Segment& segment, const Mesh& mesh, const RigidTransform& m0, const RigidTransform& m1) {
  require_valid("first_hit_moving", "segment", segment);
  require_valid("first_hit_moving", "mesh", mesh);
  require_valid("first_hit_moving", "m0", m0);
  require_valid("first_hit_moving", "m1", m1);
  // mutant moving_one_frame (step 6, "m1^-1 b"): `m1.inverse()` -> `m0.inverse()`
  const Segment local{m0.inverse() * segment.a, m1.inverse() * segment.b};
  MeshHit hit = first_hit(local, mesh);
  if (!hit.hit) return hit;
  hit.point = m1 * hit.point;
  // The normal carried to the world like a point, by m1's rotation and translation:
  // a normal is a direction, turned by the rotation only.
  // mutant normal_moved_like_a_point (step 6, "rotation only", "no translation"):
  //   `hit.normal = m1.linear() * hit.normal;`
  //   -> `hit.normal = m1 * hit.normal;`
  hit.normal = m1.linear() * hit.normal;
  return hit;
}

// ---- Step 7: moving mesh against moving mesh, by extrusion ---------------------------

namespace {

// The contact's normal from the direction n of a face's normal or of e x f: unit length,
// turned to point from B toward A, against A's motion d as seen from B (d . n <= 0).
Vec3 facing(const Vec3& n, const Vec3& d) {
  const Vec3 unit = n.normalized();
  // The normal left as the cross product happens to point: half the time from A toward B,
  // so a response would push the meshes into each other.
  // mutant contact_normal_unturned (step 7, "from B toward A", "d . normal <= 0"):
  //   `return unit.dot(d) > 0 ? Vec3(-unit) : unit;`
  //   -> `return unit;`
  return unit.dot(d) > 0 ? Vec3(-unit) : unit;
}

// Two edges e and f: e x f is normal to both. Parallel edges have no such cross product;
// then any direction perpendicular to both will do, and the part of d across them (or, if
// d runs along them too, any perpendicular) is one.
Vec3 edge_pair_normal(const Vec3& e, const Vec3& f, const Vec3& d) {
  const Vec3 n = e.cross(f);
  if (n != Vec3::Zero()) return facing(n, d);
  const Vec3 across = d - (d.dot(e) / e.squaredNorm()) * e;
  if (across != Vec3::Zero()) return facing(across, d);
  return facing(e.unitOrthogonal(), d);
}

// The earliest contact so far: its time, its point in the frame it was found in (carried
// to the world by that frame's own motion at that time), and its normal.
struct Earliest {
  MeshContact best;
  void offer(double t, const Vec3& point_in_frame, const Vec3& frame_velocity, const Vec3& normal) {
    // mutant last_contact (step 7, "first contact"): `>=` -> `<=`
    // The frame taken as half-open, [0, 1): a contact exactly at its end is dropped,
    // as if the next frame would see it (it starts with the meshes touching, which no
    // frame then reports).
    // mutant frame_end_excluded (step 9, "first touch", "t = 1"):
    //   `best.hit && t >= best.t`
    //   -> `t >= 1 || (best.hit && t >= best.t)`
    if (best.hit && t >= best.t) return;  // not earlier
    best = {true, t, point_in_frame + t * frame_velocity, normal};
  }
};

}  // namespace

// Seen from B, B stands still and A moves by d = va - vb (the delta matrix of step 6,
// for translations). Every family below is a segment against a still triangle, so the
// decisions are step 4's exact signs (decide); only t and the point are constructed.
MeshContact first_contact_moving_meshes(const Mesh& a, const Vec3& velocity_a, const Mesh& b, const Vec3& velocity_b) {
  require_valid("first_contact_moving_meshes", "a", a);
  require_valid("first_contact_moving_meshes", "b", b);
  require_finite("first_contact_moving_meshes", "velocity_a", velocity_a);
  require_finite("first_contact_moving_meshes", "velocity_b", velocity_b);
  // mutant absolute_motion (step 7, "relative motion"):
  //   `const Vec3 d = velocity_a - velocity_b;`
  //   -> `const Vec3 d = velocity_a;`
  const Vec3 d = velocity_a - velocity_b;  // relative, never absolute: B moves too
  Earliest earliest;
  // 1. A vertex p of A travels p -> p + d past B's faces; the point is in B's frame.
  for (const Vec3& p : a.vertices)
    for (std::size_t k = 0; k < b.size(); ++k) {
      const Decision h = decide({p, p + d}, b.triangle(k));
      if (h.hit) earliest.offer(h.t, p + h.t * d, velocity_b, facing(b.triangle(k).normal(), d));
    }
  // 2. Seen from A, B moves by -d: B's vertices against A's faces (the other delta matrix).
  // mutant one_delta_matrix (step 7, "vertex", "of B", "other delta matrix"): `b.vertices` -> `std::vector<Vec3>{}`
  for (const Vec3& q : b.vertices)
    for (std::size_t k = 0; k < a.size(); ++k) {
      const Decision h = decide({q, q - d}, a.triangle(k));
      if (h.hit) earliest.offer(h.t, q - h.t * d, velocity_a, facing(a.triangle(k).normal(), d));
    }
  // 3. An edge p0 p1 of A sweeps the parallelogram p0, p1, p1 + d, p0 + d (the 4D
  //    extrusion of the edge, in 3D): two triangles, against each edge q0 q1 of B. A hit
  //    point w0 p0 + w1 p1 + w2 (p1 + d) is reached at t = w2 (the weight of the moved
  //    corner); on the second triangle (p0, p1 + d, p0 + d) at t = w1 + w2.
  const auto edges_b = b.edges();
  // mutant vertex_face_only (step 7, "edge-edge"): `a.edges()` -> `std::vector<std::array<int, 2>>{}`
  for (const auto& [i, j] : a.edges()) {
    const Vec3& p0 = a.vertices[std::size_t(i)];
    const Vec3& p1 = a.vertices[std::size_t(j)];
    const Triangle first{p0, p1, p1 + d}, second{p0, p1 + d, p0 + d};
    for (const auto& [k, l] : edges_b) {
      const Segment edge{b.vertices[std::size_t(k)], b.vertices[std::size_t(l)]};
      // The classic shortcut: two edges' contact normal taken as the motion's direction. Only
      // e x f is normal to both edges; the motion crosses them at any angle.
      // mutant edge_contact_normal_along_motion (step 7, "(e x f) / |e x f|"):
      //   `const Vec3 normal = edge_pair_normal(p1 - p0, edge.b - edge.a, d);`
      //   -> `const Vec3 normal = -d.normalized();`
      const Vec3 normal = edge_pair_normal(p1 - p0, edge.b - edge.a, d);
      const SegmentTriangleHit h1 = hit_from(decide(edge, first), edge, first);
      if (h1.hit) earliest.offer(std::clamp(h1.barycentric[2], 0.0, 1.0), h1.point, velocity_b, normal);
      const SegmentTriangleHit h2 = hit_from(decide(edge, second), edge, second);
      if (h2.hit)
        earliest.offer(std::clamp(h2.barycentric[1] + h2.barycentric[2], 0.0, 1.0), h2.point, velocity_b, normal);
    }
  }
  return earliest.best;
}

}  // namespace labkit::lab02
