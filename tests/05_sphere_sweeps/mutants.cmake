# Lab 05's classic mistakes (handouts/05_sphere_sweeps.md); each must fail first in its own
# step, and the why of its first failure must show the SAYS words (the concept).

# Step 1: clamping the lines' closest pair into [0, 1]^2 instead of re-projecting an end.
labkit_mutant(05 sphere_sweeps NAME clamp_not_reproject STEP 1 SAYS "re-projected" "nearer pair"
  FIND "const double s = w.cross(d1).dot(n) / nn, t = w.cross(d0).dot(n) / nn;\n    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {"
  REPLACE "const double s = std::clamp(w.cross(d1).dot(n) / nn, 0.0, 1.0), t = std::clamp(w.cross(d0).dot(n) / nn, 0.0, 1.0);\n    {\n      consider(s, t, point_at(first, s), point_at(second, t));\n      if (nn > 0) return best;")

# Step 1: the textbook denominator a c - b^2, which cancels for nearly parallel segments
# (caught by the family of segments crossing at an angle of 2^-20 to 2^-27).
labkit_mutant(05 sphere_sweeps NAME textbook_denominator STEP 1 SAYS "nearly parallel" "|d0 x d1|^2"
  FIND "const double nn = n.squaredNorm();\n  if (nn > 0) {"
  REPLACE "const double nn = d0.squaredNorm() * d1.squaredNorm() - square(d0.dot(d1));\n  if (nn > 0) {")

# Step 2: projecting onto the plane and forgetting to clamp to the rectangle.
labkit_mutant(05 sphere_sweeps NAME no_clamp_to_rectangle STEP 2 SAYS "clamp" "half-sizes"
  FIND "r.s = std::clamp(w.dot(rectangle.u), -rectangle.half_u, rectangle.half_u);"
  REPLACE "r.s = w.dot(rectangle.u);")

# Step 2: segment-rectangle from the ends alone, forgetting the four sides.
labkit_mutant(05 sphere_sweeps NAME ends_only STEP 2 SAYS "nearer pair" "four sides"
  FIND "for (int i = 0; i < 4; ++i) {\n    const SegmentSegmentDistance e = segment_segment(segment, side(rectangle, i));"
  REPLACE "for (int i = 0; i < 0; ++i) {\n    const SegmentSegmentDistance e = segment_segment(segment, side(rectangle, i));")

# Step 2: rectangle_rectangle asks segment_rectangle with B's side first (B against A) and
# keeps its points as they come: closest0 lands on the second rectangle, closest1 on the first.
labkit_mutant(05 sphere_sweeps NAME swapped_call_not_swapped_back STEP 2 SAYS "closest0" "swapped"
  FIND "if (e.squared_distance < best.squared_distance) best = {e.squared_distance, e.closest1, e.closest0};"
  REPLACE "if (e.squared_distance < best.squared_distance) best = {e.squared_distance, e.closest0, e.closest1};")

# Step 3: r0^2 + r1^2 instead of (r0 + r1)^2.
labkit_mutant(05 sphere_sweeps NAME sum_of_squares STEP 3 SAYS "(r0 + r1)^2"
  FIND "return segment_segment_within(a.axis, b.axis, square(a.radius + b.radius));"
  REPLACE "return segment_segment_within(a.axis, b.axis, square(a.radius) + square(b.radius));")

# Step 3: two lozenges by the sides of the first one only.
labkit_mutant(05 sphere_sweeps NAME one_lozenges_sides STEP 3 SAYS "the sides of both"
  FIND "for (int i = 0; i < 4; ++i)\n    if (segment_rectangle_within(side(b.rectangle, i), a.rectangle, r2)) return true;"
  REPLACE "")

# Step 3 (the step 8 recipe read alone): (w . n)^2 <= R^2 |n|^2 for lines that are parallel
# only up to rounding, where the rounded n says nothing about their distance.
labkit_mutant(05 sphere_sweeps NAME parallel_in_floating_point STEP 3 SAYS "nearly parallel" "measure the pair"
  FIND "  if (nn < 1e-10 * d0.squaredNorm() * d1.squaredNorm()) return point_segment_within(point_at(s0, s / nn), s1, r2);\n"
  REPLACE "")

# Step 4: a plane whose normal is not unit length, used as if it were.
labkit_mutant(05 sphere_sweeps NAME unnormalised_normal STEP 4 SAYS "is n unit"
  FIND "  const Plane plane = scaled(given);\n  const double f0 = plane.value(sphere.center), g = plane.normal.dot(velocity);\n  const double nn = plane.normal.squaredNorm(), r = sphere.radius;\n  if (square(f0) <= square(r) * nn) return overlapping();\n  const PlaneApproach a = approach_plane(f0, g, r * std::sqrt(nn), square(r) * nn, duration);"
  REPLACE "  const Plane plane = given;\n  const double f0 = plane.value(sphere.center), g = plane.normal.dot(velocity);\n  const double nn = plane.normal.squaredNorm(), r = sphere.radius;\n  if (std::abs(f0) <= r) return overlapping();\n  const PlaneApproach a = approach_plane(f0, g, r, square(r), duration);")

# Step 4: a one-sided plane: only the front side is ever approached.
labkit_mutant(05 sphere_sweeps NAME one_sided_plane STEP 4 SAYS "two-sided"
  FIND "a.side = f0 > 0 ? 1.0 : -1.0;"
  REPLACE "a.side = 1.0;")

# Step 4: the later root: the time the sphere leaves the plane on the far side.
labkit_mutant(05 sphere_sweeps NAME plane_later_root STEP 4 SAYS "later root"
  FIND "a.time = std::clamp((a.side * f0 - reach) / (-a.side * g), 0.0, duration);"
  REPLACE "a.time = std::clamp((a.side * f0 + reach) / (-a.side * g), 0.0, duration);")

# Step 4: the plane not offset by the radius: the time the centre reaches the plane itself,
# after the sphere has already cut into it.
labkit_mutant(05 sphere_sweeps NAME centre_reaches_plane STEP 4 SAYS "gap reaches 0" "centre itself reaches the plane"
  FIND "const PlaneApproach a = approach_plane(f0, g, r * std::sqrt(nn), square(r) * nn, duration);"
  REPLACE "const PlaneApproach a = approach_plane(f0, g, 0.0, 0.0, duration);")

# Step 5: the textbook root (-b - sqrt(b^2 - ac)) / a, which cancels when contact is soon.
labkit_mutant(05 sphere_sweeps NAME cancelling_root STEP 5 SAYS "cancel"
  FIND "const double t = std::min(c / q, duration);"
  REPLACE "const double t = std::min((-b - std::sqrt(disc)) / a, duration); (void)q;")

# Step 5: the later root q / a (when the spheres part again) for the first contact.
labkit_mutant(05 sphere_sweeps NAME sphere_later_root STEP 5 SAYS "later root"
  FIND "const double t = std::min(c / q, duration);"
  REPLACE "const double t = std::min(q / a, duration);")

# Step 5: forgetting that spheres moving apart never meet (a negative root is reported).
labkit_mutant(05 sphere_sweeps NAME moving_apart_forgotten STEP 5 SAYS "move apart"
  FIND "if (b >= 0) return {};"
  REPLACE "")

# Step 5: an exact graze (b^2 = ac) dismissed as a miss.
labkit_mutant(05 sphere_sweeps NAME graze_is_a_miss STEP 5 SAYS "graze"
  FIND "if (disc < 0) return {};"
  REPLACE "if (disc <= 0) return {};")

# Step 5: touching at t = 0 not counted as overlapping (a strict comparison).
labkit_mutant(05 sphere_sweeps NAME touching_not_overlapping STEP 5 SAYS "touching" "overlapping"
  FIND "if (c <= 0) return overlapping();"
  REPLACE "if (c < 0) return overlapping();")

# Step 6: the grown capsule without its caps: only the side's root (and the fallback).
labkit_mutant(05 sphere_sweeps NAME forgotten_caps STEP 6 SAYS "caps"
  FIND "                       first_time_sphere(sphere.center - axis.a, velocity, R2),\n                       first_time_sphere(sphere.center - axis.b, velocity, R2)});"
  REPLACE "                       kInfinity});")

# Step 6: the later root of the side (when the centre leaves the grown capsule).
labkit_mutant(05 sphere_sweeps NAME capsule_later_root STEP 6 SAYS "later root"
  FIND "  const double t = c / (-b + std::sqrt(dd) * std::sqrt(disc));"
  REPLACE "  const double t = (-b + std::sqrt(dd) * std::sqrt(disc)) / a;")

# Step 6: the infinite cylinder's root taken without clipping it to the slab.
labkit_mutant(05 sphere_sweeps NAME unclipped_cylinder STEP 6 SAYS "slab"
  FIND "return along >= 0 && along <= dd ? t : kInfinity;"
  REPLACE "(void)along;\n  return t;")

# Step 6: the capsule grown by its own radius only (the sphere's radius forgotten).
labkit_mutant(05 sphere_sweeps NAME grown_by_one_radius STEP 6 SAYS "Minkowski"
  FIND "const double R = sphere.radius + capsule.radius, R2 = square(R);"
  REPLACE "const double R = capsule.radius, R2 = square(R);")

# Step 7: the projected radius without absolute values.
labkit_mutant(05 sphere_sweeps NAME signed_projection STEP 7 SAYS "absolute value"
  FIND "reach += box.half_extents[i] * std::abs(plane.normal.dot(box.axes.col(i)));"
  REPLACE "reach += box.half_extents[i] * plane.normal.dot(box.axes.col(i));")

# Step 9: deciding on the constructed (rounded) distance instead of division-free products.
labkit_mutant(05 sphere_sweeps NAME decide_on_rounded_distance STEP 9 SAYS "exact products"
  FIND "return segment_segment_within(a.axis, b.axis, square(a.radius + b.radius));"
  REPLACE "return segment_segment(a.axis, b.axis).squared_distance <= square(a.radius + b.radius);")

# Step 7: a box's reach toward the plane taken as its bounding sphere's radius |h|: it
# meets the plane too early.
labkit_mutant(05 sphere_sweeps NAME box_bounding_sphere STEP 7 SAYS "bounding sphere"
  FIND "for (int i = 0; i < 3; ++i) reach += box.half_extents[i] * std::abs(plane.normal.dot(box.axes.col(i)));"
  REPLACE "reach = box.half_extents.norm() * plane.normal.norm();")
