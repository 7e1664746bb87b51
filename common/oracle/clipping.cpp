#include "common/oracle/clipping.h"
#include "common/oracle/kernel.h"

#include <CGAL/intersections.h>

#include <cmath>
#include <limits>

namespace oracle {

using namespace kernel;

namespace {

FT value(const Plane& plane, const Epeck::Point_3& x) {
  return ft(plane.normal.x()) * x.x() + ft(plane.normal.y()) * x.y() + ft(plane.normal.z()) * x.z() + ft(plane.offset);
}

FT squared_norm(const Vec3& v) { return ft(v.x()) * ft(v.x()) + ft(v.y()) * ft(v.y()) + ft(v.z()) * ft(v.z()); }

// Sutherland-Hodgman against one closed half-space: keep what has value >= 0, and add
// the crossing point on every edge whose ends have strictly opposite signs.
std::vector<Epeck::Point_3> clip_by(const std::vector<Epeck::Point_3>& polygon, const Plane& plane) {
  std::vector<FT> values;
  for (const auto& p : polygon) values.push_back(value(plane, p));
  std::vector<Epeck::Point_3> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const FT& vp = values[i];
    const FT& vq = values[j];
    const CGAL::Sign sp = CGAL::sign(vp), sq = CGAL::sign(vq);
    if (sp != CGAL::NEGATIVE) out.push_back(polygon[i]);
    if (sp * sq == CGAL::NEGATIVE) out.push_back(polygon[i] + (polygon[j] - polygon[i]) * (vp / (vp - vq)));
  }
  if (out.size() < 3) out.clear();  // a point or a segment: nothing left to cut
  return out;
}

Epeck::Vector_3 twice_vector_area(const std::vector<Epeck::Point_3>& polygon) {
  Epeck::Vector_3 sum = CGAL::NULL_VECTOR;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    sum = sum + CGAL::cross_product(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
  return sum;
}

// The double evaluation of plane.value(x) is off by less than 4 eps times the sum of
// its terms' sizes (underflow aside: the kit's coordinates stay far above it).
double rounding_bound(const Plane& plane, const Vec3& x) {
  const double size = (plane.normal.cwiseProduct(x)).cwiseAbs().sum() + std::abs(plane.offset);
  return 4 * std::numeric_limits<double>::epsilon() * size;
}

// The exact sign of plane.value(x): a value beyond the bound has the right sign; only
// values within it (points on or very near the plane) are computed exactly.
int exact_side(const Plane& plane, const Vec3& x) {
  const double v = plane.value(x);
  const double bound = rounding_bound(plane, x);
  if (v > bound) return 1;
  if (v < -bound) return -1;
  return sign_of(CGAL::sign(value(plane, exact(x))));
}

std::array<int, 3> sides(const Triangle& t, const Plane& plane) {
  return {exact_side(plane, t.v0), exact_side(plane, t.v1), exact_side(plane, t.v2)};
}

// ---- The doubt walk ------------------------------------------------------------------
// The same rule in double arithmetic, on corners kept as what defines them. A point x
// of the triangle's plane is x = sum w_i v_i / sum w_i for homogeneous barycentric
// weights w, and its signed distance to a plane is then w . d / w . 1, d holding the
// three vertices' distances. The weights of a corner come from the input alone:
//   vertex i:                        w = e_i
//   edge (a, b) cut by plane k:      w = d^k_a e_b - d^k_b e_a
//   planes k and l across the plane: w = d^k x d^l
struct Corner {
  enum class Kind { vertex, edge_cut, plane_cut } kind = Kind::vertex;
  int a = 0, b = 0;     // the vertex, or the edge's ends
  int k = 0;            // the cutting plane (the first of two)
  unsigned edges = 0;   // bit e: lies on the edge from vertex e to vertex e + 1
  unsigned planes = 0;  // bit k: lies on plane k
};

int sign(double x) { return (x > 0) - (x < 0); }

// The sign of the corner's distance to plane m, or 0 when moving every distance by
// eta could change it.
int stable_sign(const Corner& c, int m, const std::vector<Vec3>& d, double eta) {
  const Vec3& dm = d[std::size_t(m)];
  if (c.kind == Corner::Kind::vertex) return std::abs(dm[c.a]) > eta ? sign(dm[c.a]) : 0;
  const Vec3& dk = d[std::size_t(c.k)];
  if (c.kind == Corner::Kind::edge_cut) {
    const double num = dk[c.a] * dm[c.b] - dk[c.b] * dm[c.a];
    const double num_bound =
        eta * (std::abs(dk[c.a]) + std::abs(dk[c.b]) + std::abs(dm[c.a]) + std::abs(dm[c.b])) + 2 * eta * eta;
    const double den = dk[c.a] - dk[c.b];
    if (std::abs(num) <= 2 * num_bound || std::abs(den) <= 4 * eta) return 0;
    return sign(num) * sign(den);
  }
  const Vec3& dl = d[std::size_t(c.b)];
  const Vec3 w = dk.cross(dl);
  const double e = std::sqrt(3.0) * eta;
  const double nk = dk.norm(), nl = dl.norm(), nm = dm.norm();
  const double num = w.dot(dm), den = w.sum();
  const double num_bound = (nk + e) * (nl + e) * (nm + e) - nk * nl * nm;
  const double den_bound = std::sqrt(3.0) * ((nk + e) * (nl + e) - nk * nl);
  if (std::abs(num) <= 2 * num_bound || std::abs(den) <= 2 * den_bound) return 0;
  return sign(num) * sign(den);
}

// The corner where plane m cuts the side p q: on their common edge, or where m crosses
// the plane they both lie on. false when they share neither (never, for this rule).
bool cut_corner(const Corner& p, const Corner& q, int m, Corner& out) {
  out = Corner{};
  if (const unsigned common = p.edges & q.edges) {
    const int e = common & 1u ? 0 : (common & 2u ? 1 : 2);
    out.kind = Corner::Kind::edge_cut;
    out.a = e;
    out.b = (e + 1) % 3;
    out.k = m;
    out.edges = 1u << e;
  } else if (const unsigned common_planes = p.planes & q.planes) {
    int k = 0;
    while (!(common_planes & (1u << k))) ++k;
    out.kind = Corner::Kind::plane_cut;
    out.k = k;
    out.b = m;  // the second plane
  } else {
    return false;
  }
  out.planes = 1u << m;
  if (out.kind == Corner::Kind::plane_cut) out.planes |= 1u << out.k;
  return true;
}

// ---- Overlap of two pieces -------------------------------------------------------------

int dominant_axis(const Vec3& n) {
  const Vec3 a = n.cwiseAbs();
  return a.x() >= a.y() && a.x() >= a.z() ? 0 : (a.y() >= a.z() ? 1 : 2);
}

template <class K> typename K::Point_2 drop(const Vec3& p, int axis) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  return {p[u], p[v]};
}

template <class Point> std::array<Point, 3> counterclockwise(Point a, Point b, Point c) {
  if (CGAL::orientation(a, b, c) == CGAL::CLOCKWISE) std::swap(b, c);
  return {a, b, c};
}

// Two counter-clockwise triangles have disjoint interiors when the closed outer side of
// an edge line of one holds the whole other one.
bool separated(const std::array<Epick::Point_2, 3>& a, const std::array<Epick::Point_2, 3>& b) {
  for (int round = 0; round < 2; ++round) {
    const auto& p = round == 0 ? a : b;
    const auto& q = round == 0 ? b : a;
    for (int i = 0; i < 3; ++i) {
      bool all_outside = true;
      for (int j = 0; j < 3 && all_outside; ++j)
        all_outside = CGAL::orientation(p[i], p[(i + 1) % 3], q[j]) != CGAL::LEFT_TURN;
      if (all_outside) return true;
    }
  }
  return false;
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

// sign(x) sqrt(x^2 / n2), rounded once: x / sqrt(n2) without rounding x^2 first.
double divided_by_root(const FT& x, const FT& n2) { return CGAL::sign(x) * std::sqrt(rounded(x * x / n2)); }

}  // namespace

ClippedPolygon clip(const Triangle& t, const std::vector<Plane>& planes) {
  ClippedPolygon result;
  // The usual cases first, from exact signs alone: wholly inside every plane, or wholly
  // outside one (strictly: a vertex on the plane would be kept).
  bool inside = true;
  for (const Plane& plane : planes) {
    const std::array<int, 3> s = sides(t, plane);
    if (s[0] < 0 && s[1] < 0 && s[2] < 0) return result;
    inside = inside && s[0] >= 0 && s[1] >= 0 && s[2] >= 0;
  }
  std::vector<Epeck::Point_3> polygon = {exact(t.v0), exact(t.v1), exact(t.v2)};
  if (!inside)
    for (const Plane& plane : planes) {
      polygon = clip_by(polygon, plane);
      if (polygon.empty()) return result;
    }
  for (const auto& p : polygon) result.corners.push_back(rounded(p));
  const FT twice2 = twice_vector_area(polygon).squared_length();
  result.has_area = CGAL::is_positive(twice2);
  result.area = 0.5 * std::sqrt(rounded(twice2));
  return result;
}

bool clip_in_doubt(const Triangle& t, const std::vector<Plane>& planes, double delta) {
  const double eta = 8 * delta;
  std::vector<Vec3> d;
  for (const Plane& plane : planes) {
    const double length = plane.normal.norm();
    if (length == 0) return true;
    d.push_back(Vec3(plane.value(t.v0), plane.value(t.v1), plane.value(t.v2)) / length);
  }
  std::vector<Corner> polygon(3), next;
  for (int i = 0; i < 3; ++i) {
    polygon[std::size_t(i)].a = i;
    polygon[std::size_t(i)].edges = (1u << i) | (1u << ((i + 2) % 3));
  }
  std::vector<int> signs;
  for (int m = 0; m < int(planes.size()) && !polygon.empty(); ++m) {
    signs.clear();
    for (const Corner& c : polygon) {
      signs.push_back(stable_sign(c, m, d, eta));
      if (signs.back() == 0) return true;
    }
    next.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const std::size_t j = (i + 1) % polygon.size();
      if (signs[i] > 0) next.push_back(polygon[i]);
      if (signs[i] * signs[j] < 0) {
        Corner cut;
        if (!cut_corner(polygon[i], polygon[j], m, cut)) return true;
        next.push_back(cut);
      }
    }
    polygon.swap(next);
    if (polygon.size() < 3) polygon.clear();
  }
  return false;
}

double overlap_area(const Triangle& a, const Triangle& b, const Triangle& reference) {
  const Vec3 n = reference.normal();
  if (n == Vec3::Zero()) return 0.0;
  const int axis = dominant_axis(n);
  const auto fa = counterclockwise(drop<Epick>(a.v0, axis), drop<Epick>(a.v1, axis), drop<Epick>(a.v2, axis));
  const auto fb = counterclockwise(drop<Epick>(b.v0, axis), drop<Epick>(b.v1, axis), drop<Epick>(b.v2, axis));
  if (CGAL::collinear(fa[0], fa[1], fa[2]) || CGAL::collinear(fb[0], fb[1], fb[2])) return 0.0;
  if (separated(fa, fb)) return 0.0;
  const auto ea = counterclockwise(drop<Epeck>(a.v0, axis), drop<Epeck>(a.v1, axis), drop<Epeck>(a.v2, axis));
  const auto eb = counterclockwise(drop<Epeck>(b.v0, axis), drop<Epeck>(b.v1, axis), drop<Epeck>(b.v2, axis));
  const auto overlap =
      CGAL::intersection(Epeck::Triangle_2(ea[0], ea[1], ea[2]), Epeck::Triangle_2(eb[0], eb[1], eb[2]));
  if (!overlap) return 0.0;
  FT area2d = 0;
  if (const auto* t = boost::get<Epeck::Triangle_2>(&*overlap)) area2d = CGAL::abs(t->area());
  if (const auto* poly = boost::get<std::vector<Epeck::Point_2>>(&*overlap)) area2d = polygon_area(*poly);
  // Areas in the dropped-axis plane shrink by |n_axis| / |n|.
  return rounded(area2d) * n.norm() / std::abs(n[axis]);
}

double signed_distance(const Plane& plane, const Vec3& x) {
  return divided_by_root(value(plane, exact(x)), squared_norm(plane.normal));
}

bool inside_all(const Vec3& x, const std::vector<Plane>& planes, double tolerance) {
  const Epeck::Point_3 p = exact(x);
  for (const Plane& plane : planes) {
    // Settled in double when the value, less a bound on its rounding error, clears
    // -tolerance |normal| (the norm's own rounding is far below the 1% spared).
    if (plane.value(x) - rounding_bound(plane, x) >= -0.99 * tolerance * plane.normal.norm()) continue;
    const FT v = value(plane, p);
    if (v >= 0) continue;
    if (v * v > ft(tolerance) * ft(tolerance) * squared_norm(plane.normal)) return false;
  }
  return true;
}

std::array<Plane, 6> frustum_planes(const Mat4& m) {
  std::array<Plane, 6> planes;
  for (int i = 0; i < 6; ++i) {
    const int row = i / 2;
    const FT sign = i % 2 == 0 ? ft(1) : ft(-1);
    FT c[4];
    for (int j = 0; j < 4; ++j) c[j] = ft(m(3, j)) + sign * ft(m(row, j));
    const FT n2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    if (CGAL::is_zero(n2)) {
      planes[std::size_t(i)] = Plane{Vec3::Zero(), 0.0};
      continue;
    }
    planes[std::size_t(i)] =
        Plane{Vec3(divided_by_root(c[0], n2), divided_by_root(c[1], n2), divided_by_root(c[2], n2)),
              divided_by_root(c[3], n2)};
  }
  return planes;
}

}  // namespace oracle
