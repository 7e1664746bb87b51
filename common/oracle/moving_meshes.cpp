#include "common/oracle/moving_meshes.h"
#include "common/oracle/kernel.h"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

namespace oracle {

using namespace kernel;

namespace {

using P = Epeck::Point_3;
using V = Epeck::Vector_3;

// Interval arithmetic on CGAL's own kernel, for the screen below.
using Interval = CGAL::Interval_nt<false>;  // needs the rounding mode set by the caller
using IK = CGAL::Simple_cartesian<Interval>;

IK::Point_3 interval_point(const Vec3& v) { return {finite(v.x()), finite(v.y()), finite(v.z())}; }
IK::Vector_3 interval_vector(const Vec3& v) { return {finite(v.x()), finite(v.y()), finite(v.z())}; }

// In either kernel (K = Epeck or IK).
template <class K> typename K::FT dot(const CGAL::Vector_3<K>& a, const CGAL::Vector_3<K>& b) { return a * b; }
template <class K> CGAL::Vector_3<K> cross(const CGAL::Vector_3<K>& a, const CGAL::Vector_3<K>& b) {
  return CGAL::cross_product(a, b);
}
template <class K>
typename K::FT triple(const CGAL::Vector_3<K>& a, const CGAL::Vector_3<K>& b, const CGAL::Vector_3<K>& c) {
  return dot(a, cross(b, c));
}

// The two tests below are written once, for exact numbers and for intervals (the screen
// further down).
//
// The vertex path p -> p + d against the still triangle (v0, v1, v2) with normal n, when
// den = d . n is not zero: the t in [0, 1] with p + t d in the closed triangle, if any.
template <class Point, class Vector, class NT>
std::optional<NT> crossing_time(const Point& p, const Vector& d, const Point& v0, const Point& v1, const Point& v2,
                                const Vector& n, const NT& den) {
  const NT t = dot(v0 - p, n) / den;
  if (t < 0 || t > 1) return std::nullopt;
  const Point x = p + t * d;
  const Point v[3] = {v0, v1, v2};
  for (int i = 0; i < 3; ++i)
    if (CGAL::is_negative(triple(v[(i + 1) % 3] - v[i], x - v[i], n))) return std::nullopt;
  return t;
}

// The edge p0 + u e swept by d against the still edge q0 + s f, with r = q0 - p0 and det
// = [e, d, -f] not zero: p0 + u e + t d = q0 + s f with u, s, t in [0, 1], by Cramer's
// rule. Returns (t, s).
template <class Vector, class NT>
std::optional<std::pair<NT, NT>> meeting_times(const Vector& r, const Vector& e, const Vector& d, const Vector& minus_f,
                                               const NT& det) {
  const NT u = triple(r, d, minus_f) / det;
  if (u < 0 || u > 1) return std::nullopt;
  const NT t = triple(e, r, minus_f) / det;
  if (t < 0 || t > 1) return std::nullopt;
  const NT s = triple(e, d, r) / det;
  if (s < 0 || s > 1) return std::nullopt;
  return std::make_pair(t, s);
}

// A candidate contact, exact.
struct Exact {
  FT t;
  P point;  // in the world at time t
  int kind, fa, fb;
  double approach;
};

// t of the point x on the segment p -> p + d (x is known to lie on it).
FT parameter(const P& p, const V& d, const P& x) { return ((x - p) * d) / (d * d); }

// The first t of the segment p -> p + d against the closed triangle, by CGAL's own
// intersection: for paths in the triangle's plane (the common part may be a piece).
std::optional<FT> first_on_segment(const P& p, const V& d, const Epeck::Triangle_3& tri) {
  if (tri.is_degenerate() || d == CGAL::NULL_VECTOR) return std::nullopt;
  const auto result = CGAL::intersection(Epeck::Segment_3(p, p + d), tri);
  if (!result) return std::nullopt;
  if (const P* x = boost::get<P>(&*result)) return parameter(p, d, *x);
  const Epeck::Segment_3& piece = boost::get<Epeck::Segment_3>(*result);
  return CGAL::min(parameter(p, d, piece.source()), parameter(p, d, piece.target()));
}

// The vertex path p -> p + d against the still triangle (v0, v1, v2): the first t in
// [0, 1] with p + t d in the closed triangle.
std::optional<FT> vertex_face(const P& p, const V& d, const P& v0, const P& v1, const P& v2, double* approach) {
  const V n = CGAL::cross_product(v1 - v0, v2 - v0);
  const FT den = d * n;
  if (CGAL::is_zero(den)) {  // parallel to the plane: a contact only if the path lies in it
    if (n == CGAL::NULL_VECTOR || !CGAL::is_zero((p - v0) * n)) return std::nullopt;
    *approach = 0;
    return first_on_segment(p, d, {v0, v1, v2});
  }
  const std::optional<FT> t = crossing_time(p, d, v0, v1, v2, n, den);
  if (t) *approach = std::abs(rounded(den)) / std::sqrt(rounded(n * n));
  return t;
}

// The edge p0 + u e swept by d against the still edge q0 + s f: p0 + u e + t d = q0 + s f
// with u, s, t in [0, 1], by Cramer's rule. A zero determinant (e, d, f in one plane) is
// left out, as above.
std::optional<std::pair<FT, FT>> edge_edge(const P& p0, const V& e, const V& d, const P& q0, const V& f,
                                           double* approach) {
  const V r = q0 - p0;
  const V minus_f = -f;
  const FT det = triple(e, d, minus_f);
  if (CGAL::is_zero(det)) return std::nullopt;
  const auto ts = meeting_times(r, e, d, minus_f, det);
  if (ts) {
    const V n = CGAL::cross_product(e, f);
    *approach = std::abs(rounded(d * n)) / std::sqrt(rounded(n * n));
  }
  return ts;
}

// ---- The screen ------------------------------------------------------------------------
// Each of the three families' tests runs first in interval arithmetic on the input's
// doubles. Most pairs of features are decided there (no contact in [0, 1], or contact at
// a time within a known interval); only the pairs it cannot decide, and those that may
// be the first contact, are tested again exactly. The intervals contain the exact values,
// so every decision the screen takes is the exact test's.

// The interval tests: no value for no contact, or an interval holding the contact time.
// Any comparison the intervals cannot decide throws CGAL::Uncertain_conversion_exception,
// and so does a path parallel to the face's plane or edges in one plane (the exact tests
// handle those).
std::optional<Interval> vertex_face_screen(const IK::Point_3& p, const IK::Vector_3& d, const IK::Point_3& v0,
                                           const IK::Point_3& v1, const IK::Point_3& v2) {
  const IK::Vector_3 n = cross(v1 - v0, v2 - v0);
  const Interval den = dot(d, n);
  if (CGAL::is_zero(den)) throw CGAL::Uncertain_conversion_exception("a path parallel to the face");
  return crossing_time(p, d, v0, v1, v2, n, den);
}

std::optional<Interval> edge_edge_screen(const IK::Point_3& p0, const IK::Vector_3& e, const IK::Vector_3& d,
                                         const IK::Point_3& q0, const IK::Vector_3& f) {
  const IK::Vector_3 r = q0 - p0;
  const IK::Vector_3 minus_f = -f;
  const Interval det = triple(e, d, minus_f);
  if (CGAL::is_zero(det)) throw CGAL::Uncertain_conversion_exception("edges in one plane");
  const auto ts = meeting_times(r, e, d, minus_f, det);
  return ts ? std::optional<Interval>(ts->first) : std::nullopt;
}

// A pair of features the screen did not rule out: family `kind` (as in MeshContact), the
// vertex or edge i and the face or edge k; `decided` when it surely touches, at a time in
// [lo, hi].
struct Screened {
  int kind;
  std::size_t i, k;
  bool decided;
  double lo, hi;
};

struct Motion {
  const Mesh& a;
  const Vec3& va;
  const Mesh& b;
  const Vec3& vb;
  std::vector<std::array<int, 2>> ea, eb;  // the meshes' edges
};

template <class Test> void screen_one(std::vector<Screened>& out, int kind, std::size_t i, std::size_t k, Test&& test) {
  try {
    if (const std::optional<Interval> t = test()) out.push_back({kind, i, k, true, t->inf(), t->sup()});
  } catch (const CGAL::Uncertain_conversion_exception&) {
    out.push_back({kind, i, k, false, 0.0, 1.0});
  }
}

std::vector<Screened> screen(const Motion& m) {
  CGAL::Protect_FPU_rounding<true> upward;
  const IK::Vector_3 d = interval_vector(m.va) - interval_vector(m.vb);
  std::vector<IK::Point_3> pa, pb;
  for (const Vec3& v : m.a.vertices) pa.push_back(interval_point(v));
  for (const Vec3& v : m.b.vertices) pb.push_back(interval_point(v));
  std::vector<Screened> out;
  for (std::size_t i = 0; i < pa.size(); ++i)
    for (std::size_t k = 0; k < m.b.triangles.size(); ++k) {
      const auto& tri = m.b.triangles[k];
      screen_one(out, 0, i, k, [&] { return vertex_face_screen(pa[i], d, pb[tri[0]], pb[tri[1]], pb[tri[2]]); });
    }
  const IK::Vector_3 minus_d = -d;
  for (std::size_t j = 0; j < pb.size(); ++j)
    for (std::size_t k = 0; k < m.a.triangles.size(); ++k) {
      const auto& tri = m.a.triangles[k];
      screen_one(out, 1, j, k, [&] { return vertex_face_screen(pb[j], minus_d, pa[tri[0]], pa[tri[1]], pa[tri[2]]); });
    }
  for (std::size_t i = 0; i < m.ea.size(); ++i)
    for (std::size_t j = 0; j < m.eb.size(); ++j) {
      const IK::Point_3& p0 = pa[m.ea[i][0]];
      const IK::Point_3& q0 = pb[m.eb[j][0]];
      screen_one(out, 2, i, j, [&] { return edge_edge_screen(p0, pa[m.ea[i][1]] - p0, d, q0, pb[m.eb[j][1]] - q0); });
    }
  return out;
}

// Every candidate the screen kept that may touch by `limit`, tested exactly and passed to
// `keep` in the screen's order; `keep` returns true to stop early.
template <class Keep> void candidates(const Motion& m, const std::vector<Screened>& kept, double limit, Keep&& keep) {
  const V wa = exact(m.va) - CGAL::ORIGIN, wb = exact(m.vb) - CGAL::ORIGIN;
  const V d = wa - wb;  // A's motion as seen from B
  const auto point = [](const Mesh& mesh, std::size_t i) { return exact(mesh.vertices[i]); };
  const auto corner = [&](const Mesh& mesh, std::size_t k, int c) {
    return point(mesh, std::size_t(mesh.triangles[k][c]));
  };
  double approach = 0;
  for (const Screened& c : kept) {
    if (c.lo > limit) continue;
    if (c.kind == 0) {
      const P p = point(m.a, c.i);
      if (auto t = vertex_face(p, d, corner(m.b, c.k, 0), corner(m.b, c.k, 1), corner(m.b, c.k, 2), &approach))
        if (keep(Exact{*t, p + *t * wa, 0, int(c.i), int(c.k), approach})) return;
    } else if (c.kind == 1) {
      const P q = point(m.b, c.i);
      if (auto t = vertex_face(q, -d, corner(m.a, c.k, 0), corner(m.a, c.k, 1), corner(m.a, c.k, 2), &approach))
        if (keep(Exact{*t, q + *t * wb, 1, int(c.k), int(c.i), approach})) return;
    } else {
      const P p0 = point(m.a, std::size_t(m.ea[c.i][0]));
      const P q0 = point(m.b, std::size_t(m.eb[c.k][0]));
      const V f = point(m.b, std::size_t(m.eb[c.k][1])) - q0;
      if (auto ts = edge_edge(p0, point(m.a, std::size_t(m.ea[c.i][1])) - p0, d, q0, f, &approach))
        if (keep(Exact{ts->first, q0 + ts->second * f + ts->first * wb, 2, int(c.i), int(c.k), approach})) return;
    }
  }
}

}  // namespace

MeshContact first_contact_translating(const Mesh& a, const Vec3& va, const Mesh& b, const Vec3& vb) {
  const Motion m{a, va, b, vb, a.edges(), b.edges()};
  const std::vector<Screened> kept = screen(m);
  // No contact is later than the latest time of any contact the screen is sure of.
  double limit = 1.0;
  for (const Screened& c : kept)
    if (c.decided) limit = std::min(limit, c.hi);
  std::optional<Exact> best;
  candidates(m, kept, limit, [&](const Exact& c) {
    if (!best || c.t < best->t) best = c;
    return false;
  });
  if (!best) return {};
  MeshContact out{true, rounded(best->t), rounded(best->point), best->kind, best->fa, best->fb, best->approach};
  // The features' normal: a face's (B's for kind 0, A's for kind 1), or e x f.
  const auto edge = [](const Mesh& m, const std::array<int, 2>& e) {
    return exact(m.vertices[std::size_t(e[1])]) - exact(m.vertices[std::size_t(e[0])]);
  };
  V n;
  if (best->kind == 2) {
    n = CGAL::cross_product(edge(a, a.edges()[std::size_t(best->fa)]), edge(b, b.edges()[std::size_t(best->fb)]));
  } else {
    const Epeck::Triangle_3 face =
        exact(best->kind == 0 ? b.triangle(std::size_t(best->fb)) : a.triangle(std::size_t(best->fa)));
    n = CGAL::cross_product(face[1] - face[0], face[2] - face[0]);
  }
  if (CGAL::is_positive(n * (exact(va) - exact(vb)))) n = -n;
  const double length = std::sqrt(rounded(n * n));
  if (length > 0) out.normal = Vec3(rounded(n.x()), rounded(n.y()), rounded(n.z())) / length + Vec3::Zero();  // no -0
  return out;
}

bool contact_by(const Mesh& a, const Vec3& va, const Mesh& b, const Vec3& vb, double t) {
  if (t < 0) return false;
  const Motion m{a, va, b, vb, a.edges(), b.edges()};
  const std::vector<Screened> kept = screen(m);
  for (const Screened& c : kept)
    if (c.decided && c.hi <= t) return true;
  bool found = false;
  const FT limit(t);
  candidates(m, kept, t, [&](const Exact& c) { return found = c.t <= limit; });
  return found;
}

namespace {

// The normal of two edges e and f (a face's normal is that of two of its edges), rounded
// to unit length, with how loosely they fix it; parallel edges give their axis.
ContactNormal normal_of(const V& e, const V& f) {
  const V n = CGAL::cross_product(e, f);
  const double ee = std::sqrt(rounded(e * e)), ff = std::sqrt(rounded(f * f));
  if (n == CGAL::NULL_VECTOR) {
    const V axis = e == CGAL::NULL_VECTOR ? f : e;
    const double length = std::sqrt(rounded(axis * axis));
    return {Vec3(rounded(axis.x()), rounded(axis.y()), rounded(axis.z())) / length, true, 1.0};
  }
  const double nn = std::sqrt(rounded(n * n));
  return {Vec3(rounded(n.x()), rounded(n.y()), rounded(n.z())) / nn, false, std::max(1.0, ee * ff / nn)};
}

// Exact: whether the segment s (perhaps a point) comes within sqrt(r2) of the closed
// triangle (not degenerate); r2 = 0 asks whether they meet. Apart, the closest pair has
// an end of s or a point of a side of the triangle (CGAL 5.5 has no segment-triangle
// distance of its own, only the point-triangle and segment-segment ones used here).
bool near_triangle(const Epeck::Segment_3& s, const Epeck::Triangle_3& tri, const FT& r2) {
  if (s.is_degenerate() ? tri.has_on(s.source()) : CGAL::do_intersect(s, tri)) return true;
  if (CGAL::is_zero(r2)) return false;
  if (s.is_degenerate()) return CGAL::squared_distance(s.source(), tri) <= r2;
  if (CGAL::squared_distance(s.source(), tri) <= r2 || CGAL::squared_distance(s.target(), tri) <= r2) return true;
  for (int i = 0; i < 3; ++i)
    if (CGAL::squared_distance(s, Epeck::Segment_3(tri[i], tri[(i + 1) % 3])) <= r2) return true;
  return false;
}

// Exact: whether the segment s (not degenerate) comes within sqrt(r2) of the segment side
// (perhaps a point).
bool near_segment(const Epeck::Segment_3& s, const Epeck::Segment_3& side, const FT& r2) {
  if (side.is_degenerate()) return CGAL::squared_distance(side.source(), s) <= r2;
  return CGAL::is_zero(r2) ? CGAL::do_intersect(s, side) : CGAL::squared_distance(s, side) <= r2;
}

// Exact: the segment s comes within sqrt(r2) of (r2 = 0: meets) the closed set the
// segment (p0, p1) sweeps along w, for s and p0 p1 in any position (the swept set may be
// a parallelogram, a segment or a point).
bool near_swept(const Epeck::Segment_3& s, const P& p0, const P& p1, const V& w, const FT& r2) {
  const P corners[4] = {p0, p1, p1 + w, p0 + w};
  if (!CGAL::collinear(corners[0], corners[1], corners[2]) || !CGAL::collinear(corners[0], corners[2], corners[3])) {
    const auto near = [&](const P& x, const P& y, const P& z) {
      const Epeck::Triangle_3 tri(x, y, z);
      return !tri.is_degenerate() && near_triangle(s, tri, r2);
    };
    if (near(corners[0], corners[1], corners[2]) || near(corners[0], corners[2], corners[3])) return true;
  }
  // Degenerate pieces: the swept set's boundary segments cover what is left.
  for (int i = 0; i < 4; ++i)
    if (near_segment(s, Epeck::Segment_3(corners[i], corners[(i + 1) % 4]), r2)) return true;
  return false;
}

}  // namespace

std::vector<ContactNormal> contact_normals_by(const Mesh& a, const Vec3& va, const Mesh& b, const Vec3& vb, double t,
                                              double reach) {
  std::vector<ContactNormal> out;
  if (!(t >= 0)) return out;
  const FT r2 = ft(reach) * ft(reach);
  const FT limit = CGAL::min(ft(t), FT(1));
  const V d = exact(va) - exact(vb);
  const V swept = limit * d;
  // A vertex of `from` along p -> p + w against each face of `to`.
  const auto vertices_on_faces = [&](const Mesh& from, const Mesh& to, const V& w) {
    for (const Vec3& v : from.vertices) {
      const P p = exact(v);
      const Epeck::Segment_3 path(p, p + w);
      for (std::size_t k = 0; k < to.size(); ++k) {
        const Epeck::Triangle_3 tri = exact(to.triangle(k));
        if (!tri.is_degenerate() && near_triangle(path, tri, r2))
          out.push_back(normal_of(tri[1] - tri[0], tri[2] - tri[0]));
      }
    }
  };
  vertices_on_faces(a, b, swept);
  vertices_on_faces(b, a, -swept);
  const auto eb = b.edges();
  for (const auto& e : a.edges()) {
    const P p0 = exact(a.vertices[std::size_t(e[0])]), p1 = exact(a.vertices[std::size_t(e[1])]);
    if (p0 == p1) continue;  // a point: its faces' vertices above cover it
    for (const auto& f : eb) {
      const Epeck::Segment_3 edge(exact(b.vertices[std::size_t(f[0])]), exact(b.vertices[std::size_t(f[1])]));
      if (edge.is_degenerate()) continue;
      if (near_swept(edge, p0, p1, swept, r2)) out.push_back(normal_of(p1 - p0, edge.to_vector()));
    }
  }
  return out;
}

bool touch_during_frame_fast(const Mesh& a, const Vec3& va, const Mesh& b, const Vec3& vb) {
  using K = Epick;
  const Vec3 d = va - vb;
  const auto hits = [](const K::Segment_3& s, const K::Triangle_3& t) {
    if (t.is_degenerate()) return false;
    return s.is_degenerate() ? t.has_on(s.source()) : CGAL::do_intersect(s, t);
  };
  for (const Vec3& p : a.vertices)
    for (std::size_t k = 0; k < b.size(); ++k)
      if (hits({fast(p), fast(p + d)}, {fast(b.triangle(k).v0), fast(b.triangle(k).v1), fast(b.triangle(k).v2)}))
        return true;
  for (const Vec3& q : b.vertices)
    for (std::size_t k = 0; k < a.size(); ++k)
      if (hits({fast(q), fast(q - d)}, {fast(a.triangle(k).v0), fast(a.triangle(k).v1), fast(a.triangle(k).v2)}))
        return true;
  const auto eb = b.edges();
  for (const auto& e : a.edges()) {
    const Vec3& p0 = a.vertices[std::size_t(e[0])];
    const Vec3& p1 = a.vertices[std::size_t(e[1])];
    const K::Triangle_3 first(fast(p0), fast(p1), fast(p1 + d)), second(fast(p0), fast(p1 + d), fast(p0 + d));
    for (const auto& f : eb) {
      const K::Segment_3 edge(fast(b.vertices[std::size_t(f[0])]), fast(b.vertices[std::size_t(f[1])]));
      if (hits(edge, first) || hits(edge, second)) return true;
    }
  }
  return false;
}

bool within_translated(const Vec3& p, const Mesh& mesh, const Vec3& offset, double tolerance) {
  const P x = exact(p);
  const V o = exact(offset) - CGAL::ORIGIN;
  const FT tol2 = ft(tolerance) * ft(tolerance);
  for (std::size_t k = 0; k < mesh.size(); ++k) {
    const Epeck::Triangle_3 tri(exact(mesh.triangle(k).v0) + o, exact(mesh.triangle(k).v1) + o,
                                exact(mesh.triangle(k).v2) + o);
    if (tri.is_degenerate()) {
      for (int i = 0; i < 3; ++i)
        if (CGAL::squared_distance(x, Epeck::Segment_3(tri[i], tri[(i + 1) % 3])) <= tol2) return true;
      continue;
    }
    if (CGAL::squared_distance(x, tri) <= tol2) return true;
  }
  return false;
}

}  // namespace oracle
