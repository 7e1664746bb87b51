// Lab 07's extensions' random inputs: two particles on a damped spring (step 9) and two
// rigid bodies at a contact (step 10), kept out of the judge's ambiguity band
// (tests/07_particles/judge.h) where a family is meant to be decisive.
#include "07_particles/judge.h"

#include <algorithm>
#include <cmath>

namespace labkit::gen {

using lab07::Particle;
using lab07::RigidBody;
using lab07::RigidCase;
using lab07::SpringCase;

namespace {

rc::Gen<double> dyadic(int low, int high, int bits) {
  return rc::gen::map(rc::gen::inRange(low, high + 1), [bits](int k) { return std::ldexp(double(k), -bits); });
}

rc::Gen<Vec3> unit_vector() {
  return rc::gen::map(direction(1.0, 4), [](const Vec3& v) { return Vec3(v.normalized()); });
}

// A coefficient of the domain's range 2^-20 to 2^20: mostly near 1.
rc::Gen<double> coefficient() {
  return rc::gen::exec([] {
    const int e = *rc::gen::weightedOneOf<int>({{4, rc::gen::inRange(-3, 4)}, {1, rc::gen::inRange(-17, 17)}});
    return std::ldexp(*dyadic(1, 8, 0), e);
  });
}

double push() { return std::ldexp(1.0, *rc::gen::inRange(4, 17)); }
double away(double value) { return value > 0 ? 1.0 : value < 0 ? -1.0 : *rc::gen::element(1.0, -1.0); }

}  // namespace

rc::Gen<SpringCase> spring_case() {
  return rc::gen::exec([] {
    const double s = *particle_scale();
    SpringCase c;
    Particle &a = c.a, &b = c.b;
    const int family = *rc::gen::inRange(0, 5);
    a.position = *point(s);
    b.position = *point(s);
    if (family == 1) b.position = a.position + *tiny(1, 20) * s * *unit_vector();  // close together
    if (family == 2) {                                                             // far from the origin
      const Vec3 far = std::ldexp(1.0, 16) * s * *unit_vector();
      a.position += far, b.position += far;
    }
    a.velocity = *point(s), b.velocity = *point(s);
    a.mass = *rc::gen::weightedOneOf<double>({{2, rc::gen::just(1.0)}, {1, dyadic(1, 64, 3)}});
    b.mass = a.mass;
    c.spring.stiffness = *coefficient();
    c.spring.damping = *rc::gen::weightedOneOf<double>({{1, rc::gen::just(0.0)}, {3, coefficient()}});
    const Vec3 gap = a.position - b.position;
    c.spring.rest_length = *rc::gen::weightedOneOf<double>({{1, rc::gen::just(0.0)}, {3, dyadic(1, 64, 2)}}) * s;
    if (family == 3) {  // at rest length: only the damping pulls, so it must have a lengthening to damp
      c.spring.rest_length = gap.norm();
      c.spring.damping = *coefficient();
      b.velocity = a.velocity - *dyadic(1, 16, 2) * gap;
    }
    if (family == 4 && gap != Vec3::Zero()) {  // circling: no lengthening, so no damping force
      const Vec3 dv = a.velocity - b.velocity;
      b.velocity = a.velocity - (dv - dv.dot(gap) / gap.squaredNorm() * gap);
    }
    if (family == 3 || family == 4) {
      // Cancellation's dust (far below the speeds) set to 0: it would leave the domain.
      for (int i = 0; i < 3; ++i)
        if (std::abs(b.velocity[i]) < std::ldexp(s, -40)) b.velocity[i] = 0;
    }
    // Coincident or nearly so: the direction is in doubt; moved apart (coincidence is a
    // worked example, not a random case).
    if (lab07::judge::spring_in_doubt(c)) b.position = a.position + s * *unit_vector();
    return c;
  });
}

namespace {

// I^-1 = R diag(d) R^T / (m L^2), symmetric exactly; entries that are rounding noise
// (below 2^-40 of the largest) set to 0.
Mat3 inverse_inertia(double mass, double length, int shape) {
  Vec3 d(*dyadic(1, 64, 3), *dyadic(1, 64, 3), *dyadic(1, 64, 3));
  if (shape == 1) d = Vec3::Constant(d.x());  // round: the same about every axis
  Mat3 r = Mat3::Identity();
  if (shape == 2) r = (*rigid_transform(1.0)).linear();  // turned: a full tensor
  Mat3 m = r * d.asDiagonal() * r.transpose() / (mass * length * length);
  m = (0.5 * (m + m.transpose())).eval();
  const double big = m.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(m(i, j)) < std::ldexp(big, -40)) m(i, j) = 0;
  return m;
}

RigidBody body(double length, double speed, int shape) {
  RigidBody b;
  b.mass = *rc::gen::weightedOneOf<double>({{2, rc::gen::just(1.0)}, {2, dyadic(1, 64, 3)}});
  b.inverse_inertia = inverse_inertia(b.mass, length, shape);
  b.velocity = *point(speed);
  b.angular_velocity = *point(speed / length);
  return b;
}

}  // namespace

rc::Gen<RigidCase> rigid_case() {
  return rc::gen::exec([] {
    const auto power = [] {
      return std::ldexp(
          1.0, *rc::gen::weightedOneOf<int>(
                   {{6, rc::gen::just(0)}, {1, rc::gen::element(-40, -20, 20, 40)}, {1, rc::gen::inRange(-8, 9)}}));
    };
    const double L = power(), V = power();
    const int family = *rc::gen::inRange(0, 6);
    const int shape = *rc::gen::inRange(0, 3);
    RigidCase c;
    c.a = body(L, V, shape);
    c.b = body(L, V, *rc::gen::inRange(0, 3));
    if (family == 5) c.b.mass = std::ldexp(c.b.mass, 12), c.b.inverse_inertia /= 4096;  // heavy b
    c.contact.point = *point(L);
    c.contact.normal = *rc::gen::weightedOneOf<Vec3>(
        {{1, rc::gen::element(Vec3(Vec3::UnitZ()), Vec3(-Vec3::UnitX()))}, {3, unit_vector()}});
    const Vec3 n = c.contact.normal;
    c.a.centre = c.contact.point + *point(L) / 4;
    c.b.centre = c.contact.point - *point(L) / 4;
    if (family == 1) {  // through both centres: r parallel to n, no turning
      c.a.centre = c.contact.point + *dyadic(1, 64, 2) * L * n;
      c.b.centre = c.contact.point - *dyadic(1, 64, 2) * L * n;
    }
    c.contact.restitution =
        *rc::gen::weightedOneOf<double>({{2, rc::gen::element(0.0, 0.5, 1.0)}, {2, dyadic(0, 16, 4)}});
    const auto v_rel = [&] {
      const Vec3 p = c.contact.point;
      return n.dot(c.a.velocity + c.a.angular_velocity.cross(p - c.a.centre) - c.b.velocity -
                   c.b.angular_velocity.cross(p - c.b.centre));
    };
    // Mostly closing; family 2 separating (the bodies are returned unchanged).
    const bool separating = family == 2;
    if ((v_rel() < 0) == separating)
      for (RigidBody* x : {&c.a, &c.b}) x->velocity = -x->velocity, x->angular_velocity = -x->angular_velocity;
    if (family == 3) c.a.velocity -= v_rel() * n;  // sliding past: v_rel about 0
    // v_rel within the band: "closing" in doubt; moved just outside it.
    const double band = lab07::judge::rigid_closing_band(c), v = v_rel();
    if (std::abs(v) <= band) c.a.velocity += away(v) * push() * band * n;
    return c;
  });
}

}  // namespace labkit::gen
