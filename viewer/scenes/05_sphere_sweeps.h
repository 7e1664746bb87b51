// Lab 05 scene: sphere-swept volumes, static and moving. What its files share:
// 05_sphere_sweeps.cpp sets the scene up and runs the sweeps' steps,
// 05_sphere_sweeps.cores.cpp the cores' steps (1 to 3),
// 05_sphere_sweeps.draw.cpp draws it and edits its inputs.
#pragma once

#include "viewer/scenes/scenes.h"
#include "viewer/shapes.h"

#include "05_sphere_sweeps/judge.h"  // the inputs: SegmentPair, SpherePlaneMotion, ...
#include "common/oracle/oracle.h"
#include "sphere_sweeps.h"

namespace viewer::sphere_sweeps {

using namespace labkit;
using namespace labkit::lab05;

enum class Mode { cores, sphere_plane, sphere_sphere, box_plane, sphere_capsule };

enum class Core { point, segment, rectangle };

// One core of a sphere-swept volume, with its radius.
struct Shape {
  Core kind = Core::point;
  Vec3 p = Vec3::Zero();
  Segment s;
  Rectangle r;
  double radius = 0;
};

// The handout's step a mode shows.
inline int step_of(Mode m) {
  switch (m) {
    case Mode::sphere_plane: return 4;
    case Mode::sphere_sphere: return 5;
    case Mode::sphere_capsule: return 6;
    case Mode::box_plane: return 7;
    case Mode::cores: break;
  }
  return 3;
}

Vec3 corner(const Rectangle& r, int k);  // k's bit 0: +u side, bit 1: +v side
// The same plane with its normal scaled by a power of two, for drawing only.
Plane drawable(const Plane& p);

class SphereSweepsScene : public Scene {
 public:
  explicit SphereSweepsScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void frame_inputs();
  void update_cores();  // 05_sphere_sweeps.cores.cpp
  void update_sphere_plane();
  void update_sphere_sphere();
  void update_sphere_capsule();
  void update_box_plane();
  template <class Motion> using Judge = check::Outcome (*)(const Motion&, const Sweep&, judge::Rules);
  template <class Motion, class Exact, class Run>
  Step sweep_step(const char* tag, const char* title, const Motion& in, const Exact& exact, Run run,
                  Judge<Motion> judge_it);
  void follow_handles();
  void draw_cores(Frame& f) const;
  void draw_sweep(Frame& f) const;
  void draw_grown_capsule(Renderer& r) const;
  void draw_answer(Renderer& r, const Vec3& start0, const Color& c) const;

  Mode mode_ = Mode::cores;
  Shape a_, b_;
  bool test_query_ = false;  // the token named a test (step 3), not a distance
  // Moving shapes: sphere 0 (and 1), the box, the plane, the step.
  Sphere s0_{{0, 0, 5}, 1}, s1_;
  Vec3 v0_ = Vec3::Zero(), v1_ = Vec3::Zero();
  Box box_;
  Capsule capsule_;
  Plane plane_{{0, 0, 1}, 0};
  double duration_ = 1;
  // Handles on derived points: the ends of the motions (centre + v T) and a point of
  // the plane. A moved handle sets its source; otherwise it follows it.
  Vec3 end0_, end1_, plane_point_;
  Vec3 last_end0_, last_end1_, last_plane_point_;
  double turn_ = 0, tilt_ = 0;  // the panel's box rotation, in degrees

  // The student's answers and the exact ones.
  std::optional<Vec3> closest0_, closest1_;
  Attempt<bool> meet_;
  Attempt<Sweep> sweep_;
  double exact_time_ = -1;  // the exact first contact (rounded), -1: none
  bool exact_overlapping_ = false;
  Verdict verdict_[8] = {};
};

}  // namespace viewer::sphere_sweeps
