// Lab 06's segment queries on a k-d tree (step 2: first, any and all hits): each answer
// against the exact crossings, and its count of tests against the leaves the walk may visit.
#include "06_spatial_trees/judge_internal.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace labkit::lab06::judge {

namespace {

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

// The listings of the leaves the header's walk visits, all of them (as all_hits walks):
// its near child first, its far child only where the segment crosses the plane inside
// the cell. On exact input every clip and t_split is exact, so this is the one walk the
// header allows, and no query may test more than it lists.
long long walk_listings(const KdTree& tree, const Segment& s) {
  auto [t0, t1] = clip(tree.bounds, s, 0.0);
  if (t0 > t1 || tree.nodes.empty()) return 0;
  const Vec3 d = s.b - s.a;
  struct Part {
    int node;
    double t0, t1;
  };
  std::vector<Part> todo{{0, t0, t1}};
  long long total = 0;
  while (!todo.empty()) {
    const Part p = todo.back();
    todo.pop_back();
    const KdNode& n = tree.nodes[std::size_t(p.node)];
    if (n.axis == kLeaf) {
      total += tree.items[std::size_t(n.index)];
      continue;
    }
    const int axis = n.axis;
    // a's side; from the plane itself the side d goes to, and below when d runs in it.
    const double side = s.a[axis] != n.split ? s.a[axis] - n.split : d[axis];
    const bool below_near = side <= 0;
    const int near = below_near ? p.node + 1 : n.index, far = below_near ? n.index : p.node + 1;
    const double t_split = d[axis] == 0 ? -1 : (n.split - s.a[axis]) / d[axis];
    if (t_split <= 0 || t_split > p.t1) {
      todo.push_back({near, p.t0, p.t1});
    } else if (t_split < p.t0) {
      todo.push_back({far, p.t0, p.t1});
    } else {
      todo.push_back({far, t_split, p.t1});
      todo.push_back({near, p.t0, t_split});
    }
  }
  return total;
}

// ---- Segment queries: the exact answer, triangle by triangle -----------------------------------

bool crossing(const SegmentTrianglePair& p) { return oracle::segment_crosses_triangle(p.segment, p.triangle); }

using judging::Status;

// Could a perturbation of tol change whether the segment crosses this triangle?
bool unstable(const Segment& s, const Triangle& tri, double tol, Rules rules) {
  return judging::unstable(s, tri, tol, rules, crossing);
}

std::vector<Status> statuses(const Segment& s, const Mesh& mesh, double tol, Rules rules) {
  return judging::statuses(s, mesh, tol, rules, crossing);
}

// How loosely a crossing fixes t: tol / |d_a - d_b| (unit-normal distances of the ends).
double t_tolerance(const Segment& s, const Triangle& tri, double tol) {
  const oracle::PlaneCrossing c = oracle::segment_plane(s, tri);
  const double change = std::abs(c.d_a - c.d_b);
  return change > 0 ? tol / change : kInfinity;
}

// How far along the segment a search that returns `got` may have looked: to the hit's t,
// as loosely as the crossing fixes it. A segment nearly in the triangle's plane fixes t
// hardly at all (given::segment_triangle's t may then lie outside every leaf the segment
// enters), and a search that stops there may have searched every leaf.
double search_until(const TreeQuery& in, const KdHit& got, double tol) {
  if (!got.hit) return kInfinity;
  if (got.triangle < 0 || std::size_t(got.triangle) >= in.mesh.size()) return got.t;
  return got.t + t_tolerance(in.segment, in.mesh.triangle(std::size_t(got.triangle)), tol);
}

// "triangle 3 at t = 0.5, ...": the exact crossings or the answer's hits.
template <class Hit> std::string describe_hits(const std::vector<Hit>& hits) {
  std::string s;
  for (std::size_t k = 0; k < hits.size() && k < 12; ++k)
    s += (s.empty() ? "" : ", ") + ("triangle " + str(hits[k].triangle) + " at t = " + fmt(hits[k].t));
  if (hits.size() > 12) s += ", ... (" + str(hits.size()) + " in all)";
  return s.empty() ? "no hit" : s;
}

std::string describe_hit(const KdHit& h) {
  return h.hit ? "triangle " + str(h.triangle) + " at t = " + fmt(h.t) : "no hit";
}

// A reported hit on a triangle: it is that triangle's crossing, as given::segment_triangle
// reports it (point on the segment and the triangle, t and the weights reproduce it).
std::string check_hit(const Segment& s, const Mesh& mesh, const KdHit& h, double tol) {
  if (h.triangle < 0 || std::size_t(h.triangle) >= mesh.size())
    return "a hit names a triangle of the mesh: triangle " + str(h.triangle) + " does not exist";
  const Triangle tri = mesh.triangle(std::size_t(h.triangle));
  if (!h.point.allFinite() || !oracle::within(h.point, tri, tol))
    return "a hit's point is where the segment meets its triangle: " + fmt(h.point) + " is not on triangle " +
           str(h.triangle) + " (tolerance " + fmt(tol) + ")";
  if (!oracle::within(h.point, s, tol))
    return "a hit's point is where the segment meets its triangle: " + fmt(h.point) +
           " is not on the segment (tolerance " + fmt(tol) + ")";
  if (!oracle::parameter_reproduces(s, h.t, h.point, tol))
    return "a hit's t gives its point, a + t (b - a): with t = " + fmt(h.t) + " it is not the point " + fmt(h.point);
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
      return ": leaf " + str(leaf.node) + " lists it, and the segment meets that leaf's cell on t = [" + fmt(t0) +
             ", " + fmt(t1) + "]; the walk must visit every leaf the segment meets";
  }
  return "";
}

// The verdict on "is any triangle hit": the exact answer stands when some hit is not in
// doubt, or when no triangle is in doubt.
Outcome mesh_yes_no(const TreeQuery& in, const KdTree& tree, const std::vector<Status>& all, bool got, Rules rules) {
  const judging::AnyHit any = judging::any_hit(all);
  const bool expected = any.hit;
  int first = -1;  // the hit that decides: the first one not in doubt, else the first one
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].hit && (first < 0 || (all[std::size_t(first)].unstable && !all[i].unstable))) first = int(i);
  if (got == expected) return any.in_doubt() ? ambiguous() : pass();
  if (any.in_doubt() && rules == Rules::random) return ambiguous();
  const std::string clear = rules == Rules::exact ? "" : " (no input within 1e-9 S answers otherwise)";
  if (expected)
    return fail("a hit", "no hit",
                "the segment hits triangle " + str(first) + " by the given test's rule" + clear +
                    missed_in(tree, in.segment, first));
  return fail("no hit", "a hit",
              "by the given test's rule the segment hits no triangle" + clear +
                  " (a segment in a triangle's plane, or of zero length, never hits here)");
}

// The counts: equal to the calls, and within the header's bound (on exact input, within
// its walk's).
std::string check_tests(const TreeQuery& in, const KdTree& tree, int reported, std::uint64_t calls, double until,
                        Rules rules) {
  if (std::uint64_t(std::max(reported, 0)) != calls || reported < 0)
    return "`tests` must count every call of given::segment_triangle: you report " + str(reported) + ", it ran " +
           str(std::size_t(calls)) + " times";
  std::vector<LeafCell> leaves;
  if (!walk_kd_tree(tree, leaves).empty()) return "";  // a hand-made tree the example checks itself
  if (rules == Rules::exact) {
    const long long walked = walk_listings(tree, in.segment);
    if (reported > walked)
      return "the walk visits the near child first (a's side of the plane; from the plane itself, the side d goes "
             "to; below, for a segment lying in the plane) and the far child only where the segment crosses the "
             "plane inside the cell (0 < t_split <= t1): its leaves list " +
             str(walked) + " triangle(s), you made " + str(reported) + " tests";
  }
  const long long allowed = allowed_tests(tree, leaves, in.segment, tolerance_of(in), until);
  if (reported <= allowed) return "";
  if (until < kInfinity)
    return "first_hit and any_hit may search only the leaves the segment enters no later than the hit they return "
           "(by t = " +
           fmt(until) + ", the hit's t and what the crossing leaves in doubt): those list " + str(allowed) +
           " triangle(s), you made " + str(reported) +
           " tests (stop once the best hit is at or before the leaf's far end t1)";
  return "a query may search only the leaves whose closed cell the segment meets: those list " + str(allowed) +
         " triangle(s), you made " + str(reported) +
         " tests (the far child is visited only when the segment crosses the plane in the cell: 0 < t_split <= t1)";
}

}  // namespace

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
    const bool doubtful =
        got.triangle >= 0 && std::size_t(got.triangle) < all.size() && all[std::size_t(got.triangle)].unstable;
    const std::string problem = doubtful ? std::string() : check_hit(in.segment, in.mesh, got, tol);
    if (!problem.empty()) return fail(expected, describe_hit(got), problem);
    const Status& st = all[std::size_t(got.triangle)];
    if (!st.hit && !st.unstable)
      return fail(expected, describe_hit(got), "the segment does not hit triangle " + str(got.triangle));
    // The first hit whose existence is not in doubt bounds t from above.
    const Triangle mine = in.mesh.triangle(std::size_t(got.triangle));
    for (const oracle::Crossing& h : hits) {
      if (all[std::size_t(h.triangle)].unstable) continue;
      const double slack =
          t_tolerance(in.segment, in.mesh.triangle(std::size_t(h.triangle)), tol) + t_tolerance(in.segment, mine, tol);
      if (got.t > h.t + slack)
        return fail(expected, describe_hit(got),
                    "first_hit returns the smallest t: triangle " + str(h.triangle) + " is hit at t = " + fmt(h.t) +
                        ", before yours; a hit beyond the far end t1 of the leaf that found it is not final (a later "
                        "leaf may hold a nearer one)");
      break;
    }
  }
  const std::string counts = check_tests(in, tree, got.tests, calls, search_until(in, got, tol), rules);
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
    const bool doubtful =
        got.triangle >= 0 && std::size_t(got.triangle) < all.size() && all[std::size_t(got.triangle)].unstable;
    const std::string problem = doubtful ? std::string() : check_hit(in.segment, in.mesh, got, tol);
    if (!problem.empty()) return fail(expected(), describe_hit(got), problem);
    const Status& st = all[std::size_t(got.triangle)];
    if (!st.hit && !st.unstable)
      return fail(expected(), describe_hit(got), "the segment does not hit triangle " + str(got.triangle));
  }
  const std::string counts = check_tests(in, tree, got.tests, calls, search_until(in, got, tol), rules);
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
      return fail(expected, answer,
                  "all_hits reports each triangle once: triangle " + str(h.triangle) +
                      " is reported twice (a triangle listed in two leaves is tested in both)");
    const Triangle tri = in.mesh.triangle(std::size_t(h.triangle));
    if (!crossing({in.segment, tri})) {
      if (!unstable(in.segment, tri, tol, rules))
        return fail(expected, answer, "the segment does not hit triangle " + str(h.triangle));
      doubt = true;
    }
    if (k + 1 < got.hits.size()) {
      const KdHit& next = got.hits[k + 1];
      const bool ordered = h.t < next.t || (h.t == next.t && h.triangle < next.triangle);
      if (!ordered && next.triangle != h.triangle)  // a repeat is named as such next
        return fail(expected, answer,
                    "all_hits lists its hits sorted by t (ties: lower index first): triangle " + str(h.triangle) +
                        " at t = " + fmt(h.t) + " comes before triangle " + str(next.triangle) +
                        " at t = " + fmt(next.t));
    }
  }
  for (const oracle::Crossing& h : hits) {
    if (reported.count(h.triangle)) continue;
    if (unstable(in.segment, in.mesh.triangle(std::size_t(h.triangle)), tol, rules)) {
      doubt = true;
      continue;
    }
    return fail(expected, answer,
                "all_hits reports every triangle hit: triangle " + str(h.triangle) + " (hit at t = " + fmt(h.t) +
                    ") is missing" + missed_in(tree, in.segment, h.triangle));
  }
  const std::string counts = check_tests(in, tree, got.tests, calls, kInfinity, rules);
  if (!counts.empty()) return fail(expected, answer + ", tests = " + str(got.tests), counts);
  return doubt ? ambiguous() : pass();
}

}  // namespace labkit::lab06::judge
