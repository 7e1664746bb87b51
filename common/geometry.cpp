#include "common/geometry.h"

#include <algorithm>

namespace labkit {

double scale_of(std::initializer_list<Vec3> points) {
  double s = 0.0;
  for (const Vec3& p : points) s = std::max(s, p.cwiseAbs().maxCoeff());
  return s;
}

double scale_of(const Mesh& mesh) {
  double s = 0.0;
  for (const Vec3& p : mesh.vertices) s = std::max(s, p.cwiseAbs().maxCoeff());
  return s;
}

}  // namespace labkit
