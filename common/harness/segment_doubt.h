// Doubt about whether a segment meets a triangle, for the judges of labs 02, 06 and 07.
// Each lab has its own hit rule (closed triangle, two-sided sheet, crossing); the doubt
// around any of them is found the same way.
#pragma once

#include "common/harness/check.h"
#include "common/inputs/inputs.h"
#include "common/oracle/segment_triangle.h"

namespace labkit::check {

// Could moving the input by `tol` change what `hit` (a predicate on SegmentTrianglePair)
// answers? A triangle whose bounding box stays more than 8 tol from the segment's never
// is in doubt; a near one gets the oracle's conservative test, then sampling.
template <class Hit> bool segment_triangle_in_doubt(const Segment& s, const Triangle& tri, double tol, Hit&& hit) {
  const Vec3 low = s.a.cwiseMin(s.b).array() - 8 * tol, high = s.a.cwiseMax(s.b).array() + 8 * tol;
  const Vec3 tri_low = tri.v0.cwiseMin(tri.v1).cwiseMin(tri.v2), tri_high = tri.v0.cwiseMax(tri.v1).cwiseMax(tri.v2);
  if ((tri_low.array() > high.array()).any() || (tri_high.array() < low.array()).any()) return false;
  return oracle::segment_triangle_in_doubt(s, tri, tol) || flips_under_perturbation(SegmentTrianglePair{s, tri}, hit);
}

}  // namespace labkit::check
