// Lab 04 scene: time of impact by bisection. What its files share:
// 04_bisection.cpp sets the scene up and runs the steps,
// 04_bisection.draw.cpp draws it and edits its inputs, 04_bisection.exact.cpp finds
// the exact first contact the searches are shown beside.
#pragma once

#include "viewer/scenes/scenes.h"
#include "viewer/shapes.h"

#include "04_bisection/judge.h"  // the inputs: MovingPairCase, SampledPair, PointBox, ...
#include "bisection.h"
#include "common/oracle/oracle.h"

#include <algorithm>

namespace viewer::bisection {

using namespace labkit;
using namespace labkit::lab04;

enum class Mode { bisect, sampled, tunnelling, advance, point, rule };

// The times a search asked for poses, in the order it first asked (the searches never
// look inside a motion, so these are exactly the instants it tested).
struct Recorder {
  std::vector<double> times;
  void note(double t) {
    if (std::find(times.begin(), times.end(), t) == times.end()) times.push_back(t);
  }
};

// The ball x(t) = -6 + 12 t and the wall [0, 8] x [-4, 4]^2 (steps 1, 2 and 4).
MovingPairCase ball_and_wall(double tolerance);

class BisectionScene : public Scene {
 public:
  explicit BisectionScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void frame_inputs();
  void layout();  // where the time axis goes: under the bodies' whole motion
  MovingPair recorded_pair(Recorder& recorder) const;
  RigidTransform pose_a(double t) const { return pose_at(case_.a.motion, t); }
  RigidTransform pose_b(double t) const { return pose_at(case_.b.motion, t); }
  // The exact answers, by exact predicates (04_bisection.exact.cpp).
  bool exact_overlap(double t) const;
  double exact_distance(double t) const;
  void exact_first_contact();
  void update_point();
  void start_search();
  void update_bisect();
  void update_sampled();
  void update_tunnelling();
  void update_advance();
  void step_overlap();
  void step_bisect(const char* title);
  void step_sampled(int n, const char* title);
  void step_closing_speed();  // the rule's speed, by the code under test
  void step_rule(const SubstepRule& rule);
  void step_advance();
  void draw_body(Renderer& r, const MovingBody& body, const RigidTransform& pose, Color c, bool filled) const;
  void draw_pair(Renderer& r, double t, Color c, bool filled) const;
  void draw_timeline(Frame& f) const;

  Mode mode_ = Mode::bisect;
  MovingPairCase case_ = ball_and_wall(1.0 / 32);
  int substeps_ = 1;           // sub-steps mode: n
  double speed_factor_ = 1.0;  // advancement: the bound is this times the true closing speed
  PointBox point_box_;
  SubstepRule rule_{6, 1, 0.25};

  // The search the picture is about: the student's answer, its verdict and what it asked.
  Attempt<TimeOfImpact> search_;
  Verdict search_verdict_ = Verdict::none;
  int search_step_ = 2;
  std::vector<double> tested_;        // the search's tested times
  std::vector<bool> tested_overlap_;  // exactly, at each
  // The exact first contact: clear at exact_lo_, overlapping at exact_hi_, exact_hi_ -
  // exact_lo_ tiny; found by sampling and bisecting with exact predicates.
  bool exact_hit_ = false, exact_at_start_ = false;
  double exact_lo_ = 0, exact_hi_ = 0;
  Attempt<Vec3> closest_;
  Verdict closest_verdict_ = Verdict::none;
  Verdict verdict_[6] = {};
  // The time axis: t0 at (left_, y0_, z_), t1 width_ to the right; rows row_ apart below.
  double left_ = 0, width_ = 1, y0_ = 0, z_ = 0, row_ = 0.1;
  Eigen::AlignedBox3d bodies_;      // what the bodies sweep over [t0, t1], roughly
  static constexpr int kRows = 12;  // bracket rows at most
};

}  // namespace viewer::bisection
