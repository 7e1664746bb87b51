# Lab 04's classic mistakes (handouts/04_bisection.md); each must fail its step.

labkit_mutant(04 bisection NAME touching_is_clear STEP 1
  FIND "return (a.center - b.center).squaredNorm() <= reach * reach;"
  REPLACE "return (a.center - b.center).squaredNorm() < reach * reach;")

labkit_mutant(04 bisection NAME clamp_in_world_axes STEP 1
  FIND "const double excess = std::abs(d.dot(box.axes.col(k))) - box.half_extents[k];"
  REPLACE "const double excess = std::abs(d[k]) - box.half_extents[k];")

labkit_mutant(04 bisection NAME axes_not_turned STEP 1
  FIND "return {pose * box.center, pose.linear() * box.axes, box.half_extents};"
  REPLACE "return {pose * box.center, box.axes, box.half_extents};")

labkit_mutant(04 bisection NAME returns_the_overlapping_end STEP 2
  FIND "  r.t = lo;
  r.t_contact = hi;"
  REPLACE "  r.t = hi;
  r.t_contact = hi;")

labkit_mutant(04 bisection NAME keeps_the_wrong_half STEP 2
  FIND "if (overlap_at(pair, mid)) hi = mid;"
  REPLACE "if (!overlap_at(pair, mid)) hi = mid;")

labkit_mutant(04 bisection NAME one_halving_too_many STEP 2
  FIND "while (hi - lo > tolerance) {"
  REPLACE "while (hi - lo >= tolerance) {")

labkit_mutant(04 bisection NAME start_assumed_clear STEP 2
  FIND "  if (overlap_at(pair, t0)) return overlapping_at_start(t0);
  if (!overlap_at(pair, t1))"
  REPLACE "  if (!overlap_at(pair, t1))")

labkit_mutant(04 bisection NAME substeps_not_strict STEP 3
  FIND "return int(std::floor(ratio)) + 1;"
  REPLACE "return std::max(1, int(std::ceil(ratio)));")

labkit_mutant(04 bisection NAME bisects_from_the_start STEP 3
  FIND "TimeOfImpact r = halve(pair, previous, tk, tolerance);"
  REPLACE "TimeOfImpact r = halve(pair, t0, tk, tolerance);")

labkit_mutant(04 bisection NAME samples_the_end_only STEP 3
  FIND "for (int k = 1; k <= substeps; ++k) {"
  REPLACE "for (int k = substeps; k <= substeps; ++k) {")

labkit_mutant(04 bisection NAME advance_by_the_distance STEP 4
  FIND "? d / max_closing_speed :"
  REPLACE "? d :")

labkit_mutant(04 bisection NAME distance_between_centres STEP 4
  FIND "return std::sqrt(d2) - reach;"
  REPLACE "return std::sqrt(d2);")

labkit_mutant(04 bisection NAME advance_without_bisecting STEP 4
  FIND "      TimeOfImpact r = halve(pair, t, next, tolerance);"
  REPLACE "      TimeOfImpact r;
      r.hit = true;
      r.t = t;
      r.t_contact = next;")

labkit_mutant(04 bisection NAME touching_a_box_is_clear STEP 5
  FIND "bool overlap(const Sphere& a, const Box& b) { return squared_distance(b, a.center) <= a.radius * a.radius; }"
  REPLACE "bool overlap(const Sphere& a, const Box& b) { return squared_distance(b, a.center) < a.radius * a.radius; }")

labkit_mutant(04 bisection NAME magic_epsilon STEP 5
  FIND "bool overlap(const Sphere& a, const Box& b) { return squared_distance(b, a.center) <= a.radius * a.radius; }"
  REPLACE "bool overlap(const Sphere& a, const Box& b) { return squared_distance(b, a.center) <= a.radius * a.radius + 1e-9; }")
