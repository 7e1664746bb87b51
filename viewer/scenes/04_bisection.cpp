// Lab 04 scene: time of impact by bisection (handouts/04_bisection.md).
//
// A replay token's query picks the mode:
//   bisection                 overlap_at, bisect, distance_at          steps 1, 2, 4
//   sub-steps                 sample_then_bisect                       steps 1, 3
//   tunnelling                bisect on the frame's ends, closing_speed,
//                             substeps_for (a closing_speed token too)  steps 1-3
//   conservative advancement  advance                                  steps 1, 4
//   closest point             closest_point                            step 1
//   sub-step rule             substeps_for                             step 3
// The two bodies are drawn along their motion (faint at every time the student's search
// asked for a pose), at the student's last clear time t and first overlapping time
// t_contact in the colour of the verdict, and at the certified exact first contact in
// violet. Below them a time axis: every tested time (white: clear, blue: overlapping,
// decided exactly), and the bracket [lo, hi] the tests so far imply, one row per test.
#include "viewer/scenes/04_bisection.h"
#include "viewer/scenes/scenes.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cmath>

namespace viewer::bisection {

const std::vector<Preset> kPresets = {
    {"lecture", "the lecture's bisection: 0.5, 0.25, 0.375, 0.4375, 0.40625", nullptr, true, -90, 86, 2},
    {"tunnelling", "a bullet passes a thin window between the frame's ends; 25 sub-steps see it", nullptr, true, -90,
     86, 3},
    {"advance", "conservative advancement: each advance leaves a quarter of the gap", nullptr, true, -90, 86, 4},
    {"spinning-bar", "a spinning bar sweeps into a resting ball", nullptr, false, -90, 86, 2},
    {"graze", "a graze at a sample time is a contact", nullptr, false, -90, 86, 3},
    {"turned-box", "the closest point of a turned box: clamp in its own axes", nullptr, false, -90, 80, 1},
};

// ---- the tests' and the handout's bodies ----------------------------------------------

MotionParameters still(const Vec3& p) {
  MotionParameters m;
  m.start = p;
  return m;
}
MotionParameters moving(const Vec3& start, const Vec3& velocity) {
  MotionParameters m = still(start);
  m.velocity = velocity;
  return m;
}
MovingBody ball(double radius, const MotionParameters& m) { return {false, Sphere{Vec3::Zero(), radius}, Box{}, m}; }
MovingBody block(const Vec3& half_extents, const MotionParameters& m) {
  return {true, Sphere{}, Box{Vec3::Zero(), Mat3::Identity(), half_extents}, m};
}
// The ball x(t) = -6 + 12 t and the wall [0, 8] x [-4, 4]^2 (steps 1, 2 and 4).
MovingPairCase ball_and_wall(double tolerance) {
  return {ball(1, moving({-6, 0, 0}, {12, 0, 0})), block({4, 4, 4}, still({4, 0, 0})), SearchTimes{0, 1, tolerance}};
}
// The bullet x(t) = -3 + 6 t, radius 1/8, and the window |x| <= 1/4 (step 3).
MovingPairCase bullet_and_window(double tolerance) {
  return {ball(0.125, moving({-3, 0, 0}, {6, 0, 0})), block({0.25, 2, 2}, still(Vec3::Zero())),
          SearchTimes{0, 1, tolerance}};
}

// ---- setup ---------------------------------------------------------------------------

BisectionScene::BisectionScene(const Setup& setup) {
  const Preset* preset = find_preset(kPresets, setup.preset);
  if (!preset && setup.token.empty()) preset = &kPresets[0];  // the lecture's example
  if (preset) yaw = preset->yaw, pitch = preset->pitch, focus = preset->focus;
  if (!setup.token.empty()) yaw = -90, pitch = 86;  // from above: the motion and the time axis side by side
  point_box_ = {{3, 2, 0}, Box{Vec3::Zero(), Mat3::Identity(), {4, 1, 1}}};
  point_box_.box.axes << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  if (setup.token.empty()) {
    const std::string name = preset ? preset->name : "lecture";
    if (name == "tunnelling") {
      mode_ = Mode::tunnelling, case_ = bullet_and_window(1.0 / 64);
    } else if (name == "advance") {
      mode_ = Mode::advance, case_ = ball_and_wall(1.0 / 256), speed_factor_ = 16.0 / 12;
    } else if (name == "spinning-bar") {
      case_ = {ball(1, still({0, 3, 0})), block({4, 1, 1}, still(Vec3::Zero())), SearchTimes{0, 1, 1.0 / 64}};
      case_.b.motion.spin = std::acos(-1.0) / 2;
    } else if (name == "graze") {
      mode_ = Mode::sampled, substeps_ = 2;
      case_ = {ball(1, moving({-4, 2, 0}, {8, 0, 0})), ball(1, still(Vec3::Zero())), SearchTimes{0, 1, 0.0625}};
    } else if (name == "turned-box") {
      mode_ = Mode::point;
    }
    frame_inputs();
    return;
  }
  const ParsedToken token = parse_token(setup.token);
  load_token(
      "04", query::table, token,
      Loaders{[&](auto q, const MovingPairCase& in) {
    case_ = in;
    if (q == query::tunnelling || q == query::closing_speed) mode_ = Mode::tunnelling;
              },
              [&](auto, const SampledPair& in) {
    mode_ = Mode::sampled, case_ = in.pair, substeps_ = std::max(1, in.substeps);
      },
      [&](auto, const AdvancedPair& in) { mode_ = Mode::advance, case_ = in.pair, speed_factor_ = in.speed_factor; },
      [&](auto, const PointBox& in) { mode_ = Mode::point, point_box_ = in; },
      [&](auto, const SubstepRule& in) { mode_ = Mode::rule, rule_ = in; }});
  frame_inputs();
}

void BisectionScene::frame_inputs() {
  const char* names[] = {"bisection",     "sub-steps",    "tunnelling", "conservative advancement",
                         "closest point", "sub-step rule"};
  mode = names[int(mode_)];
  Eigen::AlignedBox3d box;
  if (mode_ == Mode::point) {
    box.extend(point_box_.point);
    for (int i = 0; i < 8; ++i) box.extend(point_box_.box.corner(i));
  } else if (mode_ == Mode::rule) {
    box.extend(Vec3(-1, -1, 0)), box.extend(Vec3(1, 1, 0));
  } else {
    layout();
    box.extend(Vec3(left_, y0_ - (kRows + 1) * row_, z_));
    box.extend(Vec3(left_ + width_, y0_, z_));
    box.extend(bodies_);
    // Room above the bodies: their near faces look larger in perspective, and the
    // picture's caption covers the top of the view.
    box.extend(Vec3(bodies_.center().x(), bodies_.max().y() + 0.6 * bodies_.sizes().y(), bodies_.center().z()));
  }
  frame(box, 0.32);
}

std::string BisectionScene::token() const {
  switch (mode_) {
    case Mode::bisect: return replay_token(query::bisect, case_);
    case Mode::sampled: return replay_token(query::sample_then_bisect, SampledPair{case_, substeps_});
    case Mode::tunnelling: return replay_token(query::tunnelling, case_);
    case Mode::advance: return replay_token(query::advance, AdvancedPair{case_, speed_factor_});
    case Mode::point: return replay_token(query::closest_point, point_box_);
    case Mode::rule: break;
  }
  return replay_token(query::substeps_for, rule_);
}

// ---- update --------------------------------------------------------------------------

MovingPair BisectionScene::recorded_pair(Recorder& recorder) const {
  MovingPair pair = pair_of(case_);
  const Motion a = pair.motion_a;
  pair.motion_a = [a, &recorder](double t) {
    recorder.note(t);
    return a(t);
  };
  return pair;
}

void BisectionScene::step_overlap() {
  const MovingPair pair = pair_of(case_);
  const SearchTimes& T = case_.times;
  const auto got = attempt([&] { return std::pair<bool, bool>(overlap_at(pair, T.t0), overlap_at(pair, T.t1)); });
  Step s = judged("L04S1", "overlap_at the ends t0 and t1", got,
                  [&](const std::pair<bool, bool>& g) { return judge::overlap_at(case_, g.first, g.second); });
  s.rows = {{"at t0 = " + num(T.t0), got ? yes_no(got->first) : "", yes_no(exact_overlap(T.t0))},
            {"at t1 = " + num(T.t1), got ? yes_no(got->second) : "", yes_no(exact_overlap(T.t1))}};
  verdict_[1] = s.verdict;
  steps.push_back(s);
}

// The rows every search shows, and the exact first contact beside them.
std::vector<Row> search_rows(const Attempt<TimeOfImpact>& g, bool exact_hit, bool exact_at_start, double exact_lo,
                             double exact_hi) {
  const std::string contact = exact_at_start ? "at t0"
                              : exact_hit    ? "in (" + num(exact_lo) + ", " + num(exact_hi) + "]"
                                             : "none seen";
  return {{"hit", g ? yes_no(g->hit) + (g->overlapping_at_start ? " (at start)" : "") : "", exact_hit ? "yes" : "no"},
          {"t (last clear)", g ? num(g->t) : "", exact_hit && !exact_at_start ? num(exact_lo) : ""},
          {"t_contact", g && g->hit ? num(g->t_contact) : "", "first contact " + contact},
          {"steps, iterations", g ? std::to_string(g->steps) + ", " + std::to_string(g->iterations) : "", ""}};
}

void BisectionScene::step_bisect(const char* title) {
  Recorder recorder;
  const MovingPair pair = recorded_pair(recorder);
  const SearchTimes& T = case_.times;
  search_ = attempt([&] { return bisect(pair, T.t0, T.t1, T.tolerance); });
  Step s = judged("L04S2", title, search_, [&](const TimeOfImpact& got) { return judge::bisect(case_, got); });
  s.rows = search_rows(search_, exact_hit_, exact_at_start_, exact_lo_, exact_hi_);
  if (search_ && !search_->hit && exact_hit_ && !exact_at_start_ && s.verdict != Verdict::disagree && s.note.empty())
    s.note = "clear at both ends: bisection alone cannot see this contact";
  verdict_[2] = search_verdict_ = s.verdict, search_step_ = 2;
  tested_ = recorder.times;
  steps.push_back(s);
}

void BisectionScene::step_closing_speed() {
  const SearchTimes& T = case_.times;
  const auto got = attempt([&] {
    return closing_speed(case_.a.sphere, motion_of(case_.a.motion), shape_of(case_.b), motion_of(case_.b.motion), T.t0,
                         T.t1);
  });
  Step s = judged("L04S3", "closing_speed: max_speed(a) + max_speed(b)", got,
                  [&](double v) { return judge::closing_speed(case_, v); });
  s.rows = {{"closing speed", got ? num(*got) : "", num(closing_speed_of(case_))}};
  verdict_[3] = s.verdict;
  steps.push_back(s);
}

void BisectionScene::step_rule(const SubstepRule& rule) {
  const auto got = attempt([&] { return substeps_for(rule.max_speed, rule.step, rule.smallest_size); });
  Step s = judged("L04S3", "substeps_for: speed x step / n < smallest size", got,
                  [&](int n) { return judge::substeps_for(rule, n); });
  const double ratio = rule.max_speed * rule.step / rule.smallest_size;
  const int exact = rule.smallest_size > 0 && ratio < kMaxSubsteps ? int(std::floor(ratio)) + 1 : 0;
  s.rows = {{"speed, step, size", num(rule.max_speed) + ", " + num(rule.step) + ", " + num(rule.smallest_size), ""},
            {"substeps", got ? std::to_string(*got) : "", std::to_string(exact) + "  (ratio " + num(ratio) + ")"}};
  verdict_[3] = worse(verdict_[3], s.verdict);  // a wrong closing speed stays shown
  steps.push_back(s);
}

void BisectionScene::step_sampled(int n, const char* title) {
  Recorder recorder;
  const MovingPair pair = recorded_pair(recorder);
  const SearchTimes& T = case_.times;
  const SampledPair in{case_, n};
  search_ = attempt([&] { return sample_then_bisect(pair, T.t0, T.t1, n, T.tolerance); });
  Step s = judged("L04S3", title, search_, [&](const TimeOfImpact& got) { return judge::sample_then_bisect(in, got); });
  s.rows = search_rows(search_, exact_hit_, exact_at_start_, exact_lo_, exact_hi_);
  s.rows.insert(s.rows.begin(), {"sub-steps n", std::to_string(n), ""});
  verdict_[3] = worse(verdict_[3], s.verdict), search_verdict_ = s.verdict, search_step_ = 3;
  tested_ = recorder.times;
  steps.push_back(s);
}

void BisectionScene::step_advance() {
  const MovingPair pair = pair_of(case_);
  const SearchTimes& T = case_.times;
  const auto d = attempt([&] { return std::pair<double, double>(distance_at(pair, T.t0), distance_at(pair, T.t1)); });
  Step dist = judged("L04S4", "distance_at t0 and t1", d,
                     [&](const std::pair<double, double>& g) { return judge::distance_at(case_, g.first, g.second); });
  dist.rows = {{"distance at t0", d ? num(d->first) : "", num(exact_distance(T.t0))},
               {"distance at t1", d ? num(d->second) : "", num(exact_distance(T.t1))}};
  verdict_[4] = dist.verdict;
  if (mode_ != Mode::advance) {
    steps.push_back(dist);
    return;
  }
  Recorder recorder;
  const MovingPair recorded = recorded_pair(recorder);
  const AdvancedPair in{case_, speed_factor_};
  const double bound = judge::closing_speed_of(in);
  search_ = attempt([&] { return advance(recorded, T.t0, T.t1, bound, T.tolerance); });
  Step s = judged("L04S4", "advance: jump d / v, then bisect", search_,
                  [&](const TimeOfImpact& got) { return judge::advance(in, got); });
  join(s, dist);
  s.rows = dist.rows;
  s.rows.push_back({"closing-speed bound v", num(bound), num(closing_speed_of(case_)) + " (true)"});
  for (const Row& row : search_rows(search_, exact_hit_, exact_at_start_, exact_lo_, exact_hi_)) s.rows.push_back(row);
  verdict_[4] = search_verdict_ = s.verdict, search_step_ = 4;
  tested_ = recorder.times;
  steps.push_back(s);
}

void BisectionScene::update() {
  steps.clear();
  for (Verdict& v : verdict_) v = Verdict::none;
  search_ = {};
  tested_.clear(), tested_overlap_.clear();
  switch (mode_) {
    case Mode::point: update_point(); return;
    case Mode::rule: step_rule(rule_); return;
    case Mode::bisect: update_bisect(); break;
    case Mode::sampled: update_sampled(); break;
    case Mode::tunnelling: update_tunnelling(); break;
    case Mode::advance: update_advance(); break;
  }
  for (double t : tested_) tested_overlap_.push_back(exact_overlap(t));
}

void BisectionScene::update_point() {
  closest_ = attempt([&] { return closest_point(point_box_.box, point_box_.point); });
  Step s = judged("L04S1", "closest_point of the box to p", closest_,
                  [&](const Vec3& got) { return judge::closest_point(point_box_, got); });
  const RigidTransform id = RigidTransform::Identity();
  s.rows = {{"q", closest_ ? num(*closest_) : "", ""},
            {"|p - q|", closest_ ? num((*closest_ - point_box_.point).norm()) : "",
             num(oracle::sphere_box_distance(Sphere{point_box_.point, 0}, id, point_box_.box, id))}};
  closest_verdict_ = verdict_[1] = s.verdict;
  steps.push_back(s);
}

// What every search starts with: sane times, the layout, the exact first contact, step 1.
void BisectionScene::start_search() {
  SearchTimes& T = case_.times;
  T.t1 = std::max(T.t1, T.t0);
  T.tolerance = std::max(T.tolerance, std::ldexp(std::max(T.t1 - T.t0, 1e-300), -40));
  layout();
  exact_first_contact();
  step_overlap();
}

void BisectionScene::update_bisect() {
  start_search();
  step_bisect("bisect [t0, t1] to the last clear time");
  step_advance();  // distance_at only
}

void BisectionScene::update_sampled() {
  start_search();
  step_sampled(substeps_, "sample_then_bisect with n sub-steps");
}

// Bisection on the frame's ends misses the window; the rule's n sub-steps see it.
void BisectionScene::update_tunnelling() {
  start_search();
  const SearchTimes& T = case_.times;
  step_bisect("bisect: the frame's ends only");
  step_closing_speed();
  const SubstepRule rule{closing_speed_of(case_), T.t1 - T.t0, smallest_size_of(case_)};
  step_rule(rule);
  const Attempt<int> n = attempt([&] { return substeps_for(rule.max_speed, rule.step, rule.smallest_size); });
  const double ratio = rule.smallest_size > 0 ? rule.max_speed * rule.step / rule.smallest_size : 0;
  substeps_ = n && *n > 0 ? *n : int(std::clamp(std::floor(ratio) + 1, 1.0, 4096.0));
  step_sampled(std::min(substeps_, 4096), "sample_then_bisect with the rule's n");
}

void BisectionScene::update_advance() {
  start_search();
  step_advance();
}

// ---- draw: in 04_bisection.draw.cpp, with inputs() and handles() --------------------

}  // namespace viewer::bisection

LABKIT_SCENE(bisection, BisectionScene)
