// What the files of lab 04's judge share (tests/04_bisection/judge*.cpp): a case posed at
// any time with its exact status (Scene), and the checks of a reported search that
// bisection, point sampling and conservative advancement all pass.
#pragma once

#include "04_bisection/judge.h"
#include "judging.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <string>

namespace labkit::lab04 {

double reach_of(const MovingBody& b);
// max_speed of one body over its reach, on [t0, t1].
double body_speed(const MovingBody& b, double t0, double t1);

namespace judge {

using judging::kRelative;  // the header's relative tolerance and ambiguity

std::string summary(const TimeOfImpact& r);

// Whether the bodies overlap at a time, exactly, and whether that answer is in doubt.
struct Status {
  bool overlap = false;
  bool doubt = false;
};

// One case, ready to pose at any time.
class Scene {
 public:
  Scene(const MovingPairCase& c, Rules rules)
      : case_(c), pair_(pair_of(c)), rules_(rules), delta_(judging::tolerance_of(c)) {}

  Status at(double t) const {
    const RigidTransform pa = pair_.motion_a(t), pb = pair_.motion_b(t);
    Status s;
    s.overlap = case_.b.is_box ? oracle::sphere_box_overlap(case_.a.sphere, pa, case_.b.box, pb)
                               : oracle::spheres_overlap(case_.a.sphere, pa, case_.b.sphere, pb);
    s.doubt = rules_ == Rules::random && std::abs(signed_gap(pa, pb)) <= margin(t);
    return s;
  }

  // Do the bodies overlap by at least `depth` (their signed gap <= -depth), exactly?
  // Shrinks the sphere by depth (rounded down); no claim when it is thinner than that.
  bool deep_at(double t, double depth) const {
    const RigidTransform pa = pair_.motion_a(t), pb = pair_.motion_b(t);
    const double reach = case_.a.sphere.radius + (case_.b.is_box ? 0.0 : case_.b.sphere.radius);
    const double shrunk = (reach - depth) * (1 - 4 * DBL_EPSILON);
    if (!(shrunk >= 0)) return false;
    const Sphere a{case_.a.sphere.center, shrunk};
    if (case_.b.is_box) return oracle::sphere_box_overlap(a, pa, case_.b.box, pb);
    return oracle::spheres_overlap(a, pa, Sphere{case_.b.sphere.center, 0.0}, pb);
  }

  double distance(double t) const {
    const RigidTransform pa = pair_.motion_a(t), pb = pair_.motion_b(t);
    return case_.b.is_box ? oracle::sphere_box_distance(case_.a.sphere, pa, case_.b.box, pb)
                          : oracle::spheres_distance(case_.a.sphere, pa, case_.b.sphere, pb);
  }

  // The signed gap in doubles (negative: how deep they overlap), and the margin by which
  // the input's perturbation could move it, at time t.
  double signed_gap(double t) const { return signed_gap(pair_.motion_a(t), pair_.motion_b(t)); }
  double margin(double t) const { return 2 * (move(case_.a, t) + move(case_.b, t)) + 1e-12 * scale_at(t); }

  // The header's S at time t: the largest absolute coordinate of the posed bodies.
  double scale_at(double t) const {
    const RigidTransform pa = pair_.motion_a(t), pb = pair_.motion_b(t);
    double s = std::max((pa * case_.a.sphere.center).cwiseAbs().maxCoeff(), case_.a.sphere.radius);
    if (case_.b.is_box)
      s = std::max(
          {s, (pb * case_.b.box.center).cwiseAbs().maxCoeff(), case_.b.box.half_extents.cwiseAbs().maxCoeff()});
    else
      s = std::max({s, (pb * case_.b.sphere.center).cwiseAbs().maxCoeff(), case_.b.sphere.radius});
    return s;
  }

  const MovingPair& pair() const { return pair_; }

 private:
  double signed_gap(const RigidTransform& pa, const RigidTransform& pb) const {
    const Vec3 q = pa * case_.a.sphere.center;
    const double r = case_.a.sphere.radius;
    if (!case_.b.is_box) return (q - pb * case_.b.sphere.center).norm() - r - case_.b.sphere.radius;
    const Box& b = case_.b.box;
    const Vec3 d = q - pb * b.center;
    const Mat3 axes = pb.linear() * b.axes;
    double outside = 0.0, inside = -INFINITY;
    for (int k = 0; k < 3; ++k) {
      const double excess = std::abs(d.dot(axes.col(k))) - b.half_extents[k];
      if (excess > 0) outside += excess * excess;
      inside = std::max(inside, excess);
    }
    return (outside > 0 ? std::sqrt(outside) : inside) - r;
  }

  // How far one body's points can move when every length of the input moves by
  // delta = 1e-9 S and every unit-free number (axis, spin, box axes, times) by 1e-9:
  //   its origin, start + velocity t + acceleration t^2/2:  sqrt(3) delta (1 + |t| + t^2/2)
  //   its turn: the angle moves by 1e-9 |t|, the unit axis by at most 2e-9, which moves
  //     a point at distance reach by at most reach 1e-9 (|t| + 4)
  //   its shape: centre sqrt(3) delta, radius delta or a corner sqrt(3) delta, a box's
  //     axes 3e-9 |h|
  //   the time itself (t0 and t1 move a sample time by 1e-9): its speed times 2e-9.
  // The gap between two convex bodies moves by at most what their points move, so the
  // margin is the sum for both bodies; doubled, and with room for the rounding of the
  // gap computed in doubles.
  double move(const MovingBody& b, double t) const {
    const double reach = reach_of(b), at = std::abs(t);
    const double shape = b.is_box ? 2 * std::sqrt(3.0) * delta_ + 3 * kRelative * b.box.half_extents.norm()
                                  : (std::sqrt(3.0) + 1) * delta_;
    return std::sqrt(3.0) * delta_ * (1 + at + 0.5 * t * t) + kRelative * reach * (at + 4) + shape +
           2 * kRelative * max_speed(motion_of(b.motion), reach, t, t);
  }

  MovingPairCase case_;
  MovingPair pair_;
  Rules rules_;
  double delta_;
};

using Check = std::optional<Outcome>;  // a failure, or nothing

// Overlap at t0: the answer must be overlapping_at_start exactly when the bodies overlap
// there. Returns the final verdict when the answer says overlapping_at_start.
Check start_rule(const Scene& sc, const TimeOfImpact& got, double t0, bool& doubt);
// A reported bracket [t, t_contact]: inside [lo, hi] (give or take rounding), no longer
// than the tolerance, clear at t and overlapping at t_contact, exactly.
Check certify(const Scene& sc, const TimeOfImpact& got, double lo, double hi, double tolerance, bool& doubt);
// The number of halvings that takes a bracket of length `width` to `tolerance` or less
// (one more or one fewer passes within rounding of the boundary, never on exact input).
Check halvings(const TimeOfImpact& got, double width, double lo, double hi, double tolerance, Rules rules,
               const std::string& cause = "");
Outcome settle(bool doubt);

}  // namespace judge
}  // namespace labkit::lab04
