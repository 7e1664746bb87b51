// The kit's geometry types: small structs on Eigen, shared by every lab, the oracle,
// the tests and the viewer. Plain data with a few obvious helpers; no algorithms here.
// Each lists its fields (LABKIT_FIELDS): the order in which replay tokens, reports and
// the judge's process protocol carry them.
#pragma once

#include "common/fields.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <vector>

namespace labkit {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;

// A rigid motion x -> R x + t (rotation and translation, no scale).
using RigidTransform = Eigen::Isometry3d;

// The closed segment from a to b; point(t) = a + t (b - a) for t in [0, 1].
struct Segment {
  Vec3 a = Vec3::Zero();
  Vec3 b = Vec3::Zero();

  Vec3 point(double t) const { return a + t * (b - a); }
  Vec3 direction() const { return b - a; }
};
LABKIT_FIELDS(Segment, a, b)

// A triangle with vertices v0, v1, v2. Its front side is the one its normal
// (v1 - v0) x (v2 - v0) points to: counter-clockwise seen from the front.
struct Triangle {
  Vec3 v0 = Vec3::Zero();
  Vec3 v1 = Vec3::Zero();
  Vec3 v2 = Vec3::Zero();

  const Vec3& operator[](int i) const { return i == 0 ? v0 : (i == 1 ? v1 : v2); }
  Vec3& operator[](int i) { return i == 0 ? v0 : (i == 1 ? v1 : v2); }
  // Not normalised: its length is twice the triangle's area.
  Vec3 normal() const { return (v1 - v0).cross(v2 - v0); }
  double area() const { return 0.5 * normal().norm(); }
};
LABKIT_FIELDS(Triangle, v0, v1, v2)

// The plane normal . x + offset = 0. The value normal . x + offset is positive on the
// side the normal points to; it is the signed distance when the normal has unit length.
struct Plane {
  Vec3 normal = Vec3::UnitZ();
  double offset = 0.0;

  double value(const Vec3& x) const { return normal.dot(x) + offset; }
};
LABKIT_FIELDS(Plane, normal, offset)

// Six planes whose normals point into the frustum: a point is inside when it is on
// the non-negative side of all six.
struct Frustum {
  enum Side { left, right, bottom, top, near, far };
  std::array<Plane, 6> planes;
};
LABKIT_FIELDS(Frustum, planes)

// An indexed triangle mesh.
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;

  std::size_t size() const { return triangles.size(); }
  Triangle triangle(std::size_t i) const {
    const auto& f = triangles[i];
    return {vertices[f[0]], vertices[f[1]], vertices[f[2]]};
  }
  // Its edges: the distinct vertex pairs of its triangles, each once, as (lower, higher)
  // vertex indices, sorted (a triangle's repeated index makes no edge).
  std::vector<std::array<int, 2>> edges() const;
};
LABKIT_FIELDS(Mesh, vertices, triangles)

// ---- Shapes shared by the later labs (03 separating axes, 04 bisection, 05 sphere
// sweeps, 06 trees, 07 particles). Lab-specific types live in the lab's own header.

// The closed ball of points within `radius` of `center`.
struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
};
LABKIT_FIELDS(Sphere, center, radius)

// A sphere swept along a segment: points within `radius` of `axis`.
struct Capsule {
  Segment axis;
  double radius = 0.0;
};
LABKIT_FIELDS(Capsule, axis, radius)

// The closed rectangle center + s u + t v, |s| <= half_u, |t| <= half_v, with u and v
// unit length and perpendicular (Eberly's center, axes and extents).
struct Rectangle {
  Vec3 center = Vec3::Zero();
  Vec3 u = Vec3::UnitX();
  Vec3 v = Vec3::UnitY();
  double half_u = 0.0;
  double half_v = 0.0;
};
LABKIT_FIELDS(Rectangle, center, u, v, half_u, half_v)

// A sphere swept over a rectangle: points within `radius` of it.
struct Lozenge {
  Rectangle rectangle;
  double radius = 0.0;
};
LABKIT_FIELDS(Lozenge, rectangle, radius)

// An oriented box: center + sum_i s_i axes.col(i), |s_i| <= half_extents[i]. The columns
// of `axes` are meant to be orthonormal; the oracle reads the box as the exact
// parallelepiped its numbers describe.
struct Box {
  Vec3 center = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
  Vec3 half_extents = Vec3::Zero();

  Vec3 corner(int i) const {  // corner i: bit k of i picks the sign along axis k
    Vec3 p = center;
    for (int k = 0; k < 3; ++k) p += ((i >> k) & 1 ? 1.0 : -1.0) * half_extents[k] * axes.col(k);
    return p;
  }
};
LABKIT_FIELDS(Box, center, axes, half_extents)

// An axis-aligned box [min, max].
struct Aabb {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();
};
LABKIT_FIELDS(Aabb, min, max)

// The largest absolute coordinate among the given points: the length scale S that
// every tolerance in the kit is relative to.
double scale_of(std::initializer_list<Vec3> points);
double scale_of(const Mesh& mesh);

}  // namespace labkit
