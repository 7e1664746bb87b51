// The header's preconditions, checked the same way in every lab: invalid input is
// refused with std::invalid_argument whose message names the function, the argument and
// the rule, then the value it got ("segment_plane: segment.a must be finite, got (nan, 0,
// 0)"). A NaN would otherwise fail every comparison and pass for an answer. These are the
// checks every lab shares, written once; a lab's own rules (a plane's normal non-zero, a
// tolerance's floor) are built from them.
//
// The references use them, and so may your file: like the geometry types, this header is
// one a lab file may include. No step grades invalid input, so checking is your choice.
#pragma once

#include "common/geometry.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace labkit::preconditions {

// A value as it is, to 17 digits: a value one ulp off shows.
inline std::string text(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}
inline std::string text(const Vec3& v) { return "(" + text(v.x()) + ", " + text(v.y()) + ", " + text(v.z()) + ")"; }
inline std::string text(const std::string& s) { return s; }
inline std::string text(int i) { return std::to_string(i); }

// "query: argument must rule, got value".
[[noreturn]] inline void reject(const std::string& query, const std::string& argument, const std::string& rule,
                                const std::string& got) {
  throw std::invalid_argument(query + ": " + argument + " must " + rule + ", got " + got);
}

// Rejects unless ok; the message (and its strings) is built only then.
template <class Value>
void require(bool ok, const char* query, const std::string& argument, const char* rule, const Value& got) {
  if (!ok) reject(query, argument, rule, text(got));
}

inline void require_finite(const char* query, const std::string& argument, double x) {
  require(std::isfinite(x), query, argument, "be finite", x);
}
inline void require_finite(const char* query, const std::string& argument, const Vec3& v) {
  require(v.allFinite(), query, argument, "be finite", v);
}
// A length, a radius, a duration: finite and >= 0.
inline void require_size(const char* query, const std::string& argument, double x) {
  require(std::isfinite(x) && x >= 0, query, argument, "be finite and >= 0", x);
}
// A mass, a tolerance: finite and > 0.
inline void require_positive(const char* query, const std::string& argument, double x) {
  require(std::isfinite(x) && x > 0, query, argument, "be finite and > 0", x);
}
// "Unit length" and "perpendicular" are checked to 1e-6: loose enough for any rounded
// rotation, tight enough to catch a forgotten normalisation.
inline void require_unit(const char* query, const std::string& argument, const Vec3& v) {
  require_finite(query, argument, v);
  require(std::abs(v.squaredNorm() - 1) <= 1e-6, query, argument, "have unit length", v);
}
inline void require_perpendicular(const char* query, const std::string& argument, const Vec3& a, const Vec3& b) {
  if (!(std::abs(a.dot(b)) <= 1e-6))
    reject(query, argument, "be perpendicular", text(a.dot(b)) + " for their dot product");
}
// A box's axes: the columns unit length and pairwise perpendicular (to 1e-6).
inline void require_orthonormal(const char* query, const std::string& argument, const Mat3& axes) {
  for (int i = 0; i < 3; ++i) {
    const std::string column = argument + ".col(" + std::to_string(i) + ")";
    require_unit(query, column, axes.col(i));
    for (int j = 0; j < i; ++j)
      require_perpendicular(query, argument + ".col(" + std::to_string(j) + ") and " + column, axes.col(j),
                            axes.col(i));
  }
}

// The geometry types' own rules, the argument named `name` ("segment", "pair.a"). Each
// checks first and builds the names only for the part that breaks a rule: a query on a
// valid input spends a few comparisons here, never a string.
inline void require_valid(const char* query, const std::string& name, const Segment& s) {
  if (s.a.allFinite() && s.b.allFinite()) return;
  require_finite(query, name + ".a", s.a);
  require_finite(query, name + ".b", s.b);
}
inline void require_valid(const char* query, const std::string& name, const Triangle& t) {
  if (t.v0.allFinite() && t.v1.allFinite() && t.v2.allFinite()) return;
  for (int k = 0; k < 3; ++k) require_finite(query, name + ".v" + std::to_string(k), t[k]);
}
inline void require_valid(const char* query, const std::string& name, const Sphere& s) {
  if (s.center.allFinite() && std::isfinite(s.radius) && s.radius >= 0) return;
  require_finite(query, name + ".center", s.center);
  require_size(query, name + ".radius", s.radius);
}
// A box: its centre finite, its half extents finite and >= 0, its axes orthonormal.
inline void require_valid(const char* query, const std::string& name, const Box& b) {
  const bool axes_fine =
      b.axes.allFinite() && (b.axes.transpose() * b.axes - Mat3::Identity()).cwiseAbs().maxCoeff() <= 1e-6;
  if (b.center.allFinite() && b.half_extents.allFinite() && (b.half_extents.array() >= 0).all() && axes_fine) return;
  require_finite(query, name + ".center", b.center);
  for (int i = 0; i < 3; ++i) require_size(query, name + ".half_extents[" + std::to_string(i) + "]", b.half_extents[i]);
  require_orthonormal(query, name + ".axes", b.axes);
}
// A mesh has thousands of vertices: each is checked, and a name is built only for the
// one that breaks the rule.
inline void require_valid(const char* query, const std::string& name, const Mesh& mesh) {
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

}  // namespace labkit::preconditions
