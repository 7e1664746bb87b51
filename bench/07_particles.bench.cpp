// Lab 07: particle steps per second against a mesh of about 10,000 triangles (the seeded
// terrain of the lab 06 rows), with the lab 07 reference's System::step.
//
// particles/reference/10000: the scene's mesh_query is the lab 06 reference k-d tree
// (first_hit, then lab 07's hit_triangle on the triangle it found, for the normal and
// the one-sided start rule). particles/brute_force/10000: no mesh_query, so lab 07's
// first_hit tries every triangle (after a box test). Items are particle steps.
// `disagree`: particles whose position after 20 steps from the same state differs from
// brute force's by more than 1e-9.
#include "inputs.h"

#include "particles.h"
#include "spatial_trees.h"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace bench;
namespace lab06 = labkit::lab06;
namespace lab07 = labkit::lab07;

constexpr double kDt = 1.0 / 120;

// The first hit of a segment on the mesh under lab 07's rules, found through the tree.
lab07::SurfaceHit tree_query(const lab06::KdTree& tree, const Segment& s) {
  const lab06::KdHit first = lab06::first_hit(tree, s);
  if (!first.hit) return {};
  lab07::SurfaceHit h = lab07::hit_triangle(s, tree.triangles[std::size_t(first.triangle)]);
  if (!h.hit) {
    // It starts on that triangle's plane (leaving it, for lab 07): the next hit along.
    for (const lab06::KdHit& k : lab06::all_hits(tree, s).hits) {
      h = lab07::hit_triangle(s, tree.triangles[std::size_t(k.triangle)]);
      if (h.hit) {
        h.triangle = k.triangle;
        return h;
      }
    }
    return {};
  }
  h.triangle = first.triangle;
  return h;
}

// A steady stream falling on the terrain: about 1,000 particles alive, bouncing.
struct Start {
  Start() : mesh(terrain(10000)), tree(lab06::build_kd_tree(mesh)) {
    system.emitter.position = Vec3(0.5, 0.5, 0.6);
    system.emitter.half_extents = Vec3(0.4, 0.4, 0.0);
    system.emitter.direction = Vec3(0, 0, -1);
    system.emitter.cone = 0.5;
    system.emitter.speed = 1.0;
    system.emitter.speed_spread = 0.5;
    system.emitter.lifetime = 1.0;
    system.emitter.rate = 1000;
    system.scene.mesh = mesh;
    system.scene.material = {0.6, 0.1};
    system.scene.bounce_cap = 4;
    with_tree(system);
    for (int i = 0; i < 150; ++i) system.step(kDt);  // to the steady state
  }
  void with_tree(lab07::System& s) const {
    const lab06::KdTree* t = &tree;
    s.scene.mesh_query = [t](const Segment& segment, const Mesh&) { return tree_query(*t, segment); };
  }
  const Mesh& mesh;
  lab06::KdTree tree;
  lab07::System system;
};

const Start& start() {
  static const Start s;
  return s;
}

lab07::System prepared(bool with_tree) {
  lab07::System s = start().system;
  if (with_tree)
    start().with_tree(s);
  else
    s.scene.mesh_query = nullptr;
  return s;
}

void measure(benchmark::State& state, bool with_tree) {
  lab07::System system = prepared(with_tree);
  int64_t particle_steps = 0;
  for (auto _ : state) {
    particle_steps += int64_t(system.particles.size());
    system.step(kDt);
  }
  state.SetItemsProcessed(particle_steps);
  state.counters["particles"] = double(system.particles.size());
  lab07::System mine = prepared(with_tree), brute = prepared(false);
  for (int i = 0; i < 20; ++i) mine.step(kDt), brute.step(kDt);
  int differ = int(mine.particles.size() != brute.particles.size());
  for (std::size_t i = 0; i < mine.particles.size() && i < brute.particles.size(); ++i)
    differ += (mine.particles[i].position - brute.particles[i].position).norm() > 1e-9;
  state.counters["disagree"] = differ;
}

void particles_reference(benchmark::State& state) { measure(state, true); }
void particles_brute_force(benchmark::State& state) { measure(state, false); }

}  // namespace

BENCHMARK(particles_reference)->Name("particles/reference")->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(particles_brute_force)->Name("particles/brute_force")->Arg(10000)->Unit(benchmark::kMillisecond);
