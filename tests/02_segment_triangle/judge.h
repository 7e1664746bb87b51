// Lab 02's checker: the generators that draw each query's input, then the verdicts.
//
// Lab 02's verdicts: each judge compares one answer with the exact oracle, following the
// tolerances and degenerate rules of labs/02_segment_triangle/segment_triangle.h. The
// tests and the viewer both use them, so a red mark in the viewer and a failing case in
// `./labkit check` always agree. The inputs are in tests/02_segment_triangle/queries.h,
// their random draws below.
//
// The generators come first in this file (gen::). Lab 02's own random inputs, beside the
// shared segment-triangle and mesh families (common/generators/generators.h, needles.h):
// points in a triangle's plane, meshes moving rigidly, and two meshes translating toward
// a contact.
#pragma once

#include "02_segment_triangle/queries.h"
#include "common/generators/needles.h"
#include "common/harness/check.h"

#include <vector>

namespace labkit::gen {

// Inputs for the point-in-triangle steps: points exactly in the triangle's plane, many
// of them exactly on an edge or a vertex, or a tiny step inside or outside one.
rc::Gen<lab02::PointTriangle> point_triangle();
// The same on integer coordinates: exact input for the robustness step.
rc::Gen<lab02::PointTriangle> exact_point_triangle();
rc::Gen<lab02::MovingMesh> moving_mesh();
// Two small meshes (tetrahedra, tents, single triangles) apart at t = 0, aimed so that a
// chosen vertex-face or edge-edge pair meets at a chosen time, or passing just beside
// it, or stopping short: decisive, at every scale of the header.
rc::Gen<lab02::MovingMeshes> moving_meshes();
// The same meshes on integers, apart at t = 0 and aimed exactly: a vertex onto a vertex,
// an edge or a face, an edge onto an edge (at its end or its middle), touching exactly
// at t = 1, two flat triangles sliding in one plane, or no relative motion. Every
// number is a small integer over a power of two: exact input for the robustness step.
rc::Gen<lab02::MovingMeshes> exact_moving_meshes();

}  // namespace labkit::gen

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
