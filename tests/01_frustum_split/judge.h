// Lab 01's checker: the generators that draw each query's input, then the verdicts.
//
// Lab 01's verdicts: each judge compares one answer with the exact oracle, following
// the tolerances and degenerate rules of labs/01_frustum_split/frustum_split.h.
// The tests and the viewer both use them, so a red mark in the viewer and a failing
// case in `./labkit check` always agree.
//
// The generators come first in this file (gen::). Seeded inputs for view-frustum clipping
// (lab 01), on the same dyadic lattice as common/generators/generators.h, so that the
// degenerate families are exact: a vertex "on the plane" is on it, an edge "through the
// line where two planes meet" passes through it.
//
// Planes carry integer normals (not unit: the labs must not assume it) through lattice
// points, or rounded unit normals; frustums come from random cameras (rounded unit
// planes) or are exact: boxes and pyramids with integer normals. Families on purpose:
// vertices on planes, edges along them, triangles lying in them or touching them at a
// point, edges through frustum edges and corners, tiny offsets off all of these, needle
// triangles (aspects up to 2^27, about 1.3e8), every scale from 2^-20 to 2^20 and some at
// the ends of lab 01's domain (2^-100 to 2^100), and far from the origin.
#pragma once

#include "01_frustum_split/queries.h"
#include "common/harness/check.h"
#include "common/harness/codec.h"

#include <rapidcheck.h>
#include <array>
#include <vector>

namespace labkit {

// The eight corners of the camera's frustum, computed in long double and rounded:
// corner i is eye + d (f +- tx r +- ty u), d = near or far, with f, r, u the unit
// forward, right and up, ty = tan(fov_y / 2), tx = aspect ty. Bit 0 of i: right (else
// left); bit 1: top (else bottom); bit 2: far (else near).
std::array<Vec3, 8> frustum_corners(const CameraParameters& camera);

// Its six planes (left, right, bottom, top, near, far), each through three of those
// corners (the side planes through the eye), unit normals pointing in; long double,
// rounded once.
Frustum frustum_of(const CameraParameters& camera);

// gluPerspective(fov_y, aspect, near, far) * gluLookAt(eye, eye + forward, up), in
// double: OpenGL's view-projection matrix for the camera.
Mat4 view_projection(const CameraParameters& camera);

}  // namespace labkit

namespace labkit::gen {

// A plane and a triangle: generic, a vertex on the plane, an edge along it, the triangle
// in it, touching it at a vertex from either side, tiny offsets off those, every scale,
// far from the origin; integer normals (the plane through a lattice point) or rounded
// unit normals.
rc::Gen<TrianglePlane> triangle_plane();
// Only exactly degenerate ones, on integer coordinates (|x| <= 1024, times a power of
// two) and integer normals: the robustness step's input.
rc::Gen<TrianglePlane> exact_triangle_plane();

// Cameras at every scale and distance from the origin: fields of view from 20 to 120
// degrees, aspects from 1/2 to 2, far / near from 2 to 64, up at least 15 degrees away
// from forward.
rc::Gen<CameraParameters> camera();
// The same cameras as the lab's Camera, for frustum_from_camera.
rc::Gen<lab01::Camera> lab_camera();
// View-projection matrices: perspective cameras, orthographic views, and either times a
// positive power of two (the same clip volume).
rc::Gen<Mat4> view_projection_matrix();

// A triangle near a frustum: across its corners, edges and faces, inside, outside, and
// near-degenerate against frustums from cameras; exactly degenerate against exact ones.
rc::Gen<TriangleFrustum> triangle_frustum();
// Exact frustums (boxes and pyramids with integer normals) and triangles with vertices on
// their planes, edges along them, in them, touching them, and through their edges and
// corners: the robustness step's input.
rc::Gen<TriangleFrustum> exact_triangle_frustum();

// A small mesh (soup, terrain, octahedron) with colours, across a frustum.
rc::Gen<MeshFrustum> mesh_frustum();
// The same on integer coordinates, across exact frustums: the robustness step's input.
rc::Gen<MeshFrustum> exact_mesh_frustum();

}  // namespace labkit::gen

namespace labkit::lab01 {

std::string describe(Side s);

// The kit's camera type, for its generators and corners.
CameraParameters parameters_of(const Camera& camera);

namespace judge {

using check::Outcome;

using check::Rules;  // random cases, or a robustness step's exact input

// got[i] is the signed distance of vertex i to the plane.
Outcome signed_distance(const TrianglePlane& in, const std::array<double, 3>& got);
Outcome classify(const TrianglePlane& in, const std::array<Side, 3>& got, Rules rules = Rules::random);
Outcome split_triangle(const TrianglePlane& in, const std::vector<Triangle>& got, Rules rules = Rules::random);
Outcome frustum_from_camera(const Camera& in, const Frustum& got);
Outcome frustum_from_matrix(const Mat4& in, const Frustum& got);
Outcome clip_triangle(const TriangleFrustum& in, const std::vector<Triangle>& got, Rules rules = Rules::random);
Outcome clip_mesh(const MeshFrustum& in, const ClippedMesh& got, Rules rules = Rules::random);

}  // namespace judge
}  // namespace labkit::lab01

namespace labkit {

// The header's domain, value by value: coordinates and normal components 0 or of
// magnitude 2^-130 to 2^130; a plane's offset at most 2^130 (a smaller one, down to 0, is
// a plane through or near the origin). check::in_domain finds these by their argument.
namespace lab01::domain {
inline bool value(double x) { return x == 0 || (std::abs(x) >= 0x1p-130 && std::abs(x) <= 0x1p130); }
inline bool vector(const Vec3& v) { return value(v.x()) && value(v.y()) && value(v.z()); }
inline bool plane(const Plane& p) {
  return vector(p.normal) && std::isfinite(p.offset) && std::abs(p.offset) <= 0x1p130;
}
inline bool planes(const Frustum& f) {
  for (const Plane& p : f.planes)
    if (!plane(p)) return false;
  return true;
}
}  // namespace lab01::domain

inline bool header_in_domain(const TrianglePlane& in) {
  return lab01::domain::vector(in.triangle.v0) && lab01::domain::vector(in.triangle.v1) &&
         lab01::domain::vector(in.triangle.v2) && lab01::domain::plane(in.plane);
}
inline bool header_in_domain(const TriangleFrustum& in) {
  return lab01::domain::vector(in.triangle.v0) && lab01::domain::vector(in.triangle.v1) &&
         lab01::domain::vector(in.triangle.v2) && lab01::domain::planes(in.frustum);
}
inline bool header_in_domain(const MeshFrustum& in) {
  for (const Vec3& v : in.mesh.vertices)
    if (!lab01::domain::vector(v)) return false;
  return lab01::domain::planes(in.frustum);
}

}  // namespace labkit
