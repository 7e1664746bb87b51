// Inside lab 06's judge: what its files share (tests/06_spatial_trees/judge*.cpp): the
// bounding boxes and the walk of a k-d tree's cells, defined in tests/06_spatial_trees/judge.cpp.
// Not for the tests or the viewer.
#pragma once

#include "06_spatial_trees/judge.h"

#include "judging.h"

#include "common/oracle/oracle.h"

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace labkit::lab06::judge {

using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;
using judging::kRelative;
using judging::tolerance_of;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <class Integer> std::string str(Integer n) { return std::to_string(n); }

// The triangle's bounding box, corner by corner.
// Pairs as a failure shows them: the first 16, "{i, j}" each, and how many in all.
inline std::string describe_pairs(const std::vector<std::array<int, 2>>& pairs) {
  std::string s;
  for (std::size_t k = 0; k < pairs.size() && k < 16; ++k)
    s += (s.empty() ? "" : ", ") + ("{" + str(pairs[k][0]) + ", " + str(pairs[k][1]) + "}");
  if (pairs.size() > 16) s += ", ... (" + str(pairs.size()) + " in all)";
  return s.empty() ? "no pair" : s;
}

inline Aabb box_of(const Triangle& t) {
  const Vec3 low = t.v1.cwiseMin(t.v2).cwiseMin(t.v0), high = t.v1.cwiseMax(t.v2).cwiseMax(t.v0);
  return {low, high};
}

inline bool boxes_meet(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

// ---- k-d trees: shape, cells, leaves ----------------------------------------------------------

struct LeafCell {
  int node = 0;
  Aabb cell;
};

// Walks a k-d tree from the root, checking its shape; fills `leaves` with every leaf and
// its cell. Returns what is wrong, or "".
std::string walk_kd_tree(const KdTree& tree, std::vector<LeafCell>& leaves);
// The leaf's list, as a sorted vector.
std::vector<int> listed(const KdTree& tree, int leaf);
// The part of the segment in the closed box grown by `pad`, as [t0, t1]; empty: t0 > t1.
std::pair<double, double> clip(const Aabb& box, const Segment& s, double pad);

}  // namespace labkit::lab06::judge
