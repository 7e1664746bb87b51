// Seeded inputs for view-frustum clipping (lab 01), on the same dyadic lattice as
// generators.h, so that the degenerate families are exact: a vertex "on the plane" is
// on it, an edge "through the line where two planes meet" passes through it.
//
// Planes carry integer normals (not unit: the labs must not assume it) through lattice
// points, or rounded unit normals; frustums come from random cameras (rounded unit
// planes) or are exact: boxes and pyramids with integer normals. Families on purpose:
// vertices on planes, edges along them, triangles lying in them or touching them at a
// point, edges through frustum edges and corners, tiny offsets off all of these, needle
// triangles (aspects up to 2^27, about 1.3e8), every scale from 2^-20 to 2^20 and some at
// the ends of lab 01's domain (2^-100 to 2^100), and far from the origin.
#pragma once

#include "01_frustum_split/inputs.h"
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
