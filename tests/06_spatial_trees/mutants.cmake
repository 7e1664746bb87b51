# Lab 06's classic mistakes (handouts/06_spatial_trees.md); each must fail its step first,
# and that failure's why must say the words after SAYS (the concept, not a field).

# Step 1: a triangle that only touches the split plane from above is sent above only,
# though it meets the closed cell below at the plane.
labkit_mutant(06 spatial_trees NAME touching_goes_one_side STEP 1 SAYS "closed cell" "both sides"
  FIND "if (box.min[axis] <= split.position) refs_[below_last++] = i;"
  REPLACE "if (box.min[axis] < split.position) refs_[below_last++] = i;")

# Step 2: first_hit stops in the first leaf that has any hit, even one beyond the leaf's
# far end (a later leaf may hold a nearer one).
labkit_mutant(06 spatial_trees NAME first_hit_stops_too_soon STEP 2 SAYS "smallest t" "not final"
  FIND "return best.hit ? best.t : kInfinity;"
  REPLACE "return best.hit ? -kInfinity : kInfinity;")

# Step 2: all_hits reports a triangle listed in two leaves twice.
labkit_mutant(06 spatial_trees NAME all_hits_twice STEP 2 SAYS "each triangle once"
  FIND "return x.triangle == y.triangle;"
  REPLACE "return false;")

# Step 2: the near child chosen by a strict comparison alone: a segment starting exactly
# on a split plane is sent to the side above, whatever way it goes.
labkit_mutant(06 spatial_trees NAME start_on_plane_wrong_side STEP 2 SAYS "near child" "side d goes to"
  FIND "(s.a[axis] == n.split && d[axis] <= 0)"
  REPLACE "false")

# Step 2: a segment lying in a split plane (d[axis] = 0, a on the plane) sent to the
# child above: the header sends it below. Step 9's exact walk catches it too.
labkit_mutant(06 spatial_trees NAME in_split_plane_goes_above STEP 2 SAYS "below"
  FIND "(s.a[axis] == n.split && d[axis] <= 0)"
  REPLACE "(s.a[axis] == n.split && d[axis] < 0)")

# Step 2: the walk read without its t_split <= 0 rule: a segment moving away from the
# plane is sent into the far cell behind a, which it never meets.
labkit_mutant(06 spatial_trees NAME far_child_behind_a STEP 2 SAYS "t_split" "far child"
  FIND "if (t_split > span.t1 || t_split <= 0) {"
  REPLACE "if (t_split > span.t1) {")

# Step 2: any_hit walks on after its first hit, testing every triangle the walk meets
# (and keeping the last hit), where it should stop at the first one.
labkit_mutant(06 spatial_trees NAME any_hit_walks_on STEP 2 SAYS "stops at its first hit"
  FIND "return -kInfinity;"
  REPLACE "continue;  // walks on after its first hit")

# Step 3: a point on a node's plane is sent in front, as if it were off the plane.
labkit_mutant(06 spatial_trees NAME on_plane_goes_front STEP 3 SAYS "side = 0" "both subtrees"
  FIND "if (side > 0) {"
  REPLACE "if (side >= 0) {")

# Step 4: the subtree on the eye's side drawn first: front to back, not back to front.
labkit_mutant(06 spatial_trees NAME near_subtree_first STEP 4 SAYS "far subtree"
  FIND "const int near = eye_in_front ? n.front : n.back, far = eye_in_front ? n.back : n.front;"
  REPLACE "const int near = eye_in_front ? n.back : n.front, far = eye_in_front ? n.front : n.back;")

# Step 5: `tests` counts the pairs found, not the pairs tested: the kit counts the calls
# of given_balls_meet itself, and the two disagree.
labkit_mutant(06 spatial_trees NAME tests_count_pairs_found STEP 5 SAYS "given_balls_meet"
  FIND "          if (given_balls_meet(sorted[m], sorted[other])) out.pairs.push_back({i, j});"
  REPLACE "          if (given_balls_meet(sorted[m], sorted[other])) out.pairs.push_back({i, j}); else --out.tests;")

# Step 5: the grid's cells one radius wide instead of one diameter: two balls that meet
# can sit two cells apart, outside each other's block, and their pair is lost.
labkit_mutant(06 spatial_trees NAME grid_cells_one_radius STEP 5 SAYS "missing" "largest diameter"
  FIND "double side = std::max(2 * r_max * (1 + 1e-6), extent.maxCoeff() / kMaxCells);"
  REPLACE "double side = std::max(r_max, extent.maxCoeff() / kMaxCells);")

# Step 6: the ends re-sorted from scratch every frame (the list rebuilt in sphere order):
# right pairs, but n log n or worse comparisons and swaps however little the spheres moved.
labkit_mutant(06 spatial_trees NAME sweep_resorted_each_frame STEP 6 SAYS "frame coherence"
  FIND "if (!started) {"
  REPLACE "if (true) {")

# Step 6: ends compared strictly: a low end arriving exactly at a high end's value does not
# pass it, so two balls that come to touch are never paired.
labkit_mutant(06 spatial_trees NAME sweep_ties_strict STEP 6 SAYS "touching counts"
  FIND "return c < 0 || (c == 0 && !a.high && b.high);"
  REPLACE "return c < 0;")

# Step 6: a pair is added when a low end passes a high end but never removed when the
# high end passes back: pairs apart on x stay in the set and are tested every frame.
labkit_mutant(06 spatial_trees NAME sweep_pairs_never_removed STEP 6 SAYS "overlap on x" "swap"
  FIND "if (gone) continue;"
  REPLACE "(void)gone;")

# Step 7: one tree descended only: a leaf of a is tested against b's node as it is, whose
# triangles lie in leaves below it, so pairs are lost.
labkit_mutant(06 spatial_trees NAME bvh_one_tree_only STEP 7 SAYS "both trees" "leaves"
  FIND "if (leaf_a && leaf_b) {"
  REPLACE "if (leaf_a) {")

# Step 7: the smaller box descended first: right pairs, more box tests than the header's
# traversal.
labkit_mutant(06 spatial_trees NAME bvh_descends_smaller STEP 7 SAYS "larger box"
  FIND "const bool descend_a = leaf_b || (!leaf_a && volume(na) >= volume(nb));"
  REPLACE "const bool descend_a = leaf_b || (!leaf_a && volume(na) <= volume(nb));")

# Step 7: the traversal stops at the first pair found even when every pair is asked for.
labkit_mutant(06 spatial_trees NAME bvh_descends_b_at_tie STEP 7 SAYS "equal volumes"
  FIND "const bool descend_a = leaf_b || (!leaf_a && volume(na) >= volume(nb));"
  REPLACE "const bool descend_a = leaf_b || (!leaf_a && volume(na) > volume(nb));")

labkit_mutant(06 spatial_trees NAME bvh_stops_at_first_pair STEP 7 SAYS "every pair"
  FIND "if (!every) return out;"
  REPLACE "return out;")

# Step 7: two leaves' triangles tested without testing the leaves' boxes first: the box
# test only before descending, so leaves whose boxes are apart still test their pairs.
labkit_mutant(06 spatial_trees NAME bvh_leaf_boxes_untested STEP 7 SAYS "leaves' boxes overlap"
  FIND "++out.box_tests;\n    if (!given_boxes_overlap(na.box, nb.box)) continue;"
  REPLACE "const bool both_leaves = na.left < 0 && nb.left < 0;\n    if (!both_leaves) ++out.box_tests;\n    if (!both_leaves && !given_boxes_overlap(na.box, nb.box)) continue;")

# Step 8: the tree stops splitting at depth 2: leaves of thousands of triangles. Every
# answer is still right; only the count of tests gives it away.
labkit_mutant(06 spatial_trees NAME leaves_too_big STEP 8 SAYS "leaves too big"
  FIND "const Split split = depth < max_depth_ ?"
  REPLACE "const Split split = depth < 2 ?")

# Step 8: one grid cell holds every ball, so every pair is tested: the brute force.
# Every answer is still right; only the count of tests gives it away.
labkit_mutant(06 spatial_trees NAME grid_of_one_cell STEP 8 SAYS "adjacent cells"
  FIND "if (!(side > 0) || !std::isfinite(side)) side"
  REPLACE "side = 1e300; if (!(side > 0) || !std::isfinite(side)) side")

# Step 9: the clip to the root's box with strict comparisons: a segment lying in the
# plane of a wall of the root's cell is taken as outside it, and its hits are lost.
labkit_mutant(06 spatial_trees NAME clip_wall_strict STEP 9 SAYS "every leaf the segment meets"
  FIND "if (a[i] < box.min[i] || a[i] > box.max[i]) return {1.0, 0.0};"
  REPLACE "if (a[i] <= box.min[i] || a[i] >= box.max[i]) return {1.0, 0.0};")

# Counts the check keeps itself (README, "Given functions are counted by the checker"):
# each of these would once have scored by writing a count the verdict read.
# Step 2: a brute force over every triangle after the walk, left out of `tests`.
labkit_mutant(06 spatial_trees NAME uncounted_brute_force STEP 2 SAYS "must count every call of given::segment_triangle"
  FIND "  best.tests = tests;"
  REPLACE "  for (const Triangle& t : tree.triangles) given::segment_triangle(segment, t);  // not in tests
  best.tests = tests;")

# Step 5: the balls tested with a formula of its own, not the counted given_balls_meet.
labkit_mutant(06 spatial_trees NAME balls_tested_privately STEP 5 SAYS "given_balls_meet"
  FIND "          if (given_balls_meet(sorted[m], sorted[other])) out.pairs.push_back({i, j});"
  REPLACE "          const double reach = sorted[m].radius + sorted[other].radius;
          if ((sorted[m].center - sorted[other].center).squaredNorm() <= reach * reach) out.pairs.push_back({i, j});")

# Step 6: the ends compared without compare_ends, so that no comparison is counted.
labkit_mutant(06 spatial_trees NAME ends_compared_privately STEP 6 SAYS "only with compare_ends"
  FIND "  const int c = compare_ends(a, b);"
  REPLACE "  const int c = (a.value > b.value) - (a.value < b.value);")

# Step 11: a bucket's entries taken whatever their cell: the bucket also holds cells that
# collide with the one looked for, so balls far apart are tested (and, reached from two
# of the 27 cells, tested twice).
labkit_mutant(06 spatial_trees NAME hash_bucket_not_filtered STEP 11 SAYS "neighbouring cells" "key"
  FIND "if (!same_cell(entry.key, want)) continue;  // another cell that shares this bucket"
  REPLACE "(void)want;  // every entry of the bucket")

# Step 11: only the cells at dx, dy, dz = 0 or +1 looked at: a pair whose other ball lies
# below or behind, with the larger index, is lost.
labkit_mutant(06 spatial_trees NAME hash_half_neighbourhood STEP 11 SAYS "missing" "27 cells"
  FIND "for (int dx = -1; dx <= 1; ++dx)"
  REPLACE "for (int dx = 0; dx <= 1; ++dx)")

# Step 11: each pair tested from both of its balls: right pairs only after a unique, and
# twice the tests the hash needs.
labkit_mutant(06 spatial_trees NAME hash_pairs_from_both_balls STEP 11 SAYS "once"
  FIND "if (entry.sphere <= i) continue;            // each pair once: from its smaller index"
  REPLACE "if (entry.sphere == i) continue;")

# Step 12: a node cut as soon as it holds `capacity` balls, not more: the tree has cuts
# where the rule keeps a leaf.
labkit_mutant(06 spatial_trees NAME octree_cuts_at_capacity STEP 12 SAYS "at most capacity" "adapts"
  FIND "if (int(job.balls.size()) <= capacity || job.depth == max_depth) {"
  REPLACE "if (int(job.balls.size()) < capacity || job.depth == max_depth) {")

# Step 12: a ball sent only to the children its box overlaps with some width: one that
# touches a cut goes one way, and the leaf on the other side misses it.
labkit_mutant(06 spatial_trees NAME octree_touching_one_side STEP 12 SAYS "every child" "touching"
  FIND "if (a.min[i] > b.max[i] || b.min[i] > a.max[i]) return false;"
  REPLACE "if (a.min[i] >= b.max[i] || b.min[i] >= a.max[i]) return false;")

# Step 12: the query descends every child without testing its cell: right balls, but the
# balls of leaves far from the box are tested too.
labkit_mutant(06 spatial_trees NAME octree_descends_every_child STEP 12 SAYS "leaves whose cells meet the box"
  FIND "      ++out.cell_tests;\n      if (given_cell_meets_box(tree.nodes[std::size_t(node.child + k)].cell, box)) todo.push_back(node.child + k);"
  REPLACE "      todo.push_back(node.child + k);  // every child, untested")

# Step 12: a ball listed in several leaves the query reaches is tested in each of them.
labkit_mutant(06 spatial_trees NAME octree_ball_tested_per_leaf STEP 12 SAYS "once per query"
  FIND "if (tested[std::size_t(ball)]) continue;  // listed in an earlier leaf too: tested there"
  REPLACE "if (tested[std::size_t(ball)] && false) continue;")

