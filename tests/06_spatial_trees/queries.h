// Lab 06's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), the table of the queries, and how each input is drawn and each answer
// judged (last): a new query is written here, then defined in generators*.cpp and
// judge*.cpp. Both processes include it; the answerer uses only its first part.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too. A tree the student's code built crosses back with each query on it,
// as the numbers the header defines.
#pragma once

#include "spatial_trees.h"

#include "common/fields.h"
#include "common/given/segment_triangle.h"
#include "common/given/served.h"
#include "common/harness/outcome.h"
#include "common/harness/query.h"
#include "common/protocol/calls.h"

#include <vector>

namespace labkit::lab06 {

LABKIT_FIELDS(KdNode, split, axis, index)
LABKIT_FIELDS(KdTree, bounds, nodes, items, triangles)
LABKIT_FIELDS(KdHit, hit, triangle, t, point, barycentric, tests)
LABKIT_FIELDS(KdHits, hits, tests)
LABKIT_FIELDS(BspPiece, triangle, source)
LABKIT_FIELDS(BspNode, plane, front, back, first, count)
LABKIT_FIELDS(BspTree, nodes, pieces, triangles)
LABKIT_FIELDS(SpherePairs, pairs, tests)
LABKIT_FIELDS(ObbNode, box, left, right, first, count)
LABKIT_FIELDS(ObbTree, nodes, items, triangles)
LABKIT_FIELDS(TrianglePairs, pairs, box_tests, triangle_tests)
LABKIT_FIELDS(SweepFrame, pairs, tests, swaps)
LABKIT_FIELDS(OctNode, cell, child, first, count)
LABKIT_FIELDS(Octree, nodes, items, spheres)
LABKIT_FIELDS(BallsInBox, balls, cell_tests, ball_tests)

using Indices = std::vector<int>;
using Spheres = std::vector<Sphere>;

// Step 8 asks thousands of queries of one tree of 10,000 triangles. They run in the
// answerer in one call, so that the tree crosses once. Each query is a part of the call
// (given::part): the judge's process counts the given::segment_triangle calls it served
// per part (remote::last_served()), 2 parts per segment, 3 with all_hits.
struct SegmentRun {
  KdHit first;
  KdHit any;
  int all_tests = -1;  // all_hits(tree, s).tests, when asked for
};
LABKIT_FIELDS(SegmentRun, first, any, all_tests)
using SegmentRuns = std::vector<SegmentRun>;
using Segments = std::vector<Segment>;

SegmentRuns run_segments(const KdTree& tree, const Segments& segments, bool with_all);

// Step 6: one SweepAndPrune fed the frames in turn, in the answerer (the object keeps its
// state there), each frame a part: the judge counts compare_ends and given_balls_meet per
// frame. The tests pair each frame's answer with its counts (SweepRun).
using SweepFrames = std::vector<SweepFrame>;
using Frames = std::vector<std::vector<Sphere>>;

SweepFrames run_sweep(const Frames& frames);

// A frame's answer and what the judge counted while the code answered it.
struct SweepRun {
  SweepFrame frame;
  long long comparisons = 0;  // compare_ends calls
  long long ball_tests = 0;   // given_balls_meet calls
};
using SweepRuns = std::vector<SweepRun>;

// Step 7: the dual traversal's answer and the given tests' calls the judge counted.
struct BvhRun {
  TrianglePairs answer;
  long long box_calls = 0;
  long long triangle_calls = 0;
};

// Step 12: the box query's answer and the given tests' calls the judge counted.
struct OctreeRun {
  BallsInBox answer;
  long long cell_calls = 0;
  long long ball_calls = 0;
};

// The judge serves and counts the lab's given tests (tests/06_spatial_trees/given.cpp).
void serve_given();
#define LABKIT_LAB_SERVED ::labkit::lab06::serve_given

#ifdef LABKIT_IN_ANSWERER
inline SegmentRuns run_segments(const KdTree& tree, const Segments& segments, bool with_all) {
  SegmentRuns runs;
  int part = 0;
  for (const Segment& s : segments) {
    SegmentRun r;
    given::part(part++);
    r.first = first_hit(tree, s);
    given::part(part++);
    r.any = any_hit(tree, s);
    if (with_all) {
      given::part(part++);
      r.all_tests = all_hits(tree, s).tests;
    }
    runs.push_back(r);
  }
  return runs;
}

inline SweepFrames run_sweep(const Frames& frames) {
  SweepAndPrune sweep;
  SweepFrames out;
  int part = 0;
  for (const std::vector<Sphere>& spheres : frames) {
    given::part(part++);
    out.push_back(sweep.update(spheres));
  }
  return out;
}
#endif

}  // namespace labkit::lab06

// clang-format off
#define LABKIT_LAB06_CALLS(CALL, METHOD)                                   \
  CALL(KdTree, build_kd_tree, (const Mesh&))                               \
  CALL(KdHit, first_hit, (const KdTree&, const Segment&))                  \
  CALL(KdHit, any_hit, (const KdTree&, const Segment&))                    \
  CALL(KdHits, all_hits, (const KdTree&, const Segment&))                  \
  CALL(BspTree, build_bsp, (const Mesh&))                                  \
  CALL(Where, classify, (const BspTree&, const Vec3&))                     \
  CALL(Indices, back_to_front, (const BspTree&, const Vec3&))              \
  CALL(SpherePairs, overlapping_pairs, (const Spheres&))                   \
  CALL(SegmentRuns, run_segments, (const KdTree&, const Segments&, bool)) \
  CALL(SweepFrames, run_sweep, (const Frames&))                            \
  CALL(TrianglePairs, colliding_triangles, (const ObbTree&, const ObbTree&, bool)) \
  CALL(SpherePairs, hashed_pairs, (const Spheres&, double, int))                  \
  CALL(Octree, build_octree, (const Spheres&, int, int))                           \
  CALL(BallsInBox, balls_in_box, (const Octree&, const Aabb&))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab06, LABKIT_LAB06_CALLS)

// ---- The inputs ------------------------------------------------------------------------
// Lab 06's inputs: each query's arguments as one struct, whose fields() let reports print
// it and replay tokens carry it (the answers' fields are in above), and at
// the end the table of the queries that take them.
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
// Its frames, one by one (no random draw: the same numbers give the same frames).
SweepCase sweep_of(const MovingSpheres& m);

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

// ---- How each input is drawn, and the verdicts -----------------------------------------
// Declared here, beside the queries they serve; defined in generators*.cpp (gen::) and
// judge*.cpp (judge::). RapidCheck is included where the generators are called.
namespace rc {
template <typename T> class Gen;
}  // namespace rc

// Lab 06's own random inputs, drawn from the shared meshes and spheres (meshes.h):
// segments and points near a mesh with a seed for the checker's tree, sets of spheres
// moving frame by frame, and pairs of meshes that overlap in part.
namespace labkit::gen {

// Step 2: a mesh (lab 02's soups, terrains and octahedra among others), a segment near it
// and a seed for the checker's tree; the exact one on integers.
rc::Gen<lab06::TreeQuery> tree_query();
rc::Gen<lab06::TreeQuery> exact_tree_query();
// Steps 3 and 4: a mesh for a BSP tree, a point near a closed mesh, an eye near any mesh.
rc::Gen<Mesh> bsp_mesh();
rc::Gen<lab06::PointQuery> point_query();
rc::Gen<lab06::PointQuery> exact_point_query();
rc::Gen<lab06::PointQuery> eye_query();
rc::Gen<lab06::PointQuery> exact_eye_query();
// Step 5: sphere_set() and exact_sphere_set() as one input.
rc::Gen<lab06::SphereSet> sphere_set_case();
rc::Gen<lab06::SphereSet> exact_sphere_set_case();
// Step 6: step 5's spheres, then frames in which they move a little.
rc::Gen<lab06::SweepCase> sweep_case();
rc::Gen<lab06::SweepCase> exact_sweep_case();
// Step 7: two small meshes overlapping in part, seeds for the checker's OBB trees.
rc::Gen<lab06::BvhQuery> bvh_query();
// Step 11: sparse worlds (clusters 2^30 apart, on integers: exact touching), step 5's
// sets, bucket counts from 1 (every cell collides) to thousands.
rc::Gen<lab06::HashCase> hash_case();
// Step 12: clusters of balls in a wide space (the octree adapts to them), a box near
// them; or balls and a box on integers, touching exactly, judged exactly.
rc::Gen<lab06::OctreeCase> octree_case();

}  // namespace labkit::gen

// Lab 06's verdicts: each judge compares one answer with the exact oracle, following the
// rules and tolerances of labs/06_spatial_trees/spatial_trees.h. The tests and the viewer
// both use them. The inputs are in tests/06_spatial_trees/queries.h, their random draws
// below.
namespace labkit::lab06::judge {

using check::Outcome;
using check::Rules;  // random cases, or a robustness step's exact input

// Step 1: the tree is well formed and every leaf lists every triangle meeting its cell.
Outcome kd_tree(const Mesh& mesh, const KdTree& got);

// Step 2. `calls`: how many times given::segment_triangle ran during the query.
Outcome first_hit(const TreeQuery& in, const KdTree& tree, const KdHit& got, std::uint64_t calls,
                  Rules rules = Rules::random);
Outcome any_hit(const TreeQuery& in, const KdTree& tree, const KdHit& got, std::uint64_t calls,
                Rules rules = Rules::random);
Outcome all_hits(const TreeQuery& in, const KdTree& tree, const KdHits& got, std::uint64_t calls,
                 Rules rules = Rules::random);

// Step 3: the tree is a BSP tree of the mesh (pieces in their planes, in their cells,
// tiling their triangles); a point is classified like the exact oracle does.
Outcome bsp_tree(const Mesh& mesh, const BspTree& got);
Outcome classify(const PointQuery& in, Where got, Rules rules = Rules::random);
// Step 4: `tree` must pass bsp_tree; the order obeys the painter's rule at every node.
Outcome back_to_front(const PointQuery& in, const BspTree& tree, const std::vector<int>& got,
                      Rules rules = Rules::random);

// Step 5. `calls`: how many times given_balls_meet ran during the query (the judge
// served them, remote::last_served()).
Outcome overlapping_pairs(const SphereSet& in, const SpherePairs& got, long long calls, Rules rules = Rules::random);

// Step 6: every frame's pairs (as overlapping_pairs), its tests (only pairs overlapping on
// x), and, from the second frame on, its swaps and compare_ends calls within the header's
// bounds for the ends whose order changed since the previous frame.
Outcome sweep_frames(const SweepCase& in, const SweepRuns& got, Rules rules = Rules::random);
// Step 7: the pairs against the exact brute force over all triangle pairs, and the counts
// against the header's traversal (box tests, triangle tests) run on the same trees.
Outcome colliding_triangles(const BvhQuery& in, const ObbTree& a, const ObbTree& b, const BvhRun& got,
                            Rules rules = Rules::random);
Outcome hashed_pairs(const HashCase& in, const SpherePairs& got, long long calls, Rules rules = Rules::random);
// The build: node for node the header's tree (in any order of nodes).
Outcome octree(const OctreeCase& in, const Octree& got);
// The query on `tree` (the header's): the balls against the exact brute force, the counts
// against the header's traversal.
Outcome balls_in_box(const OctreeCase& in, const Octree& tree, const OctreeRun& got, Rules rules = Rules::random);

}  // namespace labkit::lab06::judge
