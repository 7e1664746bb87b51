// Lab 05's queries: the name of each question its tests ask (a replay token's prefix,
// `./labkit replay point_segment:...`) and the input it takes. The tests, the viewer's scene and
// its presets read this table (common/harness/query.h); a query is added or renamed here.
#pragma once

#include "common/harness/query.h"
#include "common/inputs/05_sphere_sweeps.h"

#define LABKIT_LAB05_QUERIES(X) \
  X(point_segment, "point_segment", PointSegmentPair)                                  \
  X(segment_segment, "segment_segment", SegmentPair)                                   \
  X(point_rectangle, "point_rectangle", PointRectanglePair)                            \
  X(segment_rectangle, "segment_rectangle", SegmentRectanglePair)                      \
  X(rectangle_rectangle, "rectangle_rectangle", RectanglePair)                         \
  X(test_sphere_sphere, "test_sphere_sphere", SpherePair)                              \
  X(test_sphere_capsule, "test_sphere_capsule", SphereCapsule)                         \
  X(test_sphere_lozenge, "test_sphere_lozenge", SphereLozenge)                         \
  X(test_capsule_capsule, "test_capsule_capsule", CapsulePair)                         \
  X(test_capsule_lozenge, "test_capsule_lozenge", CapsuleLozenge)                      \
  X(test_lozenge_lozenge, "test_lozenge_lozenge", LozengePair)                         \
  X(sweep_sphere_plane, "sweep_sphere_plane", SpherePlaneMotion)                       \
  X(sweep_sphere_sphere, "sweep_sphere_sphere", SphereSphereMotion)                    \
  X(sweep_sphere_sphere_soon, "sweep_sphere_sphere.soon", SphereSphereMotion)          \
  X(sweep_sphere_sphere_grazing, "sweep_sphere_sphere.grazing", SphereSphereMotion)    \
  X(sweep_sphere_capsule, "sweep_sphere_capsule", SphereCapsuleMotion)                 \
  X(sweep_box_plane, "sweep_box_plane", BoxPlaneMotion)                                \
  X(robust_segment_segment, "robust.segment_segment", SegmentPair)                     \
  X(robust_segment_rectangle, "robust.segment_rectangle", SegmentRectanglePair)        \
  X(robust_test_sphere_capsule, "robust.test_sphere_capsule", SphereCapsule)           \
  X(robust_test_capsule_capsule, "robust.test_capsule_capsule", CapsulePair)           \
  X(robust_test_capsule_lozenge, "robust.test_capsule_lozenge", CapsuleLozenge)        \
  X(robust_test_lozenge_lozenge, "robust.test_lozenge_lozenge", LozengePair)           \
  X(robust_sweep_sphere_plane, "robust.sweep_sphere_plane", SpherePlaneMotion)         \
  X(robust_sweep_sphere_sphere, "robust.sweep_sphere_sphere", SphereSphereMotion)      \
  X(robust_sweep_sphere_capsule, "robust.sweep_sphere_capsule", SphereCapsuleMotion)   \
  X(robust_sweep_box_plane, "robust.sweep_box_plane", BoxPlaneMotion)                 

namespace labkit::lab05::query {
LABKIT_LAB05_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB05_QUERIES)
}  // namespace labkit::lab05::query
