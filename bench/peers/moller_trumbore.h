// The plain Moller-Trumbore test (Moller and Trumbore, "Fast, minimum storage
// ray-triangle intersection", 1997) for a segment a + t (b - a), t in [0, 1]: the
// textbook version, closed bounds, no epsilon. A peer to measure against.
#pragma once

#include "common/geometry.h"

namespace bench::peers {

struct MollerTrumboreHit {
  bool hit = false;
  double t = 0, u = 0, v = 0;
};

// The find query in full, as the kit's contract asks: t, the point, the barycentric
// weights and the triangle's unit normal.
struct MollerTrumboreFind {
  bool hit = false;
  double t = 0;
  labkit::Vec3 point, barycentric, normal;
};

inline MollerTrumboreHit moller_trumbore(const labkit::Segment& s, const labkit::Triangle& tri) {
  using labkit::Vec3;
  const Vec3 d = s.b - s.a;
  const Vec3 e1 = tri.v1 - tri.v0, e2 = tri.v2 - tri.v0;
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0) return {};
  const double inv = 1.0 / det;
  const Vec3 o = s.a - tri.v0;
  const double u = o.dot(p) * inv;
  if (u < 0 || u > 1) return {};
  const Vec3 q = o.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < 0 || u + v > 1) return {};
  const double t = e2.dot(q) * inv;
  if (t < 0 || t > 1) return {};
  return {true, t, u, v};
}

inline MollerTrumboreFind moller_trumbore_find(const labkit::Segment& s, const labkit::Triangle& tri) {
  const MollerTrumboreHit h = moller_trumbore(s, tri);
  if (!h.hit) return {};
  return {true, h.t, s.point(h.t), {1 - h.u - h.v, h.u, h.v}, tri.normal().normalized()};
}

}  // namespace bench::peers
