// Lab 06 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer. A tree the student's code built
// crosses back with each query on it, as the numbers the header defines.
#pragma once

#include "spatial_trees.h"

#include "common/given/segment_triangle.h"

#include <vector>

namespace labkit::lab06 {

template <class V> void fields(KdNode& n, V&& v) {
  v("split", n.split);
  v("axis", n.axis);
  v("index", n.index);
}
template <class V> void fields(KdTree& t, V&& v) {
  v("bounds", t.bounds);
  v("nodes", t.nodes);
  v("items", t.items);
  v("triangles", t.triangles);
}
template <class V> void fields(KdHit& h, V&& v) {
  v("hit", h.hit);
  v("triangle", h.triangle);
  v("t", h.t);
  v("point", h.point);
  v("barycentric", h.barycentric);
  v("tests", h.tests);
}
template <class V> void fields(KdHits& h, V&& v) {
  v("hits", h.hits);
  v("tests", h.tests);
}
template <class V> void fields(BspPiece& p, V&& v) {
  v("triangle", p.triangle);
  v("source", p.source);
}
template <class V> void fields(BspNode& n, V&& v) {
  v("plane", n.plane);
  v("front", n.front);
  v("back", n.back);
  v("first", n.first);
  v("count", n.count);
}
template <class V> void fields(BspTree& t, V&& v) {
  v("nodes", t.nodes);
  v("pieces", t.pieces);
  v("triangles", t.triangles);
}
template <class V> void fields(SpherePairs& p, V&& v) {
  v("pairs", p.pairs);
  v("tests", p.tests);
}
template <class V> void fields(ObbNode& n, V&& v) {
  v("box", n.box);
  v("left", n.left);
  v("right", n.right);
  v("first", n.first);
  v("count", n.count);
}
template <class V> void fields(ObbTree& t, V&& v) {
  v("nodes", t.nodes);
  v("items", t.items);
  v("triangles", t.triangles);
}
template <class V> void fields(TrianglePairs& p, V&& v) {
  v("pairs", p.pairs);
  v("box_tests", p.box_tests);
  v("triangle_tests", p.triangle_tests);
}
template <class V> void fields(SweepFrame& f, V&& v) {
  v("pairs", f.pairs);
  v("tests", f.tests);
  v("swaps", f.swaps);
}

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
template <class V> void fields(SegmentRun& r, V&& v) {
  v("first", r.first);
  v("first_calls", r.first_calls);
  v("any", r.any);
  v("any_calls", r.any_calls);
  v("all_tests", r.all_tests);
}
using SegmentRuns = std::vector<SegmentRun>;
using Segments = std::vector<Segment>;

SegmentRuns run_segments(const KdTree& tree, const Segments& segments, bool with_all);

// Step 6: one SweepAndPrune fed the frames in turn, in the answerer (the object keeps its
// state there); the calls of compare_ends are counted around each update.
struct SweepRun {
  SweepFrame frame;
  long long comparisons = 0;
};
template <class V> void fields(SweepRun& r, V&& v) {
  v("frame", r.frame);
  v("comparisons", r.comparisons);
}
using SweepRuns = std::vector<SweepRun>;
using Frames = std::vector<std::vector<Sphere>>;

SweepRuns run_sweep(const Frames& frames);

// Step 7: the dual traversal, with the given tests' calls counted around it.
struct BvhRun {
  TrianglePairs answer;
  long long box_calls = 0;
  long long triangle_calls = 0;
};
template <class V> void fields(BvhRun& r, V&& v) {
  v("answer", r.answer);
  v("box_calls", r.box_calls);
  v("triangle_calls", r.triangle_calls);
}

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
