// Lab 06's pairs: spheres that overlap (step 5, and step 6 frame by frame with its sort's
// coherence) and triangles that collide between two OBB trees (step 7, the checker's trees
// and the header's traversal as the bound).
#include "06_spatial_trees/judge_internal.h"

#include "common/generators/meshes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

namespace labkit::lab06 {

SweepCase sweep_of(const MovingSpheres& m) {
  SweepCase c{{gen::spread_spheres(m.count, 100, 0.25, 1, std::uint64_t(m.seed))}};
  for (int k = 1; k < m.frames; ++k) {
    std::vector<Sphere> next = c.frames.back();
    for (std::size_t i = 0; i < next.size(); ++i) next[i].center.x() += 0.05 * std::sin(double(i * 7 + std::size_t(k)));
    c.frames.push_back(next);
  }
  return c;
}

}  // namespace labkit::lab06

namespace labkit::lab06::judge {

// ---- Step 5 ------------------------------------------------------------------------------------

Outcome overlapping_pairs(const SphereSet& in, const SpherePairs& got, long long calls, Rules rules) {
  const std::vector<Sphere>& spheres = in.spheres;
  const int n = int(spheres.size());
  const std::vector<std::array<int, 2>> exact = oracle::meeting_pairs(spheres);
  const std::string expected = describe_pairs(exact), answer = describe_pairs(got.pairs);
  for (std::size_t k = 0; k < got.pairs.size(); ++k) {
    const auto& p = got.pairs[k];
    if (p[0] < 0 || p[1] >= n || p[0] >= p[1])
      return fail(expected, answer, "{" + str(p[0]) + ", " + str(p[1]) + "} is not a pair i < j of spheres");
    if (k > 0 && !(got.pairs[k - 1] < p))
      return fail(expected, answer, "the pairs are not sorted, or a pair is reported twice");
  }
  if (got.tests != calls)
    return fail("tests = " + str(calls) + " (your calls of given_balls_meet, as the kit counted them)",
                "tests = " + str(got.tests),
                "tests counts the pairs you tested, each with one call of given_balls_meet");
  if (calls < (long long)got.pairs.size())
    return fail(expected + ", each tested", answer + " after " + str(calls) + " calls of given_balls_meet",
                "a pair is reported only after given_balls_meet said its balls meet: test every pair you report");
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
                    "closed balls meet when |c_i - c_j| <= r_i + r_j: spheres " + str(exact[i][0]) + " and " +
                        str(exact[i][1]) + " have |c_i - c_j| - (r_i + r_j) = " + gap(exact[i]) +
                        ", yet the pair is missing" +
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
                        str(got.pairs[j][1]) + " have |c_i - c_j| - (r_i + r_j) = " + gap(got.pairs[j]) +
                        " > 0: apart");
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

Outcome sweep_frames(const SweepCase& in, const SweepRuns& got, Rules rules) {
  const std::string expected = str(in.frames.size()) + " frames", answer = str(got.size()) + " frames";
  if (got.size() != in.frames.size()) return fail(expected, answer, "update answers once per frame");
  bool doubt = false;
  for (std::size_t k = 0; k < in.frames.size(); ++k) {
    const std::vector<Sphere>& spheres = in.frames[k];
    const SweepFrame& f = got[k].frame;
    const std::string frame = "frame " + str(int(k) + 1) + " of " + str(in.frames.size()) + ": ";
    Outcome right = overlapping_pairs(SphereSet{spheres}, SpherePairs{f.pairs, f.tests}, got[k].ball_tests, rules);
    if (right.verdict == Outcome::Verdict::fail) {
      right.why =
          frame + right.why +
          (k > 0
               ? " (the pairs overlapping on x change only when a low end and a high end swap: add the pair when a low "
                 "end passes a high end, remove it when a high end passes a low end)"
               : "");
      return right;
    }
    doubt = doubt || right.verdict == Outcome::Verdict::ambiguous;
    const long long on_x = overlapping_on_x(spheres);
    if (f.tests > on_x)
      return fail(
          str(on_x) + " pairs overlap on x", "tests = " + str(f.tests),
          frame +
              "test only the pairs whose intervals overlap on x; a pair leaves the set when a high end passes its "
              "low end (a swap), and must not be tested after");
    const long long ends = 2 * (long long)spheres.size();
    // Even a list already in order takes n_ends - 1 comparisons to see that it is.
    if (ends > 1 && got[k].comparisons < ends - 1)
      return fail("compare_ends calls >= " + str(ends - 1), "compare_ends calls = " + str(got[k].comparisons),
                  frame +
                      "compare the ends' values only with compare_ends: the check counts its calls, and keeping "
                      "a list of " +
                      str(ends) + " ends sorted takes at least " + str(ends - 1) + " of them each frame");
    if (k == 0) continue;
    const long long changed = changed_order(in.frames[k - 1], spheres);
    if (f.swaps > changed)
      return fail("swaps <= " + str(changed) + " (pairs of ends whose order changed)", "swaps = " + str(f.swaps),
                  frame +
                      "frame coherence: insertion sort on the kept list swaps only ends whose order changed since the "
                      "last frame; more swaps mean the list was not kept (or not sorted) from the frame before");
    if (got[k].comparisons > ends + changed)
      return fail("compare_ends calls <= " + str(ends) + " + " + str(changed),
                  "compare_ends calls = " + str(got[k].comparisons),
                  frame +
                      "frame coherence: keep the sorted ends between frames and re-sort by insertion, about one "
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
    const std::vector<int> lower(list.begin(), list.begin() + std::ptrdiff_t(list.size() / 2)),
        upper(list.begin() + std::ptrdiff_t(list.size() / 2), list.end());
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
  const ObbWalk walk = header_walk(a, b);
  TrianglePairs out;
  out.box_tests = walk.box_tests;
  for (const auto& [i, j] : walk.leaf_pairs)
    out.triangle_tests += (long long)a.nodes[std::size_t(i)].count * b.nodes[std::size_t(j)].count;
  return out;
}

bool pair_meets(const Triangle& s, const Triangle& t) {
  for (int k = 0; k < 3; ++k)
    if (oracle::segment_crosses_triangle({s[k], s[(k + 1) % 3]}, t) ||
        oracle::segment_crosses_triangle({t[k], t[(k + 1) % 3]}, s))
      return true;
  return false;
}

bool pair_in_doubt(const Triangle& s, const Triangle& t, double tol) {
  for (int k = 0; k < 3; ++k)
    if (oracle::segment_triangle_in_doubt({s[k], s[(k + 1) % 3]}, t, tol) ||
        oracle::segment_triangle_in_doubt({t[k], t[(k + 1) % 3]}, s, tol))
      return true;
  return false;
}

}  // namespace

ObbWalk header_walk(const ObbTree& a, const ObbTree& b, bool a_at_tie) {
  ObbWalk walk;
  if (a.nodes.empty() || b.nodes.empty()) return walk;
  const auto volume = [](const ObbNode& n) {
    return n.box.half_extents[0] * n.box.half_extents[1] * n.box.half_extents[2];
  };
  std::vector<std::array<int, 2>> todo{{0, 0}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    const ObbNode& na = a.nodes[std::size_t(i)];
    const ObbNode& nb = b.nodes[std::size_t(j)];
    ++walk.box_tests;
    if (!given_boxes_overlap(na.box, nb.box)) continue;
    const bool leaf_a = na.left < 0, leaf_b = nb.left < 0;
    if (leaf_a && leaf_b) {
      walk.leaf_pairs.push_back({i, j});
      continue;
    }
    const double va = volume(na), vb = volume(nb);
    if (leaf_b || (!leaf_a && (va > vb || (va == vb && a_at_tie)))) {
      todo.push_back({na.right, j}), todo.push_back({na.left, j});
    } else {
      todo.push_back({i, nb.right}), todo.push_back({i, nb.left});
    }
  }
  return walk;
}

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
    return fail(
        "box_tests = " + str(got.box_calls) + ", triangle_tests = " + str(got.triangle_calls) + " (the calls counted)",
        "box_tests = " + str(got.answer.box_tests) + ", triangle_tests = " + str(got.answer.triangle_tests),
        "box_tests and triangle_tests count your calls of given_boxes_overlap and given_triangles_meet");
  if (got.answer.box_tests > bound.box_tests) {
    std::string why =
        "the dual traversal descends one node at a time, the one that is not a leaf or else the larger box "
        "(by volume; a's at a tie), and stops where the boxes are apart: more box tests than the header's traversal";
    if (got.answer.box_tests == header_walk(a, b, false).box_tests)
      why += "; yours is what descending b's node at equal volumes costs: at a tie, descend a's";
    return fail("at most " + str(bound.box_tests) + " box tests", "box_tests = " + str(got.answer.box_tests), why);
  }
  if (got.answer.triangle_tests > bound.triangle_tests)
    return fail("at most " + str(bound.triangle_tests) + " triangle tests",
                "triangle_tests = " + str(got.answer.triangle_tests),
                "triangles are tested only in pairs of leaves whose boxes overlap, after descending both trees to "
                "their leaves");
  const double tol = kRelative * std::max(scale_of(in.a), scale_of(in.b));
  const auto doubt = [&](const std::array<int, 2>& p) {
    return rules == Rules::random &&
           pair_in_doubt(in.a.triangle(std::size_t(p[0])), in.b.triangle(std::size_t(p[1])), tol);
  };
  const int na = int(in.a.size()), nb = int(in.b.size());
  for (std::size_t k = 0; k < got.answer.pairs.size(); ++k) {
    const auto& p = got.answer.pairs[k];
    if (p[0] < 0 || p[0] >= na || p[1] < 0 || p[1] >= nb)
      return fail(expected, answer, "{" + str(p[0]) + ", " + str(p[1]) + "} is not a pair of triangles of a and b");
    if (k > 0 && !(got.answer.pairs[k - 1] < p))
      return fail(expected, answer, "the pairs are not sorted, or a pair is reported twice");
  }
  bool in_doubt = false;
  const auto meets = [&](const std::array<int, 2>& p) { return std::binary_search(exact.begin(), exact.end(), p); };
  for (const auto& p : got.answer.pairs)
    if (!meets(p)) {
      if (!doubt(p))
        return fail(expected, answer,
                    "triangles " + str(p[0]) + " and " + str(p[1]) + " do not meet: no edge of one hits the other");
      in_doubt = true;
    }
  if (in.every) {
    for (const auto& p : exact)
      if (!std::binary_search(got.answer.pairs.begin(), got.answer.pairs.end(), p)) {
        if (!doubt(p))
          return fail(expected, answer,
                      "every pair that meets, when every = true: triangles " + str(p[0]) + " and " + str(p[1]) +
                          " meet, yet the pair is missing (descend both trees until both nodes are leaves, and test "
                          "all the leaves' pairs; "
                          "stop early only when one pair is asked for)");
        in_doubt = true;
      }
  } else {
    if (got.answer.pairs.size() > 1)
      return fail("one pair or none", answer, "every = false asks for one pair: stop at the first pair found");
    if (got.answer.pairs.empty() && !exact.empty()) {
      bool all_doubt = true;
      for (const auto& p : exact) all_doubt = all_doubt && doubt(p);
      if (!all_doubt) return fail(expected, answer, "some pair meets, yet none is reported");
      in_doubt = true;
    }
  }
  return in_doubt ? ambiguous() : pass();
}

}  // namespace labkit::lab06::judge
