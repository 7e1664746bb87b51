// Lab 02 reference: segment against triangle and mesh.
//
// The one idea that makes it robust: decide with signs, then construct. Every yes/no
// below is the sign of a product of differences of input coordinates, never of a
// point we computed, so on small-integer input (the robustness step's) every decision
// is exact in double arithmetic. Points and parameters are built only after the
// decision, and only they carry rounding error.
#include "segment_triangle.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace labkit::lab02 {

namespace {

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
  // They meet: solve a + s d on the line P Q.
  const double s = cross(p - a, q - p) / cross(d, q - p);
  return std::clamp(s, 0.0, 1.0);
}

// The answer of both queries, decided once.
struct Decision {
  bool hit = false;
  double t = 0.0;
  Vec3 n = Vec3::Zero();  // the triangle's normal, unnormalised (when hit)
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
  if (inside_2d(a, p, turn)) t = 0.0;
  else
    for (int i = 0; i < 3; ++i) t = std::min(t, first_contact_2d(a, b, p[i], p[(i + 1) % 3]));
  if (!std::isfinite(t)) return d;  // the segment misses the triangle in its plane
  d.hit = true;
  d.t = t;
  d.n = n;
  return d;
}

// Both ends on the plane, to within the rounding error of d_a and d_b: then the volumes
// below are all zero up to that same rounding, and their signs are pure noise; the 2D
// test decides instead. A subtraction of two doubles is rounded relative to its result,
// so the error of d = (p - v0) . n stays below a few units of 1e-16 |p - v0| |e1| |e2|,
// whatever the coordinates' size; the bound is a thousand times that (compared squared,
// to spare the roots), and still far below 1 for integer input (|x| <= 1024), which is
// therefore treated as coplanar only when it is.
bool in_plane(double d_a, double d_b, const Vec3& a_to_v0, const Vec3& b_to_v0, const Vec3& e1, const Vec3& e2) {
  const double edges = 1e-26 * e1.squaredNorm() * e2.squaredNorm();
  return d_a * d_a <= edges * a_to_v0.squaredNorm() && d_b * d_b <= edges * b_to_v0.squaredNorm();
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
//   volume costs one subtraction, and on integer input it is still exact.
//
//          v2
//         /  \        V_0 belongs to edge v0 -> v1,
//    V_2 /    \ V_1   V_1 to edge v1 -> v2,
//       /  x   \      V_2 to edge v2 -> v0.
//     v0 ------ v1
//          V_0
Decision decide(const Segment& s, const Triangle& tri) {
  const Vec3 e1 = tri.v1 - tri.v0, e2 = tri.v2 - tri.v0;
  const Vec3 n = e1.cross(e2);
  // The vertices as seen from a, and where the segment goes.
  const Vec3 p0 = tri.v0 - s.a, p1 = tri.v1 - s.a, p2 = tri.v2 - s.a;
  const Vec3 direction = s.b - s.a;
  const double d_a = -p0.dot(n);               // (a - v0) . n
  const double d_b = d_a + direction.dot(n);  // (b - v0) . n
  if ((d_a > 0 && d_b > 0) || (d_a < 0 && d_b < 0)) return {};  // both ends strictly on one side
  if (n == Vec3::Zero()) return {};  // zero area: no plane, never hit
  if (d_a == 0 && d_b == 0) return decide_coplanar(s, tri, n);

  const double side = d_a > d_b ? 1.0 : -1.0;
  const double v0 = direction.dot(p0.cross(p1));
  if (side * v0 > 0) return {};  // x is outside edge v0 -> v1
  const double v1 = direction.dot(p1.cross(p2));
  if (side * v1 > 0) return {};  // outside edge v1 -> v2
  const double v2 = (d_b - d_a) - v0 - v1;
  if (side * v2 > 0) return {};  // outside edge v2 -> v0
  // A segment in the plane up to rounding passes the volume test by chance: in 2D.
  if (in_plane(d_a, d_b, p0, p0 - direction, e1, e2)) return decide_coplanar(s, tri, n);
  return {true, d_a / (d_a - d_b), n};
}

// Only now build the point, and describe that very point by its barycentric weights
// (step 3), so that t and the weights always tell the same story.
SegmentTriangleHit hit_from(const Decision& d, const Segment& s, const Triangle& tri) {
  if (!d.hit) return {};
  SegmentTriangleHit h;
  h.hit = true;
  h.t = d.t;
  h.point = s.point(d.t);
  const Barycentric b = barycentric(h.point, tri);
  h.barycentric = Vec3(1 - b.alpha - b.beta, b.alpha, b.beta);
  h.normal = d.n.normalized();
  return h;
}

MeshHit mesh_hit_from(const SegmentTriangleHit& h, int triangle) {
  return {h.hit, triangle, h.t, h.point, h.barycentric, h.normal};
}

}  // namespace

PlaneCrossing segment_plane(const Segment& segment, const Triangle& triangle) {
  const Vec3 n = triangle.normal();
  const double length = n.norm();
  if (length == 0) return {};  // a zero-area triangle has no plane
  PlaneCrossing c;
  c.d_a = (segment.a - triangle.v0).dot(n) / length;
  c.d_b = (segment.b - triangle.v0).dot(n) / length;
  // Both ends strictly on one side: no crossing. Both on the plane: no single point.
  if ((c.d_a > 0 && c.d_b > 0) || (c.d_a < 0 && c.d_b < 0)) return c;
  if (c.d_a == 0 && c.d_b == 0) return c;
  c.crosses = true;
  // d_a and d_b have opposite signs (or one is 0): d_a - d_b never cancels.
  c.t = c.d_a / (c.d_a - c.d_b);
  c.point = (c.d_a * segment.b - c.d_b * segment.a) / (c.d_a - c.d_b);
  return c;
}

bool point_in_triangle_edges(const Vec3& x, const Triangle& triangle) {
  const Vec3 n = triangle.normal();
  if (n == Vec3::Zero()) return false;
  for (int i = 0; i < 3; ++i) {
    const Vec3& from = triangle[i];
    const Vec3& to = triangle[(i + 1) % 3];
    // n x (to - from) lies in the plane and points into the triangle.
    if ((x - from).dot(n.cross(to - from)) < 0) return false;  // strictly outside edge i
  }
  return true;
}

Barycentric barycentric(const Vec3& x, const Triangle& triangle) {
  const Vec3 n = triangle.normal();
  if (n == Vec3::Zero()) return {};
  Barycentric b;
  b.dropped_axis = largest_axis(n);
  const Vec2 e1 = drop(triangle.v1 - triangle.v0, b.dropped_axis);
  const Vec2 e2 = drop(triangle.v2 - triangle.v0, b.dropped_axis);
  const Vec2 p = drop(x - triangle.v0, b.dropped_axis);
  // p = alpha e1 + beta e2; cross with e2, then with e1 (Cramer's rule). The
  // denominator is n[axis], the largest component: never zero here.
  const double denominator = cross(e1, e2);
  b.alpha = cross(p, e2) / denominator;
  b.beta = cross(e1, p) / denominator;
  return b;
}

bool point_in_triangle_barycentric(const Vec3& x, const Triangle& triangle) {
  const Vec3 n = triangle.normal();
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
  return decide(segment, triangle).hit;
}

SegmentTriangleHit find_segment_triangle(const Segment& segment, const Triangle& triangle) {
  return hit_from(decide(segment, triangle), segment, triangle);
}

MeshHit first_hit(const Segment& segment, const Mesh& mesh) {
  MeshHit best;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle tri = mesh.triangle(i);
    const Decision d = decide(segment, tri);
    if (!d.hit || (best.hit && d.t >= best.t)) continue;  // a miss, or not nearer
    best = mesh_hit_from(hit_from(d, segment, tri), int(i));
  }
  return best;
}

bool any_hit(const Segment& segment, const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.size(); ++i)
    if (decide(segment, mesh.triangle(i)).hit) return true;
  return false;
}

std::vector<MeshHit> all_hits(const Segment& segment, const Mesh& mesh) {
  std::vector<MeshHit> hits;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle tri = mesh.triangle(i);
    const Decision d = decide(segment, tri);
    if (d.hit) hits.push_back(mesh_hit_from(hit_from(d, segment, tri), int(i)));
  }
  std::sort(hits.begin(), hits.end(), [](const MeshHit& x, const MeshHit& y) {
    return x.t != y.t ? x.t < y.t : x.triangle < y.triangle;
  });
  return hits;
}

// The lecture's delta matrix M_delta = M0^-1 M1 carries a to where it sits relative to
// the mesh at the end of the step. We go one step further and express the whole
// segment in the mesh's own frame, a' = M0^-1 a and b' = M1^-1 b: one transform per
// end instead of one per mesh vertex. The hit found there goes back to the world by M1.
MeshHit first_hit_moving(const Segment& segment, const Mesh& mesh, const RigidTransform& m0,
                         const RigidTransform& m1) {
  const Segment local{m0.inverse() * segment.a, m1.inverse() * segment.b};
  MeshHit hit = first_hit(local, mesh);
  if (!hit.hit) return hit;
  hit.point = m1 * hit.point;
  hit.normal = m1.linear() * hit.normal;
  return hit;
}

}  // namespace labkit::lab02
