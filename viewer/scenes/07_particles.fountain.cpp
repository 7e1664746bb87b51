// Lab 07 scene, the fountain: System::step run one student's function at a time, so that
// every particle's step can be judged, and the steps the fountain shows (1, 2, 7 for all
// particles; 4 to 6 for the one followed).
#include "viewer/scenes/07_particles.h"

namespace viewer::particles {

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
      if (!p) {
        note(p.problem);
        break;
      }
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
    const auto moved = attempt(
        [&] { return s.integrator == Integrator::euler ? euler_step(p, s.forces, dt) : verlet_step(p, s.forces, dt); });
    if (&p == &s.particles.front()) motion_in_ = motion, moved_ = moved;
    if (!moved) {
      note(moved.problem);
      t.particle = p;
      tracks_.push_back(t);
      continue;
    }
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
    Step s2 = judged("L07S2", verlet ? "verlet_step (the followed particle)" : "euler_step (the followed particle)",
                     moved_, [&](const Particle& got) {
                       return verlet ? judge::verlet_step(motion_in_, got) : judge::euler_step(motion_in_, got);
                     });
    s2.rows = {{"position", moved_ ? num(moved_->position) : "", ""},
               {"velocity", moved_ ? num(moved_->velocity) : "", ""}};
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
  s7.verdict = stubbed > 0        ? Verdict::stub
               : broken > 0       ? Verdict::disagree
               : judged_count > 0 ? Verdict::agree
                                  : Verdict::none;
  if (stubbed > 0)
    s7.note = stub_;
  else if (broken > 0)
    s7.note = std::to_string(broken) + " particles broke an invariant this step (red)";
  s7.rows = {{"particles judged", std::to_string(judged_count), ""},
             {"invariants broken", std::to_string(broken), "0"}};
  verdict_[7] = s7.verdict;
  steps.push_back(s7);
}

}  // namespace viewer::particles
