// Inputs that several labs' tests share: a query's arguments as one struct, whose fields()
// let reports print it and the replay codec write it. Plain data, no generator: a
// harness or a judge reads them without reaching into the generators.
#pragma once

#include "common/geometry.h"

namespace labkit {

struct SegmentTrianglePair {
  Segment segment;
  Triangle triangle;
};
template <class Visit> void fields(SegmentTrianglePair& p, Visit&& visit) {
  visit("segment", p.segment);
  visit("triangle", p.triangle);
}

struct SegmentMeshPair {
  Segment segment;
  Mesh mesh;
};
template <class Visit> void fields(SegmentMeshPair& p, Visit&& visit) {
  visit("segment", p.segment);
  visit("mesh", p.mesh);
}

}  // namespace labkit
