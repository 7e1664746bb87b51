// Lab 06 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer. A tree the student's code built
// crosses back with each query on it, as the numbers the header defines.
#pragma once

#include "spatial_trees.h"

#include "common/fields.h"
#include "common/given/segment_triangle.h"

#include <vector>

namespace labkit::lab06 {

LABKIT_FIELDS(KdNode, split, axis, index)
LABKIT_FIELDS(KdTree, bounds, nodes, items, triangles)
LABKIT_FIELDS(KdHit, hit, triangle, t, point, barycentric, tests)
LABKIT_FIELDS(KdHits, hits, tests)
LABKIT_FIELDS(BspPiece, triangle, source)
LABKIT_FIELDS(BspNode, plane, front, back, first, count)
LABKIT_FIELDS(BspTree, nodes, pieces, triangles)
LABKIT_FIELDS(SpherePairs, pairs, tests)
LABKIT_FIELDS(ObbNode, box, left, right, first, count)
LABKIT_FIELDS(ObbTree, nodes, items, triangles)
LABKIT_FIELDS(TrianglePairs, pairs, box_tests, triangle_tests)
LABKIT_FIELDS(SweepFrame, pairs, tests, swaps)

using Indices = std::vector<int>;
using Spheres = std::vector<Sphere>;

// Step 8 asks thousands of queries of one tree of 10,000 triangles. They run in the
// answerer in one call, so that the tree crosses once; each query's calls of
// given::segment_triangle are counted there, around it.
struct SegmentRun {
  KdHit first;
  int first_calls = 0;
  KdHit any;
  int any_calls = 0;
  int all_tests = -1;  // all_hits(tree, s).tests, when asked for
};
LABKIT_FIELDS(SegmentRun, first, first_calls, any, any_calls, all_tests)
using SegmentRuns = std::vector<SegmentRun>;
using Segments = std::vector<Segment>;

SegmentRuns run_segments(const KdTree& tree, const Segments& segments, bool with_all);

// Step 6: one SweepAndPrune fed the frames in turn, in the answerer (the object keeps its
// state there); the calls of compare_ends are counted around each update.
struct SweepRun {
  SweepFrame frame;
  long long comparisons = 0;
};
LABKIT_FIELDS(SweepRun, frame, comparisons)
using SweepRuns = std::vector<SweepRun>;
using Frames = std::vector<std::vector<Sphere>>;

SweepRuns run_sweep(const Frames& frames);

// Step 7: the dual traversal, with the given tests' calls counted around it.
struct BvhRun {
  TrianglePairs answer;
  long long box_calls = 0;
  long long triangle_calls = 0;
};
LABKIT_FIELDS(BvhRun, answer, box_calls, triangle_calls)

BvhRun run_bvh(const ObbTree& a, const ObbTree& b, bool every);

#ifdef LABKIT_IN_ANSWERER
inline SegmentRuns run_segments(const KdTree& tree, const Segments& segments, bool with_all) {
  SegmentRuns runs;
  for (const Segment& s : segments) {
    SegmentRun r;
    const std::uint64_t c0 = given::segment_triangle_calls();
    r.first = first_hit(tree, s);
    const std::uint64_t c1 = given::segment_triangle_calls();
    r.any = any_hit(tree, s);
    r.first_calls = int(c1 - c0);
    r.any_calls = int(given::segment_triangle_calls() - c1);
    if (with_all) r.all_tests = all_hits(tree, s).tests;
    runs.push_back(r);
  }
  return runs;
}

inline SweepRuns run_sweep(const Frames& frames) {
  SweepAndPrune sweep;
  SweepRuns runs;
  for (const std::vector<Sphere>& spheres : frames) {
    SweepRun r;
    const long long before = compare_ends_calls();
    r.frame = sweep.update(spheres);
    r.comparisons = compare_ends_calls() - before;
    runs.push_back(r);
  }
  return runs;
}

inline BvhRun run_bvh(const ObbTree& a, const ObbTree& b, bool every) {
  BvhRun r;
  const long long boxes = given_box_tests(), triangles = given_triangle_tests();
  r.answer = colliding_triangles(a, b, every);
  r.box_calls = given_box_tests() - boxes;
  r.triangle_calls = given_triangle_tests() - triangles;
  return r;
}
#endif

}  // namespace labkit::lab06

// clang-format off
#define LABKIT_LAB06_CALLS(CALL, METHOD)                                   \
  CALL(KdTree, build_kd_tree, (const Mesh&))                               \
  CALL(KdHit, first_hit, (const KdTree&, const Segment&))                  \
  CALL(KdHit, any_hit, (const KdTree&, const Segment&))                    \
  CALL(KdHits, all_hits, (const KdTree&, const Segment&))                  \
  CALL(BspTree, build_bsp, (const Mesh&))                                  \
  CALL(Where, classify, (const BspTree&, const Vec3&))                     \
  CALL(Indices, back_to_front, (const BspTree&, const Vec3&))              \
  CALL(SpherePairs, overlapping_pairs, (const Spheres&))                   \
  CALL(SegmentRuns, run_segments, (const KdTree&, const Segments&, bool)) \
  CALL(SweepRuns, run_sweep, (const Frames&))                              \
  CALL(BvhRun, run_bvh, (const ObbTree&, const ObbTree&, bool))
// clang-format on
