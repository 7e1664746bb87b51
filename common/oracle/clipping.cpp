#include "common/oracle/clipping.h"
#include "common/oracle/kernel.h"

#include <CGAL/intersections.h>

#include <cmath>

namespace oracle {

using namespace kernel;

namespace {

FT value(const Plane& plane, const Epeck::Point_3& x) {
  return FT(plane.normal.x()) * x.x() + FT(plane.normal.y()) * x.y() + FT(plane.normal.z()) * x.z() +
         FT(plane.offset);
}

// Sutherland-Hodgman against one closed half-space: keep what has value >= 0, and add
// the crossing point on every edge whose ends have strictly opposite signs.
std::vector<Epeck::Point_3> clip_by(const std::vector<Epeck::Point_3>& polygon, const Plane& plane) {
  std::vector<Epeck::Point_3> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Epeck::Point_3& p = polygon[i];
    const Epeck::Point_3& q = polygon[(i + 1) % n];
    const FT vp = value(plane, p), vq = value(plane, q);
    if (vp >= 0) out.push_back(p);
    if ((vp > 0 && vq < 0) || (vp < 0 && vq > 0)) out.push_back(p + (q - p) * (vp / (vp - vq)));
  }
  return out;
}

FT twice_area_squared(const std::vector<Epeck::Point_3>& polygon) {
  if (polygon.size() < 3) return 0;
  Epeck::Vector_3 sum = CGAL::NULL_VECTOR;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    sum = sum + CGAL::cross_product(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
  return sum.squared_length();
}

int dominant_axis(const Vec3& n) {
  const Vec3 a = n.cwiseAbs();
  return a.x() >= a.y() && a.x() >= a.z() ? 0 : (a.y() >= a.z() ? 1 : 2);
}

Epeck::Point_2 drop(const Vec3& p, int axis) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  return {p[u], p[v]};
}

Epeck::Triangle_2 counterclockwise(Epeck::Point_2 a, Epeck::Point_2 b, Epeck::Point_2 c) {
  if (CGAL::orientation(a, b, c) == CGAL::CLOCKWISE) std::swap(b, c);
  return {a, b, c};
}

FT polygon_area(const std::vector<Epeck::Point_2>& p) {
  FT twice = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& q = p[i];
    const auto& r = p[(i + 1) % p.size()];
    twice += q.x() * r.y() - r.x() * q.y();
  }
  return CGAL::abs(twice) / 2;
}

}  // namespace

ClippedPolygon clip(const Triangle& t, const std::vector<Plane>& planes) {
  std::vector<Epeck::Point_3> polygon = {exact(t.v0), exact(t.v1), exact(t.v2)};
  for (const Plane& plane : planes) {
    if (polygon.empty()) break;
    polygon = clip_by(polygon, plane);
  }
  ClippedPolygon result;
  for (const auto& p : polygon) result.vertices.push_back(rounded(p));
  result.area = 0.5 * std::sqrt(rounded(twice_area_squared(polygon)));
  return result;
}

double overlap_area(const Triangle& a, const Triangle& b, const Triangle& reference) {
  const Vec3 n = reference.normal();
  if (n == Vec3::Zero()) return 0.0;
  const int axis = dominant_axis(n);
  const auto a0 = drop(a.v0, axis), a1 = drop(a.v1, axis), a2 = drop(a.v2, axis);
  const auto b0 = drop(b.v0, axis), b1 = drop(b.v1, axis), b2 = drop(b.v2, axis);
  if (CGAL::collinear(a0, a1, a2) || CGAL::collinear(b0, b1, b2)) return 0.0;
  const auto overlap = CGAL::intersection(counterclockwise(a0, a1, a2), counterclockwise(b0, b1, b2));
  if (!overlap) return 0.0;
  FT area2d = 0;
  if (const auto* t = boost::get<Epeck::Triangle_2>(&*overlap)) area2d = CGAL::abs(t->area());
  if (const auto* poly = boost::get<std::vector<Epeck::Point_2>>(&*overlap)) area2d = polygon_area(*poly);
  // Areas in the dropped-axis plane shrink by |n_axis| / |n|.
  return rounded(area2d) * n.norm() / std::abs(n[axis]);
}

bool inside_all(const Vec3& x, const std::vector<Plane>& planes, double tolerance) {
  const Epeck::Point_3 p = exact(x);
  for (const Plane& plane : planes) {
    const FT v = value(plane, p);
    if (v >= 0) continue;
    const FT n2 = FT(plane.normal.x()) * FT(plane.normal.x()) + FT(plane.normal.y()) * FT(plane.normal.y()) +
                  FT(plane.normal.z()) * FT(plane.normal.z());
    if (v * v > FT(tolerance) * FT(tolerance) * n2) return false;
  }
  return true;
}

}  // namespace oracle
