// Lab 02's inputs beyond the shared pairs (common/inputs/inputs.h): each query's
// arguments as one struct, whose fields() let reports print it and replay tokens carry it
// (the answers' fields are in tests/02_segment_triangle.wire.h).
#pragma once

#include "segment_triangle.h"

#include "common/inputs/inputs.h"

namespace labkit::lab02 {

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

}  // namespace labkit::lab02
