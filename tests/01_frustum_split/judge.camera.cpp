// Lab 01's cameras: the frustum a camera's parameters stand for and its corners, in long
// double, and its view and view-projection matrices (judge.h). The generators, the judge
// and the viewer's scene share them.
#include "01_frustum_split/judge.h"

#include <array>
#include <cmath>

namespace labkit {

namespace {

using Long3 = Eigen::Matrix<long double, 3, 1>;

Long3 widen(const Vec3& v) { return v.cast<long double>(); }
Vec3 narrow(const Long3& v) { return v.cast<double>(); }

struct LongFrustum {
  std::array<Long3, 8> corners;
  Long3 eye, forward;
};

LongFrustum long_frustum(const CameraParameters& c) {
  LongFrustum out;
  const Long3 f = widen(c.forward).normalized();
  const Long3 r = f.cross(widen(c.up)).normalized();
  const Long3 u = r.cross(f);
  const long double ty = std::tan(static_cast<long double>(c.fov_y) / 2);
  const long double tx = static_cast<long double>(c.aspect) * ty;
  out.eye = widen(c.eye);
  out.forward = f;
  for (int i = 0; i < 8; ++i) {
    const long double d = (i & 4) ? c.far : c.near;
    const long double sx = (i & 1) ? 1 : -1, sy = (i & 2) ? 1 : -1;
    out.corners[std::size_t(i)] = out.eye + d * (f + sx * tx * r + sy * ty * u);
  }
  return out;
}

}  // namespace

std::array<Vec3, 8> frustum_corners(const CameraParameters& camera) {
  const LongFrustum lf = long_frustum(camera);
  std::array<Vec3, 8> out;
  for (int i = 0; i < 8; ++i) out[std::size_t(i)] = narrow(lf.corners[std::size_t(i)]);
  return out;
}

Frustum frustum_of(const CameraParameters& camera) {
  const LongFrustum lf = long_frustum(camera);
  const auto& k = lf.corners;
  const Long3 center = lf.eye + lf.forward * ((static_cast<long double>(camera.near) + camera.far) / 2);
  // Three points of each plane: the eye and two far corners for the sides.
  const std::array<std::array<Long3, 3>, 6> points = {{
      {lf.eye, k[4], k[6]},  // left
      {lf.eye, k[5], k[7]},  // right
      {lf.eye, k[4], k[5]},  // bottom
      {lf.eye, k[6], k[7]},  // top
      {k[0], k[1], k[2]},    // near
      {k[4], k[5], k[6]},    // far
  }};
  Frustum f;
  for (std::size_t i = 0; i < 6; ++i) {
    const auto& p = points[i];
    Long3 n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    if (n.dot(center - p[0]) < 0) n = -n;
    f.planes[i] = Plane{narrow(n), static_cast<double>(-n.dot(p[0]))};
  }
  return f;
}

Mat4 view_matrix(const CameraParameters& c) {
  const Vec3 f = c.forward.normalized();
  const Vec3 s = f.cross(c.up).normalized();
  const Vec3 u = s.cross(f);
  Mat4 view = Mat4::Identity();
  view.row(0) << s.transpose(), -s.dot(c.eye);
  view.row(1) << u.transpose(), -u.dot(c.eye);
  view.row(2) << -f.transpose(), f.dot(c.eye);
  return view;
}

Mat4 view_projection(const CameraParameters& c) {
  const double cot = 1.0 / std::tan(c.fov_y / 2);
  Mat4 projection = Mat4::Zero();
  projection(0, 0) = cot / c.aspect;
  projection(1, 1) = cot;
  projection(2, 2) = (c.far + c.near) / (c.near - c.far);
  projection(2, 3) = 2 * c.far * c.near / (c.near - c.far);
  projection(3, 2) = -1;
  return projection * view_matrix(c);
}

}  // namespace labkit
