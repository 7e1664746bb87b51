#include "inputs.h"

#include "common/harness/check.h"
#include "common/oracle/oracle.h"

namespace bench {

// Zero-area triangles are left out: "never hit" is the kit's contract for them, not a
// fact of geometry, and the peers follow other rules (CGAL's even asserts).
std::vector<SegmentTrianglePair> segment_triangle_inputs(std::size_t n, Mix mix) {
  std::vector<SegmentTrianglePair> inputs;
  inputs.reserve(n);
  const rc::Gen<SegmentTrianglePair> gen =
      mix == Mix::typical ? gen::typical_segment_triangle() : gen::segment_triangle();
  for (std::size_t i = 0; inputs.size() < n; ++i) {
    const SegmentTrianglePair p = gen(rc::Random(i * 2654435761u + 17), 100).value();
    if (!oracle::is_degenerate(p.triangle)) inputs.push_back(p);
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

}  // namespace bench
