// Lab 05: sphere-swept volumes, static and moving. Your file: replace each stub below.
// The contract is sphere_sweeps.h; the steps are in handouts/05_sphere_sweeps.md.
// Check your work with:  ./labkit check 05        (one step: ./labkit check 05 --step 1)
#include "sphere_sweeps.h"

#include "common/not_implemented.h"

namespace labkit::lab05 {

// L05S1: project, clamp, measure.
PointSegmentDistance point_segment(const Vec3& p, const Segment& segment) { not_implemented("L05S1", p, segment); }

// L05S1: the lines' closest points, then the four ends; parallel segments too.
SegmentSegmentDistance segment_segment(const Segment& first, const Segment& second) {
  not_implemented("L05S1", first, second);
}

// L05S2: rectangle coordinates, clamped to the half-sizes.
PointRectangleDistance point_rectangle(const Vec3& p, const Rectangle& rectangle) {
  not_implemented("L05S2", p, rectangle);
}

// L05S2: through the rectangle, or the ends against it and the segment against its sides.
SegmentRectangleDistance segment_rectangle(const Segment& segment, const Rectangle& rectangle) {
  not_implemented("L05S2", segment, rectangle);
}

// L05S2: the eight sides, each against the other rectangle.
RectangleRectangleDistance rectangle_rectangle(const Rectangle& first, const Rectangle& second) {
  not_implemented("L05S2", first, second);
}

// L05S3: table 6.1, one distance per pair, against r0 + r1.
bool test_sphere_sphere(const Sphere& a, const Sphere& b) { not_implemented("L05S3", a, b); }

bool test_sphere_capsule(const Sphere& a, const Capsule& b) { not_implemented("L05S3", a, b); }

bool test_sphere_lozenge(const Sphere& a, const Lozenge& b) { not_implemented("L05S3", a, b); }

bool test_capsule_capsule(const Capsule& a, const Capsule& b) { not_implemented("L05S3", a, b); }

bool test_capsule_lozenge(const Capsule& a, const Lozenge& b) { not_implemented("L05S3", a, b); }

bool test_lozenge_lozenge(const Lozenge& a, const Lozenge& b) { not_implemented("L05S3", a, b); }

// L05S4: the centre's signed distance is linear in t.
Sweep sweep_sphere_plane(const Sphere& sphere, const Vec3& velocity, const Plane& plane, double duration) {
  not_implemented("L05S4", sphere, velocity, plane, duration);
}

// L05S5: the quadratic of relative motion, its special cases, and a stable root.
Sweep sweep_sphere_sphere(const Sphere& s0, const Vec3& v0, const Sphere& s1, const Vec3& v1, double duration) {
  not_implemented("L05S5", s0, v0, s1, v1, duration);
}

// L05S6: the centre against the capsule grown by the sphere's radius: decide with
// step 3's test on the sphere's path, then the first of three roots (the cylinder's,
// clipped to the slab between the ends, and the two end spheres').
Sweep sweep_sphere_capsule(const Sphere& sphere, const Vec3& velocity, const Capsule& capsule, double duration) {
  not_implemented("L05S6", sphere, velocity, capsule, duration);
}

// L05S7: the projected radius, then step 4.
Sweep sweep_box_plane(const Box& box, const Vec3& velocity, const Plane& plane, double duration) {
  not_implemented("L05S7", box, velocity, plane, duration);
}

}  // namespace labkit::lab05
