// Lab 06's inputs: each query's arguments as one struct, whose fields() let reports print
// it and replay tokens carry it (the answers' fields are in tests/06_spatial_trees.wire.h), and at
// the end the table of the queries that take them.
#pragma once

#include "spatial_trees.h"

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
template <class V> void fields(TreeQuery& q, V&& v) {
  v("mesh", q.mesh);
  v("segment", q.segment);
  v("tree", q.tree);
}

// A point against the solid of a closed mesh (step 3), or an eye for the painter (step 4).
struct PointQuery {
  Mesh mesh;
  Vec3 point = Vec3::Zero();
};
template <class V> void fields(PointQuery& q, V&& v) {
  v("mesh", q.mesh);
  v("point", q.point);
}

struct SphereSet {
  std::vector<Sphere> spheres;
};
template <class V> void fields(SphereSet& s, V&& v) { v("spheres", s.spheres); }

// Step 6: the frames of one simulation, the same spheres moved a little each time.
struct SweepCase {
  std::vector<std::vector<Sphere>> frames;
};
template <class V> void fields(SweepCase& c, V&& v) { v("frames", c.frames); }

// Step 6's big case: `count` spheres spread over a cube of side 100 (radii 0.25 to 1),
// then `frames` frames in which each centre moves along x by at most 0.05.
struct MovingSpheres {
  int count = 1000;
  int frames = 10;
  int seed = 1;
};
template <class V> void fields(MovingSpheres& m, V&& v) {
  v("count", m.count);
  v("frames", m.frames);
  v("seed", m.seed);
}

// Step 7: two meshes, the checker's OBB trees over them (seeds), and whether every pair
// is asked for.
struct BvhQuery {
  Mesh a, b;
  int tree_a = 0, tree_b = 0;
  bool every = true;
};
template <class V> void fields(BvhQuery& q, V&& v) {
  v("a", q.a);
  v("b", q.b);
  v("tree_a", q.tree_a);
  v("tree_b", q.tree_b);
  v("every", q.every);
}

// Step 8: one of the four big meshes (gen::MeshKind), its size, and a seed for the mesh
// (terrain, soup) and for the random segments.
struct EfficiencyCase {
  int kind = 0;
  int triangles = 10000;
  int segments = 1000;
  int seed = 1;
};
template <class V> void fields(EfficiencyCase& c, V&& v) {
  v("kind", c.kind);
  v("triangles", c.triangles);
  v("segments", c.segments);
  v("seed", c.seed);
}

// Step 8's spheres: n spread over a cube of side 100, radii from 0.25 to 1.
struct SpreadSpheres {
  int count = 2000;
  int seed = 1;
};
template <class V> void fields(SpreadSpheres& s, V&& v) {
  v("count", s.count);
  v("seed", s.seed);
}

}  // namespace labkit::lab06

// ---- The queries -------------------------------------------------------------------------
// The name of each question the tests ask (a replay token's prefix) and the input it takes,
// by the step that asks it first. The tests, the viewer's scene and its presets read this
// table (common/harness/query.h): a query is added or renamed here and nowhere else.
#define LABKIT_LAB06_QUERIES(X)                                      \
  /* step 1 */                                                       \
  X(build_kd_tree, "build_kd_tree", Mesh)                            \
  X(build_kd_tree_lattice, "build_kd_tree.lattice", Mesh)            \
  /* step 2 */                                                       \
  X(first_hit, "first_hit", TreeQuery)                               \
  X(any_hit, "any_hit", TreeQuery)                                   \
  X(all_hits, "all_hits", TreeQuery)                                 \
  /* step 3 */                                                       \
  X(build_bsp, "build_bsp", Mesh)                                    \
  X(classify, "classify", PointQuery)                                \
  /* step 4 */                                                       \
  X(back_to_front, "back_to_front", PointQuery)                      \
  /* step 5 */                                                       \
  X(overlapping_pairs, "overlapping_pairs", SphereSet)               \
  /* step 6 */                                                       \
  X(sweep_frames, "sweep_frames", SweepCase)                         \
  X(sweep_frames_moving, "sweep_frames.moving", MovingSpheres)       \
  /* step 7 */                                                       \
  X(colliding_triangles, "colliding_triangles", BvhQuery)            \
  /* step 8 */                                                       \
  X(efficiency_segments, "efficiency.segments", EfficiencyCase)      \
  X(efficiency_spheres, "efficiency.spheres", SpreadSpheres)         \
  /* step 9 */                                                       \
  X(robust_build_kd_tree, "robust.build_kd_tree", Mesh)              \
  X(robust_segment_queries, "robust.segment_queries", TreeQuery)     \
  X(robust_classify, "robust.classify", PointQuery)                  \
  X(robust_back_to_front, "robust.back_to_front", PointQuery)        \
  X(robust_overlapping_pairs, "robust.overlapping_pairs", SphereSet) \
  X(robust_sweep_frames, "robust.sweep_frames", SweepCase)           \
  X(robust_colliding_triangles, "robust.colliding_triangles", BvhQuery)

namespace labkit::lab06::query {
LABKIT_LAB06_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB06_QUERIES)
}  // namespace labkit::lab06::query
