// Lab 06: BSP and k-d trees, pair reduction. Your file: replace each stub below.
// The contract is spatial_trees.h; the steps are in handouts/06_spatial_trees.md.
// Check your work with:  ./labkit check 06        (one step: ./labkit check 06 --step 1)
//
// The segment-triangle test is given: call labkit::given::segment_triangle(segment,
// triangle) and count each call in your result's `tests`.
#include "spatial_trees.h"

#include "common/not_implemented.h"

namespace labkit::lab06 {

// L06S1: the k-d tree. Say here which split rule and which leaf size you chose.
KdTree build_kd_tree(const Mesh& mesh) { not_implemented("L06S1", mesh); }

// L06S2: the nearest hit, front to back, with an early exit.
KdHit first_hit(const KdTree& tree, const Segment& segment) { not_implemented("L06S2", tree, segment); }

// L06S2: any hit, stopping at the first one found.
KdHit any_hit(const KdTree& tree, const Segment& segment) { not_implemented("L06S2", tree, segment); }

// L06S2: every hit, each triangle once, sorted by t.
KdHits all_hits(const KdTree& tree, const Segment& segment) { not_implemented("L06S2", tree, segment); }

// L06S3: the BSP tree, cut along the mesh's triangles.
BspTree build_bsp(const Mesh& mesh) { not_implemented("L06S3", mesh); }

// L06S3: inside, outside or on the surface.
Where classify(const BspTree& tree, const Vec3& point) { not_implemented("L06S3", tree, point); }

// L06S4: the painter's order.
std::vector<int> back_to_front(const BspTree& tree, const Vec3& eye) { not_implemented("L06S4", tree, eye); }

// L06S5: the overlapping pairs, without testing them all (a pair: given_balls_meet).
SpherePairs overlapping_pairs(const std::vector<Sphere>& spheres) { not_implemented("L06S5", spheres); }

// L06S6: keep the sorted ends between frames, re-sort them by insertion, update the
// pairs overlapping on x at each swap, test only those. Compare ends with compare_ends.
SweepFrame SweepAndPrune::update(const std::vector<Sphere>& spheres) { not_implemented("L06S6", spheres); }

// L06S7: the dual traversal of two OBB trees (lecture 001's TestBVH), counted.
TrianglePairs colliding_triangles(const ObbTree& a, const ObbTree& b, bool every) {
  not_implemented("L06S7", a, b, every);
}

// L06S11: the spatial hash: buckets of (cell key, ball), the 27 cells around each ball,
// only entries whose key is the cell looked for (a pair: given_balls_meet).
SpherePairs hashed_pairs(const std::vector<Sphere>& spheres, double cell, int buckets) {
  not_implemented("L06S11", spheres, cell, buckets);
}

// L06S12: the octree: cut a node in 8 at its centre while it holds more than `capacity`
// balls (and is above max_depth); a ball goes to every child its box meets.
Octree build_octree(const std::vector<Sphere>& spheres, int capacity, int max_depth) {
  not_implemented("L06S12", spheres, capacity, max_depth);
}

// L06S12: the balls that meet a box, descending only the children whose cells meet it
// (a cell: given_cell_meets_box; a ball, once: given_ball_meets_box).
BallsInBox balls_in_box(const Octree& tree, const Aabb& box) { not_implemented("L06S12", tree, box); }

}  // namespace labkit::lab06
