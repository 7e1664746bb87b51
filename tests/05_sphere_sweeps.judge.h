// Lab 05's verdicts: each judge compares one answer with the exact oracle, following the
// tolerances and degenerate rules of labs/05_sphere_sweeps/sphere_sweeps.h. The tests
// and the viewer both use them.
#pragma once

#include "05_sphere_sweeps.wire.h"

#include "common/generators/05_sphere_sweeps.h"
#include "common/harness/check.h"

#include <string>

namespace labkit::lab05 {

std::string describe(SweepStatus s);

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

namespace judge {

using check::Outcome;

using check::Rules;  // random cases, or a robustness step's exact input

// The header's S for each input, and tol = 1e-9 S.
double scale(const PointSegmentPair& in);
double scale(const SegmentPair& in);
double scale(const PointRectanglePair& in);
double scale(const SegmentRectanglePair& in);
double scale(const RectanglePair& in);
double scale(const SpherePlaneMotion& in);
double scale(const SphereSphereMotion& in);
double scale(const SphereCapsuleMotion& in);
double scale(const BoxPlaneMotion& in);

Outcome point_segment(const PointSegmentPair& in, const PointSegmentDistance& got);
Outcome segment_segment(const SegmentPair& in, const SegmentSegmentDistance& got);
Outcome point_rectangle(const PointRectanglePair& in, const PointRectangleDistance& got);
Outcome segment_rectangle(const SegmentRectanglePair& in, const SegmentRectangleDistance& got);
Outcome rectangle_rectangle(const RectanglePair& in, const RectangleRectangleDistance& got);

Outcome test_pair(const SpherePair& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const SphereCapsule& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const SphereLozenge& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const CapsulePair& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const CapsuleLozenge& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const LozengePair& in, bool got, Rules rules = Rules::random);

Outcome sweep_sphere_plane(const SpherePlaneMotion& in, const Sweep& got, Rules rules = Rules::random);
Outcome sweep_sphere_sphere(const SphereSphereMotion& in, const Sweep& got, Rules rules = Rules::random);
Outcome sweep_sphere_capsule(const SphereCapsuleMotion& in, const Sweep& got, Rules rules = Rules::random);
Outcome sweep_box_plane(const BoxPlaneMotion& in, const Sweep& got, Rules rules = Rules::random);

// Step 3's inputs: the cores of the distance steps with radii chosen around their exact
// distance (exactly touching, a hair inside or outside at every scale, or anything);
// `exact`: small integers, with exactly touching pairs built from cores that lie in two
// parallel planes h apart over a common point.
rc::Gen<SpherePair> sphere_pair(bool exact = false);
rc::Gen<SphereCapsule> sphere_capsule(bool exact = false);
rc::Gen<SphereLozenge> sphere_lozenge(bool exact = false);
rc::Gen<CapsulePair> capsule_pair(bool exact = false);
rc::Gen<CapsuleLozenge> capsule_lozenge(bool exact = false);
rc::Gen<LozengePair> lozenge_pair(bool exact = false);

}  // namespace judge
}  // namespace labkit::lab05
