// Lab 07: particle systems that bounce. Your file: replace each stub below.
// The contract is particles.h; the steps are in handouts/07_particles.md.
// Check your work with:  ./labkit check 07        (one step: ./labkit check 07 --step 1)
#include "particles.h"

#include "common/given/segment_triangle.h"
#include "common/not_implemented.h"

namespace labkit::lab07 {

// L07S1: one new particle from the emitter's ranges.
Particle emit(const Emitter& emitter, Random& random) {
  (void)emitter;
  (void)random;
  not_implemented("L07S1");
}

// L07S1: how many are born in this step, and what is owed to the next.
Births births(const Emitter& emitter, double dt) {
  (void)emitter;
  (void)dt;
  not_implemented("L07S1");
}

// L07S1: age by dt; remove the dead.
std::vector<Particle> age(std::vector<Particle> particles, double dt) {
  (void)particles;
  (void)dt;
  not_implemented("L07S1");
}

// L07S2: gravity and drag.
Vec3 force(const Particle& p, const Forces& forces) {
  (void)p;
  (void)forces;
  not_implemented("L07S2");
}

// L07S2: explicit Euler.
Particle euler_step(const Particle& p, const Forces& forces, double dt) {
  (void)p;
  (void)forces;
  (void)dt;
  not_implemented("L07S2");
}

// L07S2: the previous position of a new Verlet particle.
Particle start_verlet(const Particle& p, const Forces& forces, double dt) {
  (void)p;
  (void)forces;
  (void)dt;
  not_implemented("L07S2");
}

// L07S2: position Verlet.
Particle verlet_step(const Particle& p, const Forces& forces, double dt) {
  (void)p;
  (void)forces;
  (void)dt;
  not_implemented("L07S2");
}

// L07S3: both launch angles, or none.
Aim aim(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity) {
  (void)from;
  (void)target;
  (void)speed;
  (void)gravity;
  not_implemented("L07S3");
}

// L07S4: a one-sided plane.
SurfaceHit hit_plane(const Segment& segment, const Plane& plane) {
  (void)segment;
  (void)plane;
  not_implemented("L07S4");
}

// L07S4: a two-sided triangle (use given::segment_triangle).
SurfaceHit hit_triangle(const Segment& segment, const Triangle& triangle) {
  (void)segment;
  (void)triangle;
  not_implemented("L07S4");
}

// L07S4: the nearest hit among all planes and triangles.
SurfaceHit first_hit(const Segment& segment, const Scene& scene) {
  (void)segment;
  (void)scene;
  not_implemented("L07S4");
}

// L07S5: restitution and Coulomb friction.
Impulse impulse(const Vec3& velocity, const Vec3& object_velocity, const Vec3& normal, double mass,
                const Material& material) {
  (void)velocity;
  (void)object_velocity;
  (void)normal;
  (void)mass;
  (void)material;
  not_implemented("L07S5");
}

// L07S6: bounce with the remaining time, up to the cap; a moving scene (scene.velocity) in its own frame.
Collision collide(const Segment& step, const Vec3& velocity, double mass, double dt, const Scene& scene) {
  (void)step;
  (void)velocity;
  (void)mass;
  (void)dt;
  (void)scene;
  not_implemented("L07S6");
}

// L07S7: never behind, exactly.
Vec3 settle(const Vec3& x, const Scene& scene, const SurfaceHit& last) {
  (void)x;
  (void)scene;
  (void)last;
  not_implemented("L07S7");
}

// L07S7: the handling loop.
void System::step(double dt) {
  (void)dt;
  not_implemented("L07S7");
}

}  // namespace labkit::lab07
