// Lab 04 scene, the exact answers: overlap and distance at a time by exact predicates, and
// the first contact found with them alone, which the student's searches are shown beside.
#include "viewer/scenes/04_bisection.h"

#include <cmath>

namespace viewer::bisection {

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

}  // namespace viewer::bisection
