// Lab 06's inputs: each query's arguments as one struct, whose fields() let reports print
// it and replay tokens carry it (the answers' fields are in tests/06_spatial_trees/wire.h), and at
// the end the table of the queries that take them.
#pragma once

#include "spatial_trees.h"

#include "common/fields.h"
#include "common/harness/query.h"

#include <vector>

namespace labkit::lab06 {

// A segment query: a mesh, a segment, and which of the checker's own trees over the mesh
// to ask (a seed: the same number always makes the same tree).
struct TreeQuery {
  Mesh mesh;
  Segment segment;
  int tree = 0;
};
LABKIT_FIELDS(TreeQuery, mesh, segment, tree)

// A point against the solid of a closed mesh (step 3), or an eye for the painter (step 4).
struct PointQuery {
  Mesh mesh;
  Vec3 point = Vec3::Zero();
};
LABKIT_FIELDS(PointQuery, mesh, point)

struct SphereSet {
  std::vector<Sphere> spheres;
};
LABKIT_FIELDS(SphereSet, spheres)

// Step 6: the frames of one simulation, the same spheres moved a little each time.
struct SweepCase {
  std::vector<std::vector<Sphere>> frames;
};
LABKIT_FIELDS(SweepCase, frames)

// Step 6's big case: `count` spheres spread over a cube of side 100 (radii 0.25 to 1),
// then `frames` frames in which each centre moves along x by at most 0.05.
struct MovingSpheres {
  int count = 1000;
  int frames = 10;
  int seed = 1;
};
LABKIT_FIELDS(MovingSpheres, count, frames, seed)

// Step 7: two meshes, the checker's OBB trees over them (seeds), and whether every pair
// is asked for.
struct BvhQuery {
  Mesh a, b;
  int tree_a = 0, tree_b = 0;
  bool every = true;
};
LABKIT_FIELDS(BvhQuery, a, b, tree_a, tree_b, every)

// Step 8: one of the four big meshes (gen::MeshKind), its size, and a seed for the mesh
// (terrain, soup) and for the random segments.
struct EfficiencyCase {
  int kind = 0;
  int triangles = 10000;
  int segments = 1000;
  int seed = 1;
};
LABKIT_FIELDS(EfficiencyCase, kind, triangles, segments, seed)

// Step 8's spheres: n spread over a cube of side 100, radii from 0.25 to 1.
struct SpreadSpheres {
  int count = 2000;
  int seed = 1;
};
LABKIT_FIELDS(SpreadSpheres, count, seed)

// Step 11: spheres, the cell side (a power of two, at least every diameter) and the bucket
// count of the hash. `exact`: centres and radii are integers (times a power of two) within
// each cluster, where given_balls_meet is exact, so the verdict allows no ambiguity.
struct HashCase {
  std::vector<Sphere> spheres;
  double cell = 1;
  int buckets = 1;
  bool exact = false;
};
LABKIT_FIELDS(HashCase, spheres, cell, buckets, exact)

// Step 12: balls, the octree's leaf capacity and depth limit, and a query box. `exact`:
// integers (times a power of two), where given_ball_meets_box is exact: no ambiguity.
struct OctreeCase {
  std::vector<Sphere> spheres;
  int capacity = 4;
  int max_depth = 6;
  Aabb box;
  bool exact = false;
};
LABKIT_FIELDS(OctreeCase, spheres, capacity, max_depth, box, exact)

}  // namespace labkit::lab06

// ---- The queries -------------------------------------------------------------------------
// Each question the tests ask and the input it takes, by the step that asks it first:
// X(name, Input) is the query "name", X_IN(group, name, Input) the query "group.name"
// (common/harness/query.h). The tests, the viewer's scene and its presets read this table:
// a query is added or renamed here and nowhere else.
// clang-format off
#define LABKIT_LAB06_QUERIES(X, X_IN)                                                              \
  /* step 1 */ X(build_kd_tree, Mesh) X_IN(build_kd_tree, lattice, Mesh)                           \
  /* step 2 */ X(first_hit, TreeQuery) X(any_hit, TreeQuery) X(all_hits, TreeQuery)                \
  /* step 3 */ X(build_bsp, Mesh) X(classify, PointQuery)                                          \
  /* step 4 */ X(back_to_front, PointQuery)                                                        \
  /* step 5 */ X(overlapping_pairs, SphereSet)                                                     \
  /* step 6 */ X(sweep_frames, SweepCase) X_IN(sweep_frames, moving, MovingSpheres)                \
  /* step 7 */ X(colliding_triangles, BvhQuery)                                                    \
  /* step 8 */ X_IN(efficiency, segments, EfficiencyCase) X_IN(efficiency, spheres, SpreadSpheres) \
  /* step 9 */ X_IN(robust, build_kd_tree, Mesh) X_IN(robust, segment_queries, TreeQuery)          \
  /* step 10 */ X_IN(robust, classify, PointQuery) X_IN(robust, back_to_front, PointQuery)         \
               X_IN(robust, overlapping_pairs, SphereSet) X_IN(robust, sweep_frames, SweepCase)    \
               X_IN(robust, colliding_triangles, BvhQuery)                                         \
  /* step 11 */ X(hashed_pairs, HashCase)                                                        \
  /* step 12 */ X(build_octree, OctreeCase) X(balls_in_box, OctreeCase)
// clang-format on

namespace labkit::lab06::query {
LABKIT_QUERIES(LABKIT_LAB06_QUERIES)
}  // namespace labkit::lab06::query
