// Lab 06's given tests (declared in its header): plain code, whose every call in the
// answerer is also counted by the judge's process (served.h).
#include "labs/06_spatial_trees/spatial_trees.h"

#include "common/given/served.h"

namespace labkit::lab06 {

int compare_ends(const Endpoint& a, const Endpoint& b) {
  given::note_call("compare_ends");
  return (a.value > b.value) - (a.value < b.value);
}

bool given_balls_meet(const Sphere& a, const Sphere& b) {
  given::note_call("given_balls_meet");
  const Vec3 gap = b.center - a.center;
  const double sum = a.radius + b.radius;
  return gap.dot(gap) <= sum * sum;  // closed balls: touching counts
}

bool given_boxes_overlap(const Box& a, const Box& b) {
  given::note_call("given_boxes_overlap");
  const Vec3 d = b.center - a.center;
  const auto apart_along = [&](const Vec3& u) {
    const double length = u.norm();
    if (!(length > 1e-9)) return false;
    double ra = 0, rb = 0;
    for (int k = 0; k < 3; ++k)
      ra += a.half_extents[k] * std::abs(a.axes.col(k).dot(u)),
          rb += b.half_extents[k] * std::abs(b.axes.col(k).dot(u));
    const double gap = std::abs(d.dot(u)) - ra - rb;
    return gap > 1e-12 * (std::abs(d.dot(u)) + ra + rb +
                          length * (a.center.cwiseAbs().maxCoeff() + b.center.cwiseAbs().maxCoeff()));
  };
  for (int k = 0; k < 3; ++k)
    if (apart_along(a.axes.col(k)) || apart_along(b.axes.col(k))) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (apart_along(a.axes.col(i).cross(b.axes.col(j)))) return false;
  return true;
}

bool given_triangles_meet(const Triangle& s, const Triangle& t) {
  given::note_call("given_triangles_meet");
  for (int k = 0; k < 3; ++k)
    if (given::segment_triangle({s[k], s[(k + 1) % 3]}, t).hit ||
        given::segment_triangle({t[k], t[(k + 1) % 3]}, s).hit)
      return true;
  return false;
}

bool given_cell_meets_box(const Aabb& cell, const Aabb& box) {
  given::note_call("given_cell_meets_box");
  return (cell.min.array() <= box.max.array()).all() && (box.min.array() <= cell.max.array()).all();
}

bool given_ball_meets_box(const Sphere& ball, const Aabb& box) {
  given::note_call("given_ball_meets_box");
  double d2 = 0;  // the squared distance from the centre to the closed box
  for (int i = 0; i < 3; ++i) {
    const double c = ball.center[i];
    const double gap = c < box.min[i] ? box.min[i] - c : (c > box.max[i] ? c - box.max[i] : 0.0);
    d2 += gap * gap;
  }
  return d2 <= ball.radius * ball.radius;  // closed: touching counts
}

void serve_given() {
  for (const char* name : {"compare_ends", "given_balls_meet", "given_boxes_overlap", "given_triangles_meet",
                           "given_cell_meets_box", "given_ball_meets_box"})
    given::countable(name);
}

}  // namespace labkit::lab06
