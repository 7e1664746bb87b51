// The shared checks of invalid input (preconditions.h, which says what each one
// requires), compiled once with the geometry types.
#include "common/preconditions.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace labkit::preconditions {

std::string text(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string text(const Vec3& v) { return "(" + text(v.x()) + ", " + text(v.y()) + ", " + text(v.z()) + ")"; }

std::string text(int i) { return std::to_string(i); }

void reject(const std::string& query, const std::string& argument, const std::string& rule, const std::string& got) {
  throw std::invalid_argument(query + ": " + argument + " must " + rule + ", got " + got);
}

void require_finite(const char* query, const std::string& argument, double x) {
  require(std::isfinite(x), query, argument, "be finite", x);
}

void require_finite(const char* query, const std::string& argument, const Vec3& v) {
  require(v.allFinite(), query, argument, "be finite", v);
}

void require_size(const char* query, const std::string& argument, double x) {
  require(std::isfinite(x) && x >= 0, query, argument, "be finite and >= 0", x);
}

void require_positive(const char* query, const std::string& argument, double x) {
  require(std::isfinite(x) && x > 0, query, argument, "be finite and > 0", x);
}

void require_unit(const char* query, const std::string& argument, const Vec3& v) {
  require_finite(query, argument, v);
  require(std::abs(v.squaredNorm() - 1) <= 1e-6, query, argument, "have unit length", v);
}

void require_perpendicular(const char* query, const std::string& argument, const Vec3& a, const Vec3& b) {
  if (!(std::abs(a.dot(b)) <= 1e-6))
    reject(query, argument, "be perpendicular", text(a.dot(b)) + " for their dot product");
}

void require_orthonormal(const char* query, const std::string& argument, const Mat3& axes) {
  for (int i = 0; i < 3; ++i) {
    const std::string column = argument + ".col(" + std::to_string(i) + ")";
    require_unit(query, column, axes.col(i));
    for (int j = 0; j < i; ++j)
      require_perpendicular(query, argument + ".col(" + std::to_string(j) + ") and " + column, axes.col(j),
                            axes.col(i));
  }
}

void require_valid(const char* query, const std::string& name, const Segment& s) {
  if (s.a.allFinite() && s.b.allFinite()) return;
  require_finite(query, name + ".a", s.a);
  require_finite(query, name + ".b", s.b);
}

void require_valid(const char* query, const std::string& name, const Triangle& t) {
  if (t.v0.allFinite() && t.v1.allFinite() && t.v2.allFinite()) return;
  for (int k = 0; k < 3; ++k) require_finite(query, name + ".v" + std::to_string(k), t[k]);
}

void require_valid(const char* query, const std::string& name, const Sphere& s) {
  if (s.center.allFinite() && std::isfinite(s.radius) && s.radius >= 0) return;
  require_finite(query, name + ".center", s.center);
  require_size(query, name + ".radius", s.radius);
}

void require_valid(const char* query, const std::string& name, const Box& b) {
  const bool axes_fine =
      b.axes.allFinite() && (b.axes.transpose() * b.axes - Mat3::Identity()).cwiseAbs().maxCoeff() <= 1e-6;
  if (b.center.allFinite() && b.half_extents.allFinite() && (b.half_extents.array() >= 0).all() && axes_fine) return;
  require_finite(query, name + ".center", b.center);
  for (int i = 0; i < 3; ++i) require_size(query, name + ".half_extents[" + std::to_string(i) + "]", b.half_extents[i]);
  require_orthonormal(query, name + ".axes", b.axes);
}

void require_valid(const char* query, const std::string& name, const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite())
      require_finite(query, name + ".vertices[" + std::to_string(i) + "]", mesh.vertices[i]);
  const int count = int(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (const int v : mesh.triangles[i])
      if (!(v >= 0 && v < count))
        reject(query, name + ".triangles[" + std::to_string(i) + "]", "index vertices (0 to vertices.size() - 1)",
               text(v));
}

void require_valid(const char* query, const std::string& name, const RigidTransform& pose) {
  require(pose.matrix().allFinite(), query, name, "have finite entries", "a NaN or an infinity");
  const Mat3 r = pose.linear();
  const double off = (r.transpose() * r - Mat3::Identity()).cwiseAbs().maxCoeff();
  if (!(off <= 1e-6) || r.determinant() < 0)
    reject(query, name, "be rigid (a rotation and a translation)", "a linear part " + text(off) + " from orthonormal");
}

}  // namespace labkit::preconditions
