// Lab 06 scene, the presets without a token: the handout's figures (walk, split, sweep,
// coherence, hash, octree) and the scene's own examples, each the same on every machine.
#include "viewer/scenes/06_spatial_trees.h"

#include "common/generators/meshes.h"

#include <cmath>
#include <cstdint>

namespace viewer::spatial_trees {

namespace {

// A repeatable draw in [0, 1): the figures look the same on every machine.
struct Draw {
  std::uint64_t state;
  double operator()() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53);
  }
};

// The "walk" figure: 48 small tilted triangles in a thin slab, seen from above, so that
// the cells are rectangles.
Mesh walk_mesh() {
  Mesh mesh;
  Draw next{7};
  for (int i = 0; i < 24; ++i) {
    const double x = 0.5 + 7 * next(), y = 0.3 + 3.4 * next(), a = 2 * M_PI * next();  // in this order
    const Vec3 c(x, y, 0);
    const int base = int(mesh.vertices.size());
    for (int k = 0; k < 3; ++k)
      mesh.vertices.push_back(c + Vec3(0.35 * std::cos(a + 2.1 * k), 0.35 * std::sin(a + 2.1 * k), 0.12 * (k - 1)));
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

}  // namespace

// A preset without a token: the handout's figures and the scene's own examples.
void SpatialTreesScene::set_up_figure(const std::string& name) {
  if (name == "walk") {  // a segment across walk_mesh()
    mesh_ = walk_mesh();
    segment_ = {{-0.3, 3.9, 0.02}, {8.3, 0.6, -0.02}};
  } else if (name == "split") {  // the handout's floor and wall
    mode_ = Mode::bsp;
    mesh_.vertices = {{0, 0, 0}, {8, 0, 0}, {0, 8, 0}, {2, 0, -2}, {2, 0, 2}, {2, 4, 0}};
    mesh_.triangles = {{0, 1, 2}, {3, 4, 5}};
    point_ = {6, 6, 3};
  } else if (name == "sweep") {  // the handout's A, R, B, C
    mode_ = Mode::spheres;
    spheres_ = {{{1, 0, 0}, 1}, {{5, 0, 0}, 2}, {{9, 3, 0}, 4}, {{9, 9, 0}, 1}};
  } else if (name == "bvh") {  // two spheres, overlapping in part
    mode_ = Mode::bvh;
    mesh_ = gen::sphere_mesh(40, {0, 0, 0}, 1);
    mesh_b_ = gen::sphere_mesh(40, {1.3, 0.3, 0.1}, 0.8);
    tree_seed_ = 3, tree_seed_b_ = 5;
  } else if (name == "coherence") {  // step 6's example: the lecture's A R B C, then C moves 2 to the left
    mode_ = Mode::frames;
    frames_ = {{{{1, 0, 0}, 1}, {{5, 0, 0}, 2}, {{9, 3, 0}, 4}, {{9, 9, 0}, 1}}};
    frames_.push_back(frames_[0]);
    frames_[1][3].center = {7, 9, 0};
    spheres_ = frames_.back();
  } else if (name == "handout") {  // A leans across x = 4, B stands in x = 5
    mesh_.vertices = {{8, -1, 0}, {8, 3, 0}, {2, 1, 3}, {5, 0, 0}, {5, 3, 0}, {5, 0, 3}};
    mesh_.triangles = {{0, 1, 2}, {3, 4, 5}};
    segment_ = {{0, 1, 1}, {8, 1, 1}};
  } else if (name == "terrain") {
    mesh_ = gen::terrain_mesh(20000, 3);
    segment_ = {{0.05, 0.1, 0.3}, {0.95, 0.85, -0.2}};
  } else if (name == "bsp") {
    mode_ = Mode::bsp;
    mesh_ = gen::voxel_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, Vec3::Zero(), 2.0);
    point_ = {3, 3, 1};
  } else if (name == "hash" || name == "octree") {
    set_up_extension(name);
  } else if (name == "spheres") {
    mode_ = Mode::spheres;
    spheres_ = gen::spread_spheres(60, 10, 0.3, 1.2, 5);
  } else {
    mesh_ = gen::torus_mesh(2048, Vec3(0.5, 0.5, 0.5), 0.35, 0.12);
  }
}

void SpatialTreesScene::set_up_extension(const std::string& preset) {
  Draw next{preset == "hash" ? 11u : 23u};
  if (preset == "hash") {  // 14 balls in the plane z = 1, cells of side 2, 4 buckets
    mode_ = Mode::hash;
    hash_cell_ = 2, hash_buckets_ = 4;
    for (int i = 0; i < 14; ++i) {
      const double x = 0.3 + 9.4 * next(), y = 0.3 + 5.4 * next(), r = 0.35 + 0.55 * next();  // in this order
      spheres_.push_back({{x, y, 1}, r});
    }
    return;
  }
  // Two clusters and a lone ball in the plane z = 0: the tree cuts deep at the clusters.
  mode_ = Mode::octree;
  capacity_ = 2, max_depth_ = 5;
  for (const Vec3& centre : {Vec3(1.5, 1.5, 0), Vec3(12.5, 8.5, 0)})
    for (int i = 0; i < 8; ++i) {
      const double x = centre.x() + 3.6 * (next() - 0.5), y = centre.y() + 3.6 * (next() - 0.5);
      spheres_.push_back({{x, y, 0}, 0.2 + 0.15 * next()});
    }
  spheres_.push_back({{12, 2, 0}, 0.4});
  query_box_ = {{12.4, 8.4, -1}, {14.2, 10.2, 1}};
}

}  // namespace viewer::spatial_trees
