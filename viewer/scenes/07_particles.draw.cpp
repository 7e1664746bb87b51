// Lab 07 scene, its drawing: the surfaces (a moving scene also where it starts the step),
// the fountain's particles in their invariants' colour, the shots at the target, one
// step's bounces in their verdict's colour; and the panel.
#include "viewer/scenes/07_particles.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

namespace viewer::particles {

// ---- draw ----------------------------------------------------------------------------

void ParticlesScene::draw_surfaces(Renderer& r) const {
  const lab07::Scene& scene = mode_ == Mode::fountain ? case_.scene : one_.scene;
  const double size = mode_ == Mode::fountain ? 5 : std::max(2.0, radius);
  // A moving scene, where it starts the step: faint, u dt behind where it ends.
  const Vec3 back = mode_ == Mode::step ? Vec3(-one_.scene.velocity * one_.dt) : Vec3(Vec3::Zero());
  if (back != Vec3::Zero()) {
    for (const Plane& p : scene.planes) {
      const double length = p.normal.norm();
      if (length == 0) continue;
      const Vec3 n = p.normal / length, foot = center - (p.value(center) / length) * n + back;
      const Square q = square_around(foot, n.unitOrthogonal(), n.cross(n.unitOrthogonal()), size);
      fill(r, q, palette::surface.with_alpha(0.08f));
      outline(r, q, palette::muted, 1, true);
      r.label(foot, "the surface at the start of the step", palette::muted, 10, 10);
    }
    for (std::size_t i = 0; i < scene.mesh.size(); ++i) {
      const Triangle t = scene.mesh.triangle(i);
      r.triangle(t.v0 + back, t.v1 + back, t.v2 + back, palette::surface.with_alpha(0.15f));
    }
  }
  for (const Plane& p : scene.planes) {  // a square patch of each plane around the scene's centre
    const double length = p.normal.norm();
    if (length == 0) continue;
    const Vec3 n = p.normal / length, foot = center - (p.value(center) / length) * n;
    fill(r, square_around(foot, n.unitOrthogonal(), n.cross(n.unitOrthogonal()), size),
         palette::surface.with_alpha(0.25f));
    r.arrow(foot, foot + 0.15 * size * n, palette::muted, 1.5f);
  }
  draw_mesh(r, scene.mesh, palette::surface.with_alpha(0.8f));
}

void ParticlesScene::draw_collision(Frame& f, const CollideCase& in, const Attempt<Collision>& got) const {
  Renderer& r = f.render;
  // A moving scene: its frame's start a' = a + u dt, where the scene carries a (lecture 004).
  const Vec3 u = in.scene.velocity, start = in.step.a + u * in.dt;
  const bool moving = u != Vec3::Zero();
  r.dashed(start, in.step.b, palette::muted, 1.5f);
  r.point(in.step.a, palette::input, 5);
  r.label(in.step.a, "a", palette::input), r.label(in.step.b, "b", palette::muted);
  if (moving) {
    r.arrow(in.step.a, start, palette::input, 1.5f);
    r.label(0.5 * (in.step.a + start), "u dt", palette::input, 8, 0);
    r.point(start, palette::input, 5), r.label(start, "a' = a + u dt", palette::input);
  }
  if (f.shows(4) && first_ && first_->hit) {
    r.ring(first_->point, colour(verdict_[4]), 14, 2.5f);
    r.arrow(first_->point, first_->point + 0.15 * radius * first_->normal, colour(verdict_[4]), 2);
  }
  if (f.show_exact && exact_hit_.hit) r.ring(exact_hit_.point, palette::exact, 9);
  if (!got) return;
  const Color c = colour(worse(verdict_[6], verdict_[7]));
  Vec3 from = start;
  const Collision& col = *got;
  const int used = std::min(col.bounces + (col.stopped ? 1 : 0), kMaxBounceCap + 1);
  for (int k = 0; k < used; ++k) {
    const Bounce& b = col.trace[std::size_t(k)];
    r.line(from, b.from, c, 2.5f);
    r.point(b.from, c, 5);
    if (f.shows(6)) r.label(b.from, k < col.bounces ? "bounce " + std::to_string(k + 1) : "stopped (cap)", c, 10, 10);
    from = b.from;
  }
  r.line(from, col.position, c, 2.5f);
  r.point(col.position, c, 6);
  r.label(col.position, "end", c);
  if (!moving) return;
  // The world's path, dotted: a point of the scene's frame at time tau is u (dt - tau)
  // ahead of where the particle was then.
  Vec3 world = in.step.a;
  double remaining = in.dt;
  for (int k = 0; k < used; ++k) {
    const Bounce& b = col.trace[std::size_t(k)];
    const double elapsed = in.dt - remaining * (1 - b.hit.t);
    const Vec3 there = b.from - u * (in.dt - elapsed);
    r.dashed(world, there, palette::input, 1.5f);
    r.point(there, palette::input, 4);
    if (f.shows(6)) r.label(there, "the world's bounce " + std::to_string(k + 1), palette::input, 10, 10);
    world = there;
    remaining *= 1 - b.hit.t;
  }
  r.dashed(world, col.position, palette::input, 1.5f);  // stopped: it rides the surface
}

void ParticlesScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::target) {
    const LaunchCase& in = launch_;
    r.point(in.from, palette::input, 6), r.label(in.from, "from", palette::input);
    r.point(in.target, palette::input, 7), r.ring(in.target, palette::input, 12),
        r.label(in.target, "target", palette::input);
    if (aim_ && aim_->count > 0) {
      const Color c = colour(verdict_[3]);
      for (const Shot* s : {&aim_->low, &aim_->high}) {  // the two parabolas, to the time of arrival
        Vec3 prev = in.from;
        const int n = 64;
        for (int i = 1; i <= n; ++i) {
          const double t = s->time * i / n;
          const Vec3 p = in.from + s->velocity * t + 0.5 * in.gravity * t * t;
          r.line(prev, p, c, 2.5f);
          prev = p;
        }
        const Vec3 mid = in.from + s->velocity * (s->time / 2) + 0.125 * in.gravity * s->time * s->time;
        char degrees[64];
        std::snprintf(degrees, sizeof degrees, "%.3f deg, arrives at %.3f s", s->angle * 180 / M_PI, s->time);
        if (s == &aim_->low)
          r.label(mid, degrees, c, -90, 22);  // below the flat arc, clear of the lobbed one
        else
          r.label(mid, degrees, c);
        r.arrow(in.from, in.from + s->velocity * 0.15, c, 2);
      }
    } else if (aim_) {
      r.label(in.target, "out of reach", colour(verdict_[3]), 12, 12);
    }
    return;
  }
  if (mode_ == Mode::spring) return draw_spring(f);
  if (mode_ == Mode::bodies) return draw_bodies(f);
  draw_surfaces(r);
  if (mode_ == Mode::step) {
    draw_collision(f, one_, collision_);
    return;
  }
  // The fountain: each particle in its invariants' colour; the followed one with its step.
  const Vec3 e = case_.emitter.position;
  r.point(e, palette::muted, 7), r.label(e, "emitter", palette::muted);
  for (const Track& t : tracks_) {
    const Color c = t.invariants == Verdict::agree ? Color{0.95f, 0.85f, 0.45f} : colour(t.invariants);
    r.point(t.particle.position, c, t.invariants == Verdict::disagree ? 6.0f : 3.5f);
    if (t.particle.bounces > 0 && f.shows(6)) r.ring(t.particle.position, colour(verdict_[6]).with_alpha(0.6f), 6, 1);
  }
  if (tracks_.empty() && !system_.particles.empty())
    for (const Particle& p : system_.particles) r.point(p.position, palette::stub, 3.5f);
  if (!tracks_.empty() && tracks_.front().step.dt > 0 && !f.figure) {
    r.ring(tracks_.front().particle.position, palette::input, 12, 1.5f);
    r.label(tracks_.front().particle.position, "followed", palette::input, 14, -14);
  }
  if (!stub_.empty()) r.label(e, stub_, palette::stub, 12, 24);
}

bool ParticlesScene::inputs() {
  if (mode_ == Mode::spring || mode_ == Mode::bodies) return inputs_extensions();
  bool changed = false;
  if (mode_ == Mode::target) {
    changed |= edit("from", launch_.from) | edit("target", launch_.target) |
               edit("speed", launch_.speed, 0.1f, 0, 1e6) | edit("gravity", launch_.gravity);
    return changed;
  }
  if (mode_ == Mode::step) {
    changed |= edit("a", one_.step.a) | edit("b", one_.step.b) | edit("velocity", one_.velocity) |
               edit("restitution", one_.scene.material.restitution, 0.01f, 0, 1) |
               edit("friction", one_.scene.material.friction, 0.01f, 0, 2) |
               edit("scene velocity u", one_.scene.velocity);
    int cap = one_.scene.bounce_cap;
    if (ImGui::SliderInt("bounce cap", &cap, 0, kMaxBounceCap)) one_.scene.bounce_cap = cap, changed = true;
    return changed;
  }
  // The fountain: play, pause, single-step; the set-up restarts it.
  if (ImGui::Button(playing_ ? "pause" : "play")) playing_ = !playing_;
  ImGui::SameLine();
  if (ImGui::Button("step")) step_once_ = true, playing_ = false;
  ImGui::SameLine();
  bool reset = ImGui::Button("restart");
  ImGui::Text("t = %.3f s, %zu particles, step %d", system_.time, system_.particles.size(), stepped_);
  reset |= edit("emitter", case_.emitter.position) | edit("direction", case_.emitter.direction) |
           edit("speed", case_.emitter.speed, 0.05f, 0, 100) | edit("rate", case_.emitter.rate, 1, 0, 2000) |
           edit("cone", case_.emitter.cone, 0.01f, 0, M_PI);
  bool material = edit("restitution", case_.scene.material.restitution, 0.01f, 0, 1) |
                  edit("friction", case_.scene.material.friction, 0.01f, 0, 2);
  int cap = case_.scene.bounce_cap;
  if (ImGui::SliderInt("bounce cap", &cap, 0, kMaxBounceCap)) case_.scene.bounce_cap = cap, material = true;
  bool verlet = case_.verlet != 0;
  if (ImGui::Checkbox("Verlet (else Euler)", &verlet)) case_.verlet = verlet ? 1 : 0, reset = true;
  if (material) system_.scene.material = case_.scene.material, system_.scene.bounce_cap = case_.scene.bounce_cap;
  if (reset) {
    case_.steps = 0;
    restart();
    changed = true;
  }
  if (playing_ || step_once_) {
    advance();
    step_once_ = false;
    changed = true;
  }
  return changed || material;
}

std::vector<Handle> ParticlesScene::handles() {
  if (mode_ == Mode::target) return {{&launch_.from, "from"}, {&launch_.target, "target"}};
  if (mode_ == Mode::step) return {{&one_.step.a, "a"}, {&one_.step.b, "b"}};
  if (mode_ == Mode::spring) return {{&spring_.a.position, "a"}, {&spring_.b.position, "b"}};
  if (mode_ == Mode::bodies)
    return {{&bodies_.a.centre, "centre a"}, {&bodies_.b.centre, "centre b"}, {&bodies_.contact.point, "contact"}};
  return {};
}

}  // namespace viewer::particles
