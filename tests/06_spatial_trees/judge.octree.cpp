// Lab 06's step 12: an octree over balls. The build is judged node for node against the
// header's tree (the rule leaves no choice); a box query runs on the checker's tree, its
// balls against the exact brute force, its tests bounded by the header's traversal, which
// the judge runs itself (the calls are counted on the judge's side).
#include "06_spatial_trees/judge_internal.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab06::judge {

namespace {

Aabb ball_box(const Sphere& s) { return {s.center - Vec3::Constant(s.radius), s.center + Vec3::Constant(s.radius)}; }

// The header's tree, and how many balls each node held (a leaf: its list's length).
struct Built {
  Octree tree;
  std::vector<int> held, depth;
};

Built build(const std::vector<Sphere>& spheres, int capacity, int max_depth) {
  Built b;
  b.tree.spheres = spheres;
  if (spheres.empty()) return b;
  Aabb root = ball_box(spheres[0]);
  for (const Sphere& s : spheres) root = {root.min.cwiseMin(ball_box(s).min), root.max.cwiseMax(ball_box(s).max)};
  std::vector<int> all(spheres.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  // Breadth first here (the student's order may differ: the walk below pairs nodes up).
  std::vector<std::vector<int>> balls{all};
  b.tree.nodes.push_back({root});
  b.held.push_back(int(all.size())), b.depth.push_back(0);
  for (std::size_t n = 0; n < b.tree.nodes.size(); ++n) {
    const std::vector<int> mine = balls[n];
    if (int(mine.size()) <= capacity || b.depth[n] == max_depth) {
      b.tree.nodes[n].first = int(b.tree.items.size());
      b.tree.nodes[n].count = int(mine.size());
      b.tree.items.insert(b.tree.items.end(), mine.begin(), mine.end());
      continue;
    }
    const Aabb cell = b.tree.nodes[n].cell;
    const Vec3 mid = 0.5 * (cell.min + cell.max);
    b.tree.nodes[n].child = int(b.tree.nodes.size());
    for (int k = 0; k < 8; ++k) {
      Aabb c = cell;
      for (int i = 0; i < 3; ++i) (k >> i & 1 ? c.min[i] : c.max[i]) = mid[i];
      std::vector<int> inside;
      for (int ball : mine)
        if (boxes_meet(ball_box(spheres[std::size_t(ball)]), c)) inside.push_back(ball);
      b.tree.nodes.push_back({c});
      b.held.push_back(int(inside.size())), b.depth.push_back(b.depth[n] + 1);
      balls.push_back(std::move(inside));
    }
  }
  return b;
}

std::string box_text(const Aabb& b) { return "[" + fmt(b.min) + ", " + fmt(b.max) + "]"; }

std::string list_text(const std::vector<int>& v) {
  std::string s;
  for (std::size_t k = 0; k < v.size() && k < 24; ++k) s += (k ? ", " : "") + str(v[k]);
  if (v.size() > 24) s += ", ... (" + str(v.size()) + " in all)";
  return "{" + s + "}";
}

// The distance from the centre to the closed box, in doubles.
double box_distance(const Sphere& s, const Aabb& box) {
  double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double c = s.center[i], gap = c < box.min[i] ? box.min[i] - c : (c > box.max[i] ? c - box.max[i] : 0.0);
    d2 += gap * gap;
  }
  return std::sqrt(d2);
}

// A leaf's list in the answer against the exact one: the balls whose boxes meet its
// closed cell, each once, in increasing index order.
Outcome leaf_list(const OctreeCase& in, const Octree& want, const OctNode& wn, const Octree& got, const OctNode& gn,
                  const std::string& where, const std::string& expected, const std::string& answer) {
  if (gn.first < 0 || gn.count < 0 || gn.first + gn.count > int(got.items.size()))
    return fail(expected, answer,
                where + "'s list runs past items: first " + str(gn.first) + ", count " + str(gn.count) + ", " +
                    str(got.items.size()) + " items");
  const std::vector<int> list(got.items.begin() + gn.first, got.items.begin() + gn.first + gn.count);
  const std::vector<int> right(want.items.begin() + wn.first, want.items.begin() + wn.first + wn.count);
  if (list == right) return pass();
  for (int ball : right)
    if (std::find(list.begin(), list.end(), ball) == list.end())
      return fail(list_text(right), list_text(list),
                  "a ball goes to every child whose closed cell meets its box (touching counts: a ball on a cut "
                  "goes both ways): ball " +
                      str(ball) + "'s box " + box_text(ball_box(in.spheres[std::size_t(ball)])) + " meets " + where +
                      "'s cell " + box_text(wn.cell) + ", yet the leaf does not list it");
  for (int ball : list)
    if (ball < 0 || ball >= int(in.spheres.size()) || std::find(right.begin(), right.end(), ball) == right.end())
      return fail(list_text(right), list_text(list),
                  ball < 0 || ball >= int(in.spheres.size())
                      ? where + " lists " + str(ball) + ", which is no ball"
                      : "a leaf lists the balls whose boxes meet its cell: ball " + str(ball) + "'s box " +
                            box_text(ball_box(in.spheres[std::size_t(ball)])) + " misses " + where + "'s cell " +
                            box_text(wn.cell));
  return fail(list_text(right), list_text(list), "a leaf lists its balls once each, in increasing index order");
}

}  // namespace

Octree octree_of(const std::vector<Sphere>& spheres, int capacity, int max_depth) {
  return build(spheres, capacity, max_depth).tree;
}

Outcome octree(const OctreeCase& in, const Octree& got) {
  const Built want = build(in.spheres, in.capacity, in.max_depth);
  const Octree& w = want.tree;
  int leaves = 0;
  for (const OctNode& n : w.nodes) leaves += n.child < 0;
  const std::string expected =
      str(w.nodes.size()) + " nodes, " + str(leaves) + " leaves, " + str(w.items.size()) + " listings";
  const std::string answer = str(got.nodes.size()) + " nodes, " + str(got.items.size()) + " items";
  if (got.spheres.size() != in.spheres.size())
    return fail(expected, answer, "the tree keeps the balls as given: spheres[i] is ball i");
  if (w.nodes.empty())
    return got.nodes.empty() ? pass() : fail(expected, answer, "no ball, no node: the tree of no balls is empty");
  if (got.nodes.empty()) return fail(expected, answer, "nodes[0] is the root: a tree of balls has nodes");
  struct Pair {
    int want, got, octant;
  };
  std::vector<Pair> todo{{0, 0, -1}};
  std::size_t visited = 0;
  while (!todo.empty()) {
    const Pair p = todo.back();
    todo.pop_back();
    if (p.got < 0 || p.got >= int(got.nodes.size()))
      return fail(expected, answer, "a child's index names a node: " + str(p.got) + " is out of range");
    if (++visited > got.nodes.size())
      return fail(expected, answer, "each node is some node's child once: the walk from the root comes back");
    const OctNode& wn = w.nodes[std::size_t(p.want)];
    const OctNode& gn = got.nodes[std::size_t(p.got)];
    const int held = want.held[std::size_t(p.want)], depth = want.depth[std::size_t(p.want)];
    const std::string where =
        p.octant < 0 ? "the root" : "node " + str(p.got) + " (child " + str(p.octant) + ", depth " + str(depth) + ")";
    if (!(gn.cell.min == wn.cell.min && gn.cell.max == wn.cell.max))
      return fail(box_text(wn.cell), box_text(gn.cell),
                  p.octant < 0 ? "the root's cell is the tightest box around every ball's box [c - r, c + r]"
                               : where +
                                     "'s cell: child k = x + 2 y + 4 z takes along axis i the lower half "
                                     "[min_i, m_i] when bit i of k is 0, the upper half [m_i, max_i] when it "
                                     "is 1, with m = 0.5 (min + max) of its parent's cell");
    const bool want_leaf = wn.child < 0, got_leaf = gn.child < 0;
    if (want_leaf && !got_leaf)
      return fail(where + " a leaf", where + " cut in 8",
                  depth == in.max_depth
                      ? "a node at max_depth = " + str(in.max_depth) + " is a leaf, however many balls it holds"
                      : "a node holding at most capacity = " + str(in.capacity) + " balls is a leaf (" + where +
                            " holds " + str(held) +
                            "): an octree cuts only where balls crowd, and that is how it adapts to them");
    if (!want_leaf && got_leaf)
      return fail(where + " cut in 8", where + " a leaf",
                  "a node holding more than capacity = " + str(in.capacity) +
                      " balls above max_depth = " + str(in.max_depth) + " is cut in 8 (" + where + " holds " +
                      str(held) + " at depth " + str(depth) + ")");
    if (!want_leaf) {
      if (gn.child < 0 || gn.child + 8 > int(got.nodes.size()))
        return fail(expected, answer, "an interior node's 8 children are nodes[child], ..., nodes[child + 7]");
      for (int k = 7; k >= 0; --k) todo.push_back({wn.child + k, gn.child + k, k});
      continue;
    }
    const Outcome leaf = leaf_list(in, w, wn, got, gn, where, expected, answer);
    if (leaf.verdict == Outcome::Verdict::fail) return leaf;
  }
  return pass();
}

OctreeWalk octree_walk(const Octree& tree, const Aabb& box) {
  OctreeWalk walk;
  if (tree.nodes.empty()) return walk;
  ++walk.cell_tests;
  if (!boxes_meet(tree.nodes[0].cell, box)) return walk;
  std::vector<char> seen(tree.spheres.size(), 0);
  std::vector<int> todo{0};
  while (!todo.empty()) {
    const int at = todo.back();
    todo.pop_back();
    const OctNode& n = tree.nodes[std::size_t(at)];
    if (n.child < 0) {
      walk.leaves.push_back(at);
      for (int k = n.first; k < n.first + n.count; ++k)
        if (!seen[std::size_t(tree.items[std::size_t(k)])])
          seen[std::size_t(tree.items[std::size_t(k)])] = 1, ++walk.ball_tests;
      continue;
    }
    for (int k = 0; k < 8; ++k) {
      ++walk.cell_tests;
      if (boxes_meet(tree.nodes[std::size_t(n.child + k)].cell, box)) todo.push_back(n.child + k);
    }
  }
  return walk;
}

Outcome balls_in_box(const OctreeCase& in, const Octree& tree, const OctreeRun& got, Rules rules) {
  if (in.exact) rules = Rules::exact;
  const std::vector<int> exact = oracle::balls_meeting_box(in.spheres, in.box);
  const std::vector<int>& balls = got.answer.balls;
  const std::string expected = list_text(exact), answer = list_text(balls);
  if (got.answer.cell_tests != got.cell_calls || got.answer.ball_tests != got.ball_calls)
    return fail(
        "cell_tests = " + str(got.cell_calls) + ", ball_tests = " + str(got.ball_calls) + " (the calls counted)",
        "cell_tests = " + str(got.answer.cell_tests) + ", ball_tests = " + str(got.answer.ball_tests),
        "cell_tests and ball_tests count your calls of given_cell_meets_box and given_ball_meets_box");
  const OctreeWalk walk = octree_walk(tree, in.box);
  if (got.cell_calls > walk.cell_tests)
    return fail("at most " + str(walk.cell_tests) + " cell tests", "cell_tests = " + str(got.cell_calls),
                "descend only the children whose cells meet the box: test the root's cell, then the 8 children's "
                "cells of each interior node whose cell meets the box; a subtree whose cell misses the box holds no "
                "ball that meets it");
  if (got.ball_calls > walk.ball_tests)
    return fail("at most " + str(walk.ball_tests) + " ball tests (the distinct balls of the " +
                    str(walk.leaves.size()) + " leaves reached)",
                "ball_tests = " + str(got.ball_calls),
                "test balls only in the leaves whose cells meet the box, and each ball once per query: a ball listed "
                "in several leaves is tested the first time only");
  for (std::size_t k = 0; k < balls.size(); ++k) {
    if (balls[k] < 0 || balls[k] >= int(in.spheres.size()))
      return fail(expected, answer, str(balls[k]) + " is no ball");
    if (k > 0 && balls[k - 1] >= balls[k])
      return fail(expected, answer, "each ball once, sorted: a ball listed in several leaves is reported once");
  }
  if (got.ball_calls < (long long)balls.size())
    return fail(expected + ", each tested", answer + " after " + str(got.ball_calls) + " ball tests",
                "a ball is reported only after given_ball_meets_box said it meets the box: test every ball you report");
  const double tol = tolerance_of(in);
  const auto doubt = [&](int b) {
    const Sphere& s = in.spheres[std::size_t(b)];
    return rules == Rules::random && std::abs(box_distance(s, in.box) - s.radius) <= 6 * tol;
  };
  bool in_doubt = false;
  for (int b : exact)
    if (!std::binary_search(balls.begin(), balls.end(), b)) {
      if (doubt(b)) {
        in_doubt = true;
        continue;
      }
      const Sphere& s = in.spheres[std::size_t(b)];
      return fail(expected, answer,
                  "a ball meets a closed box when the distance from its centre to the box is <= r (touching counts): "
                  "ball " +
                      str(b) + " is at " + fmt(box_distance(s, in.box)) + " with r = " + fmt(s.radius) +
                      ", yet it is missing. Every such ball is listed in a leaf whose closed cell meets the box: "
                      "descend every child whose cell meets it, touching included");
    }
  for (int b : balls)
    if (!std::binary_search(exact.begin(), exact.end(), b)) {
      if (doubt(b)) {
        in_doubt = true;
        continue;
      }
      const Sphere& s = in.spheres[std::size_t(b)];
      return fail(expected, answer,
                  "a ball meets a closed box when the distance from its centre to the box is <= r: ball " + str(b) +
                      " is at " + fmt(box_distance(s, in.box)) + " > r = " + fmt(s.radius) + ": apart");
    }
  return in_doubt ? ambiguous() : pass();
}

}  // namespace labkit::lab06::judge
