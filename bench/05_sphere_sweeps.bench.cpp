// Lab 05: segment-segment distance on 32,768 pairs: typical ones (uniform in a cube,
// almost never parallel) and the tests' hard mix (parallel, collinear, nearly parallel,
// crossing, zero-length, tiny and huge, far from the origin). Peer: CGAL's
// squared_distance on Epick Segment_3 (exact predicates, inexact constructions), the
// call a practitioner would make. Both get the same seeded pairs.
// `disagree` counts answers whose distance is off the exact one (the oracle's exact
// squared distance) by more than the header's tolerance, 1e-9 S with S the largest
// absolute coordinate: the same rule the lab's judge applies to students. A distance is
// a construction, not a yes/no, so no case is ambiguous (`ambiguous` is always 0; it is
// there so that every group reports the same counters).
#ifdef LABKIT_HAS_LAB05
#include "inputs.h"

#include "05_sphere_sweeps/judge.h"
#include "common/oracle/oracle.h"
#include "sphere_sweeps.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

namespace {

using namespace bench;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

std::vector<SegmentPair> typical_pairs(std::size_t n) {
  std::mt19937_64 random(20260505);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  const auto point = [&] { return Vec3(coordinate(random), coordinate(random), coordinate(random)); };
  std::vector<SegmentPair> pairs(n);
  for (SegmentPair& p : pairs) p = {{point(), point()}, {point(), point()}};
  return pairs;
}

std::vector<SegmentPair> hard_pairs(std::size_t n) {
  const rc::Gen<SegmentPair> gen = gen::segment_pair();
  std::vector<SegmentPair> pairs;
  for (std::size_t i = 0; pairs.size() < n; ++i) pairs.push_back(gen(rc::Random(i * 2654435761u + 5), 100).value());
  return pairs;
}

struct Data {
  explicit Data(std::vector<SegmentPair> in) : inputs(std::move(in)) {
    const auto point = [](const Vec3& v) { return Epick::Point_3(v.x(), v.y(), v.z()); };
    for (const SegmentPair& p : inputs) {
      epick.push_back({Epick::Segment_3(point(p.first.a), point(p.first.b)),
                       Epick::Segment_3(point(p.second.a), point(p.second.b))});
      exact.push_back(oracle::squared_distance(p.first, p.second));
      tolerance.push_back(1e-9 * std::max(1e-300, scale_of({p.first.a, p.first.b, p.second.a, p.second.b})));
    }
  }
  std::vector<SegmentPair> inputs;
  std::vector<std::pair<Epick::Segment_3, Epick::Segment_3>> epick;
  std::vector<oracle::SquaredDistance> exact;
  std::vector<double> tolerance;
};

// The benchmark's argument picks the mix: 0 typical, 1 hard.
const Data& data(const benchmark::State& state) {
  static const Data typical(typical_pairs(1 << 15)), hard(hard_pairs(1 << 15));
  return state.range(0) == 0 ? typical : hard;
}

// Speed, then correctness. `answer(d, i)` is the squared distance of pair i of d.
template <class Answer> void measure(benchmark::State& state, Answer&& answer) {
  const Data& d = data(state);
  const std::size_t n = d.inputs.size();
  double sum = 0;
  for (auto _ : state)
    for (std::size_t i = 0; i < n; ++i) sum += answer(d, i);
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * int64_t(n));
  int disagree = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double got2 = answer(d, i), tol = d.tolerance[i];
    const double got = got2 >= 0 && std::isfinite(got2) ? std::sqrt(got2) : -1.0;
    disagree += got < 0 || d.exact[i].compare(got, tol) > 0 || d.exact[i].compare(got, -tol) < 0;
  }
  state.counters["disagree"] = disagree;
  state.counters["ambiguous"] = 0;
}

void distance_reference(benchmark::State& state) {
  measure(state, [](const Data& d, std::size_t i) {
    const SegmentPair& p = d.inputs[i];
    return labkit::lab05::segment_segment(p.first, p.second).squared_distance;
  });
}

void distance_cgal_epick(benchmark::State& state) {
  measure(state,
          [](const Data& d, std::size_t i) { return CGAL::squared_distance(d.epick[i].first, d.epick[i].second); });
}

}  // namespace

#define LABKIT_BENCH_BOTH_MIXES(function, name)                \
  BENCHMARK(function)->Name(name)->Arg(0)->ArgName("typical"); \
  BENCHMARK(function)->Name(name)->Arg(1)->ArgName("hard")

LABKIT_BENCH_BOTH_MIXES(distance_reference, "segment_segment_distance/reference");
LABKIT_BENCH_BOTH_MIXES(distance_cgal_epick, "segment_segment_distance/cgal_epick");

#endif  // LABKIT_HAS_LAB05
