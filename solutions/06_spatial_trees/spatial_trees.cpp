// Lab 06 reference: k-d tree, BSP tree, sweep and prune.
//
// The k-d tree is built for speed: the surface area heuristic picks each split among 16
// binned candidates per axis (O(n) per level, O(n log n) in all), nodes are 16 bytes in
// one array, depth first, so that a descent mostly reads the next node, and queries walk
// it with a fixed stack and no allocation. The BSP tree and the sweep are written
// plainly; the BSP tree avoids recursion only because a convex mesh makes it a chain as
// deep as the mesh has triangles.
#include "spatial_trees.h"

#include "common/preconditions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace labkit::lab06 {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// ---- Preconditions (the header's "Input") --------------------------------------------------
// A NaN compares false with everything: a NaN end would make every slab test pass and
// report a hit, and a NaN centre breaks the sort of the sweep, which then loses pairs
// between finite spheres. So invalid input is refused, naming the argument and the rule.

using namespace preconditions;

// ---- k-d tree: build ------------------------------------------------------------------------

// The surface area heuristic (SAH). A segment that crosses a cell crosses a child cell
// with a probability close to the ratio of their surface areas, so a split of a cell
// with n triangles into n_below and n_above is expected to cost
//
//   traversal + test (A_below n_below + A_above n_above) / A_cell,
//
// against test n for keeping the cell as a leaf: that comparison is the only stop rule
// (besides the depth limit), so a cell becomes a leaf exactly when splitting it no longer
// pays. The costs are in units of one segment-triangle test. A step down the tree costs
// less than a test in instructions, but on a large mesh each step reads a node that is
// rarely in the cache, slower than a test: hence 3, not the textbook 0.3. A split
// that leaves one side empty cuts away empty space, which lets a query skip it at once,
// and gets a bonus.
constexpr double kTraversalCost = 3.0;
constexpr double kTestCost = 1.0;
constexpr double kEmptyBonus = 0.2;
// Binned SAH: the candidate planes are the inner walls of kBins equal bins per axis, not
// every triangle's box side. Counting triangles per bin is one pass over the cell's list,
// with no sorting, so a level of the tree costs O(n); a sort per node would make the
// build O(n log^2 n). More bins barely improve the tree (the planes are already within
// 1/16 of the cell of the best one) and cost a longer sweep per node.
constexpr int kBins = 16;

double surface_area(const Aabb& box) {
  const Vec3 e = box.max - box.min;
  return 2 * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
}

struct Split {
  int axis = -1;  // -1: a leaf is cheaper
  double position = 0.0;
  double cost = kInfinity;
};

// Builds depth first, so that each node is appended where the header's layout puts it.
// Lists live in one scratch array, refs_, used as a stack: a node's list is a range of it;
// splitting compacts the list below in place (its front part) and appends the list above
// at the end; the subtree below appends its own lists after that and gives the space back
// when it is done. No allocation per node, and the scratch array stays a few times n.
class KdBuilder {
 public:
  // The depth limit grows with the number of triangles as in pbrt (8 + 1.3 log2 n): deep
  // enough for any useful split, shallow enough that a bad case cannot run away.
  KdBuilder(KdTree& tree, std::vector<Aabb> boxes, std::vector<int> list)
      : tree_(tree),
        boxes_(std::move(boxes)),
        refs_(std::move(list)),
        max_depth_(std::min(kMaxDepth, int(8 + 1.3 * std::log2(double(std::max<std::size_t>(boxes_.size(), 1)))))) {
    refs_.reserve(3 * refs_.size() + 64);
  }

  // Appends the subtree of `cell`, which holds refs_[first, last), to the tree.
  void build(const Aabb& cell, std::size_t first, std::size_t last, int depth) {
    // The tree stops splitting at depth 2: leaves of thousands of triangles. Every
    // answer is still right; only the count of tests gives it away.
    // mutant leaves_too_big (step 8, "leaves too big"): `max_depth_` -> `2`
    const Split split = depth < max_depth_ ? best_split(cell, first, last) : Split{};
    if (split.axis < 0) {
      add_leaf(first, last);
      return;
    }
    // Closed cells: a triangle touching the plane, or lying in it, goes to both sides.
    // Writing below never overtakes reading (below_last <= k), so it can share the range.
    const int axis = split.axis;
    const std::size_t above_first = refs_.size();
    std::size_t below_last = first;
    for (std::size_t k = first; k < last; ++k) {
      const int i = refs_[k];
      const Aabb& box = boxes_[std::size_t(i)];
      if (box.max[axis] >= split.position) refs_.push_back(i);
      // A triangle that only touches the split plane from above is sent above only,
      // though it meets the closed cell below at the plane.
      // mutant touching_goes_one_side (step 1, "closed cell", "both sides"): `<=` -> `<`
      if (box.min[axis] <= split.position) refs_[below_last++] = i;
    }
    const std::size_t above_last = refs_.size();
    const std::size_t self = tree_.nodes.size();
    tree_.nodes.push_back({split.position, axis, 0});
    Aabb below_cell = cell, above_cell = cell;
    below_cell.max[axis] = above_cell.min[axis] = split.position;
    build(below_cell, first, below_last, depth + 1);  // lands at self + 1
    refs_.resize(above_last);                         // what the subtree below appended
    tree_.nodes[self].index = int(tree_.nodes.size());
    build(above_cell, above_first, above_last, depth + 1);
  }

 private:
  // Every empty leaf shares the list at items[0] (count 0): empty cells are many (they
  // are what the empty-space splits cut off), and a query crossing one then reads a
  // list that is already in the cache.
  void add_leaf(std::size_t first, std::size_t last) {
    if (first == last) {
      tree_.nodes.push_back({0.0, kLeaf, 0});
      return;
    }
    tree_.nodes.push_back({0.0, kLeaf, int(tree_.items.size())});
    tree_.items.push_back(int(last - first));
    tree_.items.insert(tree_.items.end(), refs_.begin() + std::ptrdiff_t(first), refs_.begin() + std::ptrdiff_t(last));
  }

  // The cheapest of the candidate planes, or no split when a leaf is cheaper. Each
  // triangle's box, clipped to the cell, starts in one bin and ends in one per axis; one
  // pass over the list counts both for the three axes, then a sweep over the bin walls
  // counts the triangles on each side of every wall at once.
  Split best_split(const Aabb& cell, std::size_t first, std::size_t last) const {
    const int n = int(last - first);
    const double area = surface_area(cell);
    Split best;
    best.cost = kTestCost * n;  // the cost of a leaf
    if (n <= 1 || !(area > 0)) return best;
    const Vec3 lo = cell.min, extent = cell.max - cell.min;
    double bins_per_unit[3];
    for (int axis = 0; axis < 3; ++axis) bins_per_unit[axis] = extent[axis] > 0 ? kBins / extent[axis] : 0.0;
    const auto bin = [&](double x, int axis) {
      return std::clamp(int((x - lo[axis]) * bins_per_unit[axis]), 0, kBins - 1);
    };
    int starts[3][kBins] = {}, ends[3][kBins] = {};
    for (std::size_t k = first; k < last; ++k) {
      const Aabb& box = boxes_[std::size_t(refs_[k])];
      for (int axis = 0; axis < 3; ++axis) {
        ++starts[axis][bin(box.min[axis], axis)];
        ++ends[axis][bin(box.max[axis], axis)];
      }
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (!(extent[axis] > 0)) continue;  // the cell is flat along this axis
      // Wall k lies between bins k - 1 and k. Below it: the triangles starting in a bin
      // before it; above it: those ending in a bin after it.
      int below = 0, above = n;
      const double across = extent[(axis + 1) % 3] * extent[(axis + 2) % 3];  // one face of the cut
      const double around = extent[(axis + 1) % 3] + extent[(axis + 2) % 3];
      for (int k = 1; k < kBins; ++k) {
        below += starts[axis][k - 1];
        above -= ends[axis][k - 1];
        const double position = lo[axis] + extent[axis] * k / kBins;
        const double area_below = 2 * (across + (position - lo[axis]) * around);
        const double area_above = 2 * (across + (cell.max[axis] - position) * around);
        // Progress: both sides hold fewer triangles, or one side is empty space. (A cut
        // that keeps them all on one side and some on the other could be repeated on
        // ever thinner slabs.)
        const bool empty_side = below == 0 || above == 0;
        if (!empty_side && (below == n || above == n)) continue;
        const double bonus = empty_side ? 1 - kEmptyBonus : 1.0;
        const double cost = kTraversalCost + kTestCost * bonus * (area_below * below + area_above * above) / area;
        if (cost < best.cost) best = {axis, position, cost};
      }
    }
    return best;
  }

  KdTree& tree_;
  std::vector<Aabb> boxes_;  // each triangle's bounding box
  std::vector<int> refs_;    // the lists of the nodes being built (see above)
  int max_depth_;
};

Aabb box_of(const Triangle& t) { return {t.v0.cwiseMin(t.v1).cwiseMin(t.v2), t.v0.cwiseMax(t.v1).cwiseMax(t.v2)}; }

// ---- k-d tree: queries ----------------------------------------------------------------------

// The part [t0, t1] of the segment a + t d, 0 <= t <= 1, inside a closed box, slab by
// slab; empty when t0 > t1. A slab the segment runs parallel to either holds all of it
// or none: it gets no division (0 / 0 is not a number).
struct Span {
  double t0 = 0.0, t1 = 1.0;
  bool empty() const { return t0 > t1; }
};

Span clip(const Aabb& box, const Vec3& a, const Vec3& d) {
  Span s;
  for (int i = 0; i < 3 && !s.empty(); ++i) {
    if (d[i] == 0) {
      // The clip to the root's box with strict comparisons: a segment lying in the
      // plane of a wall of the root's cell is taken as outside it, and its hits are lost.
      // mutant clip_wall_strict (step 9, "every leaf the segment meets"):
      //   `< box.min[i] || a[i] >`
      //   -> `<= box.min[i] || a[i] >=`
      if (a[i] < box.min[i] || a[i] > box.max[i]) return {1.0, 0.0};  // beside the slab
      continue;
    }
    double enter = (box.min[i] - a[i]) / d[i], leave = (box.max[i] - a[i]) / d[i];
    if (enter > leave) std::swap(enter, leave);
    s.t0 = std::max(s.t0, enter);
    s.t1 = std::min(s.t1, leave);
  }
  return s;
}

// Visits the leaves the segment meets, front to back: leaf(node, t0, t1) searches one and
// returns the t beyond which nothing more is wanted (+infinity: everything; the best hit
// so far; -infinity: stop). A leaf that ends at or after that t ends the walk, since
// every later leaf starts after it.
template <class Leaf> void front_to_back(const KdTree& tree, const Segment& s, Leaf&& leaf) {
  const Vec3 d = s.b - s.a;
  Span span = clip(tree.bounds, s.a, d);
  if (span.empty() || tree.nodes.empty()) return;
  struct Todo {
    int node;
    Span span;
  };
  Todo stack[kMaxDepth];  // far children waiting; one per interior node on the path at most
  int waiting = 0;
  int node = 0;
  for (;;) {
    const KdNode& n = tree.nodes[std::size_t(node)];
    if (n.axis != kLeaf) {
      // The child below is the next node, most likely in the same cache line; the child
      // above is far away in the array. Ask for it now, while deciding where to go.
      __builtin_prefetch(&tree.nodes[std::size_t(n.index)]);
      const int axis = n.axis;
      // The near child is on a's side; from the plane itself, on the side d leaves to.
      // The near child chosen by a strict comparison alone: a segment starting exactly
      // on a split plane is sent to the side above, whatever way it goes.
      // mutant start_on_plane_wrong_side (step 2, "near child", "side d goes to"):
      //   `(s.a[axis] == n.split && d[axis] <= 0)`
      //   -> `false`
      // A segment lying in a split plane (d[axis] = 0, a on the plane) sent to the
      // child above: the header sends it below. Step 9's exact walk catches it too.
      // mutant in_split_plane_goes_above (step 2, "below"): `<=` -> `<`
      const bool below_first = s.a[axis] < n.split || (s.a[axis] == n.split && d[axis] <= 0);
      const int near = below_first ? node + 1 : n.index, far = below_first ? n.index : node + 1;
      if (d[axis] == 0) {  // parallel to the plane: never crosses it
        node = near;
        continue;
      }
      const double t_split = (n.split - s.a[axis]) / d[axis];
      // The walk read without its t_split <= 0 rule: a segment moving away from the
      // plane is sent into the far cell behind a, which it never meets.
      // mutant far_child_behind_a (step 2, "t_split", "far child"):
      //   `if (t_split > span.t1 || t_split <= 0) {`
      //   -> `if (t_split > span.t1) {`
      if (t_split > span.t1 || t_split <= 0) {  // crosses after this cell, or behind a
        node = near;
      } else if (t_split < span.t0) {  // crossed before entering this cell
        node = far;
      } else {  // both: the near part now, the far part later
        stack[waiting++] = {far, {t_split, span.t1}};
        node = near;
        span.t1 = t_split;
      }
      continue;
    }
    const double wanted = leaf(n, span.t0, span.t1);
    if (wanted <= span.t1 || waiting == 0) return;
    const Todo next = stack[--waiting];
    if (next.span.t0 > wanted) return;  // it, and everything after it, starts too late
    node = next.node;
    span = next.span;
  }
}

// A leaf's triangles lie scattered over the triangle array, and on a large mesh each is a
// cache miss (72 bytes: two lines). Asking for all of them before testing the first lets
// the memory fetch them at once instead of one after the other.
void prefetch_triangles(const KdTree& tree, const int* list) {
  for (int k = 1; k <= list[0]; ++k) {
    const char* t = reinterpret_cast<const char*>(&tree.triangles[std::size_t(list[k])]);
    __builtin_prefetch(t);
    __builtin_prefetch(t + sizeof(Triangle) - 1);
  }
}

// One leaf's triangles: calls test(triangle index) for each.
template <class Test> void for_each_listed(const KdTree& tree, const KdNode& leaf, Test&& test) {
  const int* list = &tree.items[std::size_t(leaf.index)];
  const int count = list[0];
  prefetch_triangles(tree, list);
  for (int k = 1; k <= count; ++k) test(list[k]);
}

KdHit hit_from(const given::SegmentHit& h, int triangle) {
  KdHit r;
  r.hit = true;
  r.triangle = triangle;
  r.t = h.t;
  r.point = h.point;
  r.barycentric = h.barycentric;
  return r;
}

// ---- BSP tree ---------------------------------------------------------------------------------

// n . (x - v0) for the plane of triangle t, n = (v1 - v0) x (v2 - v0): > 0 in front.
double side_value(const Triangle& t, const Vec3& x) { return (t.v1 - t.v0).cross(t.v2 - t.v0).dot(x - t.v0); }

// The same value while building, with rounding noise taken as zero. A vertex shared with
// the plane's own triangle (a neighbour on a closed mesh) lies on the plane exactly, but
// n . (x - v0) in doubles may come out a hair off zero; the neighbour would then be cut
// into a sliver on the wrong side, and that sliver's node would claim a whole wedge of
// space for the wrong side of the solid. The rounding error is at most a few units of
// 2^-53 of |e0| |e1| |x - v0| (1-norms); 1e-13 of it is far above that, and on the
// integer input of step 10 (|x| <= 1024 times a power of two) far below the smallest
// non-zero value, so there the sign stays exact.
double build_side(const Triangle& t, const Vec3& x) {
  const Vec3 e0 = t.v1 - t.v0, e1 = t.v2 - t.v0, r = x - t.v0;
  const double d = e0.cross(e1).dot(r);
  return std::abs(d) <= 1e-13 * e0.cwiseAbs().sum() * e1.cwiseAbs().sum() * r.cwiseAbs().sum() ? 0.0 : d;
}

bool in_plane(const Triangle& plane, const Triangle& t) {
  return build_side(plane, t.v0) == 0 && build_side(plane, t.v1) == 0 && build_side(plane, t.v2) == 0;
}

// A piece while the tree is built: `whole` when it is still its source triangle.
struct Work {
  BspPiece piece;
  bool whole = true;
};

// Cuts a piece crossing the plane (d = its vertices' values) into the part in front and
// the part behind, as lab 01 clips a triangle: walk the corners in order; a corner with
// d >= 0 belongs in front, with d <= 0 behind, and an edge whose ends have strictly
// opposite signs is cut at its crossing x = (d_p q - d_q p) / (d_p - d_q), which belongs
// to both. Each side is then a triangle or a quadrilateral, fanned from its first corner.
//
//             v2               d_2 < 0: behind
//            /  \   x0 cuts edge v1 v2, x1 cuts edge v2 v0
//   -------x1----x0-------     the plane
//         /        \   front:  v0 v1 x0 x1, two triangles
//       v0 -------- v1         behind: x0 v2 x1
void split(const Work& w, const double (&d)[3], std::vector<Work>& front, std::vector<Work>& back) {
  Vec3 in_front[4], behind[4];
  int nf = 0, nb = 0;
  const Triangle& t = w.piece.triangle;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (d[i] >= 0) in_front[nf++] = t[i];
    if (d[i] <= 0) behind[nb++] = t[i];
    if ((d[i] > 0 && d[j] < 0) || (d[i] < 0 && d[j] > 0)) {
      const Vec3 x = (d[i] * t[j] - d[j] * t[i]) / (d[i] - d[j]);
      in_front[nf++] = x;
      behind[nb++] = x;
    }
  }
  for (int k = 1; k + 1 < nf; ++k)
    front.push_back({{{in_front[0], in_front[k], in_front[k + 1]}, w.piece.source}, false});
  for (int k = 1; k + 1 < nb; ++k) back.push_back({{{behind[0], behind[k], behind[k + 1]}, w.piece.source}, false});
}

// The splitter: among a few evenly spaced candidates, the one whose plane cuts the fewest
// pieces and balances the two sides best (a cut costs as much as an imbalance of 8),
// judged on a sample of the pieces so that a node costs O(n), not O(n^2).
std::size_t choose_splitter(const std::vector<Work>& pieces, const std::vector<Triangle>& triangles) {
  constexpr std::size_t kCandidates = 5, kSample = 64;
  const std::size_t n = pieces.size();
  const std::size_t step = std::max<std::size_t>(1, n / kSample);
  std::size_t best = 0;
  long best_score = std::numeric_limits<long>::max();
  for (std::size_t c = 0; c < std::min(n, kCandidates); ++c) {
    const std::size_t candidate = c * n / std::min(n, kCandidates);
    const Triangle& plane = triangles[std::size_t(pieces[candidate].piece.source)];
    long cuts = 0, front = 0, back = 0;
    for (std::size_t i = 0; i < n; i += step) {
      const Triangle& t = pieces[i].piece.triangle;
      bool any_front = false, any_back = false;
      for (int k = 0; k < 3; ++k) {
        const double v = build_side(plane, t[k]);
        any_front = any_front || v > 0;
        any_back = any_back || v < 0;
      }
      cuts += any_front && any_back;
      front += any_front && !any_back;
      back += any_back && !any_front;
    }
    const long score = 8 * cuts + std::abs(front - back);
    if (score < best_score) {
      best_score = score;
      best = candidate;
    }
  }
  return best;
}

// Is x (on the plane of `t`) in the closed triangle? Each edge function
// ((v_{i+1} - v_i) x (x - v_i)) . n is >= 0 inside: input products only, exact on
// small integers.
bool in_closed_triangle(const Triangle& t, const Vec3& x) {
  const Vec3 n = (t.v1 - t.v0).cross(t.v2 - t.v0);
  for (int i = 0; i < 3; ++i)
    if ((t[(i + 1) % 3] - t[i]).cross(x - t[i]).dot(n) < 0) return false;  // outside edge i
  return true;
}

}  // namespace

// ---- Step 1 ------------------------------------------------------------------------------------

// Split rule: the binned surface area heuristic (see KdBuilder). A cell becomes a leaf
// when no split is expected to be cheaper, when it holds one triangle, or at depth
// 8 + 1.3 log2 n (n triangles).
KdTree build_kd_tree(const Mesh& mesh) {
  require_valid("build_kd_tree", "mesh", mesh);
  KdTree tree;
  tree.triangles.reserve(mesh.size());
  std::vector<Aabb> boxes;
  std::vector<int> list;
  boxes.reserve(mesh.size());
  list.reserve(mesh.size());
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle t = mesh.triangle(i);
    tree.triangles.push_back(t);
    boxes.push_back(box_of(t));
    if (t.normal() != Vec3::Zero()) list.push_back(int(i));  // zero area: never hit, left out
  }
  if (mesh.size() > 0) {
    tree.bounds = boxes[0];
    for (const Aabb& b : boxes) {
      tree.bounds.min = tree.bounds.min.cwiseMin(b.min);
      tree.bounds.max = tree.bounds.max.cwiseMax(b.max);
    }
  }
  tree.items.push_back(0);  // items[0]: the empty list every empty leaf shares
  const std::size_t count = list.size();
  KdBuilder(tree, std::move(boxes), std::move(list)).build(tree.bounds, 0, count, 0);
  // The vectors grew by doubling: give back what they reserved and do not use.
  tree.nodes.shrink_to_fit();
  tree.items.shrink_to_fit();
  return tree;
}

// ---- Step 2 ------------------------------------------------------------------------------------

KdHit first_hit(const KdTree& tree, const Segment& segment) {
  require_valid("first_hit", "segment", segment);
  KdHit best;
  int tests = 0;
  front_to_back(tree, segment, [&](const KdNode& leaf, double, double) {
    for_each_listed(tree, leaf, [&](int i) {
      ++tests;
      const given::SegmentHit h = given::segment_triangle(segment, tree.triangles[std::size_t(i)]);
      if (!h.hit) return;
      if (best.hit && (h.t > best.t || (h.t == best.t && i >= best.triangle))) return;  // not nearer
      best = hit_from(h, i);
    });
    // A hit within this leaf's stretch beats every later leaf; one beyond it may not.
    // first_hit stops in the first leaf that has any hit, even one beyond the leaf's
    // far end (a later leaf may hold a nearer one).
    // mutant first_hit_stops_too_soon (step 2, "smallest t", "not final"): `best.t` -> `-kInfinity`
    return best.hit ? best.t : kInfinity;
  });
  // Counts the check keeps itself (README, "Given functions are counted by the checker"):
  // each of these would once have scored by writing a count the verdict read.
  // A brute force over every triangle after the walk, left out of `tests`.
  // mutant uncounted_brute_force (step 2, "must count every call of given::segment_triangle"):
  //   `best.tests = tests;`
  //   -> `for (const Triangle& t : tree.triangles) given::segment_triangle(segment, t); best.tests = tests;`
  best.tests = tests;
  return best;
}

KdHit any_hit(const KdTree& tree, const Segment& segment) {
  require_valid("any_hit", "segment", segment);
  KdHit found;
  int tests = 0;
  front_to_back(tree, segment, [&](const KdNode& leaf, double, double) {
    const int* list = &tree.items[std::size_t(leaf.index)];
    prefetch_triangles(tree, list);
    for (int k = 1; k <= list[0]; ++k) {
      ++tests;
      const given::SegmentHit h = given::segment_triangle(segment, tree.triangles[std::size_t(list[k])]);
      if (h.hit) {
        found = hit_from(h, list[k]);
        // any_hit walks on after its first hit, testing every triangle the walk meets
        // (and keeping the last hit), where it should stop at the first one.
        // mutant any_hit_walks_on (step 2, "stops at its first hit"):
        //   `return -kInfinity;`
        //   -> `continue;`
        return -kInfinity;  // stop the walk
      }
    }
    return kInfinity;
  });
  found.tests = tests;
  return found;
}

KdHits all_hits(const KdTree& tree, const Segment& segment) {
  require_valid("all_hits", "segment", segment);
  KdHits out;
  front_to_back(tree, segment, [&](const KdNode& leaf, double, double) {
    for_each_listed(tree, leaf, [&](int i) {
      ++out.tests;
      const given::SegmentHit h = given::segment_triangle(segment, tree.triangles[std::size_t(i)]);
      if (h.hit) out.hits.push_back(hit_from(h, i));
    });
    return kInfinity;
  });
  // A triangle listed in two leaves was tested twice, with the same answer: after sorting
  // by t, then index, its two hits are neighbours.
  std::sort(out.hits.begin(), out.hits.end(),
            [](const KdHit& x, const KdHit& y) { return x.t != y.t ? x.t < y.t : x.triangle < y.triangle; });
  out.hits.erase(std::unique(out.hits.begin(), out.hits.end(),
                             // all_hits reports a triangle listed in two leaves twice.
                             // mutant all_hits_twice (step 2, "each triangle once"):
                             //   `x.triangle == y.triangle`
                             //   -> `false`
                             [](const KdHit& x, const KdHit& y) { return x.triangle == y.triangle; }),
                 out.hits.end());
  return out;
}

// ---- Step 3 ------------------------------------------------------------------------------------

// Built with an explicit list of nodes still to fill, not by recursion: on a convex mesh
// every plane has all the other triangles behind it, and the tree is a chain as long as
// the mesh.
BspTree build_bsp(const Mesh& mesh) {
  require_valid("build_bsp", "mesh", mesh);
  BspTree tree;
  std::vector<Work> all;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    tree.triangles.push_back(mesh.triangle(i));
    if (tree.triangles.back().normal() != Vec3::Zero()) all.push_back({{tree.triangles.back(), int(i)}, true});
  }
  if (all.empty()) return tree;
  struct Pending {
    int node;
    std::vector<Work> pieces;
  };
  std::vector<Pending> pending;
  tree.nodes.push_back({});
  pending.push_back({0, std::move(all)});
  while (!pending.empty()) {
    Pending job = std::move(pending.back());
    pending.pop_back();
    const int plane = job.pieces[choose_splitter(job.pieces, tree.triangles)].piece.source;
    const Triangle& p = tree.triangles[std::size_t(plane)];
    std::vector<Work> front, back;
    BspNode node;
    node.plane = plane;
    node.first = int(tree.pieces.size());
    for (const Work& w : job.pieces) {
      const Triangle& source = tree.triangles[std::size_t(w.piece.source)];
      // Its triangle lies in the plane: it stays here. The splitter's own triangle always
      // does, even when rounding makes n . (v1 - v0) a hair off zero: otherwise it could be
      // sent on, chosen again below, and the build would never end.
      if (w.piece.source == plane || in_plane(p, source)) {
        tree.pieces.push_back(w.piece);
        continue;
      }
      const double d[3] = {build_side(p, w.piece.triangle.v0), build_side(p, w.piece.triangle.v1),
                           build_side(p, w.piece.triangle.v2)};
      const bool any_front = d[0] > 0 || d[1] > 0 || d[2] > 0, any_back = d[0] < 0 || d[1] < 0 || d[2] < 0;
      if (any_front && any_back)
        split(w, d, front, back);
      else if (any_back)
        back.push_back(w);
      else
        front.push_back(w);  // in front, or a zero-area sliver lying on the plane
    }
    node.count = int(tree.pieces.size()) - node.first;
    if (!front.empty()) {
      node.front = int(tree.nodes.size());
      tree.nodes.push_back({});
      pending.push_back({node.front, std::move(front)});
    }
    if (!back.empty()) {
      node.back = int(tree.nodes.size());
      tree.nodes.push_back({});
      pending.push_back({node.back, std::move(back)});
    }
    tree.nodes[std::size_t(job.node)] = node;
  }
  return tree;
}

// Descends with a list of subtrees still to look at: a point on a plane looks on both
// sides. Every descent ends where a child is missing, which says inside or outside; a
// point that ends up both inside and outside is on the surface.
Where classify(const BspTree& tree, const Vec3& point) {
  require_finite("classify", "point", point);
  if (tree.nodes.empty()) return Where::outside;
  bool inside = false, outside = false;
  std::vector<int> pending{0};
  while (!pending.empty()) {
    int node = pending.back();
    pending.pop_back();
    for (;;) {
      const BspNode& n = tree.nodes[std::size_t(node)];
      const double side = side_value(tree.triangles[std::size_t(n.plane)], point);
      // A point on a node's plane is sent in front, as if it were off the plane.
      // mutant on_plane_goes_front (step 3, "side = 0", "both subtrees"): `>` -> `>=`
      if (side > 0) {
        if (n.front < 0) {
          outside = true;
          break;
        }
        node = n.front;
      } else if (side < 0) {
        if (n.back < 0) {
          inside = true;
          break;
        }
        node = n.back;
      } else {
        // On the plane: on the surface if on a triangle lying here (the piece is that
        // triangle within this cell, and the point is in the cell); else look both ways.
        for (int k = n.first; k < n.first + n.count; ++k)
          if (in_closed_triangle(tree.triangles[std::size_t(tree.pieces[std::size_t(k)].source)], point))
            return Where::on;
        if (n.front < 0)
          outside = true;
        else
          pending.push_back(n.front);
        if (n.back < 0)
          inside = true;
        else
          pending.push_back(n.back);
        break;
      }
    }
    if (inside && outside) return Where::on;
  }
  return inside ? Where::inside : Where::outside;
}

// ---- Step 4 ------------------------------------------------------------------------------------

// The painter's order with a stack in place of recursion: to draw a node, draw the far
// subtree, then the node's pieces, then the near subtree; pushed in reverse.
std::vector<int> back_to_front(const BspTree& tree, const Vec3& eye) {
  require_finite("back_to_front", "eye", eye);
  std::vector<int> order;
  order.reserve(tree.pieces.size());
  if (tree.nodes.empty()) return order;
  struct Step {
    int node;
    bool draw_pieces;  // false: the whole subtree still to order
  };
  std::vector<Step> stack{{0, false}};
  while (!stack.empty()) {
    const Step step = stack.back();
    stack.pop_back();
    const BspNode& n = tree.nodes[std::size_t(step.node)];
    if (step.draw_pieces) {
      for (int k = n.first; k < n.first + n.count; ++k) order.push_back(k);
      continue;
    }
    // The eye in front: the back subtree is far. Behind: the front one. On the plane:
    // either order works.
    const bool eye_in_front = side_value(tree.triangles[std::size_t(n.plane)], eye) >= 0;
    // The subtree on the eye's side drawn first: front to back, not back to front.
    // mutant near_subtree_first (step 4, "far subtree"):
    //   `const int near = eye_in_front ? n.front : n.back, far = eye_in_front ? n.back : n.front;`
    //   -> `const int near = eye_in_front ? n.back : n.front, far = eye_in_front ? n.front : n.back;`
    const int near = eye_in_front ? n.front : n.back, far = eye_in_front ? n.back : n.front;
    if (near >= 0) stack.push_back({near, false});
    stack.push_back({step.node, true});
    if (far >= 0) stack.push_back({far, false});
  }
  return order;
}

// ---- Step 5 ------------------------------------------------------------------------------------

// A uniform grid (lecture 001). Cut space into cubes whose side is at least the largest
// diameter 2 r_max: two balls that meet have centres at most r_i + r_j <= 2 r_max apart,
// so their cells differ by at most one along each axis. Each ball is then tested only
// against the balls of its own cell and of the 26 around it:
//
//    +---+---+---+
//    | . | . |   |     the ball in the middle cell meets only balls whose centres
//    +---+---+---+     lie in the 3 x 3 (x 3) block around it; the rest of the
//    |   | o | . |     grid is never looked at
//    +---+---+---+
//    | . |   |   |
//    +---+---+---+
//
// Why a grid and not a sort and sweep here: nothing is kept between calls, and at a fixed
// density a sweep along one axis tests every pair whose intervals overlap on that axis,
// about n^(5/3) of them, while the grid's block holds a handful of balls whatever n is
// (step 6 keeps a sweep from frame to frame instead). At most 2^20 cells along an axis,
// so that an index fits in 21 bits however small the balls are next to their spread.
//
// The cells are never stored as an array (most are empty): each ball gets one 64-bit
// key, its (x, y, z) cell indices side by side, and the balls are sorted by key. Then
// the 3 cells of a column (x, y, z - 1 .. z + 1) have consecutive keys, one run of the
// sorted list, and a block is 9 such runs. Each pair is seen from both of its balls and
// kept from the one with the smaller index.
namespace {

constexpr int kCellBits = 21;
constexpr double kMaxCells = double(1 << (kCellBits - 1));  // per axis (a margin for the neighbour at +1)

std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  return (std::uint64_t(x) << (2 * kCellBits)) | (std::uint64_t(y) << kCellBits) | std::uint64_t(z);
}

// Steps 5 and 6 check every sphere of every frame: the message (and its string) is
// built only for the sphere that breaks the rule.
void require_spheres(const char* query, const std::vector<Sphere>& spheres) {
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Sphere& s = spheres[i];
    if (!(s.center.allFinite() && s.radius >= 0 && std::isfinite(s.radius)))
      require_valid(query, "spheres[" + std::to_string(i) + "]", s);
  }
}

}  // namespace

SpherePairs overlapping_pairs(const std::vector<Sphere>& spheres) {
  require_spheres("overlapping_pairs", spheres);
  SpherePairs out;
  if (spheres.empty()) return out;
  Vec3 lo = spheres[0].center, hi = spheres[0].center;
  double r_max = 0;
  for (const Sphere& s : spheres) {
    lo = lo.cwiseMin(s.center);
    hi = hi.cwiseMax(s.center);
    r_max = std::max(r_max, s.radius);
  }
  // The side: the largest diameter, a millionth wider so that rounding in the indices
  // below can never put two centres one diameter apart two cells apart.
  const Vec3 extent = hi - lo;
  // The grid's cells one radius wide instead of one diameter: two balls that meet
  // can sit two cells apart, outside each other's block, and their pair is lost.
  // mutant grid_cells_one_radius (step 5, "missing", "largest diameter"): `2 * r_max * (1 + 1e-6)` -> `r_max`
  double side = std::max(2 * r_max * (1 + 1e-6), extent.maxCoeff() / kMaxCells);
  // One grid cell holds every ball, so every pair is tested: the brute force.
  // Every answer is still right; only the count of tests gives it away.
  // mutant grid_of_one_cell (step 8, "adjacent cells"): `if (!(side > 0)` -> `side = 1e300; if (!(side > 0)`
  if (!(side > 0) || !std::isfinite(side)) side = std::max(1.0, extent.maxCoeff());  // all balls are one point
  const auto index = [&](double value, double low) { return std::int64_t(std::floor((value - low) / side)) + 1; };

  struct Entry {
    std::uint64_t key;
    int sphere;
  };
  std::vector<Entry> entries(spheres.size());
  for (int i = 0; i < int(spheres.size()); ++i) {
    const Vec3& c = spheres[std::size_t(i)].center;  // indices from 1: the column at x - 1 is >= 0
    entries[std::size_t(i)] = {cell_key(index(c.x(), lo.x()), index(c.y(), lo.y()), index(c.z(), lo.z())), i};
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  std::vector<Sphere> sorted(spheres.size());  // the balls in key order: a column's balls side by side in memory
  for (std::size_t k = 0; k < entries.size(); ++k) sorted[k] = spheres[std::size_t(entries[k].sphere)];

  // Cell by cell in key order. The key of the cell (x + dx, y + dy, z + dz) is the key of
  // (x, y, z) plus a fixed offset, so a column's first and end keys grow with the cell's:
  // one pair of cursors per column (dx, dy) only ever moves forward, and the whole pass
  // is linear in n plus the pairs tested.
  std::array<std::uint64_t, 9> low_offset{}, high_offset{};
  for (int column = 0; column < 9; ++column) {
    const std::int64_t dx = column / 3 - 1, dy = column % 3 - 1;
    low_offset[std::size_t(column)] =
        std::uint64_t(dx * (std::int64_t(1) << (2 * kCellBits)) + dy * (std::int64_t(1) << kCellBits) - 1);
    high_offset[std::size_t(column)] = low_offset[std::size_t(column)] + 3;  // past z + 1
  }
  const std::size_t size = entries.size();
  std::array<std::size_t, 9> from{}, to{};
  for (std::size_t run = 0; run < size;) {  // one run of equal keys: one cell
    const std::uint64_t key = entries[run].key;
    std::size_t run_end = run;
    while (run_end < size && entries[run_end].key == key) ++run_end;
    for (std::size_t column = 0; column < 9; ++column) {
      std::size_t& first = from[column];
      std::size_t& end = to[column];
      while (first < size && entries[first].key < key + low_offset[column]) ++first;
      end = std::max(end, first);
      while (end < size && entries[end].key < key + high_offset[column]) ++end;
      for (std::size_t m = run; m < run_end; ++m)
        for (std::size_t other = first; other < end; ++other) {
          const int i = entries[m].sphere, j = entries[other].sphere;
          if (i >= j) continue;  // each pair once: from its smaller index
          ++out.tests;
          // `tests` counts the pairs found, not the pairs tested: the kit counts the calls
          // of given_balls_meet itself, and the two disagree.
          // mutant tests_count_pairs_found (step 5, "given_balls_meet"):
          //   `out.pairs.push_back({i, j});`
          //   -> `out.pairs.push_back({i, j}); else --out.tests;`
          // The balls tested with a formula of its own, not the counted given_balls_meet.
          // mutant balls_tested_privately (step 5, "given_balls_meet"):
          //   `if (given_balls_meet(sorted[m], sorted[other])) out.pairs.push_back({i, j});`
          //   -> `const double reach = sorted[m].radius + sorted[other].radius; if ((sorted[m].center -
          //     sorted[other].center).squaredNorm() <= reach * reach) out.pairs.push_back({i, j});`
          if (given_balls_meet(sorted[m], sorted[other])) out.pairs.push_back({i, j});
        }
    }
    run = run_end;
  }
  std::sort(out.pairs.begin(), out.pairs.end());
  return out;
}

// ---- Step 6 ------------------------------------------------------------------------------------

namespace {

// The list's order: by value, and at equal values a low end before a high end, so that
// intervals that touch come out overlapping (closed balls: touching counts). Two lows or
// two highs at one value keep their order (the sort is stable): no swap, nothing to do.
bool before(const Endpoint& a, const Endpoint& b) {
  // The ends compared without compare_ends, so that no comparison is counted.
  // mutant ends_compared_privately (step 6, "only with compare_ends"):
  //   `compare_ends(a, b`
  //   -> `(a.value > b.value) - (a.value < b.value`
  const int c = compare_ends(a, b);
  // Ends compared strictly: a low end arriving exactly at a high end's value does not
  // pass it, so two balls that come to touch are never paired.
  // mutant sweep_ties_strict (step 6, "touching counts"):
  //   `return c < 0 || (c == 0 && !a.high && b.high);`
  //   -> `return c < 0;`
  return c < 0 || (c == 0 && !a.high && b.high);
}

std::array<int, 2> ordered(int i, int j) { return {std::min(i, j), std::max(i, j)}; }

// The first frame: the ends sorted from scratch, then the pairs overlapping on x by one
// sweep.
void sweep_from_scratch(const std::vector<Sphere>& spheres, std::vector<Endpoint>& ends,
                        std::vector<std::array<int, 2>>& overlapping) {
  ends.clear();
  for (int i = 0; i < int(spheres.size()); ++i) {
    const Sphere& s = spheres[std::size_t(i)];
    ends.push_back({s.center.x() - s.radius, i, false}), ends.push_back({s.center.x() + s.radius, i, true});
  }
  std::sort(ends.begin(), ends.end(), before);
  // Walking the sorted ends, the spheres whose low end is passed and high end is not
  // are open; each low end overlaps every open interval.
  overlapping.clear();
  std::vector<int> open;
  for (const Endpoint& e : ends) {
    if (e.high) {
      open.erase(std::find(open.begin(), open.end(), e.sphere));
    } else {
      for (int other : open) overlapping.push_back(ordered(other, e.sphere));
      open.push_back(e.sphere);
    }
  }
  std::sort(overlapping.begin(), overlapping.end());  // kept sorted from now on (below)
}

// The pairs whose intervals on x began or stopped overlapping, each list sorted.
struct PairChanges {
  std::vector<std::array<int, 2>> added, gone_pairs;
};

PairChanges insertion_sort(std::vector<Endpoint>& ends, SweepFrame& frame) {
  // Insertion sort. Each swap of a low end left past a high end makes their intervals
  // overlap (+1); a high end left past a low end parts them (-1). The changes are noted
  // here and applied to the set by update, in one pass: finding a pair in the set at each
  // swap would cost the whole set per swap.
  std::vector<std::pair<std::array<int, 2>, int>> changes;
  for (std::size_t k = 1; k < ends.size(); ++k)
    for (std::size_t m = k; m > 0 && before(ends[m], ends[m - 1]); --m) {
      const Endpoint& moving = ends[m];
      const Endpoint& passed = ends[m - 1];
      if (moving.sphere != passed.sphere && moving.high != passed.high)
        changes.push_back({ordered(moving.sphere, passed.sphere), moving.high ? -1 : +1});
      std::swap(ends[m], ends[m - 1]);
      ++frame.swaps;
    }
  // A sphere that jumped clear over another in one frame makes both changes to the pair:
  // what counts is their sum.
  std::sort(changes.begin(), changes.end());
  std::vector<std::array<int, 2>> added, gone_pairs;  // both sorted
  for (std::size_t k = 0; k < changes.size();) {
    std::size_t next = k;
    int sum = 0;
    for (; next < changes.size() && changes[next].first == changes[k].first; ++next) sum += changes[next].second;
    if (sum > 0) added.push_back(changes[k].first);
    if (sum < 0) gone_pairs.push_back(changes[k].first);
    k = next;
  }
  return {added, gone_pairs};
}

}  // namespace

// Incremental sort and sweep (lecture 002: O(n) per frame when objects move little).
// The sorted ends are kept; each frame refreshes their values and insertion-sorts them.
// An end moving left past another is one adjacent swap, and the swaps that matter are a
// low end passing a high end (those intervals now overlap) or a high end passing a low
// end (they stop overlapping); two lows or two highs passing change nothing.
//
//   frame k:    A0  A1  B0  B1        A and B apart
//   frame k+1:  A0  B0  A1  B1        B0 slid left past A1: one swap, {A, B} added
//
// The swaps are O(n + changes); the pairs overlapping on x are what costs the most on
// many spheres (each is tested every frame), so the set is touched once per frame, in
// one pass that also tests it, never searched swap by swap.
SweepFrame SweepAndPrune::update(const std::vector<Sphere>& spheres) {
  require_spheres("SweepAndPrune::update", spheres);
  if (started && spheres.size() * 2 != ends.size())
    reject("SweepAndPrune::update", "spheres", "keep the first frame's count, " + std::to_string(ends.size() / 2),
           std::to_string(spheres.size()));
  SweepFrame out;
  for (Endpoint& e : ends) {
    const Sphere& s = spheres[std::size_t(e.sphere)];
    e.value = e.high ? s.center.x() + s.radius : s.center.x() - s.radius;
  }
  // The ends re-sorted from scratch every frame (the list rebuilt in sphere order):
  // right pairs, but n log n or worse comparisons and swaps however little the spheres moved.
  // mutant sweep_resorted_each_frame (step 6, "frame coherence"): `!started` -> `true`
  if (!started) {  // the first frame: a sort from scratch, then the overlaps by one sweep
    started = true;
    sweep_from_scratch(spheres, ends, overlapping);
  }
  const auto [added, gone_pairs] = insertion_sort(ends, out);
  const auto test = [&](const std::array<int, 2>& p) {
    ++out.tests;
    if (given_balls_meet(spheres[std::size_t(p[0])], spheres[std::size_t(p[1])])) out.pairs.push_back(p);
  };
  // The set is kept sorted, so one pass merged with the sorted list of pairs that
  // stopped overlapping on x drops them, and gives the others (only those) the full test.
  std::size_t kept = 0, g = 0;
  for (std::size_t k = 0; k < overlapping.size(); ++k) {
    const std::array<int, 2> p = overlapping[k];
    while (g < gone_pairs.size() && gone_pairs[g] < p) ++g;
    const bool gone = g < gone_pairs.size() && gone_pairs[g] == p;
    // A pair is added when a low end passes a high end but never removed when the
    // high end passes back: pairs apart on x stay in the set and are tested every frame.
    // mutant sweep_pairs_never_removed (step 6, "overlap on x", "swap"): `if (gone) continue` -> `(void)gone`
    if (gone) continue;  // its intervals no longer overlap on x: out of the set
    overlapping[kept++] = p;
    test(p);
  }
  // The new pairs: tested, then merged in from the back end (no second copy of the set).
  for (const std::array<int, 2>& p : added) test(p);
  std::size_t from = kept, next = added.size(), to = kept + added.size();
  overlapping.resize(to);
  while (next > 0)
    overlapping[--to] = from > 0 && overlapping[from - 1] > added[next - 1] ? overlapping[--from] : added[--next];
  std::sort(out.pairs.begin(), out.pairs.end());
  return out;
}

// ---- Step 7 ------------------------------------------------------------------------------------

// Lecture 001's TestBVH, with an explicit stack of node pairs. Boxes apart: nothing below
// them meets. Both leaves: the triangle pairs. Otherwise descend the node that is not a
// leaf, or the larger box (the bigger half of the problem), keeping the other.
TrianglePairs colliding_triangles(const ObbTree& a, const ObbTree& b, bool every) {
  TrianglePairs out;
  if (a.nodes.empty() || b.nodes.empty()) return out;
  const auto volume = [](const ObbNode& n) {
    return n.box.half_extents[0] * n.box.half_extents[1] * n.box.half_extents[2];
  };
  std::vector<std::array<int, 2>> todo{{0, 0}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    const ObbNode& na = a.nodes[std::size_t(i)];
    const ObbNode& nb = b.nodes[std::size_t(j)];
    // Two leaves' triangles tested without testing the leaves' boxes first: the box
    // test only before descending, so leaves whose boxes are apart still test their pairs.
    // mutant bvh_leaf_boxes_untested (step 7, "leaves' boxes overlap"):
    //   `++out.box_tests; if (!given_boxes_overlap(na.box, nb.box)) continue;`
    //   -> `const bool both_leaves = na.left < 0 && nb.left < 0; if (!both_leaves) ++out.box_tests; if (!both_leaves &&
    //     !given_boxes_overlap(na.box, nb.box)) continue;`
    ++out.box_tests;
    if (!given_boxes_overlap(na.box, nb.box)) continue;
    const bool leaf_a = na.left < 0, leaf_b = nb.left < 0;
    // One tree descended only: a leaf of a is tested against b's node as it is, whose
    // triangles lie in leaves below it, so pairs are lost.
    // mutant bvh_one_tree_only (step 7, "both trees", "leaves"): `if (leaf_a && leaf_b) {` -> `if (leaf_a) {`
    if (leaf_a && leaf_b) {
      for (int p = na.first; p < na.first + na.count; ++p)
        for (int q = nb.first; q < nb.first + nb.count; ++q) {
          const int s = a.items[std::size_t(p)], t = b.items[std::size_t(q)];
          ++out.triangle_tests;
          if (given_triangles_meet(a.triangles[std::size_t(s)], b.triangles[std::size_t(t)])) {
            out.pairs.push_back({s, t});
            // mutant bvh_stops_at_first_pair (step 7, "every pair"): `if (!every) return out;` -> `return out;`
            if (!every) return out;
          }
        }
      continue;
    }
    // The smaller box descended first: right pairs, more box tests than the header's
    // traversal.
    // mutant bvh_descends_smaller (step 7, "larger box"): `>=` -> `<=`
    // The traversal stops at the first pair found even when every pair is asked for.
    // mutant bvh_descends_b_at_tie (step 7, "equal volumes"): `>=` -> `>`
    const bool descend_a = leaf_b || (!leaf_a && volume(na) >= volume(nb));
    if (descend_a) {
      todo.push_back({na.right, j}), todo.push_back({na.left, j});
    } else {
      todo.push_back({i, nb.right}), todo.push_back({i, nb.left});
    }
  }
  // A triangle listed in two leaves (the checker's trees never do it) would give a pair twice.
  std::sort(out.pairs.begin(), out.pairs.end());
  out.pairs.erase(std::unique(out.pairs.begin(), out.pairs.end()), out.pairs.end());
  return out;
}

// ---- Step 11 ------------------------------------------------------------------------------------

// Step 5's grid, with its cells kept in a hash table instead of an array. A cell is named
// by its integer coordinates, floor(p / cell) along each axis; only the cells that hold a
// centre are ever stored, so a world of clusters 2^30 apart costs what its balls cost.
//
//    cells (x, y)           bucket = cell_hash(c) % buckets           buckets = 4
//    (0, 0) (1, 0)   ->     bucket 0: [(0, 0) ball 2] [(7, -3) ball 5]   <- two cells, one bucket
//    (7, -3)                bucket 1: [(1, 0) ball 0]
//
// Why nothing is lost: `cell` is a power of two, so p / cell is exact and so is its
// floor; cell >= 2 r_max, so two balls that meet (|c_i - c_j| <= r_i + r_j <= cell) have
// centres at most one cell apart along each axis, and their cells differ by at most one
// there. Looking in the 27 cells around a ball's own finds every ball it can meet.
//
// Why nothing is added: a bucket holds every cell that hashes to it. Each entry carries
// its cell's key, and only entries whose key is the cell looked for are taken. Then an
// entry matches one of the 27 cells at most, and no pair is seen twice from one ball;
// keeping each pair from its smaller index sees it once in all.
namespace {

// p / cell is exact (cell a power of two), and so is its floor; 64 bits hold it.
Cell cell_of(const Vec3& p, double cell) {
  const auto index = [cell](double x) { return static_cast<std::int64_t>(std::floor(x / cell)); };
  return {index(p.x()), index(p.y()), index(p.z())};
}

bool same_cell(const Cell& a, const Cell& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

void require_hash_input(const std::vector<Sphere>& spheres, double cell, int buckets) {
  require_spheres("hashed_pairs", spheres);
  int exponent = 0;
  if (!(cell > 0) || !std::isfinite(cell) || std::frexp(cell, &exponent) != 0.5)
    reject("hashed_pairs", "cell", "be a power of two", text(cell));
  if (buckets < 1 || buckets > (1 << 20)) reject("hashed_pairs", "buckets", "be from 1 to 2^20", text(buckets));
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Sphere& s = spheres[i];
    if (!(2 * s.radius <= cell))
      reject("hashed_pairs", "cell", "be at least every ball's diameter",
             text(cell) + " beside spheres[" + std::to_string(i) + "].radius = " + text(s.radius));
    if (!(s.center.cwiseAbs().maxCoeff() / cell <= 0x1p60))
      reject("hashed_pairs", "spheres[" + std::to_string(i) + "].center / cell", "be at most 2^60 in every coordinate",
             text(s.center));
  }
}

}  // namespace

SpherePairs hashed_pairs(const std::vector<Sphere>& spheres, double cell, int buckets) {
  require_hash_input(spheres, cell, buckets);
  const auto bucket_of = [buckets](const Cell& c) { return std::size_t(cell_hash(c) % std::uint64_t(buckets)); };
  struct Entry {
    Cell key;  // the cell whose ball this is: the bucket holds other cells too
    int sphere;
  };
  std::vector<std::vector<Entry>> table(static_cast<std::size_t>(buckets));
  std::vector<Cell> cells(spheres.size());
  for (int i = 0; i < int(spheres.size()); ++i) {
    cells[std::size_t(i)] = cell_of(spheres[std::size_t(i)].center, cell);
    table[bucket_of(cells[std::size_t(i)])].push_back({cells[std::size_t(i)], i});
  }
  SpherePairs out;
  for (int i = 0; i < int(spheres.size()); ++i) {
    const Cell& own = cells[std::size_t(i)];
    // Only the cells at dx, dy, dz = 0 or +1 looked at: a pair whose other ball lies
    // below or behind, with the larger index, is lost.
    // mutant hash_half_neighbourhood (step 11, "missing", "27 cells"): `dx = -1` -> `dx = 0`
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const Cell want{own.x + dx, own.y + dy, own.z + dz};
          for (const Entry& entry : table[bucket_of(want)]) {
            // A bucket's entries taken whatever their cell: the bucket also holds cells that
            // collide with the one looked for, so balls far apart are tested (and, reached from two
            // of the 27 cells, tested twice).
            // mutant hash_bucket_not_filtered (step 11, "neighbouring cells", "key"):
            //   `if (!same_cell(entry.key, want)) continue;`
            //   -> `(void)want;`
            // Each pair tested from both of its balls: right pairs only after a unique, and
            // twice the tests the hash needs.
            // mutant hash_pairs_from_both_balls (step 11, "once"):
            //   `if (entry.sphere <= i) continue;`
            //   -> `if (entry.sphere == i) continue;`
            if (!same_cell(entry.key, want)) continue;  // another cell that shares this bucket
            if (entry.sphere <= i) continue;            // each pair once: from its smaller index
            ++out.tests;
            if (given_balls_meet(spheres[std::size_t(i)], spheres[std::size_t(entry.sphere)]))
              out.pairs.push_back({i, entry.sphere});
          }
        }
  }
  std::sort(out.pairs.begin(), out.pairs.end());
  return out;
}

// ---- Step 12 ------------------------------------------------------------------------------------

// An octree (lecture 001's adaptive partitioning): a cell is cut in eight at its centre
// only while it holds more than `capacity` balls, so cells stay big where space is empty
// and get small where balls crowd. Two clusters far apart cost two short chains of cuts,
// where a uniform grid as fine as the finest leaf would fill the whole space between.
//
//   child k = x + 2 y + 4 z:       z = 0:  +---+---+      z = 1:  +---+---+
//   bit i of k picks the upper             | 2 | 3 |              | 6 | 7 |
//   half along axis i                      +---+---+              +---+---+
//                                          | 0 | 1 |              | 4 | 5 |
//                                          +---+---+ -> x         +---+---+
//
// A ball goes to every child whose closed cell meets its box, so a query that reaches
// any leaf a ball touches finds it there; the price is that one ball may be listed in
// several leaves, and a query must test it once.
namespace {

Aabb ball_box(const Sphere& s) {
  const Vec3 reach(s.radius, s.radius, s.radius);
  return {s.center - reach, s.center + reach};
}

// Closed boxes: touching faces meet.
bool closed_boxes_meet(const Aabb& a, const Aabb& b) {
  for (int i = 0; i < 3; ++i) {
    // A ball sent only to the children its box overlaps with some width: one that
    // touches a cut goes one way, and the leaf on the other side misses it.
    // mutant octree_touching_one_side (step 12, "every child", "touching"):
    //   `> b.max[i] || b.min[i] >`
    //   -> `>= b.max[i] || b.min[i] >=`
    if (a.min[i] > b.max[i] || b.min[i] > a.max[i]) return false;
  }
  return true;
}

}  // namespace

Octree build_octree(const std::vector<Sphere>& spheres, int capacity, int max_depth) {
  require_spheres("build_octree", spheres);
  if (capacity < 1 || capacity > 64) reject("build_octree", "capacity", "be from 1 to 64", text(capacity));
  if (max_depth < 0 || max_depth > 10) reject("build_octree", "max_depth", "be from 0 to 10", text(max_depth));
  Octree tree;
  tree.spheres = spheres;
  if (spheres.empty()) return tree;
  std::vector<Aabb> boxes;
  Aabb root = ball_box(spheres[0]);
  for (const Sphere& s : spheres) {
    boxes.push_back(ball_box(s));
    root = {root.min.cwiseMin(boxes.back().min), root.max.cwiseMax(boxes.back().max)};
  }
  struct Job {
    int node, depth;
    std::vector<int> balls;  // increasing: filtered from the parent's, in order
  };
  std::vector<int> all(spheres.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  tree.nodes.push_back({root});
  std::vector<Job> todo;
  todo.push_back({0, 0, std::move(all)});
  while (!todo.empty()) {
    Job job = std::move(todo.back());
    todo.pop_back();
    // Few balls (or as deep as allowed): a leaf, however big its cell. This is the rule
    // that makes the tree adapt.
    // A node cut as soon as it holds `capacity` balls, not more: the tree has cuts
    // where the rule keeps a leaf.
    // mutant octree_cuts_at_capacity (step 12, "at most capacity", "adapts"): `<=` -> `<`
    if (int(job.balls.size()) <= capacity || job.depth == max_depth) {
      OctNode& leaf = tree.nodes[std::size_t(job.node)];
      leaf.first = int(tree.items.size());
      leaf.count = int(job.balls.size());
      tree.items.insert(tree.items.end(), job.balls.begin(), job.balls.end());
      continue;
    }
    const Aabb cell = tree.nodes[std::size_t(job.node)].cell;
    const Vec3 mid = 0.5 * (cell.min + cell.max);
    const int first_child = int(tree.nodes.size());
    tree.nodes[std::size_t(job.node)].child = first_child;
    for (int k = 0; k < 8; ++k) {
      Aabb c = cell;
      for (int i = 0; i < 3; ++i) {
        if (k >> i & 1)
          c.min[i] = mid[i];  // the upper half along axis i
        else
          c.max[i] = mid[i];  // the lower half
      }
      tree.nodes.push_back({c});
    }
    for (int k = 0; k < 8; ++k) {
      std::vector<int> inside;
      for (int b : job.balls)
        if (closed_boxes_meet(boxes[std::size_t(b)], tree.nodes[std::size_t(first_child + k)].cell))
          inside.push_back(b);  // touching the cut counts: a ball on it goes both ways
      todo.push_back({first_child + k, job.depth + 1, std::move(inside)});
    }
  }
  return tree;
}

// Down from the root, skipping every subtree whose cell misses the box: its balls lie
// within its cell, so none of them can meet the box. A ball listed in several leaves is
// tested the first time only.
BallsInBox balls_in_box(const Octree& tree, const Aabb& box) {
  require_finite("balls_in_box", "box.min", box.min);
  require_finite("balls_in_box", "box.max", box.max);
  if (!(box.min.array() <= box.max.array()).all())
    reject("balls_in_box", "box.min", "be <= box.max", text(box.min) + " and " + text(box.max));
  BallsInBox out;
  if (tree.nodes.empty()) return out;
  ++out.cell_tests;
  if (!given_cell_meets_box(tree.nodes[0].cell, box)) return out;
  std::vector<char> tested(tree.spheres.size(), 0);
  std::vector<int> todo{0};
  while (!todo.empty()) {
    const OctNode& node = tree.nodes[std::size_t(todo.back())];
    todo.pop_back();
    if (node.child < 0) {
      for (int k = node.first; k < node.first + node.count; ++k) {
        const int ball = tree.items[std::size_t(k)];
        // A ball listed in several leaves the query reaches is tested in each of them.
        // mutant octree_ball_tested_per_leaf (step 12, "once per query"):
        //   `if (tested[std::size_t(ball)]) continue;`
        //   -> `if (tested[std::size_t(ball)] && false) continue;`
        if (tested[std::size_t(ball)]) continue;  // listed in an earlier leaf too: tested there
        tested[std::size_t(ball)] = 1;
        ++out.ball_tests;
        if (given_ball_meets_box(tree.spheres[std::size_t(ball)], box)) out.balls.push_back(ball);
      }
      continue;
    }
    for (int k = 0; k < 8; ++k) {
      // The query descends every child without testing its cell: right balls, but the
      // balls of leaves far from the box are tested too.
      // mutant octree_descends_every_child (step 12, "leaves whose cells meet the box"):
      //   `++out.cell_tests; if (given_cell_meets_box(tree.nodes[std::size_t(node.child + k)].cell, box))
      //     todo.push_back(node.child + k);`
      //   -> `todo.push_back(node.child + k);`
      ++out.cell_tests;
      if (given_cell_meets_box(tree.nodes[std::size_t(node.child + k)].cell, box)) todo.push_back(node.child + k);
    }
  }
  std::sort(out.balls.begin(), out.balls.end());
  return out;
}

}  // namespace labkit::lab06
