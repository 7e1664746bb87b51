// Lab 06's queries: the name of each question its tests ask (a replay token's prefix,
// `./labkit replay build_kd_tree:...`) and the input it takes. The tests, the viewer's scene and
// its presets read this table (common/harness/query.h); a query is added or renamed here.
#pragma once

#include "common/harness/query.h"
#include "common/inputs/06_spatial_trees.h"

#define LABKIT_LAB06_QUERIES(X) \
  X(build_kd_tree, "build_kd_tree", Mesh)                                 \
  X(build_kd_tree_lattice, "build_kd_tree.lattice", Mesh)                 \
  X(first_hit, "first_hit", TreeQuery)                                    \
  X(any_hit, "any_hit", TreeQuery)                                        \
  X(all_hits, "all_hits", TreeQuery)                                      \
  X(build_bsp, "build_bsp", Mesh)                                         \
  X(classify, "classify", PointQuery)                                     \
  X(back_to_front, "back_to_front", PointQuery)                           \
  X(overlapping_pairs, "overlapping_pairs", SphereSet)                    \
  X(sweep_frames, "sweep_frames", SweepCase)                              \
  X(sweep_frames_moving, "sweep_frames.moving", MovingSpheres)            \
  X(colliding_triangles, "colliding_triangles", BvhQuery)                 \
  X(efficiency_segments, "efficiency.segments", EfficiencyCase)           \
  X(efficiency_spheres, "efficiency.spheres", SpreadSpheres)              \
  X(robust_build_kd_tree, "robust.build_kd_tree", Mesh)                   \
  X(robust_segment_queries, "robust.segment_queries", TreeQuery)          \
  X(robust_classify, "robust.classify", PointQuery)                       \
  X(robust_back_to_front, "robust.back_to_front", PointQuery)             \
  X(robust_overlapping_pairs, "robust.overlapping_pairs", SphereSet)      \
  X(robust_sweep_frames, "robust.sweep_frames", SweepCase)                \
  X(robust_colliding_triangles, "robust.colliding_triangles", BvhQuery)  

namespace labkit::lab06::query {
LABKIT_LAB06_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB06_QUERIES)
}  // namespace labkit::lab06::query
