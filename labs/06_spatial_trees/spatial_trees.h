// Lab 06: BSP and k-d trees, pair reduction.
// Handout: handouts/06_spatial_trees.md. Lectures 000 and 001 (collision optimization:
// BVHs, octrees, k-d trees, BSP trees, uniform grids, pair reduction), 002 (reducing the
// number of detections: partitioning space, the plane sweep) and 004 (segment against a
// mesh: first hit, any hit, all hits).
//
// You write labs/06_spatial_trees/spatial_trees.cpp; this header is the contract.
//
// Four structures that spare a search most of its tests:
//  - a k-d tree over a mesh's triangles answers segment queries (steps 1, 2);
//  - a BSP tree cut along the mesh's own triangles tells inside from outside and lists
//    the triangles back to front (steps 3, 4);
//  - a sweep (or a grid) finds the overlapping pairs among many spheres (step 5), and
//    keeps its sorted list from frame to frame (frame coherence, step 6);
//  - two trees of oriented boxes, traversed together, find the triangle pairs of two
//    meshes that meet (step 7).
// Step 8 counts the tests of steps 1, 2 and 5; step 9 feeds steps 1 and 2, and step 10
// steps 3 to 7, exact degenerate input. Extensions beyond them: a spatial hash for sparse
// worlds (step 11) and an octree that adapts to where the balls are (step 12).
//
// The primitive is given. Whether a segment hits a triangle is decided by the watertight
// test labkit::given::segment_triangle (common/given/segment_triangle.h), here and in the
// reference ("watertight": a segment through an edge or a vertex that triangles share hits
// at least one of them). You write the trees, their traversal and the broad phase, not the
// primitive. Its rules are this lab's rules for a hit: the triangle is closed (edges and
// vertices count), but a segment lying in the triangle's plane, a zero-length segment
// and a zero-area triangle never hit. Mind the difference with lab 02's contract, where
// a coplanar segment hits where it meets the triangle and a zero-length one hits when its
// point is on it: here neither does, and the checker and its exact oracle say the same.
//
// Input. Every coordinate and radius is finite, and S (below) lies between 1e-50 and
// 1e50 (or the input is all zeros); triangles may be needles (a height down to 1e-8 of
// the longest side) or have zero area. Within that domain every rule below holds. Each
// query states its preconditions; the reference refuses input that breaks one with
// std::invalid_argument naming the argument and the rule ("first_hit: segment.a must be
// finite, got (nan, 0, 0)"). Your code is not graded on invalid input.
//
// Tolerances. S is the largest absolute coordinate of the input (mesh vertices, segment
// ends, points, sphere centres and radii), and tol = 1e-9 S.
//  - Yes/no answers (is this triangle hit, is this point inside, do these balls meet,
//    which side of a plane is the eye on) must equal the exact answer, except on
//    ambiguous input, whose exact answer changes under a perturbation of tol: there
//    either answer passes. Only the answer's own geometry counts: a hit or a pair is
//    never ambiguous because a tree's split plane passes near it.
//  - Hit fields come from given::segment_triangle as it returns them: the point within
//    tol of the segment and of the triangle, a + t (b - a) within tol of the point.
//  - The k-d tree's completeness rule (step 1) is exact: no tolerance at all.
//  - BSP pieces lie within tol of their triangle and of their node's cell; their areas
//    add up to their triangle's within 1e-9 S L (L its longest edge) per piece.
//  - Test counts are exact: the checker counts the calls of the given functions
//    (given::segment_triangle, given_balls_meet, compare_ends, given_boxes_overlap,
//    given_triangles_meet). In a check or a grade they run in the checker's process,
//    which counts what it served (common/given/served.h): count them in your answers,
//    and the two must agree.
// Steps 9 and 10's input is on integers (|x| <= 1024 times a power of two; segments whose
// b - a has a power of two as its largest |component|, where the given test is exact):
// there nothing is ambiguous, and every rule below holds exactly.
#pragma once

#include "common/geometry.h"
#include "common/given/segment_triangle.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace labkit::lab06 {

// ---- Step 1 (L06S1): build a k-d tree over a mesh ----------------------------------------
//
// Every node owns a closed box, its cell; the root's is `bounds`. An interior node cuts
// its cell by the plane x[axis] = split into two closed cells: below (x[axis] <= split)
// and above (x[axis] >= split). A leaf lists triangles. Nodes sit in one array, depth
// first, each interior node directly followed by its subtree below:
//
//    y                                     nodes                       items
//    4 +-----------+-----------+           0: x = 4,  above: node 4    [0] 1   leaf 2
//      |  leaf 3   |           |           1: y = 2,  above: node 3    [1] 7
//    2 +-----------+  leaf 4   |           2: leaf, items from [0]     [2] 2   leaf 3
//      |  leaf 2   | (empty)   |           3: leaf, items from [2]     [3] 5
//    0 +-----------+-----------+--> x      4: leaf, items from [5]     [4] 7
//      0           4           8                                       [5] 0   leaf 4
//
// Triangle 7 touches y = 2, so it is listed in both leaves it meets. A leaf's list is its
// count followed by that many triangle indices.
//
// The rule a tree must keep (exactly): every triangle of non-zero area that meets the
// closed cell of a leaf, even at one point, is listed in that leaf. Sending a triangle
// below when its box's min[axis] <= split, and above when its max[axis] >= split (both,
// when it straddles or touches the plane, or lies in it) keeps it. A leaf may list more
// (triangles whose box, not themselves, meets the cell) but never an index twice.
// Zero-area triangles are never hit and may be left out.
//
// Your choice, stated in your file: the split rule (spatial median, object median, or
// the surface area heuristic of the handout), and when to stop (a leaf size, no more
// progress). Any valid tree passes this step; step 8 measures how good it is.

constexpr int kLeaf = 3;       // KdNode::axis of a leaf
constexpr int kMaxDepth = 64;  // no root-to-leaf path has more interior nodes than this

struct KdNode {
  double split = 0.0;  // interior: the plane x[axis] = split, with cell.min[axis] <= split <= cell.max[axis]
  int axis = kLeaf;    // 0, 1, 2 (x, y, z) for an interior node; kLeaf for a leaf
  int index = 0;       // interior: the child above is nodes[index] (the child below is the next
                       // node, this one's index + 1). Leaf: its list starts at items[index]
};

struct KdTree {
  Aabb bounds;                      // the root's cell: a box around every triangle (the tightest one)
  std::vector<KdNode> nodes;        // nodes[0] is the root
  std::vector<int> items;           // the leaves' lists: a count, then that many triangle indices
  std::vector<Triangle> triangles;  // triangles[i] = mesh.triangle(i): what the queries test
};

// A mesh without triangles gets a tree of one empty leaf (and bounds of zero size).
// Preconditions: every vertex finite; every index of mesh.triangles names a vertex.
KdTree build_kd_tree(const Mesh& mesh);

// ---- Step 2 (L06S2): segment queries -------------------------------------------------------
//
// The tree is any valid tree (step 1's rule), not necessarily built by your step 1: the
// checker also hands your queries trees of its own, with split planes through vertices,
// on cell walls, and empty leaves.
//
// Walk the leaves the segment meets, front to back: clip the segment to `bounds`, then at
// each interior node, with the segment's part in its cell running from t0 to t1 (a point
// of the segment is a + t (b - a)):
//
//         a *-------------|------------* b       t_split = (split - a[axis]) / (b - a)[axis]
//           t0   near     |     far    t1       near: the child on a's side of the plane;
//                       split                   when a is on it, the side b - a goes to,
//                                               and below when the segment lies in it
//
// visit the children by where the segment meets the plane:
//  - parallel to it ((b - a)[axis] = 0): the near child only, on [t0, t1]; compute no
//    t_split (0 / 0 is not a number);
//  - t_split <= 0 (the plane is behind a, or a lies on it: the segment only moves away
//    from it) or t_split > t1 (it crosses beyond this cell): the near child only;
//  - t_split < t0 (it crossed before entering this cell): the far child only;
//  - otherwise: the near child on [t0, t_split], then the far child on [t_split, t1].
//
// Tests. A query may call given::segment_triangle only on triangles listed in the leaves
// this walk visits, once per listing (not every leaf whose closed cell the segment
// touches: from a split plane, or lying in one, it visits the near child only); first_hit
// and any_hit only in leaves the segment enters no later than the hit they return (at
// t0 <= its t), or in all of them when they return none. `tests` is how many calls the query made; the checker
// counts the calls too, and the two must agree.
//
// Preconditions: the segment's ends are finite (a zero-length segment is valid and hits
// nothing); the tree keeps step 1's rule (not checked: that would cost what the tree saves).

struct KdHit {
  bool hit = false;                 // false: no triangle is hit (then only `tests` means anything)
  int triangle = -1;                // an index into the mesh's triangles
  double t = 0.0;                   // the hit point is a + t (b - a), as given::segment_triangle says
  Vec3 point = Vec3::Zero();        // that point
  Vec3 barycentric = Vec3::Zero();  // its weights of v0, v1, v2
  int tests = 0;                    // calls of given::segment_triangle this query made
};

struct KdHits {
  std::vector<KdHit> hits;  // every triangle hit, once each, sorted by t (ties: lower index
                            // first); their own `tests` fields are not read
  int tests = 0;            // calls of given::segment_triangle this query made
};

// The hit with the smallest t (two triangles tied: either). Stop as soon as the best hit
// so far is at or before the far end t1 of the leaf just searched; a hit beyond it may
// still lose to a triangle in a later leaf.
KdHit first_hit(const KdTree& tree, const Segment& segment);
// Some hit, any: front to back as above, stopping at the first triangle found hit.
KdHit any_hit(const KdTree& tree, const Segment& segment);
// Every hit: each leaf the segment meets, each triangle reported once.
KdHits all_hits(const KdTree& tree, const Segment& segment);

// ---- Step 3 (L06S3): a BSP tree: build it, classify a point ---------------------------------
//
// An auto-partition: every node's plane is the plane of one of the mesh's triangles.
//
//                 front: n . (x - v0) > 0        n = (v1 - v0) x (v2 - v0) of mesh
//      ---------*=====*------------------        triangle `plane`; the pieces lying in
//                 back:  n . (x - v0) < 0        it (=====) stay at the node
//
// Build: every triangle of non-zero area enters the root as one piece. At a node, pick
// one of its pieces; the plane of that piece's triangle is the node's plane. A piece
// whose triangle lies in that plane (all three vertices on it) stays at the node, facing
// either way; the pieces of the plane's own triangle always do (rounding may put its
// vertices a hair off its own plane: they stay anyway, or the build never ends). Any other
// piece goes front when no vertex is behind, back when no vertex
// is in front (vertices on the plane go along), and is split in two when it has vertices
// strictly on both sides: cut its edges at x = (d_p q - d_q p) / (d_p - d_q), where d is
// n . (x - v0), and cut the front and back polygons into triangles wound like the
// triangle they come from. A piece whose vertices all lie on the plane (a sliver of zero
// area, after rounding) may go either way. Build the front and back children from what
// went there; no piece: no child (-1).
//
// Decide every side by the sign of n . (x - v0) computed in doubles: on integer input
// with |x| <= 1024 it is exact. While building, take a value within rounding noise of zero,
// |d| <= 1e-13 |e0|_1 |e1|_1 |x - v0|_1 (e0 = v1 - v0, e1 = v2 - v0), as zero: a neighbour
// sharing an edge with the plane's triangle would otherwise be cut into a sliver on the
// wrong side, whose node then answers for a whole wedge of space (classify fails far from
// the surface). On step 10's integers the snap never fires. Zero-area triangles are left
// out altogether.
//
// Classify, for a closed mesh wound outward (every normal pointing out of the solid):
// where is p? Descend from the root: strictly in front, go front; strictly behind, go
// back. A missing front child means outside, a missing back child inside. On the plane:
// p is on the surface if it is in the closed triangle of a piece at this node; otherwise
// classify it in both subtrees: on if either says on or if they disagree, else what they
// agree on. (A point with inside on one side and outside on the other is on the surface.)

struct BspPiece {
  Triangle triangle;  // the whole mesh triangle, or a part of it cut by planes above, wound like it
  int source = -1;    // which mesh triangle it comes from
};

struct BspNode {
  int plane = -1;  // the node's plane is the plane of mesh triangle `plane`, front where its normal points
  int front = -1;  // the child in front, or -1: nothing there (outside, for a closed mesh)
  int back = -1;   // the child behind, or -1: nothing there (inside, for a closed mesh)
  int first = 0;   // its pieces, all in the plane, are pieces[first], ..., pieces[first + count - 1]
  int count = 0;
};

struct BspTree {
  std::vector<BspNode> nodes;       // nodes[0] is the root; none when the mesh has no triangle of non-zero area
  std::vector<BspPiece> pieces;     // every piece once, each at the one node whose plane it lies in
  std::vector<Triangle> triangles;  // triangles[i] = mesh.triangle(i): the planes' triangles
};

// Preconditions: as build_kd_tree's. Classify: the point is finite; the tree comes from
// build_bsp of a closed mesh wound outward (not checked).
BspTree build_bsp(const Mesh& mesh);

enum class Where { outside = -1, on = 0, inside = 1 };
Where classify(const BspTree& tree, const Vec3& point);

// ---- Step 4 (L06S4): back to front from an eye point --------------------------------------
//
// Every piece index once, in an order a painter can draw them in: at each node, the
// subtree on the far side of the plane from the eye first, then the node's own pieces,
// then the subtree on the eye's side. Then no piece hides any part of a piece listed
// before it. An eye exactly on a node's plane sees the plane edge on: that node's two
// subtrees and pieces may come in any order. Precondition: the eye is finite.
std::vector<int> back_to_front(const BspTree& tree, const Vec3& eye);

// ---- Step 5 (L06S5): broad phase for many spheres -------------------------------------------
//
// Every frame the spheres have moved, and the pairs that overlap must be found again. Two
// closed balls meet when |c_i - c_j| <= r_i + r_j: touching counts, so does a ball of zero
// radius (a point) on another's surface. Find them without testing all n (n - 1) / 2
// pairs: sort and sweep (the lecture's plane sweep), or a uniform grid. Nothing is kept
// from one call to the next. Preconditions: every centre finite, every radius finite and
// >= 0 (a NaN would break the sort, and pairs between finite balls would be lost).
//
// Test a pair only with given_balls_meet below (steps 5 and 6): the checker counts its
// calls, as step 2 counts given::segment_triangle, and `tests` must equal them.

// Given: |c_a - c_b| <= r_a + r_b, in doubles (squared, so no root). Counted.
bool given_balls_meet(const Sphere& a, const Sphere& b);

struct SpherePairs {
  std::vector<std::array<int, 2>> pairs;  // every {i, j}, i < j, whose balls meet, once, sorted
  long long tests = 0;                    // your calls of given_balls_meet
};

SpherePairs overlapping_pairs(const std::vector<Sphere>& spheres);

// ---- Step 6 (L06S6): sort and sweep with frame coherence ------------------------------------
//
// Between two frames the spheres move little, so the sorted list of interval ends on x
// barely changes: keep it, and re-sort it by insertion (each end slides left past the
// few ends it overtook). Every adjacent swap of a low end past a high end (or back)
// is exactly when two intervals start (or stop) overlapping: update the set of pairs
// overlapping on x there, then test only those pairs with |c_i - c_j| <= r_i + r_j.
//
// The ends. Sphere i has a low end c_i.x - r_i and a high end c_i.x + r_i, computed
// in doubles exactly so. The list is sorted by value; at equal values a low end comes
// before a high end (touching counts: [0, 1] and [1, 2] overlap). Then two intervals
// overlap on x exactly when each one's low end comes before the other's high end.
// Compare two ends' values only with compare_ends below, and test pairs only with
// given_balls_meet: the checker counts the calls of both, as step 2 counts
// given::segment_triangle.
//
// Counts. The first update sorts from scratch (any sort). Every later update, with
// changed = the number of pairs of ends whose order of values (<, = or >) is not the
// same as in the previous frame, must make
//   swaps <= changed   and   compare_ends calls <= 2 n_ends + changed   (n_ends = 2 n)
// as insertion sort does on the kept list: a re-sort from scratch makes about
// n_ends log2(n_ends) comparisons however little the spheres moved. `tests` is your
// calls of given_balls_meet this frame: at most the number of pairs whose intervals
// overlap on x.
//
// Preconditions: every centre finite, every radius finite and >= 0; every update after
// the first has as many spheres as the first (sphere i is the same body in every frame).

struct Endpoint {
  double value = 0.0;  // c.x - r (low end) or c.x + r (high end)
  int sphere = -1;     // whose end it is
  bool high = false;   // false: the low end
};

// Given: the sign of a.value - b.value (-1, 0 or 1). Counted.
int compare_ends(const Endpoint& a, const Endpoint& b);

struct SweepFrame {
  std::vector<std::array<int, 2>> pairs;  // every {i, j}, i < j, whose balls meet this frame, once, sorted
  long long tests = 0;                    // calls of given_balls_meet this frame
  long long swaps = 0;                    // adjacent swaps of ends this frame
};

// The state kept from one frame to the next. You may use these members as you like; the
// checker reads only update's answers (and the calls of compare_ends).
class SweepAndPrune {
 public:
  SweepFrame update(const std::vector<Sphere>& spheres);

  std::vector<Endpoint> ends;                   // the sorted ends on x, 2 n of them
  std::vector<std::array<int, 2>> overlapping;  // the pairs {i, j}, i < j, whose intervals overlap on x
  bool started = false;                         // false until the first update
};

// ---- Step 7 (L06S7): bounding-volume hierarchies, dual traversal ---------------------------
//
// Two meshes, each under a tree of oriented boxes (an OBB tree; the checker builds them):
// which triangle of the one meets which triangle of the other? Lecture 001's TestBVH:
//
//    test(A, B):  boxes apart                 -> nothing below A and B can meet: stop
//                 both leaves                 -> test every triangle pair of the two leaves
//                 otherwise                   -> test(child, other) for both children of the
//                                                node to descend, the other node as it is
//
// The node to descend: the one that is not a leaf; when neither is a leaf, the one with
// the larger box, by volume h[0] * h[1] * h[2] (its half extents, multiplied in that
// order); at equal volumes, A's. Descending the larger box splits the bigger problem
// first; the checker counts the box tests of exactly this traversal and allows no more.
//
// The tests are given (lab 03 taught them; here you only call them): given_boxes_overlap
// is lab 03's fifteen-axis test of two oriented boxes, conservative (it may call boxes a
// hair apart overlapping, never the reverse); given_triangles_meet decides a pair by this
// lab's hit rule: some edge of one hits the other as given::segment_triangle says, so
// touching counts and coplanar triangles never meet (a segment in a triangle's plane never
// hits). The checker counts the calls of both.
//
// Preconditions: the trees are valid (every node's box holds its subtree's triangles,
// children indices in range; not checked: that would cost what the tree saves).

struct ObbNode {
  Box box;        // holds every triangle of the node's subtree (closed)
  int left = -1;  // an interior node's children are nodes[left] and nodes[right]; -1: a leaf
  int right = -1;
  int first = 0;  // a leaf's triangles are items[first], ..., items[first + count - 1]
  int count = 0;
};

struct ObbTree {
  std::vector<ObbNode> nodes;       // nodes[0] is the root; none when the mesh has no triangle
  std::vector<int> items;           // the leaves' triangle indices
  std::vector<Triangle> triangles;  // triangles[i] = mesh.triangle(i)
};

// Lab 03's separating-axis test: the boxes' three axes each, and the nine cross products
// (those too short to mean a direction are skipped: that only says "overlap" more often).
// Apart only when a gap shows beyond a relative margin of 1e-12: conservative. Counted.
bool given_boxes_overlap(const Box& a, const Box& b);
// Some edge of one triangle hits the other (given::segment_triangle's rule). Counted.
bool given_triangles_meet(const Triangle& s, const Triangle& t);

struct TrianglePairs {
  std::vector<std::array<int, 2>> pairs;  // every {i, j} (i in a's mesh, j in b's) that meets, once, sorted
  long long box_tests = 0;                // calls of given_boxes_overlap this query made
  long long triangle_tests = 0;           // calls of given_triangles_meet this query made
};

// every = true: all pairs that meet. every = false: one pair (any), or none, and stop there.
TrianglePairs colliding_triangles(const ObbTree& a, const ObbTree& b, bool every);

// ---- Step 8 (L06S8): efficiency, counted -------------------------------------------------------
// No new function: steps 1, 2 and 5 must also be fast, measured by counting tests, never
// by timing. On meshes of about 10,000 triangles (a sphere, a torus, a terrain and a soup, from
// common/generators/meshes.h) with your own tree, over 1,000 random segments per mesh and
// query:
//  - short segments (a fiftieth of the mesh's size) at the surface: first_hit and any_hit
//    test on average at most kShortMean triangles, and never more than kShortWorst;
//  - long segments across the mesh: first_hit tests on average at most kLongFirstMean;
//    all_hits at most kLongAllMean (whatever it tests, first_hit stops early).
// Among 2,000 spheres spread over a cube of side 100, radii from 0.25 to 1,
// overlapping_pairs makes at most kSphereTests tests (brute force: 1,999,000).
constexpr double kShortMean = 40;
constexpr int kShortWorst = 400;
constexpr double kLongFirstMean = 150;
constexpr double kLongAllMean = 600;
constexpr long long kSphereTests = 100000;

// ---- Step 9 (L06S9): robustness: splits through vertices ------------------------------------
// No new function: steps 1 and 2 on exact degenerate input. Split planes through vertices
// and along faces (a triangle in the plane goes to both sides), segments lying in a split
// plane or on a wall of the root's cell, ending or starting exactly on one.

// ---- Step 10 (L06S10): robustness: BSP trees, spheres, BVHs ---------------------------------
// No new function (an extension, as steps 3 to 7 are): steps 3 to 7 on exact degenerate
// input. Points and eyes exactly on planes, faces, edges and vertices; balls touching
// exactly, even along x; triangles of two meshes touching exactly, an edge through an
// edge or a vertex on one.

// ---- Step 11 (L06S11): spatial hashing for sparse worlds ---------------------------------
//
// An extension beside step 5. A world can be sparse: a few clusters of balls, 2^30 apart.
// A dense grid of cells one diameter wide would need more cells than memory holds; a
// spatial hash keeps only the cells that hold a ball, in a table of a fixed number of
// buckets, keyed by the cell's integer coordinates:
//
//    cell of a point p:   (floor(p.x / cell), floor(p.y / cell), floor(p.z / cell))
//    bucket of a cell:    cell_hash(c) % buckets        (given below, not counted)
//
// Put every ball in the bucket of the cell holding its centre, with that cell's key.
// Then, for each ball, look in the 27 cells around its own (dx, dy, dz in -1, 0, 1): go
// to each one's bucket and take only the entries whose key is that cell. Distinct cells
// may share a bucket (a collision: `buckets` may be 1); an entry of another cell is not a
// neighbour, and a bucket reached from two of the 27 cells must not yield a pair twice.
// Test each candidate pair with given_balls_meet (step 5's counted test) once.
//
// Why it is exact: `cell` is a power of two, so p / cell and its floor are computed
// without rounding, and cell >= 2 r_max (the largest diameter): two balls that meet have
// centres at most r_i + r_j <= cell apart along every axis, so their cells differ by at
// most one along each axis. Nothing is lost, and every pair tested sits in neighbouring
// cells.
//
// Counts, by the checker (it counts given_balls_meet's calls, as in step 5): at most one
// test per pair of balls whose cells are neighbours (differ by at most 1 along each axis),
// whatever the buckets; `tests` must equal the calls.
//
// Preconditions: every centre finite, every radius finite and >= 0; `cell` a power of two
// with cell >= 2 r (every radius r); |coordinate| / cell <= 2^60 for every centre (so that
// a cell's coordinates fit in 64-bit integers, with room for the neighbour at +-1);
// 1 <= buckets <= 2^20. Random cases span 2^31 and more (clusters far apart): a cell's
// coordinates do not fit in an int. On centres and radii that are integers (times a
// power of two) below 2^24 within a cluster, given_balls_meet is exact, and nothing there
// is ambiguous: exact touching counts as meeting.

struct Cell {
  std::int64_t x = 0, y = 0, z = 0;  // the cell [x cell, (x + 1) cell) x ... holds the point
};

// Given (not counted): the classic hash of a cell, three large odd numbers and XOR. The
// bucket is cell_hash(c) % buckets.
inline std::uint64_t cell_hash(const Cell& c) {
  return (std::uint64_t(c.x) * 73856093u) ^ (std::uint64_t(c.y) * 19349663u) ^ (std::uint64_t(c.z) * 83492791u);
}

// Every pair of balls that meet, as step 5's overlapping_pairs, through a hash table of
// `buckets` buckets over cells of side `cell`.
SpherePairs hashed_pairs(const std::vector<Sphere>& spheres, double cell, int buckets);

// ---- Step 12 (L06S12): an octree that adapts -----------------------------------------------
//
// An extension beside steps 5 and 11, whose cells are all one size. An octree cuts space
// only where the balls crowd: a cell holding few balls stays whole, however big it is,
// and a crowded one is cut in eight, again and again. Drawn flat (a quadtree):
//
//    +---------------+---------------+     the root held 7 balls > capacity 2: cut in 4 (8 in 3D);
//    |               |       |  o    |     the top right quarter held 4: cut again; the other
//    |      o        |-------+-------|     quarters hold 2 or fewer and stay whole
//    |               |  o o  |   o   |
//    +---------------+---------------+     the ball x lies across the cut between the bottom
//    |               |               |     quarters: both list it
//    |               x      o        |
//    +---------------+---------------+
//
// Build. Every node owns a closed box, its cell; the root's is the tightest box around
// every ball's box [c - r, c + r] (computed in doubles so). A node at depth d (the root:
// 0) holding more than `capacity` balls, with d < max_depth, is interior: its centre
// m = 0.5 * (cell.min + cell.max) (in doubles so) cuts it into 8 children. Child k
// (k = x + 2 y + 4 z, each bit 0 or 1) takes along each axis i the lower half
// [min_i, m_i] when bit i of k is 0, the upper half [m_i, max_i] when it is 1. A ball goes
// to every child whose closed cell meets its box (box.min_i <= cell.max_i and
// cell.min_i <= box.max_i on every axis): a ball touching a cut goes both ways. Any other
// node is a leaf and lists its balls in increasing index order. No choice is left: the
// checker's tree and yours must be the same, node for node (in any order of the nodes,
// as long as a node's 8 children sit side by side).
//
// Query: every ball that meets a closed box. Test a cell against the box with
// given_cell_meets_box and a ball with given_ball_meets_box (both counted). Test the
// root's cell; at an interior node whose cell meets the box, test its 8 children's cells
// and descend only those that meet it; at a leaf, test its balls, each ball at most once
// per query (a ball may be listed in several leaves the query reaches). The checker runs
// this traversal itself and allows no more tests of either kind: cell tests <= 1 + 8 x
// (interior nodes whose cells meet the box), ball tests <= the distinct balls listed in
// the leaves reached. The checker hands your query its own tree (the one the rule above
// gives), so this query does not rest on your build.
//
// Preconditions: every centre finite, every radius finite and >= 0; 1 <= capacity <= 64;
// 0 <= max_depth <= 10 (a node at max_depth is a leaf however many balls it holds: balls
// at one point can never be separated); the query box finite, box.min <= box.max. A
// ball meets a box when the distance from its centre to the closed box is <= r (touching
// counts). On integer input (times a power of two) given_ball_meets_box is exact and
// nothing is ambiguous.

struct OctNode {
  Aabb cell;       // closed
  int child = -1;  // interior: its children are nodes[child], ..., nodes[child + 7]; -1: a leaf
  int first = 0;   // a leaf's balls are items[first], ..., items[first + count - 1], increasing
  int count = 0;
};

struct Octree {
  std::vector<OctNode> nodes;   // nodes[0] is the root; none when there is no ball
  std::vector<int> items;       // the leaves' ball indices
  std::vector<Sphere> spheres;  // spheres[i]: ball i, as given
};

// Given: the closed boxes share a point. Counted.
bool given_cell_meets_box(const Aabb& cell, const Aabb& box);
// Given: the squared distance from the centre to the closed box is <= r^2, in doubles. Counted.
bool given_ball_meets_box(const Sphere& ball, const Aabb& box);

struct BallsInBox {
  std::vector<int> balls;    // every ball that meets the box, once, sorted
  long long cell_tests = 0;  // your calls of given_cell_meets_box
  long long ball_tests = 0;  // your calls of given_ball_meets_box
};

Octree build_octree(const std::vector<Sphere>& spheres, int capacity, int max_depth);
BallsInBox balls_in_box(const Octree& tree, const Aabb& box);

}  // namespace labkit::lab06
