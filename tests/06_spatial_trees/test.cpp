// Lab 06 tests. Each step: the hand-worked examples of handouts/06_spatial_trees.md, then
// random cases against the exact oracle (tests/06_spatial_trees/judge.cpp).
#include "06_spatial_trees/judge.h"
#include "spatial_trees.h"

#include "common/given/segment_triangle.h"
#include "common/oracle/oracle.h"
#include "common/protocol/calls.h"
#include "common/splitmix.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

using namespace labkit;
using namespace labkit::lab06;
using check::Expect;
using check::Outcome;
using judge::Rules;

// The header's input domain (S from 1e-50 to 1e50, or all zeros): each case is drawn in it
// (scaled by a power of two, which keeps it the same case) and shrinking a failing case
// stays in it.
const bool kDomain = [] {
  check::domain({check::Domain::Of::scale, 1e-50, 1e50, true});
  return true;
}();

// What keeps each query's calls finite, in the header's words: a crash or a time-out in
// that query says it first (check::rule).
const bool kRules = [] {
  check::rule(query::build_kd_tree,
              "a tree has at most kMaxDepth = 64 interior nodes on any root-to-leaf path: "
              "stop splitting at a leaf size, or when a split makes no progress");
  check::rule(query::build_kd_tree_lattice, check::rule_of(query::build_kd_tree));
  for (const auto& q : {query::first_hit, query::any_hit, query::all_hits})
    check::rule(q,
                "the walk visits each node at most once: the near child, then the far child only when "
                "0 < t_split <= t1, each with a shorter t-range, never a node twice");
  check::rule(query::build_bsp,
              "each split puts every triangle in front, behind, or in the node's list: "
              "a subtree has fewer triangles than its parent");
  check::rule(query::back_to_front, "each node is visited once: one subtree, the node's triangles, the other subtree");
  check::rule(query::efficiency_segments,
              "a query tests only the triangles listed in the leaves its segment meets, a few dozen here: "
              "one that tests all 10,000 triangles of the mesh cannot answer 250 segments within a call's time limit");
  return true;
}();

namespace {

Mesh mesh_of(const std::vector<Triangle>& triangles) {
  Mesh m;
  for (const Triangle& t : triangles) {
    const int base = int(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {t.v0, t.v1, t.v2});
    m.triangles.push_back({base, base + 1, base + 2});
  }
  return m;
}

// Fails with the first problem of a or b (a first).
Outcome both(const Outcome& a, const Outcome& b) { return a.verdict == Outcome::Verdict::fail ? a : b; }

// Every call below crosses to the answerer, the student's process; the given functions
// the code called meanwhile were served, and counted, here (common/given/served.h).
// served(name) reads the count of the last call, so read it right after that call.
long long served(const char* name) { return remote::last_served().count(name); }

// Step 5: the pairs, judged with the given_balls_meet calls the judge counted.
Outcome judge_pairs(const SphereSet& in, Rules rules = Rules::random) {
  const SpherePairs got = answerer::overlapping_pairs(in.spheres);
  return judge::overlapping_pairs(in, got, served("given_balls_meet"), rules);
}

// Step 6: one SweepAndPrune fed every frame in the answerer; each frame's answer with the
// calls the judge counted while the code answered it (a part each, given::part).
SweepRuns sweep_counted(const Frames& frames) {
  const SweepFrames got = answerer::run_sweep(frames);
  const given::Served& calls = remote::last_served();
  SweepRuns runs;
  for (std::size_t k = 0; k < got.size(); ++k)
    runs.push_back({got[k], calls.count(k, "compare_ends"), calls.count(k, "given_balls_meet")});
  return runs;
}

// Step 7: the dual traversal, with the given tests' calls the judge counted.
BvhRun bvh_counted(const ObbTree& a, const ObbTree& b, bool every) {
  BvhRun run;
  run.answer = answerer::colliding_triangles(a, b, every);
  run.box_calls = served("given_boxes_overlap");
  run.triangle_calls = served("given_triangles_meet");
  return run;
}

// ---- The k-d tree of the handout's step 2 --------------------------------------------------------
//
//   A (triangle 0) leans across x = 4: the segment y = z = 1 meets it at x = 6.
//   B (triangle 1) stands in the plane x = 5.
//   The root splits at x = 4: the leaf below lists A; the leaf above lists A and B.
const Triangle kA{{8, -1, 0}, {8, 3, 0}, {2, 1, 3}};
const Triangle kB{{5, 0, 0}, {5, 3, 0}, {5, 0, 3}};

Mesh lean_and_stand() { return mesh_of({kA, kB}); }

KdTree handout_tree() {
  return judge::tree_of(lean_and_stand(), {{2, -1, 0}, {8, 3, 3}}, {{4, 0, 2}, {0, kLeaf, 0}, {0, kLeaf, 2}},
                        {1, 0, 2, 0, 1});
}

// Runs a query on a tree, counting the given test's calls, and judges it.
template <class Query, class Judge>
Outcome run_query(const TreeQuery& in, const KdTree& tree, Query&& query, Judge&& judge, Rules rules) {
  const auto got = query(tree, in.segment);
  return judge(in, tree, got, std::uint64_t(served("segment_triangle")), rules);
}

Outcome judge_first(const TreeQuery& in, const KdTree& tree, Rules rules = Rules::random) {
  return run_query(in, tree, answerer::first_hit, judge::first_hit, rules);
}
Outcome judge_any(const TreeQuery& in, const KdTree& tree, Rules rules = Rules::random) {
  return run_query(in, tree, answerer::any_hit, judge::any_hit, rules);
}
Outcome judge_all(const TreeQuery& in, const KdTree& tree, Rules rules = Rules::random) {
  return run_query(in, tree, answerer::all_hits, judge::all_hits, rules);
}

// The three queries on the checker's tree of a random case.
Outcome all_three(const TreeQuery& in, Rules rules) {
  const KdTree tree = judge::checker_tree(in.mesh, in.tree);
  return both(judge_first(in, tree, rules), both(judge_any(in, tree, rules), judge_all(in, tree, rules)));
}

}  // namespace

// ---- Step 1 --------------------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L06S1) ": worked examples", "[lab06][step1]") {
  const auto valid = [](const Mesh& m) { return judge::kd_tree(m, answerer::build_kd_tree(m)); };
  check::example(query::build_kd_tree, "the two triangles of step 2", lean_and_stand(), valid);
  // The picture in the header: triangle 7 touches y = 2, the others lie well inside
  // their leaves.
  check::example(
      query::build_kd_tree, "the header's picture",
      mesh_of(
          {{{1, 0, 0}, {3, 0, 0}, {2, 1, 0}}, {{5, 1, 0}, {7, 1, 0}, {6, 3, 0}}, {{1, 2, 0}, {3, 2, 0}, {2, 4, 0}}}),
      valid);
  // Whatever the split rule, the floor of a box lies in some plane z = 0 or touches it.
  check::example(query::build_kd_tree, "a box: faces in the planes of the cells' walls",
                 gen::box_mesh({{0, 0, 0}, {4, 2, 1}}), valid);
  check::example(query::build_kd_tree, "twenty copies of one triangle: no split separates them",
                 mesh_of(std::vector<Triangle>(20, Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})), valid);
  check::example(query::build_kd_tree, "a sphere of 200 triangles", gen::sphere_mesh(200), valid);
  check::example(query::build_kd_tree, "no triangles: one empty leaf", Mesh{}, [](const Mesh& m) {
    const KdTree tree = answerer::build_kd_tree(m);
    Expect e("a tree with no triangles is one empty leaf");
    e.equal("nodes", int(tree.nodes.size()), 1);
    if (tree.nodes.size() == 1) {
      e.equal("axis", tree.nodes[0].axis, kLeaf);
      e.that("items",
             tree.nodes[0].index >= 0 && std::size_t(tree.nodes[0].index) < tree.items.size() &&
                 tree.items[std::size_t(tree.nodes[0].index)] == 0,
             "a list of " + (tree.items.empty() ? std::string("nothing") : std::to_string(tree.items[0])),
             "a count of 0", "the only leaf lists no triangle");
    }
    return e.outcome();
  });
  check::example(query::build_kd_tree, "a zero-area triangle alone", mesh_of({{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}}),
                 valid);
}

TEST_CASE(LABKIT_STEP(L06S1) ": random cases", "[lab06][step1][oracle]") {
  check::random_cases(query::build_kd_tree, gen::any_mesh(),
                      [](const Mesh& m) { return judge::kd_tree(m, answerer::build_kd_tree(m)); });
  // Lattice meshes with faces in the planes the splits use: triangles touch split planes.
  check::random_cases(query::build_kd_tree_lattice, gen::exact_mesh(),
                      [](const Mesh& m) { return judge::kd_tree(m, answerer::build_kd_tree(m)); });
}

// ---- Step 2 --------------------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L06S2) ": worked examples", "[lab06][step2]") {
  const KdTree tree = handout_tree();
  const Mesh mesh = lean_and_stand();
  const auto expect_hit = [tree](int triangle, double t, int max_tests) {
    return [tree, triangle, t, max_tests](const TreeQuery& in) {
      const KdHit got = answerer::first_hit(tree, in.segment);
      Expect e("first_hit walks the leaves the segment meets, near to far, and returns the hit with the smallest t");
      e.equal("hit", got.hit, true);
      e.equal("triangle", got.triangle, triangle);
      e.near("t", got.t, t, 1e-12);
      e.that("tests", got.tests <= max_tests, std::to_string(got.tests), "at most " + std::to_string(max_tests),
             "first_hit searches the leaves front to back from a, the near child first (a's side of the plane, or the "
             "side d goes to when a is on it), and stops once its best hit is at or before the leaf's far end");
      return both(judge_first(in, tree, Rules::exact), e.outcome());
    };
  };
  // A is found first, in the leaf below, at t = 3/4: beyond that leaf's far end t = 1/2.
  // B, in the leaf above, is nearer: t = 5/8.
  check::example(query::first_hit, "a hit beyond the leaf's end does not end the search",
                 TreeQuery{mesh, {{0, 1, 1}, {8, 1, 1}}, 0}, expect_hit(1, 0.625, 3));
  check::example(query::first_hit, "backwards: the leaf above first, A at t = 1/4",
                 TreeQuery{mesh, {{8, 1, 1}, {0, 1, 1}}, 0}, expect_hit(0, 0.25, 2));
  check::example(query::first_hit, "in the split plane x = 4: no t_split, the leaf below",
                 TreeQuery{mesh, {{4, 1, 4}, {4, 1, 0}}, 0}, expect_hit(0, 0.5, 1));
  check::example(query::all_hits, "B then A, A once though listed twice", TreeQuery{mesh, {{0, 1, 1}, {8, 1, 1}}, 0},
                 [tree](const TreeQuery& in) {
    const KdHits got = answerer::all_hits(tree, in.segment);
    Expect e(
        "all_hits lists every triangle the segment meets once, sorted by t, though a triangle may be listed in two "
        "leaves");
    e.equal("count", int(got.hits.size()), 2);
    if (got.hits.size() == 2) {
      e.equal("first", got.hits[0].triangle, 1);
      e.near("first t", got.hits[0].t, 0.625, 1e-12);
      e.equal("second", got.hits[1].triangle, 0);
      e.near("second t", got.hits[1].t, 0.75, 1e-12);
    }
    return both(judge_all(in, tree, Rules::exact), e.outcome());
  });
  check::example(query::any_hit, "A, in the first leaf: one test", TreeQuery{mesh, {{0, 1, 1}, {8, 1, 1}}, 0},
                 [tree](const TreeQuery& in) {
    const KdHit got = answerer::any_hit(tree, in.segment);
    Expect e("any_hit stops at its first hit: it tests only the triangles before it, in the walk's order");
    e.equal("hit", got.hit, true);
    e.equal("triangle", got.triangle, 0);
    e.equal("tests", got.tests, 1);
    return both(judge_any(in, tree, Rules::exact), e.outcome());
  });
  check::example(query::first_hit, "above the bounds: no leaf, no test", TreeQuery{mesh, {{0, 1, 5}, {8, 1, 5}}, 0},
                 [tree](const TreeQuery& in) {
    Expect e("a segment that meets no leaf tests no triangle and hits nothing");
    const KdHit first = answerer::first_hit(tree, in.segment), any = answerer::any_hit(tree, in.segment);
    const KdHits all = answerer::all_hits(tree, in.segment);
    e.equal("first_hit.hit", first.hit, false);
    e.equal("first_hit.tests", first.tests, 0);
    e.equal("any_hit.tests", any.tests, 0);
    e.equal("all_hits.tests", all.tests, 0);
    return e.outcome();
  });
  // The header's walk: t_split <= 0 means the segment moves away from the plane (or
  // starts on it): the near child only, whose leaf lists A alone.
  const auto near_only = [tree](const TreeQuery& in) {
    const KdHit got = answerer::first_hit(tree, in.segment);
    Expect e("the walk visits the near child, and the far child only when 0 < t_split <= t1");
    e.that("tests", got.tests == 1, std::to_string(got.tests), "1 (A, in the leaf below)",
           "t_split <= 0: the segment moves away from the plane x = 4 (or starts on it), so the walk visits the near "
           "child only, never the far one behind a");
    return both(both(judge_first(in, tree, Rules::exact), judge_all(in, tree, Rules::exact)), e.outcome());
  };
  check::example(query::first_hit, "moving away from the split plane: t_split = -1/3, the leaf below only",
                 TreeQuery{mesh, {{3, 1, 1}, {0, 1, 1}}, 0}, near_only);
  check::example(query::first_hit, "starting on the split plane, moving away: t_split = 0, the leaf below only",
                 TreeQuery{mesh, {{4, 1, 1}, {0, 1, 1}}, 0}, near_only);
  // The given test's rule, not lab 02's: a segment in a triangle's plane, or of zero
  // length, never hits it.
  const auto no_hit = [tree](const TreeQuery& in) {
    return both(judge_first(in, tree, Rules::exact),
                both(judge_any(in, tree, Rules::exact), judge_all(in, tree, Rules::exact)));
  };
  check::example(query::first_hit, "lying in B's plane x = 5, across B: no hit (the given test's rule)",
                 TreeQuery{mesh, {{5, 0.5, 0.5}, {5, 2, 0.5}}, 0}, no_hit);
  check::example(query::first_hit, "zero length, on B: no hit (the given test's rule)",
                 TreeQuery{mesh, {{5, 1, 1}, {5, 1, 1}}, 0}, no_hit);
}

TEST_CASE(LABKIT_STEP(L06S2) ": random cases", "[lab06][step2][oracle]") {
  const auto query = [](auto&& judge_one) {
    return [judge_one](const TreeQuery& in) {
      return judge_one(in, judge::checker_tree(in.mesh, in.tree), Rules::random);
    };
  };
  check::random_cases(query::first_hit, gen::tree_query(), query(judge_first));
  check::random_cases(query::any_hit, gen::tree_query(), query(judge_any));
  check::random_cases(query::all_hits, gen::tree_query(), query(judge_all));
}

// ---- Step 3 --------------------------------------------------------------------------------------

namespace {

// The handout's tetrahedron: O X Y Z, faces wound outward.
Mesh tetrahedron() {
  Mesh m;
  m.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// A floor and a wall standing across it: the wall's plane cuts the floor, or the
// floor's plane cuts the wall.
Mesh floor_and_wall() { return mesh_of({{{0, 0, 0}, {8, 0, 0}, {0, 8, 0}}, {{2, 0, -2}, {2, 0, 2}, {2, 4, 0}}}); }

auto expect_where(Where where) {
  return [where](const PointQuery& in) {
    const BspTree tree = answerer::build_bsp(in.mesh);
    const Outcome valid = judge::bsp_tree(in.mesh, tree);
    if (valid.verdict == Outcome::Verdict::fail) return valid;
    const Where got = answerer::classify(tree, in.point);
    if (got != where) return judge::classify(in, got, Rules::exact);
    Expect e("classify follows the point down the tree by its side of each plane");
    e.equal("where", got, where);  // the handout's answer, which the oracle agrees with
    return e.outcome();
  };
}

}  // namespace

TEST_CASE(LABKIT_STEP(L06S3) ": worked examples", "[lab06][step3]") {
  const auto valid = [](const Mesh& m) { return judge::bsp_tree(m, answerer::build_bsp(m)); };
  check::example(query::build_bsp, "a tetrahedron: a chain, no cut", tetrahedron(), [](const Mesh& m) {
    const BspTree tree = answerer::build_bsp(m);
    Expect e("a BSP node holds the triangles in its plane; the others go in front or behind, cut when they cross it");
    e.equal("pieces", int(tree.pieces.size()), 4);
    e.equal("nodes", int(tree.nodes.size()), 4);
    return both(judge::bsp_tree(m, tree), e.outcome());
  });
  check::example(query::build_bsp, "a floor and a wall: one of them is cut", floor_and_wall(), [](const Mesh& m) {
    const BspTree tree = answerer::build_bsp(m);
    Expect e("a BSP node holds the triangles in its plane; the others go in front or behind, cut when they cross it");
    e.that("pieces", tree.pieces.size() == 3 || tree.pieces.size() == 4, std::to_string(tree.pieces.size()),
           "3 (the wall cut in two) or 4 (the floor cut in three)", "exactly one triangle is cut by the other's plane");
    return both(judge::bsp_tree(m, tree), e.outcome());
  });
  check::example(query::build_bsp, "two faces in one plane stay at one node", gen::box_mesh({{0, 0, 0}, {2, 2, 2}}),
                 valid);
  check::example(query::build_bsp, "a zero-area triangle is left out", mesh_of({{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}}),
                 [](const Mesh& m) {
    const BspTree tree = answerer::build_bsp(m);
    Expect e("a zero-area triangle has no plane: the tree leaves it out");
    e.equal("nodes", int(tree.nodes.size()), 0);
    e.equal("pieces", int(tree.pieces.size()), 0);
    return e.outcome();
  });
  const Mesh t = tetrahedron();
  check::example(query::classify, "(1, 1, 1): inside", PointQuery{t, {1, 1, 1}}, expect_where(Where::inside));
  check::example(query::classify, "(3, 3, 3): beyond the slanted face", PointQuery{t, {3, 3, 3}},
                 expect_where(Where::outside));
  check::example(query::classify, "(1, 1, 2): on the slanted face", PointQuery{t, {1, 1, 2}}, expect_where(Where::on));
  check::example(query::classify, "(2, 2, 0): on an edge", PointQuery{t, {2, 2, 0}}, expect_where(Where::on));
  check::example(query::classify, "(0, 0, 0): a vertex", PointQuery{t, {0, 0, 0}}, expect_where(Where::on));
  check::example(query::classify, "(6, 0, 0): on two planes, outside", PointQuery{t, {6, 0, 0}},
                 expect_where(Where::outside));
  check::example(query::classify, "(-1, 1, 1): behind nothing", PointQuery{t, {-1, 1, 1}},
                 expect_where(Where::outside));
}

TEST_CASE(LABKIT_STEP(L06S3) ": random cases", "[lab06][step3][oracle]") {
  check::random_cases(query::build_bsp, gen::bsp_mesh(),
                      [](const Mesh& m) { return judge::bsp_tree(m, answerer::build_bsp(m)); });
  check::random_cases(query::classify, gen::point_query(), [](const PointQuery& in) {
    return judge::classify(in, answerer::classify(answerer::build_bsp(in.mesh), in.point));
  });
}

// ---- Step 4 --------------------------------------------------------------------------------------

namespace {

// Three squares' worth of triangles stacked at z = 0, 1, 2, each hiding the one below it
// from above.
Mesh stack_of_three() {
  return mesh_of(
      {{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, {{0, 0, 1}, {4, 0, 1}, {0, 4, 1}}, {{0, 0, 2}, {4, 0, 2}, {0, 4, 2}}});
}

// Three long triangles, each lying over the next: no order of the whole triangles works,
// so some triangle must be cut.
Mesh pinwheel() {
  return mesh_of({{{0, 0, 0}, {12, 1, 2}, {12, -1, 2}},
                  {{12, 0, 1}, {-6, 10, 3}, {-6, 12, 3}},
                  {{-6, 11, 2}, {0, -1, 4}, {0, 1, 4}}});
}

Outcome judge_order(const PointQuery& in, Rules rules = Rules::random) {
  const BspTree tree = answerer::build_bsp(in.mesh);
  return judge::back_to_front(in, tree, answerer::back_to_front(tree, in.point), rules);
}

}  // namespace

TEST_CASE(LABKIT_STEP(L06S4) ": worked examples", "[lab06][step4]") {
  const auto sources = [](std::vector<int> expected) {
    return [expected](const PointQuery& in) {
      const BspTree tree = answerer::build_bsp(in.mesh);
      const std::vector<int> order = answerer::back_to_front(tree, in.point);
      std::vector<int> got;
      for (int k : order)
        if (k >= 0 && std::size_t(k) < tree.pieces.size()) got.push_back(tree.pieces[std::size_t(k)].source);
      Expect e("back_to_front draws the far subtree, the node's pieces, then the near subtree, at every node");
      e.equal("triangles in order", got, expected);
      return both(judge::back_to_front(in, tree, order, Rules::exact), e.outcome());
    };
  };
  check::example(query::back_to_front, "from above: bottom first", PointQuery{stack_of_three(), {1, 1, 10}},
                 sources({0, 1, 2}));
  check::example(query::back_to_front, "from below: top first", PointQuery{stack_of_three(), {1, 1, -10}},
                 sources({2, 1, 0}));
  check::example(query::back_to_front, "level with the middle one", PointQuery{stack_of_three(), {1, 1, 1}},
                 [](const PointQuery& in) {
    const BspTree tree = answerer::build_bsp(in.mesh);
    return judge::back_to_front(in, tree, answerer::back_to_front(tree, in.point), Rules::exact);
  });
  check::example(query::back_to_front, "a pinwheel: cut, then ordered", PointQuery{pinwheel(), {2, 3, 20}},
                 [](const PointQuery& in) {
    const BspTree tree = answerer::build_bsp(in.mesh);
    Expect e("three triangles that overlap in a cycle cannot be ordered whole: the tree cuts them");
    e.that("pieces", tree.pieces.size() > 3, std::to_string(tree.pieces.size()), "more than 3",
           "three triangles that overlap in a cycle cannot be ordered whole");
    return both(judge::back_to_front(in, tree, answerer::back_to_front(tree, in.point), Rules::exact), e.outcome());
  });
}

TEST_CASE(LABKIT_STEP(L06S4) ": random cases", "[lab06][step4][oracle]") {
  check::random_cases(query::back_to_front, gen::eye_query(), [](const PointQuery& in) {
    const BspTree tree = answerer::build_bsp(in.mesh);
    return judge::back_to_front(in, tree, answerer::back_to_front(tree, in.point));
  });
}

// ---- Step 5 --------------------------------------------------------------------------------------

namespace {

auto expect_pairs(std::vector<std::array<int, 2>> pairs) {
  return [pairs](const SphereSet& in) {
    const SpherePairs got = answerer::overlapping_pairs(in.spheres);
    const Outcome right = judge::overlapping_pairs(in, got, served("given_balls_meet"), Rules::exact);
    Expect e("overlapping_pairs reports every pair of balls that meet (touching counts), each once");
    e.equal("pairs", got.pairs, pairs);
    return both(right, e.outcome());
  };
}

}  // namespace

TEST_CASE(LABKIT_STEP(L06S5) ": worked examples", "[lab06][step5]") {
  // The lecture's sweep: along x the intervals run A0 A1 R0 B0 R1 C0 C1 B1.
  const SphereSet lecture{{{{1, 0, 0}, 1}, {{5, 0, 0}, 2}, {{9, 3, 0}, 4}, {{9, 9, 0}, 1}}};
  check::example(query::overlapping_pairs, "the lecture's A R B C: only R and B meet", lecture, expect_pairs({{1, 2}}));
  check::example(query::overlapping_pairs, "touching along x: intervals [-1, 1] and [1, 3]",
                 SphereSet{{{{0, 0, 0}, 1}, {{2, 0, 0}, 1}}}, expect_pairs({{0, 1}}));
  check::example(query::overlapping_pairs, "a point on a sphere", SphereSet{{{{3, 4, 0}, 5}, {{0, 0, 0}, 0}}},
                 expect_pairs({{0, 1}}));
  check::example(query::overlapping_pairs, "a row along y: x tells nothing",
                 SphereSet{{{{0, 0, 0}, 1}, {{0, 3, 0}, 1}, {{0, 6, 0}, 1.5}, {{0, 8, 0}, 1}}}, expect_pairs({{2, 3}}));
  check::example(query::overlapping_pairs, "no spheres", SphereSet{}, expect_pairs({}));
  check::example(query::overlapping_pairs, "one sphere inside another",
                 SphereSet{{{{0, 0, 0}, 5}, {{1, 1, 1}, 1}, {{20, 0, 0}, 1}}}, expect_pairs({{0, 1}}));
}

TEST_CASE(LABKIT_STEP(L06S5) ": random cases", "[lab06][step5][oracle]") {
  check::random_cases(query::overlapping_pairs, gen::sphere_set_case(),
                      [](const SphereSet& in) { return judge_pairs(in); });
}

// ---- Step 6 --------------------------------------------------------------------------------------

namespace {

// Each frame's expected pairs, tests and swaps (the handout's tables), after the judge.
struct FrameCounts {
  std::vector<std::array<int, 2>> pairs;
  long long tests, swaps;
};

auto expect_frames(std::vector<FrameCounts> expected, Rules rules = Rules::exact) {
  return [expected, rules](const SweepCase& in) {
    const SweepRuns got = sweep_counted(in.frames);
    const Outcome right = judge::sweep_frames(in, got, rules);
    if (right.verdict == Outcome::Verdict::fail || expected.empty()) return right;
    Expect e(
        "sort and sweep keeps the ends sorted by insertion, and tests the pairs whose intervals start overlapping");
    for (std::size_t k = 0; k < got.size() && k < expected.size(); ++k) {
      const std::string frame = "frame " + std::to_string(k + 1) + " ";
      e.equal(frame + "pairs", got[k].frame.pairs, expected[k].pairs);
      e.equal(frame + "tests", int(got[k].frame.tests), int(expected[k].tests));
      if (k > 0) e.equal(frame + "swaps", int(got[k].frame.swaps), int(expected[k].swaps));  // the first sort is free
    }
    return e.outcome();
  };
}

std::vector<Sphere> with_b_at(double x) { return {{{0, 0, 0}, 1}, {{x, 0, 0}, 1}}; }

}  // namespace

TEST_CASE(LABKIT_STEP(L06S6) ": worked examples", "[lab06][step6]") {
  // A at 0 and B sliding along x (radius 1 each): ends A0 = -1, A1 = 1, B0 = x - 1, B1 = x + 1.
  check::example(query::sweep_frames, "B slides to touch A, into it, and away: x = 5, 2.5, 2, 1.5, 4",
                 SweepCase{{with_b_at(5), with_b_at(2.5), with_b_at(2), with_b_at(1.5), with_b_at(4)}},
                 expect_frames({{{}, 0, 0}, {{}, 0, 0}, {{{0, 1}}, 1, 1}, {{{0, 1}}, 1, 0}, {{}, 0, 1}}));
  // The lecture's A R B C; then C moves 2 to the left: C0 = 6 passes R1 = 7.
  const std::vector<Sphere> lecture{{{1, 0, 0}, 1}, {{5, 0, 0}, 2}, {{9, 3, 0}, 4}, {{9, 9, 0}, 1}};
  std::vector<Sphere> moved = lecture;
  moved[3].center = {7, 9, 0};
  check::example(query::sweep_frames, "the lecture's A R B C, then C 2 to the left", SweepCase{{lecture, moved}},
                 expect_frames({{{{1, 2}}, 2, 0}, {{{1, 2}}, 3, 1}}));
  check::example(query::sweep_frames, "no spheres, twice", SweepCase{{{}, {}}},
                 expect_frames({{{}, 0, 0}, {{}, 0, 0}}));
  check::example(query::sweep_frames_moving, "1,000 spheres, 10 frames of small moves along x",
                 MovingSpheres{1000, 10, 6},
                 [](const MovingSpheres& m) { return expect_frames({}, Rules::random)(sweep_of(m)); });
}

TEST_CASE(LABKIT_STEP(L06S6) ": random cases", "[lab06][step6][oracle]") {
  check::random_cases(query::sweep_frames, gen::sweep_case(),
                      [](const SweepCase& in) { return judge::sweep_frames(in, sweep_counted(in.frames)); });
}

// ---- Step 7 --------------------------------------------------------------------------------------

namespace {

Outcome judge_bvh(const BvhQuery& in, Rules rules = Rules::random) {
  const ObbTree a = judge::obb_tree(in.a, in.tree_a), b = judge::obb_tree(in.b, in.tree_b);
  return judge::colliding_triangles(in, a, b, bvh_counted(a, b, in.every), rules);
}

auto expect_bvh(std::vector<std::array<int, 2>> pairs, int box_tests, int triangle_tests) {
  return [=](const BvhQuery& in) {
    const ObbTree a = judge::obb_tree(in.a, in.tree_a), b = judge::obb_tree(in.b, in.tree_b);
    const BvhRun got = bvh_counted(a, b, in.every);
    const Outcome right = judge::colliding_triangles(in, a, b, got, Rules::exact);
    if (right.verdict == Outcome::Verdict::fail) return right;
    Expect e(
        "the BVH descends the node with the larger volume (a's on a tie), tests two boxes before their children, and "
        "two triangles only where two leaves' boxes overlap");
    e.equal("pairs", got.answer.pairs, pairs);
    e.equal("box_tests", int(got.answer.box_tests), box_tests);
    e.equal("triangle_tests", int(got.answer.triangle_tests), triangle_tests);
    return e.outcome();
  };
}

// Two meshes whose roots' boxes have equal volumes (4 x 1 x 6, and the same largest
// coordinate, so the same padding): a's root descends first. a's second leaf is apart
// from b's root, and both of b's leaves overlap a's root, so descending b first would
// take 7 box tests instead of 5.
Mesh tie_a() { return mesh_of({{{-2, 0, -3}, {1.5, 0, 3}, {0, 1, 0}}, {{1.5, 0, 0}, {2, 0, 0}, {1.75, 1, 0}}}); }
Mesh tie_b() { return mesh_of({{{-3, 0, -3}, {-1, 0, 3}, {-2, 1, 0}}, {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}}}); }

// a: two triangles 10 apart along x; b: one triangle piercing a's second one.
Mesh two_apart() { return mesh_of({{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, {{10, 0, 0}, {12, 0, 0}, {10, 2, 0}}}); }
Mesh piercing() { return mesh_of({{{10.5, 0.5, -1}, {10.5, 0.5, 1}, {11.5, 3, 0}}}); }

}  // namespace

TEST_CASE(LABKIT_STEP(L06S7) ": OBB trees, worked examples", "[lab06][step7]") {
  check::example(query::colliding_triangles, "one triangle through another: 1 box test, 1 triangle test",
                 BvhQuery{mesh_of({{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}}),
                          mesh_of({{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, 3, 0}}}), 0, 0, true},
                 expect_bvh({{0, 0}}, 1, 1));
  check::example(query::colliding_triangles, "a's root, then its two leaves against b: 3 box tests, 1 triangle test",
                 BvhQuery{two_apart(), piercing(), 0, 0, true}, expect_bvh({{1, 0}}, 3, 1));
  check::example(query::colliding_triangles, "b far away: the roots' boxes are apart, 1 box test",
                 BvhQuery{two_apart(), mesh_of({{{0, 0, 50}, {2, 0, 50}, {0, 2, 50}}}), 0, 0, true},
                 expect_bvh({}, 1, 0));
  check::example(query::colliding_triangles, "coplanar overlapping triangles never meet here",
                 BvhQuery{mesh_of({{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}}),
                          mesh_of({{{0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0}}}), 0, 0, true},
                 expect_bvh({}, 1, 1));
  check::example(query::colliding_triangles, "equal volumes: a's root descends first, 5 box tests (b's first: 7)",
                 BvhQuery{tie_a(), tie_b(), 0, 0, true},
                 [](const BvhQuery& in) {
    const ObbTree a = judge::obb_tree(in.a, in.tree_a), b = judge::obb_tree(in.b, in.tree_b);
    const BvhRun got = bvh_counted(a, b, in.every);
    const Outcome right = judge::colliding_triangles(in, a, b, got, Rules::exact);
    if (right.verdict == Outcome::Verdict::fail) return right;
    Expect e("the BVH descends the node with the larger volume (a's on a tie)");
    e.that("box_tests", got.answer.box_tests <= 5, std::to_string(got.answer.box_tests), "at most 5",
           "at equal volumes the header descends a's node: a's second leaf is then apart from b's root at once; "
           "descending b's root first tests a's root against both of b's leaves, and each of those against both of "
           "a's");
    return e.outcome();
  });
  check::example(query::colliding_triangles, "two spheres of 80 triangles overlapping, every pair",
                 BvhQuery{gen::sphere_mesh(80, {0, 0, 0}, 1), gen::sphere_mesh(80, {1.2, 0.3, 0.1}, 0.8), 3, 5, true},
                 [](const BvhQuery& in) { return judge_bvh(in, Rules::random); });
  check::example(query::colliding_triangles, "the same, one pair asked for",
                 BvhQuery{gen::sphere_mesh(80, {0, 0, 0}, 1), gen::sphere_mesh(80, {1.2, 0.3, 0.1}, 0.8), 3, 5, false},
                 [](const BvhQuery& in) { return judge_bvh(in, Rules::random); });
}

TEST_CASE(LABKIT_STEP(L06S7) ": OBB trees, random cases", "[lab06][step7][oracle]") {
  check::random_cases(query::colliding_triangles, gen::bvh_query(), [](const BvhQuery& in) { return judge_bvh(in); });
}

// ---- Step 8 --------------------------------------------------------------------------------------

namespace {

using Random = SplitMix64;  // the efficiency segments, the same on every machine

// The segments of an efficiency case, `short_ones` or long ones.
std::vector<Segment> efficiency_segments(const Mesh& mesh, int count, bool short_ones, std::uint64_t seed) {
  Random random{seed};
  Aabb box{mesh.vertices[0], mesh.vertices[0]};
  for (const Vec3& v : mesh.vertices) box = {box.min.cwiseMin(v), box.max.cwiseMax(v)};
  const double size = (box.max - box.min).norm();
  const auto in_ball = [&] {
    for (;;) {
      const Vec3 v(2 * random.uniform() - 1, 2 * random.uniform() - 1, 2 * random.uniform() - 1);
      if (v.squaredNorm() <= 1 && v.squaredNorm() > 1e-6) return v;
    }
  };
  std::vector<Segment> out;
  while (int(out.size()) < count) {
    if (short_ones) {
      // Centred within size / 100 of a random point of a random triangle, size / 50 long.
      const Triangle t = mesh.triangle(std::size_t(random.below(int(mesh.size()))));
      double u = random.uniform(), v = random.uniform();
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const Vec3 c = t.v0 + u * (t.v1 - t.v0) + v * (t.v2 - t.v0) + size / 100 * in_ball();
      const Vec3 d = size / 100 * in_ball().normalized();
      out.push_back({c - d, c + d});
    } else {
      // Two points of the box grown by a tenth, at least half its diagonal apart.
      const auto any = [&] {
        Vec3 p;
        for (int i = 0; i < 3; ++i)
          p[i] = box.min[i] - 0.1 * size + (box.max[i] - box.min[i] + 0.2 * size) * random.uniform();
        return p;
      };
      const Vec3 a = any(), b = any();
      if ((b - a).norm() >= size / 2) out.push_back({a, b});
    }
  }
  return out;
}

// Segments per call of run_segments: a few thousand given calls, far within a call's limit.
constexpr std::size_t kSegmentsPerCall = 250;

// Tests per query over a batch of segments.
struct Tally {
  long long total = 0;
  int worst = 0, count = 0;
  void add(int tests) {
    total += tests;
    worst = std::max(worst, tests);
    ++count;
  }
  double mean() const { return count ? double(total) / count : 0.0; }
  std::string text() const { return "mean " + fmt(std::round(mean() * 10) / 10) + ", worst " + std::to_string(worst); }
};

// The segments' answers, in chunks so that no call runs into the time limit of one call,
// with the given tests the judge counted for each: every query of a chunk is a part of
// it (first_hit, any_hit and, for long segments, all_hits).
struct CountedRuns {
  SegmentRuns runs;
  std::vector<std::array<long long, 3>> calls;
};
Outcome run_counted(const KdTree& tree, const Segments& segments, bool short_ones, CountedRuns& out) {
  const std::size_t parts = short_ones ? 2 : 3;
  for (std::size_t at = 0; at < segments.size(); at += kSegmentsPerCall) {
    const Segments chunk(segments.begin() + long(at),
                         segments.begin() + long(std::min(segments.size(), at + kSegmentsPerCall)));
    const SegmentRuns got = answerer::run_segments(tree, chunk, !short_ones);
    const given::Served& counted = remote::last_served();
    if (got.size() != chunk.size())
      return check::fail(std::to_string(chunk.size()) + " answers", std::to_string(got.size()) + " answers",
                         "run_segments answers each segment once, in order");
    for (std::size_t k = 0; k < chunk.size(); ++k) {
      out.runs.push_back(got[k]);
      out.calls.push_back({});
      for (std::size_t p = 0; p < parts; ++p) out.calls.back()[p] = counted.count(k * parts + p, "segment_triangle");
    }
  }
  return check::pass();
}

// One segment's answers: each tests count is the calls the kit counted, and the hits are
// those of testing every triangle with the same given test.
Outcome check_segment_run(const Segment& s, const SegmentRun& run, const std::array<long long, 3>& calls,
                          bool short_ones, const KdHit& expected, const std::string& name) {
  const KdHit& first = run.first;
  const KdHit& any = run.any;
  const bool all_counted = short_ones || run.all_tests == calls[2];
  if (first.tests != calls[0] || any.tests != calls[1] || !all_counted)
    return check::fail("tests = " + std::to_string(calls[0]) + ", " + std::to_string(calls[1]) +
                           (short_ones ? "" : ", " + std::to_string(calls[2])) + " (first_hit, any_hit" +
                           (short_ones ? "" : ", all_hits") +
                           ": your calls of given::segment_triangle, as the kit counted them)",
                       "tests = " + std::to_string(first.tests) + ", " + std::to_string(any.tests) +
                           (short_ones ? "" : ", " + std::to_string(run.all_tests)),
                       "tests counts the triangles a query tested, each with one call of given::segment_triangle: "
                       "count every call, and only those, for a=" +
                           fmt(s.a) + " b=" + fmt(s.b));
  if (first.hit != expected.hit || (expected.hit && first.t != expected.t))
    return check::fail(
        expected.hit ? "a hit at t = " + fmt(expected.t) : "no hit",
        first.hit ? "a hit at t = " + fmt(first.t) : "no hit",
        "first_hit on the " + name + " disagrees with testing every triangle, for a=" + fmt(s.a) + " b=" + fmt(s.b));
  if (any.hit != expected.hit)
    return check::fail(expected.hit ? "a hit" : "no hit", any.hit ? "a hit" : "no hit", "any_hit on the " + name);
  return check::pass();
}

// Tests per query, by kind of segment and query.
struct Tallies {
  Tally short_first, short_any, long_first, long_all;
};

// The tallies against the step's bounds: a bound missed is a tree that does not prune.
Outcome efficiency_verdict(const Tallies& t, const std::string& name) {
  const std::string got = "short first_hit " + t.short_first.text() + "; short any_hit " + t.short_any.text() +
                          "; long first_hit mean " + fmt(std::round(t.long_first.mean())) + "; long all_hits mean " +
                          fmt(std::round(t.long_all.mean()));
  const std::string expected = "short: mean <= " + fmt(kShortMean) + ", worst <= " + std::to_string(kShortWorst) +
                               "; long first_hit mean <= " + fmt(kLongFirstMean) +
                               "; long all_hits mean <= " + fmt(kLongAllMean);
  const std::string leaves =
      ": are the leaves too big? Split while a split is cheaper than a leaf (the SAH), down to a "
      "few triangles per leaf";
  for (const Tally* s : {&t.short_first, &t.short_any})
    if (s->mean() > kShortMean || s->worst > kShortWorst)
      return check::fail(expected, got,
                         "a short segment meets few leaves, so its tests per query are bounded: short "
                         "segments test too many triangles of the " +
                             name + leaves);
  if (t.long_first.mean() > kLongFirstMean)
    return check::fail(expected, got,
                       "first_hit on long segments must stop early (at the first leaf whose far end t1 is "
                       "past the best hit): too many tests on the " +
                           name + leaves);
  if (t.long_all.mean() > kLongAllMean)
    return check::fail(expected, got,
                       "all_hits tests only the leaves the segment meets: too many tests on the " + name + leaves);
  check::note(query::efficiency_segments.name, name + ": " + got + " (bounds: " + expected + ")");
  return check::pass();
}

// "sphere of 10,082 triangles (10,000 asked for: its grid rounds the count)": the mesh's
// own count, which a torus's or a sphere's grid rounds.
std::string efficiency_mesh_name(gen::MeshKind kind, const Mesh& mesh, int asked) {
  const auto grouped = [](std::size_t n) {
    std::string digits = std::to_string(n);
    for (int at = int(digits.size()) - 3; at > 0; at -= 3) digits.insert(std::size_t(at), ",");
    return digits;
  };
  return std::string(gen::name_of(kind)) + " of " + grouped(mesh.size()) + " triangles" +
         (mesh.size() == std::size_t(asked)
              ? ""
              : " (" + grouped(std::size_t(asked)) + " asked for: its grid rounds the count)");
}

// The tree must be valid, its answers counted honestly and right (the same as testing
// every triangle with the same given test: the segments are random, nothing here is near
// a tie), and its tests per query within the step's bounds.
Outcome run_efficiency(const EfficiencyCase& in) {
  const auto kind = gen::MeshKind(in.kind);
  const Mesh mesh = gen::mesh_of_kind(kind, in.triangles, std::uint64_t(in.seed));
  const KdTree tree = answerer::build_kd_tree(mesh);
  const Outcome valid = judge::kd_tree(mesh, tree);
  if (valid.verdict == Outcome::Verdict::fail) return valid;
  const std::vector<Aabb> boxes = judge::triangle_boxes(tree.triangles);
  const std::string name = efficiency_mesh_name(kind, mesh, in.triangles);
  Tallies tallies;
  for (bool short_ones : {true, false}) {
    const auto segments = efficiency_segments(mesh, in.segments, short_ones, std::uint64_t(in.seed) * 7 + short_ones);
    CountedRuns counted;
    if (const Outcome ran = run_counted(tree, segments, short_ones, counted); ran.verdict == Outcome::Verdict::fail)
      return ran;
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const KdHit expected = judge::brute_first_hit(tree.triangles, boxes, segments[k]);
      const SegmentRun& run = counted.runs[k];
      const Outcome one = check_segment_run(segments[k], run, counted.calls[k], short_ones, expected, name);
      if (one.verdict == Outcome::Verdict::fail) return one;
      if (short_ones) {
        tallies.short_first.add(run.first.tests);
        tallies.short_any.add(run.any.tests);
      } else {
        tallies.long_first.add(run.first.tests);
        tallies.long_all.add(run.all_tests);
      }
    }
  }
  return efficiency_verdict(tallies, name);
}

}  // namespace

TEST_CASE(LABKIT_STEP(L06S8) ": tests counted on about 10,000 triangles", "[lab06][step8]") {
  // The meshes' seed is drawn like a query's cases (mixed from the run's seed, never its digits).
  const int seed = int(check::detail::seed_for("efficiency") % 1000000);
  for (int kind = 0; kind < 4; ++kind)
    check::example(query::efficiency_segments, gen::name_of(gen::MeshKind(kind)),
                   EfficiencyCase{kind, 10000, 1000, seed}, run_efficiency);
  check::example(query::efficiency_spheres, "2,000 spheres spread over a cube", SpreadSpheres{2000, seed},
                 [](const SpreadSpheres& in) {
    const SphereSet set{gen::spread_spheres(in.count, 100, 0.25, 1, std::uint64_t(in.seed))};
    const SpherePairs got = answerer::overlapping_pairs(set.spheres);
    const Outcome right = judge::overlapping_pairs(set, got, served("given_balls_meet"));
    if (right.verdict == Outcome::Verdict::fail) return right;
    Expect e("a broad phase tests only the pairs that can meet");
    e.that("tests", got.tests <= kSphereTests, std::to_string(got.tests), "at most " + std::to_string(kSphereTests),
           "a broad phase tests only pairs that can meet: a sweep, those whose intervals overlap on the sweep axis "
           "(stop at the first interval starting after high[i]); a grid, those in the same or adjacent cells (cells at "
           "least one diameter wide, not much more); the brute force makes " +
               std::to_string(in.count * (in.count - 1) / 2));
    const Outcome o = e.outcome();
    if (o.verdict == Outcome::Verdict::pass)
      check::note(query::efficiency_spheres.name, std::to_string(in.count) + " spheres: " + std::to_string(got.tests) +
                                                      " tests (bound " + std::to_string(kSphereTests) +
                                                      "; the brute force makes " +
                                                      std::to_string(in.count * (in.count - 1) / 2) + ")");
    return o;
  });
}

// ---- Step 9: robustness ----------------------------------------------------------------------------
// Exact degenerate input on integers: the header's rules hold exactly.

namespace {

// A 2 x 1 x 1 block of two unit cubes, scaled by 2: its faces lie in the planes x = 0,
// 2, 4, y = 0, 2, z = 0, 2.
Mesh two_cubes() { return gen::voxel_mesh({{0, 0, 0}, {1, 0, 0}}, Vec3::Zero(), 2.0); }

// A tree over two_cubes() by hand: the root splits at x = 2, through the wall between
// the cubes (it has no faces: only vertices and edges of the faces around it); its child
// above splits at z = 2, along the top faces, on the wall of its cell: the child above
// that is flat.
KdTree cubes_tree() {
  const Mesh m = two_cubes();
  std::vector<int> below{0}, above_low{0}, above_high{0};
  const auto add = [](std::vector<int>& list, int i) { list.push_back(i), ++list[0]; };
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Triangle t = m.triangle(i);
    const Vec3 lo = t.v0.cwiseMin(t.v1).cwiseMin(t.v2), hi = t.v0.cwiseMax(t.v1).cwiseMax(t.v2);
    if (lo.x() <= 2) add(below, int(i));
    if (hi.x() >= 2 && lo.z() <= 2) add(above_low, int(i));
    if (hi.x() >= 2 && hi.z() >= 2) add(above_high, int(i));
  }
  std::vector<int> items = below;
  const int low_at = int(items.size());
  items.insert(items.end(), above_low.begin(), above_low.end());
  const int high_at = int(items.size());
  items.insert(items.end(), above_high.begin(), above_high.end());
  return judge::tree_of(m, {{0, 0, 0}, {4, 2, 2}},
                        {{2, 0, 2}, {0, kLeaf, 0}, {2, 2, 4}, {0, kLeaf, low_at}, {0, kLeaf, high_at}}, items);
}

}  // namespace

TEST_CASE(LABKIT_STEP(L06S9) ": k-d trees on exact input", "[lab06][step9]") {
  const KdTree tree = cubes_tree();
  const Mesh mesh = two_cubes();
  const auto exact_all = [tree](const TreeQuery& in) {
    return both(judge_all(in, tree, Rules::exact),
                both(judge_first(in, tree, Rules::exact), judge_any(in, tree, Rules::exact)));
  };
  constexpr auto q = query::robust_segment_queries;
  check::example(q, "down the split plane x = 2", TreeQuery{mesh, {{2, 1, 4}, {2, 1, -4}}, 0}, exact_all);
  check::example(q, "along the top, in the plane z = 2", TreeQuery{mesh, {{-2, 1, 2}, {6, 1, 2}}, 0}, exact_all);
  check::example(q, "along the wall y = 0 of the root's cell", TreeQuery{mesh, {{1, 0, 1}, {1, 0, -1}}, 0}, exact_all);
  check::example(q, "ending exactly on the split plane", TreeQuery{mesh, {{-2, 1, 1}, {2, 1, 1}}, 0}, exact_all);
  check::example(q, "starting on the split plane, through a shared edge", TreeQuery{mesh, {{2, 1, 4}, {2, 1, 2}}, 0},
                 exact_all);
  check::example(q, "through the corner (2, 0, 2) of three cells", TreeQuery{mesh, {{0, -2, 0}, {4, 2, 4}}, 0},
                 exact_all);
  check::example(query::robust_build_kd_tree, "two cubes: splits along their faces", mesh,
                 [](const Mesh& m) { return judge::kd_tree(m, answerer::build_kd_tree(m)); });
}

TEST_CASE(LABKIT_STEP(L06S9) ": random exact degenerate cases", "[lab06][step9][oracle]") {
  check::random_cases(query::robust_segment_queries, gen::exact_tree_query(),
                      [](const TreeQuery& in) { return all_three(in, Rules::exact); });
  check::random_cases(query::robust_build_kd_tree, gen::exact_mesh(),
                      [](const Mesh& m) { return judge::kd_tree(m, answerer::build_kd_tree(m)); });
}

// ---- Step 10: robustness of steps 3 to 7 (extensions, as they are) -----------------------

TEST_CASE(LABKIT_STEP(L06S10) ": BSP trees, spheres and BVHs on exact input", "[lab06][step10]") {
  // An L of three cubes (scaled by 2): faces share planes, points lie on them.
  const Mesh l = gen::voxel_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, Vec3::Zero(), 2.0);
  constexpr auto q = query::robust_classify;
  check::example(q, "in the notch of the L", PointQuery{l, {3, 3, 1}}, expect_where(Where::outside));
  check::example(q, "beyond the notch, on two face planes", PointQuery{l, {4, 4, 1}}, expect_where(Where::outside));
  check::example(q, "on the inner corner edge", PointQuery{l, {2, 2, 1}}, expect_where(Where::on));
  check::example(q, "inside, on the plane between two cubes", PointQuery{l, {2, 1, 1}}, expect_where(Where::inside));
  check::example(q, "on a top face, on a cube's edge line", PointQuery{l, {1, 2, 2}}, expect_where(Where::on));
  check::example(q, "beyond the top, on a face's plane", PointQuery{l, {1, 5, 2}}, expect_where(Where::outside));
  check::example(query::robust_back_to_front, "the eye in the plane of the top faces", PointQuery{l, {9, 9, 2}},
                 [](const PointQuery& in) { return judge_order(in, Rules::exact); });
  check::example(query::robust_overlapping_pairs, "a chain touching along x, listed backwards",
                 SphereSet{{{{6, 0, 0}, 1}, {{3, 0, 0}, 2}, {{0, 0, 0}, 1}}}, expect_pairs({{0, 1}, {1, 2}}));
  // Step 7 on exact contacts (every edge's largest |component| a power of two: the given
  // test is exact): an edge through the other triangle's edge, an edge starting on it.
  const Mesh floor = mesh_of({{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}});
  check::example(query::robust_colliding_triangles, "an edge crossing the other's edge at (1, 0, 0)",
                 BvhQuery{floor, mesh_of({{{1, 0, -1}, {1, 0, 1}, {1, -2, 0}}}), 0, 0, true},
                 expect_bvh({{0, 0}}, 1, 1));
  check::example(query::robust_colliding_triangles, "a vertex exactly on the other's edge, at (1, 1, 0)",
                 BvhQuery{floor, mesh_of({{{1, 1, 0}, {1, 1, 2}, {3, 3, 2}}}), 0, 0, true}, expect_bvh({{0, 0}}, 1, 1));
  // Three equal balls whose ends meet exactly: a low end arrives at a high end's value
  // (touching: the low end must pass it), twice.
  check::example(query::robust_sweep_frames, "ends arriving exactly on ends",
                 SweepCase{{{{{0, 0, 0}, 1}, {{4, 0, 0}, 1}, {{8, 0, 0}, 1}},
                            {{{0, 0, 0}, 1}, {{2, 0, 0}, 1}, {{8, 0, 0}, 1}},
                            {{{0, 0, 0}, 1}, {{2, 0, 0}, 1}, {{4, 0, 0}, 1}}}},
                 expect_frames({{{}, 0, 0}, {{{0, 1}}, 1, 1}, {{{0, 1}, {1, 2}}, 2, 1}}));
}

TEST_CASE(LABKIT_STEP(L06S10) ": random exact degenerate cases", "[lab06][step10][oracle]") {
  check::random_cases(query::robust_classify, gen::exact_point_query(), [](const PointQuery& in) {
    return judge::classify(in, answerer::classify(answerer::build_bsp(in.mesh), in.point), Rules::exact);
  });
  check::random_cases(query::robust_back_to_front, gen::exact_eye_query(), [](const PointQuery& in) {
    const BspTree tree = answerer::build_bsp(in.mesh);
    return judge::back_to_front(in, tree, answerer::back_to_front(tree, in.point), Rules::exact);
  });
  check::random_cases(query::robust_overlapping_pairs, gen::exact_sphere_set_case(),
                      [](const SphereSet& in) { return judge_pairs(in, Rules::exact); });
  check::random_cases(query::robust_sweep_frames, gen::exact_sweep_case(), [](const SweepCase& in) {
    return judge::sweep_frames(in, sweep_counted(in.frames), Rules::exact);
  });
}

// ---- Step 11 (extension): spatial hashing ---------------------------------------------------------

namespace {

// The pairs and the calls of given_balls_meet the judge counted, judged; then the pairs
// and the tests the handout's example works out.
Outcome judge_hash(const HashCase& in, Rules rules = Rules::random) {
  const SpherePairs got = answerer::hashed_pairs(in.spheres, in.cell, in.buckets);
  return judge::hashed_pairs(in, got, served("given_balls_meet"), rules);
}

auto expect_hash(std::vector<std::array<int, 2>> pairs, long long tests) {
  return [pairs, tests](const HashCase& in) {
    const SpherePairs got = answerer::hashed_pairs(in.spheres, in.cell, in.buckets);
    const Outcome right = judge::hashed_pairs(in, got, served("given_balls_meet"), Rules::exact);
    if (right.verdict == Outcome::Verdict::fail) return right;
    Expect e("a spatial hash tests the pairs of balls in neighbouring cells, each once, whatever the buckets");
    e.equal("pairs", got.pairs, pairs);
    e.equal("tests", int(got.tests), int(tests));
    return e.outcome();
  };
}

// The handout's example: unit balls, cells of side 2, two pairs 2^31 apart along x. With
// 4 buckets the cells (0, 0, 0) and (2^30, 0, 0) share bucket 0, (1, 0, 0) and
// (2^30 + 1, 0, 0) bucket 1.
constexpr double kFar = 2147483648.0;  // 2^31
HashCase two_far_pairs(int buckets) {
  return HashCase{{{{1, 1, 0}, 1}, {{2.5, 1, 0}, 1}, {{kFar + 1, 1, 0}, 1}, {{kFar + 3, 1, 0}, 1}}, 2, buckets, true};
}

// A sparse world: `clusters` clusters of `per` balls on integers (centres in [0, 64]^3,
// radii 1 to 3), each moved by a multiple of 2^32 along the axes.
HashCase sparse_world(int clusters, int per, int buckets, std::uint64_t seed) {
  SplitMix64 random{seed};
  HashCase c{{}, 8, buckets, true};
  for (int k = 0; k < clusters; ++k) {
    const Vec3 offset = 4294967296.0 * Vec3(random.below(17) - 8, random.below(17) - 8, random.below(17) - 8);
    for (int i = 0; i < per; ++i)
      c.spheres.push_back({offset + Vec3(random.below(65), random.below(65), random.below(65)), 1.0 + random.below(3)});
  }
  return c;
}

}  // namespace

TEST_CASE(LABKIT_STEP(L06S11) ": worked examples", "[lab06][step11]") {
  check::example(query::hashed_pairs, "two pairs 2^31 apart, 4 buckets: cells share buckets", two_far_pairs(4),
                 expect_hash({{0, 1}, {2, 3}}, 2));
  check::example(query::hashed_pairs, "the same with 1 bucket: every cell collides", two_far_pairs(1),
                 expect_hash({{0, 1}, {2, 3}}, 2));
  check::example(query::hashed_pairs, "touching across a wall at x = 0, below zero on one side",
                 HashCase{{{{-0.5, 0, 0}, 0.5}, {{0.5, 0, 0}, 0.5}, {{-2.5, 0, 0}, 0.5}}, 1, 7, true},
                 expect_hash({{0, 1}}, 1));
  check::example(query::hashed_pairs, "diagonal neighbours, the larger index below and behind",
                 HashCase{{{{0.25, 0.25, 0.25}, 1}, {{-0.25, -0.25, -0.25}, 1}}, 2, 64, true},
                 expect_hash({{0, 1}}, 1));
  check::example(query::hashed_pairs, "no spheres", HashCase{{}, 1, 3, true}, expect_hash({}, 0));
  check::example(query::hashed_pairs, "600 balls in 6 clusters 2^32 apart, 64 buckets", sparse_world(6, 100, 64, 11),
                 [](const HashCase& in) {
    const Outcome o = judge_hash(in, Rules::exact);
    if (o.verdict == Outcome::Verdict::pass)
      check::note(query::hashed_pairs.name, "600 balls in 6 clusters: at most " +
                                                std::to_string(judge::neighbour_pairs(in)) +
                                                " tests (the brute force makes 179,700)");
    return o;
  });
}

TEST_CASE(LABKIT_STEP(L06S11) ": random cases", "[lab06][step11][oracle]") {
  check::random_cases(query::hashed_pairs, gen::hash_case(), [](const HashCase& in) { return judge_hash(in); });
}

// ---- Step 12 (extension): an octree ---------------------------------------------------------------

namespace {

Outcome judge_build(const OctreeCase& in) {
  return judge::octree(in, answerer::build_octree(in.spheres, in.capacity, in.max_depth));
}

// The box query on the checker's tree, with the given tests' calls the judge counted.
OctreeRun octree_counted(const Octree& tree, const Aabb& box) {
  OctreeRun run;
  run.answer = answerer::balls_in_box(tree, box);
  run.cell_calls = served("given_cell_meets_box");
  run.ball_calls = served("given_ball_meets_box");
  return run;
}

Outcome judge_box(const OctreeCase& in, Rules rules = Rules::random) {
  const Octree tree = judge::octree_of(in.spheres, in.capacity, in.max_depth);
  return judge::balls_in_box(in, tree, octree_counted(tree, in.box), rules);
}

// The handout's example: capacity 2. The root [0, 8]^3 holds 5 balls: cut at 4. Its octant
// 0 holds balls 0 and 4 (4 lies across x = 4), octant 1 ball 4, octant 7 balls 1, 2, 3:
// cut again at 6. 17 nodes, 15 leaves.
OctreeCase handout_octree(const Aabb& box) {
  return OctreeCase{
      {{{1, 1, 1}, 1}, {{7.5, 7.5, 7.5}, 0.5}, {{5, 5, 5}, 0.5}, {{7, 5, 5}, 0.5}, {{4, 1, 1}, 0.5}}, 2, 4, box, true};
}

auto expect_octree(std::size_t nodes, int leaves) {
  return [nodes, leaves](const OctreeCase& in) {
    const Octree got = answerer::build_octree(in.spheres, in.capacity, in.max_depth);
    const Outcome right = judge::octree(in, got);
    if (right.verdict == Outcome::Verdict::fail) return right;
    Expect e("an octree cuts a node in 8 only while it holds more than capacity balls");
    int got_leaves = 0;
    for (const OctNode& n : got.nodes) got_leaves += n.child < 0;
    e.equal("nodes", int(got.nodes.size()), int(nodes));
    e.equal("leaves", got_leaves, leaves);
    return e.outcome();
  };
}

auto expect_box(std::vector<int> balls, long long cell_tests, long long ball_tests) {
  return [=](const OctreeCase& in) {
    const Octree tree = judge::octree_of(in.spheres, in.capacity, in.max_depth);
    const OctreeRun got = octree_counted(tree, in.box);
    const Outcome right = judge::balls_in_box(in, tree, got, Rules::exact);
    if (right.verdict == Outcome::Verdict::fail) return right;
    Expect e("the query descends only the children whose cells meet the box, and tests each ball once");
    e.equal("balls", got.answer.balls, balls);
    e.equal("cell_tests", int(got.answer.cell_tests), int(cell_tests));
    e.equal("ball_tests", int(got.answer.ball_tests), int(ball_tests));
    return e.outcome();
  };
}

// Two clusters of 200 balls, each in a cube of 8 units, 1024 units apart along the
// diagonal: the tree cuts deep at the clusters only.
OctreeCase two_clusters() {
  SplitMix64 random{5};
  OctreeCase c{{}, 8, 10, {{0, 0, 0}, {4, 4, 4}}, true};
  for (double corner : {0.0, 1024.0})
    for (int i = 0; i < 200; ++i)
      c.spheres.push_back(
          {Vec3(corner + random.below(8), corner + random.below(8), corner + random.below(8)), 0.25 * random.below(3)});
  return c;
}

}  // namespace

TEST_CASE(LABKIT_STEP(L06S12) ": worked examples", "[lab06][step12]") {
  check::example(query::build_octree, "the handout's five balls, capacity 2: 17 nodes, 15 leaves",
                 handout_octree({{3, 0, 0}, {5, 1, 1}}), expect_octree(17, 15));
  check::example(query::build_octree, "two balls touching the cut x = 2, capacity 1: every child lists both",
                 OctreeCase{{{{1, 1, 1}, 1}, {{3, 1, 1}, 1}}, 1, 1, {}, true}, expect_octree(9, 8));
  check::example(query::build_octree, "no balls: no node", OctreeCase{{}, 4, 6, {}, true}, expect_octree(0, 0));
  check::example(query::build_octree,
                 "two balls at one point, capacity 1: no cut parts them, so only max_depth 4 stops the splitting: "
                 "1 + 8 + 64 + 512 + 4096 = 4681 nodes, 4096 leaves",
                 OctreeCase{{{{1, 1, 1}, 1}, {{1, 1, 1}, 1}}, 1, 4, {}, true}, expect_octree(4681, 4096));
  check::example(query::build_octree, "two clusters of 200 balls, 1024 apart: deep at the clusters only",
                 two_clusters(),
                 [](const OctreeCase& in) {
    const Outcome o = judge_build(in);
    if (o.verdict == Outcome::Verdict::pass)
      check::note(
          query::build_octree.name,
          "two clusters: " + std::to_string(judge::octree_of(in.spheres, in.capacity, in.max_depth).nodes.size()) +
              " nodes (a uniform grid as fine as depth 10: 2^30 cells)");
    return o;
  });
  check::example(query::balls_in_box, "a box across x = 4: 9 cell tests, ball 4 tested once though listed twice",
                 handout_octree({{3, 0, 0}, {5, 1, 1}}), expect_box({4}, 9, 2));
  check::example(query::balls_in_box, "a box at the crowded octant's centre: all 8 of its children",
                 handout_octree({{5.5, 5.5, 5.5}, {6.5, 6.5, 6.5}}), expect_box({}, 17, 3));
  check::example(query::balls_in_box, "a box touching ball 0 at (2, 1, 1)",
                 handout_octree({{2, 0.5, 0.5}, {3, 1.5, 1.5}}), expect_box({0}, 9, 2));
}

TEST_CASE(LABKIT_STEP(L06S12) ": random cases", "[lab06][step12][oracle]") {
  check::random_cases(query::build_octree, gen::octree_case(), judge_build);
  check::random_cases(query::balls_in_box, gen::octree_case(), [](const OctreeCase& in) { return judge_box(in); });
}

// ---- The header's preconditions (not a graded step) ---------------------------------------------
// Tagged [contract]: ctest runs it with the reference only. Students are not graded on
// invalid input; the reference refuses each kind with std::invalid_argument naming the
// argument and the rule.

TEST_CASE("L06 preconditions: invalid input is refused, naming the argument", "[lab06][contract]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  // The message names the argument and states the rule ("must"), not only the name.
  const auto refused = [](const std::string& argument, auto&& call) {
    CHECK_THAT(check::rejects(argument, call), check::contains_text("must"));
  };
  const KdTree tree = handout_tree();
  const Vec3 finite(0, 1, 1);
  for (double bad : {nan, inf, -inf}) {
    const Vec3 v(bad, 1, 1);
    refused("segment.a", [&] { answerer::first_hit(tree, {v, finite}); });
    refused("segment.b", [&] { answerer::first_hit(tree, {finite, v}); });
    refused("segment.a", [&] { answerer::any_hit(tree, {v, finite}); });
    refused("segment.b", [&] { answerer::all_hits(tree, {finite, v}); });
    Mesh broken = lean_and_stand();
    broken.vertices[4] = v;
    refused("mesh.vertices[4]", [&] { answerer::build_kd_tree(broken); });
    refused("mesh.vertices[4]", [&] { answerer::build_bsp(broken); });
    const BspTree bsp = answerer::build_bsp(lean_and_stand());
    refused("point", [&] { answerer::classify(bsp, v); });
    refused("eye", [&] { answerer::back_to_front(bsp, v); });
    refused("spheres[1].center", [&] { answerer::overlapping_pairs({{{0, 0, 0}, 1}, {v, 1}, {{1, 0, 0}, 1}}); });
    refused("spheres[0].radius", [&] { answerer::overlapping_pairs({{{0, 0, 0}, bad}, {{1, 0, 0}, 1}}); });
    refused("spheres[1].center", [&] {
      answerer::run_sweep({{{{0, 0, 0}, 1}, {{1, 0, 0}, 1}}, {{{0, 0, 0}, 1}, {v, 1}}});
    });
    refused("spheres[0].radius", [&] { answerer::run_sweep({{{{0, 0, 0}, bad}}}); });
  }
  refused("spheres[0].radius", [&] { answerer::run_sweep({{{{0, 0, 0}, -1}}}); });
  refused("spheres", [&] { answerer::run_sweep({{{{0, 0, 0}, 1}}, {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}}}); });
  refused("spheres[1].radius", [&] { answerer::overlapping_pairs({{{0, 0, 0}, 1}, {{1, 0, 0}, -1}}); });
  refused("cell", [&] { answerer::hashed_pairs({{{0, 0, 0}, 1}}, 3, 4); });
  refused("cell", [&] { answerer::hashed_pairs({{{0, 0, 0}, 1}}, 1, 4); });  // below the diameter 2
  refused("buckets", [&] { answerer::hashed_pairs({{{0, 0, 0}, 1}}, 2, 0); });
  refused("spheres[0].center", [&] { answerer::hashed_pairs({{{0x1p62, 0, 0}, 1}}, 2, 4); });
  refused("capacity", [&] { answerer::build_octree({{{0, 0, 0}, 1}}, 0, 4); });
  refused("max_depth", [&] { answerer::build_octree({{{0, 0, 0}, 1}}, 4, 11); });
  refused("spheres[0].radius", [&] { answerer::build_octree({{{0, 0, 0}, -1}}, 4, 4); });
  refused("box.min", [&] { answerer::balls_in_box(Octree{}, {{nan, 0, 0}, {1, 1, 1}}); });
  refused("box.min", [&] { answerer::balls_in_box(Octree{}, {{2, 0, 0}, {1, 1, 1}}); });
  refused("spheres[1].radius", [&] { answerer::hashed_pairs({{{0, 0, 0}, 1}, {{1, 0, 0}, nan}}, 2, 4); });
  Mesh out_of_range = lean_and_stand();
  out_of_range.triangles[1][2] = 6;
  refused("mesh.triangles[1]", [&] { answerer::build_kd_tree(out_of_range); });
  out_of_range.triangles[1][2] = -1;
  refused("mesh.triangles[1]", [&] { answerer::build_bsp(out_of_range); });
  // Valid, with a documented answer: a zero-length segment never hits; a point sphere
  // (radius 0) is a ball like any other.
  CHECK_FALSE(answerer::first_hit(tree, {finite, finite}).hit);
  CHECK(answerer::overlapping_pairs({{{0, 0, 0}, 0}, {{0, 0, 0}, 0}}).pairs.size() == 1);
  // Step 7's trees are not checked (that would cost what they save); trees without nodes
  // (meshes without triangles) have no pair and cost no test.
  const BvhRun none = bvh_counted(ObbTree{}, judge::obb_tree(lean_and_stand(), 0), true);
  CHECK(none.answer.pairs.empty());
  CHECK(none.box_calls == 0);
}

// Step 2's count rule, for a segment lying in a triangle's plane: any answer about such a
// triangle passes, and the given test's t for it may lie anywhere (CI's sweep, seed 808:
// a t just before the segment enters the leaf's cell). A search that stops at that hit
// may still have searched the leaf that lists the triangle.
TEST_CASE("L06 step 2's judge: a hit in doubt bounds the search only as well as its t", "[lab06][contract]") {
  const Triangle flat{{0, 2, 0}, {1, 3, -2}, {0, 3, -1}};  // in the plane x + y + z = 2
  const TreeQuery in{mesh_of({flat}), {{-1, 1.5, 1.5}, {1, 2.5, -1.5}}, 0};
  const KdTree one_leaf = judge::tree_of(in.mesh, {{0, 2, -2}, {1, 3, 0}}, {{0, kLeaf, 0}}, {1, 0});
  KdHit got;
  got.hit = true, got.triangle = 0, got.t = 0.25, got.tests = 1;  // the cell starts at t = 0.5
  CHECK(judge::first_hit(in, one_leaf, got, 1, Rules::random).verdict != Outcome::Verdict::fail);
  CHECK(judge::any_hit(in, one_leaf, got, 1, Rules::random).verdict != Outcome::Verdict::fail);
  got.tests = 2;  // the leaf lists one triangle
  CHECK(judge::first_hit(in, one_leaf, got, 2, Rules::random).verdict == Outcome::Verdict::fail);
}

// ---- Figures (not a graded step) ----------------------------------------------------------------
// Primitive tests per query on 10k, 100k and 1M triangles, against brute force (every
// triangle once). Hidden: run it with
//   LABKIT_ANSWERER=build/answer_06_spatial_trees_reference build/test_06_spatial_trees "[lab06-figures]"
// It counts calls of given::segment_triangle; it times nothing.
TEST_CASE("L06 figures: primitive tests per query", "[.][lab06-figures]") {
  const int segments = 1000;
  std::printf("%-8s %9s | %-24s | %-24s | %-24s | %-24s\n", "mesh", "triangles", "short first_hit mean/worst",
              "short any_hit mean/worst", "long first_hit mean/worst", "long all_hits mean/worst");
  for (int size : {10000, 100000, 1000000})
    for (int kind = 0; kind < 4; ++kind) {
      const Mesh mesh = gen::mesh_of_kind(gen::MeshKind(kind), size, 1);
      const KdTree tree = answerer::build_kd_tree(mesh);
      Tally tallies[4];
      for (bool short_ones : {true, false})
        for (const Segment& s : efficiency_segments(mesh, segments, short_ones, 7 + short_ones)) {
          if (short_ones) {
            tallies[0].add(answerer::first_hit(tree, s).tests);
            tallies[1].add(answerer::any_hit(tree, s).tests);
          } else {
            tallies[2].add(answerer::first_hit(tree, s).tests);
            tallies[3].add(answerer::all_hits(tree, s).tests);
          }
        }
      const auto cell = [](const Tally& t) {
        char text[64];
        std::snprintf(text, sizeof text, "%.1f / %d", t.mean(), t.worst);
        return std::string(text);
      };
      std::printf("%-8s %9zu | %-24s | %-24s | %-24s | %-24s   (brute force: %zu per query; %zu nodes, %zu items)\n",
                  gen::name_of(gen::MeshKind(kind)), mesh.size(), cell(tallies[0]).c_str(), cell(tallies[1]).c_str(),
                  cell(tallies[2]).c_str(), cell(tallies[3]).c_str(), mesh.size(), tree.nodes.size(),
                  tree.items.size());
      std::fflush(stdout);
    }
  SUCCEED();
}
