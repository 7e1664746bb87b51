// Spheres and oriented boxes placed by poses (lab 04): exact overlap and distance.
//
// A body is given in its own frame, with a pose x -> R x + p. Every number is read as
// the exact rational it is, the pose's too: a rotation made by floating-point
// trigonometry is then a nearly (not exactly) rigid linear map, and a posed box is the
// exact parallelepiped  R c + p + sum_k s_k R (h_k axis_k), |s_k| <= 1,  that its numbers
// describe. A posed sphere keeps its radius. Closed sets: touching counts as overlap.
#pragma once

#include "common/geometry.h"

namespace oracle {

using labkit::Box;
using labkit::RigidTransform;
using labkit::Sphere;

bool spheres_overlap(const Sphere& a, const RigidTransform& pose_a, const Sphere& b, const RigidTransform& pose_b);
bool sphere_box_overlap(const Sphere& a, const RigidTransform& pose_a, const Box& b, const RigidTransform& pose_b);

// The distance between the posed bodies, 0 when they overlap: the exact squared distance
// between the centres (or from the sphere's centre to the box), rounded once, its root,
// less the radii.
double spheres_distance(const Sphere& a, const RigidTransform& pose_a, const Sphere& b, const RigidTransform& pose_b);
double sphere_box_distance(const Sphere& a, const RigidTransform& pose_a, const Box& b, const RigidTransform& pose_b);

}  // namespace oracle
