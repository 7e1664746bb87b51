# Lab 02's classic mistakes (handouts/02_segment_triangle.md); each must fail its step.

labkit_mutant(02 segment_triangle NAME crossing_t_sign STEP 1
  FIND "c.t = c.d_a / (c.d_a - c.d_b);"
  REPLACE "c.t = c.d_a / (c.d_b - c.d_a);")

labkit_mutant(02 segment_triangle NAME strict_edge_test STEP 2
  FIND "if ((x - from).dot(n.cross(to - from)) < 0) return false;  // strictly outside edge i"
  REPLACE "if ((x - from).dot(n.cross(to - from)) <= 0) return false;")

labkit_mutant(02 segment_triangle NAME beta_sign STEP 3
  FIND "b.beta = cross(e1, p) / denominator;"
  REPLACE "b.beta = cross(p, e1) / denominator;")

labkit_mutant(02 segment_triangle NAME fuzzy_zero_area STEP 4
  FIND "if (n == Vec3::Zero()) return {};  // zero area: no plane, never hit"
  REPLACE "if (n.isZero()) return {};")

labkit_mutant(02 segment_triangle NAME magic_epsilon STEP 4
  FIND "if ((d_a > 0 && d_b > 0) || (d_a < 0 && d_b < 0)) return {};  // both ends strictly on one side"
  REPLACE "if ((d_a > 1e-9 && d_b > 1e-9) || (d_a < -1e-9 && d_b < -1e-9)) return {};")

labkit_mutant(02 segment_triangle NAME first_found_not_nearest STEP 5
  FIND "if (!d.hit || (best.hit && d.t >= best.t)) continue;  // a miss, or not nearer"
  REPLACE "if (!d.hit || best.hit) continue;")

labkit_mutant(02 segment_triangle NAME hits_unsorted STEP 5
  FIND "return x.t != y.t ? x.t < y.t : x.triangle < y.triangle;"
  REPLACE "return x.triangle < y.triangle;")

labkit_mutant(02 segment_triangle NAME moving_one_frame STEP 6
  FIND "const Segment local{m0.inverse() * segment.a, m1.inverse() * segment.b};"
  REPLACE "const Segment local{m0.inverse() * segment.a, m0.inverse() * segment.b};")

labkit_mutant(02 segment_triangle NAME crossing_point_edge_tests STEP 7
  FIND "const double side = d_a > d_b ? 1.0 : -1.0;"
  REPLACE "if (!point_in_triangle_edges(s.point(d_a / (d_a - d_b)), tri)) return {}; const double side = 0;")

labkit_mutant(02 segment_triangle NAME coplanar_is_a_miss STEP 7
  FIND "if (d_a == 0 && d_b == 0) return decide_coplanar(s, tri, n);"
  REPLACE "if (d_a == 0 && d_b == 0) return {};")
