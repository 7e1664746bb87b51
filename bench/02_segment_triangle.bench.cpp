// Lab 02: segment against triangle, test and find, on 65,536 pairs: typical ones
// (random, about half crossing) and the tests' hard mix (touching, coplanar,
// near-parallel, tiny and huge). Peers: CGAL with inexact constructions (Epick) and
// with exact ones (Epeck), and the plain Moller-Trumbore test.
// Targets (on typical pairs): the reference at least 3x Epick and at least 0.8x
// Moller-Trumbore, with no disagreement with the exact answer outside the ambiguous
// cases; the hard mix shows what each one gets wrong.
#include "inputs.h"
#include "peers/moller_trumbore.h"

#include "segment_triangle.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

namespace {

using namespace bench;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

template <class K> struct CgalPairs {
  std::vector<typename K::Segment_3> segments;
  std::vector<typename K::Triangle_3> triangles;
};

template <class K> CgalPairs<K> convert(const std::vector<SegmentTrianglePair>& inputs) {
  const auto point = [](const Vec3& v) { return typename K::Point_3(v.x(), v.y(), v.z()); };
  CgalPairs<K> c;
  for (const SegmentTrianglePair& p : inputs) {
    c.segments.emplace_back(point(p.segment.a), point(p.segment.b));
    c.triangles.emplace_back(point(p.triangle.v0), point(p.triangle.v1), point(p.triangle.v2));
  }
  return c;
}

struct Data {
  explicit Data(Mix mix) : inputs(segment_triangle_inputs(1 << 16, mix)) {}
  std::vector<SegmentTrianglePair> inputs;
  Exact exact = exact_segment_triangle(inputs);
  CgalPairs<Epick> epick = convert<Epick>(inputs);
  CgalPairs<Epeck> epeck = convert<Epeck>(inputs);
};

// Built once per mix, on first use.
const Data& data(Mix mix) {
  static const Data typical(Mix::typical), hard(Mix::hard);
  return mix == Mix::typical ? typical : hard;
}

// Speed, then correctness: how many answers differ from the exact ones where the exact
// answer is not in doubt. `answer(d, i)` answers pair i of d.
template <class Answer> void measure(benchmark::State& state, Mix mix, Answer&& answer) {
  const Data& d = data(mix);
  const std::size_t n = d.inputs.size();
  std::size_t hits = 0;
  for (auto _ : state)
    for (std::size_t i = 0; i < n; ++i) hits += answer(d, i);
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * int64_t(n));
  std::vector<bool> answers(n);
  for (std::size_t i = 0; i < n; ++i) answers[i] = answer(d, i);
  state.counters["disagree"] = disagreements(answers, d.exact);
  state.counters["ambiguous"] = ambiguous(d.exact);
}

void test_reference(benchmark::State& state, Mix mix) {
  measure(state, mix, [](const Data& d, std::size_t i) {
    const auto& p = d.inputs[i];
    return labkit::lab02::test_segment_triangle(p.segment, p.triangle);
  });
}

void test_cgal_epick(benchmark::State& state, Mix mix) {
  measure(state, mix,
          [](const Data& d, std::size_t i) { return CGAL::do_intersect(d.epick.segments[i], d.epick.triangles[i]); });
}

void test_cgal_epeck(benchmark::State& state, Mix mix) {
  measure(state, mix,
          [](const Data& d, std::size_t i) { return CGAL::do_intersect(d.epeck.segments[i], d.epeck.triangles[i]); });
}

void test_moller_trumbore(benchmark::State& state, Mix mix) {
  measure(state, mix, [](const Data& d, std::size_t i) {
    const auto& p = d.inputs[i];
    return peers::moller_trumbore(p.segment, p.triangle).hit;
  });
}

void find_reference(benchmark::State& state, Mix mix) {
  measure(state, mix, [](const Data& d, std::size_t i) {
    const auto& p = d.inputs[i];
    const auto h = labkit::lab02::find_segment_triangle(p.segment, p.triangle);
    benchmark::DoNotOptimize(h.point);
    benchmark::DoNotOptimize(h.normal);
    return h.hit;
  });
}

// Epick's constructions are inexact: on near-degenerate pairs CGAL's own assertions
// can fail inside intersection(). Such an answer is counted as a miss (and so, where
// the exact answer is a hit, as a disagreement).
template <class K> bool cgal_find(const CgalPairs<K>& c, std::size_t i) {
  try {
    const auto result = CGAL::intersection(c.segments[i], c.triangles[i]);
    if (!result) return false;
    benchmark::DoNotOptimize(&*result);
    return true;
  } catch (const CGAL::Failure_exception&) {
    return false;
  }
}

void find_cgal_epick(benchmark::State& state, Mix mix) {
  measure(state, mix, [](const Data& d, std::size_t i) { return cgal_find(d.epick, i); });
}

void find_cgal_epeck(benchmark::State& state, Mix mix) {
  measure(state, mix, [](const Data& d, std::size_t i) { return cgal_find(d.epeck, i); });
}

void find_moller_trumbore(benchmark::State& state, Mix mix) {
  measure(state, mix, [](const Data& d, std::size_t i) {
    const auto& p = d.inputs[i];
    const auto h = peers::moller_trumbore_find(p.segment, p.triangle);
    benchmark::DoNotOptimize(h.point);
    return h.hit;
  });
}

// Names: kernel/implementation/mix (labkit-bench-report shows each mix in its own table).
const bool registered = [] {
  const std::pair<const char*, void (*)(benchmark::State&, Mix)> kernels[] = {
      {"segment_triangle_test/reference", test_reference},
      {"segment_triangle_test/moller_trumbore", test_moller_trumbore},
      {"segment_triangle_test/cgal_epick", test_cgal_epick},
      {"segment_triangle_test/cgal_epeck", test_cgal_epeck},
      {"segment_triangle_find/reference", find_reference},
      {"segment_triangle_find/moller_trumbore", find_moller_trumbore},
      {"segment_triangle_find/cgal_epick", find_cgal_epick},
      {"segment_triangle_find/cgal_epeck", find_cgal_epeck},
  };
  for (const auto& [name, function] : kernels) {
    benchmark::RegisterBenchmark((std::string(name) + "/typical").c_str(), function, Mix::typical);
    benchmark::RegisterBenchmark((std::string(name) + "/hard").c_str(), function, Mix::hard);
  }
  return true;
}();

}  // namespace
