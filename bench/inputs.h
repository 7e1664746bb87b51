// Seeded inputs shared by the benchmarks, and the exact verdict on each answer: every
// implementation is measured on the same inputs, and its disagreements with the exact
// answer (outside the ambiguous cases) are counted beside its speed.
#pragma once

#include "common/generators/generators.h"
#include "common/generators/meshes.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace bench {

using namespace labkit;

// n segment-triangle pairs, zero-area triangles left out: `typical` ones (random, about
// half crossing), or the tests' `hard` mix (touching, coplanar, near-parallel, ...).
enum class Mix { typical, hard };
std::vector<SegmentTrianglePair> segment_triangle_inputs(std::size_t n, Mix mix);

// For each pair: the exact answer, and whether it is in doubt (ambiguous).
struct Exact {
  std::vector<bool> hit;
  std::vector<bool> doubt;
};
Exact exact_segment_triangle(const std::vector<SegmentTrianglePair>& inputs);

// How many answers differ from the exact ones where the exact answer is not in doubt.
int disagreements(const std::vector<bool>& answers, const Exact& exact);
int ambiguous(const Exact& exact);

// ---- Trees and particles (labs 06, 07) ---------------------------------------------------

// The seeded mesh of the tree benchmarks: a terrain of about `triangles` triangles over
// [0, 1]^2 (gen::terrain_mesh, seed 6), built once per size and kept.
const Mesh& terrain(int triangles);

// `count` short segments at the mesh, as lab 06's step 6 draws them: centred within
// size / 100 of a random point of a random triangle, size / 50 long (size: the mesh
// box's diagonal). Seeded splitmix64, the same on every machine.
std::vector<Segment> short_segments(const Mesh& mesh, int count, std::uint64_t seed);

// Bytes the heap holds now (glibc's mallinfo2: arena in use plus mmapped blocks): the
// difference across a build is what the built structure keeps.
long long heap_bytes();

}  // namespace bench
