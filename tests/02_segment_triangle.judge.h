// Lab 02's verdicts: each judge compares one answer with the exact oracle, following
// the tolerances and degenerate rules of labs/02_segment_triangle/segment_triangle.h.
// The tests and the viewer both use them, so a red mark in the viewer and a failing
// case in `./labkit check` always agree.
#pragma once

#include "02_segment_triangle.wire.h"

#include "common/generators/needles.h"
#include "common/harness/check.h"

#include <vector>

namespace labkit::lab02 {

// Inputs list their fields, so that reports can print them (answers: the wire header).
struct PointTriangle {
  Vec3 x = Vec3::Zero();
  Triangle triangle;
};
template <class V> void fields(PointTriangle& p, V&& v) { v("x", p.x); v("triangle", p.triangle); }

struct MovingMesh {
  Segment segment;
  Mesh mesh;
  RigidTransform m0 = RigidTransform::Identity();
  RigidTransform m1 = RigidTransform::Identity();
};
template <class V> void fields(MovingMesh& m, V&& v) {
  v("segment", m.segment); v("mesh", m.mesh); v("m0", m.m0); v("m1", m.m1);
}

// Step 7: two meshes, each moving by a translation over [0, 1].
struct MovingMeshes {
  Mesh a;
  Vec3 velocity_a = Vec3::Zero();
  Mesh b;
  Vec3 velocity_b = Vec3::Zero();
};
template <class V> void fields(MovingMeshes& m, V&& v) {
  v("a", m.a); v("velocity_a", m.velocity_a); v("b", m.b); v("velocity_b", m.velocity_b);
}

namespace judge {

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

// Inputs for the point-in-triangle steps: points exactly in the triangle's plane, many
// of them exactly on an edge or a vertex, or a tiny step inside or outside one.
rc::Gen<PointTriangle> point_triangle();
// The same on integer coordinates: exact input for the robustness step.
rc::Gen<PointTriangle> exact_point_triangle();
rc::Gen<MovingMesh> moving_mesh();
// Two small meshes (tetrahedra, tents, single triangles) apart at t = 0, aimed so that a
// chosen vertex-face or edge-edge pair meets at a chosen time, or passing just beside
// it, or stopping short: decisive, at every scale of the header.
rc::Gen<MovingMeshes> moving_meshes();

}  // namespace judge
}  // namespace labkit::lab02
