// Lab 03 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's answer types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer.
#pragma once

#include "separating_axes.h"

#include "common/fields.h"
#include "common/protocol/calls.h"

namespace labkit::lab03 {

LABKIT_FIELDS(Projection, center, radius)
LABKIT_FIELDS(BoxContact, intersecting, axis_index, axis, depth)
LABKIT_FIELDS(LineIntervals, crossing, axis, low0, high0, low1, high1, overlap)
LABKIT_FIELDS(ContactInterval, contact, first, last)

}  // namespace labkit::lab03

// clang-format off
#define LABKIT_LAB03_CALLS(CALL, METHOD)                                                            \
  CALL(Projection, project_box, (const Box&, const Vec3&))                                          \
  CALL(bool, separated_on_axis, (const Box&, const Box&, const Vec3&))                              \
  CALL(Vec3, box_axis, (const Box&, const Box&, int))                                               \
  CALL(bool, test_boxes, (const Box&, const Box&))                                                  \
  CALL(BoxContact, find_boxes, (const Box&, const Box&))                                            \
  CALL(LineIntervals, triangles_by_intervals, (const Triangle&, const Triangle&))                   \
  CALL(bool, test_triangles, (const Triangle&, const Triangle&))                                    \
  CALL(bool, test_moving_boxes, (const Box&, const Vec3&, const Box&, const Vec3&, double))         \
  CALL(ContactInterval, find_moving_boxes, (const Box&, const Vec3&, const Box&, const Vec3&, double))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab03, LABKIT_LAB03_CALLS)
