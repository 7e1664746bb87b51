# Lab 05's classic mistakes (handouts/05_sphere_sweeps.md); each must fail its step.

# Step 1: clamping the lines' closest pair into [0, 1]^2 instead of re-projecting an end.
labkit_mutant(05 sphere_sweeps NAME clamp_not_reproject STEP 1
  FIND "const double s = w.cross(d1).dot(n) / nn, t = w.cross(d0).dot(n) / nn;\n    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {"
  REPLACE "const double s = std::clamp(w.cross(d1).dot(n) / nn, 0.0, 1.0), t = std::clamp(w.cross(d0).dot(n) / nn, 0.0, 1.0);\n    {")

# Step 1: the textbook denominator a c - b^2, which cancels for nearly parallel segments.
# NOT YET CAUGHT: the segment generators have nearly parallel pairs only with a large
# offset, where the border candidates are as good; it needs a family of segments that
# cross at a tiny angle (2^-22 to 2^-36). Enable once that family is in.
# labkit_mutant(05 sphere_sweeps NAME textbook_denominator STEP 1
#   FIND "const double nn = n.squaredNorm();\n  if (nn > 0) {"
#   REPLACE "const double nn = d0.squaredNorm() * d1.squaredNorm() - square(d0.dot(d1));\n  if (nn > 0) {")

# Step 2: projecting onto the plane and forgetting to clamp to the rectangle.
labkit_mutant(05 sphere_sweeps NAME no_clamp_to_rectangle STEP 2
  FIND "r.s = std::clamp(w.dot(rectangle.u), -rectangle.half_u, rectangle.half_u);"
  REPLACE "r.s = w.dot(rectangle.u);")

# Step 2: segment-rectangle from the ends alone, forgetting the four sides.
labkit_mutant(05 sphere_sweeps NAME ends_only STEP 2
  FIND "for (int i = 0; i < 4; ++i) {\n    const SegmentSegmentDistance e = segment_segment(segment, side(rectangle, i));"
  REPLACE "for (int i = 0; i < 0; ++i) {\n    const SegmentSegmentDistance e = segment_segment(segment, side(rectangle, i));")

# Step 3: r0^2 + r1^2 instead of (r0 + r1)^2.
labkit_mutant(05 sphere_sweeps NAME sum_of_squares STEP 3
  FIND "return segment_segment_within(a.axis, b.axis, square(a.radius + b.radius));"
  REPLACE "return segment_segment_within(a.axis, b.axis, square(a.radius) + square(b.radius));")

# Step 3: two lozenges by the sides of the first one only.
labkit_mutant(05 sphere_sweeps NAME one_lozenges_sides STEP 3
  FIND "for (int i = 0; i < 4; ++i)\n    if (segment_rectangle_within(side(b.rectangle, i), a.rectangle, r2)) return true;"
  REPLACE "")

# Step 4: a plane whose normal is not unit length, used as if it were.
labkit_mutant(05 sphere_sweeps NAME unnormalised_normal STEP 4
  FIND "if (square(f0) <= square(r) * nn) return overlapping();  // touching or cutting it now\n  const PlaneApproach a = approach_plane(f0, g, r * std::sqrt(nn), square(r) * nn, duration);"
  REPLACE "if (std::abs(f0) <= r) return overlapping();\n  const PlaneApproach a = approach_plane(f0, g, r, square(r), duration);")

# Step 4: a one-sided plane: only the front side is ever approached.
labkit_mutant(05 sphere_sweeps NAME one_sided_plane STEP 4
  FIND "a.side = f0 > 0 ? 1.0 : -1.0;"
  REPLACE "a.side = 1.0;")

# Step 5: the textbook root (-b - sqrt(b^2 - ac)) / a, which cancels when contact is soon.
labkit_mutant(05 sphere_sweeps NAME cancelling_root STEP 5
  FIND "const double t = std::min(c / q, duration);"
  REPLACE "const double t = std::min((-b - std::sqrt(disc)) / a, duration); (void)q;")

# Step 5: forgetting that spheres moving apart never meet (a negative root is reported).
labkit_mutant(05 sphere_sweeps NAME moving_apart_forgotten STEP 5
  FIND "if (b >= 0) return {};  // moving apart or sideways: the gap only grows"
  REPLACE "")

# Step 5: an exact graze (b^2 = ac) dismissed as a miss.
labkit_mutant(05 sphere_sweeps NAME graze_is_a_miss STEP 5
  FIND "if (disc < 0) return {};  // the closest approach misses"
  REPLACE "if (disc <= 0) return {};")

# Step 6: the projected radius without absolute values.
labkit_mutant(05 sphere_sweeps NAME signed_projection STEP 6
  FIND "reach += box.half_extents[i] * std::abs(plane.normal.dot(box.axes.col(i)));"
  REPLACE "reach += box.half_extents[i] * plane.normal.dot(box.axes.col(i));")

# Step 7: deciding on the constructed (rounded) distance instead of division-free products.
labkit_mutant(05 sphere_sweeps NAME decide_on_rounded_distance STEP 7
  FIND "return segment_segment_within(a.axis, b.axis, square(a.radius + b.radius));"
  REPLACE "return segment_segment(a.axis, b.axis).squared_distance <= square(a.radius + b.radius);")

# Step 7: touching at t = 0 not counted as overlapping (a strict comparison).
labkit_mutant(05 sphere_sweeps NAME touching_not_overlapping STEP 7
  FIND "if (c <= 0) return overlapping();  // touching or overlapping at t = 0"
  REPLACE "if (c < 0) return overlapping();")
