# Lab 02's classic mistakes (handouts/02_segment_triangle.md); each must fail its step,
# and the why of its first failure must name the concept (SAYS).

labkit_mutant(02 segment_triangle NAME crossing_t_sign STEP 1 SAYS "d_a / (d_a - d_b)" "denominator"
  FIND "c.t = d_a / (d_a - d_b);"
  REPLACE "c.t = d_a / (d_b - d_a);")

labkit_mutant(02 segment_triangle NAME distance_not_normalized STEP 1 SAYS "distance" "unit"
  FIND "c.d_a = scale.out(d_a);\n  c.d_b = scale.out(d_b);"
  REPLACE "c.d_a = (segment.a - triangle.v0).dot(triangle.normal());\n  c.d_b = (segment.b - triangle.v0).dot(triangle.normal());")

labkit_mutant(02 segment_triangle NAME strict_edge_test STEP 2 SAYS "closed"
  FIND "if ((x - from).dot(n.cross(to - from)) < 0) return false;"
  REPLACE "if ((x - from).dot(n.cross(to - from)) <= 0) return false;")

labkit_mutant(02 segment_triangle NAME beta_sign STEP 3 SAYS "beta" "sign"
  FIND "b.beta = (p - b.alpha * e1).dot(e2) / e2.squaredNorm();"
  REPLACE "b.beta = cross(p, e1) / cross(e1, e2);")

labkit_mutant(02 segment_triangle NAME fuzzy_zero_area STEP 4 SAYS "zero area"
  FIND "if (n == Vec3::Zero()) return {};"
  REPLACE "if (input_tri.normal().isZero()) return {};")

labkit_mutant(02 segment_triangle NAME magic_epsilon STEP 4 SAYS "same side"
  FIND "if ((d_a > 0 && d_b > 0) || (d_a < 0 && d_b < 0)) return {};"
  REPLACE "if ((d_a > 1e-9 && d_b > 1e-9) || (d_a < -1e-9 && d_b < -1e-9)) return {};")

labkit_mutant(02 segment_triangle NAME normal_toward_a STEP 4 SAYS "as wound"
  FIND "h.normal = d.n.normalized();"
  REPLACE "h.normal = d.n.normalized(); if ((s.a - tri.v0).dot(h.normal) < 0) h.normal = -h.normal;")

# Step 4: each volume V_i taken as the weight of v_i, the start of its edge; it weighs the
# vertex facing that edge (V_1 weighs v0, V_2 v1, V_0 v2): the weights turn one place.
labkit_mutant(02 segment_triangle NAME weights_on_wrong_vertices STEP 4 SAYS "weights of v0, v1, v2" "another order"
  FIND "Vec3(Vec3(v1, v2, v0) / sum)"
  REPLACE "Vec3(Vec3(v0, v1, v2) / sum)")

labkit_mutant(02 segment_triangle NAME first_found_not_nearest STEP 5 SAYS "smallest t"
  FIND "if (!d.hit || (best.hit && d.t >= best.t)) continue;"
  REPLACE "if (!d.hit || best.hit) continue;")

labkit_mutant(02 segment_triangle NAME hits_unsorted STEP 5 SAYS "sorted by t"
  FIND "return x.t != y.t ? x.t < y.t : x.triangle < y.triangle;"
  REPLACE "return x.triangle < y.triangle;")

labkit_mutant(02 segment_triangle NAME all_hits_drops_equal_t STEP 5 SAYS "missing" "same t"
  FIND "  return hits;\n}"
  REPLACE "  hits.erase(std::unique(hits.begin(), hits.end(), [](const MeshHit& x, const MeshHit& y) { return x.t == y.t; }), hits.end());\n  return hits;\n}")

labkit_mutant(02 segment_triangle NAME moving_one_frame STEP 6 SAYS "m1^-1 b"
  FIND "const Segment local{m0.inverse() * segment.a, m1.inverse() * segment.b};"
  REPLACE "const Segment local{m0.inverse() * segment.a, m0.inverse() * segment.b};")

# Step 6: the normal carried to the world like a point, by m1's rotation and translation:
# a normal is a direction, turned by the rotation only.
labkit_mutant(02 segment_triangle NAME normal_moved_like_a_point STEP 6 SAYS "rotation only" "no translation"
  FIND "hit.normal = m1.linear() * hit.normal;"
  REPLACE "hit.normal = m1 * hit.normal;")

labkit_mutant(02 segment_triangle NAME vertex_face_only STEP 7 SAYS "edge-edge"
  FIND "for (const auto& [i, j] : a.edges()) {"
  REPLACE "for (const auto& [i, j] : std::vector<std::array<int, 2>>{}) {")

labkit_mutant(02 segment_triangle NAME one_delta_matrix STEP 7 SAYS "vertex" "of B" "other delta matrix"
  FIND "for (const Vec3& q : b.vertices)"
  REPLACE "for (const Vec3& q : std::vector<Vec3>{})")

labkit_mutant(02 segment_triangle NAME absolute_motion STEP 7 SAYS "relative motion"
  FIND "const Vec3 d = velocity_a - velocity_b;"
  REPLACE "const Vec3 d = velocity_a;")

labkit_mutant(02 segment_triangle NAME last_contact STEP 7 SAYS "first contact"
  FIND "if (best.hit && t >= best.t) return;"
  REPLACE "if (best.hit && t <= best.t) return;")

# The normal left as the cross product happens to point: half the time from A toward B,
# so a response would push the meshes into each other.
labkit_mutant(02 segment_triangle NAME contact_normal_unturned STEP 7 SAYS "from B toward A" "d . normal <= 0"
  FIND "return unit.dot(d) > 0 ? Vec3(-unit) : unit;"
  REPLACE "return unit;")

# The classic shortcut: two edges' contact normal taken as the motion's direction. Only
# e x f is normal to both edges; the motion crosses them at any angle.
labkit_mutant(02 segment_triangle NAME edge_contact_normal_along_motion STEP 7 SAYS "(e x f) / |e x f|"
  FIND "const Vec3 normal = edge_pair_normal(p1 - p0, edge.b - edge.a, d);"
  REPLACE "const Vec3 normal = -d.normalized();")

labkit_mutant(02 segment_triangle NAME crossing_point_edge_tests STEP 8 SAYS "boundary"
  FIND "const double side = d_a > d_b ? 1.0 : -1.0;"
  REPLACE "if (!point_in_triangle_edges(s.point(d_a / (d_a - d_b)), tri)) return {}; const double side = 0;")

labkit_mutant(02 segment_triangle NAME coplanar_is_a_miss STEP 8 SAYS "in the plane"
  FIND "if (d_a == 0 && d_b == 0) return decide_coplanar(s, tri, n);"
  REPLACE "if (d_a == 0 && d_b == 0) return {};")

# Step 9: the frame taken as half-open, [0, 1): a contact exactly at its end is dropped,
# as if the next frame would see it (it starts with the meshes touching, which no
# frame then reports).
labkit_mutant(02 segment_triangle NAME frame_end_excluded STEP 9 SAYS "first touch" "t = 1"
  FIND "if (best.hit && t >= best.t) return;"
  REPLACE "if (t >= 1 || (best.hit && t >= best.t)) return;")
