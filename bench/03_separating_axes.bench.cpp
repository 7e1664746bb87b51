// Lab 03: separating axes. Two yes/no queries on 16,384 seeded pairs each, typical and
// hard, every implementation on the same pairs:
//   obb_test       two oriented boxes: the reference (15 axes, every term along the
//                  computed axis) against FCL's boolean OBB test (fcl::OBBd::overlap,
//                  Gottschalk's test with 1e-6 added to |R|) and FCL's narrow phase
//                  (fcl::collide on two fcl::Boxd shapes);
//   triangle_test  two triangles: the reference (signs of orientations, Guigue and
//                  Devillers) against CGAL::do_intersect with Epick (exact predicates).
// Typical pairs: boxes with centres in [-2, 2]^3, half extents 0.2 to 1.5, random
// rotations (about half intersect); triangles with vertices in the unit cube around
// nearby centres. Hard pairs: the tests' generators (touching faces, edges and corners,
// parallel and nearly parallel edges, 2^-k gaps, coplanar triangles, 2^-20 to 2^20).
// Flat boxes and zero-area triangles are left out: the kit's rules for them are its own
// contract, not facts of geometry, and the peers follow other rules (CGAL asserts).
// `disagree` counts answers that differ from the exact one (CGAL with exact arithmetic
// on the boxes' corners and the triangles' vertices) outside the ambiguous cases.
// No targets: issue 5 states none for this lab.
#include "inputs.h"

#include "03_separating_axes/judge.h"
#include "common/harness/check.h"
#include "common/oracle/oracle.h"
#include "separating_axes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <random>

#ifdef LABKIT_HAS_FCL
#include <fcl/math/bv/OBB.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#endif

namespace {

using namespace bench;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
constexpr std::size_t kPairs = 1 << 14;

// ---- inputs ---------------------------------------------------------------------------

Box random_box(std::mt19937_64& rng, double spread) {
  std::uniform_real_distribution<double> unit(-1, 1), size(0.2, 1.5);
  Box b;
  b.center = spread * Vec3(unit(rng), unit(rng), unit(rng));
  b.half_extents = Vec3(size(rng), size(rng), size(rng));
  Eigen::Quaterniond q(unit(rng), unit(rng), unit(rng), unit(rng));
  b.axes = q.normalized().toRotationMatrix();
  return b;
}

bool flat(const Box& b) { return (b.half_extents.array() == 0).any(); }
bool zero_area(const Triangle& t) { return t.normal() == Vec3::Zero(); }

std::vector<BoxPair> box_pairs(Mix mix) {
  std::vector<BoxPair> pairs;
  std::mt19937_64 rng(3);
  const rc::Gen<BoxPair> hard = gen::box_pair();
  for (std::size_t i = 0; pairs.size() < kPairs; ++i) {
    const BoxPair p = mix == Mix::typical ? BoxPair{random_box(rng, 0), random_box(rng, 2)}
                                          : hard(rc::Random(i * 2654435761u + 17), 100).value();
    if (!flat(p.a) && !flat(p.b)) pairs.push_back(p);
  }
  return pairs;
}

std::vector<TrianglePair> triangle_pairs(Mix mix) {
  std::vector<TrianglePair> pairs;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  const auto point = [&](const Vec3& around) { return Vec3(around + Vec3(unit(rng), unit(rng), unit(rng))); };
  const rc::Gen<TrianglePair> hard = gen::triangle_pair();
  for (std::size_t i = 0; pairs.size() < kPairs; ++i) {
    TrianglePair p;
    if (mix == Mix::typical) {
      const Vec3 c0 = Vec3::Zero(), c1(0.6 * unit(rng), 0.6 * unit(rng), 0.6 * unit(rng));
      p = {{point(c0), point(c0), point(c0)}, {point(c1), point(c1), point(c1)}};
    } else {
      p = hard(rc::Random(i * 2654435761u + 17), 100).value();
    }
    if (!zero_area(p.t0) && !zero_area(p.t1)) pairs.push_back(p);
  }
  return pairs;
}

// The exact answers, and the cases in doubt, by the same rules as the lab's judges
// (tests/03_separating_axes/judge.cpp): boxes whose exact margin is within 24 tol,
// triangles that oracle::triangle_pair_in_doubt or a sampled perturbation flips.
Exact exact_boxes(const std::vector<BoxPair>& pairs) {
  Exact e;
  for (const BoxPair& p : pairs) {
    e.hit.push_back(oracle::boxes_intersect(p.a, p.b));
    e.doubt.push_back(std::abs(oracle::box_pair_margin(p.a, p.b)) <= 24 * 1e-9 * scale_of(p));
  }
  return e;
}

Exact exact_triangles(const std::vector<TrianglePair>& pairs) {
  Exact e;
  const auto hit = [](const TrianglePair& p) { return oracle::triangles_intersect(p.t0, p.t1); };
  for (const TrianglePair& p : pairs) {
    e.hit.push_back(hit(p));
    e.doubt.push_back(oracle::triangle_pair_in_doubt(p.t0, p.t1, 1e-9 * scale_of(p)) ||
                      labkit::check::flips_under_perturbation(p, hit));
  }
  return e;
}

#ifdef LABKIT_HAS_FCL
struct FclPair {
  fcl::OBBd a, b;
  std::shared_ptr<fcl::CollisionObjectd> oa, ob;
};

fcl::OBBd obb(const Box& b) {
  fcl::OBBd o;
  o.axis = b.axes;
  o.To = b.center;
  o.extent = b.half_extents;
  return o;
}

std::shared_ptr<fcl::CollisionObjectd> object(const Box& b) {
  auto shape = std::make_shared<fcl::Boxd>(2 * b.half_extents);
  fcl::Transform3d pose = fcl::Transform3d::Identity();
  pose.linear() = b.axes;
  pose.translation() = b.center;
  return std::make_shared<fcl::CollisionObjectd>(shape, pose);
}
#endif

struct BoxData {
  explicit BoxData(Mix mix) : pairs(box_pairs(mix)) {
#ifdef LABKIT_HAS_FCL
    for (const BoxPair& p : pairs) fcl.push_back({obb(p.a), obb(p.b), object(p.a), object(p.b)});
#endif
  }
  std::vector<BoxPair> pairs;
  Exact exact = exact_boxes(pairs);
#ifdef LABKIT_HAS_FCL
  std::vector<FclPair> fcl;
#endif
};

struct TriangleData {
  explicit TriangleData(Mix mix) : pairs(triangle_pairs(mix)) {
    const auto point = [](const Vec3& v) { return Epick::Point_3(v.x(), v.y(), v.z()); };
    for (const TrianglePair& p : pairs) {
      cgal.emplace_back(point(p.t0.v0), point(p.t0.v1), point(p.t0.v2));
      cgal.emplace_back(point(p.t1.v0), point(p.t1.v1), point(p.t1.v2));
    }
  }
  std::vector<TrianglePair> pairs;
  Exact exact = exact_triangles(pairs);
  std::vector<Epick::Triangle_3> cgal;  // t0 of pair i at 2 i, t1 at 2 i + 1
};

// The benchmark's argument picks the mix: 0 typical, 1 hard.
const BoxData& boxes(const benchmark::State& state) {
  static const BoxData typical(Mix::typical), hard(Mix::hard);
  return state.range(0) == 0 ? typical : hard;
}
const TriangleData& triangles(const benchmark::State& state) {
  static const TriangleData typical(Mix::typical), hard(Mix::hard);
  return state.range(0) == 0 ? typical : hard;
}

// Speed, then correctness against the exact answers outside the ambiguous cases.
template <class Data, class Answer> void measure(benchmark::State& state, const Data& d, Answer&& answer) {
  const std::size_t n = d.pairs.size();
  std::size_t hits = 0;
  for (auto _ : state)
    for (std::size_t i = 0; i < n; ++i) hits += answer(d, i);
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * int64_t(n));
  std::vector<bool> answers(n);
  std::size_t yes = 0;
  for (std::size_t i = 0; i < n; ++i) yes += answers[i] = answer(d, i);
  state.counters["disagree"] = disagreements(answers, d.exact);
  state.counters["ambiguous"] = ambiguous(d.exact);
  state.counters["intersecting"] = double(yes);
}

void obb_reference(benchmark::State& state) {
  measure(state, boxes(state),
          [](const BoxData& d, std::size_t i) { return labkit::lab03::test_boxes(d.pairs[i].a, d.pairs[i].b); });
}

#ifdef LABKIT_HAS_FCL
void obb_fcl_obb(benchmark::State& state) {
  measure(state, boxes(state), [](const BoxData& d, std::size_t i) { return d.fcl[i].a.overlap(d.fcl[i].b); });
}

void obb_fcl_collide(benchmark::State& state) {
  measure(state, boxes(state), [](const BoxData& d, std::size_t i) {
    const fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    fcl::collide(d.fcl[i].oa.get(), d.fcl[i].ob.get(), request, result);
    return result.isCollision();
  });
}
#endif

void triangle_reference(benchmark::State& state) {
  measure(state, triangles(state), [](const TriangleData& d, std::size_t i) {
    return labkit::lab03::test_triangles(d.pairs[i].t0, d.pairs[i].t1);
  });
}

void triangle_cgal_epick(benchmark::State& state) {
  measure(state, triangles(state),
          [](const TriangleData& d, std::size_t i) { return CGAL::do_intersect(d.cgal[2 * i], d.cgal[2 * i + 1]); });
}

}  // namespace

// Names: group/implementation/mix, mix 0 typical and 1 hard.
#define LABKIT_BENCH03_BOTH_MIXES(function, name)              \
  BENCHMARK(function)->Name(name)->Arg(0)->ArgName("typical"); \
  BENCHMARK(function)->Name(name)->Arg(1)->ArgName("hard")

LABKIT_BENCH03_BOTH_MIXES(obb_reference, "obb_test/reference");
#ifdef LABKIT_HAS_FCL
LABKIT_BENCH03_BOTH_MIXES(obb_fcl_obb, "obb_test/fcl_obb");
LABKIT_BENCH03_BOTH_MIXES(obb_fcl_collide, "obb_test/fcl_collide");
#endif
LABKIT_BENCH03_BOTH_MIXES(triangle_reference, "triangle_test/reference");
LABKIT_BENCH03_BOTH_MIXES(triangle_cgal_epick, "triangle_test/cgal_epick");
