#include "common/generators/needles.h"

#include <algorithm>
#include <cmath>

namespace labkit::gen {

namespace {

// 2^-k, k in [kmin, kmax]: an offset relative to a size. tol is 1e-9 S, about 2^-30 S,
// so k <= 24 keeps an offset of a size near S at 60 tol or more: outside the band.
double relative(int kmin, int kmax) { return std::ldexp(1.0, -*rc::gen::inRange(kmin, kmax + 1)); }

double sign() { return *rc::gen::element(-1.0, 1.0); }

Vec3 nonzero(double s) {
  return *rc::gen::suchThat(point(s), [](const Vec3& v) { return v != Vec3::Zero(); });
}

double size_of(const Triangle& t) {
  return std::max({(t.v1 - t.v0).norm(), (t.v2 - t.v1).norm(), (t.v0 - t.v2).norm()});
}

// The point with weights (1 - alpha - beta, alpha, beta).
Vec3 at(const Triangle& t, double alpha, double beta) { return t.v0 + alpha * (t.v1 - t.v0) + beta * (t.v2 - t.v0); }

// Weights well inside: each at least 2^-10.
Vec3 inside(const Triangle& t) {
  const int i = *rc::gen::inRange(1, 1023), j = *rc::gen::inRange(1, 1024 - i);
  return at(t, std::ldexp(i, -10), std::ldexp(j, -10));
}

// A point of edge i (its start vertex when f = 0), then moved in the plane across that
// edge: inward by a fraction of the triangle's height over it, or outward by a fraction
// of its size.
Vec3 near_edge_point(const Triangle& t) {
  const int i = *rc::gen::inRange(0, 3);
  const Vec3 from = t[i], edge = t[(i + 1) % 3] - from;
  const double f = *rc::gen::element(0.0, std::ldexp(*rc::gen::inRange(1, 1024), -10));
  const Vec3 n = t.normal();
  const Vec3 across = n.cross(edge).normalized();  // into the triangle
  const double height = n.norm() / edge.norm();
  const double shift = *rc::gen::element(1, 2) == 1 ? relative(1, 12) * height : -relative(6, 24) * size_of(t);
  return from + f * edge + shift * across;
}

// A segment through x, crossing the plane steeply or not, long or short.
Segment through(const Vec3& x, double s) {
  const Vec3 d = nonzero(s) * relative(0, 16);
  const double k = *rc::gen::inRange(1, 17) / 8.0;
  return *rc::gen::element(Segment{x + d, x - k * d}, Segment{x - k * d, x + d});
}

// The unit normal, and a point of the plane with in-plane weights anywhere.
Vec3 unit_normal(const Triangle& t) { return t.normal().normalized(); }
Vec3 in_plane(const Triangle& t) {
  return at(t, std::ldexp(*rc::gen::inRange(-2048, 3072), -10), std::ldexp(*rc::gen::inRange(-2048, 3072), -10));
}

Triangle wide_triangle(double s) { return *any_triangle(s); }

rc::Gen<SegmentTrianglePair> family(int which) {
  return rc::gen::exec([which] {
    const double s = *wide_scale();
    const Triangle t = wide_triangle(s);
    const double size = size_of(t);
    const Vec3 n = unit_normal(t);
    switch (which) {
      case 0:  // anything
        return SegmentTrianglePair{{*point(s), *point(s)}, t};
      case 1:  // through the inside
        return SegmentTrianglePair{through(inside(t), s), t};
      case 2:  // through a point a little inside or outside an edge or a vertex
        return SegmentTrianglePair{through(near_edge_point(t), s), t};
      case 3: {  // a little off the plane: nearly parallel, or crossing it at a shallow angle
        const Vec3 a = in_plane(t), b = in_plane(t);
        const double lift = relative(6, 24) * size;
        const double other = *rc::gen::element(1.0, -1.0, 0.5, 2.0);
        return SegmentTrianglePair{{a + sign() * lift * n, b + other * lift * n}, t};
      }
      case 4: {  // an end a little above or below the triangle (or its plane beside it)
        const Vec3 x = *rc::gen::oneOf(rc::gen::just(inside(t)), rc::gen::just(near_edge_point(t)));
        const Vec3 end = x + sign() * relative(6, 24) * size * n;
        const Vec3 other = end + nonzero(s);
        return *rc::gen::element(SegmentTrianglePair{{end, other}, t}, SegmentTrianglePair{{other, end}, t});
      }
      case 5: {  // zero length, off the triangle
        const Vec3 x = *rc::gen::oneOf(rc::gen::just(inside(t)), rc::gen::just(near_edge_point(t)));
        const Vec3 p = x + sign() * relative(6, 24) * size * n * double(*rc::gen::element(0, 1, 1));
        return SegmentTrianglePair{{p, p}, t};
      }
      case 6: {  // in the plane, nearly along an edge's line (the rest: anywhere in it)
        const int i = *rc::gen::inRange(0, 3);
        const Vec3 from = t[i], edge = t[(i + 1) % 3] - from;
        const Vec3 across = t.normal().cross(edge).normalized() * size;
        const auto on_line = [&] {
          return from + std::ldexp(*rc::gen::inRange(-1024, 2048), -10) * edge + sign() * relative(20, 50) * across;
        };
        const Vec3 a = on_line(), b = *rc::gen::element(0, 1) ? on_line() : in_plane(t);
        return SegmentTrianglePair{{a, b}, t};
      }
      default: {  // zero area: never hit
        const Triangle flat = *degenerate_triangle(s);
        return SegmentTrianglePair{{*point(s), *point(s)}, flat};
      }
    }
  });
}

// The size far_away() moves a case by multiples of: the whole case's.
double case_size(const SegmentTrianglePair& c) {
  return scale_of({c.triangle.v0, c.triangle.v1, c.triangle.v2, c.segment.a, c.segment.b});
}

// A small mesh, some of whose faces are double-sided: the same vertices wound both ways.
rc::Gen<Mesh> mesh_with_twins(double s) {
  return rc::gen::exec([s] {
    Mesh m =
        *rc::gen::weightedOneOf<Mesh>({{3, mesh(s)}, {1, rc::gen::exec([s] {
                                                        Mesh soup;
                                                        const int k = *rc::gen::inRange(1, 7);
                                                        for (int i = 0; i < k; ++i) {
                                                          const Triangle t = *any_triangle(s);
                                                          const int base = int(soup.vertices.size());
                                                          soup.vertices.insert(soup.vertices.end(), {t.v0, t.v1, t.v2});
                                                          soup.triangles.push_back({base, base + 1, base + 2});
                                                        }
                                                        return soup;
                                                      })}});
    if (*rc::gen::inRange(0, 3) == 0 && m.size() > 0) {
      const std::size_t count = m.triangles.size();
      for (std::size_t i = 0; i < count; ++i)
        if (*rc::gen::element(0, 1)) m.triangles.push_back({m.triangles[i][0], m.triangles[i][2], m.triangles[i][1]});
    }
    return m;
  });
}

}  // namespace

rc::Gen<double> wide_scale() {
  return rc::gen::weightedElement<double>({{12, 1.0},
                                           {2, std::ldexp(1.0, -10)},
                                           {2, std::ldexp(1.0, 10)},
                                           {1, std::ldexp(1.0, -20)},
                                           {1, std::ldexp(1.0, 20)},
                                           {1, std::ldexp(1.0, -166)},
                                           {1, std::ldexp(1.0, 166)}});
}

rc::Gen<Triangle> needle(double s, int thinnest) {
  return rc::gen::suchThat(rc::gen::exec([s, thinnest] {
                             const Vec3 p = *point(s), u = nonzero(s);
                             // A direction across the long edge u, with any other component removed.
                             Vec3 w = *rc::gen::suchThat(point(1.0), [&u](const Vec3& v) {
                               return v.cross(u).squaredNorm() > 1e-6 * v.squaredNorm() * u.squaredNorm();
                             });
                             w -= (w.dot(u) / u.dot(u)) * u;
                             const double aspect = std::ldexp(1.0, *rc::gen::inRange(thinnest, 28));
                             w *= u.norm() / (aspect * w.norm());
                             // Where the third vertex sits along the long edge: at an end (a spike), inside it
                             // or beyond it (slivers).
                             const double f = *rc::gen::element(0.0, 1.0, std::ldexp(*rc::gen::inRange(1, 1024), -10),
                                                                1.0 + std::ldexp(*rc::gen::inRange(1, 512), -10));
                             Vec3 v[3] = {p, p + u, p + f * u + w};
                             const int first = *rc::gen::inRange(0, 3);
                             std::rotate(v, v + first, v + 3);
                             if (*rc::gen::element(0, 1)) std::swap(v[1], v[2]);
                             return Triangle{v[0], v[1], v[2]};
                           }),
                           [](const Triangle& t) { return t.normal() != Vec3::Zero(); });
}

rc::Gen<Triangle> any_triangle(double s) {
  return rc::gen::weightedOneOf<Triangle>({{3, triangle(s)}, {1, needle(s)}});
}

// A needle crossed by a short, steep segment near its long edge: 64 to 2048 tol inside
// or outside it (nearer is within the checker's band of doubt), or anywhere across its
// height. Where along the segment the crossing is, and weights that rebuild it within
// tol, need the needle's plane to full precision: rounded in plain doubles its normal is
// off by the aspect ratio times 1e-16, and the crossing a few tol off the plane.
rc::Gen<SegmentTrianglePair> needle_crossed_steeply() {
  return rc::gen::exec([] {
    const double s = *wide_scale();
    // The thinnest: aspect ratios 2^24 and up. A crossing inside the very thinnest is
    // within the checker's band of doubt (either yes/no passes), but its t and weights
    // are still checked.
    const Triangle t = *needle(s, 24);
    int i = 0;  // the long edge runs from t[i] to t[i + 1]
    for (int k = 1; k < 3; ++k)
      if ((t[(k + 1) % 3] - t[k]).squaredNorm() > (t[(i + 1) % 3] - t[i]).squaredNorm()) i = k;
    const Vec3 from = t[i], edge = t[(i + 1) % 3] - from, n = t.normal();
    const Vec3 across = n.cross(edge).normalized();  // into the triangle
    const double height = n.norm() / edge.norm();
    const double tol = 1e-9 * scale_of({t.v0, t.v1, t.v2});
    const double shift = *rc::gen::element(0, 1) ? sign() * std::ldexp(1.0, *rc::gen::inRange(6, 12)) * tol
                                                 : std::ldexp(*rc::gen::inRange(1, 1024), -10) * height;
    const Vec3 x = from + std::ldexp(*rc::gen::inRange(16, 1009), -10) * edge + shift * across;
    // Steep: along the normal, tilted by at most a quarter; as short as the needle is
    // thin (4 to 4096 tol), or longer, up to S.
    const Vec3 tilt = *point(1.0) / 64.0;
    const int length = *rc::gen::element(0, 1) ? *rc::gen::inRange(2, 13) : *rc::gen::inRange(13, 31);
    const Vec3 d =
        (n.normalized() + tilt - tilt.dot(n) / n.squaredNorm() * n).normalized() * (std::ldexp(1.0, length) * tol);
    const double before = std::ldexp(*rc::gen::inRange(1, 16), -4);  // the share of d before x
    // Centred on the long edge, so that tol (1e-9 of the largest coordinate) is as small
    // beside the needle as it gets: there its plane's rounding matters most.
    SegmentTrianglePair c{{x + before * d, x - (1 - before) * d}, t};
    translate(c, -(from + 0.5 * edge));
    return c;
  });
}

rc::Gen<SegmentTrianglePair> decisive_segment_triangle() {
  const rc::Gen<SegmentTrianglePair> families = rc::gen::weightedOneOf<SegmentTrianglePair>({
      {3, family(0)},
      {4, family(1)},
      {4, family(2)},
      {3, family(3)},
      {2, family(4)},
      {1, family(5)},
      {1, family(6)},
      {1, family(7)},
  });
  return rc::gen::weightedOneOf<SegmentTrianglePair>({{7, families}, {1, far_away(families, translate, case_size)}});
}

rc::Gen<SegmentMeshPair> decisive_segment_mesh() {
  return rc::gen::exec([] {
    const double s = *wide_scale();
    const Mesh m = *mesh_with_twins(s);
    // Aim at some triangle three times in four (hits are rarer than misses otherwise):
    // through a point well inside it, a little outside one of its edges, or crossing its
    // plane inside it at an angle of 2^-17 to 2^-26, so nearly parallel that a hit's
    // weights must be measured on its point (the ends stay clearly off the plane).
    Segment seg{*point(s), *point(s)};
    const int aim = *rc::gen::inRange(0, 4);
    if (aim != 0 && m.size() > 0) {
      const Triangle t = m.triangle(std::size_t(*rc::gen::inRange(0, int(m.size()))));
      if (t.normal() != Vec3::Zero() && aim == 3) {
        const Vec3 x = inside(t), along = t[*rc::gen::inRange(0, 3)] - x;
        const Vec3 d = along + sign() * relative(17, 26) * along.norm() * unit_normal(t);
        const double k = *rc::gen::inRange(1, 17) / 8.0;
        seg = *rc::gen::element(Segment{x + d, x - k * d}, Segment{x - k * d, x + d});
      } else if (t.normal() != Vec3::Zero()) {
        seg = through(aim == 1 ? near_edge_point(t) : inside(t), s);
      }
    }
    return SegmentMeshPair{seg, m};
  });
}

}  // namespace labkit::gen
