// What the files of lab 05's judge share (tests/05_sphere_sweeps/judge*.cpp): the kit's
// tolerance and the plane helper both the scales and the sweeps' reports use.
#pragma once

#include "judging.h"

#include "common/geometry.h"

#include <cmath>

namespace labkit::lab05::judge {

using judging::kRelative;  // tol = 1e-9 S (the header's tolerances)

// The plane with its normal scaled by a power of two (largest component in [1, 2)): the
// same plane, whose |n|^2 neither overflows nor underflows.
inline Plane scaled(const Plane& p) {
  const int e = std::ilogb(p.normal.cwiseAbs().maxCoeff());
  return {Vec3(std::ldexp(p.normal.x(), -e), std::ldexp(p.normal.y(), -e), std::ldexp(p.normal.z(), -e)),
          std::ldexp(p.offset, -e)};
}

}  // namespace labkit::lab05::judge
