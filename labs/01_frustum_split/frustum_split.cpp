// Lab 01: view-frustum clipping by triangle splitting. Your file: replace each stub below.
// The contract is frustum_split.h; the steps are in handouts/01_frustum_split.md.
// Check your work with:  ./labkit check 01        (one step: ./labkit check 01 --step 1)
#include "frustum_split.h"

#include "common/not_implemented.h"

namespace labkit::lab01 {

// L01S1: the plane's value at x, over the length of its normal.
double signed_distance(const Plane& plane, const Vec3& x) { not_implemented("L01S1", plane, x); }

// L01S1: in, on or out, for each vertex.
std::array<Side, 3> classify(const Plane& plane, const Triangle& triangle) {
  not_implemented("L01S1", plane, triangle);
}

// L01S2: keep the part with value >= 0: the four configurations.
std::vector<Triangle> split_triangle(const Triangle& triangle, const Plane& plane) {
  not_implemented("L01S2", triangle, plane);
}

// L01S3: the six planes from the camera's parameters.
Frustum frustum_from_camera(const Camera& camera) { not_implemented("L01S3", camera); }

// L01S3: the six planes from the rows of a view-projection matrix.
Frustum frustum_from_matrix(const Mat4& view_projection) { not_implemented("L01S3", view_projection); }

// L01S4: one plane after the other.
std::vector<Triangle> clip_triangle(const Triangle& triangle, const Frustum& frustum) {
  not_implemented("L01S4", triangle, frustum);
}

// L01S5: every triangle, and a colour for every new vertex.
ClippedMesh clip_mesh(const ColoredMesh& mesh, const Frustum& frustum) { not_implemented("L01S5", mesh, frustum); }

}  // namespace labkit::lab01
