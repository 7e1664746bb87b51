// Lab 07 scene: particle systems that bounce (handouts/07_particles.md).
//
// A replay token's query picks the mode:
//   fountain         system (or no token): a fountain on a terrain and a floor,
//                    animated with play, pause and single-step        steps 1, 2, 4-7
//   target practice  aim, exact.aim: the two shots at a target        step 3
//   one step         collide, invariants, first_hit, exact.first_hit, hit_plane:
//                    one particle's step and its bounces               steps 4-7
//                    (a moving scene, Scene::velocity u: the surfaces drawn where they
//                    end the step and, faint, where they start it; the bounces in the
//                    scene's frame from a' = a + u dt, and the world's path, dotted)
// The fountain runs the handling loop of System::step itself, through the student's
// functions one by one (births, emit, the integrator, collide, age), so that every
// particle's step can be judged: a particle whose step breaks an invariant (behind a
// surface, energy gained) is drawn red. One particle (the oldest) is followed: its
// step, hits and impulse are judged in full and the exact first hit is ringed in violet.
#include "viewer/scenes/scenes.h"

#include "07_particles.judge.h"
#include "common/oracle/oracle.h"
#include "particles.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

namespace viewer {
namespace {

using namespace labkit;
using namespace labkit::lab07;

enum class Mode { fountain, target, step };

const std::vector<Preset> kPresets = {
    {"fountain", "a fountain bouncing on a terrain: e = 0.6, mu = 0.2", nullptr, true, -50, 22},
    {"target", "the lecture's target practice: 25 m/s, 40 m away: 19.445 and 70.555 degrees",
     "aim:0,0,0,40,0,0,25,0,0,-9.81", true, -90, 2, 3},
    {"corner", "floor, then wall: two bounces in the remaining time (e = 1)", nullptr, true, -90, 2, 6},
    {"crack", "a crack between floor and ceiling: bounces up to the cap, then stops", nullptr, false, -90, 2, 6},
    {"dead", "a dead bounce (e = 0): the hit point is settled above the floor", nullptr, false, -90, 2, 7},
    {"paddle", "a floor rising at u = (0, 0, 2) (e = 1/2): the bounce seen from the floor, from a' = a + u dt", nullptr, true,
     -90, 2, 6},
};

// Rolling hills of 2 n^2 triangles over [-4, 4]^2, below z = 0.6.
Mesh hills(int n) {
  Mesh m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = -4 + 8.0 * i / n, y = -4 + 8.0 * j / n;
      m.vertices.push_back({x, y, 0.35 + 0.3 * std::sin(x * 1.1) * std::cos(y * 0.8)});
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int v = i * (n + 1) + j;
      m.triangles.push_back({v, v + n + 1, v + n + 2});
      m.triangles.push_back({v, v + n + 2, v + 1});
    }
  return m;
}

// The exact first hit of a segment on a scene (planes, then triangles; ties to the first).
struct ExactHit {
  bool hit = false;
  double t = 0;
  Vec3 point = Vec3::Zero();
};
ExactHit exact_first_hit(const Segment& s, const lab07::Scene& scene) {
  ExactHit best;
  for (const Plane& p : scene.planes)
    if (oracle::plane_hit(s, p)) {
      const double t = oracle::plane_hit_t(s, p);
      if (!best.hit || t < best.t) best = {true, t, s.point(t)};
    }
  const Vec3 low = s.a.cwiseMin(s.b), high = s.a.cwiseMax(s.b);
  for (std::size_t i = 0; i < scene.mesh.size(); ++i) {
    const Triangle tri = scene.mesh.triangle(i);
    const Vec3 tl = tri.v0.cwiseMin(tri.v1).cwiseMin(tri.v2), th = tri.v0.cwiseMax(tri.v1).cwiseMax(tri.v2);
    if ((tl.array() > high.array()).any() || (th.array() < low.array()).any()) continue;
    if (!oracle::sheet_hit(s, tri)) continue;
    const oracle::SegmentHit h = oracle::segment_triangle(s, tri);
    if (!best.hit || h.t < best.t) best = {true, h.t, h.point};
  }
  return best;
}

// One particle's last step, as the scene saw it.
struct Track {
  Particle particle;         // after the step
  CollideCase step;          // the collision input of that step (no collision: dt = 0)
  Attempt<Collision> collision;
  Verdict invariants = Verdict::none;
};

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
  Verdict verdict_[8] = {};
};

// ---- setup ---------------------------------------------------------------------------

SystemCase default_fountain() {
  SystemCase c;
  Emitter& e = c.emitter;
  e.position = Vec3(0, 0, 1.2);
  e.half_extents = Vec3(0.1, 0.1, 0);
  e.direction = Vec3(0.15, 0.1, 1).normalized();
  e.cone = 0.35;
  e.speed = 6;
  e.speed_spread = 1;
  e.lifetime = 3.5;
  e.lifetime_spread = 0.5;
  e.rate = 40;
  c.scene.planes = {Plane{{0, 0, 1}, 0}};
  c.scene.mesh = hills(16);
  c.scene.material = {0.6, 0.2};
  c.scene.bounce_cap = 4;
  c.forces.gravity = Vec3(0, 0, -9.81);
  c.seed = 7;
  c.dt = 1.0 / 60;
  c.steps = 0;
  return c;
}

CollideCase preset_step(const std::string& name) {
  CollideCase c;
  c.scene.planes = {Plane{{0, 0, 1}, 0}};
  c.mass = 1, c.dt = 1;
  if (name == "corner") {
    c.scene.planes.push_back(Plane{{-1, 0, 0}, 3});
    c.scene.material = {1, 0};
    c.step = {{0, 0, 1}, {4, 0, -1}}, c.velocity = Vec3(4, 0, -2);
  } else if (name == "crack") {
    c.scene.planes.push_back(Plane{{0, 0, -1}, 0.5});
    c.scene.material = {1, 0};
    c.scene.bounce_cap = kMaxBounceCap;
    c.step = {{0.5, 0, 0.25}, {8.5, 0, -7.75}}, c.velocity = Vec3(8, 0, -8);
  } else if (name == "paddle") {  // step 6's moving example: the floor rises at 2, at z = 0 when the step ends
    c.scene.material = {0.5, 0};
    c.scene.velocity = Vec3(0, 0, 2);
    c.step = {{0, 0, 1}, {1, 0, -1}}, c.velocity = Vec3(1, 0, -2);
  } else {  // dead
    c.scene.material = {0, 0};
    c.step = {{0, 0, 0.1}, {1, 0, -0.7}}, c.velocity = Vec3(1, 0, -0.8);
  }
  return c;
}

ParticlesScene::ParticlesScene(const Setup& setup) {
  case_ = default_fountain();
  const Preset* preset = view_preset(kPresets, setup);
  if (setup.token.empty() && preset && !preset->token) {
    if (preset->name != std::string("fountain")) mode_ = Mode::step, one_ = preset_step(preset->name);
    // A figure shows the fountain grown: two seconds of it.
    else case_.steps = 120;
    restart();
    frame_inputs();
    return;
  }
  const std::string start = starting_token(setup, kPresets, "");
  if (start.empty()) {
    restart();
    frame_inputs();
    return;
  }
  const ParsedToken token = parse_token(start);
  const std::string& q = token.query;
  if (q == "system") {
    case_ = input_from_token<SystemCase>(token);
  } else if (q == "aim" || q == "exact.aim") {
    mode_ = Mode::target, launch_ = input_from_token<LaunchCase>(token);
  } else if (q == "collide" || q == "invariants") {
    mode_ = Mode::step, one_ = input_from_token<CollideCase>(token);
  } else if (q == "first_hit" || q == "exact.first_hit" || q == "hit_plane") {
    const auto in = input_from_token<SegmentScene>(token);
    mode_ = Mode::step, one_ = CollideCase{in.segment, in.segment.b - in.segment.a, 1, 1, in.scene};
    if (q == "hit_plane") one_.scene.planes.resize(std::min<std::size_t>(1, one_.scene.planes.size())), one_.scene.mesh = {};
  } else {
    throw unknown_query("07", q, "system, aim, exact.aim, collide, invariants, first_hit, exact.first_hit, hit_plane");
  }
  if (mode_ == Mode::fountain) {
    const int steps = case_.steps;
    case_.steps = 0;
    restart();
    playing_ = false;
    for (int k = 0; k < steps; ++k) advance();
  } else {
    restart();
  }
  frame_inputs();
}

void ParticlesScene::restart() {
  system_ = system_of(case_);
  tracks_.clear();
  stepped_ = 0;
  for (int k = 0; k < case_.steps; ++k) advance();
}

void ParticlesScene::frame_inputs() {
  const char* names[] = {"fountain", "target practice", "one step"};
  mode = names[int(mode_)];
  Eigen::AlignedBox3d box;
  if (mode_ == Mode::fountain) {
    box.extend(Vec3(-4, -4, 0)), box.extend(Vec3(4, 4, 3));
  } else if (mode_ == Mode::target) {
    box.extend(launch_.from), box.extend(launch_.target);
    const double reach = launch_.speed * launch_.speed / std::max(launch_.gravity.norm(), 1e-9);
    box.extend(launch_.from - launch_.gravity.normalized() * std::min(reach / 2, 2 * (launch_.target - launch_.from).norm()));
  } else {
    // A moving scene: also where it carries a (a') and where its surfaces start the step.
    const Vec3 carried = one_.scene.velocity * one_.dt;
    box.extend(one_.step.a), box.extend(one_.step.b), box.extend(one_.step.a + carried), box.extend(one_.step.b - carried);
    for (const Vec3& v : one_.scene.mesh.vertices) box.extend(v);
  }
  frame(box);
  if (mode_ == Mode::step && one_.scene.velocity != Vec3::Zero()) radius *= 1.3;  // room for a' above the legend
}

// ---- update --------------------------------------------------------------------------

// System::step, one call at a time, so each particle's collision can be judged. A stubbed
// function leaves what it would have done undone (no births, no motion, no bounce).
void ParticlesScene::advance() {
  System& s = system_;
  const double dt = case_.dt;
  stub_.clear();
  const auto note = [&](const std::string& problem) {
    if (stub_.empty()) stub_ = problem;
  };
  emitter_before_ = s.emitter;
  births_ = attempt([&] { return births(s.emitter, dt); });
  if (births_) {
    s.emitter.owed = births_->owed;
    for (int i = 0; i < births_->count; ++i) {
      const auto p = attempt([&] { return emit(s.emitter, s.random); });
      if (!p) { note(p.problem); break; }
      if (s.integrator == Integrator::verlet) {
        const auto v = attempt([&] { return start_verlet(*p, s.forces, dt); });
        s.particles.push_back(v ? *v : *p);
      } else {
        s.particles.push_back(*p);
      }
    }
  } else {
    note(births_.problem);
  }
  tracks_.clear();
  for (Particle& p : s.particles) {
    Track t;
    const Vec3 a = p.position;
    const MotionCase motion{p, s.forces, dt};
    const auto moved = attempt([&] {
      return s.integrator == Integrator::euler ? euler_step(p, s.forces, dt) : verlet_step(p, s.forces, dt);
    });
    if (&p == &s.particles.front()) motion_in_ = motion, moved_ = moved;
    if (!moved) { note(moved.problem); t.particle = p; tracks_.push_back(t); continue; }
    p = *moved;
    t.step = CollideCase{{a, p.position}, p.velocity, p.mass, dt, s.scene};
    t.collision = attempt([&] { return collide(t.step.step, p.velocity, p.mass, dt, s.scene); });
    if (t.collision) {
      p.position = t.collision->position, p.velocity = t.collision->velocity, p.bounces = t.collision->bounces;
      if (s.integrator == Integrator::verlet && (t.collision->bounces > 0 || t.collision->stopped))
        p.previous = p.position - p.velocity * dt;
      const check::Outcome o = judge::invariants(t.step, *t.collision);
      t.invariants = o.verdict == check::Outcome::Verdict::fail ? Verdict::disagree : Verdict::agree;
    } else {
      note(t.collision.problem);
      t.invariants = t.collision.stub ? Verdict::stub : Verdict::disagree;
    }
    t.particle = p;
    tracks_.push_back(t);
  }
  age_in_ = AgeCase{s.particles, dt};
  aged_ = attempt([&] { return age(s.particles, dt); });
  if (aged_) {
    // Keep the tracks of the survivors: age keeps the order, so match them in turn.
    std::vector<Track> kept;
    std::size_t k = 0;
    for (const Particle& q : *aged_) {
      while (k < tracks_.size() && tracks_[k].particle.position != q.position) ++k;
      if (k < tracks_.size()) kept.push_back(tracks_[k++]);
    }
    s.particles = *aged_;
    tracks_ = kept;
  } else {
    note(aged_.problem);
    if (s.particles.size() > 2000) s.particles.erase(s.particles.begin());  // no deaths: keep it bounded
  }
  s.time += dt;
  ++stepped_;
}

void ParticlesScene::update() {
  steps.clear();
  if (mode_ == Mode::fountain) update_fountain();
  else if (mode_ == Mode::target) update_target();
  else update_step(one_, 4);
}

void ParticlesScene::update_fountain() {
  const double dt = case_.dt;
  Step s1 = judged("L07S1", "births, emit, age", births_, [&](const Births& got) {
    return judge::births(BirthsCase{emitter_before_, dt, 1}, {got});
  });
  if (births_ && aged_) {
    join(s1, aged_, [&](const std::vector<Particle>& got) { return judge::age(age_in_, got); });
  }
  s1.rows = {{"born this step", births_ ? std::to_string(births_->count) : "", ""},
             {"owed", births_ ? num(births_->owed) : "", ""},
             {"alive", std::to_string(system_.particles.size()), ""},
             {"time", num(system_.time), ""}};
  verdict_[1] = s1.verdict;
  steps.push_back(s1);

  const bool verlet = system_.integrator == Integrator::verlet;
  if (moved_.value || moved_.stub || !moved_.problem.empty()) {
    Step s2 = judged("L07S2", verlet ? "verlet_step (the followed particle)" : "euler_step (the followed particle)", moved_,
                     [&](const Particle& got) {
                       return verlet ? judge::verlet_step(motion_in_, got) : judge::euler_step(motion_in_, got);
                     });
    s2.rows = {{"position", moved_ ? num(moved_->position) : "", ""}, {"velocity", moved_ ? num(moved_->velocity) : "", ""}};
    verdict_[2] = s2.verdict;
    steps.push_back(s2);
  } else {
    steps.push_back({"L07S2", "integrate", Verdict::none, {}, "no particle yet"});
  }

  // Steps 4 to 6 for the followed particle (the oldest), step 7 for all.
  if (!tracks_.empty() && tracks_.front().step.dt > 0) {
    one_ = tracks_.front().step;
    update_step(one_, 4);
  } else {
    steps.push_back({"L07S4", "first_hit", Verdict::none, {}, "no particle step to test yet"});
  }
  int broken = 0, judged_count = 0, stubbed = 0;
  for (const Track& t : tracks_) {
    if (t.invariants == Verdict::disagree) ++broken;
    if (t.invariants == Verdict::stub) ++stubbed;
    if (t.invariants != Verdict::none) ++judged_count;
  }
  // Replace the single-particle step 7 with the whole fountain's.
  if (!steps.empty() && steps.back().tag == "L07S7") steps.pop_back();
  Step s7{"L07S7", "never behind, energy: every particle's step", Verdict::none, {}, {}};
  s7.verdict = stubbed > 0 ? Verdict::stub : broken > 0 ? Verdict::disagree : judged_count > 0 ? Verdict::agree : Verdict::none;
  if (stubbed > 0) s7.note = stub_;
  else if (broken > 0) s7.note = std::to_string(broken) + " particles broke an invariant this step (red)";
  s7.rows = {{"particles judged", std::to_string(judged_count), ""}, {"invariants broken", std::to_string(broken), "0"}};
  verdict_[7] = s7.verdict;
  steps.push_back(s7);
}

void ParticlesScene::update_target() {
  const LaunchCase& in = launch_;
  aim_ = attempt([&] { return aim(in.from, in.target, in.speed, in.gravity); });
  Step s3 = judged("L07S3", "aim: the launch angles", aim_, [&](const Aim& got) { return judge::aim(in, got); });
  const int sign = oracle::launch_sign(in.from, in.target, in.speed, in.gravity);
  const bool vertical = oracle::launch_vertical(in.from, in.target, in.gravity) || in.speed == 0;
  const int exact_count = vertical ? 0 : sign > 0 ? 2 : sign == 0 ? 1 : 0;
  const double deg = 180 / M_PI;
  s3.rows = {{"count", aim_ ? std::to_string(aim_->count) : "", std::to_string(exact_count)},
             {"radicand", aim_ ? num(aim_->radicand) : "", num(oracle::launch_radicand(in.from, in.target, in.speed, in.gravity))}};
  if (aim_ && aim_->count > 0) {
    s3.rows.push_back({"low: degrees, time", num(aim_->low.angle * deg) + ", " + num(aim_->low.time), ""});
    s3.rows.push_back({"high: degrees, time", num(aim_->high.angle * deg) + ", " + num(aim_->high.time), ""});
  }
  verdict_[3] = s3.verdict;
  steps.push_back(s3);
}

void ParticlesScene::update_step(const CollideCase& in, int) {
  // A moving scene is tested in its own frame: the relative step a' -> b, a' = a + u dt.
  const Vec3 u = in.scene.velocity;
  const bool moving = u != Vec3::Zero();
  const SegmentScene seg{{in.step.a + u * in.dt, in.step.b}, in.scene};
  first_ = attempt([&] { return first_hit(seg.segment, in.scene); });
  exact_hit_ = exact_first_hit(seg.segment, in.scene);
  Step s4 = judged("L07S4", moving ? "first_hit of the relative step a' -> b" : "first_hit of the step a -> b", first_,
                   [&](const SurfaceHit& got) { return judge::first_hit(seg, got); });
  const auto& f = first_;
  s4.rows = {{"hit", f ? (f->hit ? (f->plane >= 0 ? "plane " + std::to_string(f->plane) : "triangle " + std::to_string(f->triangle)) : "none") : "",
              exact_hit_.hit ? "yes" : "none"},
             {"t", f && f->hit ? num(f->t) : "", exact_hit_.hit ? num(exact_hit_.t) : ""},
             {"point", f && f->hit ? num(f->point) : "", exact_hit_.hit ? num(exact_hit_.point) : ""}};
  verdict_[4] = s4.verdict;
  steps.push_back(s4);

  // Step 5: the impulse at the first hit, with the exact normal of what was hit.
  if (exact_hit_.hit && f && f->hit) {
    const ImpulseCase ic{in.velocity, u, f->normal, in.mass, in.scene.material};
    impulse_ = attempt([&] { return impulse(ic.velocity, ic.object_velocity, ic.normal, ic.mass, ic.material); });
    Step s5 = judged("L07S5", "impulse at the first hit", impulse_, [&](const Impulse& got) { return judge::impulse(ic, got); });
    const oracle::Impulse e = oracle::impulse(ic.velocity, ic.object_velocity, ic.normal, ic.mass, ic.material.restitution,
                                              ic.material.friction);
    s5.rows = {{"v_close", impulse_ ? num(impulse_->v_close) : "", num(e.v_close)},
               {"velocity after", impulse_ ? num(impulse_->velocity) : "", num(e.velocity)}};
    verdict_[5] = s5.verdict;
    steps.push_back(s5);
  } else {
    impulse_ = {};
    verdict_[5] = Verdict::none;
    steps.push_back({"L07S5", "impulse", Verdict::none, {}, f ? "no hit: no impulse" : "needs first_hit (L07S4)"});
  }

  collision_ = attempt([&] { return collide(in.step, in.velocity, in.mass, in.dt, in.scene); });
  Step s6 = judged("L07S6", "collide: bounces in the remaining time", collision_,
                   [&](const Collision& got) { return judge::collide(in, got); });
  s6.rows = {{"bounces", collision_ ? std::to_string(collision_->bounces) + (collision_->stopped ? ", stopped" : "") : "", ""},
             {"end", collision_ ? num(collision_->position) : "", ""},
             {"velocity", collision_ ? num(collision_->velocity) : "", ""}};
  verdict_[6] = s6.verdict;
  steps.push_back(s6);
  Step s7 = judged("L07S7", "invariants: never behind, energy", collision_,
                   [&](const Collision& got) { return judge::invariants(in, got); });
  s7.rows = {{moving ? "|v - u|^2 before, after" : "|v|^2 before, after",
              collision_ ? num((in.velocity - u).squaredNorm()) + ", " + num((collision_->velocity - u).squaredNorm()) : "", ""}};
  verdict_[7] = s7.verdict;
  steps.push_back(s7);
}

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
      const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
      const Vec3 q[4] = {foot + size * (u + w), foot + size * (-u + w), foot + size * (-u - w), foot + size * (u - w)};
      r.triangle(q[0], q[1], q[2], palette::surface.with_alpha(0.08f));
      r.triangle(q[0], q[2], q[3], palette::surface.with_alpha(0.08f));
      for (int k = 0; k < 4; ++k) r.dashed(q[k], q[(k + 1) % 4], palette::muted, 1);
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
    const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
    const Vec3 q[4] = {foot + size * (u + w), foot + size * (-u + w), foot + size * (-u - w), foot + size * (u - w)};
    r.triangle(q[0], q[1], q[2], palette::surface.with_alpha(0.25f));
    r.triangle(q[0], q[2], q[3], palette::surface.with_alpha(0.25f));
    r.arrow(foot, foot + 0.15 * size * n, palette::muted, 1.5f);
  }
  for (std::size_t i = 0; i < scene.mesh.size(); ++i) {
    const Triangle t = scene.mesh.triangle(i);
    r.triangle(t.v0, t.v1, t.v2, palette::surface.with_alpha(0.8f));
    const Color e{0.30f, 0.40f, 0.55f};
    r.line(t.v0, t.v1, e, 1), r.line(t.v1, t.v2, e, 1), r.line(t.v2, t.v0, e, 1);
  }
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
    r.point(in.target, palette::input, 7), r.ring(in.target, palette::input, 12), r.label(in.target, "target", palette::input);
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
        if (s == &aim_->low) r.label(mid, degrees, c, -90, 22);  // below the flat arc, clear of the lobbed one
        else r.label(mid, degrees, c);
        r.arrow(in.from, in.from + s->velocity * 0.15, c, 2);
      }
    } else if (aim_) {
      r.label(in.target, "out of reach", colour(verdict_[3]), 12, 12);
    }
    return;
  }
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
  bool changed = false;
  if (mode_ == Mode::target) {
    changed |= edit("from", launch_.from) | edit("target", launch_.target) | edit("speed", launch_.speed, 0.1f, 0, 1e6) |
               edit("gravity", launch_.gravity);
    return changed;
  }
  if (mode_ == Mode::step) {
    changed |= edit("a", one_.step.a) | edit("b", one_.step.b) | edit("velocity", one_.velocity) |
               edit("restitution", one_.scene.material.restitution, 0.01f, 0, 1) |
               edit("friction", one_.scene.material.friction, 0.01f, 0, 2) | edit("scene velocity u", one_.scene.velocity);
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
  return {};
}

std::string ParticlesScene::token() const {
  if (mode_ == Mode::target) return replay_token("aim", launch_);
  if (mode_ == Mode::step) return replay_token("collide", one_);
  SystemCase c = case_;
  c.steps = stepped_;
  return replay_token("system", c);
}

}  // namespace

std::unique_ptr<Scene> make_particles(const Setup& setup) { return std::make_unique<ParticlesScene>(setup); }
const std::vector<Preset>& particles_presets() { return kPresets; }

}  // namespace viewer
