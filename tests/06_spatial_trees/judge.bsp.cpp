// Lab 06's BSP trees: step 3 (a tree of the mesh: pieces in their planes and cells, tiling
// their triangles; a point classified against the solid) and step 4 (the painter's order).
#include "06_spatial_trees/judge_internal.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab06::judge {

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

double longest_edge(const Triangle& t) {
  return std::max({(t.v1 - t.v0).norm(), (t.v2 - t.v1).norm(), (t.v0 - t.v2).norm()});
}

struct BspShape {
  std::vector<int> owner;                              // the node of each piece
  std::vector<int> parent;                             // -1 for the root
  std::vector<std::vector<std::pair<int, int>>> path;  // per node: (ancestor, side +1 front / -1 back)
  std::vector<int> post_order;                         // children before parents
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
      return name + " owns pieces " + str(node.first) + " to " + str(node.first + node.count - 1) +
             ", outside pieces (size " + str(tree.pieces.size()) + ")";
    for (int k = node.first; k < node.first + node.count; ++k) {
      if (shape.owner[std::size_t(k)] >= 0) return "piece " + str(k) + " belongs to two nodes";
      shape.owner[std::size_t(k)] = at;
    }
    for (const auto& [child, side] : {std::pair<int, int>{node.front, 1}, std::pair<int, int>{node.back, -1}}) {
      if (child < 0) continue;
      if (std::size_t(child) >= n) return name + " has child " + str(child) + ": no such node";
      if (seen[std::size_t(child)])
        return "node " + str(child) + " is reached twice from the root: the nodes do not form a tree";
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
  if (tree.triangles.size() != mesh.size())
    return "tree.triangles must hold the mesh's " + str(mesh.size()) + " triangles";
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
    if (piece.source < 0 || std::size_t(piece.source) >= mesh.size())
      return name + " comes from triangle " + str(piece.source) + ": no such triangle";
    const Triangle source = mesh.triangle(std::size_t(piece.source));
    if (oracle::is_degenerate(source))
      return name + " comes from triangle " + str(piece.source) + ", which has zero area";
    const Triangle plane = mesh.triangle(std::size_t(tree.nodes[std::size_t(node)].plane));
    // In the plane exactly, or within tol of it: the header decides sides in doubles, and
    // rounding may call a triangle a hair off the plane coplanar.
    for (int v = 0; v < 3; ++v)
      if (oracle::orientation(plane.v0, plane.v1, plane.v2, source[v]) != 0 &&
          !(std::abs(plane_distance(plane, source[v])) <= tol))
        return name + ": its triangle " + str(piece.source) + " does not lie in the node's plane (that of triangle " +
               str(tree.nodes[std::size_t(node)].plane) + ")";
    for (int v = 0; v < 3; ++v) {
      const Vec3& x = piece.triangle[v];
      if (!x.allFinite() || !near_triangle(source, x, tol))
        return name + ": its corner " + fmt(x) + " is not on triangle " + str(piece.source) + " (tolerance " +
               fmt(tol) + ")";
      for (const auto& [ancestor, side] : shape.path[std::size_t(node)]) {
        const Triangle& cut = mesh.triangle(std::size_t(tree.nodes[std::size_t(ancestor)].plane));
        if (side * plane_distance(cut, x) < -tol)
          return name + ": its corner " + fmt(x) + " is " + (side > 0 ? "behind" : "in front of") +
                 " the plane of node " + str(ancestor) + " by " + fmt(std::abs(plane_distance(cut, x))) +
                 ", but the node sent it " + (side > 0 ? "front" : "back");
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
    return fail("a BSP tree of the mesh (the header's rules)",
                str(got.nodes.size()) + " nodes, " + str(got.pieces.size()) + " pieces", problem);
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
  std::string why =
      "the point is " + (expected == Where::on ? std::string("on the surface") : describe(expected) + " the solid") +
      " of the closed mesh" + (rules == Rules::exact ? std::string() : " (more than 8 tol from its surface)") +
      ", not " + describe(got);
  if (expected == Where::on)
    why +=
        ": it lies on a closed triangle of the surface; a point on a node's plane (side = 0) is neither in front nor "
        "behind: test the node's pieces, then classify it in both subtrees";
  else
    why +=
        ": descend strictly in front to the front child, strictly behind to the back child; a missing front child "
        "is outside, a missing back child inside";
  return fail(describe(expected), describe(got), why);
}

Outcome back_to_front(const PointQuery& in, const BspTree& tree, const std::vector<int>& got, Rules rules) {
  BspShape shape;
  const std::string problem = check_bsp(in.mesh, tree, shape);
  if (!problem.empty()) return fail("a valid BSP tree first (step 3)", "an invalid one", problem);
  const std::size_t n = tree.pieces.size();
  if (got.size() != n)
    return fail("all " + str(n) + " pieces", str(got.size()) + " entries", "list every piece exactly once");
  std::vector<int> position(n, -1);
  for (std::size_t k = 0; k < got.size(); ++k) {
    const int piece = got[k];
    if (piece < 0 || std::size_t(piece) >= n) return fail("piece indices", "entry " + str(piece), "no such piece");
    if (position[std::size_t(piece)] >= 0)
      return fail("each piece once", "piece " + str(piece) + " twice", "list every piece exactly once");
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
      why = "the eye is " + where +
            ", so its far subtree comes before its own pieces; yet a far piece is at position " + str(far_range.hi) +
            " and the node's own at " + str(mine.lo);
    else if (mine.hi >= 0 && near_range.hi >= 0 && mine.hi > near_range.lo)
      why = "the eye is " + where +
            ", so its own pieces come before its near subtree; yet a near piece is at position " + str(near_range.lo) +
            " and the node's own at " + str(mine.hi);
    else if (far_range.hi >= 0 && near_range.hi >= 0 && far_range.hi > near_range.lo)
      why = "the eye is " + where +
            ", so its far subtree comes before its near subtree; yet a near piece is at position " +
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

}  // namespace labkit::lab06::judge
