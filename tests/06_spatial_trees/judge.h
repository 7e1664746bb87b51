// Lab 06's checker: the generators that draw each query's input, then the verdicts.
//
// Lab 06's verdicts: each judge compares one answer with the exact oracle, following the
// rules and tolerances of labs/06_spatial_trees/spatial_trees.h. The tests and the viewer
// both use them. The inputs are in tests/06_spatial_trees/queries.h, their random draws
// below.
//
// The generators, first in this file (gen::):
// Lab 06's own random inputs, drawn from the shared meshes and spheres (meshes.h): segments
// and points near a mesh with a seed for the checker's tree, sets of spheres moving frame
// by frame, and pairs of meshes that overlap in part.
#pragma once

#include "06_spatial_trees/queries.h"
#include "common/generators/meshes.h"
#include "common/harness/check.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

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
// Step 6's big case, frame by frame (no random draw: the same numbers give the same
// frames).
lab06::SweepCase moving_spheres(const lab06::MovingSpheres& m);
// Step 7: two small meshes overlapping in part, seeds for the checker's OBB trees.
rc::Gen<lab06::BvhQuery> bvh_query();
// Step 11: sparse worlds (clusters 2^30 apart, on integers: exact touching), step 5's
// sets, bucket counts from 1 (every cell collides) to thousands.
rc::Gen<lab06::HashCase> hash_case();
// Step 12: clusters of balls in a wide space (the octree adapts to them), a box near
// them; or balls and a box on integers, touching exactly, judged exactly.
rc::Gen<lab06::OctreeCase> octree_case();

}  // namespace labkit::gen

namespace labkit::lab06 {

std::string describe(Where w);

namespace judge {

using check::Outcome;

using check::Rules;  // random cases, or a robustness step's exact input

// The checker's own k-d trees: valid by step 1's rule, and awkward on purpose: splits
// through vertices, on cell walls and at random places, empty leaves, zero-area
// triangles listed. The same seed gives the same tree.
KdTree checker_tree(const Mesh& mesh, int seed);
// A tree by hand: bounds, nodes and items as given, triangles from the mesh.
KdTree tree_of(const Mesh& mesh, const Aabb& bounds, std::vector<KdNode> nodes, std::vector<int> items);

// Step 1: the tree is well formed and every leaf lists every triangle meeting its cell.
Outcome kd_tree(const Mesh& mesh, const KdTree& got);
// The first hit by brute force: given::segment_triangle on every triangle whose box meets
// the segment's (the others cannot be hit), lowest t first (ties: the lower index). The
// efficiency step's yardstick; `boxes` is triangle_boxes(triangles).
std::vector<Aabb> triangle_boxes(const std::vector<Triangle>& triangles);
KdHit brute_first_hit(const std::vector<Triangle>& triangles, const std::vector<Aabb>& boxes, const Segment& segment);

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
// The number of pairs of ends (values on x, as the header computes them) whose order of
// values differs between two frames: the header's `changed`.
long long changed_order(const std::vector<Sphere>& before, const std::vector<Sphere>& after);

// Step 7: the checker's OBB trees. Seed 0: axis-aligned boxes, one triangle per leaf,
// split at the median along the longest axis (the handout's examples). Other seeds: each
// node's box turned by a rotation of its own, leaves of 1 to 4 triangles.
ObbTree obb_tree(const Mesh& mesh, int seed);
// The header's dual traversal of two OBB trees (colliding_triangles): the leaf pairs it
// reaches with overlapping boxes, in its order, and the box tests it makes on the way.
// The judge bounds an answer's counts by it; the viewer draws the leaf pairs.
struct ObbWalk {
  std::vector<std::array<int, 2>> leaf_pairs;
  long long box_tests = 0;
};
// The header's traversal; with a_at_tie false, the one that descends b's node at equal
// volumes (a likely mistake the judge names when it sees its count).
ObbWalk header_walk(const ObbTree& a, const ObbTree& b, bool a_at_tie = true);
// Step 7: the pairs against the exact brute force over all triangle pairs, and the counts
// against the header's traversal (box tests, triangle tests) run on the same trees.
Outcome colliding_triangles(const BvhQuery& in, const ObbTree& a, const ObbTree& b, const BvhRun& got,
                            Rules rules = Rules::random);

// Step 11 (tests/06_spatial_trees/judge.hash.cpp). The pairs of balls whose cells
// (floor(c / cell), exact: cell is a power of two) differ by at most 1 along each axis:
// the most tests the header allows. The pairs against the exact brute force; `calls`,
// given_balls_meet's calls the judge counted, against that bound. An exact case (in.exact)
// allows no ambiguity, whatever `rules` says.
long long neighbour_pairs(const HashCase& in);
Outcome hashed_pairs(const HashCase& in, const SpherePairs& got, long long calls, Rules rules = Rules::random);

// Step 12 (tests/06_spatial_trees/judge.octree.cpp). The header's octree: the checker's
// tree, which the box queries run on, and the yardstick of a student's build.
Octree octree_of(const std::vector<Sphere>& spheres, int capacity, int max_depth);
// The build: node for node the header's tree (in any order of nodes).
Outcome octree(const OctreeCase& in, const Octree& got);
// The header's traversal of a box query: its tests of either kind, and the leaves reached.
struct OctreeWalk {
  long long cell_tests = 0, ball_tests = 0;
  std::vector<int> leaves;
};
OctreeWalk octree_walk(const Octree& tree, const Aabb& box);
// The query on `tree` (the header's): the balls against the exact brute force, the counts
// against the header's traversal.
Outcome balls_in_box(const OctreeCase& in, const Octree& tree, const OctreeRun& got, Rules rules = Rules::random);

}  // namespace judge
}  // namespace labkit::lab06
