// Lab 02's queries: the name of each question its tests ask (a replay token's prefix,
// `./labkit replay segment_plane:...`) and the input it takes. The tests, the viewer's scene and
// its presets read this table (common/harness/query.h); a query is added or renamed here.
#pragma once

#include "common/harness/query.h"
#include "common/inputs/02_segment_triangle.h"

#define LABKIT_LAB02_QUERIES(X) \
  X(segment_plane, "segment_plane", SegmentTrianglePair)                                      \
  X(point_in_triangle_edges, "point_in_triangle_edges", PointTriangle)                        \
  X(barycentric, "barycentric", PointTriangle)                                                \
  X(point_in_triangle_barycentric, "point_in_triangle_barycentric", PointTriangle)            \
  X(test_segment_triangle, "test_segment_triangle", SegmentTrianglePair)                      \
  X(find_segment_triangle, "find_segment_triangle", SegmentTrianglePair)                      \
  X(any_hit, "any_hit", SegmentMeshPair)                                                      \
  X(first_hit, "first_hit", SegmentMeshPair)                                                  \
  X(all_hits, "all_hits", SegmentMeshPair)                                                    \
  X(first_hit_moving, "first_hit_moving", MovingMesh)                                         \
  X(first_contact_moving_meshes, "first_contact_moving_meshes", MovingMeshes)                 \
  X(robust_point_in_triangle, "robust.point_in_triangle", PointTriangle)                      \
  X(robust_find_segment_triangle, "robust.find_segment_triangle", SegmentTrianglePair)        \
  X(robust_all_hits, "robust.all_hits", SegmentMeshPair)                                      \
  X(robust_first_contact_moving_meshes, "robust.first_contact_moving_meshes", MovingMeshes)  

namespace labkit::lab02::query {
LABKIT_LAB02_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB02_QUERIES)
}  // namespace labkit::lab02::query
