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
#include "viewer/scenes/scenes.h"

#include "04_bisection.judge.h"
#include "bisection.h"
#include "common/oracle/oracle.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace viewer {
namespace {

using namespace labkit;
using namespace labkit::lab04;

enum class Mode { bisect, sampled, tunnelling, advance, point, rule };

const std::vector<Preset> kPresets = {
    {"lecture", "the lecture's bisection: 0.5, 0.25, 0.375, 0.4375, 0.40625", nullptr, true, -90, 86, 2},
    {"tunnelling", "a bullet passes a thin window between the frame's ends; 25 sub-steps see it", nullptr, true, -90, 86, 3},
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
  return {ball(0.125, moving({-3, 0, 0}, {6, 0, 0})), block({0.25, 2, 2}, still(Vec3::Zero())), SearchTimes{0, 1, tolerance}};
}


// The times a search asked for poses, in the order it first asked (the searches never
// look inside a motion, so these are exactly the instants it tested).
struct Recorder {
  std::vector<double> times;
  void note(double t) {
    if (std::find(times.begin(), times.end(), t) == times.end()) times.push_back(t);
  }
};

class BisectionScene : public Scene {
 public:
  explicit BisectionScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void frame_inputs();
  void layout();  // where the time axis goes: under the bodies' whole motion
  MovingPair recorded_pair(Recorder& recorder) const;
  RigidTransform pose_a(double t) const { return pose_at(case_.a.motion, t); }
  RigidTransform pose_b(double t) const { return pose_at(case_.b.motion, t); }
  bool exact_overlap(double t) const;
  double exact_distance(double t) const;
  void exact_first_contact();
  void step_overlap();
  void step_bisect(const char* title);
  void step_sampled(int n, const char* title);
  void step_closing_speed();  // the rule's speed, by the code under test
  void step_rule(const SubstepRule& rule);
  void step_advance();
  void draw_body(Renderer& r, const MovingBody& body, const RigidTransform& pose, Color c, bool filled) const;
  void draw_pair(Renderer& r, double t, Color c, bool filled) const;
  void draw_timeline(Frame& f) const;

  Mode mode_ = Mode::bisect;
  MovingPairCase case_ = ball_and_wall(1.0 / 32);
  int substeps_ = 1;           // sub-steps mode: n
  double speed_factor_ = 1.0;  // advancement: the bound is this times the true closing speed
  PointBox point_box_;
  SubstepRule rule_{6, 1, 0.25};

  // The search the picture is about: the student's answer, its verdict and what it asked.
  Attempt<TimeOfImpact> search_;
  Verdict search_verdict_ = Verdict::none;
  int search_step_ = 2;
  std::vector<double> tested_;        // the search's tested times
  std::vector<bool> tested_overlap_;  // exactly, at each
  double bracket_lo_ = 0, bracket_hi_ = 1;  // the interval the search is given (a sub-step's for sampling)
  // The exact first contact: clear at exact_lo_, overlapping at exact_hi_, exact_hi_ -
  // exact_lo_ tiny; found by sampling and bisecting with exact predicates.
  bool exact_hit_ = false, exact_at_start_ = false;
  double exact_lo_ = 0, exact_hi_ = 0;
  Attempt<Vec3> closest_;
  Verdict closest_verdict_ = Verdict::none;
  Verdict verdict_[6] = {};
  // The time axis: t0 at (left_, y0_, z_), t1 width_ to the right; rows row_ apart below.
  double left_ = 0, width_ = 1, y0_ = 0, z_ = 0, row_ = 0.1;
  Eigen::AlignedBox3d bodies_;  // what the bodies sweep over [t0, t1], roughly
  static constexpr int kRows = 12;  // bracket rows at most
};

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
  const std::string& q = token.query;
  if (q == "overlap_at" || q == "bisect" || q == "distance_at" || q == "robust.overlap_at" || q == "robust.bisect") {
    case_ = input_from_token<MovingPairCase>(token);
  } else if (q == "tunnelling" || q == "closing_speed") {
    mode_ = Mode::tunnelling, case_ = input_from_token<MovingPairCase>(token);
  } else if (q == "sample_then_bisect" || q == "robust.sample_then_bisect") {
    const auto in = input_from_token<SampledPair>(token);
    mode_ = Mode::sampled, case_ = in.pair, substeps_ = std::max(1, in.substeps);
  } else if (q == "advance" || q == "robust.advance") {
    const auto in = input_from_token<AdvancedPair>(token);
    mode_ = Mode::advance, case_ = in.pair, speed_factor_ = in.speed_factor;
  } else if (q == "closest_point" || q == "robust.closest_point") {
    mode_ = Mode::point, point_box_ = input_from_token<PointBox>(token);
  } else if (q == "substeps_for" || q == "robust.substeps_for") {
    mode_ = Mode::rule, rule_ = input_from_token<SubstepRule>(token);
  } else {
    throw unknown_query("04", q, "overlap_at, closest_point, bisect, closing_speed, substeps_for, sample_then_bisect, tunnelling, "
                                  "distance_at, advance (and their robust. forms)");
  }
  frame_inputs();
}

void BisectionScene::frame_inputs() {
  const char* names[] = {"bisection", "sub-steps", "tunnelling", "conservative advancement", "closest point", "sub-step rule"};
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

void BisectionScene::layout() {
  const SearchTimes& T = case_.times;
  Eigen::AlignedBox3d& box = bodies_;
  box.setEmpty();
  for (int k = 0; k <= 32; ++k) {
    const double t = T.t0 + (T.t1 - T.t0) * k / 32;
    for (const MovingBody* b : {&case_.a, &case_.b}) {
      const RigidTransform p = pose_at(b->motion, t);
      const double reach = b->is_box ? b->box.half_extents.norm() : b->sphere.radius;
      const Vec3 c = p * (b->is_box ? b->box.center : b->sphere.center);
      box.extend(c - Vec3::Constant(reach)), box.extend(c + Vec3::Constant(reach));
    }
  }
  const double size = std::max(box.diagonal().norm(), 1e-9);
  width_ = std::max(box.sizes().x(), 0.6 * size);
  left_ = box.center().x() - 0.5 * width_;
  y0_ = box.min().y() - 0.12 * size;
  row_ = 0.04 * size;
  z_ = box.center().z();
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

bool BisectionScene::exact_overlap(double t) const {
  return case_.b.is_box ? oracle::sphere_box_overlap(case_.a.sphere, pose_a(t), case_.b.box, pose_b(t))
                        : oracle::spheres_overlap(case_.a.sphere, pose_a(t), case_.b.sphere, pose_b(t));
}

double BisectionScene::exact_distance(double t) const {
  return case_.b.is_box ? oracle::sphere_box_distance(case_.a.sphere, pose_a(t), case_.b.box, pose_b(t))
                        : oracle::spheres_distance(case_.a.sphere, pose_a(t), case_.b.sphere, pose_b(t));
}

// The first contact, found with exact predicates only: the start; then samples no
// farther apart than the lecture's rule asks (at least 64, at most 4096); then bisection
// of the first overlapping sub-step down to 2^-40 of the interval. A contact shorter
// than a sub-step (a graze between samples) can still be missed; a contact that passes
// through cannot.
void BisectionScene::exact_first_contact() {
  const SearchTimes& T = case_.times;
  exact_hit_ = exact_at_start_ = false;
  if (exact_overlap(T.t0)) {
    exact_hit_ = exact_at_start_ = true, exact_lo_ = exact_hi_ = T.t0;
    return;
  }
  const SubstepRule rule{closing_speed_of(case_), T.t1 - T.t0, smallest_size_of(case_)};
  const double ratio = rule.smallest_size > 0 ? rule.max_speed * rule.step / rule.smallest_size : 4096;
  const int n = int(std::clamp(std::floor(ratio) + 1, 64.0, 4096.0));
  double previous = T.t0;
  for (int k = 1; k <= n; ++k) {
    const double tk = k == n ? T.t1 : T.t0 + (T.t1 - T.t0) * k / n;
    if (!exact_overlap(tk)) {
      previous = tk;
      continue;
    }
    double lo = previous, hi = tk;
    const double fine = std::ldexp(T.t1 - T.t0, -40);
    while (hi - lo > fine) {
      const double mid = lo + 0.5 * (hi - lo);
      if (mid <= lo || mid >= hi) break;
      (exact_overlap(mid) ? hi : lo) = mid;
    }
    exact_hit_ = true, exact_lo_ = lo, exact_hi_ = hi;
    return;
  }
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
  const std::string contact = exact_at_start ? "at t0" : exact_hit ? "in (" + num(exact_lo) + ", " + num(exact_hi) + "]" : "none seen";
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
  tested_ = recorder.times, bracket_lo_ = T.t0, bracket_hi_ = T.t1;
  steps.push_back(s);
}

void BisectionScene::step_closing_speed() {
  const SearchTimes& T = case_.times;
  const auto got = attempt([&] {
    return closing_speed(case_.a.sphere, motion_of(case_.a.motion), shape_of(case_.b), motion_of(case_.b.motion), T.t0, T.t1);
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
  tested_ = recorder.times, bracket_lo_ = T.t0, bracket_hi_ = T.t1;
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
  tested_ = recorder.times, bracket_lo_ = T.t0, bracket_hi_ = T.t1;
  steps.push_back(s);
}

void BisectionScene::update() {
  steps.clear();
  for (Verdict& v : verdict_) v = Verdict::none;
  search_ = {};
  tested_.clear(), tested_overlap_.clear();
  if (mode_ == Mode::point) {
    closest_ = attempt([&] { return closest_point(point_box_.box, point_box_.point); });
    Step s = judged("L04S1", "closest_point of the box to p", closest_,
                    [&](const Vec3& got) { return judge::closest_point(point_box_, got); });
    const RigidTransform id = RigidTransform::Identity();
    s.rows = {{"q", closest_ ? num(*closest_) : "", ""},
              {"|p - q|", closest_ ? num((*closest_ - point_box_.point).norm()) : "",
               num(oracle::sphere_box_distance(Sphere{point_box_.point, 0}, id, point_box_.box, id))}};
    closest_verdict_ = verdict_[1] = s.verdict;
    steps.push_back(s);
    return;
  }
  if (mode_ == Mode::rule) {
    step_rule(rule_);
    return;
  }
  SearchTimes& T = case_.times;
  T.t1 = std::max(T.t1, T.t0);
  T.tolerance = std::max(T.tolerance, std::ldexp(std::max(T.t1 - T.t0, 1e-300), -40));
  layout();
  exact_first_contact();
  step_overlap();
  switch (mode_) {
    case Mode::bisect:
      step_bisect("bisect [t0, t1] to the last clear time");
      step_advance();  // distance_at only
      break;
    case Mode::sampled: step_sampled(substeps_, "sample_then_bisect with n sub-steps"); break;
    case Mode::tunnelling: {
      step_bisect("bisect: the frame's ends only");
      step_closing_speed();
      const SubstepRule rule{closing_speed_of(case_), T.t1 - T.t0, smallest_size_of(case_)};
      step_rule(rule);
      const Attempt<int> n = attempt([&] { return substeps_for(rule.max_speed, rule.step, rule.smallest_size); });
      const double ratio = rule.smallest_size > 0 ? rule.max_speed * rule.step / rule.smallest_size : 0;
      substeps_ = n && *n > 0 ? *n : int(std::clamp(std::floor(ratio) + 1, 1.0, 4096.0));
      step_sampled(std::min(substeps_, 4096), "sample_then_bisect with the rule's n");
      break;
    }
    case Mode::advance: step_advance(); break;
    default: break;
  }
  for (double t : tested_) tested_overlap_.push_back(exact_overlap(t));
}

// ---- draw ----------------------------------------------------------------------------

// A sphere as three great circles (and a translucent ball), a box as its 12 edges (and
// its faces).
void BisectionScene::draw_body(Renderer& r, const MovingBody& body, const RigidTransform& pose, Color c, bool filled) const {
  const float width = filled ? 2.0f : 1.0f;
  if (!body.is_box) {
    const Vec3 o = pose * body.sphere.center;
    const double rad = body.sphere.radius;
    if (rad <= 0) {
      r.point(o, c, 4);
      return;
    }
    const Mat3 R = pose.linear();
    const int n = 48;
    for (int axis = 0; axis < 3; ++axis) {
      const Vec3 u = R.col((axis + 1) % 3), v = R.col((axis + 2) % 3);
      for (int k = 0; k < n; ++k) {
        const double a0 = 2 * M_PI * k / n, a1 = 2 * M_PI * (k + 1) / n;
        r.line(o + rad * (std::cos(a0) * u + std::sin(a0) * v), o + rad * (std::cos(a1) * u + std::sin(a1) * v), c, width);
      }
    }
    if (filled) {
      const int m = 12;
      const auto at = [&](int i, int j) {
        const double th = M_PI * i / m, ph = 2 * M_PI * j / (2 * m);
        return Vec3(o + rad * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
      };
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < 2 * m; ++j) {
          r.triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1), c.with_alpha(0.25f));
          r.triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1), c.with_alpha(0.25f));
        }
    }
    return;
  }
  const Box placed_box{pose * body.box.center, pose.linear() * body.box.axes, body.box.half_extents};
  Vec3 p[8];
  for (int i = 0; i < 8; ++i) p[i] = placed_box.corner(i);
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k)
      if (!(i & (1 << k))) r.line(p[i], p[i | (1 << k)], c, width);
  if (!filled) return;
  for (int k = 0; k < 3; ++k)
    for (int side = 0; side < 2; ++side) {
      const int a = (k + 1) % 3, b = (k + 2) % 3, s = side << k;
      const Vec3 q0 = p[s], q1 = p[s | (1 << a)], q2 = p[s | (1 << a) | (1 << b)], q3 = p[s | (1 << b)];
      r.triangle(q0, q1, q2, c.with_alpha(0.30f));
      r.triangle(q0, q2, q3, c.with_alpha(0.30f));
    }
}

void BisectionScene::draw_pair(Renderer& r, double t, Color c, bool filled) const {
  draw_body(r, case_.a, pose_a(t), c, filled);
  const bool b_moves = case_.b.motion.velocity != Vec3::Zero() || case_.b.motion.acceleration != Vec3::Zero() ||
                       case_.b.motion.spin != 0;
  if (b_moves) draw_body(r, case_.b, pose_b(t), c, false);
}

// The time axis under the bodies, along world x: t0 at the left of the picture, t1 at
// the right. Row 0 holds the tested times; the rows below it the bracket after each test.
void BisectionScene::draw_timeline(Frame& f) const {
  Renderer& r = f.render;
  const SearchTimes& T = case_.times;
  const auto at = [&](double t, int k) {
    const double u = T.t1 > T.t0 ? (t - T.t0) / (T.t1 - T.t0) : 0.5;
    return Vec3(left_ + u * width_, y0_ - row_ * k, z_);
  };
  r.line(at(T.t0, 0), at(T.t1, 0), palette::muted, 2);
  r.label(at(T.t0, 0), "t0 = " + num(T.t0), palette::muted, -70, -8);
  r.label(at(T.t1, 0), "t1 = " + num(T.t1), palette::muted, 10, -8);
  const double tick = 0.4 * row_;
  // The tests, numbered in the order the search asked, coloured by the exact overlap. In
  // bisection the ends carry the axis's t0 and t1, and the midpoints are numbered as the
  // lecture numbers its iterations (1 to 5 in its example). Labels that would overlap are
  // stacked upward, each on a thin leader down to its tick.
  const std::size_t shown = std::min<std::size_t>(tested_.size(), 40);
  const double pixel = r.pixels(at(T.t0, 0), 1);  // world length of a pixel on the axis
  std::vector<std::vector<std::pair<double, double>>> taken;  // per stacking level: label spans, in pixels
  int number = 0;
  for (std::size_t i = 0; i < shown; ++i) {
    const Color c = tested_overlap_[i] ? palette::surface : palette::input;
    const Vec3 top = at(tested_[i], 0) + Vec3(0, tick, 0);
    r.line(at(tested_[i], 0) - Vec3(0, tick, 0), top, c, 2.5f);
    const bool end = mode_ == Mode::bisect && (tested_[i] == T.t0 || tested_[i] == T.t1);
    if (end) continue;
    ++number;
    if (shown > 24) continue;
    const std::string text = std::to_string(number);
    const double w = 7.0 * double(text.size()) + 2, x = (top.x() - left_) / pixel - 0.5 * w;
    const auto clashes = [&](const std::pair<double, double>& s) { return x < s.second + 3 && s.first < x + w + 3; };
    std::size_t level = 0;
    while (level < taken.size() && std::any_of(taken[level].begin(), taken[level].end(), clashes)) ++level;
    if (level == taken.size()) taken.emplace_back();
    taken[level].push_back({x, x + w});
    const float lift = 14.0f * float(level);
    if (level > 0) r.line(top, top + Vec3(0, pixel * (lift + 2), 0), c.with_alpha(0.5f), 1);
    r.label(top, text, c, float(-0.5 * w), -18 - lift);
  }
  // The bracket the tests imply: the earliest overlapping time tested, and the latest
  // clear time tested before it.
  std::vector<std::pair<double, double>> brackets;
  for (std::size_t i = 0; i < tested_.size(); ++i) {
    double hi = INFINITY, lo = -INFINITY;
    for (std::size_t j = 0; j <= i; ++j)
      if (tested_overlap_[j]) hi = std::min(hi, tested_[j]);
    if (!std::isfinite(hi) || hi == tested_[0]) continue;
    for (std::size_t j = 0; j <= i; ++j)
      if (!tested_overlap_[j] && tested_[j] < hi) lo = std::max(lo, tested_[j]);
    if (std::isfinite(lo) && (brackets.empty() || brackets.back() != std::make_pair(lo, hi))) brackets.push_back({lo, hi});
  }
  const std::size_t first = brackets.size() > kRows ? brackets.size() - kRows : 0;
  for (std::size_t i = first; i < brackets.size(); ++i) {
    const int k = int(i - first) + 1;
    r.line(at(brackets[i].first, k), at(brackets[i].second, k), palette::muted, 3);
    r.label(at(brackets[i].second, k), "[" + num(brackets[i].first) + ", " + num(brackets[i].second) + "]", palette::muted, 8, -7);
  }
  // The student's final bracket, and the exact first contact.
  const int last = int(brackets.size() - first) + 1;
  if (search_ && search_->hit && f.shows(search_step_)) {
    const Color c = colour(search_verdict_);
    r.line(at(search_->t, last), at(search_->t_contact, last), c, 5);
    r.label(at(search_->t, last), "yours: t = " + num(search_->t), c, -40, 10);
  } else if (search_ && f.shows(search_step_)) {
    r.label(at(T.t1, last), "yours: no hit", colour(search_verdict_), -40, 10);
  }
  if (f.show_exact && exact_hit_) {
    r.ring(at(exact_hi_, 0), palette::exact, 9, 2.5f);
    r.label(at(exact_hi_, last + 1), "exact first contact " + num(exact_hi_), palette::exact, -40, 10);
  }
}

void BisectionScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::rule) {
    r.label(Vec3::Zero(), "the sub-step rule has no picture: see the panel", palette::muted);
    return;
  }
  if (mode_ == Mode::point) {
    const MovingBody box{true, Sphere{}, point_box_.box, {}};
    draw_body(r, box, RigidTransform::Identity(), palette::surface, true);
    r.point(point_box_.point, palette::input, 6);
    r.label(point_box_.point, "p", palette::input);
    if (closest_) {
      const Color c = colour(closest_verdict_);
      r.dashed(point_box_.point, *closest_, c, 2);
      r.point(*closest_, c, 5);
      r.label(*closest_, "q", c, 10, 10);
    }
    return;
  }
  const SearchTimes& T = case_.times;
  // The paths of the body's centres, and both bodies at t0 (faint) and t1.
  for (const MovingBody* b : {&case_.a, &case_.b}) {
    const Vec3 local = b->is_box ? b->box.center : b->sphere.center;
    for (int k = 0; k < 48; ++k) {
      const double s0 = T.t0 + (T.t1 - T.t0) * k / 48, s1 = T.t0 + (T.t1 - T.t0) * (k + 1) / 48;
      r.line(pose_at(b->motion, s0) * local, pose_at(b->motion, s1) * local, palette::muted.with_alpha(0.7f), 1);
    }
  }
  draw_body(r, case_.b, pose_b(T.t0), palette::surface, true);
  draw_body(r, case_.a, pose_a(T.t0), palette::input, false);
  r.label(pose_a(T.t0) * case_.a.sphere.center, "t0", palette::input, 8, -8);
  draw_body(r, case_.a, pose_a(T.t1), palette::muted, false);
  r.label(pose_a(T.t1) * case_.a.sphere.center, "t1", palette::muted, 8, -8);
  // Every tested time, faint: where the search looked.
  if (tested_.size() <= 64)
    for (std::size_t i = 0; i < tested_.size(); ++i)
      draw_body(r, case_.a, pose_a(tested_[i]), (tested_overlap_[i] ? palette::surface : palette::input).with_alpha(0.35f), false);
  if (search_ && search_->hit && f.shows(search_step_)) {
    const Color c = colour(search_verdict_);
    draw_pair(r, search_->t, c, true);
    if (search_->t_contact != search_->t) draw_pair(r, search_->t_contact, c.with_alpha(0.6f), false);
    r.label(pose_a(search_->t) * case_.a.sphere.center, "t = " + num(search_->t), c, -30, 16);
  }
  if (f.show_exact && exact_hit_) {
    draw_pair(r, exact_hi_, palette::exact, false);
    r.ring(pose_a(exact_hi_) * case_.a.sphere.center, palette::exact, 9);
  }
  draw_timeline(f);
}

bool BisectionScene::inputs() {
  bool changed = false;
  if (mode_ == Mode::rule) {
    changed |= edit("max speed", rule_.max_speed, 0.05f, 0, 1e12) | edit("step", rule_.step, 0.01f, 0, 1e6) |
               edit("smallest size", rule_.smallest_size, 0.01f, 0, 1e6);
    return changed;
  }
  if (mode_ == Mode::point) {
    changed |= edit("p", point_box_.point) | edit("box centre", point_box_.box.center) |
               edit("half extents", point_box_.box.half_extents, 0.02f);
    point_box_.box.half_extents = point_box_.box.half_extents.cwiseAbs();
    return changed;
  }
  ImGui::TextDisabled("a: a sphere");
  changed |= edit("a radius", case_.a.sphere.radius, 0.01f, 0, 1e9);
  changed |= edit("a start", case_.a.motion.start) | edit("a velocity", case_.a.motion.velocity) |
             edit("a acceleration", case_.a.motion.acceleration) | edit("a spin", case_.a.motion.spin, 0.02f);
  bool box = case_.b.is_box;
  if (ImGui::Checkbox("b is a box", &box)) {
    case_.b.is_box = box, changed = true;
    if (box && case_.b.box.half_extents == Vec3::Zero()) case_.b.box.half_extents = Vec3::Constant(case_.b.sphere.radius);
    if (!box && case_.b.sphere.radius == 0) case_.b.sphere.radius = case_.b.box.half_extents.maxCoeff();
  }
  if (case_.b.is_box) {
    changed |= edit("b half extents", case_.b.box.half_extents, 0.02f);
    case_.b.box.half_extents = case_.b.box.half_extents.cwiseAbs();
  } else {
    changed |= edit("b radius", case_.b.sphere.radius, 0.01f, 0, 1e9);
  }
  changed |= edit("b start", case_.b.motion.start) | edit("b velocity", case_.b.motion.velocity) |
             edit("b spin", case_.b.motion.spin, 0.02f) | edit("b spin axis", case_.b.motion.axis);
  if (case_.b.motion.axis == Vec3::Zero()) case_.b.motion.axis = Vec3::UnitZ();
  ImGui::TextDisabled("the search");
  changed |= edit("t0", case_.times.t0, 0.01f) | edit("t1", case_.times.t1, 0.01f) |
             edit("tolerance", case_.times.tolerance, 0.001f, 1e-12, 1e6);
  if (mode_ == Mode::sampled) changed |= ImGui::SliderInt("sub-steps n", &substeps_, 1, 64);
  if (mode_ == Mode::advance) changed |= edit("bound factor", speed_factor_, 0.01f, 1, 100);
  return changed;
}

std::vector<Handle> BisectionScene::handles() {
  if (mode_ == Mode::point) return {{&point_box_.point, "p"}, {&point_box_.box.center, "box centre"}};
  if (mode_ == Mode::rule) return {};
  return {{&case_.a.motion.start, "a at t = 0"}, {&case_.b.motion.start, "b at t = 0"}};
}

std::string BisectionScene::token() const {
  switch (mode_) {
    case Mode::bisect: return replay_token("bisect", case_);
    case Mode::sampled: return replay_token("sample_then_bisect", SampledPair{case_, substeps_});
    case Mode::tunnelling: return replay_token("tunnelling", case_);
    case Mode::advance: return replay_token("advance", AdvancedPair{case_, speed_factor_});
    case Mode::point: return replay_token("closest_point", point_box_);
    case Mode::rule: break;
  }
  return replay_token("substeps_for", rule_);
}

}  // namespace

std::unique_ptr<Scene> make_bisection(const Setup& setup) { return std::make_unique<BisectionScene>(setup); }
const std::vector<Preset>& bisection_presets() { return kPresets; }

}  // namespace viewer
