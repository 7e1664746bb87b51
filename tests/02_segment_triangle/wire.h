// Lab 02 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's answer types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer.
#pragma once

#include "segment_triangle.h"

#include "common/fields.h"
#include "common/protocol/calls.h"

namespace labkit::lab02 {

LABKIT_FIELDS(PlaneCrossing, d_a, d_b, crosses, t, point)
LABKIT_FIELDS(Barycentric, dropped_axis, alpha, beta)
LABKIT_FIELDS(SegmentTriangleHit, hit, t, point, barycentric, normal)
LABKIT_FIELDS(MeshHit, hit, triangle, t, point, barycentric, normal)

LABKIT_FIELDS(MeshContact, hit, t, point, normal)

using MeshHits = std::vector<MeshHit>;

}  // namespace labkit::lab02

// clang-format off
#define LABKIT_LAB02_CALLS(CALL, METHOD)                                                          \
  CALL(PlaneCrossing, segment_plane, (const Segment&, const Triangle&))                           \
  CALL(bool, point_in_triangle_edges, (const Vec3&, const Triangle&))                             \
  CALL(Barycentric, barycentric, (const Vec3&, const Triangle&))                                  \
  CALL(bool, point_in_triangle_barycentric, (const Vec3&, const Triangle&))                       \
  CALL(bool, test_segment_triangle, (const Segment&, const Triangle&))                            \
  CALL(SegmentTriangleHit, find_segment_triangle, (const Segment&, const Triangle&))              \
  CALL(MeshHit, first_hit, (const Segment&, const Mesh&))                                         \
  CALL(bool, any_hit, (const Segment&, const Mesh&))                                              \
  CALL(MeshHits, all_hits, (const Segment&, const Mesh&))                                         \
  CALL(MeshHit, first_hit_moving, (const Segment&, const Mesh&, const RigidTransform&, const RigidTransform&)) \
  CALL(MeshContact, first_contact_moving_meshes, (const Mesh&, const Vec3&, const Mesh&, const Vec3&))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab02, LABKIT_LAB02_CALLS)
