// Lab 05's checker beyond its queries (queries.h declares the queries, their generators
// and their verdicts): what the lab's generators, judges, tests and viewer scene share.
#pragma once

#include "05_sphere_sweeps/queries.h"
#include "common/harness/check.h"
#include "common/harness/codec.h"
#include "common/oracle/sphere_sweeps.h"

#include <rapidcheck.h>
#include <string>

namespace labkit::lab05 {

// The exact distance between the cores of a pair (table 6.1's distance calculator): what
// step 3's generators place the radii around, and what its judge compares r0 + r1 with.
oracle::SquaredDistance core_distance(const SpherePair& p);
oracle::SquaredDistance core_distance(const SphereCapsule& p);
oracle::SquaredDistance core_distance(const SphereLozenge& p);
oracle::SquaredDistance core_distance(const CapsulePair& p);
oracle::SquaredDistance core_distance(const CapsuleLozenge& p);
oracle::SquaredDistance core_distance(const LozengePair& p);

}  // namespace labkit::lab05

namespace labkit::lab05 {

std::string describe(SweepStatus s);

namespace judge {

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

}  // namespace judge
}  // namespace labkit::lab05

namespace labkit {

// The header's S of the inputs whose S is not their largest length (a plane counts by its
// distance from the origin, not its normal's size): the domain check::in_domain keeps a
// shrunk case in.
inline double header_scale(const SpherePlaneMotion& in) { return lab05::judge::scale(in); }
inline double header_scale(const BoxPlaneMotion& in) { return lab05::judge::scale(in); }

}  // namespace labkit
