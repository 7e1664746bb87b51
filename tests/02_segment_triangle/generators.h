// Lab 02's own random inputs, beside the shared segment-triangle and mesh families
// (generators.h, needles.h): points in a triangle's plane, meshes moving rigidly, and two
// meshes translating toward a contact.
#pragma once

#include "02_segment_triangle/inputs.h"
#include "common/generators/needles.h"

namespace labkit::gen {

// Inputs for the point-in-triangle steps: points exactly in the triangle's plane, many
// of them exactly on an edge or a vertex, or a tiny step inside or outside one.
rc::Gen<lab02::PointTriangle> point_triangle();
// The same on integer coordinates: exact input for the robustness step.
rc::Gen<lab02::PointTriangle> exact_point_triangle();
rc::Gen<lab02::MovingMesh> moving_mesh();
// Two small meshes (tetrahedra, tents, single triangles) apart at t = 0, aimed so that a
// chosen vertex-face or edge-edge pair meets at a chosen time, or passing just beside
// it, or stopping short: decisive, at every scale of the header.
rc::Gen<lab02::MovingMeshes> moving_meshes();
// The same meshes on integers, apart at t = 0 and aimed exactly: a vertex onto a vertex,
// an edge or a face, an edge onto an edge (at its end or its middle), touching exactly
// at t = 1, two flat triangles sliding in one plane, or no relative motion. Every
// number is a small integer over a power of two: exact input for the robustness step.
rc::Gen<lab02::MovingMeshes> exact_moving_meshes();

}  // namespace labkit::gen
