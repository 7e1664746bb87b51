// Lab 03 scene: separating axes. What its two files share:
// 03_separating_axes.cpp sets the scene up and runs the steps,
// 03_separating_axes.draw.cpp draws it and edits its inputs.
#pragma once

#include "viewer/scenes/scenes.h"
#include "viewer/shapes.h"

#include "03_separating_axes/judge.h"  // the inputs: BoxPair, TrianglePair, MovingBoxes, ...
#include "common/oracle/oracle.h"
#include "separating_axes.h"

namespace viewer::separating_axes {

using namespace labkit;
using namespace labkit::lab03;

enum class Mode { boxes, triangles, moving };

inline Box make_box(Vec3 center, Vec3 half, Mat3 axes = Mat3::Identity()) {
  Box b;
  b.center = center, b.half_extents = half, b.axes = axes;
  return b;
}

inline Mat3 sevenths() {
  Mat3 m;
  m << 3, -2, 6, 6, 3, -2, -2, 6, 3;
  return m / 7.0;
}

std::string axis_name(int index);  // "7 A_0 x B_1"
// Euler angles (degrees, z then y then x) for editing a box's axes.
Vec3 angles_of(const Mat3& axes);
Mat3 axes_of(const Vec3& degrees);

class SeparatingAxesScene : public Scene {
 public:
  explicit SeparatingAxesScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void preset(const std::string& name);
  void frame_inputs();
  void update_boxes();
  void update_triangles();
  void update_moving();
  void draw_triangles(Frame& f) const;
  void draw_moving(Frame& f) const;
  void draw_projection(Frame& f) const;
  void draw_line_intervals(Frame& f) const;

  Mode mode_ = Mode::boxes;
  Box a_ = make_box({0, 0, 0}, {1, 1, 1});
  Box b_ = make_box({0, 0.25, 0.5}, {1, 1, 1}, sevenths());
  Vec3 axis_ = Vec3::UnitX();  // step 1's axis L
  Vec3 angles_a_ = Vec3::Zero(), angles_b_ = Vec3::Zero();
  Triangle t0_{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, t1_{{1, 1, -2}, {1, 1, 2}, {1, -3, 0}};
  Vec3 va_ = Vec3::Zero(), vb_ = Vec3::Zero();
  double duration_ = 1, shown_time_ = 0;

  // The student's answers and the exact ones.
  Attempt<Projection> proj_a_, proj_b_;
  Attempt<bool> separated_, test_, tri_, moving_test_;
  Attempt<std::array<Vec3, 15>> axes_;
  Attempt<BoxContact> find_;
  Attempt<ContactInterval> interval_;
  Attempt<LineIntervals> line_;
  bool exact_intersect_ = false;
  int exact_index_ = -1;
  Vec3 exact_axis_ = Vec3::Zero();
  double exact_depth_ = 0;
  oracle::ContactTimes exact_times_;
  Verdict verdict_[7] = {};
};

}  // namespace viewer::separating_axes
