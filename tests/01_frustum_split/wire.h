// Lab 01 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer.
#pragma once

#include "frustum_split.h"

#include "common/fields.h"
#include "common/protocol/calls.h"

#include <array>
#include <vector>

namespace labkit::lab01 {

LABKIT_FIELDS(Camera, eye, forward, up, fov_y, aspect, near, far)
LABKIT_FIELDS(ColoredMesh, mesh, colors)
LABKIT_FIELDS(ClippedMesh, mesh, colors, source)

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

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab01, LABKIT_LAB01_CALLS)
