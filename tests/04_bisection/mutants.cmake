# Lab 04's classic mistakes (handouts/04_bisection.md); each must fail first in its step,
# and that first failure's why must say the SAYS words (the concept it breaks).

labkit_mutant(04 bisection NAME touching_is_clear STEP 1 SAYS "touching counts"
  FIND "return (a.center - b.center).squaredNorm() <= reach * reach;"
  REPLACE "return (a.center - b.center).squaredNorm() < reach * reach;")

labkit_mutant(04 bisection NAME clamp_in_world_axes STEP 1 SAYS "own axes"
  FIND "const double excess = std::abs(d.dot(box.axes.col(k))) - box.half_extents[k];"
  REPLACE "const double excess = std::abs(d[k]) - box.half_extents[k];")

labkit_mutant(04 bisection NAME axes_not_turned STEP 1 SAYS "axes" "rotation"
  FIND "return {pose * box.center, pose.linear() * box.axes, box.half_extents};"
  REPLACE "return {pose * box.center, box.axes, box.half_extents};")

# The header's closed sets: a strict < misses a touch (handout step 5; step 1's examples
# already touch a face).
labkit_mutant(04 bisection NAME touching_a_box_is_clear STEP 1 SAYS "touching counts"
  FIND "return squared_distance(b, a.center) <= a.radius * a.radius;"
  REPLACE "return squared_distance(b, a.center) < a.radius * a.radius;")

# A fuzzy 1e-9 (handout step 5): a near miss at the scale 1e-6 counts as a contact.
labkit_mutant(04 bisection NAME magic_epsilon STEP 1 SAYS "epsilon" "clear"
  FIND "return squared_distance(b, a.center) <= a.radius * a.radius;"
  REPLACE "return squared_distance(b, a.center) <= a.radius * a.radius + 1e-9;")

# Step 1: the closest point clamped in the box's own axes and left there: its local
# coordinates returned, never taken back to the world (centre + sum of s_k axis_k).
labkit_mutant(04 bisection NAME closest_point_left_local STEP 1 SAYS "taken back to the world"
  FIND "q += std::clamp(d.dot(box.axes.col(k)), -h, h) * box.axes.col(k);"
  REPLACE "q[k] = std::clamp(d.dot(box.axes.col(k)), -h, h);")

labkit_mutant(04 bisection NAME returns_the_overlapping_end STEP 2 SAYS "last clear time" "overlapping end"
  FIND "  r.t = lo;
  r.t_contact = hi;"
  REPLACE "  r.t = hi;
  r.t_contact = hi;")

labkit_mutant(04 bisection NAME keeps_the_wrong_half STEP 2 SAYS "half whose ends differ"
  FIND "if (overlap_at(pair, mid))
      hi = mid;"
  REPLACE "if (!overlap_at(pair, mid)) hi = mid;")

labkit_mutant(04 bisection NAME one_halving_too_many STEP 2 SAYS "one halving too many" "hi - lo > tolerance"
  FIND "while (hi - lo > tolerance) {"
  REPLACE "while (hi - lo >= tolerance) {")

labkit_mutant(04 bisection NAME start_assumed_clear STEP 2 SAYS "already overlap at t0"
  FIND "  if (overlap_at(pair, t0)) return overlapping_at_start(t0);
  if (!overlap_at(pair, t1))"
  REPLACE "  if (!overlap_at(pair, t1))")

# Halving until the bracket has no length left: two neighbouring doubles have no
# midpoint between them, and the loop never ends (the time-out names the bound).
labkit_mutant(04 bisection NAME halves_to_zero STEP 2 SAYS "log2" "tolerance"
  FIND "while (hi - lo > tolerance) {"
  REPLACE "while (hi - lo > 0) {")

# Step 3: a sphere's smallest size taken as its radius: a sphere is as thin as its diameter.
labkit_mutant(04 bisection NAME sphere_size_is_radius STEP 3 SAYS "diameter" "1/2 of the answer"
  FIND "if (shape.kind == Shape::Kind::sphere) return 2 * shape.sphere.radius;"
  REPLACE "if (shape.kind == Shape::Kind::sphere) return shape.sphere.radius;")

labkit_mutant(04 bisection NAME substeps_not_strict STEP 3 SAYS "strict"
  FIND "return int(std::floor(ratio)) + 1;"
  REPLACE "return std::max(1, int(std::ceil(ratio)));")

# The lecture's "speed of the fastest object" taken literally for two moving bodies.
labkit_mutant(04 bisection NAME closing_speed_of_the_fastest STEP 3 SAYS "relative speed" "sum"
  FIND "return speed_a + speed_b;"
  REPLACE "return std::max(speed_a, speed_b);")

# Step 3: a box's reach taken as its bounding sphere's radius |h| about its own centre: the
# header's reach is from the body's origin, |c| + |h|, and a box set off its origin orbits.
labkit_mutant(04 bisection NAME box_reach_from_its_centre STEP 3 SAYS "each over its reach"
  FIND "const double reach_b = b.kind == Shape::Kind::sphere ? reach(b.sphere) : reach(b.box);"
  REPLACE "const double reach_b = b.kind == Shape::Kind::sphere ? reach(b.sphere) : b.box.half_extents.norm();")

labkit_mutant(04 bisection NAME bisects_from_the_start STEP 3 SAYS "first overlapping sub-step"
  FIND "TimeOfImpact r = halve(pair, previous, tk, tolerance);"
  REPLACE "TimeOfImpact r = halve(pair, t0, tk, tolerance);")

labkit_mutant(04 bisection NAME samples_the_end_only STEP 3 SAYS "every sample"
  FIND "for (int k = 1; k <= substeps; ++k) {"
  REPLACE "for (int k = substeps; k <= substeps; ++k) {")

labkit_mutant(04 bisection NAME distance_between_centres STEP 4 SAYS "centres" "radii"
  FIND "return std::sqrt(d2) - reach;"
  REPLACE "return std::sqrt(d2);")

labkit_mutant(04 bisection NAME advance_by_the_distance STEP 4 SAYS "d / v" "time"
  FIND "? d / max_closing_speed :"
  REPLACE "? d :")

labkit_mutant(04 bisection NAME advance_without_bisecting STEP 4 SAYS "bisection" "tolerance"
  FIND "      TimeOfImpact r = halve(pair, t, next, tolerance);"
  REPLACE "      TimeOfImpact r;
      r.hit = true;
      r.t = t;
      r.t_contact = next;")

# Without the floor of one tolerance a near miss creeps forward forever (handout step 4).
labkit_mutant(04 bisection NAME advance_without_the_floor STEP 4 SAYS "at least one tolerance"
  FIND "std::min(t + std::max(safe, tolerance), t1);"
  REPLACE "std::min(t + safe, t1);")
