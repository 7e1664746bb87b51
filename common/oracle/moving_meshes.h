// Two meshes moving by translations over [0, 1] (lab 02, step 7): mesh A's vertex p is at
// p + t va at time t, mesh B's q at q + t vb. Their first contact, exact: the smallest t
// at which a vertex of A touches a face of B, a vertex of B a face of A, or an edge of A
// an edge of B (closed sets: touching counts). Meshes that touch at t = 0 are outside
// the lab's contract (its precondition); here their first contact is whatever the three
// families find.
#pragma once

#include "common/geometry.h"

#include <array>
#include <vector>

namespace oracle {

using labkit::Mesh;
using labkit::Vec3;

struct MeshContact {
  bool hit = false;
  double t = 0.0;              // the first contact time (exact, rounded)
  Vec3 point = Vec3::Zero();   // a common point at that time, in the world (rounded)
  int kind = -1;               // 0: a vertex of A on a face of B; 1: a vertex of B on a face of A; 2: edge-edge
  int feature_a = -1;          // kind 0: vertex of A; 1: triangle of A; 2: edge of A (index in Mesh::edges)
  int feature_b = -1;          // kind 0: triangle of B; 1: vertex of B; 2: edge of B
  double approach = 0.0;       // the closing speed along the contact's unit normal (face normal,
                               // or e x f for edge-edge): how sharply t is fixed
  Vec3 normal = Vec3::Zero();  // that unit normal, from B toward A (d . normal <= 0), rounded
};

MeshContact first_contact_translating(const Mesh& a, const Vec3& va, const Mesh& b, const Vec3& vb);

// The normals a contact by time t may have (lab 02, step 7): one for each face a vertex
// meets by then, and each edge pair that meets by then (exact tests of the swept paths).
// With reach > 0, also each feature pair that comes within reach of meeting by then (a
// perturbation of reach makes them meet: the header's tolerance).
struct ContactNormal {
  Vec3 direction = Vec3::Zero();  // unit, rounded: the face's normal, or e x f
  // Parallel edges: direction is their unit axis, and any normal perpendicular to it will do.
  bool perpendicular_to_direction = false;
  double spread = 1.0;  // k = |e| |f| / |e x f| (>= 1): how loosely the edges fix the normal
};
std::vector<ContactNormal> contact_normals_by(const Mesh& a, const Vec3& va, const Mesh& b, const Vec3& vb, double t,
                                              double reach = 0);

// Exact: do the meshes touch at some time in [0, t]? (False for t < 0.)
bool contact_by(const Mesh& a, const Vec3& va, const Mesh& b, const Vec3& vb, double t);

// Whether they touch during [0, 1], from exact predicates on the extrusions rounded
// once (p + d in doubles): fast, for the judges' perturbation tests of doubt only.
bool touch_during_frame_fast(const Mesh& a, const Vec3& va, const Mesh& b, const Vec3& vb);

// Exact: is p within `tolerance` of the mesh translated by `offset`?
bool within_translated(const Vec3& p, const Mesh& mesh, const Vec3& offset, double tolerance);

}  // namespace oracle
