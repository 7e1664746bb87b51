# Lab 03's classic mistakes (handouts/03_separating_axes.md); each must fail first in its
# step, with a first failure whose why line holds its SAYS words (the concept).

labkit_mutant(03 separating_axes NAME radius_without_abs STEP 1 SAYS "absolute value"
  FIND "p.radius += box.half_extents[k] * std::abs(box.axes.col(k).dot(axis));"
  REPLACE "p.radius += box.half_extents[k] * box.axes.col(k).dot(axis);")

labkit_mutant(03 separating_axes NAME touching_intervals_separate STEP 1 SAYS "touching" "strict"
  FIND "return std::abs(s) > r;"
  REPLACE "return std::abs(s) >= r;")

labkit_mutant(03 separating_axes NAME edge_axis_normalized STEP 2 SAYS "not normalised"
  FIND "return a.axes.col(i).cross(b.axes.col(j));"
  REPLACE "return a.axes.col(i).cross(b.axes.col(j)).normalized();")

labkit_mutant(03 separating_axes NAME textbook_radius STEP 2 SAYS "nearly parallel"
  FIND "b[m] * std::abs(C(i, n)) + b[n] * std::abs(C(i, m))"
  REPLACE "b[m] * std::abs(R(i, n)) + b[n] * std::abs(R(i, m))")

labkit_mutant(03 separating_axes NAME epsilon_guard STEP 2 SAYS "separating axis" "epsilon"
  FIND "x.r = a[i] + b[0] * std::abs(R(i, 0)) + b[1] * std::abs(R(i, 1)) + b[2] * std::abs(R(i, 2));"
  REPLACE "x.r = a[i] + b[0] * (std::abs(R(i, 0)) + 1e-6) + b[1] * (std::abs(R(i, 1)) + 1e-6) + b[2] * (std::abs(R(i, 2)) + 1e-6);")

labkit_mutant(03 separating_axes NAME face_axes_only STEP 2 SAYS "separating axis" "edge axes"
  FIND "  p.cofactors();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (separates(p.edge_axis(i, j))) return false;"
  REPLACE "")

# Step 2: B's face axis read as a row of its rotation matrix: its axes are the columns.
labkit_mutant(03 separating_axes NAME b_axis_from_a_row STEP 2 SAYS "B's column"
  FIND "if (index < 6) return b.axes.col(index - 3);"
  REPLACE "if (index < 6) return b.axes.row(index - 3).transpose();")

# Step 2: the centres' offset c_B - c_A left in world coordinates while R and the radii are
# in A's frame: it must be expressed in A's frame too, t = A^T (c_B - c_A).
labkit_mutant(03 separating_axes NAME offset_not_in_a_frame STEP 2 SAYS "projections" "A's frame"
  FIND "t(box_a.axes.transpose() * (box_b.center - box_a.center)),"
  REPLACE "t(box_b.center - box_a.center),")

labkit_mutant(03 separating_axes NAME depth_not_normalized STEP 3 SAYS "unit axis" "divide by |L|"
  FIND "c.depth = (x.r - std::abs(x.s)) / length;"
  REPLACE "c.depth = x.r - std::abs(x.s);")

labkit_mutant(03 separating_axes NAME axis_not_toward_b STEP 3 SAYS "from A toward B"
  FIND "if (x.s < 0) c.axis = -c.axis;"
  REPLACE "")

labkit_mutant(03 separating_axes NAME deepest_axis STEP 3 SAYS "least penetration"
  FIND "if (contact.axis_index < 0 || depth < least) {"
  REPLACE "if (contact.axis_index < 0 || depth > least) {")

# The lecture's interval method (triangles_by_intervals).
labkit_mutant(03 separating_axes NAME intervals_not_sorted STEP 4 SAYS "sort" "low <= high"
  FIND "return {std::min(end_q, end_r), std::max(end_q, end_r)};"
  REPLACE "return {end_q, end_r};")

labkit_mutant(03 separating_axes NAME ratio_from_wrong_vertex STEP 4 SAYS "alone on its side"
  FIND "((d[0] > 0) == (d[2] > 0) ? 1 : 0)"
  REPLACE "((d[0] > 0) == (d[2] > 0) ? 0 : 1)")

labkit_mutant(03 separating_axes NAME line_on_smallest_coordinate STEP 4 SAYS "largest"
  FIND "out.axis = m.x() >= m.y() && m.x() >= m.z() ? 0 : (m.y() >= m.z() ? 1 : 2);"
  REPLACE "out.axis = m.x() <= m.y() && m.x() <= m.z() ? 0 : (m.y() <= m.z() ? 1 : 2);")

labkit_mutant(03 separating_axes NAME coplanar_is_a_miss STEP 4 SAYS "coplanar" "overlap in their plane"
  FIND "if (s1.coplanar || s0.coplanar) return coplanar_triangles_intersect(t0, t1);"
  REPLACE "if (s1.coplanar || s0.coplanar) return false;")

labkit_mutant(03 separating_axes NAME interval_ends_strict STEP 4 SAYS "touch"
  FIND "return orient(a.v0, a.v1, b.v0, b.v1) <= 0 && orient(a.v0, a.v2, b.v2, b.v0) <= 0;"
  REPLACE "return orient(a.v0, a.v1, b.v0, b.v1) < 0 && orient(a.v0, a.v2, b.v2, b.v0) < 0;")

labkit_mutant(03 separating_axes NAME coplanar_only_when_exactly_zero STEP 4 SAYS "coplanar up to rounding"
  FIND "const bool in_plane = std::abs(d) <= 4e-15 * (of[i] - plane.at).norm() * plane.edges;"
  REPLACE "const bool in_plane = d == 0;")

labkit_mutant(03 separating_axes NAME needle_normal_at_any_vertex STEP 4 SAYS "needle" "shortest edges"
  FIND "const Plane3 plane = plane_of(t);"
  REPLACE "const Plane3 plane{t.v0, t.normal(), (t.v1 - t.v0).norm() * (t.v2 - t.v0).norm()};")

labkit_mutant(03 separating_axes NAME enter_leave_not_swapped STEP 5 SAYS "entering time"
  FIND "if (x.ds < 0) std::swap(enter, leave);"
  REPLACE "")

# Step 5: the motion axes left out, W x A_i and W x B_j alike (both loops: EVERYWHERE).
labkit_mutant(03 separating_axes NAME no_motion_axes STEP 5 SAYS "W x A_i"
  FIND "    if (std::abs(s) > r) return false;"
  REPLACE "" EVERYWHERE)

labkit_mutant(03 separating_axes NAME an_instant_is_no_contact STEP 5 SAYS "single instant"
  FIND "if (first - last > first_error + last_error) return {};"
  REPLACE "return {};")

labkit_mutant(03 separating_axes NAME times_from_rounding_noise STEP 5 SAYS "rounding noise"
  FIND "if (std::abs(x.ds) * duration <= noise) {"
  REPLACE "if (x.ds == 0) {")

labkit_mutant(03 separating_axes NAME touching_boxes_separate STEP 2 SAYS "nearly parallel" "zero axis"
  FIND "bool separates(const AxisTest& x) { return std::abs(x.s) > x.r; }"
  REPLACE "bool separates(const AxisTest& x) { return std::abs(x.s) >= x.r; }")

# >= for >, with the usual guard that skips short axes (so that parallel edges, a zero
# axis, no longer give it away): only exactly touching boxes show it.
labkit_mutant(03 separating_axes NAME touching_faces_apart STEP 6 SAYS "only touch" "strict"
  FIND "bool separates(const AxisTest& x) { return std::abs(x.s) > x.r; }"
  REPLACE "bool separates(const AxisTest& x) { return x.length2 > 1e-20 && std::abs(x.s) >= x.r; }")

# Step 7: an axis along which B does not move tested with >= for >: boxes sliding along
# each other while touching come out apart for the whole frame.
labkit_mutant(03 separating_axes NAME sliding_contact_apart STEP 7 SAYS "does not move" "strictly"
  FIND "if (separates(x)) return {};"
  REPLACE "if (x.length2 > 0 && std::abs(x.s) >= x.r) return {};")
