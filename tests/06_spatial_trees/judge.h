// Lab 06's checker beyond its queries (queries.h declares the queries, their generators
// and their verdicts): what the lab's generators, judges, tests and viewer scene share.
#pragma once

#include "06_spatial_trees/queries.h"
#include "common/generators/meshes.h"
#include "common/harness/check.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace labkit::lab06 {

std::string describe(Where w);

namespace judge {

// The checker's own k-d trees: valid by step 1's rule, and awkward on purpose: splits
// through vertices, on cell walls and at random places, empty leaves, zero-area
// triangles listed. The same seed gives the same tree.
KdTree checker_tree(const Mesh& mesh, int seed);
// A tree by hand: bounds, nodes and items as given, triangles from the mesh.
KdTree tree_of(const Mesh& mesh, const Aabb& bounds, std::vector<KdNode> nodes, std::vector<int> items);
// The first hit by brute force: given::segment_triangle on every triangle whose box meets
// the segment's (the others cannot be hit), lowest t first (ties: the lower index). The
// efficiency step's yardstick; `boxes` is triangle_boxes(triangles).
std::vector<Aabb> triangle_boxes(const std::vector<Triangle>& triangles);
KdHit brute_first_hit(const std::vector<Triangle>& triangles, const std::vector<Aabb>& boxes, const Segment& segment);
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

// Step 11 (tests/06_spatial_trees/judge.hash.cpp). The pairs of balls whose cells
// (floor(c / cell), exact: cell is a power of two) differ by at most 1 along each axis:
// the most tests the header allows. The pairs against the exact brute force; `calls`,
// given_balls_meet's calls the judge counted, against that bound. An exact case (in.exact)
// allows no ambiguity, whatever `rules` says.
long long neighbour_pairs(const HashCase& in);

// Step 12 (tests/06_spatial_trees/judge.octree.cpp). The header's octree: the checker's
// tree, which the box queries run on, and the yardstick of a student's build.
Octree octree_of(const std::vector<Sphere>& spheres, int capacity, int max_depth);
// The header's traversal of a box query: its tests of either kind, and the leaves reached.
struct OctreeWalk {
  long long cell_tests = 0, ball_tests = 0;
  std::vector<int> leaves;
};
OctreeWalk octree_walk(const Octree& tree, const Aabb& box);

}  // namespace judge
}  // namespace labkit::lab06
