// Inputs that several labs' tests share: a query's arguments as one struct, whose fields()
// let reports print it and the replay codec write it. Plain data, no generator: a
// harness or a judge reads them without reaching into the generators.
#pragma once

#include "common/fields.h"
#include "common/geometry.h"

namespace labkit {

struct SegmentTrianglePair {
  Segment segment;
  Triangle triangle;
};
LABKIT_FIELDS(SegmentTrianglePair, segment, triangle)

struct SegmentMeshPair {
  Segment segment;
  Mesh mesh;
};
LABKIT_FIELDS(SegmentMeshPair, segment, mesh)

}  // namespace labkit
