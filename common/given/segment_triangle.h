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

// How many times segment_triangle has run on this thread. The labs measure a search
// structure's efficiency by counting primitive tests, never by timing: a check reads
// this before and after a query.
std::uint64_t segment_triangle_calls();
// Adds calls made elsewhere: the judge's process adds those the answerer's process made
// for it (common/protocol/calls.h), so that counting around a call reads the same.
void count_segment_triangle_calls(std::uint64_t n);

}  // namespace labkit::given
