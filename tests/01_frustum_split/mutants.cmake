# Lab 01's classic mistakes (handouts/01_frustum_split.md); each must fail first in its
# own step, and its first failure's why must name the concept (SAYS).

labkit_mutant(01 frustum_split NAME distance_not_normalized STEP 1 SAYS "divide by |n|"
  FIND "return plane.value(x) / plane.normal.norm();"
  REPLACE "return plane.value(x);")

labkit_mutant(01 frustum_split NAME magic_epsilon STEP 1 SAYS "exact sign" "magic epsilon"
  FIND "Side side_of(double value) { return value > 0 ? Side::in : (value < 0 ? Side::out : Side::on); }"
  REPLACE "Side side_of(double value) { return value > 1e-9 ? Side::in : (value < -1e-9 ? Side::out : Side::on); }")

labkit_mutant(01 frustum_split NAME strict_keep STEP 2 SAYS "closed" "value 0 is in"
  FIND "if (sides[i] != Side::out) next.add(p);"
  REPLACE "if (sides[i] == Side::in) next.add(p);")

labkit_mutant(01 frustum_split NAME cut_t_from_wrong_end STEP 2 SAYS "cut point" "measured from p"
  FIND "c.w[b] = d[std::size_t(m)][a];
    c.w[a] = -d[std::size_t(m)][b];"
  REPLACE "c.w[a] = d[std::size_t(m)][a];
    c.w[b] = -d[std::size_t(m)][b];")

labkit_mutant(01 frustum_split NAME winding_lost STEP 2 SAYS "wind like the input"
  FIND "out.push_back({first, previous, current});"
  REPLACE "out.push_back({first, current, previous});")

labkit_mutant(01 frustum_split NAME outward_normals STEP 3 SAYS "point into the frustum"
  FIND "const Vec3 n = normal.normalized();"
  REPLACE "const Vec3 n = -normal.normalized();")

labkit_mutant(01 frustum_split NAME full_angle_tangent STEP 3 SAYS "full angle" "fov_y / 2"
  FIND "const double ty = std::tan(camera.fov_y / 2);"
  REPLACE "const double ty = std::tan(camera.fov_y);")

labkit_mutant(01 frustum_split NAME columns_not_rows STEP 3 SAYS "rows"
  FIND "(view_projection.row(3) + sign * view_projection.row(row)).transpose()"
  REPLACE "view_projection.col(3) + sign * view_projection.col(row)")

labkit_mutant(01 frustum_split NAME matrix_planes_not_normalized STEP 3 SAYS "unit length"
  FIND "return Plane{c.head<3>() / length, c[3] / length};"
  REPLACE "return Plane{c.head<3>(), c[3]};")

# A step 2 written from the four configurations, and a polygon loop for step 4 that
# walks the sides i -> i + 1 only: the closing side is cut by the first plane alone.
labkit_mutant(01 frustum_split NAME closing_side_not_cut STEP 4 SAYS "closing side"
  FIND "const int j = (i + 1) % polygon.size;"
  REPLACE "const int j = k == 0 || i + 1 < polygon.size ? (i + 1) % polygon.size : i;")

labkit_mutant(01 frustum_split NAME side_planes_only STEP 4 SAYS "all six planes"
  FIND "return fan(clip_polygon(triangle, frustum.planes.data(), 6), triangle);"
  REPLACE "return fan(clip_polygon(triangle, frustum.planes.data(), 4), triangle);")

labkit_mutant(01 frustum_split NAME colour_from_wrong_vertices STEP 5 SAYS "same t" "same vertices"
  FIND "out.colors.push_back(
          blend(c, in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])], in.colors[std::size_t(face[2])]));"
  REPLACE "out.colors.push_back(blend(c, in.colors[std::size_t(face[1])], in.colors[std::size_t(face[2])],
                                 in.colors[std::size_t(face[0])]));")

# c_b + t (c_a - c_b): the colour's t measured from the other end of the edge.
labkit_mutant(01 frustum_split NAME colour_t_from_wrong_end STEP 5 SAYS "same t" "other end"
  FIND "out.colors.push_back(
          blend(c, in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])], in.colors[std::size_t(face[2])]));"
  REPLACE "Corner mirrored = c;
      if (c.edges) {
        const int a = c.edges & 1u ? 0 : (c.edges & 2u ? 1 : 2);
        std::swap(mirrored.w[a], mirrored.w[(a + 1) % 3]);
      }
      out.colors.push_back(blend(mirrored, in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])],
                                 in.colors[std::size_t(face[2])]));")

labkit_mutant(01 frustum_split NAME new_vertex_without_colour STEP 5 SAYS "every vertex needs a colour"
  FIND "out.colors.push_back(
          blend(c, in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])], in.colors[std::size_t(face[2])]));"
  REPLACE "")

labkit_mutant(01 frustum_split NAME classify_rounded_points STEP 6 SAYS "rounded cut point"
  FIND "sides[i] = side_of(polygon.corner[std::size_t(i)].w.dot(d[std::size_t(k)]));"
  REPLACE "sides[i] = side_of(plane.value(blend(polygon.corner[std::size_t(i)], t.v0, t.v1, t.v2)));")
