// Lab 05's verdicts: each judge compares one answer with the exact oracle, following the
// tolerances and degenerate rules of labs/05_sphere_sweeps/sphere_sweeps.h. The tests
// and the viewer both use them.
#pragma once

#include "05_sphere_sweeps/wire.h"

#include "05_sphere_sweeps/generators.h"
#include "05_sphere_sweeps/inputs.h"
#include "common/harness/check.h"

#include <string>

namespace labkit::lab05 {

std::string describe(SweepStatus s);

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

}  // namespace judge
}  // namespace labkit::lab05

namespace labkit {

// The header's S of the inputs whose S is not their largest length (a plane counts by its
// distance from the origin, not its normal's size): the domain check::in_domain keeps a
// shrunk case in.
inline double header_scale(const SpherePlaneMotion& in) { return lab05::judge::scale(in); }
inline double header_scale(const BoxPlaneMotion& in) { return lab05::judge::scale(in); }

}  // namespace labkit
