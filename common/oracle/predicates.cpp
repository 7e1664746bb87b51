#include "common/oracle/predicates.h"
#include "common/oracle/kernel.h"

namespace oracle {

using namespace kernel;

namespace {

FT value(const Plane& plane, const Vec3& x) {
  return ft(plane.normal.x()) * ft(x.x()) + ft(plane.normal.y()) * ft(x.y()) + ft(plane.normal.z()) * ft(x.z()) +
         ft(plane.offset);
}

FT squared(double x) { return ft(x) * ft(x); }

// The closed set of a zero-area triangle is its longest edge.
Epeck::Segment_3 longest_edge(const Epeck::Triangle_3& t) {
  Epeck::Segment_3 best(t[0], t[1]);
  for (int i = 1; i < 3; ++i) {
    Epeck::Segment_3 e(t[i], t[(i + 1) % 3]);
    if (e.squared_length() > best.squared_length()) best = e;
  }
  return best;
}

FT squared_distance_to(const Epeck::Point_3& p, const Epeck::Segment_3& s) {
  if (s.is_degenerate()) return CGAL::squared_distance(p, s.source());
  return CGAL::squared_distance(p, s);
}

FT squared_distance_to(const Epeck::Point_3& p, const Epeck::Triangle_3& t) {
  if (t.is_degenerate()) return squared_distance_to(p, longest_edge(t));
  return CGAL::squared_distance(p, t);
}

}  // namespace

int side(const Plane& plane, const Vec3& x) { return sign_of(CGAL::sign(value(plane, x))); }

int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return sign_of(CGAL::orientation(fast(a), fast(b), fast(c), fast(d)));
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) { return CGAL::collinear(fast(a), fast(b), fast(c)); }

bool is_degenerate(const Triangle& t) { return collinear(t.v0, t.v1, t.v2); }

bool within(const Vec3& p, const Vec3& q, double tolerance) {
  return CGAL::squared_distance(exact(p), exact(q)) <= squared(tolerance);
}

bool within(const Vec3& p, const Segment& s, double tolerance) {
  return squared_distance_to(exact(p), exact(s)) <= squared(tolerance);
}

bool within(const Vec3& p, const Triangle& t, double tolerance) {
  return squared_distance_to(exact(p), exact(t)) <= squared(tolerance);
}

bool within(const Vec3& p, const Plane& plane, double tolerance) {
  const FT v = value(plane, p);
  const FT n2 = squared(plane.normal.x()) + squared(plane.normal.y()) + squared(plane.normal.z());
  return v * v <= squared(tolerance) * n2;
}

double distance(const Vec3& p, const Triangle& t) {
  return std::sqrt(rounded(squared_distance_to(exact(p), exact(t))));
}

double distance(const Vec3& p, const Segment& s) { return std::sqrt(rounded(squared_distance_to(exact(p), exact(s)))); }

}  // namespace oracle
