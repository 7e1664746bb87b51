// Lab 02's verdicts: each judge compares one answer with the exact oracle, following
// the tolerances and degenerate rules of labs/02_segment_triangle/segment_triangle.h.
// The tests and the viewer both use them, so a red mark in the viewer and a failing
// case in `./labkit check` always agree. The inputs are tests/02_segment_triangle/inputs.h,
// their random draws tests/02_segment_triangle/generators.h.
#pragma once

#include "02_segment_triangle/wire.h"

#include "02_segment_triangle/generators.h"
#include "02_segment_triangle/inputs.h"
#include "common/harness/check.h"

#include <vector>

namespace labkit::lab02::judge {

using check::Outcome;

using check::Rules;  // random cases, or a robustness step's exact input

Outcome segment_plane(const SegmentTrianglePair& in, const PlaneCrossing& got, Rules rules = Rules::random);
Outcome point_in_triangle(const PointTriangle& in, bool got, Rules rules = Rules::random);
Outcome barycentric(const PointTriangle& in, const Barycentric& got);
Outcome test_segment_triangle(const SegmentTrianglePair& in, bool got, Rules rules = Rules::random);
Outcome find_segment_triangle(const SegmentTrianglePair& in, const SegmentTriangleHit& got,
                              Rules rules = Rules::random);
Outcome any_hit(const SegmentMeshPair& in, bool got, Rules rules = Rules::random);
Outcome first_hit(const SegmentMeshPair& in, const MeshHit& got, Rules rules = Rules::random);
Outcome all_hits(const SegmentMeshPair& in, const std::vector<MeshHit>& got, Rules rules = Rules::random);
Outcome first_hit_moving(const MovingMesh& in, const MeshHit& got);
Outcome first_contact_moving_meshes(const MovingMeshes& in, const MeshContact& got, Rules rules = Rules::random);

}  // namespace labkit::lab02::judge
