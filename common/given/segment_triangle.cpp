#include "common/given/segment_triangle.h"
#include "common/given/served.h"

#include <cmath>

namespace labkit::given {

namespace {
thread_local std::uint64_t calls = 0;
}  // namespace

std::uint64_t segment_triangle_calls() { return calls; }

// Work in "segment space": translate so a is the origin, then shear so the segment's
// direction becomes the z axis. The question becomes 2D: does the origin lie inside the
// sheared triangle's projection? Its three edge functions U, V, W (2D cross products of
// vertex pairs) answer it, and they are the barycentric weights up to a common factor.
SegmentHit segment_triangle(const Segment& segment, const Triangle& triangle) {
  if (served()) count("segment_triangle");  // counted by the judge (served.h)
  ++calls;
  const Vec3 d = segment.b - segment.a;
  int kz = 0;
  d.cwiseAbs().maxCoeff(&kz);
  if (d[kz] == 0) return {};  // zero length: nothing to cross
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (d[kz] < 0) std::swap(kx, ky);  // keeps the triangle's winding
  const double sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0 / d[kz];

  const Vec3 a = triangle.v0 - segment.a, b = triangle.v1 - segment.a, c = triangle.v2 - segment.a;
  const double ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
  const double bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
  const double cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];

  // Each edge function uses only its edge's two vertices: the watertight property.
  long double u = (long double)cx * by - (long double)cy * bx;
  long double v = (long double)ax * cy - (long double)ay * cx;
  long double w = (long double)bx * ay - (long double)by * ax;
  if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return {};  // outside an edge
  const long double det = u + v + w;
  if (det == 0) return {};  // in the triangle's plane, or a zero-area triangle
  // A zero-area triangle can also leave det a hair off zero after the shear's rounding:
  // ask the triangle itself (exact for collinear vertices on a lattice). Only candidate
  // hits get here, so the cost is small.
  if ((triangle.v1 - triangle.v0).cross(triangle.v2 - triangle.v0) == Vec3::Zero()) return {};

  // The crossing's depth along the segment, as a weighted sum, still scaled by det.
  const long double depth = u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz]);
  const long double t = depth / det;
  if (t < 0 || t > 1) return {};  // the line crosses the triangle beyond an end

  SegmentHit h;
  h.hit = true;
  h.t = double(t);
  h.barycentric = Vec3(double(u / det), double(v / det), double(w / det));
  h.point = segment.point(h.t);
  return h;
}

}  // namespace labkit::given
