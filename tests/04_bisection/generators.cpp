#include "common/generators/generators.h"
#include "04_bisection/judge.h"

#include <algorithm>
#include <cmath>

namespace labkit::gen {

namespace {

// ---- Pieces ---------------------------------------------------------------------------

// A whole number in [lo, hi), uniformly at every size (RapidCheck's inRange narrows the
// range at small sizes), shrinking toward lo.
rc::Gen<int> pick(int lo, int hi) { return rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi)); }

// The kit's scales, and both ends of the domain lab 04's header states (lengths from
// 1e-100 to 1e100): 2^-300 and 2^300, powers of two, so that exact input stays exact.
rc::Gen<double> scales() {
  return rc::gen::weightedOneOf<double>(
      {{18, scale()}, {1, rc::gen::just(std::ldexp(1.0, -300))}, {1, rc::gen::just(std::ldexp(1.0, 300))}});
}

double reach_of(const MovingBody& b) {
  return b.is_box ? b.box.center.norm() + b.box.half_extents.norm() : b.sphere.center.norm() + b.sphere.radius;
}

// Where the body's shape centre is at time t.
Vec3 centre_at(const MovingBody& b, double t) {
  return pose_at(b.motion, t) * (b.is_box ? b.box.center : b.sphere.center);
}

// A signed permutation matrix: a box turned by quarter turns, exactly.
rc::Gen<Mat3> quarter_turns() {
  return rc::gen::exec([] {
    int order[3] = {0, 1, 2};
    std::swap(order[0], order[*pick(0, 3)]);
    std::swap(order[1], order[*pick(1, 3)]);
    Mat3 m = Mat3::Zero();
    for (int k = 0; k < 3; ++k) m(order[k], k) = *rc::gen::element(1.0, -1.0);
    return m;
  });
}

rc::Gen<Mat3> axes() {
  return rc::gen::weightedOneOf<Mat3>(
      {{2, rc::gen::just<Mat3>(Mat3::Identity())},
       {2, quarter_turns()},
       {5, rc::gen::map(rigid_transform(1.0), [](const RigidTransform& m) { return Mat3(m.linear()); })}});
}

// Sizes: quarters of the scale up to 8, now and then exactly zero.
rc::Gen<double> size(double s) {
  return rc::gen::exec([s] { return *rc::gen::weightedElement<int>({{1, 0}, {12, 1}}) * s * *pick(1, 33) / 4.0; });
}

rc::Gen<Sphere> sphere(double s) {
  return rc::gen::exec([s] { return Sphere{Vec3::Zero(), *size(s)}; });
}

rc::Gen<Box> box(double s) {
  return rc::gen::exec([s] { return Box{Vec3::Zero(), *axes(), Vec3(*size(s), *size(s), *size(s))}; });
}

// Any standard motion; velocities move a body by a few times the scale per unit of time.
rc::Gen<MotionParameters> motion(double s) {
  return rc::gen::exec([s] {
    MotionParameters m;
    m.start = *point(s);
    const int kind = *pick(0, 6);  // rest, linear, rotating, screw, accelerating, all
    if (kind == 1 || kind == 4 || kind == 5) m.velocity = *direction(s, 8);
    if (kind == 4 || kind == 5) m.acceleration = *direction(s, 8);
    if (kind == 2 || kind == 3 || kind == 5) {
      m.axis = *direction(1.0, 3);
      m.spin = *rc::gen::suchThat(integer(24), [](int k) { return k != 0; }) / 4.0;
    }
    if (kind == 3) m.velocity = *integer(8) * s * m.axis.normalized();
    return m;
  });
}

rc::Gen<SearchTimes> times(int finest) {
  return rc::gen::exec([finest] {
    SearchTimes t;
    t.t0 = *rc::gen::element(0.0, 0.0, 0.0, 0.25, 0.5, 1.0);
    const double span = *rc::gen::element(1.0, 1.0, 0.5, 0.25, 2.0, 0.75, 1.5);
    t.t1 = t.t0 + span;
    t.tolerance = std::ldexp(span * *rc::gen::element(1.0, 0.75, 0.625), -*pick(1, finest + 1));
    return t;
  });
}

MovingBody sphere_body(const Sphere& s, const MotionParameters& m) { return {false, s, Box{}, m}; }
MovingBody box_body(const Box& b, const MotionParameters& m) { return {true, Sphere{}, b, m}; }

rc::Gen<MovingBody> body(double s) {
  return rc::gen::exec([s] {
    const MotionParameters m = *motion(s);
    MovingBody b = *rc::gen::element(true, false) ? box_body(*box(s), m) : sphere_body(*sphere(s), m);
    // Now and then the shape sits away from the body's origin: a spinning body orbits.
    if (*pick(0, 4) == 0) (b.is_box ? b.box.center : b.sphere.center) = *point(s);
    return b;
  });
}

// The motion that puts a body's origin at p0 at time t0 and at p1 at time t1, with the
// given acceleration (solve start + v t + a t^2 / 2 at both times).
MotionParameters through(const Vec3& p0, double t0, const Vec3& p1, double t1, const Vec3& acceleration) {
  MotionParameters m;
  m.acceleration = acceleration;
  m.velocity = (p1 - p0 - acceleration * (0.5 * (t1 * t1 - t0 * t0))) / (t1 - t0);
  m.start = p0 - m.velocity * t0 - acceleration * (0.5 * t0 * t0);
  return m;
}

// A point of the body's shape (in its own frame), `depth` of the way from its centre to
// its boundary (0: the centre).
Vec3 inner_point(const MovingBody& b, double depth) {
  const double f = depth * *pick(0, 9) / 8.0;
  if (!b.is_box) return b.sphere.center + f * b.sphere.radius * Vec3(*direction(1.0, 4)).normalized();
  Vec3 p = b.box.center;
  for (int k = 0; k < 3; ++k) p += f * *rc::gen::element(1.0, -1.0, 0.5) * b.box.half_extents[k] * b.box.axes.col(k);
  return p;
}

// ---- Families -------------------------------------------------------------------------

// A sphere runs into the other body: deep inside it at t1, well away at t0 (along some
// direction, at a few times the bodies' reach); linearly or accelerating.
rc::Gen<MovingPairCase> collision(int finest) {
  return rc::gen::exec([finest] {
    const double s = *scales();
    MovingPairCase c;
    c.times = *times(finest);
    c.b = *body(s);
    const double r = *size(s);
    const Vec3 target = pose_at(c.b.motion, c.times.t1) * inner_point(c.b, 0.9);
    const double away = (reach_of(c.b) + r) * *pick(3, 9) / 2.0 + s;
    const Vec3 from = target - away * Vec3(*direction(1.0, 4)).normalized();
    const Vec3 acceleration = *rc::gen::element(0, 0, 1) ? Vec3(*direction(s, 8)) : Vec3::Zero();
    c.a = sphere_body(Sphere{Vec3::Zero(), r}, through(from, c.times.t0, target, c.times.t1, acceleration));
    // A spinning sphere looks the same: spin it now and then anyway.
    if (*pick(0, 4) == 0) {
      c.a.motion.axis = *direction(1.0, 3);
      c.a.motion.spin = *integer(16) / 4.0;
    }
    return c;
  });
}

// The sphere already overlaps the other body at t0.
rc::Gen<MovingPairCase> started(int finest) {
  return rc::gen::exec([finest] {
    const double s = *scales();
    MovingPairCase c;
    c.times = *times(finest);
    c.b = *body(s);
    const Vec3 inside = pose_at(c.b.motion, c.times.t0) * inner_point(c.b, 0.9);
    const Vec3 later = inside + Vec3(*direction(s, 8));
    c.a = sphere_body(*sphere(s), through(inside, c.times.t0, later, c.times.t1, Vec3::Zero()));
    return c;
  });
}

// Two unrelated bodies: they may meet, or never.
rc::Gen<MovingPairCase> unrelated(int finest) {
  return rc::gen::exec([finest] {
    const double s = *scales();
    MovingPairCase c;
    c.times = *times(finest);
    c.b = *body(s);
    c.a = *body(s);
    c.a.is_box = false;
    return c;
  });
}

// ---- Exact touching -------------------------------------------------------------------

// Directions with small whole numerators and denominators 1, 3, 5 or 7, of unit length:
// a radius that is a multiple of 105 times such a direction is a whole number.
struct RationalDirection {
  Vec3 numerator;
  double denominator;
};

rc::Gen<RationalDirection> rational_direction() {
  return rc::gen::exec([] {
    const auto [n, d] =
        *rc::gen::element(std::pair<Vec3, double>{Vec3(1, 0, 0), 1}, std::pair<Vec3, double>{Vec3(3, 4, 0), 5},
                          std::pair<Vec3, double>{Vec3(1, 2, 2), 3}, std::pair<Vec3, double>{Vec3(2, 3, 6), 7});
    int order[3] = {0, 1, 2};
    std::swap(order[0], order[*pick(0, 3)]);
    std::swap(order[1], order[*pick(1, 3)]);
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[order[k]] = n[k] * *rc::gen::element(1.0, -1.0);
    return RationalDirection{p, d};
  });
}

// A point where a sphere of radius r touches the (posed, motionless for now) body from
// outside, with the outward normal there; exact when the body's numbers are.
struct Touch {
  Vec3 centre;  // the touching sphere's centre
  Vec3 normal;  // outward, not unit (whole numbers)
};

Touch touch_sphere(const Sphere& b, double r, const RationalDirection& u) {
  return {b.center + (b.radius + r) * u.numerator / u.denominator, u.numerator};
}

// On a face, an edge or a corner of the box: a point of that feature, pushed out by r
// along a normal that points out of the box there.
Touch touch_box(const Box& b, double r, double s) {
  const int feature = *pick(0, 3);  // free axes: 2 (face), 1 (edge), 0 (corner)
  int order[3] = {0, 1, 2};
  std::swap(order[0], order[*pick(0, 3)]);
  std::swap(order[1], order[*pick(1, 3)]);
  const Vec3 sign(*rc::gen::element(1.0, -1.0), *rc::gen::element(1.0, -1.0), *rc::gen::element(1.0, -1.0));
  static const Vec3 kNormals[3] = {Vec3(1, 0, 0), Vec3(3, 4, 0), Vec3(2, 3, 6)};
  static const double kDenominators[3] = {1, 5, 7};
  Vec3 local, normal;
  for (int k = 0; k < 3; ++k) {
    const int axis = order[k];
    const double h = b.half_extents[axis];
    // Fixed axes sit at +-h; free axes anywhere in [-h, h] on the lattice of 8 s.
    const bool fixed = k <= feature;
    local[axis] = fixed ? sign[axis] * h : std::clamp(8 * s * *integer(16), -h, h);
    normal[axis] = fixed ? sign[axis] * kNormals[feature][k] : 0.0;
  }
  const Vec3 offset = r * normal / kDenominators[feature];
  return {b.center + b.axes * (local + offset), b.axes * normal};
}

// Exact (or, with a nudge, nearly exact) touching at a time tau of the search: the
// sphere, moving by its state (position, velocity, acceleration) at tau, touches the
// other body there, and then approaches it, leaves it, or only grazes it.
rc::Gen<MovingPairCase> touching(bool exact) {
  return rc::gen::exec([exact] {
    const double s = *scales() * 8;
    MovingPairCase c;
    c.times.t0 = *rc::gen::element(0.0, 0.0, 0.25, 1.0);
    const double span = *rc::gen::element(1.0, 2.0, 0.5);
    c.times.t1 = c.times.t0 + span;
    c.times.tolerance = std::ldexp(span, -*pick(2, 13));
    const double tau = c.times.t0 + span * *rc::gen::element(0.0, 1.0, 0.5, 0.25, 0.75, 0.125, 0.375);

    // The other body: at rest or moving linearly, its shape at its own origin.
    MotionParameters mb;
    mb.start = *lattice_point(s);
    if (*rc::gen::element(true, false)) mb.velocity = *lattice_point(s, 8);
    const double r = 105 * s / 8 * *pick(0, 3);
    Touch touch;
    if (*rc::gen::element(true, false)) {
      Box b{Vec3::Zero(), *quarter_turns(), Vec3::Zero()};
      for (int k = 0; k < 3; ++k) b.half_extents[k] = s * *rc::gen::weightedElement<int>({{1, 0}, {6, *pick(1, 9)}});
      c.b = box_body(b, mb);
      touch = touch_box(b, r, s);
    } else {
      const Sphere b{Vec3::Zero(), 105 * s / 8 * *pick(0, 3)};
      c.b = sphere_body(b, mb);
      touch = touch_sphere(b, r, *rational_direction());
    }
    Vec3 centre = pose_at(mb, tau) * touch.centre;
    // Nudged off: by a hair (random cases), or exactly one lattice step out (a near miss
    // a fuzzy comparison takes for a touch).
    if (!exact)
      centre += *integer(4) * *tiny(20, 50) * s * touch.normal.normalized();
    else if (*pick(0, 4) == 0)
      centre += s / 8 * touch.normal;

    // Relative velocity at tau: toward, away from, or along the surface.
    Vec3 v = *lattice_point(s, 8);
    const int how = *pick(0, 3);
    if (how == 2)
      v = touch.normal.cross(v) / 8;  // along: perpendicular to the normal (whole numbers)
    else if ((how == 0) == (v.dot(touch.normal) > 0))
      v = -v;
    if (how != 2 && v.dot(touch.normal) == 0) v -= how == 0 ? touch.normal : -touch.normal;
    const Vec3 g = *rc::gen::element(0, 0, 1) ? Vec3(*lattice_point(2 * s, 4)) : Vec3::Zero();
    const Vec3 u = mb.velocity + v;
    MotionParameters ma;
    ma.acceleration = g;
    ma.velocity = u - g * tau;
    ma.start = centre - u * tau + g * (0.5 * tau * tau);
    c.a = sphere_body(Sphere{Vec3::Zero(), r}, ma);
    return c;
  });
}

// A fast small sphere through a thin wall (or a small sphere), between two samples.
rc::Gen<MovingPairCase> tunnelling() {
  return rc::gen::exec([] {
    const double s = *scales();
    MovingPairCase c;
    c.times = *times(12);
    const double span = c.times.t1 - c.times.t0;
    const double r = s * *pick(1, 9) / 64;
    MotionParameters mb;
    mb.start = *point(s);
    double thickness;
    Vec3 normal, across1, across2;
    if (*pick(0, 4) > 0) {  // a wall: thin along its first axis
      Box wall{Vec3::Zero(), *axes(), Vec3(s * *pick(1, 9) / 128, s * *pick(4, 17), s * *pick(4, 17))};
      c.b = box_body(wall, mb);
      thickness = 2 * wall.half_extents[0];
      normal = wall.axes.col(0);
      across1 = wall.half_extents[1] / 4 * wall.axes.col(1);
      across2 = wall.half_extents[2] / 4 * wall.axes.col(2);
    } else {  // a small ball
      const Sphere ball{Vec3::Zero(), s * *pick(1, 9) / 64};
      c.b = sphere_body(ball, mb);
      thickness = 2 * ball.radius;
      normal = Vec3(*direction(1.0, 4)).normalized();
      across1 = across2 = Vec3::Zero();  // right through the middle
    }
    if (*rc::gen::element(0, 0, 1)) c.b.motion.velocity = *direction(s / 8, 4);  // a slowly drifting target
    // The sphere crosses the target's middle at t_c, tilted at most 1/8 off its normal,
    // moving `ratio` smallest sizes per search: far enough that both ends are clear.
    const double smallest = std::min(2 * r, thickness);
    const double needed = 12 * (thickness / 2 + r) / smallest;           // keeps 1/6 of the path clear at either end
    const double ratio = std::max(needed, double(*pick(4, 401))) + 0.5;  // not a whole number of sizes
    const double t_c = c.times.t0 + span * *pick(2, 7) / 8.0;
    const Vec3 tilt = Vec3(*direction(1.0, 4)).normalized() / 8;
    const Vec3 heading = (normal + tilt - tilt.dot(normal) * normal).normalized() * *rc::gen::element(1.0, -1.0);
    const Vec3 crossing = centre_at(c.b, t_c) + *integer(4) / 4.0 * across1 + *integer(4) / 4.0 * across2;
    const Vec3 relative = heading * ratio * smallest / span;
    MotionParameters ma;
    ma.velocity = c.b.motion.velocity + relative;
    ma.start = crossing - ma.velocity * t_c;
    c.a = sphere_body(Sphere{Vec3::Zero(), r}, ma);
    return c;
  });
}

// Moved far from the origin (far_away): both bodies' starts, by multiples of the
// bodies' reach, at least 1.
void move_starts(MovingPairCase& c, const Vec3& offset) {
  c.a.motion.start += offset;
  c.b.motion.start += offset;
}
double reach_of_pair(const MovingPairCase& c) { return std::max({1.0, reach_of(c.a), reach_of(c.b)}); }

rc::Gen<MovingPairCase> pairs(int finest) {
  const rc::Gen<MovingPairCase> families = rc::gen::weightedOneOf<MovingPairCase>({
      {8, collision(finest)},
      {2, started(finest)},
      {2, unrelated(finest)},
      {2, touching(false)},
      {1, touching(true)},
      {1, tunnelling()},
  });
  return rc::gen::weightedOneOf<MovingPairCase>({{7, families}, {1, far_away(families, move_starts, reach_of_pair)}});
}

}  // namespace

rc::Gen<MovingPairCase> moving_pair() { return pairs(30); }
rc::Gen<MovingPairCase> advancing_pair() { return pairs(12); }
rc::Gen<MovingPairCase> exact_moving_pair() { return touching(true); }
rc::Gen<MovingPairCase> tunnelling_pair() { return tunnelling(); }

rc::Gen<PointBox> point_box() {
  return rc::gen::exec([] {
    const double s = *scales();
    Box b = *box(s);
    b.center = *point(s);
    // On a face, an edge or a corner, inside, outside, or a hair off any of them.
    Vec3 local;
    for (int k = 0; k < 3; ++k) local[k] = b.half_extents[k] * *integer(12) / 8.0;
    Vec3 p = b.center + b.axes * local;
    if (*rc::gen::element(0, 1)) p += *integer(4) * *tiny(20, 50) * s * Vec3(*direction(1.0, 2)).normalized();
    return PointBox{p, b};
  });
}

rc::Gen<PointBox> exact_point_box() {
  return rc::gen::exec([] {
    const double s = 8 * *scales();
    Box b{*lattice_point(s), *quarter_turns(), Vec3::Zero()};
    for (int k = 0; k < 3; ++k) b.half_extents[k] = s * *pick(0, 9);
    Vec3 local;
    for (int k = 0; k < 3; ++k) local[k] = b.half_extents[k] * *integer(12) / 8.0 + s * *integer(1);
    return PointBox{b.center + b.axes * local, b};
  });
}

// Sizes from 2^-20 to 2^23, steps of 2^-k: the ratio speed * step / size is a whole
// number (exact input: on the rule's boundary; otherwise 2^-20 to either side of it, just
// outside the band where rounding decides), a whole number near the cap 2^20, anything,
// or there is no size at all.
rc::Gen<SubstepRule> substep_rule(bool exact) {
  return rc::gen::exec([exact] {
    const double size = std::ldexp(1.0, *pick(-20, 21)) * *pick(1, 9);
    const double step = std::ldexp(1.0, -*pick(0, 8));
    const double fraction = exact ? 0.0 : *pick(1, 1 << 20) / double(1 << 20);
    const int kind = *rc::gen::weightedElement<int>({{exact ? 4 : 1, 0}, {1, 1}, {1, 2}, {exact ? 0 : 4, 3}});
    if (kind == 0 && !exact)
      return SubstepRule{size / step * (*pick(1, 2000) + *rc::gen::element(1.0, -1.0) * std::ldexp(1.0, -20)), step,
                         size};
    if (kind == 0) return SubstepRule{size / step * *pick(0, 2000), step, size};
    if (kind == 1) return SubstepRule{size / step * (*pick((1 << 20) - 2, (1 << 20) + 2) + fraction), step, size};
    if (kind == 2) return SubstepRule{*pick(0, 1000) * 1.0, step, 0.0};
    return SubstepRule{size / step * (*pick(0, 2000) + fraction), step, size};
  });
}

rc::Gen<SubstepRule> substep_rule() { return substep_rule(false); }
rc::Gen<SubstepRule> exact_substep_rule() { return substep_rule(true); }

rc::Gen<SampledPair> sampled_pair() {
  return rc::gen::exec([] {
    return SampledPair{*rc::gen::weightedOneOf<MovingPairCase>({{4, moving_pair()}, {1, tunnelling()}}),
                       *rc::gen::element(1, 2, 3, 4, 7, 8, 16, 33, 64)};
  });
}

rc::Gen<SampledPair> exact_sampled_pair() {
  return rc::gen::exec([] { return SampledPair{*exact_moving_pair(), *rc::gen::element(1, 2, 4, 8)}; });
}

rc::Gen<AdvancedPair> advanced_pair() {
  return rc::gen::exec([] {
    return AdvancedPair{*rc::gen::weightedOneOf<MovingPairCase>({{4, advancing_pair()}, {1, tunnelling()}}),
                        *rc::gen::element(1.0, 1.0, 1.5, 2.0, 8.0)};
  });
}

rc::Gen<AdvancedPair> exact_advanced_pair() {
  return rc::gen::exec([] { return AdvancedPair{*exact_moving_pair(), *rc::gen::element(1.0, 2.0)}; });
}

}  // namespace labkit::gen
