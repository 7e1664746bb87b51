// Lab 06's k-d trees: the checker's own trees (checker_tree, tree_of), the walk of a tree's
// cells that the segment judges share, and step 1's judge of a built tree; the brute-force
// first hit that the efficiency step measures against. Steps 2 to 7: judge.segments.cpp,
// judge.bsp.cpp, judge.pairs.cpp.
#include "06_spatial_trees/judge_internal.h"

#include "common/splitmix.h"

#include <algorithm>
#include <map>
#include <set>

namespace labkit::lab06 {

std::string describe(Where w) { return w == Where::inside ? "inside" : (w == Where::outside ? "outside" : "on"); }

}  // namespace labkit::lab06

namespace labkit::lab06::judge {

using Random = SplitMix64;  // the checker's trees

// Walks a k-d tree from the root, checking its shape; fills `leaves` with every leaf and
// its cell. Returns what is wrong, or "".
std::string walk_kd_tree(const KdTree& tree, std::vector<LeafCell>& leaves) {
  leaves.clear();
  const std::size_t n = tree.nodes.size();
  if (n == 0) return "the tree has no nodes (even an empty mesh gets one empty leaf)";
  struct Todo {
    int node;
    Aabb cell;
    int depth;
  };
  std::vector<char> seen(n, 0);
  std::vector<Todo> todo{{0, tree.bounds, 0}};
  while (!todo.empty()) {
    const Todo at = todo.back();
    todo.pop_back();
    const std::string name = "node " + str(at.node);
    if (seen[std::size_t(at.node)]) return name + " is reached twice from the root: the nodes do not form a tree";
    seen[std::size_t(at.node)] = 1;
    const KdNode& node = tree.nodes[std::size_t(at.node)];
    if (node.axis == kLeaf) {
      if (node.index < 0 || std::size_t(node.index) >= tree.items.size())
        return name + " is a leaf whose list starts at items[" + str(node.index) + "], outside items (size " +
               str(tree.items.size()) + ")";
      const int count = tree.items[std::size_t(node.index)];
      if (count < 0 || std::size_t(node.index) + std::size_t(count) >= tree.items.size())
        return name + " is a leaf listing " + str(count) + " triangles from items[" + str(node.index) +
               "], past the end of items (size " + str(tree.items.size()) + ")";
      std::set<int> listed;
      for (int k = 1; k <= count; ++k) {
        const int i = tree.items[std::size_t(node.index + k)];
        if (i < 0 || std::size_t(i) >= tree.triangles.size())
          return name + " lists triangle " + str(i) + ", which does not exist (" + str(tree.triangles.size()) +
                 " triangles)";
        if (!listed.insert(i).second) return name + " lists triangle " + str(i) + " twice";
      }
      leaves.push_back({at.node, at.cell});
      continue;
    }
    if (node.axis < 0 || node.axis > 2) return name + " has axis " + str(node.axis) + " (0, 1, 2, or kLeaf = 3)";
    if (at.depth >= kMaxDepth)
      return name + " is an interior node at depth " + str(at.depth) + ": deeper than kMaxDepth";
    const int axis = node.axis;
    if (!(node.split >= at.cell.min[axis] && node.split <= at.cell.max[axis]))
      return name + " splits at " + fmt(node.split) + " on axis " + str(axis) + ", outside its cell [" +
             fmt(at.cell.min[axis]) + ", " + fmt(at.cell.max[axis]) + "]";
    if (std::size_t(at.node) + 1 >= n) return name + " is interior but is the last node: no child below";
    if (node.index <= at.node || std::size_t(node.index) >= n)
      return name + " has its child above at index " + str(node.index) + ", not a later node of the tree";
    Aabb below = at.cell, above = at.cell;
    below.max[axis] = above.min[axis] = node.split;
    todo.push_back({node.index, above, at.depth + 1});
    todo.push_back({at.node + 1, below, at.depth + 1});
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!seen[i]) return "node " + str(i) + " is never reached from the root";
  return "";
}

// The leaf's list, as a sorted vector.
std::vector<int> listed(const KdTree& tree, int leaf) {
  const int first = tree.nodes[std::size_t(leaf)].index;
  std::vector<int> out(tree.items.begin() + first + 1, tree.items.begin() + first + 1 + tree.items[std::size_t(first)]);
  std::sort(out.begin(), out.end());
  return out;
}

// The part of the segment in the closed box grown by `pad`, as [t0, t1]; empty: t0 > t1.
std::pair<double, double> clip(const Aabb& box, const Segment& s, double pad) {
  double t0 = 0, t1 = 1;
  const Vec3 d = s.b - s.a;
  for (int i = 0; i < 3; ++i) {
    const double lo = box.min[i] - pad, hi = box.max[i] + pad;
    if (d[i] == 0) {
      if (s.a[i] < lo || s.a[i] > hi) return {1, 0};
      continue;
    }
    double enter = (lo - s.a[i]) / d[i], leave = (hi - s.a[i]) / d[i];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
  }
  return {t0, t1};
}

// How many tests a query may make (the header's rule): the lists of the leaves whose

// ---- The checker's trees -----------------------------------------------------------------------

KdTree tree_of(const Mesh& mesh, const Aabb& bounds, std::vector<KdNode> nodes, std::vector<int> items) {
  KdTree tree;
  tree.bounds = bounds;
  tree.nodes = std::move(nodes);
  tree.items = std::move(items);
  for (std::size_t i = 0; i < mesh.size(); ++i) tree.triangles.push_back(mesh.triangle(i));
  return tree;
}

KdTree checker_tree(const Mesh& mesh, int seed) {
  KdTree tree = tree_of(mesh, {}, {}, {});
  std::vector<int> all;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Aabb b = box_of(tree.triangles[i]);
    if (i == 0) tree.bounds = b;
    tree.bounds.min = tree.bounds.min.cwiseMin(b.min);
    tree.bounds.max = tree.bounds.max.cwiseMax(b.max);
    all.push_back(int(i));  // zero-area triangles too: listing more is allowed
  }
  Random random{std::uint64_t(seed) * 0x2545f4914f6cdd1dull + 17};
  // Depth first, below before above, as the header lays it out.
  const auto build = [&](auto&& self, const Aabb& cell, const std::vector<int>& list, int depth) -> void {
    const bool leaf = depth >= 10 || list.empty() || random.below(100) < (list.size() <= 2 ? 50 : 12);
    if (leaf) {
      tree.nodes.push_back({0.0, kLeaf, int(tree.items.size())});
      tree.items.push_back(int(list.size()));
      tree.items.insert(tree.items.end(), list.begin(), list.end());
      return;
    }
    const int axis = random.below(3);
    const double lo = cell.min[axis], hi = cell.max[axis];
    double split = lo;
    switch (random.below(5)) {
      case 0:
      case 1: {  // through a vertex of a listed triangle
        const Triangle& t = tree.triangles[std::size_t(list[std::size_t(random.below(int(list.size())))])];
        split = std::clamp(t[random.below(3)][axis], lo, hi);
        break;
      }
      case 2: split = lo + (hi - lo) / 2; break;
      case 3: split = random.below(2) ? lo : hi; break;  // on a wall of the cell: one side is flat
      default: split = std::clamp(lo + (hi - lo) * random.uniform(), lo, hi);
    }
    std::vector<int> below, above;
    for (int i : list) {
      const Aabb b = box_of(tree.triangles[std::size_t(i)]);
      if (b.min[axis] <= split) below.push_back(i);
      if (b.max[axis] >= split) above.push_back(i);
    }
    const std::size_t self_index = tree.nodes.size();
    tree.nodes.push_back({split, axis, 0});
    Aabb below_cell = cell, above_cell = cell;
    below_cell.max[axis] = above_cell.min[axis] = split;
    self(self, below_cell, below, depth + 1);
    tree.nodes[self_index].index = int(tree.nodes.size());
    self(self, above_cell, above, depth + 1);
  };
  build(build, tree.bounds, all, 0);
  return tree;
}

// ---- Step 1 ------------------------------------------------------------------------------------

Outcome kd_tree(const Mesh& mesh, const KdTree& got) {
  const std::string expected = "a valid k-d tree (the header's rule)";
  if (got.triangles.size() != mesh.size())
    return fail(expected, str(got.triangles.size()) + " triangles",
                "tree.triangles must hold the mesh's " + str(mesh.size()) + " triangles");
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle t = mesh.triangle(i);
    if (got.triangles[i].v0 != t.v0 || got.triangles[i].v1 != t.v1 || got.triangles[i].v2 != t.v2)
      return fail(expected, "tree.triangles[" + str(i) + "] = " + labkit::describe(got.triangles[i]),
                  "tree.triangles[i] must be mesh.triangle(i)");
    if (t.normal() == Vec3::Zero()) continue;
    const Aabb b = box_of(t);
    if (!((b.min.array() >= got.bounds.min.array()).all() && (b.max.array() <= got.bounds.max.array()).all()))
      return fail(expected, "bounds " + labkit::describe(got.bounds),
                  "the tree's bounds hold every triangle of the mesh: triangle " + str(i) + " is not inside them");
  }
  std::vector<LeafCell> leaves;
  const std::string shape = walk_kd_tree(got, leaves);
  if (!shape.empty()) return fail(expected, str(got.nodes.size()) + " nodes", shape);
  // Completeness, triangle by triangle: descend from the root into every cell its box
  // meets (the shape is sound: walk_kd_tree said so), and at each leaf whose closed cell
  // the triangle itself meets (exactly), it must be listed. A descent, not every leaf:
  // the efficiency step checks trees of 10,000 triangles and thousands of leaves.
  std::map<int, std::vector<int>> lists;
  for (const LeafCell& leaf : leaves) lists[leaf.node] = listed(got, leaf.node);
  std::vector<LeafCell> reached, todo;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle t = mesh.triangle(i);
    if (oracle::is_degenerate(t)) continue;
    const Aabb box = box_of(t);
    const auto meets = [&](const Aabb& cell) {
      if (!boxes_meet(box, cell)) return false;
      if ((box.min.array() >= cell.min.array()).all() && (box.max.array() <= cell.max.array()).all()) return true;
      return oracle::triangle_meets_box(t, cell);
    };
    reached.clear();
    todo.assign(1, LeafCell{0, got.bounds});
    while (!todo.empty()) {
      const LeafCell at = todo.back();
      todo.pop_back();
      if (!boxes_meet(box, at.cell)) continue;
      const KdNode& node = got.nodes[std::size_t(at.node)];
      if (node.axis == kLeaf) {
        reached.push_back(at);
        continue;
      }
      LeafCell below{at.node + 1, at.cell}, above{node.index, at.cell};
      below.cell.max[node.axis] = above.cell.min[node.axis] = node.split;
      todo.push_back(above);
      todo.push_back(below);
    }
    for (const LeafCell& leaf : reached) {
      if (!meets(leaf.cell)) continue;
      const std::vector<int>& l = lists[leaf.node];
      if (!std::binary_search(l.begin(), l.end(),
                              int(i))) {  // only touching the cell's wall: the classic strict comparison
        bool touches = false;
        for (int a = 0; a < 3; ++a)
          touches = touches || box.max[a] == leaf.cell.min[a] || box.min[a] == leaf.cell.max[a];
        return fail(expected, "leaf " + str(leaf.node) + " without triangle " + str(i),
                    "every triangle that meets a leaf's closed cell, even at one point, is listed in it: triangle " +
                        str(i) + " (" + labkit::describe(t) + ") meets the closed cell of leaf " + str(leaf.node) +
                        " (" + labkit::describe(leaf.cell) + ")" +
                        (touches ? ", touching its wall: a triangle touching the split plane goes to both sides "
                                   "(min[axis] <= split, max[axis] >= split)"
                                 : ""));
      }
    }
  }
  return pass();
}

std::vector<Aabb> triangle_boxes(const std::vector<Triangle>& triangles) {
  std::vector<Aabb> boxes;
  for (const Triangle& t : triangles) boxes.push_back(box_of(t));
  return boxes;
}

KdHit brute_first_hit(const std::vector<Triangle>& triangles, const std::vector<Aabb>& boxes, const Segment& segment) {
  const Aabb reach{segment.a.cwiseMin(segment.b), segment.a.cwiseMax(segment.b)};
  KdHit best;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    if (!boxes_meet(reach, boxes[i])) continue;
    const given::SegmentHit h = given::segment_triangle(segment, triangles[i]);
    if (h.hit && (!best.hit || h.t < best.t)) best = {true, int(i), h.t, h.point, h.barycentric, 0};
  }
  return best;
}

}  // namespace labkit::lab06::judge
