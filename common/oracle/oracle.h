// The exact oracle: what the tests, the grader and the viewer compare answers against.
// Every double it is given is read as the exact rational number it is; predicates are
// exact, constructions are exact rationals rounded on the way out to a relative 1e-12
// (usually to the nearest double), far below any tolerance of the labs. A plain
// (non-template) API over the kit's geometry types; CGAL stays inside common/oracle/.
#pragma once

#include "common/oracle/boxes.h"
#include "common/oracle/clipping.h"
#include "common/oracle/particles.h"
#include "common/oracle/posed_shapes.h"
#include "common/oracle/predicates.h"
#include "common/oracle/segment_triangle.h"
#include "common/oracle/spatial_trees.h"
#include "common/oracle/sphere_sweeps.h"
#include "common/oracle/triangle_pair.h"
