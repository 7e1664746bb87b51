// Lab 06 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer. A tree the student's code built
// crosses back with each query on it, as the numbers the header defines.
#pragma once

#include "spatial_trees.h"

#include "common/fields.h"
#include "common/given/segment_triangle.h"
#include "common/given/served.h"
#include "common/protocol/calls.h"

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
LABKIT_FIELDS(OctNode, cell, child, first, count)
LABKIT_FIELDS(Octree, nodes, items, spheres)
LABKIT_FIELDS(BallsInBox, balls, cell_tests, ball_tests)

using Indices = std::vector<int>;
using Spheres = std::vector<Sphere>;

// Step 8 asks thousands of queries of one tree of 10,000 triangles. They run in the
// answerer in one call, so that the tree crosses once. Each query is a part of the call
// (given::part): the judge's process counts the given::segment_triangle calls it served
// per part (remote::last_served()), 2 parts per segment, 3 with all_hits.
struct SegmentRun {
  KdHit first;
  KdHit any;
  int all_tests = -1;  // all_hits(tree, s).tests, when asked for
};
LABKIT_FIELDS(SegmentRun, first, any, all_tests)
using SegmentRuns = std::vector<SegmentRun>;
using Segments = std::vector<Segment>;

SegmentRuns run_segments(const KdTree& tree, const Segments& segments, bool with_all);

// Step 6: one SweepAndPrune fed the frames in turn, in the answerer (the object keeps its
// state there), each frame a part: the judge counts compare_ends and given_balls_meet per
// frame. The tests pair each frame's answer with its counts (SweepRun).
using SweepFrames = std::vector<SweepFrame>;
using Frames = std::vector<std::vector<Sphere>>;

SweepFrames run_sweep(const Frames& frames);

// A frame's answer and what the judge counted while the code answered it.
struct SweepRun {
  SweepFrame frame;
  long long comparisons = 0;  // compare_ends calls
  long long ball_tests = 0;   // given_balls_meet calls
};
using SweepRuns = std::vector<SweepRun>;

// Step 7: the dual traversal's answer and the given tests' calls the judge counted.
struct BvhRun {
  TrianglePairs answer;
  long long box_calls = 0;
  long long triangle_calls = 0;
};

// Step 12: the box query's answer and the given tests' calls the judge counted.
struct OctreeRun {
  BallsInBox answer;
  long long cell_calls = 0;
  long long ball_calls = 0;
};

// The judge serves and counts the lab's given tests (tests/06_spatial_trees/given.cpp).
void serve_given();
#define LABKIT_LAB_SERVED ::labkit::lab06::serve_given

#ifdef LABKIT_IN_ANSWERER
inline SegmentRuns run_segments(const KdTree& tree, const Segments& segments, bool with_all) {
  SegmentRuns runs;
  int part = 0;
  for (const Segment& s : segments) {
    SegmentRun r;
    given::part(part++);
    r.first = first_hit(tree, s);
    given::part(part++);
    r.any = any_hit(tree, s);
    if (with_all) {
      given::part(part++);
      r.all_tests = all_hits(tree, s).tests;
    }
    runs.push_back(r);
  }
  return runs;
}

inline SweepFrames run_sweep(const Frames& frames) {
  SweepAndPrune sweep;
  SweepFrames out;
  int part = 0;
  for (const std::vector<Sphere>& spheres : frames) {
    given::part(part++);
    out.push_back(sweep.update(spheres));
  }
  return out;
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
  CALL(SweepFrames, run_sweep, (const Frames&))                            \
  CALL(TrianglePairs, colliding_triangles, (const ObbTree&, const ObbTree&, bool)) \
  CALL(SpherePairs, hashed_pairs, (const Spheres&, double, int))                  \
  CALL(Octree, build_octree, (const Spheres&, int, int))                           \
  CALL(BallsInBox, balls_in_box, (const Octree&, const Aabb&))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab06, LABKIT_LAB06_CALLS)
