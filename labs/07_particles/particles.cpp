// Lab 07: particle systems that bounce. Your file: replace each stub below.
// The contract is particles.h; the steps are in handouts/07_particles.md.
// Check your work with:  ./labkit check 07        (one step: ./labkit check 07 --step 1)
#include "particles.h"

#include "common/given/segment_triangle.h"
#include "common/not_implemented.h"

namespace labkit::lab07 {

// L07S1: one new particle from the emitter's ranges.
Particle emit(const Emitter& emitter, Random& random) { not_implemented("L07S1", emitter, random); }

// L07S1: how many are born in this step, and what is owed to the next.
Births births(const Emitter& emitter, double dt) { not_implemented("L07S1", emitter, dt); }

// L07S1: age by dt; remove the dead.
std::vector<Particle> age(std::vector<Particle> particles, double dt) { not_implemented("L07S1", particles, dt); }

// L07S2: gravity and drag.
Vec3 force(const Particle& p, const Forces& forces) { not_implemented("L07S2", p, forces); }

// L07S2: explicit Euler.
Particle euler_step(const Particle& p, const Forces& forces, double dt) { not_implemented("L07S2", p, forces, dt); }

// L07S2: the previous position of a new Verlet particle.
Particle start_verlet(const Particle& p, const Forces& forces, double dt) { not_implemented("L07S2", p, forces, dt); }

// L07S2: position Verlet.
Particle verlet_step(const Particle& p, const Forces& forces, double dt) { not_implemented("L07S2", p, forces, dt); }

// L07S3: both launch angles, or none.
Aim aim(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity) {
  not_implemented("L07S3", from, target, speed, gravity);
}

// L07S4: a one-sided plane.
SurfaceHit hit_plane(const Segment& segment, const Plane& plane) { not_implemented("L07S4", segment, plane); }

// L07S4: a two-sided triangle (use given::segment_triangle).
SurfaceHit hit_triangle(const Segment& segment, const Triangle& triangle) {
  not_implemented("L07S4", segment, triangle);
}

// L07S4: the nearest hit among all planes and triangles.
SurfaceHit first_hit(const Segment& segment, const Scene& scene) { not_implemented("L07S4", segment, scene); }

// L07S5: restitution and Coulomb friction.
Impulse impulse(const Vec3& velocity, const Vec3& object_velocity, const Vec3& normal, double mass,
                const Material& material) {
  not_implemented("L07S5", velocity, object_velocity, normal, mass, material);
}

// L07S6: bounce with the remaining time, up to the cap; a moving scene (scene.velocity) in its own frame.
Collision collide(const Segment& step, const Vec3& velocity, double mass, double dt, const Scene& scene) {
  not_implemented("L07S6", step, velocity, mass, dt, scene);
}

// L07S7: never behind, exactly (L07S8: in creases and corners too).
Vec3 settle(const Vec3& x, const Scene& scene, const SurfaceHit& last) { not_implemented("L07S7", x, scene, last); }

// L07S8: the handling loop.
void System::step(double dt) { not_implemented("L07S8", dt); }

// L07S9 (extension): Hooke's law along the spring, plus damping along it.
Vec3 spring_force(const Particle& a, const Particle& b, const Spring& spring) {
  not_implemented("L07S9", a, b, spring);
}

// L07S10 (extension): one impulse changes linear and angular velocities.
RigidImpulse rigid_impulse(const RigidBody& a, const RigidBody& b, const Contact& contact) {
  not_implemented("L07S10", a, b, contact);
}

}  // namespace labkit::lab07
