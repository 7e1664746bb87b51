// Lab 05's inputs: what each query of sphere_sweeps.h is given, one struct per query, and
// their fields() (the names a report prints and a replay token reads). The generators
// (common/generators/05_sphere_sweeps.h) draw them, the judge and the viewer read them.
#pragma once

#include "sphere_sweeps.h"

#include "common/harness/query.h"

namespace labkit {

struct PointSegmentPair {
  Vec3 p = Vec3::Zero();
  Segment segment;
};
template <class V> void fields(PointSegmentPair& x, V&& v) {
  v("p", x.p);
  v("segment", x.segment);
}

struct SegmentPair {
  Segment first, second;
};
template <class V> void fields(SegmentPair& x, V&& v) {
  v("first", x.first);
  v("second", x.second);
}

struct PointRectanglePair {
  Vec3 p = Vec3::Zero();
  Rectangle rectangle;
};
template <class V> void fields(PointRectanglePair& x, V&& v) {
  v("p", x.p);
  v("rectangle", x.rectangle);
}

struct SegmentRectanglePair {
  Segment segment;
  Rectangle rectangle;
};
template <class V> void fields(SegmentRectanglePair& x, V&& v) {
  v("segment", x.segment);
  v("rectangle", x.rectangle);
}

struct RectanglePair {
  Rectangle first, second;
};
template <class V> void fields(RectanglePair& x, V&& v) {
  v("first", x.first);
  v("second", x.second);
}

// Moving shapes: centre + t velocity for t in [0, duration].
struct SpherePlaneMotion {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
  double duration = 1.0;
};
template <class V> void fields(SpherePlaneMotion& x, V&& v) {
  v("sphere", x.sphere);
  v("velocity", x.velocity);
  v("plane", x.plane);
  v("duration", x.duration);
}

struct SphereSphereMotion {
  Sphere s0;
  Vec3 v0 = Vec3::Zero();
  Sphere s1;
  Vec3 v1 = Vec3::Zero();
  double duration = 1.0;
};
template <class V> void fields(SphereSphereMotion& x, V&& v) {
  v("s0", x.s0);
  v("v0", x.v0);
  v("s1", x.s1);
  v("v1", x.v1);
  v("duration", x.duration);
}

// A sphere moving against a static capsule (step 6).
struct SphereCapsuleMotion {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Capsule capsule;
  double duration = 1.0;
};
template <class V> void fields(SphereCapsuleMotion& x, V&& v) {
  v("sphere", x.sphere);
  v("velocity", x.velocity);
  v("capsule", x.capsule);
  v("duration", x.duration);
}

struct BoxPlaneMotion {
  Box box;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
  double duration = 1.0;
};
template <class V> void fields(BoxPlaneMotion& x, V&& v) {
  v("box", x.box);
  v("velocity", x.velocity);
  v("plane", x.plane);
  v("duration", x.duration);
}

}  // namespace labkit

namespace labkit::lab05 {

// Step 3's inputs: two sphere-swept volumes.
struct SpherePair {
  Sphere a, b;
};
struct SphereCapsule {
  Sphere a;
  Capsule b;
};
struct SphereLozenge {
  Sphere a;
  Lozenge b;
};
struct CapsulePair {
  Capsule a, b;
};
struct CapsuleLozenge {
  Capsule a;
  Lozenge b;
};
struct LozengePair {
  Lozenge a, b;
};
template <class V> void fields(SpherePair& x, V&& v) {
  v("a", x.a);
  v("b", x.b);
}
template <class V> void fields(SphereCapsule& x, V&& v) {
  v("a", x.a);
  v("b", x.b);
}
template <class V> void fields(SphereLozenge& x, V&& v) {
  v("a", x.a);
  v("b", x.b);
}
template <class V> void fields(CapsulePair& x, V&& v) {
  v("a", x.a);
  v("b", x.b);
}
template <class V> void fields(CapsuleLozenge& x, V&& v) {
  v("a", x.a);
  v("b", x.b);
}
template <class V> void fields(LozengePair& x, V&& v) {
  v("a", x.a);
  v("b", x.b);
}

}  // namespace labkit::lab05

// ---- The queries -------------------------------------------------------------------------
// The name of each question the tests ask (a replay token's prefix) and the input it takes,
// by the step that asks it first. The tests, the viewer's scene and its presets read this
// table (common/harness/query.h): a query is added or renamed here and nowhere else.
#define LABKIT_LAB05_QUERIES(X)                                                      \
  /* step 1 */                                                                       \
  X(point_segment, "point_segment", PointSegmentPair)                                \
  X(segment_segment, "segment_segment", SegmentPair)                                 \
  /* step 2 */                                                                       \
  X(point_rectangle, "point_rectangle", PointRectanglePair)                          \
  X(segment_rectangle, "segment_rectangle", SegmentRectanglePair)                    \
  X(rectangle_rectangle, "rectangle_rectangle", RectanglePair)                       \
  /* step 3 */                                                                       \
  X(test_sphere_sphere, "test_sphere_sphere", SpherePair)                            \
  X(test_sphere_capsule, "test_sphere_capsule", SphereCapsule)                       \
  X(test_sphere_lozenge, "test_sphere_lozenge", SphereLozenge)                       \
  X(test_capsule_capsule, "test_capsule_capsule", CapsulePair)                       \
  X(test_capsule_lozenge, "test_capsule_lozenge", CapsuleLozenge)                    \
  X(test_lozenge_lozenge, "test_lozenge_lozenge", LozengePair)                       \
  /* step 4 */                                                                       \
  X(sweep_sphere_plane, "sweep_sphere_plane", SpherePlaneMotion)                     \
  /* step 5 */                                                                       \
  X(sweep_sphere_sphere, "sweep_sphere_sphere", SphereSphereMotion)                  \
  X(sweep_sphere_sphere_soon, "sweep_sphere_sphere.soon", SphereSphereMotion)        \
  X(sweep_sphere_sphere_grazing, "sweep_sphere_sphere.grazing", SphereSphereMotion)  \
  /* step 6 */                                                                       \
  X(sweep_sphere_capsule, "sweep_sphere_capsule", SphereCapsuleMotion)               \
  /* step 7 */                                                                       \
  X(sweep_box_plane, "sweep_box_plane", BoxPlaneMotion)                              \
  /* step 8 */                                                                       \
  X(robust_segment_segment, "robust.segment_segment", SegmentPair)                   \
  X(robust_segment_rectangle, "robust.segment_rectangle", SegmentRectanglePair)      \
  X(robust_test_sphere_capsule, "robust.test_sphere_capsule", SphereCapsule)         \
  X(robust_test_capsule_capsule, "robust.test_capsule_capsule", CapsulePair)         \
  X(robust_test_capsule_lozenge, "robust.test_capsule_lozenge", CapsuleLozenge)      \
  X(robust_test_lozenge_lozenge, "robust.test_lozenge_lozenge", LozengePair)         \
  X(robust_sweep_sphere_plane, "robust.sweep_sphere_plane", SpherePlaneMotion)       \
  X(robust_sweep_sphere_sphere, "robust.sweep_sphere_sphere", SphereSphereMotion)    \
  X(robust_sweep_sphere_capsule, "robust.sweep_sphere_capsule", SphereCapsuleMotion) \
  X(robust_sweep_box_plane, "robust.sweep_box_plane", BoxPlaneMotion)

namespace labkit::lab05::query {
LABKIT_LAB05_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB05_QUERIES)
}  // namespace labkit::lab05::query
