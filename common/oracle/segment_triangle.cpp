#include "common/oracle/segment_triangle.h"
#include "common/oracle/kernel.h"

#include <CGAL/Aff_transformation_3.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace oracle {

using namespace kernel;

namespace {

// t of the point p on the segment (p is known to lie on it).
FT parameter(const Epeck::Segment_3& s, const Epeck::Point_3& p) {
  const Epeck::Vector_3 d = s.to_vector();
  return (p - s.source()) * d / (d * d);
}

// The exact first common point of a segment and a triangle, both already exact.
struct ExactHit {
  bool hit = false;
  bool coplanar = false;
  FT t = 0;
  Epeck::Point_3 point;
};

ExactHit first_hit(const Epeck::Segment_3& s, const Epeck::Triangle_3& t) {
  ExactHit h;
  if (t.is_degenerate()) return h;  // a zero-area triangle is never hit
  h.coplanar = CGAL::coplanar(t[0], t[1], t[2], s.source()) && CGAL::coplanar(t[0], t[1], t[2], s.target());
  if (s.is_degenerate()) {
    if (!t.has_on(s.source())) return h;
    h.hit = true;
    h.point = s.source();
    return h;
  }
  const auto result = CGAL::intersection(s, t);
  if (!result) return h;
  h.hit = true;
  if (const Epeck::Point_3* p = boost::get<Epeck::Point_3>(&*result)) {
    h.point = *p;
    h.t = parameter(s, *p);
  } else {
    // Coplanar overlap: the end of the shared piece nearer to a.
    const Epeck::Segment_3& piece = boost::get<Epeck::Segment_3>(*result);
    const FT t0 = parameter(s, piece.source()), t1 = parameter(s, piece.target());
    h.point = t0 <= t1 ? piece.source() : piece.target();
    h.t = CGAL::min(t0, t1);
  }
  return h;
}

SegmentHit rounded_hit(const ExactHit& h, int triangle) {
  SegmentHit r;
  r.hit = h.hit;
  r.coplanar = h.coplanar;
  r.triangle = triangle;
  if (h.hit) {
    r.t = rounded(h.t);
    r.point = rounded(h.point);
  }
  return r;
}

Epeck::Aff_transformation_3 exact_transform(const RigidTransform& m) {
  const auto& a = m.matrix();
  return {ft(a(0, 0)), ft(a(0, 1)), ft(a(0, 2)), ft(a(0, 3)), ft(a(1, 0)), ft(a(1, 1)), ft(a(1, 2)),
          ft(a(1, 3)), ft(a(2, 0)), ft(a(2, 1)), ft(a(2, 2)), ft(a(2, 3)), ft(1)};
}

bool by_t_then_index(const SegmentHit& x, const SegmentHit& y) {
  return x.t != y.t ? x.t < y.t : x.triangle < y.triangle;
}

}  // namespace

bool segment_hits_triangle(const Segment& s, const Triangle& t) {
  const Epick::Triangle_3 tri(fast(t.v0), fast(t.v1), fast(t.v2));
  if (tri.is_degenerate()) return false;
  const Epick::Segment_3 seg(fast(s.a), fast(s.b));
  if (seg.is_degenerate()) return tri.has_on(seg.source());
  return CGAL::do_intersect(seg, tri);
}

PlaneCrossing segment_plane(const Segment& s, const Triangle& t) {
  PlaneCrossing c;
  const Epeck::Triangle_3 tri = exact(t);
  if (tri.is_degenerate()) return c;
  const Epeck::Vector_3 n = CGAL::cross_product(tri[1] - tri[0], tri[2] - tri[0]);
  const FT na = (exact(s.a) - tri[0]) * n, nb = (exact(s.b) - tri[0]) * n;
  c.side_a = sign_of(CGAL::sign(na));
  c.side_b = sign_of(CGAL::sign(nb));
  // d = num / |n|: square, divide exactly, round, take the root, put the sign back.
  const FT n2 = n.squared_length();
  c.d_a = c.side_a * std::sqrt(rounded(na * na / n2));
  c.d_b = c.side_b * std::sqrt(rounded(nb * nb / n2));
  c.crosses = c.side_a * c.side_b <= 0 && !(c.side_a == 0 && c.side_b == 0);
  if (c.crosses) {
    const FT t = na / (na - nb);
    c.t = rounded(t);
    c.point = rounded(exact(s.a) + (exact(s.b) - exact(s.a)) * t);
  }
  return c;
}

bool segment_crosses_plane(const Segment& s, const Triangle& t) {
  const Epick::Point_3 v0 = fast(t.v0), v1 = fast(t.v1), v2 = fast(t.v2);
  if (CGAL::collinear(v0, v1, v2)) return false;
  const int side_a = sign_of(CGAL::orientation(v0, v1, v2, fast(s.a)));
  const int side_b = sign_of(CGAL::orientation(v0, v1, v2, fast(s.b)));
  return side_a * side_b <= 0 && !(side_a == 0 && side_b == 0);
}

// The projection along n is inside exactly when x is on the inner side of the three
// planes through the edges that contain n: signs of (n x e_i) . (x - v_i).
bool point_in_triangle_projected(const Vec3& x, const Triangle& t) {
  const Epeck::Triangle_3 tri = exact(t);
  if (tri.is_degenerate()) return false;
  const Epeck::Vector_3 n = CGAL::cross_product(tri[1] - tri[0], tri[2] - tri[0]);
  const Epeck::Point_3 p = exact(x);
  for (int i = 0; i < 3; ++i) {
    const Epeck::Vector_3 inward = CGAL::cross_product(n, tri[(i + 1) % 3] - tri[i]);
    if (CGAL::is_negative(inward * (p - tri[i]))) return false;
  }
  return true;
}

bool point_in_triangle_in_doubt(const Vec3& x, const Triangle& t, double delta) {
  const Epeck::Triangle_3 tri = exact(t);
  if (tri.is_degenerate()) return false;
  const Epeck::Point_3 projected = tri.supporting_plane().projection(exact(x));
  const FT reach = ft(delta) * ft(delta);
  for (int i = 0; i < 3; ++i)
    if (CGAL::squared_distance(projected, Epeck::Segment_3(tri[i], tri[(i + 1) % 3])) <= reach) return true;
  return false;
}

Vec3 unit_normal(const Triangle& t) {
  const Epeck::Triangle_3 tri = exact(t);
  if (tri.is_degenerate()) return Vec3::Zero();
  const Epeck::Vector_3 n = CGAL::cross_product(tri[1] - tri[0], tri[2] - tri[0]);
  const FT n2 = n.squared_length();
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = CGAL::sign(n[i]) * std::sqrt(rounded(n[i] * n[i] / n2));
  return r;
}

namespace {
bool within_exact(const Epeck::Point_3& p, const Vec3& x, double tolerance) {
  return CGAL::squared_distance(p, exact(x)) <= ft(tolerance) * ft(tolerance);
}
}  // namespace

bool weights_reproduce(const Triangle& t, const Vec3& w, const Vec3& x, double tolerance) {
  const Epeck::Point_3 origin = CGAL::ORIGIN;
  const Epeck::Point_3 p = origin + (exact(t.v0) - origin) * ft(w[0]) + (exact(t.v1) - origin) * ft(w[1]) +
                           (exact(t.v2) - origin) * ft(w[2]);
  return within_exact(p, x, tolerance);
}

bool alpha_beta_reproduce(const Triangle& t, double alpha, double beta, const Vec3& x, double tolerance) {
  const Epeck::Point_3 v0 = exact(t.v0);
  const Epeck::Point_3 p = v0 + (exact(t.v1) - v0) * ft(alpha) + (exact(t.v2) - v0) * ft(beta);
  return within_exact(p, x, tolerance);
}

bool parameter_reproduces(const Segment& s, double t, const Vec3& x, double tolerance) {
  const Epeck::Point_3 a = exact(s.a);
  return within_exact(a + (exact(s.b) - a) * ft(t), x, tolerance);
}

namespace {

double squared_distance_fast(const Epick::Point_3& p, const Epick::Segment_3& s) {
  return s.is_degenerate() ? CGAL::squared_distance(p, s.source()) : CGAL::squared_distance(p, s);
}

double squared_distance_fast(const Epick::Segment_3& s, const Epick::Segment_3& e) {
  if (s.is_degenerate()) return squared_distance_fast(s.source(), e);
  if (e.is_degenerate()) return squared_distance_fast(e.source(), s);
  return CGAL::squared_distance(s, e);
}

// Distance between a segment and a closed triangle that do not intersect: the nearest
// points lie on an end of the segment or on an edge of the triangle.
double separation(const Segment& s, const Triangle& t) {
  const Epick::Segment_3 seg(fast(s.a), fast(s.b));
  const Epick::Triangle_3 tri(fast(t.v0), fast(t.v1), fast(t.v2));
  double d2 = std::numeric_limits<double>::infinity();
  if (!tri.is_degenerate())
    d2 = std::min(CGAL::squared_distance(seg.source(), tri), CGAL::squared_distance(seg.target(), tri));
  for (int i = 0; i < 3; ++i) d2 = std::min(d2, squared_distance_fast(seg, Epick::Segment_3(tri[i], tri[(i + 1) % 3])));
  return std::sqrt(d2);
}

}  // namespace

bool segment_triangle_in_doubt(const Segment& s, const Triangle& t, double delta) {
  const double eps = std::sqrt(3.0) * delta;  // how far any one point may move
  if (!segment_hits_triangle(s, t)) return separation(s, t) <= 4 * eps;

  // A hit (so the triangle has area). Barycentric coordinates of any point's
  // projection, extended beyond the triangle: the plane's height at p is their
  // combination of the vertices' heights, so moving each vertex by eps moves the plane
  // at p by at most eps * sum |lambda_i|.
  const Vec3 n = t.normal();
  const double twice_area = n.norm();
  const Vec3 unit = n / twice_area;
  const auto lambda = [&](const Vec3& p) {
    return Vec3((t.v1 - p).cross(t.v2 - p).dot(unit), (t.v2 - p).cross(t.v0 - p).dot(unit),
                (t.v0 - p).cross(t.v1 - p).dot(unit)) /
           twice_area;
  };
  const auto slack = [&](const Vec3& p) { return 2 * eps * (1 + lambda(p).cwiseAbs().sum()); };
  const double h_a = (s.a - t.v0).dot(unit), h_b = (s.b - t.v0).dot(unit);
  const double slack_a = slack(s.a), slack_b = slack(s.b);
  if (std::abs(h_a) <= slack_a || std::abs(h_b) <= slack_b) return true;  // an end may reach the plane

  // Both ends clear of the plane. The crossing x = a + t (b - a), t = h_a / (h_a - h_b),
  // moves by at most eps + |b - a| dt; its barycentric coordinates by that over the
  // triangle's smallest height, plus what the vertices' own moves add.
  const double dt = (slack_a + slack_b) / (std::abs(h_a) + std::abs(h_b));
  const Vec3 x = s.point(h_a / (h_a - h_b));
  const double dx = eps + (s.b - s.a).norm() * dt;
  const double longest = std::max({(t.v1 - t.v0).norm(), (t.v2 - t.v1).norm(), (t.v0 - t.v2).norm()});
  const double smallest_height = twice_area / longest;
  return lambda(x).minCoeff() <= 2 * (dx + 3 * eps) / smallest_height;
}

SegmentHit segment_triangle(const Segment& s, const Triangle& t) {
  return rounded_hit(first_hit(exact(s), exact(t)), 0);
}

bool segment_hits_mesh(const Segment& s, const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.size(); ++i)
    if (segment_hits_triangle(s, mesh.triangle(i))) return true;
  return false;
}

std::vector<SegmentHit> segment_mesh_hits(const Segment& s, const Mesh& mesh) {
  std::vector<SegmentHit> hits;
  const Epeck::Segment_3 seg = exact(s);
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    if (!segment_hits_triangle(s, mesh.triangle(i))) continue;  // cheap exact rejection first
    hits.push_back(rounded_hit(first_hit(seg, exact(mesh.triangle(i))), int(i)));
  }
  std::sort(hits.begin(), hits.end(), by_t_then_index);
  return hits;
}

namespace {
Epeck::Segment_3 local_path(const Segment& s, const RigidTransform& m0, const RigidTransform& m1) {
  return {exact_transform(m0).inverse().transform(exact(s.a)), exact_transform(m1).inverse().transform(exact(s.b))};
}
}  // namespace

Segment moving_local_path(const Segment& s, const RigidTransform& m0, const RigidTransform& m1) {
  const Epeck::Segment_3 local = local_path(s, m0, m1);
  return {rounded(local.source()), rounded(local.target())};
}

bool moving_mesh_hit_any(const Segment& s, const Mesh& mesh, const RigidTransform& m0, const RigidTransform& m1) {
  const Epeck::Segment_3 local = local_path(s, m0, m1);
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Epeck::Triangle_3 tri = exact(mesh.triangle(i));
    if (tri.is_degenerate()) continue;
    if (local.is_degenerate() ? tri.has_on(local.source()) : CGAL::do_intersect(local, tri)) return true;
  }
  return false;
}

std::string check_moving_hit(const Segment& s, const Mesh& mesh, const RigidTransform& m0, const RigidTransform& m1,
                             int index, double t, const Vec3& point, double tolerance) {
  if (index < 0 || std::size_t(index) >= mesh.size()) return "the triangle index is out of range";
  const Epeck::Aff_transformation_3 pose = exact_transform(m1);
  const Epeck::Triangle_3 posed = exact(mesh.triangle(std::size_t(index))).transform(pose);
  const Epeck::Point_3 a_delta = pose.transform(exact_transform(m0).inverse().transform(exact(s.a)));
  const Epeck::Segment_3 path(a_delta, exact(s.b));
  const Epeck::Point_3 p = exact(point);
  const FT tol2 = ft(tolerance) * ft(tolerance);
  const auto distance2 = [](const Epeck::Point_3& q, const Epeck::Segment_3& seg) {
    return seg.is_degenerate() ? CGAL::squared_distance(q, seg.source()) : CGAL::squared_distance(q, seg);
  };
  if (!posed.is_degenerate() && CGAL::squared_distance(p, posed) > tol2)
    return "the point is not on that triangle (with the mesh at m1)";
  if (distance2(p, path) > tol2) return "the point is not on the path a' -> b, a' = m1 m0^-1 a";
  if (CGAL::squared_distance(a_delta + (path.target() - a_delta) * ft(t), p) > tol2)
    return "a' + t (b - a') does not reproduce the point";
  return "";
}

std::vector<SegmentHit> moving_mesh_hits(const Segment& s, const Mesh& mesh, const RigidTransform& m0,
                                         const RigidTransform& m1) {
  const Epeck::Aff_transformation_3 to_world = exact_transform(m1);
  const Epeck::Segment_3 local = local_path(s, m0, m1);
  std::vector<SegmentHit> hits;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    ExactHit h = first_hit(local, exact(mesh.triangle(i)));
    if (!h.hit) continue;
    h.point = to_world.transform(h.point);
    hits.push_back(rounded_hit(h, int(i)));
  }
  std::sort(hits.begin(), hits.end(), by_t_then_index);
  return hits;
}

}  // namespace oracle
