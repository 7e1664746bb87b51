// Lab 03 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's answer types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer.
#pragma once

#include "separating_axes.h"

namespace labkit::lab03 {

template <class V> void fields(Projection& p, V&& v) {
  v("center", p.center);
  v("radius", p.radius);
}
template <class V> void fields(BoxContact& c, V&& v) {
  v("intersecting", c.intersecting);
  v("axis_index", c.axis_index);
  v("axis", c.axis);
  v("depth", c.depth);
}
template <class V> void fields(LineIntervals& i, V&& v) {
  v("crossing", i.crossing);
  v("axis", i.axis);
  v("low0", i.low0);
  v("high0", i.high0);
  v("low1", i.low1);
  v("high1", i.high1);
  v("overlap", i.overlap);
}
template <class V> void fields(ContactInterval& c, V&& v) {
  v("contact", c.contact);
  v("first", c.first);
  v("last", c.last);
}

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
