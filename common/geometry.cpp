#include "common/geometry.h"

#include <algorithm>
#include <set>

namespace labkit {

std::vector<std::array<int, 2>> Mesh::edges() const {
  std::set<std::array<int, 2>> found;
  for (const auto& tri : triangles)
    for (int i = 0; i < 3; ++i) {
      const int u = tri[std::size_t(i)], v = tri[std::size_t((i + 1) % 3)];
      if (u != v) found.insert({std::min(u, v), std::max(u, v)});
    }
  return {found.begin(), found.end()};
}

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
