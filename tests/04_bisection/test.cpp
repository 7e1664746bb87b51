// Lab 04 tests. Each step: the hand-worked examples of handouts/04_bisection.md, then
// random cases against the exact oracle (tests/04_bisection/judge.cpp).
#include "04_bisection/judge.h"
#include "bisection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace labkit;
using namespace labkit::lab04;
using check::Expect;
using check::Outcome;
using check::rejects;
using judge::Rules;

// The header's input domain (every length 0 or of magnitude from 1e-100 to 1e100):
// shrinking a failing case stays in it.
const bool kDomain = [] {
  check::domain({check::Domain::Of::each, 1e-100, 1e100});
  return true;
}();

namespace {

// ---- The handout's scenes ------------------------------------------------------------------

MotionParameters resting_at(const Vec3& p) {
  MotionParameters m;
  m.start = p;
  return m;
}
MotionParameters moving(const Vec3& start, const Vec3& velocity) {
  MotionParameters m;
  m.start = start;
  m.velocity = velocity;
  return m;
}
MovingBody ball(double radius, const MotionParameters& m) { return {false, Sphere{Vec3::Zero(), radius}, Box{}, m}; }
MovingBody block(const Vec3& half_extents, const MotionParameters& m) {
  return {true, Sphere{}, Box{Vec3::Zero(), Mat3::Identity(), half_extents}, m};
}
MovingPairCase scene(const MovingBody& a, const MovingBody& b, double t0, double t1, double tolerance) {
  return {a, b, SearchTimes{t0, t1, tolerance}};
}

// The wall: the box [0, 8] x [-4, 4] x [-4, 4], at rest. The ball: radius 1, centre
// x(t) = -6 + 12 t on the x axis. It touches the wall's face x = 0 when x = -1: t = 5/12.
const MovingBody kWall = block({4, 4, 4}, resting_at({4, 0, 0}));
const MovingBody kBall = ball(1, moving({-6, 0, 0}, {12, 0, 0}));
MovingPairCase ball_and_wall(double t0, double t1, double tolerance) { return scene(kBall, kWall, t0, t1, tolerance); }

// The window: |x| <= 1/4, |y|, |z| <= 2, at rest. The bullet: radius 1/8, centre
// x(t) = -3 + 6 t. In contact while |x| <= 3/8: t in [7/16, 9/16].
const MovingBody kWindow = block({0.25, 2, 2}, resting_at(Vec3::Zero()));
const MovingBody kBullet = ball(0.125, moving({-3, 0, 0}, {6, 0, 0}));
MovingPairCase bullet_and_window(double tolerance) { return scene(kBullet, kWindow, 0, 1, tolerance); }

// A quarter turn about z, then a shift: exact numbers, no trigonometry.
RigidTransform quarter_turn_then(const Vec3& shift) {
  RigidTransform m = RigidTransform::Identity();
  m.linear() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  m.translation() = shift;
  return m;
}

std::string yes_no(bool b) { return b ? "true" : "false"; }

// Expectations of a search's answer.
auto expect_hit(double t, double t_contact, int steps, int iterations, const std::string& rule = "") {
  return [=](const TimeOfImpact& got) {
    Expect e(rule.empty() ? "the search returns t, the last time found clear, and t_contact, the first found "
                            "overlapping, within the tolerance"
                          : rule);
    e.equal("hit", got.hit, true);
    e.equal("overlapping_at_start", got.overlapping_at_start, false);
    e.near("t", got.t, t, 1e-12);
    e.near("t_contact", got.t_contact, t_contact, 1e-12);
    e.equal("steps", got.steps, steps);
    e.equal("iterations", got.iterations, iterations);
    return e.outcome();
  };
}
auto expect_no_hit(double t1, int steps) {
  return [=](const TimeOfImpact& got) {
    Expect e("a motion that never overlaps is no hit, with t the end of the interval");
    e.equal("hit", got.hit, false);
    e.near("t", got.t, t1, 0);
    e.equal("steps", got.steps, steps);
    return e.outcome();
  };
}
auto expect_start(double t0) {
  return [=](const TimeOfImpact& got) {
    Expect e("bodies that overlap at t0 are a hit at the start: overlapping_at_start, t = t_contact = t0");
    e.equal("hit", got.hit, true);
    e.equal("overlapping_at_start", got.overlapping_at_start, true);
    e.near("t", got.t, t0, 0);
    e.near("t_contact", got.t_contact, t0, 0);
    return e.outcome();
  };
}

// A search that did not finish: say the header's bound on its loop, with the numbers.
template <class Search> TimeOfImpact bounded(Search search, const std::string& bound) {
  try {
    return search();
  } catch (const remote::Failed& e) {
    if (e.got != remote::kNoAnswer) throw;
    throw remote::Failed(e.got, std::string(e.what()) + ". " + bound);
  }
}
std::string halving_bound(const SearchTimes& T) {
  const double rounds = std::ceil(std::log2(std::max(1.0, (T.t1 - T.t0) / T.tolerance))) + 2;
  return "Bisection halves while hi - lo > tolerance, and each halving halves the bracket: at most log2((t1 - t0) / "
         "tolerance) + 2 = " +
         fmt(rounds) + " rounds here";
}

// The searches on a case, by query name.
TimeOfImpact run_bisect(const MovingPairCase& in) {
  return bounded([&] { return answerer::bisect(pair_of(in), in.times.t0, in.times.t1, in.times.tolerance); },
                 halving_bound(in.times));
}
TimeOfImpact run_sampled(const SampledPair& in) {
  const SearchTimes& T = in.pair.times;
  return bounded([&] { return answerer::sample_then_bisect(pair_of(in.pair), T.t0, T.t1, in.substeps, T.tolerance); },
                 "Point sampling tests n = " + std::to_string(in.substeps) + " samples, then bisects one sub-step. " +
                     halving_bound(T));
}
TimeOfImpact run_advance(const AdvancedPair& in) {
  const SearchTimes& T = in.pair.times;
  return bounded(
      [&] { return answerer::advance(pair_of(in.pair), T.t0, T.t1, judge::closing_speed_of(in), T.tolerance); },
      "Conservative advancement moves at least one tolerance per step (next = t + max(d / v, tolerance)): "
      "at most (t1 - t0) / tolerance + 1 = " +
          fmt(std::ceil((T.t1 - T.t0) / T.tolerance) + 1) + " steps here, then one bisection. " + halving_bound(T));
}
// The pair's closing speed, by the code under test.
double run_closing_speed(const MovingPairCase& in) {
  return answerer::closing_speed(in.a.sphere, motion_of(in.a.motion), shape_of(in.b), motion_of(in.b.motion),
                                 in.times.t0, in.times.t1);
}

// Step 3's tunnelling: the closing speed and the sub-steps it asks for, by the code under
// test, then one sample against n samples.
Outcome judge_tunnelling(const MovingPairCase& in) {
  const MovingPair pair = pair_of(in);
  const SearchTimes& T = in.times;
  const double speed = run_closing_speed(in);
  const int n = answerer::substeps_for(speed, T.t1 - T.t0, smallest_size_of(in));
  return judge::tunnelling(in, speed, n, answerer::sample_then_bisect(pair, T.t0, T.t1, 1, T.tolerance),
                           answerer::sample_then_bisect(pair, T.t0, T.t1, n < 1 ? 1 : n, T.tolerance));
}

// Both the exact judge (first: it says which rule broke) and the hand-worked numbers.
template <class Input, class Run, class Judge, class Expectation>
auto both(Run run, Judge judge_it, Expectation expectation) {
  return [=](const Input& in) {
    const TimeOfImpact got = run(in);
    const Outcome o = judge_it(in, got);
    if (o.verdict == Outcome::Verdict::fail) return o;
    const Outcome e = expectation(got);
    return e.verdict == Outcome::Verdict::fail ? e : o;
  };
}

Outcome judge_sampled(const SampledPair& in, const TimeOfImpact& got) { return judge::sample_then_bisect(in, got); }
Outcome judge_advance(const AdvancedPair& in, const TimeOfImpact& got) { return judge::advance(in, got); }
// Exact input (the robustness step's, and step 2's worked examples): the header's rules,
// with nothing in doubt.
Outcome exact_bisect(const MovingPairCase& in, const TimeOfImpact& got) { return judge::bisect(in, got, Rules::exact); }
Outcome exact_sampled(const SampledPair& in, const TimeOfImpact& got) {
  return judge::sample_then_bisect(in, got, Rules::exact);
}
Outcome exact_advance(const AdvancedPair& in, const TimeOfImpact& got) { return judge::advance(in, got, Rules::exact); }

}  // namespace

// ---- Step 1 ------------------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L04S1) ": worked examples", "[lab04][step1]") {
  const RigidTransform pose = quarter_turn_then({5, 0, 0});
  check::example(query::placed, "a quarter turn, then 5 along x", Sphere{{1, 0, 0}, 2}, [=](const Sphere& in) {
    const Sphere s = answerer::placed(in, pose);
    const Box b = answerer::placed(Box{in.center, Mat3::Identity(), {2, 1, 1}}, pose);
    const std::string rule =
        "a pose moves a centre by the whole pose and turns a box's axes by its rotation, pose.linear() * axes; "
        "sizes stay";
    Expect e(rule);
    e.near("sphere centre", s.center, Vec3(5, 1, 0), 1e-12);
    e.near("sphere radius", s.radius, 2, 0);
    e.near("box centre", b.center, Vec3(5, 1, 0), 1e-12);
    const bool turned =
        (Vec3(b.axes.col(0)) - Vec3(0, 1, 0)).norm() <= 1e-12 && (Vec3(b.axes.col(1)) - Vec3(-1, 0, 0)).norm() <= 1e-12;
    e.that("box axes 0, 1", turned, fmt(Vec3(b.axes.col(0))) + ", " + fmt(Vec3(b.axes.col(1))), "(0, 1, 0), (-1, 0, 0)",
           rule + " (the quarter turn takes axis x to y)");
    e.near("box half extents", b.half_extents, Vec3(2, 1, 1), 0);
    return e.outcome();
  });

  const std::string closed = "sets are closed, touching counts: overlap <=> |c_a - c_b|^2 <= (r_a + r_b)^2";
  const auto spheres = [closed](bool expected) {
    return [=](const Sphere& b) {
      const bool got = answerer::overlap(Sphere{Vec3::Zero(), 1}, b);
      Expect e("sets are closed, touching counts");
      e.that("overlap", got == expected, yes_no(got), yes_no(expected), closed);
      return e.outcome();
    };
  };
  check::example(query::overlap_spheres, "5 apart, radii 1 and 3: clear", Sphere{{3, 4, 0}, 3}, spheres(false));
  check::example(query::overlap_spheres, "5 apart, radii 1 and 4: touching counts", Sphere{{3, 4, 0}, 4},
                 spheres(true));
  check::example(query::overlap_spheres, "5 apart, radii 1 and 5: overlap", Sphere{{3, 4, 0}, 5}, spheres(true));

  const Box wall{{4, 0, 0}, Mat3::Identity(), {4, 4, 4}};
  const auto nearest = [](const Vec3& expected) {
    return [expected](const PointBox& in) {
      Expect e(
          "the closest point of a box to x is x clamped to the box in the box's own axes, then taken back to the "
          "world");
      e.near("closest point", answerer::closest_point(in.box, in.point), expected, 1e-12);
      return e.outcome();
    };
  };
  check::example(query::closest_point, "beyond a face and an edge", PointBox{{-3, 2, 5}, wall}, nearest({0, 2, 4}));
  check::example(query::closest_point, "inside: the point itself", PointBox{{1, 2, 3}, wall}, nearest({1, 2, 3}));
  // A box turned a quarter turn: long along y. Clamping world coordinates would give (3, 1, 0).
  const Box turned{Vec3::Zero(), quarter_turn_then(Vec3::Zero()).linear(), {4, 1, 1}};
  check::example(query::closest_point, "a turned box: clamp in its own axes", PointBox{{3, 2, 0}, turned},
                 nearest({1, 2, 0}));

  const auto sphere_box = [wall](bool expected) {
    return [wall, expected](const Sphere& a) {
      const bool got = answerer::overlap(a, wall);
      Expect e("sets are closed, touching counts");
      e.that("overlap", got == expected, yes_no(got), yes_no(expected),
             "sets are closed, touching counts: overlap <=> |c - closest_point(box, c)|^2 <= r^2, the closest point "
             "clamped in the box's own axes");
      return e.outcome();
    };
  };
  check::example(query::overlap_sphere_box, "squared distance 10, radius 3: clear", Sphere{{-3, 2, 5}, 3},
                 sphere_box(false));
  check::example(query::overlap_sphere_box, "squared distance 10, radius 4: overlap", Sphere{{-3, 2, 5}, 4},
                 sphere_box(true));
  check::example(query::overlap_sphere_box, "touching the face x = 0", Sphere{{-2, 0, 0}, 2}, sphere_box(true));

  const auto at = [](bool at_t0, bool at_t1) {
    return [=](const MovingPairCase& in) {
      const MovingPair pair = pair_of(in);
      const bool got_t0 = answerer::overlap_at(pair, in.times.t0), got_t1 = answerer::overlap_at(pair, in.times.t1);
      const Outcome o = judge::overlap_at(in, got_t0, got_t1);
      if (o.verdict == Outcome::Verdict::fail) return o;
      Expect e("overlap_at(t) places both bodies at time t and tests those shapes");
      e.equal("overlap_at(t0)", got_t0, at_t0);
      e.equal("overlap_at(t1)", got_t1, at_t1);
      return e.outcome();
    };
  };
  check::example(query::overlap_at, "the ball at x = -1.125, then at x = -0.75", ball_and_wall(0.40625, 0.4375, 1),
                 at(false, true));
  // A bar 8 long spins a quarter turn about z in one unit of time, and sweeps into a
  // resting ball 3 from its middle.
  MovingBody bar = block({4, 1, 1}, resting_at(Vec3::Zero()));
  bar.motion.spin = std::acos(-1.0) / 2;
  check::example(query::overlap_at, "a spinning bar reaches the ball",
                 scene(ball(1, resting_at({0, 3, 0})), bar, 0, 1, 1), at(false, true));
}

TEST_CASE(LABKIT_STEP(L04S1) ": random cases", "[lab04][step1][oracle]") {
  check::random_cases(query::closest_point, gen::point_box(), [](const PointBox& in) {
    return judge::closest_point(in, answerer::closest_point(in.box, in.point));
  });
  check::random_cases(query::overlap_at, gen::moving_pair(), [](const MovingPairCase& in) {
    const MovingPair pair = pair_of(in);
    return judge::overlap_at(in, answerer::overlap_at(pair, in.times.t0), answerer::overlap_at(pair, in.times.t1));
  });
}

// ---- Step 2 ------------------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L04S2) ": worked examples", "[lab04][step2]") {
  // The lecture's iterations: 0.5 (overlap), 0.25, 0.375 (clear), 0.4375 (overlap), 0.40625 (clear).
  check::example(query::bisect, "the lecture's five iterations", ball_and_wall(0, 1, 1.0 / 32),
                 both<MovingPairCase>(run_bisect, exact_bisect, expect_hit(0.40625, 0.4375, 0, 5)));
  // Any callable is a motion: this one writes down every time it is asked for a pose.
  // After the two ends, the times asked are the lecture's midpoints, in its order.
  check::example(query::bisect, "the lecture's midpoints, seen by a recording motion", ball_and_wall(0, 1, 1.0 / 32),
                 [](const MovingPairCase& in) {
    MovingPair pair = pair_of(in);
    const RecordingMotion recording{motion_of(in.a.motion)};
    pair.motion_a = recording;
    const TimeOfImpact got = answerer::bisect(pair, in.times.t0, in.times.t1, in.times.tolerance);
    std::vector<double> midpoints;
    for (double t : *recording.asked)
      if (t != in.times.t0 && t != in.times.t1 && std::find(midpoints.begin(), midpoints.end(), t) == midpoints.end())
        midpoints.push_back(t);
    Expect e("bisection asks the midpoint of the bracket each time, halving it, in the lecture's order");
    e.equal("times asked besides t0 and t1", int(midpoints.size()), 5);
    const double lecture[] = {0.5, 0.25, 0.375, 0.4375, 0.40625};
    for (std::size_t k = 0; k < std::min<std::size_t>(5, midpoints.size()); ++k)
      e.near("midpoint " + std::to_string(k + 1), midpoints[k], lecture[k], 0);
    e.near("t", got.t, 0.40625, 0);
    return e.outcome();
  });
  check::example(query::bisect, "a coarse tolerance: two iterations", ball_and_wall(0, 1, 0.25),
                 both<MovingPairCase>(run_bisect, exact_bisect, expect_hit(0.25, 0.5, 0, 2)));
  check::example(query::bisect, "already overlapping at t0", ball_and_wall(0.5, 1, 1.0 / 32),
                 both<MovingPairCase>(run_bisect, exact_bisect, expect_start(0.5)));
  check::example(query::bisect, "still clear at t1: no hit", ball_and_wall(0, 0.25, 1.0 / 32),
                 both<MovingPairCase>(run_bisect, exact_bisect, expect_no_hit(0.25, 0)));
}

TEST_CASE(LABKIT_STEP(L04S2) ": random cases", "[lab04][step2][oracle]") {
  check::random_cases(query::bisect, gen::moving_pair(),
                      [](const MovingPairCase& in) { return judge::bisect(in, run_bisect(in)); });
}

// ---- Step 3 ------------------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L04S3) ": worked examples", "[lab04][step3]") {
  check::example(query::smallest_size, "a sphere's diameter, a box's thinnest extent", bullet_and_window(1.0 / 64),
                 [](const MovingPairCase& in) {
    Expect e(
        "a shape's smallest size is its thinnest width: a sphere's diameter 2 r, a box's smallest full extent 2 h");
    e.near("bullet", answerer::smallest_size(shape_of(in.a)), 0.25, 0);
    e.near("window", answerer::smallest_size(shape_of(in.b)), 0.5, 0);
    return e.outcome();
  });
  const auto rule = [](int expected) {
    return [expected](const SubstepRule& in) {
      const int got = answerer::substeps_for(in.max_speed, in.step, in.smallest_size);
      const Outcome o = judge::substeps_for(in, got, Rules::exact);
      if (o.verdict == Outcome::Verdict::fail) return o;
      Expect e(
          "substeps = ceil(max_speed step / smallest_size): no sub-step moves a body further than its smallest size");
      e.equal("substeps", got, expected);
      return e.outcome();
    };
  };
  check::example(query::substeps_for, "6 per unit, size 1/4: 24 is not enough, 25", SubstepRule{6, 1, 0.25}, rule(25));
  check::example(query::substeps_for, "6 per unit, size 0.3: 21", SubstepRule{6, 1, 0.3}, rule(21));
  check::example(query::substeps_for, "a step of 1/64 at 30 per unit, size 1/8: 3.75, so 4",
                 SubstepRule{30, 1.0 / 64, 0.125}, rule(4));
  check::example(query::substeps_for, "not moving: 1", SubstepRule{0, 1, 0.25}, rule(1));
  check::example(query::substeps_for, "a point can always be missed: 0", SubstepRule{6, 1, 0}, rule(0));
  check::example(query::substeps_for, "more than 2^20 sub-steps: 0", SubstepRule{1e9, 1, 1e-3}, rule(0));

  // The window flies at the bullet: each moves at 3, and they close at 6, as before.
  MovingPairCase head_on = bullet_and_window(1.0 / 64);
  head_on.a.motion = moving({-1.5, 0, 0}, {3, 0, 0});
  head_on.b.motion = moving({1.5, 0, 0}, {-3, 0, 0});
  check::example(query::closing_speed, "the bullet and the window head on, 3 each: 6", head_on,
                 [](const MovingPairCase& in) {
    const double got = run_closing_speed(in);
    const Outcome o = judge::closing_speed(in, got);
    if (o.verdict == Outcome::Verdict::fail) return o;
    Expect e("two bodies close on each other at most at the sum of their max speeds");
    e.near("closing_speed", got, 6, 0);
    return e.outcome();
  });
  check::example(query::sample_then_bisect, "the frame's ends only: the bullet tunnels",
                 SampledPair{bullet_and_window(1.0 / 64), 1},
                 both<SampledPair>(run_sampled, judge_sampled, expect_no_hit(1, 1)));
  check::example(query::sample_then_bisect, "25 sub-steps: sample 11 at t = 0.44 overlaps",
                 SampledPair{bullet_and_window(1.0 / 64), 25},
                 both<SampledPair>(run_sampled, judge_sampled, expect_hit(0.43, 0.44, 11, 2)));
  check::example(query::tunnelling, "the bullet and the window", bullet_and_window(1.0 / 64), judge_tunnelling);
  check::example(query::tunnelling, "the bullet and the window, head on", head_on, judge_tunnelling);
}

TEST_CASE(LABKIT_STEP(L04S3) ": random cases", "[lab04][step3][oracle]") {
  check::random_cases(query::substeps_for, gen::substep_rule(), [](const SubstepRule& in) {
    return judge::substeps_for(in, answerer::substeps_for(in.max_speed, in.step, in.smallest_size));
  });
  check::random_cases(query::sample_then_bisect, gen::sampled_pair(),
                      [](const SampledPair& in) { return judge::sample_then_bisect(in, run_sampled(in)); });
  check::random_cases(query::closing_speed, gen::moving_pair(),
                      [](const MovingPairCase& in) { return judge::closing_speed(in, run_closing_speed(in)); });
  check::random_cases(query::tunnelling, gen::tunnelling_pair(), judge_tunnelling);
}

// ---- Step 4 ------------------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L04S4) ": worked examples", "[lab04][step4]") {
  const auto surfaces = [](double got, double expected, double radii) {
    Expect e("the distance between the closed bodies is the gap between their surfaces");
    e.that("distance", std::abs(got - expected) <= 1e-12, fmt(got), fmt(expected),
           "the distance between the closed bodies is the gap between their surfaces (0 when they overlap)" +
               std::string(std::abs(got - expected - radii) <= 1e-12 ? ": yours is larger by the radii, measured "
                                                                       "between centres"
                                                                     : ""));
    return e.outcome();
  };
  const auto spheres = [surfaces](double expected) {
    return [=](const Sphere& b) {
      return surfaces(answerer::distance(Sphere{Vec3::Zero(), 1}, b), expected, 1 + b.radius);
    };
  };
  check::example(query::distance_spheres, "5 apart, radii 1 and 3: 1", Sphere{{3, 4, 0}, 3}, spheres(1));
  check::example(query::distance_spheres, "overlapping: 0", Sphere{{3, 4, 0}, 5}, spheres(0));
  const Box wall{{4, 0, 0}, Mat3::Identity(), {4, 4, 4}};
  const auto sphere_box = [wall, surfaces](double expected) {
    return [=](const Sphere& a) { return surfaces(answerer::distance(a, wall), expected, a.radius); };
  };
  check::example(query::distance_sphere_box, "sqrt(10) - 3", Sphere{{-3, 2, 5}, 3}, sphere_box(std::sqrt(10.0) - 3));
  check::example(query::distance_sphere_box, "overlapping: 0", Sphere{{-3, 2, 5}, 4}, sphere_box(0));
  check::example(query::distance_at, "the ball at t = 0 and at t = 0.3125", ball_and_wall(0, 0.3125, 1),
                 [](const MovingPairCase& in) {
    const MovingPair pair = pair_of(in);
    Expect e("distance_at(t) is the gap between the bodies' surfaces at time t, each body at its pose then");
    e.near("distance_at(0)", answerer::distance_at(pair, 0), 5, 1e-12);
    e.near("distance_at(0.3125)", answerer::distance_at(pair, 0.3125), 1.25, 1e-12);
    return e.outcome();
  });

  // The ball closes at 12; advancing with the bound 16 leaves 1/4 of the gap each step.
  check::example(query::advance, "the ball, bound 16: gaps 5, 1.25, 0.3125, ...",
                 AdvancedPair{ball_and_wall(0, 1, 1.0 / 256), 16.0 / 12},
                 both<AdvancedPair>(run_advance, judge_advance,
                                    expect_hit(0.4150390625, 0.4189453125, 5, 0,
                                               "each advance jumps by the time d / v, the gap over the closing speed "
                                               "(5 / 16, then 1.25 / 16, ...), at least one tolerance: 5 advances")));
  // The exact bound 6 lands on the first touch, t = 7/16; bisection finishes.
  check::example(query::advance, "the bullet, exact bound 6: no tunnelling",
                 AdvancedPair{bullet_and_window(1.0 / 64), 1},
                 both<AdvancedPair>(run_advance, judge_advance, expect_hit(0.423828125, 0.4375, 1, 5)));
}

TEST_CASE(LABKIT_STEP(L04S4) ": random cases", "[lab04][step4][oracle]") {
  check::random_cases(query::distance_at, gen::moving_pair(), [](const MovingPairCase& in) {
    const MovingPair pair = pair_of(in);
    return judge::distance_at(in, answerer::distance_at(pair, in.times.t0), answerer::distance_at(pair, in.times.t1));
  });
  check::random_cases(query::advance, gen::advanced_pair(),
                      [](const AdvancedPair& in) { return judge::advance(in, run_advance(in)); });
}

// ---- Step 5: robustness ---------------------------------------------------------------------------
// Exact input: the header's rules hold exactly, nothing is ambiguous.

TEST_CASE(LABKIT_STEP(L04S5) ": touching, grazing, zero sizes", "[lab04][step5]") {
  // Bodies at rest, tested at t = 0.
  const auto still = [](const MovingBody& a, const MovingBody& b) { return scene(a, b, 0, 0, 1); };
  const auto overlapping = [](bool expected) {
    return [expected](const MovingPairCase& in) {
      const bool got = answerer::overlap_at(pair_of(in), 0);
      Expect e("sets are closed: bodies that touch at t overlap at t");
      e.equal("overlap_at(0)", got, expected);
      const Outcome o = e.outcome();
      return o.verdict == Outcome::Verdict::fail ? o : judge::overlap_at(in, got, got, Rules::exact);
    };
  };
  const MovingBody cube = block({2, 2, 2}, resting_at(Vec3::Zero()));
  const MovingBody square = block({0, 2, 2}, resting_at(Vec3::Zero()));  // a flat box
  constexpr auto o = query::robust_overlap_at;
  check::example(o, "a sphere touching an edge, (3, 4) / 5 from it", still(ball(5, resting_at({5, 6, 0})), cube),
                 overlapping(true));
  check::example(o, "the same sphere, radius 4", still(ball(4, resting_at({5, 6, 0})), cube), overlapping(false));
  check::example(o, "a sphere touching a corner, (2, 3, 6) / 7 from it", still(ball(7, resting_at({4, 5, 8})), cube),
                 overlapping(true));
  check::example(o, "a point on a face", still(ball(0, resting_at({2, 1, -1})), cube), overlapping(true));
  check::example(o, "a point on a flat box", still(ball(0, resting_at({0, 1, 1})), square), overlapping(true));
  check::example(o, "a sphere touching a flat box", still(ball(1, resting_at({1, 1, 1})), square), overlapping(true));
  // A box 2^-19 wide and a point 2^-20 beyond its face: the squared gap is 2^-40, far
  // below a fuzzy 1e-9, and still not zero.
  const double tiny = std::ldexp(1.0, -20);
  check::example(o, "a near miss at the scale 1e-6",
                 still(ball(0, resting_at({2 * tiny, 0, 0})), block({tiny, tiny, tiny}, resting_at(Vec3::Zero()))),
                 overlapping(false));
  check::example(o, "spheres (3, 4, 0) apart, radii 2 and 3: touching",
                 still(ball(2, resting_at(Vec3::Zero())), ball(3, resting_at({3, 4, 0}))),
                 [=](const MovingPairCase& in) {
    const Outcome touch = overlapping(true)(in);
    if (touch.verdict == Outcome::Verdict::fail) return touch;
    Expect e("touching bodies are 0 apart");
    e.near("distance_at(0)", answerer::distance_at(pair_of(in), 0), 0, 0);
    return e.outcome();
  });

  constexpr auto q = query::robust_bisect;
  // x(t) = -4 + 3 t touches the wall's face (x = -1) exactly at t1 = 1, and only there.
  check::example(q, "touching only at t1", scene(ball(1, moving({-4, 0, 0}, {3, 0, 0})), kWall, 0, 1, 0.125),
                 both<MovingPairCase>(run_bisect, exact_bisect, expect_hit(0.875, 1, 0, 3)));
  // x(t) = -2 + 2 t touches at the first midpoint, t = 1/2: touching is a contact.
  check::example(q, "touching at the midpoint", scene(ball(1, moving({-2, 0, 0}, {2, 0, 0})), kWall, 0, 1, 0.125),
                 both<MovingPairCase>(run_bisect, exact_bisect, expect_hit(0.375, 0.5, 0, 3)));
  check::example(q, "touching at t0", scene(ball(1, moving({-1, 0, 0}, {2, 0, 0})), kWall, 0, 1, 0.125),
                 both<MovingPairCase>(run_bisect, exact_bisect, expect_start(0)));
  // A ball along y = 2 grazes a ball of radius 1 at the origin: they touch only at t = 1/2.
  const MovingPairCase graze =
      scene(ball(1, moving({-4, 2, 0}, {8, 0, 0})), ball(1, resting_at(Vec3::Zero())), 0, 1, 0.0625);
  check::example(q, "a graze between the ends is not seen", graze,
                 both<MovingPairCase>(run_bisect, exact_bisect, expect_no_hit(1, 0)));
  check::example(query::robust_sample_then_bisect, "a graze at a sample time is a contact", SampledPair{graze, 2},
                 both<SampledPair>(run_sampled, exact_sampled, expect_hit(0.4375, 0.5, 1, 3)));
  check::example(query::robust_advance, "touching at t0: nothing to advance",
                 AdvancedPair{scene(ball(1, moving({-1, 0, 0}, {2, 0, 0})), kWall, 0, 1, 0.125), 1},
                 both<AdvancedPair>(run_advance, exact_advance, expect_start(0)));
  check::example(query::robust_advance, "nothing moves: one advance to t1",
                 AdvancedPair{scene(ball(1, resting_at({-3, 0, 0})), kWall, 0, 1, 0.125), 1},
                 both<AdvancedPair>(run_advance, exact_advance, expect_no_hit(1, 1)));
}

TEST_CASE(LABKIT_STEP(L04S5) ": random exact cases", "[lab04][step5][oracle]") {
  check::random_cases(query::robust_closest_point, gen::exact_point_box(), [](const PointBox& in) {
    return judge::closest_point(in, answerer::closest_point(in.box, in.point), Rules::exact);
  });
  check::random_cases(query::robust_substeps_for, gen::exact_substep_rule(), [](const SubstepRule& in) {
    return judge::substeps_for(in, answerer::substeps_for(in.max_speed, in.step, in.smallest_size), Rules::exact);
  });
  check::random_cases(query::robust_overlap_at, gen::exact_moving_pair(), [](const MovingPairCase& in) {
    const MovingPair pair = pair_of(in);
    return judge::overlap_at(in, answerer::overlap_at(pair, in.times.t0), answerer::overlap_at(pair, in.times.t1),
                             Rules::exact);
  });
  check::random_cases(query::robust_bisect, gen::exact_moving_pair(),
                      [](const MovingPairCase& in) { return judge::bisect(in, run_bisect(in), Rules::exact); });
  check::random_cases(query::robust_sample_then_bisect, gen::exact_sampled_pair(), [](const SampledPair& in) {
    return judge::sample_then_bisect(in, run_sampled(in), Rules::exact);
  });
  check::random_cases(query::robust_advance, gen::exact_advanced_pair(),
                      [](const AdvancedPair& in) { return judge::advance(in, run_advance(in), Rules::exact); });
}

// ---- The header's preconditions -------------------------------------------------------------
// Run with the reference only (tagged [contract], in no step: students are not graded on
// invalid input). Every kind of invalid input must throw std::invalid_argument naming the
// function and the argument; none may hang (a tolerance of 0 used to halve forever).

TEST_CASE("L04 preconditions: invalid input is rejected, naming the argument", "[lab04][contract]") {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const MovingPair good = pair_of(ball_and_wall(0, 1, 1.0 / 32));
  const auto with_ball = [&](const Sphere& a) {
    MovingPair p = good;
    p.a = a;
    return p;
  };
  const auto with_box = [&](const Box& b) {
    MovingPair p = good;
    p.b = shape_of(b);
    return p;
  };
  const Box wall = good.b.box;

  // The searches' times and tolerance.
  for (const auto& [search, run] : std::vector<std::pair<std::string, std::function<void(double, double, double)>>>{
           {"bisect", [&](double t0, double t1, double tol) { answerer::bisect(good, t0, t1, tol); }},
           {"sample_then_bisect",
            [&](double t0, double t1, double tol) { answerer::sample_then_bisect(good, t0, t1, 4, tol); }},
           {"advance", [&](double t0, double t1, double tol) { answerer::advance(good, t0, t1, 12, tol); }}}) {
    rejects(search + ": tolerance 0 (halving forever)", search + ": tolerance", [&] { run(0, 1, 0); });
    rejects(search + ": tolerance -1", search + ": tolerance", [&] { run(0, 1, -1); });
    rejects(search + ": tolerance NaN", search + ": tolerance", [&] { run(0, 1, nan); });
    rejects(search + ": tolerance infinite", search + ": tolerance", [&] { run(0, 1, inf); });
    rejects(search + ": tolerance below the spacing of doubles near t", search + ": tolerance",
            [&] { run(1e6, 1e6 + 1, 1e-20); });
    rejects(search + ": t0 NaN", search + ": t0", [&] { run(nan, 1, 0.25); });
    rejects(search + ": t1 infinite", search + ": t1", [&] { run(0, inf, 0.25); });
    rejects(search + ": t0 > t1", search + ": t0 <= t1", [&] { run(1, 0, 0.25); });
    rejects(search + ": t1 - t0 overflows", search + ": t1 - t0", [&] { run(-1e308, 1e308, 1e300); });
  }
  rejects("sample_then_bisect: 0 sub-steps", "sample_then_bisect: substeps",
          [&] { answerer::sample_then_bisect(good, 0, 1, 0, 0.25); });
  rejects("sample_then_bisect: -3 sub-steps", "sample_then_bisect: substeps",
          [&] { answerer::sample_then_bisect(good, 0, 1, -3, 0.25); });
  rejects("advance: a negative speed bound", "advance: max_closing_speed",
          [&] { answerer::advance(good, 0, 1, -1, 0.25); });
  rejects("advance: a NaN speed bound", "advance: max_closing_speed",
          [&] { answerer::advance(good, 0, 1, nan, 0.25); });

  // The bodies, in every function that takes one.
  rejects("a negative radius", "bisect: pair.a.radius", [&] {
    answerer::bisect(with_ball({Vec3::Zero(), -1}), 0, 1, 0.25);
  });
  rejects("a NaN radius", "overlap_at: pair.a.radius", [&] {
    answerer::overlap_at(with_ball({Vec3::Zero(), nan}), 0);
  });
  rejects("a NaN centre", "distance_at: pair.a.center", [&] { answerer::distance_at(with_ball({{nan, 0, 0}, 1}), 0); });
  rejects("a negative half extent", "advance: pair.b.half_extents", [&] {
    answerer::advance(with_box({wall.center, wall.axes, {4, -1, 4}}), 0, 1, 12, 0.25);
  });
  rejects("a NaN half extent", "smallest_size: shape.half_extents", [&] {
    answerer::smallest_size(shape_of(Box{wall.center, wall.axes, {nan, 4, 4}}));
  });
  rejects("NaN box axes", "sample_then_bisect: pair.b.axes", [&] {
    answerer::sample_then_bisect(with_box({wall.center, Mat3::Constant(nan), wall.half_extents}), 0, 1, 2, 0.25);
  });
  rejects("overlap: a negative radius", "overlap: a.radius", [] {
    answerer::overlap(Sphere{Vec3::Zero(), -1}, Sphere{Vec3::Zero(), 1});
  });
  rejects("overlap: an infinite centre", "overlap: a.center", [&] { answerer::overlap(Sphere{{inf, 0, 0}, 1}, wall); });
  rejects("distance: a NaN radius", "distance: b.radius", [] {
    answerer::distance(Sphere{Vec3::Zero(), 1}, Sphere{Vec3::Zero(), nan});
  });
  rejects("distance: a negative half extent", "distance: b.half_extents", [] {
    answerer::distance(Sphere{Vec3::Zero(), 1}, Box{Vec3::Zero(), Mat3::Identity(), {-1, 1, 1}});
  });
  rejects("closest_point: a NaN point", "closest_point: p", [&] { answerer::closest_point(wall, Vec3(nan, 0, 0)); });
  rejects("overlap_at: a NaN time", "overlap_at: t", [&] { answerer::overlap_at(good, nan); });

  // The motions: a NaN velocity poses the body nowhere.
  MotionParameters nan_velocity = moving({-6, 0, 0}, {nan, 0, 0});
  MovingPair lost = good;
  lost.motion_a = motion_of(nan_velocity);
  rejects("a motion that returns a NaN pose", "pair.motion_a", [&] { answerer::bisect(lost, 0, 1, 0.25); });
  rejects("closing_speed: a NaN velocity", "closing_speed: motion_a", [&] {
    answerer::closing_speed(good.a, motion_of(nan_velocity), good.b, motion_of(resting_at({4, 0, 0})), 0, 1);
  });
  rejects("closing_speed: t0 > t1", "closing_speed: t0 <= t1",
          [&] { answerer::closing_speed(good.a, StandardMotion{}, good.b, StandardMotion{}, 1, 0); });

  // The sub-step rule's numbers.
  rejects("substeps_for: a negative speed", "substeps_for: closing_speed", [] { answerer::substeps_for(-6, 1, 0.25); });
  rejects("substeps_for: an infinite speed", "substeps_for: closing_speed",
          [] { answerer::substeps_for(inf, 1, 0.25); });
  rejects("substeps_for: a NaN step", "substeps_for: step", [] { answerer::substeps_for(6, nan, 0.25); });
  rejects("substeps_for: a negative size", "substeps_for: smallest_size", [] { answerer::substeps_for(6, 1, -0.25); });

  // What the header allows, at its edges, is answered.
  CHECK(answerer::bisect(good, 0.5, 0.5, 1.0 / 32).overlapping_at_start);  // t0 = t1
  CHECK(answerer::bisect(good, 0, 0.25, 0.25).hit == false);
  CHECK_NOTHROW(answerer::bisect(good, 1e6, 1e6 + 1, std::ldexp(1e6 + 1, -50)));  // the finest tolerance allowed
  CHECK(answerer::substeps_for(6, 1, 0) == 0);                                    // a size of 0: the documented 0
  CHECK(answerer::advance(good, 0, 0.25, 0, 1.0 / 32).steps == 1);                // a bound of 0 jumps to t1
}
