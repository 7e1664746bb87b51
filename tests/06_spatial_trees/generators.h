// Lab 06's own random inputs, drawn from the shared meshes and spheres (meshes.h): segments
// and points near a mesh with a seed for the checker's tree, sets of spheres moving frame
// by frame, and pairs of meshes that overlap in part.
#pragma once

#include "06_spatial_trees/inputs.h"
#include "common/generators/meshes.h"

namespace labkit::gen {

// Step 2: a mesh (lab 02's soups, terrains and octahedra among others), a segment near it
// and a seed for the checker's tree; the exact one on integers.
rc::Gen<lab06::TreeQuery> tree_query();
rc::Gen<lab06::TreeQuery> exact_tree_query();
// Steps 3 and 4: a mesh for a BSP tree, a point near a closed mesh, an eye near any mesh.
rc::Gen<Mesh> bsp_mesh();
rc::Gen<lab06::PointQuery> point_query();
rc::Gen<lab06::PointQuery> exact_point_query();
rc::Gen<lab06::PointQuery> eye_query();
rc::Gen<lab06::PointQuery> exact_eye_query();
// Step 5: sphere_set() and exact_sphere_set() as one input.
rc::Gen<lab06::SphereSet> sphere_set_case();
rc::Gen<lab06::SphereSet> exact_sphere_set_case();
// Step 6: step 5's spheres, then frames in which they move a little.
rc::Gen<lab06::SweepCase> sweep_case();
rc::Gen<lab06::SweepCase> exact_sweep_case();
// Step 6's big case, frame by frame (no random draw: the same numbers give the same frames).
lab06::SweepCase moving_spheres(const lab06::MovingSpheres& m);
// Step 7: two small meshes overlapping in part, seeds for the checker's OBB trees.
rc::Gen<lab06::BvhQuery> bvh_query();
// Step 11: sparse worlds (clusters 2^30 apart, on integers: exact touching), step 5's
// sets, bucket counts from 1 (every cell collides) to thousands.
rc::Gen<lab06::HashCase> hash_case();
// Step 12: clusters of balls in a wide space (the octree adapts to them), a box near
// them; or balls and a box on integers, touching exactly, judged exactly.
rc::Gen<lab06::OctreeCase> octree_case();

}  // namespace labkit::gen
