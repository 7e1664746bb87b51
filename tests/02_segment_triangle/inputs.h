// Lab 02's inputs beyond the shared pairs (common/inputs/inputs.h): each query's
// arguments as one struct, whose fields() let reports print it and replay tokens carry it
// (the answers' fields are in tests/02_segment_triangle/wire.h).
#pragma once

#include "segment_triangle.h"

#include "common/fields.h"
#include "common/harness/query.h"

#include "common/inputs/inputs.h"

namespace labkit::lab02 {

struct PointTriangle {
  Vec3 x = Vec3::Zero();
  Triangle triangle;
};
LABKIT_FIELDS(PointTriangle, x, triangle)

struct MovingMesh {
  Segment segment;
  Mesh mesh;
  RigidTransform m0 = RigidTransform::Identity();
  RigidTransform m1 = RigidTransform::Identity();
};
LABKIT_FIELDS(MovingMesh, segment, mesh, m0, m1)

// Step 7: two meshes, each moving by a translation over [0, 1].
struct MovingMeshes {
  Mesh a;
  Vec3 velocity_a = Vec3::Zero();
  Mesh b;
  Vec3 velocity_b = Vec3::Zero();
};
LABKIT_FIELDS(MovingMeshes, a, velocity_a, b, velocity_b)

}  // namespace labkit::lab02

// ---- The queries -------------------------------------------------------------------------
// Each question the tests ask and the input it takes, by the step that asks it first:
// X(name, Input) is the query "name", X_IN(group, name, Input) the query "group.name"
// (common/harness/query.h). The tests, the viewer's scene and its presets read this table:
// a query is added or renamed here and nowhere else.
// clang-format off
#define LABKIT_LAB02_QUERIES(X, X_IN)                                                                           \
  /* step 1 */ X(segment_plane, SegmentTrianglePair)                                                            \
  /* step 2 */ X(point_in_triangle_edges, PointTriangle)                                                        \
  /* step 3 */ X(barycentric, PointTriangle) X(point_in_triangle_barycentric, PointTriangle)                    \
  /* step 4 */ X(test_segment_triangle, SegmentTrianglePair) X(find_segment_triangle, SegmentTrianglePair)      \
  /* step 5 */ X(any_hit, SegmentMeshPair) X(first_hit, SegmentMeshPair) X(all_hits, SegmentMeshPair)           \
  /* step 6 */ X(first_hit_moving, MovingMesh)                                                                  \
  /* step 7 */ X(first_contact_moving_meshes, MovingMeshes)                                                     \
  /* step 8 */ X_IN(robust, point_in_triangle, PointTriangle)                                                   \
               X_IN(robust, find_segment_triangle, SegmentTrianglePair) X_IN(robust, all_hits, SegmentMeshPair) \
               X_IN(needle, find_segment_triangle, SegmentTrianglePair)                                         \
  /* step 9 */ X_IN(robust, first_contact_moving_meshes, MovingMeshes)
// clang-format on

namespace labkit::lab02::query {
LABKIT_QUERIES(LABKIT_LAB02_QUERIES)
}  // namespace labkit::lab02::query
