// Lab 01 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer.
#pragma once

#include "frustum_split.h"

#include <array>
#include <vector>

namespace labkit::lab01 {

template <class V> void fields(Camera& c, V&& v) {
  v("eye", c.eye);
  v("forward", c.forward);
  v("up", c.up);
  v("fov_y", c.fov_y);
  v("aspect", c.aspect);
  v("near", c.near);
  v("far", c.far);
}
template <class V> void fields(ColoredMesh& m, V&& v) {
  v("mesh", m.mesh);
  v("colors", m.colors);
}
template <class V> void fields(ClippedMesh& m, V&& v) {
  v("mesh", m.mesh);
  v("colors", m.colors);
  v("source", m.source);
}

using Sides = std::array<Side, 3>;
using Triangles = std::vector<Triangle>;

}  // namespace labkit::lab01

// clang-format off
#define LABKIT_LAB01_CALLS(CALL, METHOD)                                           \
  CALL(double, signed_distance, (const Plane&, const Vec3&))                       \
  CALL(Sides, classify, (const Plane&, const Triangle&))                           \
  CALL(Triangles, split_triangle, (const Triangle&, const Plane&))                 \
  CALL(Frustum, frustum_from_camera, (const Camera&))                              \
  CALL(Frustum, frustum_from_matrix, (const Mat4&))                                \
  CALL(Triangles, clip_triangle, (const Triangle&, const Frustum&))                \
  CALL(ClippedMesh, clip_mesh, (const ColoredMesh&, const Frustum&))
// clang-format on
