// Lab 07 scene: particle systems that bounce (handouts/07_particles.md).
//
// A replay token's query picks the mode:
//   fountain         system (or no token): a fountain on a terrain and a floor,
//                    animated with play, pause and single-step        steps 1, 2, 4-7
//   target practice  aim, exact.aim: the two shots at a target        step 3
//   spring           spring_force: two particles on a damped spring   step 9
//   bodies           rigid_impulse: two rigid bodies at a contact     step 10
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
#include "viewer/scenes/07_particles.h"
#include "viewer/scenes/scenes.h"

#include "common/generators/meshes.h"
#include "common/oracle/oracle.h"

#include <cmath>

namespace viewer::particles {

const std::vector<Preset> kPresets = {
    {"fountain", "a fountain bouncing on a terrain: e = 0.6, mu = 0.2", nullptr, true, -50, 22},
    {"target", "the lecture's target practice: 25 m/s, 40 m away: 19.445 and 70.555 degrees",
     "aim:0,0,0,40,0,0,25,0,0,-9.81", true, -90, 2, 3},
    {"corner", "floor, then wall: two bounces in the remaining time (e = 1)", nullptr, true, -90, 2, 6},
    {"crack", "a crack between floor and ceiling: bounces up to the cap, then stops", nullptr, false, -90, 2, 6},
    {"dead", "a dead bounce (e = 0): the hit point is settled above the floor", nullptr, false, -90, 2, 7},
    {"paddle", "a floor rising at u = (0, 0, 2) (e = 1/2): the bounce seen from the floor, from a' = a + u dt", nullptr,
     true, -90, 2, 6},
    {"spring", "a stretched spring with damping: the force on a, and its opposite on b", nullptr, true, -90, 2, 9},
    {"bodies", "a box falls on its edge onto a block (e = 1/2): j = 1, and it starts to turn", nullptr, true, -90, 2,
     10},
};

// The exact first hit of a segment on a scene (planes, then triangles; ties to the first).
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
  c.scene.mesh = gen::height_field(16, -4, 4, -4, 4, [](double x, double y) {  // rolling hills, below z = 0.6
    return 0.35 + 0.3 * std::sin(x * 1.1) * std::cos(y * 0.8);
  });
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
  spring_ = default_spring();
  bodies_ = default_bodies();
  const Preset* preset = view_preset(kPresets, setup);
  if (setup.token.empty() && preset && !preset->token) {
    if (preset->name == std::string("bodies"))
      mode_ = Mode::bodies;
    else if (preset->name == std::string("spring"))
      mode_ = Mode::spring;
    else if (preset->name != std::string("fountain"))
      mode_ = Mode::step, one_ = preset_step(preset->name);
    // A figure shows the fountain grown: two seconds of it.
    else
      case_.steps = 120;
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
  load_token("07", query::table, token,
             Loaders{[&](auto, const SystemCase& in) { case_ = in; },
                     [&](auto, const LaunchCase& in) { mode_ = Mode::target, launch_ = in; },
                     [&](auto, const CollideCase& in) { mode_ = Mode::step, one_ = in; },
                     [&](auto, const SpringCase& in) { mode_ = Mode::spring, spring_ = in; },
                     [&](auto, const RigidCase& in) { mode_ = Mode::bodies, bodies_ = in; },
                     [&](auto q, const SegmentScene& in) {
    mode_ = Mode::step, one_ = CollideCase{in.segment, in.segment.b - in.segment.a, 1, 1, in.scene};
    if (q == query::hit_plane) {
      one_.scene.planes.resize(std::min<std::size_t>(1, one_.scene.planes.size()));
      one_.scene.mesh = {};
    }
                     }});
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
  const char* names[] = {"fountain", "target practice", "one step", "spring", "bodies"};
  mode = names[int(mode_)];
  Eigen::AlignedBox3d box;
  if (mode_ == Mode::fountain) {
    box.extend(Vec3(-4, -4, 0)), box.extend(Vec3(4, 4, 3));
  } else if (mode_ == Mode::target) {
    box.extend(launch_.from), box.extend(launch_.target);
    const double reach = launch_.speed * launch_.speed / std::max(launch_.gravity.norm(), 1e-9);
    box.extend(launch_.from -
               launch_.gravity.normalized() * std::min(reach / 2, 2 * (launch_.target - launch_.from).norm()));
  } else if (mode_ == Mode::spring) {
    box.extend(spring_.a.position), box.extend(spring_.b.position);
    box.extend(spring_.a.position + Vec3::Constant(0.5)), box.extend(spring_.b.position - Vec3::Constant(0.5));
  } else if (mode_ == Mode::bodies) {
    for (const Vec3& p : {bodies_.a.centre, bodies_.b.centre, bodies_.contact.point}) box.extend(p);
    box.extend(box.min() - Vec3::Constant(1)), box.extend(box.max() + Vec3::Constant(1));
  } else {
    // A moving scene: also where it carries a (a') and where its surfaces start the step.
    const Vec3 carried = one_.scene.velocity * one_.dt;
    box.extend(one_.step.a), box.extend(one_.step.b), box.extend(one_.step.a + carried),
        box.extend(one_.step.b - carried);
    for (const Vec3& v : one_.scene.mesh.vertices) box.extend(v);
  }
  frame(box);
  if (mode_ == Mode::step && one_.scene.velocity != Vec3::Zero()) radius *= 1.3;  // room for a' above the legend
}

std::string ParticlesScene::token() const {
  if (mode_ == Mode::target) return replay_token(query::aim, launch_);
  if (mode_ == Mode::step) return replay_token(query::collide, one_);
  if (mode_ == Mode::spring) return replay_token(query::spring_force, spring_);
  if (mode_ == Mode::bodies) return replay_token(query::rigid_impulse, bodies_);
  SystemCase c = case_;
  c.steps = stepped_;
  return replay_token(query::system, c);
}

// ---- update --------------------------------------------------------------------------

void ParticlesScene::update() {
  steps.clear();
  if (mode_ == Mode::fountain)
    update_fountain();
  else if (mode_ == Mode::target)
    update_target();
  else if (mode_ == Mode::spring)
    update_spring();
  else if (mode_ == Mode::bodies)
    update_bodies();
  else
    update_step(one_, 4);
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
             {"radicand", aim_ ? num(aim_->radicand) : "",
              num(oracle::launch_radicand(in.from, in.target, in.speed, in.gravity))}};
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
  s4.rows = {
      {"hit",
       f ? (f->hit ? (f->plane >= 0 ? "plane " + std::to_string(f->plane) : "triangle " + std::to_string(f->triangle))
                   : "none")
         : "",
       exact_hit_.hit ? "yes" : "none"},
      {"t", f && f->hit ? num(f->t) : "", exact_hit_.hit ? num(exact_hit_.t) : ""},
      {"point", f && f->hit ? num(f->point) : "", exact_hit_.hit ? num(exact_hit_.point) : ""}};
  verdict_[4] = s4.verdict;
  steps.push_back(s4);

  // Step 5: the impulse at the first hit, with the exact normal of what was hit.
  if (exact_hit_.hit && f && f->hit) {
    const ImpulseCase ic{in.velocity, u, f->normal, in.mass, in.scene.material};
    impulse_ = attempt([&] { return impulse(ic.velocity, ic.object_velocity, ic.normal, ic.mass, ic.material); });
    Step s5 = judged("L07S5", "impulse at the first hit", impulse_,
                     [&](const Impulse& got) { return judge::impulse(ic, got); });
    const oracle::Impulse e = oracle::impulse(ic.velocity, ic.object_velocity, ic.normal, ic.mass,
                                              ic.material.restitution, ic.material.friction);
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
  s6.rows = {
      {"bounces", collision_ ? std::to_string(collision_->bounces) + (collision_->stopped ? ", stopped" : "") : "", ""},
      {"end", collision_ ? num(collision_->position) : "", ""},
      {"velocity", collision_ ? num(collision_->velocity) : "", ""}};
  verdict_[6] = s6.verdict;
  steps.push_back(s6);
  Step s7 = judged("L07S7", "invariants: never behind, energy", collision_,
                   [&](const Collision& got) { return judge::invariants(in, got); });
  s7.rows = {
      {moving ? "|v - u|^2 before, after" : "|v|^2 before, after",
       collision_ ? num((in.velocity - u).squaredNorm()) + ", " + num((collision_->velocity - u).squaredNorm()) : "",
       ""}};
  verdict_[7] = s7.verdict;
  steps.push_back(s7);
}

// ---- draw: in 07_particles.draw.cpp, with inputs() and handles() --------------------

}  // namespace viewer::particles

LABKIT_SCENE(particles, ParticlesScene)
