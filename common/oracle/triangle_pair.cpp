#include "common/oracle/triangle_pair.h"
#include "common/oracle/kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oracle {

using namespace kernel;

namespace {

Epick::Triangle_3 fast(const Triangle& t) { return {kernel::fast(t.v0), kernel::fast(t.v1), kernel::fast(t.v2)}; }

// The closed set of a zero-area triangle: its longest edge, or a point.
Epick::Segment_3 hull(const Epick::Triangle_3& t) {
  Epick::Segment_3 best(t[0], t[1]);
  for (int i = 1; i < 3; ++i) {
    const Epick::Segment_3 e(t[i], t[(i + 1) % 3]);
    if (e.squared_length() > best.squared_length()) best = e;
  }
  return best;
}

double squared_distance(const Epick::Segment_3& s, const Epick::Segment_3& e) {
  if (s.is_degenerate() && e.is_degenerate()) return CGAL::squared_distance(s.source(), e.source());
  if (s.is_degenerate()) return CGAL::squared_distance(s.source(), e);
  if (e.is_degenerate()) return CGAL::squared_distance(e.source(), s);
  return CGAL::squared_distance(s, e);
}

// A segment (or point) and a triangle with area.
double squared_distance(const Epick::Segment_3& s, const Epick::Triangle_3& t) {
  if (s.is_degenerate()) return CGAL::squared_distance(s.source(), t);
  if (CGAL::do_intersect(s, t)) return 0.0;
  double d2 = std::min(CGAL::squared_distance(s.source(), t), CGAL::squared_distance(s.target(), t));
  for (int i = 0; i < 3; ++i) d2 = std::min(d2, squared_distance(s, Epick::Segment_3(t[i], t[(i + 1) % 3])));
  return d2;
}

labkit::Vec3 rounded_vector(const Epeck::Vector_3& v) { return {rounded(v.x()), rounded(v.y()), rounded(v.z())}; }

// The shortest translation that separates two intersecting triangles with area: the
// distance from the origin to the boundary of T0 ⊕ (-T1). Its facet normals are n0,
// n1 and the cross products of an edge of each, so the depth is the least overlap of
// the projections over those axes (exact directions, rounded once). Coplanar
// triangles make it flat: then the overlap along n0 is zero.
double penetration_depth(const Triangle& t0, const Triangle& t1) {
  const Epeck::Triangle_3 a = exact(t0), b = exact(t1);
  Epeck::Vector_3 e[3], f[3];
  for (int i = 0; i < 3; ++i) {
    e[i] = a[(i + 1) % 3] - a[i];
    f[i] = b[(i + 1) % 3] - b[i];
  }
  labkit::Vec3 axes[11];
  axes[0] = rounded_vector(CGAL::cross_product(e[0], e[1]));
  axes[1] = rounded_vector(CGAL::cross_product(f[0], f[1]));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) axes[2 + 3 * i + j] = rounded_vector(CGAL::cross_product(e[i], f[j]));
  double depth = std::numeric_limits<double>::infinity();
  for (const labkit::Vec3& axis : axes) {
    const double length = axis.norm();
    if (length == 0) continue;
    const labkit::Vec3 u = axis / length;
    double lo0 = t0.v0.dot(u), hi0 = lo0, lo1 = t1.v0.dot(u), hi1 = lo1;
    for (int i = 1; i < 3; ++i) {
      lo0 = std::min(lo0, t0[i].dot(u));
      hi0 = std::max(hi0, t0[i].dot(u));
      lo1 = std::min(lo1, t1[i].dot(u));
      hi1 = std::max(hi1, t1[i].dot(u));
    }
    depth = std::min(depth, std::min(hi0 - lo1, hi1 - lo0));
  }
  return depth;
}

double smallest_height(const Triangle& t) {
  const double longest = std::max({(t.v1 - t.v0).norm(), (t.v2 - t.v1).norm(), (t.v0 - t.v2).norm()});
  return t.normal().norm() / longest;
}

}  // namespace

namespace {

// t's segment in the plane of `other`, exact: the two edges from the vertex alone on its
// side, cut where they cross the plane. False when a vertex lies in it or all on one side.
bool exact_interval(const Epeck::Triangle_3& t, const Epeck::Triangle_3& other, int k, double& low, double& high) {
  int side[3];
  for (int i = 0; i < 3; ++i) side[i] = sign_of(CGAL::orientation(other[0], other[1], other[2], t[i]));
  if (side[0] == 0 || side[1] == 0 || side[2] == 0 || (side[0] == side[1] && side[1] == side[2])) return false;
  const int p = side[0] == side[1] ? 2 : (side[0] == side[2] ? 1 : 0);
  const Epeck::Plane_3 plane(other[0], other[1], other[2]);
  double ends[2];
  for (int e = 0; e < 2; ++e) {
    const Epeck::Segment_3 edge(t[p], t[(p + 1 + e) % 3]);
    const auto hit = CGAL::intersection(edge, plane);
    const Epeck::Point_3* x = hit ? boost::get<Epeck::Point_3>(&*hit) : nullptr;
    if (!x) return false;  // unreachable: the edge's ends are strictly on both sides
    ends[e] = rounded((*x)[k]);
  }
  low = std::min(ends[0], ends[1]), high = std::max(ends[0], ends[1]);
  return true;
}

}  // namespace

TriangleIntervals triangle_intervals(const Triangle& t0, const Triangle& t1, int k) {
  const Epeck::Triangle_3 a = exact(t0), b = exact(t1);
  if (a.is_degenerate() || b.is_degenerate()) return {};
  TriangleIntervals out;
  if (!exact_interval(a, b, k, out.low0, out.high0) || !exact_interval(b, a, k, out.low1, out.high1)) return {};
  out.crossing = true;
  return out;
}

labkit::Vec3 planes_line_direction(const Triangle& t0, const Triangle& t1) {
  const Epeck::Triangle_3 a = exact(t0), b = exact(t1);
  const Epeck::Vector_3 n0 = CGAL::cross_product(a[1] - a[0], a[2] - a[0]);
  const Epeck::Vector_3 n1 = CGAL::cross_product(b[1] - b[0], b[2] - b[0]);
  return rounded_vector(CGAL::cross_product(n0, n1));
}

bool triangles_intersect(const Triangle& t0, const Triangle& t1) {
  const Epick::Triangle_3 a = fast(t0), b = fast(t1);
  if (a.is_degenerate() || b.is_degenerate()) return false;
  return CGAL::do_intersect(a, b);
}

bool triangle_pair_in_doubt(const Triangle& t0, const Triangle& t1, double delta) {
  // 2 eps, with a margin for the rounding of the distances below (relative 1e-12).
  const double reach = 2 * std::sqrt(3.0) * delta * 1.01;
  const Epick::Triangle_3 a = fast(t0), b = fast(t1);
  const bool flat0 = a.is_degenerate(), flat1 = b.is_degenerate();
  if (flat0 || flat1) {
    const double d2 = flat0 && flat1 ? squared_distance(hull(a), hull(b))
                                     : (flat0 ? squared_distance(hull(a), b) : squared_distance(hull(b), a));
    return d2 <= reach * reach;
  }
  if (!CGAL::do_intersect(a, b)) return CGAL::squared_distance(a, b) <= reach * reach;
  if (smallest_height(t0) <= reach || smallest_height(t1) <= reach) return true;
  return penetration_depth(t0, t1) <= reach;
}

}  // namespace oracle
