#include "common/oracle/spatial_trees.h"

#include "common/oracle/kernel.h"
#include "common/oracle/predicates.h"
#include "common/oracle/segment_triangle.h"

#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace oracle {

using namespace kernel;

bool segment_crosses_triangle(const Segment& s, const Triangle& t) {
  if (is_degenerate(t)) return false;
  if (orientation(t.v0, t.v1, t.v2, s.a) == 0 && orientation(t.v0, t.v1, t.v2, s.b) == 0) return false;
  return segment_hits_triangle(s, t);
}

std::vector<Crossing> segment_mesh_crossings(const Segment& s, const Mesh& mesh) {
  std::vector<Crossing> out;
  for (const SegmentHit& h : segment_mesh_hits(s, mesh))
    if (!h.coplanar) out.push_back({h.triangle, h.t});  // sorted by t, then index, already
  return out;
}

namespace {

// A filter before the exact test: the separating axes of a triangle and a box (the box's
// three axes, the triangle's normal, and the nine products of a box axis with an edge) in
// doubles. Returns -1 when some axis separates them by more than the rounding could
// account for, +1 when every axis shows them overlapping by more than that, 0 in doubt.
// Margins: a dot product a . x of doubles is off by at most 3u |a|_1 R (u = 2^-53, R the
// largest |coordinate|); an axis a box axis times an edge is off by u |a|_1 (the edge's
// subtraction), the normal by about 12u |e0|_1 |e1|_1. 1e-12 is far above all of it. An
// axis the products make exactly zero (an edge parallel to a box axis: the subtraction
// gives 0 exactly when the coordinates are equal) is not needed and is skipped.
int triangle_box_filter(const Triangle& t, const Aabb& box) {
  double reach = 0;
  for (int i = 0; i < 3; ++i)
    reach = std::max({reach, t[i].cwiseAbs().maxCoeff(), box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff()});
  const Vec3 e[3] = {t.v1 - t.v0, t.v2 - t.v1, t.v0 - t.v2};
  bool overlap = true;
  const auto axis = [&](const Vec3& a, double scale) {  // -1 apart, else whether the overlap is certain
    const double margin = 1e-12 * reach * scale;
    double lo = 0, hi = 0;
    for (int i = 0; i < 3; ++i) {
      lo += std::min(a[i] * box.min[i], a[i] * box.max[i]);
      hi += std::max(a[i] * box.min[i], a[i] * box.max[i]);
    }
    const double p0 = a.dot(t.v0), p1 = a.dot(t.v1), p2 = a.dot(t.v2);
    const double tlo = std::min({p0, p1, p2}), thi = std::max({p0, p1, p2});
    if (thi < lo - margin || hi < tlo - margin) return -1;
    if (!(thi - lo > margin && hi - tlo > margin)) overlap = false;
    return 0;
  };
  for (int i = 0; i < 3; ++i) {
    Vec3 unit = Vec3::Zero();
    unit[i] = 1;
    if (axis(unit, 1) < 0) return -1;
  }
  const Vec3 n = e[0].cross(e[1]);
  if (axis(n, n.cwiseAbs().sum() + e[0].cwiseAbs().sum() * e[1].cwiseAbs().sum()) < 0) return -1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Vec3 unit = Vec3::Zero();
      unit[i] = 1;
      const Vec3 a = unit.cross(e[j]);
      if (a == Vec3::Zero()) continue;
      if (axis(a, a.cwiseAbs().sum()) < 0) return -1;
    }
  return overlap ? 1 : 0;
}

}  // namespace

bool triangle_meets_box(const Triangle& t, const Aabb& box) {
  if (is_degenerate(t)) return false;
  if (const int clear = triangle_box_filter(t, box); clear != 0) return clear > 0;
  const Epick::Triangle_3 tri(fast(t.v0), fast(t.v1), fast(t.v2));
  const Epick::Iso_cuboid_3 cuboid(fast(box.min), fast(box.max));
  return CGAL::do_intersect(tri, cuboid);
}

namespace {

bool on_triangle(const Triangle& t, const Vec3& p) {
  return Epick::Triangle_3(fast(t.v0), fast(t.v1), fast(t.v2)).has_on(fast(p));
}

// Does the ray's segment p -> r cross the triangle properly (through its interior, the
// ends off its plane)? `degenerate` is set when it passes through an edge's line or r
// lies on the plane: then parity along this ray means nothing.
bool crosses(const Vec3& p, const Vec3& r, const Triangle& t, bool& degenerate) {
  const int side_p = orientation(t.v0, t.v1, t.v2, p), side_r = orientation(t.v0, t.v1, t.v2, r);
  if (side_r == 0) {
    degenerate = true;
    return false;
  }
  if (side_p == side_r || side_p == 0) return false;  // one side, or p on the plane (and off the triangle)
  int signs[3];
  for (int i = 0; i < 3; ++i) signs[i] = orientation(p, r, t[i], t[(i + 1) % 3]);
  if (signs[0] == 0 || signs[1] == 0 || signs[2] == 0) {
    degenerate = true;
    return false;
  }
  return signs[0] == signs[1] && signs[1] == signs[2];
}

}  // namespace

int point_in_solid(const Vec3& p, const Mesh& closed) {
  double reach = 1.0;
  for (const Vec3& v : closed.vertices) reach = std::max(reach, (v - p).cwiseAbs().maxCoeff());
  for (std::size_t i = 0; i < closed.size(); ++i) {
    const Triangle t = closed.triangle(i);
    if (!is_degenerate(t) && on_triangle(t, p)) return 0;
  }
  // Directions with unrelated dyadic components: a ray through an edge or a vertex is a
  // coincidence that the next direction will not repeat.
  static const Vec3 directions[] = {{1, 0.3134765625, 0.0712890625},  {-0.4482421875, 1, 0.1962890625},
                                    {0.2548828125, -0.6728515625, 1}, {-1, -0.1103515625, 0.5830078125},
                                    {0.8623046875, 0.4189453125, -1}, {0.0380859375, -1, -0.7451171875},
                                    {1, -0.8935546875, 0.6611328125}, {-0.5322265625, 0.9716796875, -1}};
  for (const Vec3& d : directions) {
    // r: far enough to be outside the mesh's box (the rounding of r does not matter).
    const Vec3 r = p + 4 * reach * d;
    bool degenerate = false;
    int count = 0;
    for (std::size_t i = 0; i < closed.size() && !degenerate; ++i) {
      const Triangle t = closed.triangle(i);
      if (!is_degenerate(t) && crosses(p, r, t, degenerate)) ++count;
    }
    if (!degenerate) return count % 2 == 1 ? 1 : -1;
  }
  throw std::logic_error("point_in_solid: every ray direction passed through an edge");
}

bool side_in_doubt(const Triangle& t, const Vec3& x, double delta) {
  const Vec3 n = t.normal();
  const double twice_area = n.norm();
  if (twice_area == 0) return true;
  const Vec3 unit = n / twice_area;
  const Vec3 lambda = Vec3((t.v1 - x).cross(t.v2 - x).dot(unit), (t.v2 - x).cross(t.v0 - x).dot(unit),
                           (t.v0 - x).cross(t.v1 - x).dot(unit)) /
                      twice_area;
  const double eps = std::sqrt(3.0) * delta;
  return std::abs((x - t.v0).dot(unit)) <= 2 * eps * (1 + lambda.cwiseAbs().sum());
}

bool balls_meet(const Sphere& a, const Sphere& b) {
  // Decide in doubles when the answer is clear by far more than their rounding error
  // (a relative 1e-12 of the sizes involved), exactly otherwise.
  const double d2 = (a.center - b.center).squaredNorm(), sum = a.radius + b.radius, s2 = sum * sum;
  const double margin = 1e-12 * (d2 + s2);
  if (d2 > s2 + margin) return false;
  if (d2 < s2 - margin) return true;
  const Epeck::Point_3 ca = exact(a.center), cb = exact(b.center);
  const FT r = ft(a.radius) + ft(b.radius);
  return CGAL::squared_distance(ca, cb) <= r * r;
}

std::vector<std::array<int, 2>> meeting_pairs(const std::vector<Sphere>& spheres) {
  std::vector<std::array<int, 2>> out;
  for (int i = 0; i < int(spheres.size()); ++i)
    for (int j = i + 1; j < int(spheres.size()); ++j)
      if (balls_meet(spheres[std::size_t(i)], spheres[std::size_t(j)])) out.push_back({i, j});
  return out;
}

bool ball_meets_box(const Sphere& ball, const Aabb& box) {
  FT d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double c = ball.center[i];
    if (c < box.min[i]) d2 += CGAL::square(ft(box.min[i]) - ft(c));
    if (c > box.max[i]) d2 += CGAL::square(ft(c) - ft(box.max[i]));
  }
  return d2 <= CGAL::square(ft(ball.radius));
}

std::vector<int> balls_meeting_box(const std::vector<Sphere>& spheres, const Aabb& box) {
  std::vector<int> out;
  for (int i = 0; i < int(spheres.size()); ++i)
    if (ball_meets_box(spheres[std::size_t(i)], box)) out.push_back(i);
  return out;
}

}  // namespace oracle
