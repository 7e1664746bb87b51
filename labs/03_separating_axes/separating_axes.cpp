// Lab 03: separating axes. Your file: replace each stub below.
// The contract is separating_axes.h; the steps are in handouts/03_separating_axes.md.
// Check your work with:  ./labkit check 03        (one step: ./labkit check 03 --step 1)
#include "separating_axes.h"

#include "common/not_implemented.h"

namespace labkit::lab03 {

// L03S1: the centre and the radius of the box's projection onto the axis.
Projection project_box(const Box& box, const Vec3& axis) { not_implemented("L03S1", box, axis); }

// L03S1: do the two projections miss each other?
bool separated_on_axis(const Box& a, const Box& b, const Vec3& axis) { not_implemented("L03S1", a, b, axis); }

// L03S2: axis number `index` of the 15.
Vec3 box_axis(const Box& a, const Box& b, int index) { not_implemented("L03S2", a, b, index); }

// L03S2: the 15 axes, in A's frame; stop at the first that separates.
bool test_boxes(const Box& a, const Box& b) { not_implemented("L03S2", a, b); }

// L03S3: the separating axis, or the axis and depth of least penetration.
BoxContact find_boxes(const Box& a, const Box& b) { not_implemented("L03S3", a, b); }

// L03S4 (first): the lecture's method: the intervals on the line of the two planes.
LineIntervals triangles_by_intervals(const Triangle& t0, const Triangle& t1) { not_implemented("L03S4", t0, t1); }

// L03S4: planes, sides, then the intervals' order by signs alone; coplanar in 2D.
bool test_triangles(const Triangle& t0, const Triangle& t1) { not_implemented("L03S4", t0, t1); }

// L03S5: the swept test, with the six axes of table 6.7.
bool test_moving_boxes(const Box& a, const Vec3& velocity_a, const Box& b, const Vec3& velocity_b, double duration) {
  not_implemented("L03S5", a, velocity_a, b, velocity_b, duration);
}

// L03S5: intersect the 15 axes' time intervals with [0, duration].
ContactInterval find_moving_boxes(const Box& a, const Vec3& velocity_a, const Box& b, const Vec3& velocity_b,
                                  double duration) {
  not_implemented("L03S5", a, velocity_a, b, velocity_b, duration);
}

}  // namespace labkit::lab03
