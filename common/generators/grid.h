// Where a family of generated cases draws its numbers: a scale (a power of two) and
// whether it keeps to its lab's exact lattice. What that lattice is (integers, multiples
// of 8, how far out) is the lab's: see the grid_point and grid_direction beside its use.
#pragma once

#include <rapidcheck.h>

namespace labkit::gen {

struct Grid {
  double s = 1.0;      // every coordinate is a lattice value times s
  bool exact = false;  // the lab's exact lattice, not the fine dyadic one (integers plus 20-bit fractions)
};

// A Grid whose scale is drawn by scale() (or by `scales`): one draw, shrinking toward 1.
rc::Gen<Grid> grid(bool exact);
rc::Gen<Grid> grid(bool exact, rc::Gen<double> scales);

}  // namespace labkit::gen
