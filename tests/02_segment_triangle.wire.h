// Lab 02 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's answer types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer.
#pragma once

#include "segment_triangle.h"

namespace labkit::lab02 {

template <class V> void fields(PlaneCrossing& c, V&& v) {
  v("d_a", c.d_a);
  v("d_b", c.d_b);
  v("crosses", c.crosses);
  v("t", c.t);
  v("point", c.point);
}
template <class V> void fields(Barycentric& b, V&& v) {
  v("dropped_axis", b.dropped_axis);
  v("alpha", b.alpha);
  v("beta", b.beta);
}
template <class V> void fields(SegmentTriangleHit& h, V&& v) {
  v("hit", h.hit);
  v("t", h.t);
  v("point", h.point);
  v("barycentric", h.barycentric);
  v("normal", h.normal);
}
template <class V> void fields(MeshHit& h, V&& v) {
  v("hit", h.hit);
  v("triangle", h.triangle);
  v("t", h.t);
  v("point", h.point);
  v("barycentric", h.barycentric);
  v("normal", h.normal);
}

template <class V> void fields(MeshContact& c, V&& v) {
  v("hit", c.hit);
  v("t", c.t);
  v("point", c.point);
}

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
