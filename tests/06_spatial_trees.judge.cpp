#include "06_spatial_trees.judge.h"

#include "common/generators/generators.h"
#include "common/splitmix.h"
#include "common/oracle/oracle.h"
#include "common/harness/segment_doubt.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

namespace labkit::lab06 {

std::string describe(Where w) { return w == Where::inside ? "inside" : (w == Where::outside ? "outside" : "on"); }

namespace judge {

namespace {

using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;

constexpr double kRelative = 1e-9;  // tol = 1e-9 S (the header's tolerances)
constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <class Input>
double tolerance_of(const Input& in) { return kRelative * check::scale_of_input(in); }

template <class Integer>
std::string str(Integer n) { return std::to_string(n); }

// The triangle's bounding box, corner by corner.
Aabb box_of(const Triangle& t) {
  const Vec3 low = t.v1.cwiseMin(t.v2).cwiseMin(t.v0), high = t.v1.cwiseMax(t.v2).cwiseMax(t.v0);
  return {low, high};
}

bool boxes_meet(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

using Random = SplitMix64;  // the checker's trees and the efficiency segments

// ---- k-d trees: shape, cells, leaves ----------------------------------------------------------

struct LeafCell {
  int node = 0;
  Aabb cell;
};

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
          return name + " lists triangle " + str(i) + ", which does not exist (" + str(tree.triangles.size()) + " triangles)";
        if (!listed.insert(i).second) return name + " lists triangle " + str(i) + " twice";
      }
      leaves.push_back({at.node, at.cell});
      continue;
    }
    if (node.axis < 0 || node.axis > 2) return name + " has axis " + str(node.axis) + " (0, 1, 2, or kLeaf = 3)";
    if (at.depth >= kMaxDepth) return name + " is an interior node at depth " + str(at.depth) + ": deeper than kMaxDepth";
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
// closed cell the segment meets, grown by tol against rounding; with `until`, only the
// leaves it enters by that t.
long long allowed_tests(const KdTree& tree, const std::vector<LeafCell>& leaves, const Segment& s, double tol,
                        double until = kInfinity) {
  const double length = (s.b - s.a).norm();
  const double t_pad = length > 0 ? 4 * tol / length : 0.0;
  long long total = 0;
  for (const LeafCell& leaf : leaves) {
    const auto [t0, t1] = clip(leaf.cell, s, tol);
    if (t0 <= t1 && t0 <= until + t_pad) total += tree.items[std::size_t(tree.nodes[std::size_t(leaf.node)].index)];
  }
  return total;
}

// ---- Segment queries: the exact answer, triangle by triangle -----------------------------------

bool crossing(const SegmentTrianglePair& p) { return oracle::segment_crosses_triangle(p.segment, p.triangle); }

// Could a perturbation of tol change whether the segment crosses this triangle?
bool unstable(const Segment& s, const Triangle& tri, double tol, Rules rules) {
  return rules == Rules::random && check::segment_triangle_in_doubt(s, tri, tol, crossing);
}

struct Status {
  bool hit = false;
  bool unstable = false;
};

std::vector<Status> statuses(const Segment& s, const Mesh& mesh, double tol, Rules rules) {
  std::vector<Status> all(mesh.size());
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle tri = mesh.triangle(i);
    all[i] = {crossing({s, tri}), unstable(s, tri, tol, rules)};
  }
  return all;
}

// How loosely a crossing fixes t: tol / |d_a - d_b| (unit-normal distances of the ends).
double t_tolerance(const Segment& s, const Triangle& tri, double tol) {
  const oracle::PlaneCrossing c = oracle::segment_plane(s, tri);
  const double change = std::abs(c.d_a - c.d_b);
  return change > 0 ? tol / change : kInfinity;
}

// "triangle 3 at t = 0.5, ...": the exact crossings or the answer's hits.
template <class Hit>
std::string describe_hits(const std::vector<Hit>& hits) {
  std::string s;
  for (std::size_t k = 0; k < hits.size() && k < 12; ++k)
    s += (s.empty() ? "" : ", ") + ("triangle " + str(hits[k].triangle) + " at t = " + fmt(hits[k].t));
  if (hits.size() > 12) s += ", ... (" + str(hits.size()) + " in all)";
  return s.empty() ? "no hit" : s;
}

std::string describe_hit(const KdHit& h) { return h.hit ? "triangle " + str(h.triangle) + " at t = " + fmt(h.t) : "no hit"; }

// A reported hit on a triangle: it is that triangle's crossing, as given::segment_triangle
// reports it (point on the segment and the triangle, t and the weights reproduce it).
std::string check_hit(const Segment& s, const Mesh& mesh, const KdHit& h, double tol) {
  if (h.triangle < 0 || std::size_t(h.triangle) >= mesh.size()) return "triangle " + str(h.triangle) + " does not exist";
  const Triangle tri = mesh.triangle(std::size_t(h.triangle));
  if (!h.point.allFinite() || !oracle::within(h.point, tri, tol))
    return "the point " + fmt(h.point) + " is not on triangle " + str(h.triangle) + " (tolerance " + fmt(tol) + ")";
  if (!oracle::within(h.point, s, tol)) return "the point " + fmt(h.point) + " is not on the segment (tolerance " + fmt(tol) + ")";
  if (!oracle::parameter_reproduces(s, h.t, h.point, tol)) return "a + t (b - a) with t = " + fmt(h.t) + " is not the point " + fmt(h.point);
  if (!(std::abs(h.barycentric.sum() - 1) <= kRelative) || !oracle::weights_reproduce(tri, h.barycentric, h.point, tol))
    return "the weights " + fmt(h.barycentric) + " do not describe the point (use given::segment_triangle's)";
  return "";
}

// Where a missed hit was: the first leaf listing the triangle whose closed cell the
// segment meets, which the walk must visit.
std::string missed_in(const KdTree& tree, const Segment& s, int triangle) {
  std::vector<LeafCell> leaves;
  if (!walk_kd_tree(tree, leaves).empty()) return "";
  for (const LeafCell& leaf : leaves) {
    const auto [t0, t1] = clip(leaf.cell, s, 0.0);
    const std::vector<int> l = listed(tree, leaf.node);
    if (t0 <= t1 && std::binary_search(l.begin(), l.end(), triangle))
      return ": leaf " + str(leaf.node) + " lists it, and the segment meets that leaf's cell on t = [" + fmt(t0) + ", " +
             fmt(t1) + "]; the walk must visit every leaf the segment meets";
  }
  return "";
}

// The verdict on "is any triangle hit": the exact answer stands when some hit is not in
// doubt, or when no triangle is in doubt.
Outcome mesh_yes_no(const TreeQuery& in, const KdTree& tree, const std::vector<Status>& all, bool got, Rules rules) {
  bool expected = false, stable_hit = false, doubt = false;
  int first = -1;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Status& st = all[i];
    if (st.hit && (first < 0 || (all[std::size_t(first)].unstable && !st.unstable))) first = int(i);
    expected = expected || st.hit;
    stable_hit = stable_hit || (st.hit && !st.unstable);
    doubt = doubt || st.unstable;
  }
  if (got == expected) return !stable_hit && doubt ? ambiguous() : pass();
  if (!stable_hit && doubt && rules == Rules::random) return ambiguous();
  const std::string clear = rules == Rules::exact ? "" : " (no input within 1e-9 S answers otherwise)";
  if (expected)
    return fail("a hit", "no hit",
                "the segment hits triangle " + str(first) + " by the given test's rule" + clear + missed_in(tree, in.segment, first));
  return fail("no hit", "a hit",
              "by the given test's rule the segment hits no triangle" + clear +
                  " (a segment in a triangle's plane, or of zero length, never hits here)");
}

// The counts: equal to the calls, and within the header's bound.
std::string check_tests(const TreeQuery& in, const KdTree& tree, int reported, std::uint64_t calls, double until) {
  if (std::uint64_t(std::max(reported, 0)) != calls || reported < 0)
    return "`tests` must count every call of given::segment_triangle: you report " + str(reported) + ", it ran " +
           str(std::size_t(calls)) + " times";
  std::vector<LeafCell> leaves;
  if (!walk_kd_tree(tree, leaves).empty()) return "";  // a hand-made tree the example checks itself
  const long long allowed = allowed_tests(tree, leaves, in.segment, tolerance_of(in), until);
  if (reported <= allowed) return "";
  if (until < kInfinity)
    return "first_hit and any_hit may search only the leaves the segment enters no later than the hit they return (t = " +
           fmt(until) + "): those list " + str(allowed) + " triangle(s), you made " + str(reported) +
           " tests (stop once the best hit is at or before the leaf's far end t1)";
  return "a query may search only the leaves whose closed cell the segment meets: those list " + str(allowed) +
         " triangle(s), you made " + str(reported) +
         " tests (the far child is visited only when the segment crosses the plane in the cell: 0 < t_split <= t1)";
}

}  // namespace

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
    return fail(expected, str(got.triangles.size()) + " triangles", "tree.triangles must hold the mesh's " + str(mesh.size()) + " triangles");
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle t = mesh.triangle(i);
    if (got.triangles[i].v0 != t.v0 || got.triangles[i].v1 != t.v1 || got.triangles[i].v2 != t.v2)
      return fail(expected, "tree.triangles[" + str(i) + "] = " + labkit::describe(got.triangles[i]),
                  "tree.triangles[i] must be mesh.triangle(i)");
    if (t.normal() == Vec3::Zero()) continue;
    const Aabb b = box_of(t);
    if (!((b.min.array() >= got.bounds.min.array()).all() && (b.max.array() <= got.bounds.max.array()).all()))
      return fail(expected, "bounds " + labkit::describe(got.bounds), "triangle " + str(i) + " is not inside the bounds");
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
      if (!std::binary_search(l.begin(), l.end(), int(i)))
      {  // only touching the cell's wall: the classic strict comparison
        bool touches = false;
        for (int a = 0; a < 3; ++a) touches = touches || box.max[a] == leaf.cell.min[a] || box.min[a] == leaf.cell.max[a];
        return fail(expected, "leaf " + str(leaf.node) + " without triangle " + str(i),
                    "every triangle that meets a leaf's closed cell, even at one point, is listed in it: triangle " + str(i) +
                        " (" + labkit::describe(t) + ") meets the closed cell of leaf " + str(leaf.node) + " (" +
                        labkit::describe(leaf.cell) + ")" +
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

// ---- Step 2 ------------------------------------------------------------------------------------

Outcome first_hit(const TreeQuery& in, const KdTree& tree, const KdHit& got, std::uint64_t calls, Rules rules) {
  const double tol = tolerance_of(in);
  const std::vector<Status> all = statuses(in.segment, in.mesh, tol, rules);
  const std::vector<oracle::Crossing> hits = oracle::segment_mesh_crossings(in.segment, in.mesh);
  const std::string expected = describe_hits(hits);
  const Outcome decision = mesh_yes_no(in, tree, all, got.hit, rules);
  if (decision.verdict == Outcome::Verdict::fail) return fail(expected, describe_hit(got), decision.why);
  if (got.hit) {
    // A hit on a triangle whose crossing is in doubt (nearly flat, grazed) is not checked
    // for its geometry: there the given test's point may be far off, and any answer passes.
    const bool doubtful = got.triangle >= 0 && std::size_t(got.triangle) < all.size() && all[std::size_t(got.triangle)].unstable;
    const std::string problem = doubtful ? std::string() : check_hit(in.segment, in.mesh, got, tol);
    if (!problem.empty()) return fail(expected, describe_hit(got), problem);
    const Status& st = all[std::size_t(got.triangle)];
    if (!st.hit && !st.unstable) return fail(expected, describe_hit(got), "the segment does not hit triangle " + str(got.triangle));
    // The first hit whose existence is not in doubt bounds t from above.
    const Triangle mine = in.mesh.triangle(std::size_t(got.triangle));
    for (const oracle::Crossing& h : hits) {
      if (all[std::size_t(h.triangle)].unstable) continue;
      const double slack = t_tolerance(in.segment, in.mesh.triangle(std::size_t(h.triangle)), tol) + t_tolerance(in.segment, mine, tol);
      if (got.t > h.t + slack)
        return fail(expected, describe_hit(got),
                    "first_hit returns the smallest t: triangle " + str(h.triangle) + " is hit at t = " + fmt(h.t) +
                        ", before yours; a hit beyond the far end t1 of the leaf that found it is not final (a later "
                        "leaf may hold a nearer one)");
      break;
    }
  }
  const std::string counts = check_tests(in, tree, got.tests, calls, got.hit ? got.t : kInfinity);
  if (!counts.empty()) return fail(expected, describe_hit(got) + ", tests = " + str(got.tests), counts);
  return decision;
}

Outcome any_hit(const TreeQuery& in, const KdTree& tree, const KdHit& got, std::uint64_t calls, Rules rules) {
  const double tol = tolerance_of(in);
  const std::vector<Status> all = statuses(in.segment, in.mesh, tol, rules);
  const Outcome decision = mesh_yes_no(in, tree, all, got.hit, rules);
  const auto expected = [&] { return describe_hits(oracle::segment_mesh_crossings(in.segment, in.mesh)); };
  if (decision.verdict == Outcome::Verdict::fail) return fail(expected(), describe_hit(got), decision.why);
  if (got.hit) {
    const bool doubtful = got.triangle >= 0 && std::size_t(got.triangle) < all.size() && all[std::size_t(got.triangle)].unstable;
    const std::string problem = doubtful ? std::string() : check_hit(in.segment, in.mesh, got, tol);
    if (!problem.empty()) return fail(expected(), describe_hit(got), problem);
    const Status& st = all[std::size_t(got.triangle)];
    if (!st.hit && !st.unstable) return fail(expected(), describe_hit(got), "the segment does not hit triangle " + str(got.triangle));
  }
  const std::string counts = check_tests(in, tree, got.tests, calls, got.hit ? got.t : kInfinity);
  if (!counts.empty()) return fail(expected(), describe_hit(got) + ", tests = " + str(got.tests), counts);
  return decision;
}

Outcome all_hits(const TreeQuery& in, const KdTree& tree, const KdHits& got, std::uint64_t calls, Rules rules) {
  const double tol = tolerance_of(in);
  const std::vector<oracle::Crossing> hits = oracle::segment_mesh_crossings(in.segment, in.mesh);
  const std::string expected = describe_hits(hits), answer = describe_hits(got.hits);
  bool doubt = false;
  std::set<int> reported;
  for (std::size_t k = 0; k < got.hits.size(); ++k) {
    const KdHit& h = got.hits[k];
    if (!h.hit) return fail(expected, answer, "entry " + str(k) + " has hit = false");
    const bool known = h.triangle >= 0 && std::size_t(h.triangle) < in.mesh.size();
    const bool doubtful = known && unstable(in.segment, in.mesh.triangle(std::size_t(h.triangle)), tol, rules);
    const std::string problem = doubtful ? std::string() : check_hit(in.segment, in.mesh, h, tol);
    if (!problem.empty()) return fail(expected, answer, problem);
    if (!reported.insert(h.triangle).second)
      return fail(expected, answer, "all_hits reports each triangle once: triangle " + str(h.triangle) +
                                        " is reported twice (a triangle listed in two leaves is tested in both)");
    const Triangle tri = in.mesh.triangle(std::size_t(h.triangle));
    if (!crossing({in.segment, tri})) {
      if (!unstable(in.segment, tri, tol, rules)) return fail(expected, answer, "the segment does not hit triangle " + str(h.triangle));
      doubt = true;
    }
    if (k + 1 < got.hits.size()) {
      const KdHit& next = got.hits[k + 1];
      const bool ordered = h.t < next.t || (h.t == next.t && h.triangle < next.triangle);
      if (!ordered && next.triangle != h.triangle)  // a repeat is named as such next
        return fail(expected, answer, "all_hits lists its hits sorted by t (ties: lower index first): triangle " +
                                          str(h.triangle) + " at t = " + fmt(h.t) + " comes before triangle " +
                                          str(next.triangle) + " at t = " + fmt(next.t));
    }
  }
  for (const oracle::Crossing& h : hits) {
    if (reported.count(h.triangle)) continue;
    if (unstable(in.segment, in.mesh.triangle(std::size_t(h.triangle)), tol, rules)) {
      doubt = true;
      continue;
    }
    return fail(expected, answer, "all_hits reports every triangle hit: triangle " + str(h.triangle) + " (hit at t = " +
                                      fmt(h.t) + ") is missing" + missed_in(tree, in.segment, h.triangle));
  }
  const std::string counts = check_tests(in, tree, got.tests, calls, kInfinity);
  if (!counts.empty()) return fail(expected, answer + ", tests = " + str(got.tests), counts);
  return doubt ? ambiguous() : pass();
}

// ---- Step 3 ------------------------------------------------------------------------------------

namespace {

// Signed distance of x to the plane of t (unit normal), in doubles: its rounding error is
// some 1e-15 S, far below every tolerance it is compared with.
double plane_distance(const Triangle& t, const Vec3& x) {
  const Vec3 n = t.normal();
  return n.dot(x - t.v0) / n.norm();
}

// Within tol of the closed triangle: of its plane, and inside its three edges' walls.
bool near_triangle(const Triangle& t, const Vec3& x, double tol) {
  const Vec3 n = t.normal();
  if (std::abs(plane_distance(t, x)) > tol) return false;
  for (int i = 0; i < 3; ++i) {
    const Vec3 inward = n.cross(t[(i + 1) % 3] - t[i]);
    if (inward.dot(x - t[i]) < -tol * inward.norm()) return false;
  }
  return true;
}

double longest_edge(const Triangle& t) { return std::max({(t.v1 - t.v0).norm(), (t.v2 - t.v1).norm(), (t.v0 - t.v2).norm()}); }

struct BspShape {
  std::vector<int> owner;                                  // the node of each piece
  std::vector<int> parent;                                 // -1 for the root
  std::vector<std::vector<std::pair<int, int>>> path;      // per node: (ancestor, side +1 front / -1 back)
  std::vector<int> post_order;                             // children before parents
};

std::string walk_bsp(const BspTree& tree, BspShape& shape) {
  const std::size_t n = tree.nodes.size();
  shape.owner.assign(tree.pieces.size(), -1);
  shape.parent.assign(n, -1);
  shape.path.assign(n, {});
  shape.post_order.clear();
  if (n == 0) return "";
  std::vector<char> seen(n, 0);
  std::vector<int> todo{0};
  seen[0] = 1;
  std::vector<int> pre_order;
  while (!todo.empty()) {
    const int at = todo.back();
    todo.pop_back();
    pre_order.push_back(at);
    const BspNode& node = tree.nodes[std::size_t(at)];
    const std::string name = "node " + str(at);
    if (node.plane < 0 || std::size_t(node.plane) >= tree.triangles.size())
      return name + " has plane " + str(node.plane) + ": no such triangle";
    if (oracle::is_degenerate(tree.triangles[std::size_t(node.plane)]))
      return name + " takes its plane from triangle " + str(node.plane) + ", which has zero area";
    if (node.count < 0 || node.first < 0 || std::size_t(node.first) + std::size_t(node.count) > tree.pieces.size())
      return name + " owns pieces " + str(node.first) + " to " + str(node.first + node.count - 1) + ", outside pieces (size " +
             str(tree.pieces.size()) + ")";
    for (int k = node.first; k < node.first + node.count; ++k) {
      if (shape.owner[std::size_t(k)] >= 0) return "piece " + str(k) + " belongs to two nodes";
      shape.owner[std::size_t(k)] = at;
    }
    for (const auto& [child, side] : {std::pair<int, int>{node.front, 1}, std::pair<int, int>{node.back, -1}}) {
      if (child < 0) continue;
      if (std::size_t(child) >= n) return name + " has child " + str(child) + ": no such node";
      if (seen[std::size_t(child)]) return "node " + str(child) + " is reached twice from the root: the nodes do not form a tree";
      seen[std::size_t(child)] = 1;
      shape.parent[std::size_t(child)] = at;
      shape.path[std::size_t(child)] = shape.path[std::size_t(at)];
      shape.path[std::size_t(child)].push_back({at, side});
      todo.push_back(child);
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!seen[i]) return "node " + str(i) + " is never reached from the root";
  for (std::size_t k = 0; k < tree.pieces.size(); ++k)
    if (shape.owner[k] < 0) return "piece " + str(k) + " belongs to no node";
  shape.post_order.assign(pre_order.rbegin(), pre_order.rend());
  return "";
}

std::string check_bsp(const Mesh& mesh, const BspTree& tree, BspShape& shape) {
  if (tree.triangles.size() != mesh.size()) return "tree.triangles must hold the mesh's " + str(mesh.size()) + " triangles";
  bool any_area = false;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle t = mesh.triangle(i);
    if (tree.triangles[i].v0 != t.v0 || tree.triangles[i].v1 != t.v1 || tree.triangles[i].v2 != t.v2)
      return "tree.triangles[" + str(i) + "] is not mesh.triangle(" + str(i) + ")";
    any_area = any_area || !oracle::is_degenerate(t);
  }
  if (!any_area && !(tree.nodes.empty() && tree.pieces.empty()))
    return "the mesh has no triangle of non-zero area: the tree must have no nodes and no pieces";
  if (any_area && tree.nodes.empty()) return "the tree has no nodes";
  const std::string s = walk_bsp(tree, shape);
  if (!s.empty()) return s;
  const double tol = kRelative * std::max(scale_of(mesh), 1e-300);
  std::vector<double> area(mesh.size(), 0.0);
  std::vector<int> count(mesh.size(), 0);
  for (std::size_t k = 0; k < tree.pieces.size(); ++k) {
    const BspPiece& piece = tree.pieces[k];
    const int node = shape.owner[k];
    const std::string name = "piece " + str(k) + " (at node " + str(node) + ")";
    if (piece.source < 0 || std::size_t(piece.source) >= mesh.size()) return name + " comes from triangle " + str(piece.source) + ": no such triangle";
    const Triangle source = mesh.triangle(std::size_t(piece.source));
    if (oracle::is_degenerate(source)) return name + " comes from triangle " + str(piece.source) + ", which has zero area";
    const Triangle plane = mesh.triangle(std::size_t(tree.nodes[std::size_t(node)].plane));
    // In the plane exactly, or within tol of it: the header decides sides in doubles, and
    // rounding may call a triangle a hair off the plane coplanar.
    for (int v = 0; v < 3; ++v)
      if (oracle::orientation(plane.v0, plane.v1, plane.v2, source[v]) != 0 && !(std::abs(plane_distance(plane, source[v])) <= tol))
        return name + ": its triangle " + str(piece.source) + " does not lie in the node's plane (that of triangle " +
               str(tree.nodes[std::size_t(node)].plane) + ")";
    for (int v = 0; v < 3; ++v) {
      const Vec3& x = piece.triangle[v];
      if (!x.allFinite() || !near_triangle(source, x, tol))
        return name + ": its corner " + fmt(x) + " is not on triangle " + str(piece.source) + " (tolerance " + fmt(tol) + ")";
      for (const auto& [ancestor, side] : shape.path[std::size_t(node)]) {
        const Triangle& cut = mesh.triangle(std::size_t(tree.nodes[std::size_t(ancestor)].plane));
        if (side * plane_distance(cut, x) < -tol)
          return name + ": its corner " + fmt(x) + " is " + (side > 0 ? "behind" : "in front of") + " the plane of node " +
                 str(ancestor) + " by " + fmt(std::abs(plane_distance(cut, x))) + ", but the node sent it " +
                 (side > 0 ? "front" : "back");
      }
    }
    const Vec3 n = piece.triangle.normal();
    area[std::size_t(piece.source)] += 0.5 * n.norm();
    ++count[std::size_t(piece.source)];
    if (0.5 * n.norm() > tol * longest_edge(source) && n.dot(source.normal()) < 0)
      return name + " is wound against its triangle " + str(piece.source);
  }
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle t = mesh.triangle(i);
    if (oracle::is_degenerate(t)) continue;
    const double exact = t.area(), slack = tol * longest_edge(t) * (count[i] + 1);
    if (std::abs(area[i] - exact) > slack)
      return "the pieces of triangle " + str(i) + " (" + str(count[i]) + " of them) cover an area of " + fmt(area[i]) +
             ", not its " + fmt(exact);
  }
  return "";
}

}  // namespace

Outcome bsp_tree(const Mesh& mesh, const BspTree& got) {
  BspShape shape;
  const std::string problem = check_bsp(mesh, got, shape);
  if (!problem.empty())
    return fail("a BSP tree of the mesh (the header's rules)", str(got.nodes.size()) + " nodes, " + str(got.pieces.size()) + " pieces", problem);
  return pass();
}

Outcome classify(const PointQuery& in, Where got, Rules rules) {
  const int exact = oracle::point_in_solid(in.point, in.mesh);
  const Where expected = exact > 0 ? Where::inside : (exact < 0 ? Where::outside : Where::on);
  bool doubt = false;
  if (rules == Rules::random) {
    // Within 8 tol of the surface, a perturbation may carry the point across it.
    const double tol = tolerance_of(in);
    const Aabb near{in.point.array() - 8 * tol, in.point.array() + 8 * tol};
    for (std::size_t i = 0; i < in.mesh.size() && !doubt; ++i) {
      const Triangle t = in.mesh.triangle(i);
      doubt = boxes_meet(near, box_of(t)) && oracle::within(in.point, t, 8 * tol);
    }
  }
  if (got == expected) return doubt ? ambiguous() : pass();
  if (doubt) return ambiguous();
  std::string why = "the point is " + (expected == Where::on ? std::string("on the surface") : describe(expected) + " the solid") +
                    " of the closed mesh" +
                    (rules == Rules::exact ? std::string() : " (more than 8 tol from its surface)") + ", not " + describe(got);
  if (expected == Where::on)
    why += ": it lies on a closed triangle of the surface; a point on a node's plane (side = 0) is neither in front nor "
           "behind: test the node's pieces, then classify it in both subtrees";
  else
    why += ": descend strictly in front to the front child, strictly behind to the back child; a missing front child "
           "is outside, a missing back child inside";
  return fail(describe(expected), describe(got), why);
}

Outcome back_to_front(const PointQuery& in, const BspTree& tree, const std::vector<int>& got, Rules rules) {
  BspShape shape;
  const std::string problem = check_bsp(in.mesh, tree, shape);
  if (!problem.empty()) return fail("a valid BSP tree first (step 3)", "an invalid one", problem);
  const std::size_t n = tree.pieces.size();
  if (got.size() != n) return fail("all " + str(n) + " pieces", str(got.size()) + " entries", "list every piece exactly once");
  std::vector<int> position(n, -1);
  for (std::size_t k = 0; k < got.size(); ++k) {
    const int piece = got[k];
    if (piece < 0 || std::size_t(piece) >= n) return fail("piece indices", "entry " + str(piece), "no such piece");
    if (position[std::size_t(piece)] >= 0) return fail("each piece once", "piece " + str(piece) + " twice", "list every piece exactly once");
    position[std::size_t(piece)] = int(k);
  }
  // Per node: the first and last positions of its own pieces, and of its whole subtree.
  const std::size_t nodes = tree.nodes.size();
  struct Range {
    int lo = std::numeric_limits<int>::max(), hi = -1;
    void add(const Range& r) { lo = std::min(lo, r.lo), hi = std::max(hi, r.hi); }
  };
  std::vector<Range> own(nodes), subtree(nodes);
  for (std::size_t k = 0; k < n; ++k) {
    Range& r = own[std::size_t(shape.owner[k])];
    r.lo = std::min(r.lo, position[k]);
    r.hi = std::max(r.hi, position[k]);
  }
  for (int node : shape.post_order) {
    subtree[std::size_t(node)].add(own[std::size_t(node)]);
    for (int child : {tree.nodes[std::size_t(node)].front, tree.nodes[std::size_t(node)].back})
      if (child >= 0) subtree[std::size_t(node)].add(subtree[std::size_t(child)]);
  }
  const double tol = tolerance_of(in);
  bool doubt = false;
  for (std::size_t node = 0; node < nodes; ++node) {
    const BspNode& b = tree.nodes[node];
    const Triangle plane = in.mesh.triangle(std::size_t(b.plane));
    const int side = oracle::orientation(plane.v0, plane.v1, plane.v2, in.point);
    if (side == 0) continue;  // edge on: any order
    const int far = side > 0 ? b.back : b.front, near = side > 0 ? b.front : b.back;
    const Range none;
    const Range& far_range = far >= 0 ? subtree[std::size_t(far)] : none;
    const Range& near_range = near >= 0 ? subtree[std::size_t(near)] : none;
    const Range& mine = own[node];
    std::string why;
    const std::string where = std::string(side > 0 ? "in front of" : "behind") + " the plane of node " + str(node) +
                              " (triangle " + str(b.plane) + ")";
    if (far_range.hi >= 0 && mine.hi >= 0 && far_range.hi > mine.lo)
      why = "the eye is " + where + ", so its far subtree comes before its own pieces; yet a far piece is at position " +
            str(far_range.hi) + " and the node's own at " + str(mine.lo);
    else if (mine.hi >= 0 && near_range.hi >= 0 && mine.hi > near_range.lo)
      why = "the eye is " + where + ", so its own pieces come before its near subtree; yet a near piece is at position " +
            str(near_range.lo) + " and the node's own at " + str(mine.hi);
    else if (far_range.hi >= 0 && near_range.hi >= 0 && far_range.hi > near_range.lo)
      why = "the eye is " + where + ", so its far subtree comes before its near subtree; yet a near piece is at position " +
            str(near_range.lo) + " and a far one at " + str(far_range.hi);
    if (why.empty()) continue;
    if (rules == Rules::random && oracle::side_in_doubt(plane, in.point, tol)) {
      doubt = true;
      continue;
    }
    return fail("far side first at every node", "a near piece before a far one", why);
  }
  return doubt ? ambiguous() : pass();
}

// ---- Step 5 ------------------------------------------------------------------------------------

namespace {

std::string describe_pairs(const std::vector<std::array<int, 2>>& pairs) {
  std::string s;
  for (std::size_t k = 0; k < pairs.size() && k < 16; ++k)
    s += (s.empty() ? "" : ", ") + ("{" + str(pairs[k][0]) + ", " + str(pairs[k][1]) + "}");
  if (pairs.size() > 16) s += ", ... (" + str(pairs.size()) + " in all)";
  return s.empty() ? "no pair" : s;
}

}  // namespace

Outcome overlapping_pairs(const SphereSet& in, const SpherePairs& got, Rules rules) {
  const std::vector<Sphere>& spheres = in.spheres;
  const int n = int(spheres.size());
  const std::vector<std::array<int, 2>> exact = oracle::meeting_pairs(spheres);
  const std::string expected = describe_pairs(exact), answer = describe_pairs(got.pairs);
  for (std::size_t k = 0; k < got.pairs.size(); ++k) {
    const auto& p = got.pairs[k];
    if (p[0] < 0 || p[1] >= n || p[0] >= p[1]) return fail(expected, answer, "{" + str(p[0]) + ", " + str(p[1]) + "} is not a pair i < j of spheres");
    if (k > 0 && !(got.pairs[k - 1] < p)) return fail(expected, answer, "the pairs are not sorted, or a pair is reported twice");
  }
  const long long all = (long long)n * (n - 1) / 2;
  if (got.tests < (long long)got.pairs.size() || got.tests > all)
    return fail(expected, answer + ", tests = " + str(got.tests),
                "tests must count the pairs you tested: at least the " + str(got.pairs.size()) + " you report, at most all " + str(all));
  // Within 6 tol of touching, a perturbation may part them or make them meet: moving the
  // centres by tol changes their distance by up to 2 sqrt(3) tol, the radii by 2 tol.
  const double tol = tolerance_of(in);
  const auto in_doubt = [&](const std::array<int, 2>& p) {
    const Sphere& a = spheres[std::size_t(p[0])];
    const Sphere& b = spheres[std::size_t(p[1])];
    return rules == Rules::random && std::abs((a.center - b.center).norm() - (a.radius + b.radius)) <= 6 * tol;
  };
  const auto gap_of = [&](const std::array<int, 2>& p) {
    const Sphere& a = spheres[std::size_t(p[0])];
    const Sphere& b = spheres[std::size_t(p[1])];
    return (a.center - b.center).norm() - (a.radius + b.radius);
  };
  const auto gap = [&](const std::array<int, 2>& p) { return fmt(gap_of(p)); };
  bool doubt = false;
  std::size_t i = 0, j = 0;
  while (i < exact.size() || j < got.pairs.size()) {
    if (j == got.pairs.size() || (i < exact.size() && exact[i] < got.pairs[j])) {  // missing
      if (!in_doubt(exact[i]))
        return fail(expected, answer,
                    "closed balls meet when |c_i - c_j| <= r_i + r_j: spheres " + str(exact[i][0]) + " and " + str(exact[i][1]) +
                        " have |c_i - c_j| - (r_i + r_j) = " + gap(exact[i]) + ", yet the pair is missing" +
                        (gap_of(exact[i]) == 0 ? " (they touch, and touching counts: compare with <=, never <)" : "") +
                        ". A pair is lost before its test when a sweep stops too early (keep going while low[j] <= "
                        "high[i]) or a grid's cells are narrower than the largest diameter 2 r_max (balls that meet "
                        "then sit two cells apart)");
      doubt = true;
      ++i;
    } else if (i == exact.size() || got.pairs[j] < exact[i]) {  // extra
      if (!in_doubt(got.pairs[j]))
        return fail(expected, answer,
                    "closed balls meet when |c_i - c_j| <= r_i + r_j: spheres " + str(got.pairs[j][0]) + " and " +
                        str(got.pairs[j][1]) + " have |c_i - c_j| - (r_i + r_j) = " + gap(got.pairs[j]) + " > 0: apart");
      doubt = true;
      ++j;
    } else {
      doubt = doubt || in_doubt(exact[i]);
      ++i, ++j;
    }
  }
  return doubt ? ambiguous() : pass();
}

// ---- Step 6 ---------------------------------------------------------------------------------------

namespace {

std::vector<double> end_values(const std::vector<Sphere>& spheres) {
  std::vector<double> v;
  for (const Sphere& s : spheres) v.push_back(s.center.x() - s.radius), v.push_back(s.center.x() + s.radius);
  return v;
}

int sign(double x) { return (x > 0) - (x < 0); }

long long overlapping_on_x(const std::vector<Sphere>& spheres) {
  long long n = 0;
  for (std::size_t i = 0; i < spheres.size(); ++i)
    for (std::size_t j = i + 1; j < spheres.size(); ++j) {
      const double lo_i = spheres[i].center.x() - spheres[i].radius, hi_i = spheres[i].center.x() + spheres[i].radius;
      const double lo_j = spheres[j].center.x() - spheres[j].radius, hi_j = spheres[j].center.x() + spheres[j].radius;
      n += lo_j <= hi_i && lo_i <= hi_j;
    }
  return n;
}

}  // namespace

long long changed_order(const std::vector<Sphere>& before, const std::vector<Sphere>& after) {
  const std::vector<double> a = end_values(before), b = end_values(after);
  long long n = 0;
  for (std::size_t p = 0; p < a.size() && p < b.size(); ++p)
    for (std::size_t q = p + 1; q < a.size() && q < b.size(); ++q) n += sign(a[p] - a[q]) != sign(b[p] - b[q]);
  return n;
}

SweepCase moving_spheres(const MovingSpheres& m) {
  SweepCase c{{gen::spread_spheres(m.count, 100, 0.25, 1, std::uint64_t(m.seed))}};
  for (int k = 1; k < m.frames; ++k) {
    std::vector<Sphere> next = c.frames.back();
    for (std::size_t i = 0; i < next.size(); ++i) next[i].center.x() += 0.05 * std::sin(double(i * 7 + std::size_t(k)));
    c.frames.push_back(next);
  }
  return c;
}

Outcome sweep_frames(const SweepCase& in, const SweepRuns& got, Rules rules) {
  const std::string expected = str(in.frames.size()) + " frames", answer = str(got.size()) + " frames";
  if (got.size() != in.frames.size()) return fail(expected, answer, "update answers once per frame");
  bool doubt = false;
  for (std::size_t k = 0; k < in.frames.size(); ++k) {
    const std::vector<Sphere>& spheres = in.frames[k];
    const SweepFrame& f = got[k].frame;
    const std::string frame = "frame " + str(int(k) + 1) + " of " + str(in.frames.size()) + ": ";
    Outcome right = overlapping_pairs(SphereSet{spheres}, SpherePairs{f.pairs, f.tests}, rules);
    if (right.verdict == Outcome::Verdict::fail) {
      right.why = frame + right.why +
                  (k > 0 ? " (the pairs overlapping on x change only when a low end and a high end swap: add the pair when a low "
                           "end passes a high end, remove it when a high end passes a low end)"
                         : "");
      return right;
    }
    doubt = doubt || right.verdict == Outcome::Verdict::ambiguous;
    const long long on_x = overlapping_on_x(spheres);
    if (f.tests > on_x)
      return fail(str(on_x) + " pairs overlap on x", "tests = " + str(f.tests),
                  frame + "test only the pairs whose intervals overlap on x; a pair leaves the set when a high end passes its "
                          "low end (a swap), and must not be tested after");
    if (k == 0) continue;
    const long long changed = changed_order(in.frames[k - 1], spheres);
    const long long ends = 2 * (long long)spheres.size();
    if (f.swaps > changed)
      return fail("swaps <= " + str(changed) + " (pairs of ends whose order changed)", "swaps = " + str(f.swaps),
                  frame + "frame coherence: insertion sort on the kept list swaps only ends whose order changed since the "
                          "last frame; more swaps mean the list was not kept (or not sorted) from the frame before");
    if (got[k].comparisons > ends + changed)
      return fail("compare_ends calls <= " + str(ends) + " + " + str(changed), "compare_ends calls = " + str(got[k].comparisons),
                  frame + "frame coherence: keep the sorted ends between frames and re-sort by insertion, about one "
                          "comparison per end plus one per swap; sorting from scratch costs n log n however little the "
                          "spheres moved");
  }
  return doubt ? ambiguous() : pass();
}

// ---- Step 7 ---------------------------------------------------------------------------------------

ObbTree obb_tree(const Mesh& mesh, int seed) {
  ObbTree tree;
  for (std::size_t i = 0; i < mesh.size(); ++i) tree.triangles.push_back(mesh.triangle(i));
  std::vector<int> all;
  for (std::size_t i = 0; i < mesh.size(); ++i) all.push_back(int(i));
  if (all.empty()) return tree;
  std::mt19937_64 random(std::uint64_t(seed) * 0x9E3779B97F4A7C15ull + 1);
  const int leaf_size = seed == 0 ? 1 : 1 + int(random() % 4);
  const double s = std::max(scale_of(mesh), 1e-300);
  // The box of some triangles in the axes R: their corners' extents, padded so that
  // rounding never leaves a vertex outside.
  const auto box_of = [&](const std::vector<int>& list, const Mat3& r) {
    Vec3 lo = Vec3::Constant(kInfinity), hi = Vec3::Constant(-kInfinity);
    for (int i : list)
      for (int k = 0; k < 3; ++k) {
        const Vec3 p = r.transpose() * tree.triangles[std::size_t(i)][k];
        lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      }
    Box box;
    box.axes = r;
    box.center = r * (0.5 * (lo + hi));
    box.half_extents = (0.5 * (hi - lo)).array() * (1 + 1e-12) + 1e-12 * s;
    return box;
  };
  const auto rotation = [&] {
    if (seed == 0) return Mat3(Mat3::Identity());
    std::normal_distribution<double> n;
    Eigen::Quaterniond q(n(random), n(random), n(random), n(random));
    q.normalize();
    return Mat3(q.toRotationMatrix());
  };
  const auto build = [&](auto&& self, std::vector<int> list) -> int {
    const int at = int(tree.nodes.size());
    tree.nodes.push_back({});
    const Mat3 r = rotation();
    tree.nodes[std::size_t(at)].box = box_of(list, r);
    if (int(list.size()) <= leaf_size) {
      tree.nodes[std::size_t(at)].first = int(tree.items.size());
      tree.nodes[std::size_t(at)].count = int(list.size());
      tree.items.insert(tree.items.end(), list.begin(), list.end());
      return at;
    }
    int axis = 0;
    tree.nodes[std::size_t(at)].box.half_extents.maxCoeff(&axis);
    const Vec3 u = r.col(axis);
    const auto key = [&](int i) {
      const Triangle& t = tree.triangles[std::size_t(i)];
      return u.dot(t.v0 + t.v1 + t.v2);
    };
    std::sort(list.begin(), list.end(), [&](int x, int y) { return key(x) < key(y) || (key(x) == key(y) && x < y); });
    const std::vector<int> lower(list.begin(), list.begin() + std::ptrdiff_t(list.size() / 2)), upper(list.begin() + std::ptrdiff_t(list.size() / 2), list.end());
    const int left = self(self, lower);
    const int right = self(self, upper);
    tree.nodes[std::size_t(at)].left = left, tree.nodes[std::size_t(at)].right = right;
    return at;
  };
  build(build, all);
  return tree;
}

namespace {

// The header's traversal, counted: what the answer may cost at most.
TrianglePairs header_traversal(const ObbTree& a, const ObbTree& b) {
  TrianglePairs out;
  if (a.nodes.empty() || b.nodes.empty()) return out;
  const auto volume = [](const ObbNode& n) { return n.box.half_extents[0] * n.box.half_extents[1] * n.box.half_extents[2]; };
  std::vector<std::array<int, 2>> todo{{0, 0}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    const ObbNode& na = a.nodes[std::size_t(i)];
    const ObbNode& nb = b.nodes[std::size_t(j)];
    ++out.box_tests;
    if (!given_boxes_overlap(na.box, nb.box)) continue;
    const bool leaf_a = na.left < 0, leaf_b = nb.left < 0;
    if (leaf_a && leaf_b) {
      out.triangle_tests += (long long)na.count * nb.count;
      continue;
    }
    if (leaf_b || (!leaf_a && volume(na) >= volume(nb))) {
      todo.push_back({na.right, j}), todo.push_back({na.left, j});
    } else {
      todo.push_back({i, nb.right}), todo.push_back({i, nb.left});
    }
  }
  return out;
}

bool pair_meets(const Triangle& s, const Triangle& t) {
  for (int k = 0; k < 3; ++k)
    if (oracle::segment_crosses_triangle({s[k], s[(k + 1) % 3]}, t) || oracle::segment_crosses_triangle({t[k], t[(k + 1) % 3]}, s)) return true;
  return false;
}

bool pair_in_doubt(const Triangle& s, const Triangle& t, double tol) {
  for (int k = 0; k < 3; ++k)
    if (oracle::segment_triangle_in_doubt({s[k], s[(k + 1) % 3]}, t, tol) || oracle::segment_triangle_in_doubt({t[k], t[(k + 1) % 3]}, s, tol)) return true;
  return false;
}

}  // namespace

Outcome colliding_triangles(const BvhQuery& in, const ObbTree& a, const ObbTree& b, const BvhRun& got, Rules rules) {
  // The exact brute force: every pair whose bounding boxes touch, decided exactly.
  std::vector<std::array<int, 2>> exact;
  for (std::size_t i = 0; i < in.a.size(); ++i)
    for (std::size_t j = 0; j < in.b.size(); ++j) {
      const Triangle s = in.a.triangle(i), t = in.b.triangle(j);
      if (boxes_meet(box_of(s), box_of(t)) && pair_meets(s, t)) exact.push_back({int(i), int(j)});
    }
  const std::string expected = describe_pairs(exact), answer = describe_pairs(got.answer.pairs);
  const TrianglePairs bound = header_traversal(a, b);
  if (got.box_calls != got.answer.box_tests || got.triangle_calls != got.answer.triangle_tests)
    return fail("box_tests = " + str(got.box_calls) + ", triangle_tests = " + str(got.triangle_calls) + " (the calls counted)",
                "box_tests = " + str(got.answer.box_tests) + ", triangle_tests = " + str(got.answer.triangle_tests),
                "box_tests and triangle_tests count your calls of given_boxes_overlap and given_triangles_meet");
  if (got.answer.box_tests > bound.box_tests)
    return fail("at most " + str(bound.box_tests) + " box tests", "box_tests = " + str(got.answer.box_tests),
                "the dual traversal descends one node at a time, the one that is not a leaf or else the larger box "
                "(by volume; a's at a tie), and stops where the boxes are apart: more box tests than the header's traversal");
  if (got.answer.triangle_tests > bound.triangle_tests)
    return fail("at most " + str(bound.triangle_tests) + " triangle tests", "triangle_tests = " + str(got.answer.triangle_tests),
                "triangles are tested only in pairs of leaves whose boxes overlap, after descending both trees to their leaves");
  const double tol = kRelative * std::max(scale_of(in.a), scale_of(in.b));
  const auto doubt = [&](const std::array<int, 2>& p) {
    return rules == Rules::random && pair_in_doubt(in.a.triangle(std::size_t(p[0])), in.b.triangle(std::size_t(p[1])), tol);
  };
  const int na = int(in.a.size()), nb = int(in.b.size());
  for (std::size_t k = 0; k < got.answer.pairs.size(); ++k) {
    const auto& p = got.answer.pairs[k];
    if (p[0] < 0 || p[0] >= na || p[1] < 0 || p[1] >= nb) return fail(expected, answer, "{" + str(p[0]) + ", " + str(p[1]) + "} is not a pair of triangles of a and b");
    if (k > 0 && !(got.answer.pairs[k - 1] < p)) return fail(expected, answer, "the pairs are not sorted, or a pair is reported twice");
  }
  bool in_doubt = false;
  const auto meets = [&](const std::array<int, 2>& p) { return std::binary_search(exact.begin(), exact.end(), p); };
  for (const auto& p : got.answer.pairs)
    if (!meets(p)) {
      if (!doubt(p))
        return fail(expected, answer, "triangles " + str(p[0]) + " and " + str(p[1]) + " do not meet: no edge of one hits the other");
      in_doubt = true;
    }
  if (in.every) {
    for (const auto& p : exact)
      if (!std::binary_search(got.answer.pairs.begin(), got.answer.pairs.end(), p)) {
        if (!doubt(p))
          return fail(expected, answer,
                      "every pair that meets, when every = true: triangles " + str(p[0]) + " and " + str(p[1]) +
                          " meet, yet the pair is missing (descend both trees until both nodes are leaves, and test all the leaves' pairs; "
                          "stop early only when one pair is asked for)");
        in_doubt = true;
      }
  } else {
    if (got.answer.pairs.size() > 1) return fail("one pair or none", answer, "every = false asks for one pair: stop at the first pair found");
    if (got.answer.pairs.empty() && !exact.empty()) {
      bool all_doubt = true;
      for (const auto& p : exact) all_doubt = all_doubt && doubt(p);
      if (!all_doubt) return fail(expected, answer, "some pair meets, yet none is reported");
      in_doubt = true;
    }
  }
  return in_doubt ? ambiguous() : pass();
}

// ---- Inputs --------------------------------------------------------------------------------------

rc::Gen<TreeQuery> tree_query() {
  return rc::gen::exec([] {
    TreeQuery q;
    q.mesh = *gen::any_mesh();  // lab 02's soups, terrains and octahedra among others
    q.segment = *gen::segment_near(q.mesh);
    q.tree = *rc::gen::inRange(0, 1000000);
    return q;
  });
}

rc::Gen<TreeQuery> exact_tree_query() {
  return rc::gen::exec([] {
    TreeQuery q;
    q.mesh = *gen::exact_mesh();
    q.segment = *gen::exact_segment_near(q.mesh);
    q.tree = *rc::gen::inRange(0, 1000000);
    return q;
  });
}

rc::Gen<Mesh> bsp_mesh() { return gen::any_mesh(); }

rc::Gen<PointQuery> point_query() {
  return rc::gen::exec([] {
    const Mesh m = *gen::closed_mesh();
    return PointQuery{m, *gen::point_near(m, false)};
  });
}

rc::Gen<PointQuery> exact_point_query() {
  return rc::gen::exec([] {
    const Mesh m = *gen::exact_closed_mesh();
    return PointQuery{m, *gen::point_near(m, true)};
  });
}

rc::Gen<PointQuery> eye_query() {
  return rc::gen::exec([] {
    const Mesh m = *gen::any_mesh();
    return PointQuery{m, *gen::point_near(m, false)};
  });
}

rc::Gen<PointQuery> exact_eye_query() {
  return rc::gen::exec([] {
    const Mesh m = *rc::gen::oneOf(gen::exact_mesh(), gen::exact_closed_mesh());
    return PointQuery{m, *gen::point_near(m, true)};
  });
}

rc::Gen<SphereSet> sphere_set() { return rc::gen::map(gen::sphere_set(), [](std::vector<Sphere> s) { return SphereSet{std::move(s)}; }); }
rc::Gen<SphereSet> exact_sphere_set() {
  return rc::gen::map(gen::exact_sphere_set(), [](std::vector<Sphere> s) { return SphereSet{std::move(s)}; });
}

// Step 6: a set of spheres (step 5's kinds), then frames in which every centre moves a
// little: up to a few hundredths of the set's scale, so the order of ends changes in a
// few places per frame. Radii stay.
rc::Gen<SweepCase> sweep_case() {
  return rc::gen::exec([] {
    SweepCase c;
    c.frames.push_back(*gen::sphere_set());
    double s = 0;
    for (const Sphere& b : c.frames[0]) s = std::max({s, b.center.cwiseAbs().maxCoeff(), b.radius});
    if (s == 0) s = 1;
    const int frames = *rc::gen::inRange(2, 7);
    for (int k = 1; k < frames; ++k) {
      std::vector<Sphere> next = c.frames.back();
      for (Sphere& b : next)
        for (int i = 0; i < 3; ++i) b.center[i] += s * *rc::gen::inRange(-1024, 1024) / 32768.0;
      c.frames.push_back(next);
    }
    return c;
  });
}

// Exact: step 5's exact spheres (touching chains on integers), moved by whole units
// of their scale along x and y, so ends meet and pass exactly, and balls come to touch.
rc::Gen<SweepCase> exact_sweep_case() {
  return rc::gen::exec([] {
    SweepCase c;
    c.frames.push_back(*gen::exact_sphere_set());
    double unit = 0;
    for (const Sphere& b : c.frames[0]) unit = std::max(unit, b.radius);
    if (unit == 0) unit = 1;
    const int frames = *rc::gen::inRange(2, 6);
    for (int k = 1; k < frames; ++k) {
      std::vector<Sphere> next = c.frames.back();
      for (Sphere& b : next) b.center.x() += unit * *rc::gen::inRange(-1, 2), b.center.y() += unit * *rc::gen::inRange(-1, 2);
      c.frames.push_back(next);
    }
    return c;
  });
}

// Step 7: two small meshes (soups, spheres, terrains) placed so that they overlap in part,
// the checker's trees over them, every pair or one.
rc::Gen<BvhQuery> bvh_query() {
  return rc::gen::exec([] {
    BvhQuery q;
    const auto small = [] {
      const int kind = *rc::gen::inRange(0, 3);
      const int n = *rc::gen::inRange(1, 40);
      const std::uint64_t seed = std::uint64_t(*rc::gen::inRange(1, 1 << 20));
      if (kind == 0) return gen::soup_mesh(n, seed);
      if (kind == 1) return gen::terrain_mesh(std::max(n, 2), seed);
      return gen::sphere_mesh(std::max(n, 8), Vec3(0.5, 0.5, 0.5), 0.4);
    };
    q.a = small(), q.b = small();
    const double scale = std::pow(2.0, *rc::gen::inRange(-20, 21));
    const Vec3 shift(*rc::gen::inRange(-8, 9) / 16.0, *rc::gen::inRange(-8, 9) / 16.0, *rc::gen::inRange(-8, 9) / 16.0);
    for (Vec3& v : q.a.vertices) v *= scale;
    for (Vec3& v : q.b.vertices) v = (v + shift) * scale;
    q.tree_a = *rc::gen::inRange(0, 100), q.tree_b = *rc::gen::inRange(0, 100);
    q.every = *rc::gen::inRange(0, 4) != 0;
    return q;
  });
}

}  // namespace judge
}  // namespace labkit::lab06
