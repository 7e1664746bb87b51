// Lab 03's inputs: what each query of separating_axes.h is given, one struct per query,
// and their fields() (the names a report prints and a replay token reads). The generators
// (common/generators/03_separating_axes.h) draw them, the judge and the viewer read them.
#pragma once

#include "separating_axes.h"

namespace labkit {

struct BoxOnAxis {
  Box box;
  Vec3 axis = Vec3::UnitX();
};
template <class Visit>
void fields(BoxOnAxis& p, Visit&& visit) {
  visit("box", p.box);
  visit("axis", p.axis);
}

struct BoxPair {
  Box a;
  Box b;
};
template <class Visit>
void fields(BoxPair& p, Visit&& visit) {
  visit("a", p.a);
  visit("b", p.b);
}

struct BoxPairOnAxis {
  Box a;
  Box b;
  Vec3 axis = Vec3::UnitX();
};
template <class Visit>
void fields(BoxPairOnAxis& p, Visit&& visit) {
  visit("a", p.a);
  visit("b", p.b);
  visit("axis", p.axis);
}

struct TrianglePair {
  Triangle t0;
  Triangle t1;
};
template <class Visit>
void fields(TrianglePair& p, Visit&& visit) {
  visit("t0", p.t0);
  visit("t1", p.t1);
}

// Box a moves with velocity_a, box b with velocity_b, for t in [0, duration].
struct MovingBoxes {
  Box a;
  Vec3 velocity_a = Vec3::Zero();
  Box b;
  Vec3 velocity_b = Vec3::Zero();
  double duration = 1.0;
};
template <class Visit>
void fields(MovingBoxes& p, Visit&& visit) {
  visit("a", p.a);
  visit("velocity_a", p.velocity_a);
  visit("b", p.b);
  visit("velocity_b", p.velocity_b);
  visit("duration", p.duration);
}

}  // namespace labkit
