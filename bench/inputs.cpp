#include "inputs.h"

#include "common/harness/check.h"
#include "common/oracle/oracle.h"
#include "common/splitmix.h"

#include <malloc.h>

#include <map>
#include <memory>

namespace bench {

// Zero-area triangles and zero-length segments are left out: "never hit" is the kit's
// contract for the first, not a fact of geometry, and CGAL requires segments of some
// length (its own assertions fail on them). Segments lying in the triangle's plane stay:
// the kit's contract decides them in 2D, and that is where peers go wrong.
std::vector<SegmentTrianglePair> segment_triangle_inputs(std::size_t n, Mix mix) {
  std::vector<SegmentTrianglePair> inputs;
  inputs.reserve(n);
  const rc::Gen<SegmentTrianglePair> gen =
      mix == Mix::typical ? gen::typical_segment_triangle() : gen::segment_triangle();
  for (std::size_t i = 0; inputs.size() < n; ++i) {
    const SegmentTrianglePair p = gen(rc::Random(i * 2654435761u + 17), 100).value();
    if (!oracle::is_degenerate(p.triangle) && p.segment.a != p.segment.b) inputs.push_back(p);
  }
  return inputs;
}

Exact exact_segment_triangle(const std::vector<SegmentTrianglePair>& inputs) {
  Exact e;
  const auto hit = [](const SegmentTrianglePair& p) { return oracle::segment_hits_triangle(p.segment, p.triangle); };
  for (const SegmentTrianglePair& p : inputs) {
    e.hit.push_back(hit(p));
    const double delta = check::kAmbiguity * check::scale_of_input(p);
    e.doubt.push_back(oracle::segment_triangle_in_doubt(p.segment, p.triangle, delta) ||
                      check::flips_under_perturbation(p, hit));
  }
  return e;
}

int disagreements(const std::vector<bool>& answers, const Exact& exact) {
  int n = 0;
  for (std::size_t i = 0; i < answers.size(); ++i) n += !exact.doubt[i] && answers[i] != exact.hit[i];
  return n;
}

int ambiguous(const Exact& exact) {
  int n = 0;
  for (bool d : exact.doubt) n += d;
  return n;
}

const Mesh& terrain(int triangles) {
  static std::map<int, std::unique_ptr<Mesh>> meshes;
  auto& m = meshes[triangles];
  if (!m) m = std::make_unique<Mesh>(gen::terrain_mesh(triangles, 6));
  return *m;
}

std::vector<Segment> short_segments(const Mesh& mesh, int count, std::uint64_t seed) {
  SplitMix64 random{seed};
  Vec3 low = mesh.vertices[0], high = low;
  for (const Vec3& v : mesh.vertices) low = low.cwiseMin(v), high = high.cwiseMax(v);
  const double size = (high - low).norm();
  const auto in_ball = [&] {
    for (;;) {
      const Vec3 v(2 * random.uniform() - 1, 2 * random.uniform() - 1, 2 * random.uniform() - 1);
      if (v.squaredNorm() <= 1 && v.squaredNorm() > 1e-6) return v;
    }
  };
  std::vector<Segment> out;
  out.reserve(count);
  while (int(out.size()) < count) {
    const Triangle t = mesh.triangle(std::size_t(random.next() % mesh.size()));
    double u = random.uniform(), v = random.uniform();
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vec3 c = t.v0 + u * (t.v1 - t.v0) + v * (t.v2 - t.v0) + size / 100 * in_ball();
    const Vec3 d = size / 100 * in_ball().normalized();
    out.push_back({c - d, c + d});
  }
  return out;
}

long long heap_bytes() {
  const struct mallinfo2 m = mallinfo2();
  return (long long)(m.uordblks + m.hblkhd);
}

}  // namespace bench
