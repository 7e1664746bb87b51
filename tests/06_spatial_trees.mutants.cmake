# Lab 06's classic mistakes (handouts/06_spatial_trees.md); each must fail its step.

# Step 1: a triangle that only touches the split plane from above is sent above only,
# though it meets the closed cell below at the plane.
labkit_mutant(06 spatial_trees NAME touching_goes_one_side STEP 1
  FIND "if (boxes_[std::size_t(i)].min[split.axis] <= split.position) below.push_back(i);"
  REPLACE "if (boxes_[std::size_t(i)].min[split.axis] < split.position) below.push_back(i);")

# Step 2: first_hit stops in the first leaf that has any hit, even one beyond the leaf's
# far end (a later leaf may hold a nearer one).
labkit_mutant(06 spatial_trees NAME first_hit_stops_too_soon STEP 2
  FIND "return best.hit ? best.t : kInfinity;"
  REPLACE "return best.hit ? -kInfinity : kInfinity;")

# Step 2: all_hits reports a triangle listed in two leaves twice.
labkit_mutant(06 spatial_trees NAME all_hits_twice STEP 2
  FIND "return x.triangle == y.triangle;"
  REPLACE "return false;")

# Step 3: a point on a node's plane is sent in front, as if it were off the plane.
labkit_mutant(06 spatial_trees NAME on_plane_goes_front STEP 3
  FIND "if (side > 0) {"
  REPLACE "if (side >= 0) {")

# Step 4: the subtree on the eye's side drawn first: front to back, not back to front.
labkit_mutant(06 spatial_trees NAME near_subtree_first STEP 4
  FIND "const int near = eye_in_front ? n.front : n.back, far = eye_in_front ? n.back : n.front;"
  REPLACE "const int near = eye_in_front ? n.back : n.front, far = eye_in_front ? n.front : n.back;")

# Step 5: intervals that only touch are taken as apart, so touching balls are missed.
labkit_mutant(06 spatial_trees NAME touching_intervals_apart STEP 5
  FIND "intervals[j].low <= intervals[i].high"
  REPLACE "intervals[j].low < intervals[i].high")

# Step 6: the tree stops splitting at depth 2: leaves of thousands of triangles. Every
# answer is still right; only the count of tests gives it away.
labkit_mutant(06 spatial_trees NAME leaves_too_big STEP 6
  FIND "const Split split = depth < max_depth_ ?"
  REPLACE "const Split split = depth < 2 ?")

# Step 6: the sweep tests every later interval, overlapping or not: the brute force.
labkit_mutant(06 spatial_trees NAME sweep_tests_all_pairs STEP 6
  FIND "j < intervals.size() && intervals[j].low <= intervals[i].high; ++j"
  REPLACE "j < intervals.size(); ++j")

# Step 7: a segment starting exactly on a split plane is sent to the side of its start
# by a strict comparison alone: going down from the plane, it walks the cell above and
# never the one below.
labkit_mutant(06 spatial_trees NAME start_on_plane_wrong_side STEP 7
  FIND "(s.a[axis] == n.split && d[axis] <= 0)"
  REPLACE "false")
