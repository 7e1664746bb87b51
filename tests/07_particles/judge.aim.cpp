// Lab 07's step 3: aiming a shot at a target under gravity (how many angles reach it, and
// each shot's angle, velocity and time), against the exact discriminant and roots.
#include "07_particles/judge_internal.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab07::judge {

// ---- Step 3 ----------------------------------------------------------------------------

namespace {

// Could moving from and target by 1e-9 S, and speed and gravity by 1e-9 of themselves,
// change the sign of D = v^4 + 2 v^2 (d . g) - |d x g|^2, or move the target off (or
// onto) the vertical? Each term's change is bounded by its size times its relative
// change; twice the sum is the doubt.
bool launch_in_doubt(const LaunchCase& in) {
  const double eps = kRelative;
  const double S = std::max({largest(in.from), largest(in.target), 1e-300});
  const Vec3 d = in.target - in.from;
  const double dd = 2 * kRoot3 * eps * S;  // how far d may move
  const double v2 = in.speed * in.speed, g = in.gravity.norm(), dn = d.norm();
  const double cross = d.cross(in.gravity).norm();
  const double dg = std::abs(d.dot(in.gravity));
  const double change = 4.01 * eps * v2 * v2 + 2 * v2 * (2.01 * eps * dg + dd * g + dn * kRoot3 * eps * g) +
                        2 * cross * (dd * g + dn * kRoot3 * eps * g) +
                        (dd * g + dn * kRoot3 * eps * g) * (dd * g + dn * kRoot3 * eps * g);
  const double D = oracle::launch_discriminant(in.from, in.target, in.speed, in.gravity);
  return std::abs(D) <= 2 * change || cross <= 4 * (dd * g + dn * kRoot3 * eps * g);
}

int expected_count(const LaunchCase& in) {
  if (in.speed == 0 || oracle::launch_vertical(in.from, in.target, in.gravity)) return 0;
  const int sign = oracle::launch_sign(in.from, in.target, in.speed, in.gravity);
  return sign > 0 ? 2 : (sign == 0 ? 1 : 0);
}

// A shot must have the speed, leave at its angle, and be at the target at its time.
void check_shot(Expect& e, const std::string& name, const LaunchCase& in, const Shot& s, double tol) {
  const Vec3 up = -in.gravity.normalized();
  e.that(name + ".velocity", std::abs(s.velocity.norm() - in.speed) <= kRelative * in.speed, fmt(s.velocity),
         "a velocity of length " + fmt(in.speed), "its length is " + fmt(s.velocity.norm()));
  e.that(name + ".angle", in.speed > 0 && std::abs(std::sin(s.angle) - s.velocity.dot(up) / in.speed) <= 1e-9,
         fmt(s.angle), "the elevation of the velocity",
         "sin(angle) does not match the velocity's upward part over the speed");
  e.that(name + ".time",
         s.time > 0 && oracle::trajectory_reaches(in.from, s.velocity, s.time, in.gravity, in.target, tol), fmt(s.time),
         "from + velocity t + g t^2 / 2 = target",
         "at t = " + fmt(s.time) + " the shot is at " +
             fmt(Vec3(in.from + s.velocity * s.time + 0.5 * s.time * s.time * in.gravity)) +
             ", not at the target (tolerance " + fmt(tol) + ")");
}

// The exact angles, and how far a relative perturbation of 1e-9 of the input moves them.
// Computed in long double (64-bit significands), each root in a form without
// cancellation: the high root adds sqrt(D) to v^2; the low root is the product of the
// roots, (g x^2 + 2 y v^2) / (g x^2), divided by the high one. Their errors, near 1e-19
// relative, are far below the tolerance.
//   To first order, with P(u) = g x u^2 - 2 v^2 u + g x + 2 y v^2 / x = 0 (the lecture's
//   quadratic times 2 v^2 / x) and P'(u) = 2 (g x u - v^2) = -+2 sqrt(D) at the roots:
//   |du| <= ((1 + u^2) |d(g x)| + 2 |u| |d(v^2)| + |d(2 y v^2 / x)|) / (2 sqrt(D)), and the
//   angle moves by du / (1 + u^2).
struct Angles {
  double low = 0, high = 0, low_tol = 0, high_tol = 0, fast = 0;  // fast: g x / v^2
};
Angles exact_angles(const LaunchCase& in, int count) {
  using Real = long double;
  const Vec3 d = in.target - in.from;
  const Real gx = in.gravity.x(), gy = in.gravity.y(), gz = in.gravity.z();
  const Real dx = d.x(), dy = d.y(), dz = d.z();
  const Real g = std::sqrt(gx * gx + gy * gy + gz * gz), v2 = Real(in.speed) * in.speed;
  const Real cx = dy * gz - dz * gy, cy = dz * gx - dx * gz, cz = dx * gy - dy * gx;
  const Real x = std::sqrt(cx * cx + cy * cy + cz * cz) / g, y = -(dx * gx + dy * gy + dz * gz) / g;
  const Real D = count == 1 ? 0 : std::max(Real(0), v2 * v2 - 2 * g * y * v2 - g * g * x * x), root = std::sqrt(D);
  const Real high = (v2 + root) / (g * x), low = (g * x * x + 2 * y * v2) / (x * (v2 + root));
  const Real eps = kRelative, S = std::max({largest(in.from), largest(in.target), 1e-300});
  const Real moved = 2 * kRoot3 * eps * S + kRoot3 * eps * std::sqrt(dx * dx + dy * dy + dz * dz);  // of x and y
  const Real d_gx = g * moved + kRoot3 * eps * g * x, d_v2 = 2 * eps * v2;
  const Real d_y_term = 2 * v2 * (moved / x + std::abs(y) * moved / (x * x) + 2 * eps * std::abs(y) / x);
  const auto tolerance = [&](Real u) {
    if (root == 0) return Real(1e-9) * std::abs(u);  // D = 0 exactly: one root, v^2 / (g x)
    return 2 * ((1 + u * u) * d_gx + 2 * std::abs(u) * d_v2 + d_y_term) / (2 * root) / (1 + u * u);
  };
  return {double(std::atan(low)), double(std::atan(high)), double(tolerance(low) + 1e-15),
          double(tolerance(high) + 1e-15), double(g * x / v2)};
}

void check_angles(Expect& e, const LaunchCase& in, const Aim& got, int count) {
  const Angles exact = exact_angles(in, count);
  const double low_off = std::abs(got.low.angle - exact.low), high_off = std::abs(got.high.angle - exact.high);
  const bool swapped = std::abs(got.low.angle - exact.high) <= exact.high_tol;
  std::string why = "low.angle must be the low root, atan((v^2 - sqrt(D)) / (g x)) = " + fmt(exact.low) +
                    ": yours is off by " + fmt(low_off) + " (tolerance " + fmt(exact.low_tol) + ")";
  if (swapped && count == 2)
    why += "; yours is the high root, the lobbed shot";
  else if (exact.fast < 1e-4)
    why += ". Here g x / v^2 = " + fmt(exact.fast) +
           ": v^2 - sqrt(D) cancels (subtracts two nearly equal numbers) and "
           "loses the low root's digits; take the product of the roots, (g x^2 + 2 y v^2) / (g x^2), divided by the "
           "high root";
  e.that("low.angle", low_off <= exact.low_tol, fmt(got.low.angle), fmt(exact.low), why);
  e.that("high.angle", high_off <= exact.high_tol, fmt(got.high.angle), fmt(exact.high),
         "high.angle must be the high root, atan((v^2 + sqrt(D)) / (g x)) = " + fmt(exact.high) + ": yours is off by " +
             fmt(high_off) + " (tolerance " + fmt(exact.high_tol) + ")" +
             (count == 1 ? "; with D = 0 there is one angle and high = low" : ""));
}

}  // namespace

Outcome aim(const LaunchCase& in, const Aim& got, Rules rules) {
  const int expected = expected_count(in);
  const bool doubt = rules == Rules::random && launch_in_doubt(in);
  if (got.count != expected) {
    if (doubt) return ambiguous();
    return fail("count = " + std::to_string(expected), "count = " + std::to_string(got.count),
                expected == 0 ? "the target is out of reach (D < 0), or straight above or below"
                              : (expected == 1 ? "D = 0 exactly: the target is just in reach, by one angle"
                                               : "D > 0: two angles reach the target"));
  }
  const Vec3 d = in.target - in.from;
  const double g = in.gravity.norm();
  Expect e(
      "tan(angle) = (v^2 +- sqrt(D)) / (g x) with D = v^4 + 2 v^2 (d . g) - |d x g|^2; each angle's velocity and "
      "flight time follow from it");
  const bool vertical = in.speed == 0 || oracle::launch_vertical(in.from, in.target, in.gravity);
  const double radicand = oracle::launch_radicand(in.from, in.target, in.speed, in.gravity);
  if (!std::isfinite(got.radicand) || !std::isfinite(got.low.angle) || !std::isfinite(got.high.angle) ||
      !finite(got.low.velocity) || !finite(got.high.velocity) || !std::isfinite(got.low.time) ||
      !std::isfinite(got.high.time))
    return fail("finite numbers",
                "radicand " + fmt(got.radicand) + ", angles " + fmt(got.low.angle) + ", " + fmt(got.high.angle),
                "an aim's radicand, angles, velocities and times must be finite numbers");
  if (vertical) {
    e.equal("radicand", got.radicand, 0.0);
  } else {
    const double x2 = d.cross(in.gravity).squaredNorm() / (g * g), y = -d.dot(in.gravity) / g;
    const double A = g * x2 / (2 * in.speed * in.speed);
    e.near("radicand", got.radicand, radicand, kRelative * (x2 + 4 * A * (A + std::abs(y))));
  }
  if (expected >= 1 && g > 0) {
    const double S = std::max({largest(in.from), largest(in.target), in.speed * in.speed / g});
    const double tol = kRelative * S;
    check_shot(e, "low", in, got.low, tol);
    check_shot(e, "high", in, got.high, tol);
    e.that("order", got.low.angle <= got.high.angle + 1e-12, fmt(got.low.angle) + " <= " + fmt(got.high.angle),
           "low.angle <= high.angle", "the low shot must have the lower angle");
    check_angles(e, in, got, expected);
  }
  const Outcome o = e.outcome();
  if (o.verdict == Outcome::Verdict::fail) return doubt && expected == 1 ? ambiguous() : o;
  return doubt ? ambiguous() : pass();
}

}  // namespace labkit::lab07::judge
