// Lab 07 scene: particle systems that bounce. What its files share:
// 07_particles.cpp sets the scene up and runs the steps,
// 07_particles.fountain.cpp runs the fountain, 07_particles.draw.cpp draws it and edits
// its inputs, 07_particles.bodies.cpp runs, draws and edits the extensions' two modes
// (a spring, two rigid bodies).
#pragma once

#include "viewer/scenes/scenes.h"
#include "viewer/shapes.h"

#include "07_particles/judge.h"  // the inputs: SystemCase, LaunchCase, CollideCase, ...
#include "common/oracle/oracle.h"
#include "particles.h"

namespace viewer::particles {

using namespace labkit;
using namespace labkit::lab07;

enum class Mode { fountain, target, step, spring, bodies };

// The exact first hit of a segment on a scene (exact_first_hit).
struct ExactHit {
  bool hit = false;
  double t = 0;
  Vec3 point = Vec3::Zero();
};

// One particle's last step, as the scene saw it.
struct Track {
  Particle particle;  // after the step
  CollideCase step;   // the collision input of that step (no collision: dt = 0)
  Attempt<Collision> collision;
  Verdict invariants = Verdict::none;
};

// The extensions' modes start from their handout's examples (07_particles.bodies.cpp).
SpringCase default_spring();
RigidCase default_bodies();

class ParticlesScene : public Scene {
 public:
  explicit ParticlesScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void advance();  // one step of the handling loop, through the student's functions
  void restart();
  void frame_inputs();
  void update_fountain();
  void update_target();
  void update_step(const CollideCase& in, int first_step);
  void draw_surfaces(Renderer& r) const;
  void draw_collision(Frame& f, const CollideCase& in, const Attempt<Collision>& got) const;
  // The extensions (07_particles.bodies.cpp).
  void update_spring();
  void update_bodies();
  void draw_spring(Frame& f) const;
  void draw_bodies(Frame& f) const;
  bool inputs_extensions();

  Mode mode_ = Mode::fountain;
  SystemCase case_;  // the fountain's set-up: emitter, scene, forces, seed, dt
  System system_;
  std::vector<Track> tracks_;  // one per particle alive, in order
  int stepped_ = 0;
  bool playing_ = true, step_once_ = false;
  std::string stub_;  // the first stubbed function the loop met, if any
  Attempt<Births> births_;
  Emitter emitter_before_;
  AgeCase age_in_;
  Attempt<std::vector<Particle>> aged_;
  MotionCase motion_in_;
  Attempt<Particle> moved_;

  LaunchCase launch_{Vec3::Zero(), {40, 0, 0}, 25, {0, 0, -9.81}};
  Attempt<Aim> aim_;

  CollideCase one_;  // the step mode's input, or the followed particle's
  Attempt<SurfaceHit> first_;
  Attempt<Impulse> impulse_;
  Attempt<Collision> collision_;
  ExactHit exact_hit_;
  Verdict verdict_[11] = {};

  SpringCase spring_;  // step 9: two particles on a spring
  Attempt<Vec3> spring_force_;
  RigidCase bodies_;  // step 10: two rigid bodies at a contact
  Attempt<RigidImpulse> rigid_;
};

}  // namespace viewer::particles
