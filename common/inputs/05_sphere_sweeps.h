// Lab 05's inputs: what each query of sphere_sweeps.h is given, one struct per query, and
// their fields() (the names a report prints and a replay token reads). The generators
// (common/generators/05_sphere_sweeps.h) draw them, the judge and the viewer read them.
#pragma once

#include "sphere_sweeps.h"

namespace labkit {

struct PointSegmentPair {
  Vec3 p = Vec3::Zero();
  Segment segment;
};
template <class V> void fields(PointSegmentPair& x, V&& v) { v("p", x.p); v("segment", x.segment); }

struct SegmentPair {
  Segment first, second;
};
template <class V> void fields(SegmentPair& x, V&& v) { v("first", x.first); v("second", x.second); }

struct PointRectanglePair {
  Vec3 p = Vec3::Zero();
  Rectangle rectangle;
};
template <class V> void fields(PointRectanglePair& x, V&& v) { v("p", x.p); v("rectangle", x.rectangle); }

struct SegmentRectanglePair {
  Segment segment;
  Rectangle rectangle;
};
template <class V> void fields(SegmentRectanglePair& x, V&& v) { v("segment", x.segment); v("rectangle", x.rectangle); }

struct RectanglePair {
  Rectangle first, second;
};
template <class V> void fields(RectanglePair& x, V&& v) { v("first", x.first); v("second", x.second); }

// Moving shapes: centre + t velocity for t in [0, duration].
struct SpherePlaneMotion {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
  double duration = 1.0;
};
template <class V> void fields(SpherePlaneMotion& x, V&& v) {
  v("sphere", x.sphere); v("velocity", x.velocity); v("plane", x.plane); v("duration", x.duration);
}

struct SphereSphereMotion {
  Sphere s0;
  Vec3 v0 = Vec3::Zero();
  Sphere s1;
  Vec3 v1 = Vec3::Zero();
  double duration = 1.0;
};
template <class V> void fields(SphereSphereMotion& x, V&& v) {
  v("s0", x.s0); v("v0", x.v0); v("s1", x.s1); v("v1", x.v1); v("duration", x.duration);
}

// A sphere moving against a static capsule (step 6).
struct SphereCapsuleMotion {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Capsule capsule;
  double duration = 1.0;
};
template <class V> void fields(SphereCapsuleMotion& x, V&& v) {
  v("sphere", x.sphere); v("velocity", x.velocity); v("capsule", x.capsule); v("duration", x.duration);
}

struct BoxPlaneMotion {
  Box box;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
  double duration = 1.0;
};
template <class V> void fields(BoxPlaneMotion& x, V&& v) {
  v("box", x.box); v("velocity", x.velocity); v("plane", x.plane); v("duration", x.duration);
}

}  // namespace labkit

namespace labkit::lab05 {

// Step 3's inputs: two sphere-swept volumes.
struct SpherePair { Sphere a, b; };
struct SphereCapsule { Sphere a; Capsule b; };
struct SphereLozenge { Sphere a; Lozenge b; };
struct CapsulePair { Capsule a, b; };
struct CapsuleLozenge { Capsule a; Lozenge b; };
struct LozengePair { Lozenge a, b; };
template <class V> void fields(SpherePair& x, V&& v) { v("a", x.a); v("b", x.b); }
template <class V> void fields(SphereCapsule& x, V&& v) { v("a", x.a); v("b", x.b); }
template <class V> void fields(SphereLozenge& x, V&& v) { v("a", x.a); v("b", x.b); }
template <class V> void fields(CapsulePair& x, V&& v) { v("a", x.a); v("b", x.b); }
template <class V> void fields(CapsuleLozenge& x, V&& v) { v("a", x.a); v("b", x.b); }
template <class V> void fields(LozengePair& x, V&& v) { v("a", x.a); v("b", x.b); }

}  // namespace labkit::lab05
