// Lab 03 reference: separating axes.
//
// Two boxes are compared in A's frame (Gottschalk's OBB test, as in Eberly's book):
// R(i, j) = A_i . B_j holds B's axes as columns, t = A^T (c_B - c_A) the offset, and
// every one of the 15 axes becomes a few products of entries of R and t. The face
// axes are tested first (they settle most separated pairs), then the 9 edge axes.
//
// The one idea that makes it robust: test along the vector you computed. Any direction
// at all is a valid separating axis, so the only danger is rounding, and rounding is
// harmless when every term of the comparison |s| > r_A + r_B is a product with a
// component of the axis itself: its error then shrinks with the axis, and an axis that
// comes out exactly zero gives 0 > 0, which separates nothing. The textbook shortcut
// breaks that rule for the edge axes (see edge_axis below), and so does any fixed
// epsilon meant to repair it.
#include "separating_axes.h"

#include "common/preconditions.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace labkit::lab03 {

namespace {

// ---- The header's preconditions: rejected with std::invalid_argument, naming the
// argument and the rule. A NaN would otherwise fail every comparison and pass for
// "no axis separates them", and a negative half extent would shrink the radii.

using namespace preconditions;

void require_motion(const char* function, const Box& a, const Vec3& velocity_a, const Box& b, const Vec3& velocity_b,
                    double duration) {
  require_valid(function, "a", a);
  require_valid(function, "b", b);
  require_finite(function, "velocity_a", velocity_a);
  require_finite(function, "velocity_b", velocity_b);
  require_size(function, "duration", duration);
}

// Edge axes shorter than this (|A_i x B_j| < 1e-6) are left out of the search for the
// least penetration: rounding turns them by up to about 1e-16 / |A_i x B_j| radians.
constexpr double kShortAxis2 = 1e-12;

// The two indices after i, in cyclic order: (i, k, l) is (0, 1, 2), (1, 2, 0) or (2, 0, 1).
int next(int i) { return i == 2 ? 0 : i + 1; }
int after_next(int i) { return i == 0 ? 2 : i - 1; }

// One axis L, written in A's frame, and what the test needs along it:
//   s = (c_B - c_A) . L    the centres' offset,
//   r = r_A + r_B          the sum of the projected radii,
//   ds = (v_B - v_A) . L   how fast s changes when the boxes move,
//   length2 = |L|^2.
// L separates the boxes when |s| > r; the depth along the unit axis is (r - |s|) / |L|.
struct AxisTest {
  double s = 0.0;
  double r = 0.0;
  double ds = 0.0;
  double length2 = 1.0;
  Vec3 local = Vec3::Zero();  // L in A's frame
};

// Everything the 15 axes are made of, in A's frame.
struct Pair {
  Mat3 R;     // R(i, j) = A_i . B_j
  Vec3 t;     // A^T (c_B - c_A)
  Vec3 w;     // A^T (v_B - v_A): the relative velocity (zero for static boxes)
  Vec3 a, b;  // half extents
  Mat3 C;     // the cofactors of R (filled by cofactors() before the edge axes)

  Pair(const Box& box_a, const Box& box_b, const Vec3& velocity)
      : R(box_a.axes.transpose() * box_b.axes),
        // The centres' offset c_B - c_A left in world coordinates while R and the radii are
        // in A's frame: it must be expressed in A's frame too, t = A^T (c_B - c_A).
        // mutant offset_not_in_a_frame (step 2, "projections", "A's frame"):
        //   `t(box_a.axes.transpose() * (box_b.center - box_a.center)),`
        //   -> `t(box_b.center - box_a.center),`
        t(box_a.axes.transpose() * (box_b.center - box_a.center)),
        w(box_a.axes.transpose() * velocity),
        a(box_a.half_extents),
        b(box_b.half_extents) {}

  // Column n of C is R_col(n+1) x R_col(n+2). For an exact rotation C = R, which is the
  // identity the textbook uses; for ours they differ by rounding, and only C keeps the
  // error proportional to the edge axis (see edge_axis).
  void cofactors() {
    for (int n = 0; n < 3; ++n) C.col(n) = R.col(next(n)).cross(R.col(after_next(n)));
  }

  // Axis 0..2: A_i. In A's frame it is e_i: s = t_i, r_A = a_i, r_B = sum_j b_j |R(i, j)|.
  AxisTest face_a(int i) const {
    AxisTest x;
    x.s = t[i];
    x.ds = w[i];
    // mutant epsilon_guard (step 2, "separating axis", "epsilon"):
    //   `x.r = a[i] + b[0] * std::abs(R(i, 0)) + b[1] * std::abs(R(i, 1)) + b[2] * std::abs(R(i, 2));`
    //   -> `x.r = a[i] + b[0] * (std::abs(R(i, 0)) + 1e-6) + b[1] * (std::abs(R(i, 1)) + 1e-6) + b[2] * (std::abs(R(i,
    //     2)) + 1e-6);`
    x.r = a[i] + b[0] * std::abs(R(i, 0)) + b[1] * std::abs(R(i, 1)) + b[2] * std::abs(R(i, 2));
    x.local = Vec3::Unit(i);
    return x;
  }

  // Axis 3..5: B_j, which in A's frame is column j of R.
  AxisTest face_b(int j) const {
    AxisTest x;
    x.s = t.dot(R.col(j));
    x.ds = w.dot(R.col(j));
    x.r = a[0] * std::abs(R(0, j)) + a[1] * std::abs(R(1, j)) + a[2] * std::abs(R(2, j)) + b[j];
    x.local = R.col(j);
    return x;
  }

  // Axis 6 + 3 i + j: L = A_i x B_j, in A's frame e_i x R_col(j). With (i, k, l) cyclic
  // its components are L_i = 0, L_k = -R(l, j), L_l = R(k, j), so
  //   s   = t_l R(k, j) - t_k R(l, j)
  //   r_A = a_k |R(l, j)| + a_l |R(k, j)|
  //   r_B = sum over m != j of b_m |B_m . L|,  B_m . L = R_col(m) . L = +-C(i, n)
  // (n the third index besides j and m). Each term holds R(k, j) or R(l, j), the
  // components of L: an axis that is small because A_i and B_j are nearly parallel
  // gives a comparison whose rounding is small in proportion, and a zero axis gives
  // 0 > 0. The textbook writes R(i, n) for C(i, n) (equal for an exact rotation): its
  // rounding, about 1e-16, does not shrink with L, and near-parallel edges then report
  // separations that are not there; the usual repair adds an epsilon to |R| and in
  // turn misses gaps of up to about sqrt(epsilon) S.
  AxisTest edge_axis(int i, int j) const {
    const int k = next(i), l = after_next(i);
    const int m = next(j), n = after_next(j);
    AxisTest x;
    x.s = t[l] * R(k, j) - t[k] * R(l, j);
    x.ds = w[l] * R(k, j) - w[k] * R(l, j);
    // mutant textbook_radius (step 2, "nearly parallel"):
    //   `C(i, n)) + b[n] * std::abs(C`
    //   -> `R(i, n)) + b[n] * std::abs(R`
    x.r = a[k] * std::abs(R(l, j)) + a[l] * std::abs(R(k, j)) + b[m] * std::abs(C(i, n)) + b[n] * std::abs(C(i, m));
    x.length2 = R(k, j) * R(k, j) + R(l, j) * R(l, j);
    x.local[i] = 0.0;
    x.local[k] = -R(l, j);
    x.local[l] = R(k, j);
    return x;
  }

  AxisTest axis(int index) const {
    if (index < 3) return face_a(index);
    if (index < 6) return face_b(index - 3);
    return edge_axis((index - 6) / 3, (index - 6) % 3);
  }
};

// The strict test: touching projections (|s| == r) do not separate.
// mutant touching_boxes_separate (step 2, "nearly parallel", "zero axis"): `>` -> `>=`
// >= for >, with the usual guard that skips short axes (so that parallel edges, a zero
// axis, no longer give it away): only exactly touching boxes show it.
// mutant touching_faces_apart (step 6, "only touch", "strict"):
//   `std::abs(x.s) >`
//   -> `x.length2 > 1e-20 && std::abs(x.s) >=`
bool separates(const AxisTest& x) { return std::abs(x.s) > x.r; }

// The unit axis in the world, pointing from A toward B, and the depth along it.
void describe_axis(BoxContact& c, const AxisTest& x, int index, const Box& a) {
  const double length = std::sqrt(x.length2);
  c.axis_index = index;
  c.axis = a.axes * x.local / length;
  // mutant axis_not_toward_b (step 3, "from A toward B"): `if (x.s < 0) c.axis = -c.axis;` -> ``
  if (x.s < 0) c.axis = -c.axis;
  // mutant depth_not_normalized (step 3, "unit axis", "divide by |L|"):
  //   `(x.r - std::abs(x.s)) / length`
  //   -> `x.r - std::abs(x.s)`
  c.depth = (x.r - std::abs(x.s)) / length;
}

}  // namespace

Projection project_box(const Box& box, const Vec3& axis) {
  require_valid("project_box", "box", box);
  require_finite("project_box", "axis", axis);
  Projection p;
  p.center = box.center.dot(axis);
  // The corner farthest along L takes, on each box axis, the side where A_k . L >= 0.
  // mutant radius_without_abs (step 1, "absolute value"):
  //   `std::abs(box.axes.col(k).dot(axis)`
  //   -> `box.axes.col(k).dot(axis`
  for (int k = 0; k < 3; ++k) p.radius += box.half_extents[k] * std::abs(box.axes.col(k).dot(axis));
  return p;
}

bool separated_on_axis(const Box& a, const Box& b, const Vec3& axis) {
  require_valid("separated_on_axis", "a", a);
  require_valid("separated_on_axis", "b", b);
  require_finite("separated_on_axis", "axis", axis);
  const double s = (b.center - a.center).dot(axis);
  const double r = project_box(a, axis).radius + project_box(b, axis).radius;
  // mutant touching_intervals_separate (step 1, "touching", "strict"): `> r` -> `>= r`
  return std::abs(s) > r;  // a zero axis gives 0 > 0: never separated
}

Vec3 box_axis(const Box& a, const Box& b, int index) {
  require_valid("box_axis", "a", a);
  require_valid("box_axis", "b", b);
  require(index >= 0 && index <= 14, "box_axis", "index", "be 0 to 14", index);
  if (index < 3) return a.axes.col(index);
  // B's face axis read as a row of its rotation matrix: its axes are the columns.
  // mutant b_axis_from_a_row (step 2, "B's column"): `b.axes.col(index - 3)` -> `b.axes.row(index - 3).transpose()`
  if (index < 6) return b.axes.col(index - 3);
  const int i = (index - 6) / 3, j = (index - 6) % 3;
  // mutant edge_axis_normalized (step 2, "not normalised"):
  //   `cross(b.axes.col(j))`
  //   -> `cross(b.axes.col(j)).normalized()`
  return a.axes.col(i).cross(b.axes.col(j));
}

bool test_boxes(const Box& a, const Box& b) {
  require_valid("test_boxes", "a", a);
  require_valid("test_boxes", "b", b);
  Pair p(a, b, Vec3::Zero());
  // Face axes first: for boxes far apart one of them nearly always separates.
  for (int i = 0; i < 3; ++i)
    if (separates(p.face_a(i))) return false;
  for (int j = 0; j < 3; ++j)
    if (separates(p.face_b(j))) return false;
  // mutant face_axes_only (step 2, "separating axis", "edge axes"):
  //   `p.cofactors(); for (int i = 0; i < 3; ++i) for (int j = 0; j < 3; ++j) if (separates(p.edge_axis(i, j))) return
  //     false;`
  //   -> ``
  p.cofactors();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (separates(p.edge_axis(i, j))) return false;
  return true;  // no axis separates: the boxes touch or overlap
}

BoxContact find_boxes(const Box& a, const Box& b) {
  require_valid("find_boxes", "a", a);
  require_valid("find_boxes", "b", b);
  Pair p(a, b, Vec3::Zero());
  p.cofactors();
  BoxContact contact;
  contact.intersecting = true;
  double least = 0.0;
  for (int index = 0; index < 15; ++index) {
    const AxisTest x = p.axis(index);
    if (separates(x)) {  // separated: report this axis and the gap along it
      BoxContact apart;
      describe_axis(apart, x, index, a);
      return apart;
    }
    if (x.length2 < kShortAxis2) continue;  // nearly parallel edges: direction too uncertain
    const double depth = (x.r - std::abs(x.s)) / std::sqrt(x.length2);
    // mutant deepest_axis (step 3, "least penetration"): `depth <` -> `depth >`
    if (contact.axis_index < 0 || depth < least) {
      least = depth;
      describe_axis(contact, x, index, a);
    }
  }
  return contact;
}

// ---- Step 4, first: the lecture's interval method, as the slides give it ---------------
//
//          p            d_p > 0         t1's plane meets t0 along the line L (direction
//         / \                           D = n0 x n1); the edges p q and p r cross it at
//   -----x---x-----     d = 0           x = p + (q - p) d_p / (d_p - d_q), read on the
//       /     \                         coordinate k of the largest |D_k|: an interval.
//      q-------r        d_q, d_r < 0    The same for t1 in t0's plane; overlap or not.
//
// Exact only where every ratio is well away from 0/0 and rounding (the header's domain):
// the ends are built numbers, and two ends that (nearly) coincide compare by rounding.

namespace {

// One triangle's segment in the other's plane, on coordinate k. d holds the signed
// volumes of t's vertices against that plane, all non-zero and not all of one sign.
std::pair<double, double> interval_on_line(const Triangle& t, const double d[3], int k) {
  // p: the vertex whose side the other two do not share.
  // mutant ratio_from_wrong_vertex (step 4, "alone on its side"): `1 : 0` -> `0 : 1`
  const int p = (d[0] > 0) == (d[1] > 0) ? 2 : ((d[0] > 0) == (d[2] > 0) ? 1 : 0);
  const int q = next(p), r = after_next(p);
  // Similar triangles: the crossing splits edge p q in the ratio d_p : -d_q.
  const double end_q = t[p][k] + (t[q][k] - t[p][k]) * (d[p] / (d[p] - d[q]));
  const double end_r = t[p][k] + (t[r][k] - t[p][k]) * (d[p] / (d[p] - d[r]));
  // The lecture's interval method (triangles_by_intervals).
  // mutant intervals_not_sorted (step 4, "sort", "low <= high"):
  //   `return {std::min(end_q, end_r), std::max(end_q, end_r)};`
  //   -> `return {end_q, end_r};`
  return {std::min(end_q, end_r), std::max(end_q, end_r)};  // the ends come in either order
}

// The signed volumes of `of`'s vertices against t's plane; false when one of them is 0
// or all three share a sign (the lecture's method then has no segment to build).
bool straddles(const Triangle& t, const Triangle& of, double d[3]) {
  const Vec3 n = t.normal();
  for (int i = 0; i < 3; ++i) d[i] = n.dot(of[i] - t.v0);
  const bool zero = d[0] == 0 || d[1] == 0 || d[2] == 0;
  const bool one_side = (d[0] > 0) == (d[1] > 0) && (d[1] > 0) == (d[2] > 0);
  return !zero && !one_side;
}

}  // namespace

LineIntervals triangles_by_intervals(const Triangle& t0, const Triangle& t1) {
  require_valid("triangles_by_intervals", "t0", t0);
  require_valid("triangles_by_intervals", "t1", t1);
  LineIntervals out;
  double d0[3], d1[3];  // t0's vertices against t1's plane, t1's against t0's
  if (!straddles(t1, t0, d0) || !straddles(t0, t1, d1)) return out;  // no crossing segments
  const Vec3 m = t0.normal().cross(t1.normal()).cwiseAbs();          // |D_k|, D = n0 x n1
  // The coordinate that varies most along the line (never one where D_k = 0, which
  // would read every point of the line as the same number).
  // mutant line_on_smallest_coordinate (step 4, "largest"):
  //   `out.axis = m.x() >= m.y() && m.x() >= m.z() ? 0 : (m.y() >= m.z() ? 1 : 2);`
  //   -> `out.axis = m.x() <= m.y() && m.x() <= m.z() ? 0 : (m.y() <= m.z() ? 1 : 2);`
  out.axis = m.x() >= m.y() && m.x() >= m.z() ? 0 : (m.y() >= m.z() ? 1 : 2);
  out.crossing = true;
  std::tie(out.low0, out.high0) = interval_on_line(t0, d0, out.axis);
  std::tie(out.low1, out.high1) = interval_on_line(t1, d1, out.axis);
  out.overlap = out.low0 <= out.high1 && out.low1 <= out.high0;  // closed: touching ends overlap
  return out;
}

//   Derivation (lecture 003, "narrow phase between triangles"). If neither triangle
//   lies wholly on one side of the other's plane, each meets the other's plane in a
//   segment, and both segments lie on the line where the planes meet, L = O + u D,
//   D = n0 x n1. The triangles intersect exactly when the two segments overlap on L.
//   The lecture computes the four ends as numbers u (interpolating along the edges
//   that cross) and compares them. Every such comparison is the sign of one volume:
//   the end of T0's segment on edge p0 q0 lies before the end of T1's segment on edge
//   p1 q1 exactly when orient(p0, q0, p1, q1) has a known sign. So, as in lab 02, we
//   decide with signs of input-only products and never build the ends at all.
//
//   Canonical form (Guigue and Devillers): rotate each triangle's vertices so that p is
//   the one alone on its side of the other's plane, with p on the positive side and q,
//   r on the other (or on the plane); swapping the other triangle's q and r flips the
//   side. Then T0's segment runs from edge p0 q0 to edge p0 r0, T1's from p1 q1 to p1 r1,
//   and they overlap exactly when
//       orient(p0, q0, p1, q1) <= 0   and   orient(p0, r0, r1, p1) <= 0.
//
//          p0            above T1's plane     orient(a, b, c, d) = ((b - a) x (c - a)) . (d - a)
//         /  |
//   -----x---x-----      T1's plane           x: where edges p0 q0 and p0 r0 cross it
//       /    |
//     q0 --- r0          below (or on) it

namespace {

double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return (b - a).cross(c - a).dot(d - a); }

int sign(double x) { return (x > 0) - (x < 0); }

// The plane of a triangle, built where rounding hurts least: at the vertex opposite the
// longest edge, from the two shortest edges. A cross product is off by a few units of
// 1e-16 of |e_a| |e_b|; with the two long edges of a needle (aspect 1e8) that is 1e8 times
// its area, and the "normal" then tilts by up to 1e-8 rad: enough to take a triangle
// turned by 1e-7 for coplanar, or to give a vertex off the plane the wrong side.
struct Plane3 {
  Vec3 at;             // the vertex between the two shortest edges
  Vec3 n;              // e_a x e_b: the normal, |n| twice the area
  double edges = 0.0;  // |e_a| |e_b|: the scale of n's rounding
};

Plane3 plane_of(const Triangle& t) {
  int k = 0;  // the vertex opposite the longest edge
  double longest = -1.0;
  for (int i = 0; i < 3; ++i) {
    const double l = (t[next(i)] - t[after_next(i)]).squaredNorm();
    if (l > longest) longest = l, k = i;
  }
  const Vec3 ea = t[next(k)] - t[k], eb = t[after_next(k)] - t[k];
  return {t[k], ea.cross(eb), ea.norm() * eb.norm()};
}

// The side signs of v0, v1, v2 with respect to the plane of `t`, with the test for
// "all three in the plane". d = (q - at) . n is off by at most about 1.2e-15 |q - at|
// |e_a| |e_b| (the rounding of e_a, e_b, n and the dot product); below a bound of
// 4e-15 times that its sign is not known, and the vertex counts as in the plane. For a
// triangle whose shortest edges meet at a good angle, that is a turn of 4e-15 rad. On
// small integer input (|x| <= 1024) the bound is below 1 while every non-zero volume is
// an integer: exact input is coplanar only when it truly is.
struct Sides {
  int sign[3] = {0, 0, 0};
  bool coplanar = false;
};

Sides sides(const Triangle& t, const Triangle& of) {
  // mutant needle_normal_at_any_vertex (step 4, "needle", "shortest edges"):
  //   `const Plane3 plane = plane_of(t);`
  //   -> `const Plane3 plane{t.v0, t.normal(), (t.v1 - t.v0).norm() * (t.v2 - t.v0).norm()};`
  const Plane3 plane = plane_of(t);
  Sides s;
  for (int i = 0; i < 3; ++i) {
    const double d = (of[i] - plane.at).dot(plane.n);
    // mutant coplanar_only_when_exactly_zero (step 4, "coplanar up to rounding"):
    //   `const bool in_plane = std::abs(d) <= 4e-15 * (of[i] - plane.at).norm() * plane.edges;`
    //   -> `const bool in_plane = d == 0;`
    const bool in_plane = std::abs(d) <= 4e-15 * (of[i] - plane.at).norm() * plane.edges;
    s.sign[i] = in_plane ? 0 : sign(d);
  }
  s.coplanar = s.sign[0] == 0 && s.sign[1] == 0 && s.sign[2] == 0;
  return s;
}

bool one_side(const Sides& s) {
  return (s.sign[0] > 0 && s.sign[1] > 0 && s.sign[2] > 0) || (s.sign[0] < 0 && s.sign[1] < 0 && s.sign[2] < 0);
}

// Rotates t so that its vertex 0 is alone on its side, and says whether the other
// triangle's plane must be flipped so that vertex 0 is on its positive side:
// afterwards sign(p) >= 0, sign(q) <= 0, sign(r) <= 0, and not all zero.
bool canonical(Triangle& t, const Sides& s) {
  for (int k = 0; k < 3; ++k) {
    const int p = s.sign[k], q = s.sign[next(k)], r = s.sign[after_next(k)];
    for (const int flip : {1, -1}) {
      if (flip * p >= 0 && flip * q <= 0 && flip * r <= 0 && (flip * p > 0 || (flip * q < 0 && flip * r < 0))) {
        t = {t[k], t[next(k)], t[after_next(k)]};
        return flip < 0;
      }
    }
  }
  return false;  // unreachable: the caller rejected "all on one side" and "all zero"
}

// In the plane: drop the normal's largest coordinate and run the 2D separating axis
// test with the six edge normals. Projection along a coordinate keeps every
// separation, and the 2D normals of the edges are exact in the input's numbers.
bool coplanar_triangles_intersect(const Triangle& t0, const Triangle& t1) {
  const Vec3 n = plane_of(t0).n.cwiseAbs();
  const int drop = n.x() >= n.y() && n.x() >= n.z() ? 0 : (n.y() >= n.z() ? 1 : 2);
  const auto flat = [drop](const Vec3& p) { return Vec2(p[next(drop)], p[after_next(drop)]); };
  const Vec2 p[3] = {flat(t0.v0), flat(t0.v1), flat(t0.v2)};
  const Vec2 q[3] = {flat(t1.v0), flat(t1.v1), flat(t1.v2)};
  for (const Vec2* poly : {p, q})
    for (int i = 0; i < 3; ++i) {
      const Vec2 e = poly[next(i)] - poly[i];
      const Vec2 normal(-e.y(), e.x());
      double min0 = normal.dot(p[0]), max0 = min0, min1 = normal.dot(q[0]), max1 = min1;
      for (int k = 1; k < 3; ++k) {
        min0 = std::min(min0, normal.dot(p[k]));
        max0 = std::max(max0, normal.dot(p[k]));
        min1 = std::min(min1, normal.dot(q[k]));
        max1 = std::max(max1, normal.dot(q[k]));
      }
      if (max0 < min1 || max1 < min0) return false;  // this edge's normal separates them
    }
  return true;
}

}  // namespace

bool test_triangles(const Triangle& t0, const Triangle& t1) {
  require_valid("test_triangles", "t0", t0);
  require_valid("test_triangles", "t1", t1);
  if (t0.normal() == Vec3::Zero() || t1.normal() == Vec3::Zero()) return false;  // zero area: no plane
  const Sides s1 = sides(t0, t1);                                                // T1's vertices against T0's plane
  if (one_side(s1)) return false;  // T1 lies strictly on one side of T0's plane
  const Sides s0 = sides(t1, t0);  // T0's vertices against T1's plane
  if (one_side(s0)) return false;
  // mutant coplanar_is_a_miss (step 4, "coplanar", "overlap in their plane"):
  //   `coplanar_triangles_intersect(t0, t1)`
  //   -> `false`
  if (s1.coplanar || s0.coplanar) return coplanar_triangles_intersect(t0, t1);
  Triangle a = t0, b = t1;
  const bool flip_b = canonical(a, s0);  // a's vertex 0 above b's plane
  const bool flip_a = canonical(b, s1);
  if (flip_b) std::swap(b.v1, b.v2);  // swapping b's q and r flips b's plane
  if (flip_a) std::swap(a.v1, a.v2);
  // The two segments on L overlap: T1's starts before T0's ends, and ends after it starts.
  // mutant interval_ends_strict (step 4, "touch"):
  //   `return orient(a.v0, a.v1, b.v0, b.v1) <= 0 && orient(a.v0, a.v2, b.v2, b.v0) <= 0;`
  //   -> `return orient(a.v0, a.v1, b.v0, b.v1) < 0 && orient(a.v0, a.v2, b.v2, b.v0) < 0;`
  return orient(a.v0, a.v1, b.v0, b.v1) <= 0 && orient(a.v0, a.v2, b.v2, b.v0) <= 0;
}

// Two moving boxes. In B's motion relative to A, W = v_B - v_A, the offset along an
// axis L is s + t ds at time t. On a face or edge axis the projections overlap while
//   |s + t ds| <= r,   i.e. for t between (-r - s) / ds and (r - s) / ds,
// and the boxes overlap exactly when they overlap on all 15 axes: the contact times
// are the intersection of 15 intervals with [0, duration]. (The axes do not turn: the
// boxes only translate.)
ContactInterval find_moving_boxes(const Box& a, const Vec3& velocity_a, const Box& b, const Vec3& velocity_b,
                                  double duration) {
  require_motion("find_moving_boxes", a, velocity_a, b, velocity_b, duration);
  Pair p(a, b, velocity_b - velocity_a);
  p.cofactors();
  // How far rounding can move a time (r - s) / ds: s and r are sums of products whose
  // size is at most `size` |L|, each good to a few units of 1e-16 of that.
  const double size = (b.center - a.center).norm() + a.half_extents.sum() + b.half_extents.sum();
  double first = 0.0, last = duration, first_error = 0.0, last_error = 0.0;
  double surely_before = 0.0, surely_after = duration;  // widened by the errors
  for (int index = 0; index < 15; ++index) {
    const AxisTest x = p.axis(index);
    // No motion along this axis, or less over the whole duration than the rounding of s
    // and r (then the times below would be rounding noise): a static test.
    const double noise = 4e-15 * size * std::sqrt(x.length2);
    // mutant times_from_rounding_noise (step 5, "rounding noise"): `std::abs(x.ds) * duration <= noise` -> `x.ds == 0`
    if (std::abs(x.ds) * duration <= noise) {
      // An axis along which B does not move tested with >= for >: boxes sliding along
      // each other while touching come out apart for the whole frame.
      // mutant sliding_contact_apart (step 7, "does not move", "strictly"):
      //   `separates(x)`
      //   -> `x.length2 > 0 && std::abs(x.s) >= x.r`
      if (separates(x)) return {};  // apart on this axis at every time: never
      continue;                     // overlapping on it at every time: no constraint
    }
    double enter = (-x.r - x.s) / x.ds, leave = (x.r - x.s) / x.ds;
    // mutant enter_leave_not_swapped (step 5, "entering time"): `if (x.ds < 0) std::swap(enter, leave);` -> ``
    if (x.ds < 0) std::swap(enter, leave);
    const double error = noise / std::abs(x.ds) + 4e-15 * std::max(std::abs(enter), std::abs(leave));
    if (enter > first) first = enter, first_error = error;
    if (leave < last) last = leave, last_error = error;
    surely_before = std::max(surely_before, enter - error);
    surely_after = std::min(surely_after, leave + error);
  }
  // Apart beyond any rounding: some axis leaves before another enters, by more than
  // both their errors.
  if (surely_before > surely_after) return {};
  if (first > last) {
    // Exactly one common time, up to rounding: flat boxes (zero half extents) that pass
    // through each other touch for a single instant, the enter time of one axis equal
    // to the leave time of another, and rounding may put the two in either order. A
    // wider gap between them than their errors: they never touch.
    // mutant an_instant_is_no_contact (step 5, "single instant"):
    //   `if (first - last > first_error + last_error) return {};`
    //   -> `return {};`
    if (first - last > first_error + last_error) return {};
    // The instant is the better known of the two times: the one from the axis along which
    // B moves faster. At it the slower axis is off by only its rounding (|ds| times its
    // error), while a time from the slower axis (or halfway) can leave the faster one
    // apart by far more than tol.
    first = last = std::clamp(first_error <= last_error ? first : last, 0.0, duration);
  }
  return {true, first, last};
}

// The test query over the whole motion (lecture 000, table 6.7). On each of the 15
// axes, B's projection sweeps from s to s + duration ds: apart when both ends are beyond
// r on the same side. Six more axes are needed, perpendicular to the motion, W x A_i and
// W x B_j: along them nothing moves and the test is the static |s| > r.
bool test_moving_boxes(const Box& a, const Vec3& velocity_a, const Box& b, const Vec3& velocity_b, double duration) {
  require_motion("test_moving_boxes", a, velocity_a, b, velocity_b, duration);
  Pair p(a, b, velocity_b - velocity_a);
  p.cofactors();
  for (int index = 0; index < 15; ++index) {
    const AxisTest x = p.axis(index);
    const double s0 = x.s, s1 = x.s + duration * x.ds;
    if (std::min(s0, s1) > x.r || std::max(s0, s1) < -x.r) return false;  // swept, still apart
  }
  // W x A_i, in A's frame w x e_i: components L_k = w_l, L_l = -w_k (i, k, l cyclic).
  // Table 6.7: R0 = a_k |w_l| + a_l |w_k|, R1 = sum_m b_m |B_m . L|, R = |t . L|.
  for (int i = 0; i < 3; ++i) {
    const int k = next(i), l = after_next(i);
    const double s = p.t[k] * p.w[l] - p.t[l] * p.w[k];
    double r = p.a[k] * std::abs(p.w[l]) + p.a[l] * std::abs(p.w[k]);
    for (int m = 0; m < 3; ++m) r += p.b[m] * std::abs(p.R(k, m) * p.w[l] - p.R(l, m) * p.w[k]);
    // The motion axes left out, W x A_i and W x B_j alike (both loops).
    // mutant no_motion_axes (step 5, "W x A_i"): `if (std::abs(s) > r) return false;` -> ``
    if (std::abs(s) > r) return false;
  }
  // W x B_j, in B's frame w_B x e_j, with w_B = R^T w and t_B = R^T t. Now B's radius
  // is the short one, and A's takes the dot products with the rows of R.
  const Vec3 wb = p.R.transpose() * p.w, tb = p.R.transpose() * p.t;
  for (int j = 0; j < 3; ++j) {
    const int k = next(j), l = after_next(j);
    const double s = tb[k] * wb[l] - tb[l] * wb[k];
    double r = p.b[k] * std::abs(wb[l]) + p.b[l] * std::abs(wb[k]);
    for (int m = 0; m < 3; ++m) r += p.a[m] * std::abs(p.R(m, k) * wb[l] - p.R(m, l) * wb[k]);
    // mutant no_motion_axes (step 5, "W x A_i"): `if (std::abs(s) > r) return false;` -> ``
    if (std::abs(s) > r) return false;
  }
  return true;
}

}  // namespace labkit::lab03
