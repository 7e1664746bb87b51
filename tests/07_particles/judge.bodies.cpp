// Lab 07's extensions: the damped spring (step 9) and the rigid-body impulse with its
// angular part (step 10), each against the exact oracle with the tolerances of
// labs/07_particles/particles.h.
#include "07_particles/judge_internal.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab07::judge {

// ---- Step 9 ----------------------------------------------------------------------------

namespace {

// S and V of the header's step 9: the positions' and the rest length's largest absolute
// coordinate, the velocities' largest absolute component.
double spring_scale(const SpringCase& in) {
  return std::max({largest(in.a.position), largest(in.b.position), in.spring.rest_length});
}
double spring_speed(const SpringCase& in) { return std::max(largest(in.a.velocity), largest(in.b.velocity)); }

}  // namespace

bool spring_in_doubt(const SpringCase& in) {
  return (in.a.position - in.b.position).norm() <= kRelative * spring_scale(in);
}

Outcome spring_force(const SpringCase& in, const Vec3& got) {
  if (!finite(got)) return fail("a finite force", describe(got), "the spring's force is finite for every input");
  const Spring& s = in.spring;
  if (in.a.position == in.b.position) {
    Expect e("zero length: a and b at the same point give the spring no direction, and the force is zero");
    e.near("force", got, Vec3::Zero(), 0.0);
    return e.outcome();
  }
  if (spring_in_doubt(in)) return ambiguous();
  const Vec3 exact = oracle::spring_force(in.a.position, in.a.velocity, in.b.position, in.b.velocity, s.stiffness,
                                          s.damping, s.rest_length);
  // d = a - b carries rounding of size S: the length is off by about S, the direction by
  // about S / l, which turns the whole force |F| <= k_s |l - l_rest| + k_d |v_a - v_b|.
  const double S = spring_scale(in), V = spring_speed(in), l = (in.a.position - in.b.position).norm();
  const double tol =
      kRelative * (s.stiffness * (S + std::abs(l - s.rest_length) * S / l) + s.damping * V * (1 + 4 * S / l)) + 1e-300;
  Expect e(
      "F_a = -(k_s (l - l_rest) + k_d ((v_a - v_b) . u)) u, u = (a - b) / l: the force is on a, Hooke's law pulls it "
      "back toward the rest length along the spring, and the damping takes only the part of the relative velocity "
      "along the spring");
  e.near("force", got, exact, tol);
  return e.outcome();
}

// ---- Step 10 ---------------------------------------------------------------------------

namespace {

oracle::Body body_of(const RigidBody& b) {
  return {b.centre, b.velocity, b.angular_velocity, b.mass, b.inverse_inertia};
}

// The header's step 10 scales.
struct RigidScales {
  double S = 0, R_a = 0, R_b = 0, K_a = 0, K_b = 0, T = 0, D_abs = 0;
};

RigidScales scales(const RigidCase& in) {
  RigidScales x;
  const Vec3& p = in.contact.point;
  x.S = std::max({largest(in.a.centre), largest(in.b.centre), largest(p)});
  x.R_a = (p - in.a.centre).norm() + x.S;
  x.R_b = (p - in.b.centre).norm() + x.S;
  x.K_a = 3 * in.a.inverse_inertia.cwiseAbs().maxCoeff();
  x.K_b = 3 * in.b.inverse_inertia.cwiseAbs().maxCoeff();
  x.T = in.a.velocity.norm() + in.b.velocity.norm() + in.a.angular_velocity.norm() * x.R_a +
        in.b.angular_velocity.norm() * x.R_b;
  x.D_abs = 1 / in.a.mass + 1 / in.b.mass + x.K_a * x.R_a * x.R_a + x.K_b * x.R_b * x.R_b;
  return x;
}

}  // namespace

double rigid_closing_band(const RigidCase& in) { return 10 * kRelative * scales(in).T; }

Outcome rigid_impulse(const RigidCase& in, const RigidImpulse& got) {
  const Contact& c = in.contact;
  const oracle::Body a = body_of(in.a), b = body_of(in.b);
  const oracle::RigidImpulse exact = oracle::rigid_impulse(a, b, c.point, c.normal, c.restitution);
  for (const Vec3& v : {got.velocity_a, got.angular_velocity_a, got.velocity_b, got.angular_velocity_b})
    if (!finite(v) || !std::isfinite(got.j) || !std::isfinite(got.v_rel))
      return fail("finite numbers", describe(got), "the impulse and the velocities after it are finite");
  const RigidScales x = scales(in);
  const double e_ = c.restitution;
  // A tie, v_rel = 0 exactly, is the header's rule (not closing); near it, either answer.
  if (exact.v_rel != 0 && std::abs(exact.v_rel) <= rigid_closing_band(in)) return ambiguous();
  if (got.closing != exact.closing)
    return fail("closing = " + describe(exact.closing), "closing = " + describe(got.closing),
                "the contact points close when v_rel = n . ((v_a + w_a x r_a) - (v_b + w_b x r_b)) < 0 (0 is not "
                "closing); here v_rel = " +
                    fmt(exact.v_rel));

  Expect rel("v_rel = n . (v_pa - v_pb) with each contact point's velocity v + w x r, r = point - centre");
  rel.near("v_rel", got.v_rel, exact.v_rel, kRelative * x.T + 1e-300);
  if (const Outcome o = rel.outcome(); o.verdict == Outcome::Verdict::fail) return o;

  const double tol_j = kRelative * ((1 + e_) * x.T + std::abs(exact.j) * x.D_abs) / exact.denominator + 1e-300;
  Expect size(
      "j = -(1 + e) v_rel / (1/m_a + 1/m_b + n . ((I_a^-1 (r_a x n)) x r_a) + n . ((I_b^-1 (r_b x n)) x r_b)): the "
      "angular terms belong in the denominator, and j = 0 when not closing");
  size.near("j", got.j, exact.j, tol_j);
  if (const Outcome o = size.outcome(); o.verdict == Outcome::Verdict::fail) return o;

  const double dj = tol_j + kRelative * std::abs(exact.j);
  const double tol_va = kRelative * in.a.velocity.norm() + dj / in.a.mass + 1e-300;
  const double tol_vb = kRelative * in.b.velocity.norm() + dj / in.b.mass + 1e-300;
  const double tol_wa = kRelative * in.a.angular_velocity.norm() + x.K_a * x.R_a * dj + 1e-300;
  const double tol_wb = kRelative * in.b.angular_velocity.norm() + x.K_b * x.R_b * dj + 1e-300;
  Expect linear("J = j n changes a's momentum by +J and b's by -J: v_a' = v_a + J / m_a, v_b' = v_b - J / m_b");
  linear.near("velocity_a", got.velocity_a, exact.velocity_a, tol_va);
  linear.near("velocity_b", got.velocity_b, exact.velocity_b, tol_vb);
  if (const Outcome o = linear.outcome(); o.verdict == Outcome::Verdict::fail) return o;
  Expect angular(
      "the angular impulse r x J turns each body through its world-frame inverse inertia: w_a' = w_a + I_a^-1 (r_a x "
      "J), w_b' = w_b - I_b^-1 (r_b x J)");
  angular.near("angular_velocity_a", got.angular_velocity_a, exact.angular_velocity_a, tol_wa);
  angular.near("angular_velocity_b", got.angular_velocity_b, exact.angular_velocity_b, tol_wb);
  if (const Outcome o = angular.outcome(); o.verdict == Outcome::Verdict::fail) return o;
  if (!exact.closing) return pass();

  // The invariants, exact on the answer: they follow from the fields within the
  // tolerances above, and say what the formulas are for.
  const double momentum = oracle::momentum_change(a, b, got.velocity_a, got.velocity_b).norm();
  if (momentum > in.a.mass * tol_va + in.b.mass * tol_vb)
    return fail("m_a v_a + m_b v_b unchanged", "it changed by " + fmt(momentum),
                "the impulse pair J, -J keeps the total momentum m_a v_a + m_b v_b");
  oracle::Body a_after = a, b_after = b;
  a_after.velocity = got.velocity_a, a_after.angular_velocity = got.angular_velocity_a;
  b_after.velocity = got.velocity_b, b_after.angular_velocity = got.angular_velocity_b;
  const double defect = oracle::restitution_defect(a, b, a_after, b_after, c.point, c.normal, e_);
  const double tol_defect = tol_va + tol_vb + tol_wa * x.R_a + tol_wb * x.R_b;
  if (std::abs(defect) > tol_defect)
    return fail("n . (v_pa' - v_pb') = -e v_rel = " + fmt(-e_ * exact.v_rel), "it is off by " + fmt(defect),
                "restitution: after the impulse the contact points separate at -e times the speed they closed with");
  return pass();
}

}  // namespace labkit::lab07::judge
