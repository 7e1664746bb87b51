// Lab 01's verdicts: each judge compares one answer with the exact oracle, following
// the tolerances and degenerate rules of labs/01_frustum_split/frustum_split.h.
// The tests and the viewer both use them, so a red mark in the viewer and a failing
// case in `./labkit check` always agree.
#pragma once

#include "01_frustum_split/wire.h"

#include "01_frustum_split/generators.h"
#include "01_frustum_split/inputs.h"
#include "common/harness/check.h"

#include <array>
#include <vector>

namespace labkit::lab01 {

std::string describe(Side s);

// The kit's camera type, for its generators and corners.
CameraParameters parameters_of(const Camera& camera);

namespace judge {

using check::Outcome;

using check::Rules;  // random cases, or a robustness step's exact input

// got[i] is the signed distance of vertex i to the plane.
Outcome signed_distance(const TrianglePlane& in, const std::array<double, 3>& got);
Outcome classify(const TrianglePlane& in, const std::array<Side, 3>& got, Rules rules = Rules::random);
Outcome split_triangle(const TrianglePlane& in, const std::vector<Triangle>& got, Rules rules = Rules::random);
Outcome frustum_from_camera(const Camera& in, const Frustum& got);
Outcome frustum_from_matrix(const Mat4& in, const Frustum& got);
Outcome clip_triangle(const TriangleFrustum& in, const std::vector<Triangle>& got, Rules rules = Rules::random);
Outcome clip_mesh(const MeshFrustum& in, const ClippedMesh& got, Rules rules = Rules::random);

}  // namespace judge
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
