// What the files of lab 01's judge share (tests/01_frustum_split/judge*.cpp): the kit's
// tolerance, the band of doubt around a plane, S of an input with planes, long double.
#pragma once

#include "judging.h"

#include "common/geometry.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

namespace labkit::lab01::judge {

using judging::kRelative;             // tol = 1e-9 S (the header's tolerances)
inline constexpr double kMargin = 8;  // ambiguous within 8 tol of a plane

using Long3 = Eigen::Matrix<long double, 3, 1>;
inline Long3 widen(const Vec3& v) { return v.cast<long double>(); }

// S: the largest |coordinate| of the points, and the planes' distances from the origin.
inline double scale_of_input(std::initializer_list<Vec3> points, const std::vector<Plane>& planes) {
  double s = scale_of(points);
  for (const Plane& p : planes) {
    const double length = p.normal.norm();
    if (length > 0) s = std::max(s, std::abs(p.offset) / length);
  }
  return std::max(s, 1e-300);
}

}  // namespace labkit::lab01::judge
