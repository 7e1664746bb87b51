// Lab 01's checker beyond its queries (queries.h declares the queries, their generators
// and their verdicts): what the lab's generators, judges, tests and viewer scene share.
#pragma once

#include "01_frustum_split/queries.h"
#include "common/harness/check.h"
#include "common/harness/codec.h"

#include <rapidcheck.h>
#include <array>
#include <vector>

namespace labkit {

// The eight corners of the camera's frustum, computed in long double and rounded:
// corner i is eye + d (f +- tx r +- ty u), d = near or far, with f, r, u the unit
// forward, right and up, ty = tan(fov_y / 2), tx = aspect ty. Bit 0 of i: right (else
// left); bit 1: top (else bottom); bit 2: far (else near).
std::array<Vec3, 8> frustum_corners(const CameraParameters& camera);

// Its six planes (left, right, bottom, top, near, far), each through three of those
// corners (the side planes through the eye), unit normals pointing in; long double,
// rounded once.
Frustum frustum_of(const CameraParameters& camera);

// gluLookAt(eye, eye + forward, up), in double: OpenGL's view matrix for the camera.
Mat4 view_matrix(const CameraParameters& camera);

// gluPerspective(fov_y, aspect, near, far) * gluLookAt(eye, eye + forward, up), in
// double: OpenGL's view-projection matrix for the camera.
Mat4 view_projection(const CameraParameters& camera);

}  // namespace labkit

namespace labkit::lab01 {

std::string describe(Side s);

// The kit's camera type, for its generators and corners.
CameraParameters parameters_of(const Camera& camera);

}  // namespace labkit::lab01

namespace labkit {

// The header's domain, value by value: coordinates and normal components 0 or of
// magnitude 2^-130 to 2^130; a plane's offset at most 2^130 (a smaller one, down to 0, is
// a plane through or near the origin). check::in_domain finds these by their argument.
namespace lab01::domain {
inline bool value(double x) { return x == 0 || (std::abs(x) >= 0x1p-130 && std::abs(x) <= 0x1p130); }
inline bool vector(const Vec3& v) { return value(v.x()) && value(v.y()) && value(v.z()); }
inline bool plane(const Plane& p) {
  return vector(p.normal) && std::isfinite(p.offset) && std::abs(p.offset) <= 0x1p130;
}
inline bool planes(const Frustum& f) {
  for (const Plane& p : f.planes)
    if (!plane(p)) return false;
  return true;
}
}  // namespace lab01::domain

inline bool header_in_domain(const TrianglePlane& in) {
  return lab01::domain::vector(in.triangle.v0) && lab01::domain::vector(in.triangle.v1) &&
         lab01::domain::vector(in.triangle.v2) && lab01::domain::plane(in.plane);
}
inline bool header_in_domain(const TriangleFrustum& in) {
  return lab01::domain::vector(in.triangle.v0) && lab01::domain::vector(in.triangle.v1) &&
         lab01::domain::vector(in.triangle.v2) && lab01::domain::planes(in.frustum);
}
inline bool header_in_domain(const MeshFrustum& in) {
  for (const Vec3& v : in.mesh.vertices)
    if (!lab01::domain::vector(v)) return false;
  return lab01::domain::planes(in.frustum);
}

}  // namespace labkit
