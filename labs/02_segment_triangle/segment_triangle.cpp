// Lab 02: segment against triangle and mesh. Your file: replace each stub below.
// The contract is segment_triangle.h; the steps are in handouts/02_segment_triangle.md.
// Check your work with:  ./labkit check 02        (one step: ./labkit check 02 --step 1)
#include "segment_triangle.h"

#include "common/not_implemented.h"

namespace labkit::lab02 {

// L02S1: signed distances of a and b, and the crossing point.
PlaneCrossing segment_plane(const Segment& segment, const Triangle& triangle) {
  not_implemented("L02S1", segment, triangle);
}

// L02S2: the three edge tests.
bool point_in_triangle_edges(const Vec3& x, const Triangle& triangle) { not_implemented("L02S2", x, triangle); }

// L02S3: alpha and beta in the plane with one coordinate dropped.
Barycentric barycentric(const Vec3& x, const Triangle& triangle) { not_implemented("L02S3", x, triangle); }

// L02S3: the containment test from alpha and beta.
bool point_in_triangle_barycentric(const Vec3& x, const Triangle& triangle) { not_implemented("L02S3", x, triangle); }

// L02S4: yes or no.
bool test_segment_triangle(const Segment& segment, const Triangle& triangle) {
  not_implemented("L02S4", segment, triangle);
}

// L02S4: where and when.
SegmentTriangleHit find_segment_triangle(const Segment& segment, const Triangle& triangle) {
  not_implemented("L02S4", segment, triangle);
}

// L02S5: the nearest hit along the segment.
MeshHit first_hit(const Segment& segment, const Mesh& mesh) { not_implemented("L02S5", segment, mesh); }

// L02S5: any hit at all.
bool any_hit(const Segment& segment, const Mesh& mesh) { not_implemented("L02S5", segment, mesh); }

// L02S5: every hit, sorted by t.
std::vector<MeshHit> all_hits(const Segment& segment, const Mesh& mesh) { not_implemented("L02S5", segment, mesh); }

// L02S6: the delta matrix.
MeshHit first_hit_moving(const Segment& segment, const Mesh& mesh, const RigidTransform& m0, const RigidTransform& m1) {
  not_implemented("L02S6", segment, mesh, m0, m1);
}

// L02S7: vertex paths against faces, both ways, and swept edges against edges.
MeshContact first_contact_moving_meshes(const Mesh& a, const Vec3& velocity_a, const Mesh& b, const Vec3& velocity_b) {
  not_implemented("L02S7", a, velocity_a, b, velocity_b);
}

}  // namespace labkit::lab02
