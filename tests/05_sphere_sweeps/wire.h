// Lab 05 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's answer types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer.
#pragma once

#include "sphere_sweeps.h"

#include "common/fields.h"
#include "common/protocol/calls.h"

namespace labkit::lab05 {

LABKIT_FIELDS(PointSegmentDistance, squared_distance, t, closest)
LABKIT_FIELDS(SegmentSegmentDistance, squared_distance, s, t, closest0, closest1)
LABKIT_FIELDS(PointRectangleDistance, squared_distance, s, t, closest)
LABKIT_FIELDS(SegmentRectangleDistance, squared_distance, r, s, t, closest0, closest1)
LABKIT_FIELDS(RectangleRectangleDistance, squared_distance, closest0, closest1)
LABKIT_FIELDS(Sweep, status, time, point)

}  // namespace labkit::lab05

// clang-format off
#define LABKIT_LAB05_CALLS(CALL, METHOD)                                                              \
  CALL(PointSegmentDistance, point_segment, (const Vec3&, const Segment&))                            \
  CALL(SegmentSegmentDistance, segment_segment, (const Segment&, const Segment&))                     \
  CALL(PointRectangleDistance, point_rectangle, (const Vec3&, const Rectangle&))                      \
  CALL(SegmentRectangleDistance, segment_rectangle, (const Segment&, const Rectangle&))               \
  CALL(RectangleRectangleDistance, rectangle_rectangle, (const Rectangle&, const Rectangle&))         \
  CALL(bool, test_sphere_sphere, (const Sphere&, const Sphere&))                                      \
  CALL(bool, test_sphere_capsule, (const Sphere&, const Capsule&))                                    \
  CALL(bool, test_sphere_lozenge, (const Sphere&, const Lozenge&))                                    \
  CALL(bool, test_capsule_capsule, (const Capsule&, const Capsule&))                                  \
  CALL(bool, test_capsule_lozenge, (const Capsule&, const Lozenge&))                                  \
  CALL(bool, test_lozenge_lozenge, (const Lozenge&, const Lozenge&))                                  \
  CALL(Sweep, sweep_sphere_plane, (const Sphere&, const Vec3&, const Plane&, double))                 \
  CALL(Sweep, sweep_sphere_sphere, (const Sphere&, const Vec3&, const Sphere&, const Vec3&, double))  \
  CALL(Sweep, sweep_sphere_capsule, (const Sphere&, const Vec3&, const Capsule&, double))              \
  CALL(Sweep, sweep_box_plane, (const Box&, const Vec3&, const Plane&, double))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab05, LABKIT_LAB05_CALLS)
