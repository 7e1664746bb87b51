// Lab 07 scene, its extensions' modes (handouts/07_particles.extensions.md):
//   spring  step 9: two particles on a damped spring, the force on each (arrows), the
//           exact force beside yours;
//   bodies  step 10: two rigid bodies (drawn as boxes) at a contact, the arms r_a and
//           r_b, the impulse J, and each body's velocity and spin after it.
#include "viewer/scenes/07_particles.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace viewer::particles {

// ---- setup ---------------------------------------------------------------------------

SpringCase default_spring() {  // stretched from 1 to 3, a moving off along and across it
  SpringCase c;
  c.a.position = {3, 0, 1}, c.a.velocity = {0.5, 0, 1};
  c.b.position = {0, 0, 1};
  c.spring = {1, 0.5, 1};
  return c;
}

RigidCase default_bodies() {  // the handout's worked example 1
  RigidCase c;
  c.a.centre = {-1, 0, 1}, c.a.velocity = {0, 0, -2};
  c.b.centre = {0, 0, -1};
  c.contact = {Vec3::Zero(), Vec3::UnitZ(), 0.5};
  return c;
}

// ---- update --------------------------------------------------------------------------

void ParticlesScene::update_spring() {
  const SpringCase& in = spring_;
  spring_force_ = attempt([&] { return spring_force(in.a, in.b, in.spring); });
  Step s9 = judged("L07S9", "spring_force: Hooke's law and damping along the spring", spring_force_,
                   [&](const Vec3& got) { return judge::spring_force(in, got); });
  const Vec3 exact = oracle::spring_force(in.a.position, in.a.velocity, in.b.position, in.b.velocity,
                                          in.spring.stiffness, in.spring.damping, in.spring.rest_length);
  s9.rows = {{"length", num((in.a.position - in.b.position).norm()), ""},
             {"force on a", spring_force_ ? num(*spring_force_) : "", num(exact)}};
  verdict_[9] = s9.verdict;
  steps.push_back(s9);
}

namespace {

oracle::Body body_of(const RigidBody& b) {
  return {b.centre, b.velocity, b.angular_velocity, b.mass, b.inverse_inertia};
}

}  // namespace

void ParticlesScene::update_bodies() {
  const RigidCase& in = bodies_;
  rigid_ = attempt([&] { return rigid_impulse(in.a, in.b, in.contact); });
  Step s10 = judged("L07S10", "rigid_impulse: j, then linear and angular velocities", rigid_,
                    [&](const RigidImpulse& got) { return judge::rigid_impulse(in, got); });
  const oracle::RigidImpulse x =
      oracle::rigid_impulse(body_of(in.a), body_of(in.b), in.contact.point, in.contact.normal, in.contact.restitution);
  const auto& g = rigid_;
  s10.rows = {{"v_rel", g ? num(g->v_rel) : "", num(x.v_rel)},
              {"j", g ? num(g->j) : "", num(x.j)},
              {"v_a'", g ? num(g->velocity_a) : "", num(x.velocity_a)},
              {"w_a'", g ? num(g->angular_velocity_a) : "", num(x.angular_velocity_a)},
              {"v_b'", g ? num(g->velocity_b) : "", num(x.velocity_b)},
              {"w_b'", g ? num(g->angular_velocity_b) : "", num(x.angular_velocity_b)}};
  verdict_[10] = s10.verdict;
  steps.push_back(s10);
}

// ---- draw ----------------------------------------------------------------------------

void ParticlesScene::draw_spring(Frame& f) const {
  Renderer& r = f.render;
  const SpringCase& in = spring_;
  const Vec3 a = in.a.position, b = in.b.position;
  // The spring as a zigzag from b to a, its rest length marked on the line.
  const Vec3 d = a - b;
  const double l = d.norm();
  if (l > 0) {
    // The zigzag across the spring in the picture's plane (x-z) when it can be.
    const Vec3 u = d / l, across = u.cross(Vec3::UnitY()).norm() > 0.1 ? Vec3(u.cross(Vec3::UnitY()).normalized())
                                                                       : Vec3(u.unitOrthogonal());
    const Vec3 side = across * std::min(0.15, 0.1 * l);
    Vec3 prev = b;
    const int coils = 12;
    for (int i = 1; i <= coils; ++i) {
      const Vec3 next = b + d * (double(i) / coils) + (i == coils ? Vec3::Zero() : Vec3((i % 2 ? 1.0 : -1.0) * side));
      r.line(prev, next, palette::muted, 1.5f);
      prev = next;
    }
    const Vec3 rest = b + std::min(in.spring.rest_length, 2 * l) * u;
    r.ring(rest, palette::muted, 6, 1.5f);
    r.label(rest, "rest length", palette::muted, 8, -16);
  }
  r.point(a, palette::input, 7), r.label(a, "a", palette::input);
  r.point(b, palette::input, 7), r.label(b, "b", palette::input);
  r.arrow(a, a + 0.5 * in.a.velocity, palette::input, 1.5f), r.label(a + 0.5 * in.a.velocity, "v_a", palette::input);
  // Forces drawn to one scale: the larger of yours and the exact one is 0.4 l long.
  const Vec3 exact = oracle::spring_force(a, in.a.velocity, b, in.b.velocity, in.spring.stiffness, in.spring.damping,
                                          in.spring.rest_length);
  const double big = std::max(exact.norm(), spring_force_ ? spring_force_->norm() : 0.0);
  const double k = big > 0 ? 0.4 * std::max(l, 1e-300) / big : 0;
  if (f.show_exact && big > 0) r.arrow(a, a + k * exact, palette::exact, 4);
  if (spring_force_ && spring_force_->allFinite()) {
    const Color c = colour(verdict_[9]);
    r.arrow(a, a + k * *spring_force_, c, 2.5f), r.label(a + 0.5 * k * *spring_force_, "F_a", c, 0, 20);
    r.arrow(b, b - k * *spring_force_, c, 2.5f), r.label(b - 0.5 * k * *spring_force_, "F_b = -F_a", c, -20, 20);
  }
}

void ParticlesScene::draw_bodies(Frame& f) const {
  Renderer& r = f.render;
  const RigidCase& in = bodies_;
  const Vec3 p = in.contact.point, n = in.contact.normal;
  // Each body as a box around its centre that reaches the contact point.
  for (const RigidBody* body : {&in.a, &in.b}) {
    Box box;
    box.center = body->centre;
    box.half_extents = ((p - body->centre).cwiseAbs().array().max(0.5)).matrix();
    box.half_extents.y() = std::max(box.half_extents.y(), 0.8);
    draw_faces(r, corners_of(box), palette::surface.with_alpha(0.18f));
    draw_edges(r, corners_of(box), palette::muted, 1.5f);
    r.point(body->centre, palette::input, 6);
    r.dashed(body->centre, p, palette::input, 1.5f);
  }
  r.label(in.a.centre, "a", palette::input), r.label(in.b.centre, "b", palette::input);
  r.label(0.5 * (in.a.centre + p), "r_a", palette::input, -30, 0),
      r.label(0.5 * (in.b.centre + p), "r_b", palette::input);
  r.point(p, palette::input, 5);
  r.arrow(p, p + n, palette::muted, 1.5f), r.label(p + n, "n", palette::muted, -20, -8);
  r.arrow(in.a.centre, in.a.centre + 0.5 * in.a.velocity, palette::input, 1.5f);
  r.label(in.a.centre + 0.5 * in.a.velocity, "v_a", palette::input, -40, 0);
  const oracle::RigidImpulse x = oracle::rigid_impulse(body_of(in.a), body_of(in.b), p, n, in.contact.restitution);
  if (f.show_exact && x.closing) r.arrow(p, p + x.j * n, palette::exact, 4);
  if (!rigid_) return;
  const RigidImpulse& g = *rigid_;
  const Color c = colour(verdict_[10]);
  if (g.closing && std::isfinite(g.j)) r.arrow(p, p + g.j * n, c, 2.5f), r.label(p + g.j * n, "J = j n", c, 8, -20);
  const auto after = [&](const Vec3& centre, const Vec3& v, const Vec3& w, const char* vl, const char* wl) {
    if (!v.allFinite() || !w.allFinite()) return;
    r.arrow(centre, centre + 0.5 * v, c, 2.5f), r.label(centre + 0.5 * v, vl, c);
    if (w != Vec3::Zero()) {  // the spin: its axis, and a circle about it
      r.arrow(centre, centre + 0.5 * w, c, 1.5f), r.label(centre + 0.5 * w, wl, c, 8, 16);
      const Vec3 axis = w.normalized();
      draw_circle(r, centre, axis.unitOrthogonal(), axis.cross(axis.unitOrthogonal()), 0.35, c, 1.5f);
    }
  };
  after(in.a.centre, g.velocity_a, g.angular_velocity_a, "v_a'", "w_a'");
  after(in.b.centre, g.velocity_b, g.angular_velocity_b, "v_b'", "w_b'");
}

// ---- inputs --------------------------------------------------------------------------

bool ParticlesScene::inputs_extensions() {
  if (mode_ == Mode::spring) {
    SpringCase& c = spring_;
    return edit("a", c.a.position) | edit("b", c.b.position) | edit("velocity a", c.a.velocity) |
           edit("velocity b", c.b.velocity) | edit("stiffness k_s", c.spring.stiffness, 0.01f, 0, 100) |
           edit("damping k_d", c.spring.damping, 0.01f, 0, 100) |
           edit("rest length", c.spring.rest_length, 0.01f, 0, 100);
  }
  RigidCase& c = bodies_;
  return edit("centre a", c.a.centre) | edit("velocity a", c.a.velocity) | edit("spin a", c.a.angular_velocity) |
         edit("mass a", c.a.mass, 0.01f, 0.01, 100) | edit("centre b", c.b.centre) | edit("velocity b", c.b.velocity) |
         edit("spin b", c.b.angular_velocity) | edit("mass b", c.b.mass, 0.01f, 0.01, 100) |
         edit("contact", c.contact.point) | edit("restitution", c.contact.restitution, 0.01f, 0, 1);
}

}  // namespace viewer::particles
