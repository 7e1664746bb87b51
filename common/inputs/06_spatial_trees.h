// Lab 06's inputs: each query's arguments as one struct, whose fields() let reports print
// it and replay tokens carry it (the answers' fields are in tests/06_spatial_trees.wire.h).
#pragma once

#include "spatial_trees.h"

#include <vector>

namespace labkit::lab06 {

// A segment query: a mesh, a segment, and which of the checker's own trees over the mesh
// to ask (a seed: the same number always makes the same tree).
struct TreeQuery {
  Mesh mesh;
  Segment segment;
  int tree = 0;
};
template <class V> void fields(TreeQuery& q, V&& v) { v("mesh", q.mesh); v("segment", q.segment); v("tree", q.tree); }

// A point against the solid of a closed mesh (step 3), or an eye for the painter (step 4).
struct PointQuery {
  Mesh mesh;
  Vec3 point = Vec3::Zero();
};
template <class V> void fields(PointQuery& q, V&& v) { v("mesh", q.mesh); v("point", q.point); }

struct SphereSet {
  std::vector<Sphere> spheres;
};
template <class V> void fields(SphereSet& s, V&& v) { v("spheres", s.spheres); }

// Step 6: the frames of one simulation, the same spheres moved a little each time.
struct SweepCase {
  std::vector<std::vector<Sphere>> frames;
};
template <class V> void fields(SweepCase& c, V&& v) { v("frames", c.frames); }

// Step 6's big case: `count` spheres spread over a cube of side 100 (radii 0.25 to 1),
// then `frames` frames in which each centre moves along x by at most 0.05.
struct MovingSpheres {
  int count = 1000;
  int frames = 10;
  int seed = 1;
};
template <class V> void fields(MovingSpheres& m, V&& v) { v("count", m.count); v("frames", m.frames); v("seed", m.seed); }

// Step 7: two meshes, the checker's OBB trees over them (seeds), and whether every pair
// is asked for.
struct BvhQuery {
  Mesh a, b;
  int tree_a = 0, tree_b = 0;
  bool every = true;
};
template <class V> void fields(BvhQuery& q, V&& v) {
  v("a", q.a); v("b", q.b); v("tree_a", q.tree_a); v("tree_b", q.tree_b); v("every", q.every);
}

// Step 8: one of the four big meshes (gen::MeshKind), its size, and a seed for the mesh
// (terrain, soup) and for the random segments.
struct EfficiencyCase {
  int kind = 0;
  int triangles = 10000;
  int segments = 1000;
  int seed = 1;
};
template <class V> void fields(EfficiencyCase& c, V&& v) {
  v("kind", c.kind); v("triangles", c.triangles); v("segments", c.segments); v("seed", c.seed);
}

// Step 8's spheres: n spread over a cube of side 100, radii from 0.25 to 1.
struct SpreadSpheres {
  int count = 2000;
  int seed = 1;
};
template <class V> void fields(SpreadSpheres& s, V&& v) { v("count", s.count); v("seed", s.seed); }

}  // namespace labkit::lab06
