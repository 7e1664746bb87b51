// Given code: a watertight segment-triangle test for the labs that use one as a
// building block (06 spatial trees, 07 particles). Lab 02 has you derive your own from
// the lecture; this one is a different method (Woop, Benthin and Wald, "Watertight
// Ray/Triangle Intersection", JCGT 2013), used here as a ready tool.
//
// Watertight: the three edge functions are computed from the edge's two vertices only,
// so two triangles sharing an edge agree on it, and a segment through a shared edge or
// vertex hits at least one of them: nothing slips through a closed mesh. Edges and
// vertices count as hits (closed triangles). A segment lying in the triangle's plane,
// a zero-length segment and a zero-area triangle do not hit.
#pragma once

#include "common/fields.h"
#include "common/geometry.h"

#include <cstdint>

namespace labkit::given {

struct SegmentHit {
  bool hit = false;
  double t = 0.0;  // the point is a + t (b - a), 0 <= t <= 1
  Vec3 point = Vec3::Zero();
  Vec3 barycentric = Vec3::Zero();  // weights of v0, v1, v2, summing to 1
};

SegmentHit segment_triangle(const Segment& segment, const Triangle& triangle);

LABKIT_FIELDS(SegmentHit, hit, t, point, barycentric)

// How many times segment_triangle has run in this process, on this thread: what the
// viewer shows next to a query. The checker never reads it: in a graded or checked run
// the test is served by the judge's process, which counts the calls itself (served.h).
std::uint64_t segment_triangle_calls();

}  // namespace labkit::given
