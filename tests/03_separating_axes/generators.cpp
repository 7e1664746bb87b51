#include "common/generators/generators.h"
#include "03_separating_axes/judge.h"
#include "common/generators/grid.h"
#include "common/harness/codec.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace labkit::gen {

namespace {

constexpr double kFraction = 1.0 / (1 << 20);

// Where a family draws its numbers (its Grid): the fine dyadic lattice with rounded
// rotations, or (exact) multiples of 8 units with |x| <= 1024 units and signed-permutation
// axes. Box pairs in contact carry one more switch.
struct BoxGrid : Grid {
  bool touching = false;  // rounded pairs may touch exactly (the moving boxes' contacts)
};

// A number of units with a 20-bit fraction, or (exact) a multiple of 8 units.
double length(Grid g, int low, int high) {
  const int n = *rc::gen::inRange(low, high + 1);
  if (g.exact) return 8 * n * g.s;
  return (n + kFraction * *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 1 << 20))) * g.s;
}

Mat3 permutation(int order, int signs) {
  static const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  Mat3 m = Mat3::Zero();
  for (int k = 0; k < 3; ++k) m(orders[order][k], k) = (signs >> k) & 1 ? -1.0 : 1.0;
  return m;
}

rc::Gen<Mat3> signed_permutation() {
  return rc::gen::exec([] { return permutation(*rc::gen::inRange(0, 6), *rc::gen::inRange(0, 8)); });
}

rc::Gen<Mat3> quaternion_rotation() {
  return rc::gen::exec([] {
    Eigen::Quaterniond q(*integer(4), *integer(4), *integer(4), *integer(4));
    if (q.squaredNorm() == 0) q = Eigen::Quaterniond(1, 0, 0, 0);
    return Mat3(q.normalized().toRotationMatrix());
  });
}

// B's axes, related to A's on purpose: independent; a signed permutation of A's (every
// edge exactly parallel to one of A's); A's turned by 2^-k about some axis (nearly
// parallel); or sharing one axis exactly with A, turned about it.
Mat3 related_axes(const Mat3& a, bool exact) {
  if (exact) return a * *signed_permutation();
  switch (*rc::gen::inRange(0, 4)) {
    case 0: return *rotation();
    case 1: return a * *signed_permutation();
    case 2: {
      const Vec3 axis = Vec3(*direction(1.0, 4)).normalized();
      const double angle = (*rc::gen::element(-1.0, 1.0)) * std::ldexp(1.0, -*rc::gen::inRange(4, 53));
      return Mat3(a * Eigen::AngleAxisd(angle, axis).toRotationMatrix() * *signed_permutation());
    }
    default: {
      const int k = *rc::gen::inRange(0, 3);
      Vec3 turn(*integer(4), *integer(4), 0);
      if (turn.isZero()) turn = Vec3(1, 1, 0);
      turn.normalize();
      Mat3 b;
      b.col(k) = a.col(k);
      b.col((k + 1) % 3) = turn.x() * a.col((k + 1) % 3) + turn.y() * a.col((k + 2) % 3);
      b.col((k + 2) % 3) = -turn.y() * a.col((k + 1) % 3) + turn.x() * a.col((k + 2) % 3);
      return Mat3(b * *signed_permutation());
    }
  }
}

Vec3 half_extents(Grid g) {
  Vec3 h;
  for (int k = 0; k < 3; ++k) h[k] = length(g, 0, 8) / (g.exact ? 1 : 2);
  // Sometimes flat: a rectangle, a segment or a point.
  const int flat = *rc::gen::weightedElement<int>({{8, 0}, {1, 1}, {1, 2}, {1, 3}});
  for (int k = 0; k < flat; ++k) h[*rc::gen::inRange(0, 3)] = 0.0;
  return h;
}

Box grid_box(Grid g) {
  Box b;
  b.center = g.exact ? Vec3(*lattice_point(8 * g.s, 16)) : Vec3(*point(g.s));
  b.axes = g.exact ? *signed_permutation() : *rotation();
  b.half_extents = half_extents(g);
  return b;
}

// A dyadic fraction in [-1, 1] (in eighths) of each of the box's half extents.
Vec3 local_point(const Box& box, int bound = 8) {
  Vec3 p = box.center;
  for (int k = 0; k < 3; ++k) p += (*rc::gen::inRange(-bound, bound + 1) / 8.0) * box.half_extents[k] * box.axes.col(k);
  return p;
}

double radius_along(const Box& box, const Vec3& n) {
  double r = 0;
  for (int k = 0; k < 3; ++k) r += box.half_extents[k] * std::abs(box.axes.col(k).dot(n));
  return r;
}

// A gap between the boxes, either way (negative: into each other): a power of two of
// the pair's size, from clearly apart down to 2^-20 of it, or just outside the band
// where the check calls a pair ambiguous (2 to 16 times 24 tol, tol = 1e-9 S; `reach`
// bounds S): near-degenerate but decisive. Exactly touching pairs (zero gap) are the
// robustness step's, on exact input.
double gap(BoxGrid g, double size, double reach) {
  if (g.exact) return *rc::gen::weightedElement<double>({{4, 0.0}, {1, 8 * g.s}, {1, -8 * g.s}});
  const double sign = *rc::gen::element(-1.0, 1.0);
  // Moving boxes touch along an axis they then slide along (W nearly perpendicular to
  // it): s - r is rounding there, and times (r - s) / ds from it are noise.
  if (g.touching && *rc::gen::inRange(0, 6) == 0) return 0.0;
  if (*rc::gen::inRange(0, 4) == 0) return sign * *rc::gen::inRange(2, 17) * 24e-9 * reach;
  return sign * size * std::ldexp(1.0, -*rc::gen::inRange(4, 21));
}
// A bound on S for a pair whose box A is `a` and whose B is placed within `size` of it.
double reach(const Box& a, double size) { return a.center.cwiseAbs().maxCoeff() + 4 * size; }

// The corner offset of `box` that is extreme along -n (the point of B that reaches
// toward A), on the box's axes other than `free_axis` (-1: all three).
Vec3 extreme_toward(const Box& box, const Vec3& n, int free_axis = -1) {
  Vec3 p = Vec3::Zero();
  for (int k = 0; k < 3; ++k)
    if (k != free_axis) p -= (box.axes.col(k).dot(n) >= 0 ? 1.0 : -1.0) * box.half_extents[k] * box.axes.col(k);
  return p;
}

// B against a face of A (or A against a face of B), shifted sideways within the face.
// `along_face`, when asked for: another axis of the face's owner, so along that face.
BoxPair face_contact(BoxGrid g, Vec3* along_face = nullptr) {
  Box a = grid_box(g), b = grid_box(g);
  b.axes = related_axes(a.axes, g.exact);
  const bool on_b = *rc::gen::inRange(0, 3) == 0;
  const Box& owner = on_b ? b : a;
  const int k = *rc::gen::inRange(0, 3);
  if (along_face) *along_face = owner.axes.col((k + *rc::gen::inRange(1, 3)) % 3);
  Vec3 n = (*rc::gen::element(-1.0, 1.0)) * owner.axes.col(k);
  const double size = std::max(a.half_extents.maxCoeff(), b.half_extents.maxCoeff()) + g.s;
  const double along = radius_along(a, n) + radius_along(b, n) + gap(g, size, reach(a, size));
  Vec3 lateral = Vec3::Zero();
  for (int m = 0; m < 3; ++m)
    if (m != k) lateral += (*rc::gen::inRange(-10, 11) / 8.0) * owner.half_extents[m] * owner.axes.col(m);
  b.center = a.center + along * n + lateral;
  return {a, b};
}

// An edge of A across an edge of B: n = A_i x B_j is the axis between them.
BoxPair edge_contact(BoxGrid g) {
  Box a = grid_box(g), b = grid_box(g);
  b.axes = related_axes(a.axes, g.exact);
  const int i = *rc::gen::inRange(0, 3), j = *rc::gen::inRange(0, 3);
  Vec3 n = a.axes.col(i).cross(b.axes.col(j));
  if (n.squaredNorm() < 1e-6) return face_contact(g);
  n.normalize();
  const double size = std::max(a.half_extents.maxCoeff(), b.half_extents.maxCoeff()) + g.s;
  // A's edge along A_i farthest along n, at a point part way along it; B's edge along
  // B_j farthest along -n, placed through that point plus the gap.
  const Vec3 p =
      a.center - extreme_toward(a, n, i) + (*rc::gen::inRange(-8, 9) / 8.0) * a.half_extents[i] * a.axes.col(i);
  const Vec3 q = extreme_toward(b, n, j) + (*rc::gen::inRange(-8, 9) / 8.0) * b.half_extents[j] * b.axes.col(j);
  b.center = p + gap(g, size, reach(a, size)) * n - q;
  return {a, b};
}

// A corner of B on a face of A.
BoxPair corner_contact(BoxGrid g) {
  Box a = grid_box(g), b = grid_box(g);
  b.axes = related_axes(a.axes, g.exact);
  const int k = *rc::gen::inRange(0, 3);
  const Vec3 n = (*rc::gen::element(-1.0, 1.0)) * a.axes.col(k);
  Vec3 p = local_point(a);
  p += (a.half_extents[k] - a.axes.col(k).dot(p - a.center) * n.dot(a.axes.col(k))) * n;  // onto the face
  const double size = std::max(a.half_extents.maxCoeff(), b.half_extents.maxCoeff()) + g.s;
  b.center = p + gap(g, size, reach(a, size)) * n - extreme_toward(b, n);
  return {a, b};
}

// Near each other: overlapping deeply, a little, or apart, along A's axes.
BoxPair nearby(Grid g) {
  Box a = grid_box(g), b = grid_box(g);
  b.axes = related_axes(a.axes, g.exact);
  const double reach = b.half_extents.maxCoeff();
  b.center = a.center;
  for (int k = 0; k < 3; ++k) {
    const double extent = a.half_extents[k] + reach + g.s;
    b.center += (*rc::gen::inRange(-12, 13) / 8.0) * extent * a.axes.col(k);
  }
  return {a, b};
}

// One inside the other, or the same box twice.
BoxPair nested(Grid g) {
  Box a = grid_box(g);
  Box b = a;
  if (*rc::gen::inRange(0, 2) == 0) {
    b.axes = related_axes(a.axes, g.exact);
    for (int k = 0; k < 3; ++k) b.half_extents[k] = a.half_extents.minCoeff() / (g.exact ? 2 : 4);
    b.center = local_point(a, 2);
  }
  return {a, b};
}

BoxPair far_away(BoxPair p) {
  const double size = std::max(1.0, scale_of(p));
  const Vec3 offset = *lattice_point(size * 1024.0, 64);
  p.a.center += offset;
  p.b.center += offset;
  return p;
}

BoxPair pair_of(BoxGrid g) {
  switch (*rc::gen::weightedElement<int>({{4, 0}, {3, 1}, {3, 2}, {2, 3}, {1, 4}})) {
    case 0: return nearby(g);
    case 1: return face_contact(g);
    case 2: return edge_contact(g);
    case 3: return corner_contact(g);
    default: return nested(g);
  }
}

rc::Gen<BoxPair> pair_family(bool exact) {
  return rc::gen::exec([exact] { return pair_of(BoxGrid{*grid(exact)}); });
}

Vec3 rounded_unit() { return Vec3(*direction(1.0, 8)).normalized(); }

// ---- Triangles -------------------------------------------------------------------------

Vec3 grid_point(Grid g) { return g.exact ? Vec3(*lattice_point(8 * g.s, 16)) : Vec3(*point(g.s)); }
Vec3 grid_direction(Grid g) { return *direction(g.exact ? 8 * g.s : g.s, 8); }
Triangle grid_triangle(Grid g) {
  return *rc::gen::suchThat(rc::gen::exec([g] {
                              return Triangle{grid_point(g), grid_point(g), grid_point(g)};
                            }),
                            [](const Triangle& t) { return t.normal() != Vec3::Zero(); });
}
Vec3 eighths(const Vec3& origin, const Vec3& u, int p, const Vec3& v, int q) {
  return origin + (p / 8.0) * u + (q / 8.0) * v;
}

// T1 through a point x of T0 (inside, on an edge, or a vertex): x is T1's centroid
// (crossing), a vertex of T1 (touching), or a point of an edge of T1.
TrianglePair through_point(Grid g) {
  const Triangle t0 = grid_triangle(g);
  const int i = *rc::gen::inRange(0, 3);
  const Vec3 x =
      *rc::gen::oneOf(point_in_triangle(t0),
                      rc::gen::just(eighths(t0[i], t0[(i + 1) % 3] - t0[i], *rc::gen::inRange(0, 9), Vec3::Zero(), 0)));
  const Vec3 d1 = grid_direction(g), d2 = grid_direction(g);
  Triangle t1;
  switch (*rc::gen::weightedElement<int>({{3, 0}, {1, 1}, {1, 2}})) {
    case 0: t1 = {x + d1, x + d2, x - d1 - d2}; break;
    case 1: t1 = {x, x + d1, x + d2}; break;
    default: t1 = {x + d1, x - (*rc::gen::inRange(1, 17) / 8.0) * d1, x + d2}; break;
  }
  // On rounded input, three in four are moved off the contact by 1 to 8 times 1e-8 S along
  // T0's normal (10 tol: just outside the band where the check calls them ambiguous),
  // into a crossing or a gap; exact contacts are the robustness step's.
  if (!g.exact && *rc::gen::inRange(0, 4) != 0) {
    const double lift = *rc::gen::element(-1.0, 1.0) * *rc::gen::inRange(1, 9) * 1e-8 * scale_of(TrianglePair{t0, t1});
    const Vec3 n = t0.normal().normalized();
    for (int k = 0; k < 3; ++k) t1[k] += lift * n;
  }
  return *rc::gen::element(TrianglePair{t0, t1}, TrianglePair{t1, t0});
}

// Both in T0's plane: overlapping, nested, touching at vertices or along edges, apart.
TrianglePair coplanar(Grid g) {
  const Triangle t0 = grid_triangle(g);
  const Vec3 u = t0.v1 - t0.v0, v = t0.v2 - t0.v0;
  Triangle t1;
  for (int k = 0; k < 3; ++k) t1[k] = eighths(t0.v0, u, *rc::gen::inRange(-8, 17), v, *rc::gen::inRange(-8, 17));
  return {t0, t1};
}

// Coplanar, lifted off the plane by 1 to 8 times 1e-8 S (10 tol: just outside the band
// where the check calls the pair ambiguous), or (one in four) left in it.
TrianglePair lifted_coplanar() {
  TrianglePair p = coplanar(*grid(false));
  if (*rc::gen::inRange(0, 4) == 0) return p;
  const Vec3 n = p.t0.normal().normalized();
  const double lift = *rc::gen::element(-1.0, 1.0) * *rc::gen::inRange(1, 9) * 1e-8 * scale_of(p);
  for (int k = 0; k < 3; ++k) p.t1[k] += lift * n;
  return p;
}

// Coplanar, then lifted off the plane by tiny amounts: the same at every vertex
// (parallel planes) or differing (nearly parallel planes, often crossing).
TrianglePair near_coplanar() {
  TrianglePair p = coplanar(*grid(false));
  const Vec3 n = p.t0.normal().normalized();
  const double size = scale_of({p.t0.v0, p.t0.v1, p.t0.v2});
  const bool parallel = *rc::gen::inRange(0, 2) == 0;
  const double shift = *rc::gen::element(-3.0, -2.0, -1.0, 1.0, 2.0, 3.0) * *tiny(10, 25) * size;
  for (int k = 0; k < 3; ++k) p.t1[k] += (parallel ? shift : *integer(4) * *tiny(10, 25) * size) * n;
  return p;
}

// Through a point of T0, then shifted a tiny amount: near a vertex or an edge.
TrianglePair near_touching() {
  TrianglePair p = through_point(*grid(false));
  const double size = scale_of(p);
  const Vec3 shift =
      *rc::gen::element(-3.0, -2.0, -1.0, 1.0, 2.0, 3.0) * *tiny(12, 25) * size * Vec3(*direction(1.0, 4)).normalized();
  for (int k = 0; k < 3; ++k) p.t1[k] += shift;
  return p;
}

TrianglePair zero_area(Grid g) {
  const Vec3 a = grid_point(g), b = grid_point(g);
  const Triangle flat = *rc::gen::element(Triangle{a, b, eighths(a, b - a, *rc::gen::inRange(-8, 17), Vec3::Zero(), 0)},
                                          Triangle{a, a, b}, Triangle{a, a, a});
  TrianglePair p = through_point(g);
  // The flat triangle through the same point, so that it would touch if it had area.
  const Vec3 x = p.t0.v0;
  Triangle moved = flat;
  for (int k = 0; k < 3; ++k) moved[k] += x - flat.v0;
  return *rc::gen::element(TrianglePair{p.t0, moved}, TrianglePair{moved, p.t1}, TrianglePair{moved, moved});
}

TrianglePair generic_triangles(Grid g) { return {grid_triangle(g), grid_triangle(g)}; }

// A needle: a long edge p -> p + u and a third vertex 2^-k |u| off its line (k from 6 to
// 27: aspect ratios up to 1.3e8), beside one end (a spike: two long edges) or part way
// along (a cap: one angle near 180 degrees), in any orientation, vertices in any order.
Triangle needle(Grid g, Vec3* unit_normal, Vec3* across) {
  const Vec3 p = grid_point(g), u = 2 * grid_direction(g);
  Vec3 side = u.cross(grid_direction(g));
  if (side.isZero()) side = u.unitOrthogonal();
  side.normalize();
  const double height = std::ldexp(u.norm(), -*rc::gen::inRange(6, 28));
  const double at = *rc::gen::inRange(-2, 11) / 8.0;
  Triangle t{p, p + u, p + at * u + height * side};
  const int first = *rc::gen::inRange(0, 3);
  t = {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
  if (unit_normal) *unit_normal = u.cross(side).normalized();
  if (across) *across = side * u.norm();
  return t;
}

// A needle T0 and T1: through a point of the needle; in the needle's plane turned by
// 2^-j (j from 16 to 30) about a line beside it or through it (so that T1 misses the
// needle by up to thousands of tol, or crosses it); in a parallel plane; or another
// needle through it.
TrianglePair needles() {
  const Grid g = *grid(false);
  Vec3 n, w;
  const Triangle t0 = needle(g, &n, &w);
  const Vec3 u = t0.v1 - t0.v0;
  const double size = scale_of({t0.v0, t0.v1, t0.v2});
  Triangle t1;
  switch (*rc::gen::inRange(0, 4)) {
    case 0: {  // through a point of the needle
      const Vec3 x = *point_in_triangle(t0);
      const Vec3 d1 = grid_direction(g), d2 = grid_direction(g);
      t1 = {x + d1, x + d2, x - d1 - d2};
      break;
    }
    case 1: {  // turned by 2^-j about a line of the needle's plane beside the needle
      const double turn = std::ldexp(1.0, -*rc::gen::inRange(16, 31)), line = *rc::gen::inRange(-8, 9) / 8.0;
      for (int k = 0; k < 3; ++k) {
        const double a = *rc::gen::inRange(-8, 17) / 8.0, b = *rc::gen::inRange(-8, 9) / 8.0;
        t1[k] = t0.v0 + a * u + b * w + (b - line) * turn * u.norm() * n;
      }
      break;
    }
    case 2: {  // in a parallel plane, a few to hundreds of tol off
      const double shift = *integer(64) * 1e-8 * size;
      for (int k = 0; k < 3; ++k)
        t1[k] = t0.v0 + (*rc::gen::inRange(-8, 17) / 8.0) * u + (*rc::gen::inRange(-8, 9) / 8.0) * w + shift * n;
      break;
    }
    default: {  // another needle, through a point of this one
      Triangle other = needle(g, nullptr, nullptr);
      const Vec3 x = *point_in_triangle(t0), y = *point_in_triangle(other);
      for (int k = 0; k < 3; ++k) t1[k] = other[k] + (x - y);
      break;
    }
  }
  if (t1.normal() == Vec3::Zero()) t1 = grid_triangle(g);
  return *rc::gen::element(TrianglePair{t0, t1}, TrianglePair{t1, t0});
}

TrianglePair far_triangles(TrianglePair p) {
  const double size = std::max(1.0, scale_of(p));
  const Vec3 offset = *lattice_point(size * 1024.0, 64);
  for (int k = 0; k < 3; ++k) {
    p.t0[k] += offset;
    p.t1[k] += offset;
  }
  return p;
}

// ---- Moving boxes ----------------------------------------------------------------------

// Two boxes flat across the same axis A_k (half extent 0 along it), overlapping in one
// plane at time t*, and moving across that plane: they touch for a single instant, where
// the enter time of one axis equals the leave time of another (and rounding may put the
// two in either order).
BoxPair flat_crossing(Grid g, Vec3* across) {
  Box a = grid_box(g), b = grid_box(g);
  b.axes = a.axes;
  const int k = *rc::gen::inRange(0, 3);
  a.half_extents[k] = 0;
  b.half_extents[k] = 0;
  b.center = a.center;
  for (int m = 0; m < 3; ++m)
    if (m != k) b.center += (*rc::gen::inRange(-7, 8) / 8.0) * (a.half_extents[m] + b.half_extents[m]) * a.axes.col(m);
  *across = a.axes.col(k);
  return {a, b};
}

// A pair in contact (or a gap apart) at time t* = duration k / 8, moved back along
// lattice velocities: head on, at an angle, grazing (W perpendicular to one box's axis),
// not moving relative to each other, flat boxes crossing for an instant, or sliding
// along a face or a shared axis: then W . L on the other axes is zero in exact arithmetic
// but rounding noise in doubles, and times computed from it are noise too.
MovingBoxes moving(bool exact) {
  const BoxGrid g{*grid(exact), /*touching=*/true};
  const int kind = *rc::gen::weightedElement<int>({{6, 0}, {1, 1}, {1, 2}, {1, 3}});
  const bool flat = kind == 1, sliding = kind >= 2;
  Vec3 across = Vec3::Zero(), along = Vec3::Zero();
  BoxPair at_contact = flat ? flat_crossing(g, &across) : kind == 2 ? face_contact(g, &along) : pair_of(g);
  if (kind == 3) {  // the same axes, B beside or across A, sliding along one of them
    at_contact.b.axes = at_contact.a.axes;
    at_contact.b.center = at_contact.a.center;
    for (int m = 0; m < 3; ++m)
      at_contact.b.center += (*rc::gen::inRange(-8, 9) / 8.0) *
                             (at_contact.a.half_extents[m] + at_contact.b.half_extents[m]) * at_contact.a.axes.col(m);
    along = at_contact.a.axes.col(*rc::gen::inRange(0, 3));
  }
  const double duration = *rc::gen::weightedElement<double>({{8, 1.0}, {2, 2.0}, {2, 0.5}, {1, 0.0}});
  const double meet = duration * *rc::gen::inRange(-4, 13) / 8.0;
  const double size = std::max({at_contact.a.half_extents.maxCoeff(), at_contact.b.half_extents.maxCoeff(), g.s});
  // Speeds: displacements over one time unit of 1 to 16 units of the pair's size.
  const double unit = exact ? 8 * g.s : std::ldexp(1.0, std::ilogb(size));
  const Vec3 va = *rc::gen::weightedElement<int>({{2, 0}, {1, 1}}) ? Vec3(*lattice_point(unit, 8)) : Vec3::Zero();
  Vec3 w;
  switch (flat ? 4 : sliding ? 5 : *rc::gen::inRange(0, 4)) {
    case 0:  // at any angle
      w = *direction(unit, 8);
      break;
    case 1: {  // head on: along the line between the centres (rounded to the lattice)
      const Vec3 d = at_contact.a.center - at_contact.b.center;
      w = d.isZero() ? Vec3(*direction(unit, 8)) : Vec3((d / unit * 4).array().round() * unit);
      if (w.isZero()) w = *direction(unit, 8);
      break;
    }
    case 2: {  // grazing: perpendicular to one of the boxes' axes, in exact arithmetic
      const Box* owner = *rc::gen::element(&at_contact.a, &at_contact.b);
      w = (*integer(8) + 0.5) * unit * owner->axes.col(*rc::gen::inRange(0, 3));
      break;
    }
    case 3:  // moving together
      w = Vec3::Zero();
      break;
    case 4:  // across the flat boxes' common plane, maybe sliding along it too
      w = *rc::gen::element(-1.0, 1.0) * *rc::gen::inRange(1, 9) * unit * across;
      if (*rc::gen::inRange(0, 2) == 0) w += *direction(unit, 2);
      break;
    default:  // sliding along a face, or along a shared axis
      w = (*integer(8) + 0.5) * unit * along;
  }
  MovingBoxes m;
  m.a = at_contact.a;
  m.b = at_contact.b;
  m.velocity_a = va;
  m.velocity_b = va + w;
  m.duration = duration;
  m.a.center -= meet * m.velocity_a;
  m.b.center -= meet * m.velocity_b;
  return m;
}

// The ends of the header's scale range: every position (and velocity) times the power of
// two that takes the case's S to just inside 1e50 (2^165 <= S < 2^166) or 1e-50
// (2^-166 <= S < 2^-165). Powers of two keep every relation of the case exact.
template <class T> double scale_end(const T& c) {
  const double s = std::max(values_of(c).largest_length(), 1e-300);
  return std::ldexp(1.0, *rc::gen::element(165, -166) - std::ilogb(s));
}
Box scaled(Box b, double f) {
  b.center *= f;
  b.half_extents *= f;
  return b;
}
BoxPair scaled(const BoxPair& p, double f) { return {scaled(p.a, f), scaled(p.b, f)}; }
TrianglePair scaled(TrianglePair p, double f) {
  for (int k = 0; k < 3; ++k) p.t0[k] *= f, p.t1[k] *= f;
  return p;
}
MovingBoxes scaled(MovingBoxes m, double f) {
  m.a = scaled(m.a, f), m.b = scaled(m.b, f);
  m.velocity_a *= f, m.velocity_b *= f;
  return m;
}
// One case in 16 at an end of the scale range.
template <class T> rc::Gen<T> with_scale_ends(rc::Gen<T> gen) {
  return rc::gen::weightedOneOf<T>({{15, gen}, {1, rc::gen::exec([gen] {
                                                  const T c = *gen;
                                                  return scaled(c, scale_end(c));
                                                })}});
}

}  // namespace

rc::Gen<Mat3> rotation() {
  return rc::gen::weightedOneOf<Mat3>({{5, quaternion_rotation()}, {1, signed_permutation()}});
}

rc::Gen<Box> box(double s) {
  return rc::gen::exec([s] { return grid_box(Grid{s, false}); });
}

rc::Gen<BoxOnAxis> box_on_axis() {
  return rc::gen::exec([] {
    const Grid g = *grid(false);
    BoxOnAxis in{grid_box(g), Vec3::UnitX()};
    switch (*rc::gen::inRange(0, 4)) {
      case 0: in.axis = *direction(1.0, 8); break;  // a lattice direction, any length
      case 1: in.axis = rounded_unit(); break;
      case 2: in.axis = in.box.axes.col(*rc::gen::inRange(0, 3)); break;  // its own axis
      default:  // perpendicular to one of its axes, to rounding: |A_k . L| is noise
        in.axis = in.box.axes.col(0).cross(in.box.axes.col(*rc::gen::inRange(1, 3)));
    }
    if (*rc::gen::inRange(0, 8) == 0) in.box.center += *lattice_point(1024.0 * std::max(1.0, scale_of(in)), 64);
    if (*rc::gen::inRange(0, 16) == 0) in.box = scaled(in.box, scale_end(in.box));
    return in;
  });
}

rc::Gen<BoxPairOnAxis> box_pair_on_axis() {
  return rc::gen::exec([] {
    const BoxPair p = *box_pair();
    Vec3 axis;
    const int kind = *rc::gen::inRange(0, 3);
    if (kind == 0) {
      axis = *direction(1.0, 8);
    } else if (kind == 1) {
      const int index = *rc::gen::inRange(0, 15);
      axis = index < 3 ? Vec3(p.a.axes.col(index))
                       : (index < 6 ? Vec3(p.b.axes.col(index - 3))
                                    : Vec3(p.a.axes.col((index - 6) / 3).cross(p.b.axes.col((index - 6) % 3))));
    } else {
      axis = p.b.center - p.a.center;
    }
    return BoxPairOnAxis{p.a, p.b, axis};
  });
}

rc::Gen<BoxPair> box_pair() {
  const rc::Gen<BoxPair> families = pair_family(false);
  return with_scale_ends(
      rc::gen::weightedOneOf<BoxPair>({{7, families}, {1, rc::gen::exec([families] { return far_away(*families); })}}));
}

rc::Gen<BoxPair> exact_box_pair() { return pair_family(true); }

// The header's domain: zero area, or a smallest height at least 1e-8 of the longest edge
// (longest^2 <= 1e8 |n|, |n| twice the area).
bool in_domain(const Triangle& t) {
  const double longest =
      std::max({(t.v1 - t.v0).squaredNorm(), (t.v2 - t.v1).squaredNorm(), (t.v0 - t.v2).squaredNorm()});
  const double n = t.normal().norm();
  return n == 0 || longest <= 1e8 * n;
}

rc::Gen<TrianglePair> triangle_pair() {
  const rc::Gen<TrianglePair> families = rc::gen::suchThat(
      rc::gen::exec([] {
        const Grid g = *grid(false);
        switch (*rc::gen::weightedElement<int>({{6, 0}, {8, 1}, {3, 2}, {4, 3}, {4, 4}, {1, 5}, {8, 6}})) {
          case 0: return generic_triangles(g);
          case 1: return through_point(g);
          case 2: return lifted_coplanar();
          case 3: return near_coplanar();
          case 4: return near_touching();
          case 5: return zero_area(g);
          default: return needles();
        }
      }),
      [](const TrianglePair& p) { return in_domain(p.t0) && in_domain(p.t1); });
  return with_scale_ends(rc::gen::weightedOneOf<TrianglePair>(
      {{7, families}, {1, rc::gen::exec([families] { return far_triangles(*families); })}}));
}

rc::Gen<TrianglePair> crossing_triangle_pair() {
  const rc::Gen<TrianglePair> families = rc::gen::suchThat(
      rc::gen::exec([] {
        const Grid g = *grid(false);
        const Triangle t0 = grid_triangle(g);
        const Vec3 d1 = grid_direction(g), d2 = grid_direction(g);
        if (*rc::gen::inRange(0, 3) == 0) {  // through a point inside t0
          const Vec3 x = *point_in_triangle(t0);
          return *rc::gen::element(TrianglePair{t0, {x + d1, x + d2, x - d1 - d2}},
                                   TrianglePair{{x + d1, x + d2, x - d1 - d2}, t0});
        }
        // An edge of t1 through a point x of an edge of t0: both segments on the line of the
        // planes end at x. Then t1 slides along that line by 2 to 16 times 1e-8 S (10 tol
        // and more: outside the band where the check calls them ambiguous): two ends just
        // apart, or just overlapping.
        const int i = *rc::gen::inRange(0, 3);
        const Vec3 x = eighths(t0[i], t0[(i + 1) % 3] - t0[i], *rc::gen::inRange(1, 8), Vec3::Zero(), 0);
        Triangle t1{x + d1, x - (*rc::gen::inRange(1, 17) / 8.0) * d1, x + d2};
        const Vec3 line = t0.normal().cross(t1.normal());
        if (line.isZero()) return TrianglePair{t0, t1};  // rejected below
        const double slide =
            *rc::gen::element(-1.0, 1.0) * *rc::gen::inRange(2, 17) * 1e-8 * scale_of(TrianglePair{t0, t1});
        for (int k = 0; k < 3; ++k) t1[k] += slide * line.normalized();
        return *rc::gen::element(TrianglePair{t0, t1}, TrianglePair{t1, t0});
      }),
      lab03::judge::in_interval_domain);
  return with_scale_ends(families);  // not far from the origin: S/100 off the planes, S counting the offset
}

rc::Gen<TrianglePair> exact_triangle_pair() {
  return rc::gen::exec([] {
    const Grid g = *grid(true);
    switch (*rc::gen::weightedElement<int>({{4, 0}, {3, 1}, {1, 2}})) {
      case 0: return through_point(g);
      case 1: return coplanar(g);
      default: return zero_area(g);
    }
  });
}

rc::Gen<MovingBoxes> moving_boxes() {
  return with_scale_ends(rc::gen::exec([] { return moving(false); }));
}

rc::Gen<MovingBoxes> exact_moving_boxes() {
  return rc::gen::exec([] { return moving(true); });
}

}  // namespace labkit::gen
