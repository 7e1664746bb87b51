// Lab 06: trees over a mesh, and the broad phase.
//
// tree_first_hit/IMPL/SIZE: first-hit queries of short segments (a fiftieth of the mesh's
// size, at its surface) on a seeded terrain of about SIZE triangles. Implementations:
// the reference k-d tree (lab 06), CGAL's AABB_tree (Epick, AABB_triangle_primitive,
// first_intersection of the ray a -> b, cut at b), Embree 3 (rtcIntersect1, the segment
// as a ray with tnear 0 and tfar its length, one build thread) and brute force
// (given::segment_triangle on every triangle, on the first few segments only).
// `disagree`: queries on which an answer differs from brute force's, on the segments
// brute force answered: a hit where it found none or the reverse, or a hit whose point
// a + t (b - a) lies farther than 1e-6 of the mesh's size from brute force's.
// Counters: tests_per_query (calls of the segment-triangle test, for the trees that
// count them) and bytes_per_triangle (what a build keeps, over the triangle count).
//
// tree_build/IMPL/SIZE: building those trees on the same meshes; items are triangles.
//
// bsp_build/reference/SIZE and bsp_classify/IMPL/10000: the BSP on a closed sphere mesh
// (on the terrain its fragments explode; bench/NOTES.md), built, then asked inside or
// outside for points, against CGAL's Side_of_triangle_mesh.
//
// broad_phase/IMPL/SIZE: overlapping pairs among SIZE moving spheres, as dense as the
// lab's 2,000 in a cube of side 100, over a run of 100 frames of motion (so that a
// structure kept from frame to frame pays off): the reference is lab 06's
// overlapping_pairs (step 5, a uniform grid built every frame), sweep_and_prune its
// SweepAndPrune (step 6, the sorted ends kept from frame to frame), nanoflann a k-d tree
// rebuilt every frame. Items are the n (n - 1) / 2 pairs each frame covers.
#include "common/generators/meshes.h"
#include "inputs.h"

#include "spatial_trees.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <benchmark/benchmark.h>
#ifdef LABKIT_HAS_NANOFLANN
#include <nanoflann.hpp>
#endif

#ifdef LABKIT_HAS_EMBREE
#include <embree3/rtcore.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <set>

namespace {

using namespace bench;
namespace lab06 = labkit::lab06;

constexpr int kQueries = 10000;

// A first hit as every implementation reports it: where along the segment.
struct First {
  bool hit = false;
  double t = 0.0;
};

// Brute force answers the first few segments: every triangle, for each.
int brute_queries(int triangles) { return triangles <= 10000 ? 2000 : triangles <= 100000 ? 200 : 20; }

First brute_first_hit(const Mesh& mesh, const Segment& s) {
  First best;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const labkit::given::SegmentHit h = labkit::given::segment_triangle(s, mesh.triangle(i));
    if (h.hit && (!best.hit || h.t < best.t)) best = {true, h.t};
  }
  return best;
}

struct TreeInputs {
  explicit TreeInputs(int n) : mesh(terrain(n)), segments(short_segments(mesh, kQueries, 6000 + n)) {
    Vec3 low = mesh.vertices[0], high = low;
    for (const Vec3& v : mesh.vertices) low = low.cwiseMin(v), high = high.cwiseMax(v);
    size = (high - low).norm();
    for (int i = 0; i < brute_queries(n); ++i) brute.push_back(brute_first_hit(mesh, segments[i]));
  }
  const Mesh& mesh;
  std::vector<Segment> segments;
  double size = 0;
  std::vector<First> brute;  // brute force's answers on segments[0 .. brute.size())
};

const TreeInputs& inputs(int n) {
  static std::map<int, std::unique_ptr<TreeInputs>> cache;
  auto& p = cache[n];
  if (!p) p = std::make_unique<TreeInputs>(n);
  return *p;
}

int disagreements(const TreeInputs& in, const std::vector<First>& answers) {
  int n = 0;
  for (std::size_t i = 0; i < in.brute.size() && i < answers.size(); ++i) {
    const First &a = answers[i], &b = in.brute[i];
    const double length = (in.segments[i].b - in.segments[i].a).norm();
    n += a.hit != b.hit || (a.hit && std::abs(a.t - b.t) * length > 1e-6 * in.size);
  }
  return n;
}

// Runs `query` over every segment per iteration, then counts its disagreements with
// brute force. `query(segment)` returns a First.
template <class Query> void measure_queries(benchmark::State& state, const TreeInputs& in, Query&& query) {
  std::size_t hits = 0;
  for (auto _ : state)
    for (const Segment& s : in.segments) hits += query(s).hit;
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * int64_t(in.segments.size()));
  std::vector<First> answers;
  for (std::size_t i = 0; i < in.brute.size(); ++i) answers.push_back(query(in.segments[i]));
  state.counters["disagree"] = disagreements(in, answers);
}

// A query benchmark's structure, built once per size (Google Benchmark calls the
// function several times) and kept, with the bytes its build kept per triangle.
template <class Built> struct Cached {
  std::unique_ptr<Built> built;
  double bytes_per_triangle = 0;
};
template <class Built, class Make> const Cached<Built>& cached(const Mesh& mesh, Make&& make) {
  static std::map<const Mesh*, Cached<Built>> cache;
  Cached<Built>& c = cache[&mesh];
  if (!c.built) {
    const long long before = heap_bytes();
    c.built = make(mesh);
    c.bytes_per_triangle = double(heap_bytes() - before) / double(mesh.size());
  }
  return c;
}

// ---- The reference k-d tree -------------------------------------------------------------

void build_reference(benchmark::State& state) {
  const Mesh& mesh = terrain(int(state.range(0)));
  long long kept = 0;
  for (auto _ : state) {
    const long long before = heap_bytes();
    lab06::KdTree tree = lab06::build_kd_tree(mesh);
    kept = heap_bytes() - before;
    benchmark::DoNotOptimize(tree.nodes.data());
  }
  state.SetItemsProcessed(state.iterations() * int64_t(mesh.size()));
  state.counters["bytes_per_triangle"] = double(kept) / double(mesh.size());
}

void first_hit_reference(benchmark::State& state) {
  const TreeInputs& in = inputs(int(state.range(0)));
  const auto& c = cached<lab06::KdTree>(
      in.mesh, [](const Mesh& m) { return std::make_unique<lab06::KdTree>(lab06::build_kd_tree(m)); });
  const lab06::KdTree& tree = *c.built;
  state.counters["bytes_per_triangle"] = c.bytes_per_triangle;
  long long tests = 0, queries = 0;
  measure_queries(state, in, [&](const Segment& s) {
    const lab06::KdHit h = lab06::first_hit(tree, s);
    tests += h.tests, ++queries;
    return First{h.hit, h.t};
  });
  state.counters["tests_per_query"] = double(tests) / double(queries);
}

// ---- CGAL's AABB_tree ----------------------------------------------------------------------

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalTriangles = std::vector<Epick::Triangle_3>;
using CgalPrimitive = CGAL::AABB_triangle_primitive<Epick, CgalTriangles::const_iterator>;
using CgalTree = CGAL::AABB_tree<CGAL::AABB_traits<Epick, CgalPrimitive>>;

// The tree keeps iterators into the triangles: both are what the build makes (the k-d
// tree, too, keeps its own copy of the triangles).
struct CgalBuilt {
  explicit CgalBuilt(const Mesh& mesh) {
    triangles.reserve(mesh.size());
    const auto point = [](const Vec3& v) { return Epick::Point_3(v.x(), v.y(), v.z()); };
    for (std::size_t i = 0; i < mesh.size(); ++i) {
      const Triangle t = mesh.triangle(i);
      triangles.emplace_back(point(t.v0), point(t.v1), point(t.v2));
    }
    tree.insert(triangles.begin(), triangles.end());
    tree.build();
  }
  CgalTriangles triangles;
  CgalTree tree;
};

void build_cgal(benchmark::State& state) {
  const Mesh& mesh = terrain(int(state.range(0)));
  long long kept = 0;
  for (auto _ : state) {
    const long long before = heap_bytes();
    CgalBuilt built(mesh);
    kept = heap_bytes() - before;
    benchmark::DoNotOptimize(&built.tree);
  }
  state.SetItemsProcessed(state.iterations() * int64_t(mesh.size()));
  state.counters["bytes_per_triangle"] = double(kept) / double(mesh.size());
}

// first_intersection takes a ray: the ray from a through b, whose first hit counts when
// it is no farther than b.
void first_hit_cgal(benchmark::State& state) {
  const TreeInputs& in = inputs(int(state.range(0)));
  const auto& c = cached<CgalBuilt>(in.mesh, [](const Mesh& m) { return std::make_unique<CgalBuilt>(m); });
  const CgalBuilt& built = *c.built;
  state.counters["bytes_per_triangle"] = c.bytes_per_triangle;
  measure_queries(state, in, [&](const Segment& s) {
    const Epick::Point_3 a(s.a.x(), s.a.y(), s.a.z()), b(s.b.x(), s.b.y(), s.b.z());
    const auto result = built.tree.first_intersection(Epick::Ray_3(a, b));
    if (!result) return First{};
    Epick::Point_3 p;
    if (const auto* point = boost::get<Epick::Point_3>(&result->first))
      p = *point;
    else if (const auto* part = boost::get<Epick::Segment_3>(&result->first))  // in the triangle's plane
      p = CGAL::squared_distance(a, part->source()) <= CGAL::squared_distance(a, part->target()) ? part->source()
                                                                                                 : part->target();
    const double t = ((p - a) * (b - a)) / (b - a).squared_length();
    return t <= 1 ? First{true, t} : First{};
  });
}

// ---- Embree 3 ---------------------------------------------------------------------------------
#ifdef LABKIT_HAS_EMBREE

// Embree allocates through its own allocator (mmap for its blocks): its memory monitor
// callback, not mallinfo, sees what a scene keeps.
std::atomic<long long> embree_bytes{0};
bool embree_monitor(void*, ssize_t bytes, bool) {
  embree_bytes += bytes;
  return true;
}

// One device for every scene, made outside the timings: one build thread, like the
// other builds.
RTCDevice embree_device() {
  static const RTCDevice device = [] {
    const RTCDevice d = rtcNewDevice("threads=1");
    rtcSetDeviceMemoryMonitorFunction(d, embree_monitor, nullptr);
    return d;
  }();
  return device;
}

struct EmbreeBuilt {
  explicit EmbreeBuilt(const Mesh& mesh) {
    const RTCDevice device = embree_device();
    const long long before = embree_bytes;
    scene = rtcNewScene(device);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh.vertices.size()));
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = float(mesh.vertices[i][k]);
    auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(unsigned), mesh.size()));
    for (std::size_t i = 0; i < mesh.size(); ++i)
      for (int k = 0; k < 3; ++k) f[3 * i + k] = unsigned(mesh.triangles[i][k]);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene);
    kept = embree_bytes - before;
  }
  ~EmbreeBuilt() { rtcReleaseScene(scene); }
  EmbreeBuilt(const EmbreeBuilt&) = delete;
  EmbreeBuilt& operator=(const EmbreeBuilt&) = delete;
  RTCScene scene;
  long long kept = 0;
};

void build_embree(benchmark::State& state) {
  const Mesh& mesh = terrain(int(state.range(0)));
  long long kept = 0;
  for (auto _ : state) {
    EmbreeBuilt built(mesh);
    kept = built.kept;
  }
  state.SetItemsProcessed(state.iterations() * int64_t(mesh.size()));
  state.counters["bytes_per_triangle"] = double(kept) / double(mesh.size());
}

void first_hit_embree(benchmark::State& state) {
  const TreeInputs& in = inputs(int(state.range(0)));
  const auto& c = cached<EmbreeBuilt>(in.mesh, [](const Mesh& m) { return std::make_unique<EmbreeBuilt>(m); });
  const EmbreeBuilt& built = *c.built;
  state.counters["bytes_per_triangle"] = double(built.kept) / double(in.mesh.size());  // its monitor's count
  measure_queries(state, in, [&](const Segment& s) {
    const Vec3 d = s.b - s.a;
    const double length = d.norm();
    const Vec3 u = d / length;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit r;
    r.ray.org_x = float(s.a.x()), r.ray.org_y = float(s.a.y()), r.ray.org_z = float(s.a.z());
    r.ray.dir_x = float(u.x()), r.ray.dir_y = float(u.y()), r.ray.dir_z = float(u.z());
    r.ray.tnear = 0.0f;
    r.ray.tfar = float(length);
    r.ray.mask = ~0u;
    r.ray.flags = 0;
    r.ray.time = 0.0f;
    r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(built.scene, &context, &r);
    if (r.hit.geomID == RTC_INVALID_GEOMETRY_ID) return First{};
    return First{true, double(r.ray.tfar) / length};
  });
}

#endif

// ---- Brute force ------------------------------------------------------------------------------

void first_hit_brute_force(benchmark::State& state) {
  const TreeInputs& in = inputs(int(state.range(0)));
  const std::size_t n = in.brute.size();
  std::size_t hits = 0;
  for (auto _ : state)
    for (std::size_t i = 0; i < n; ++i) hits += brute_first_hit(in.mesh, in.segments[i]).hit;
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * int64_t(n));
  state.counters["disagree"] = 0;  // it is the yardstick
  state.counters["tests_per_query"] = double(in.mesh.size());
  state.counters["bytes_per_triangle"] = 0;
}

// ---- Broad phase ------------------------------------------------------------------------------

constexpr int kFrames = 100;         // one run of motion: what an iteration of broad_phase times
constexpr int kBruteSubset = 10000;  // brute force at 100k: all pairs among the first 10,000

// Spheres in motion: spread_spheres at the lab's density, each moving at its own constant
// velocity of up to 1 per axis per second, 60 frames a second (so up to 1/60 per axis per
// frame, a small fraction of a radius: the frame-to-frame coherence of a simulation).
struct Spheres {
  explicit Spheres(int n) {
    const double side = 100 * std::cbrt(n / 2000.0);
    start = gen::spread_spheres(n, side, 0.25, 1.0, 7000 + n);
    const std::vector<Sphere> pace = gen::spread_spheres(n, 2.0, 0.0, 0.0, 8000 + n);
    for (int i = 0; i < n; ++i) velocity.push_back((pace[i].center - Vec3(1, 1, 1)) / 60);
  }
  // Frame f: every centre moved f steps along its velocity.
  void frame(int f, std::vector<Sphere>& out) const {
    out = start;
    for (std::size_t i = 0; i < out.size(); ++i) out[i].center += double(f) * velocity[i];
  }
  std::vector<Sphere> start;
  std::vector<Vec3> velocity;
};

const Spheres& spheres(int n) {
  static std::map<int, std::unique_ptr<Spheres>> cache;
  auto& p = cache[n];
  if (!p) p = std::make_unique<Spheres>(n);
  return *p;
}

std::set<std::array<int, 2>> brute_pairs(const std::vector<Sphere>& s, int m) {
  std::set<std::array<int, 2>> pairs;
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      if ((s[i].center - s[j].center).norm() <= s[i].radius + s[j].radius) pairs.insert({i, j});
  return pairs;
}

// Pairs that `got` and brute force disagree on, over the pairs brute force tests on
// `frame` (all of them, or those among the subset).
int disagreements(const std::vector<std::array<int, 2>>& got, const std::vector<Sphere>& frame, int n) {
  const int m = std::min(n, kBruteSubset);
  const std::set<std::array<int, 2>> exact = brute_pairs(frame, m);
  std::set<std::array<int, 2>> mine;
  for (const auto& pair : got)
    if (pair[1] < m) mine.insert(pair);
  int differ = 0;
  for (const auto& pair : mine) differ += !exact.count(pair);
  for (const auto& pair : exact) differ += !mine.count(pair);
  return differ;
}

// Runs of kFrames frames: `start()` makes the state one run keeps (nothing, or a
// SweepAndPrune), `frame(state, spheres)` answers one frame. Counters: disagreements on
// the run's last frame, sphere tests per frame.
template <class Start, class Frame> void broad_phase_runs(benchmark::State& state, Start start, Frame frame) {
  const int n = int(state.range(0));
  const Spheres& in = spheres(n);
  std::vector<Sphere> current;
  long long tests = 0, frames = 0;
  std::vector<std::array<int, 2>> last;
  for (auto _ : state) {
    auto kept = start();
    for (int f = 0; f < kFrames; ++f) {
      in.frame(f, current);
      auto p = frame(kept, current);
      tests += p.tests, ++frames;
      if (f == kFrames - 1) last = std::move(p.pairs);
    }
  }
  state.SetItemsProcessed(state.iterations() * kFrames * (int64_t(n) * (n - 1) / 2));
  in.frame(kFrames - 1, current);
  state.counters["disagree"] = disagreements(last, current, n);
  state.counters["tests_per_query"] = double(tests) / double(frames);
}

// The reference: lab 06's overlapping_pairs (step 5), a uniform grid, every frame.
void broad_phase_reference(benchmark::State& state) {
  broad_phase_runs(
      state, [] { return 0; },
      [](int, const std::vector<Sphere>& spheres) { return lab06::overlapping_pairs(spheres); });
}

// Lab 06's SweepAndPrune (step 6), one object for the whole run, so that every frame
// after the first re-sorts the kept list by insertion and updates the kept pairs. Each
// iteration is a fresh run of kFrames frames (its first frame sorts from scratch).
void broad_phase_sweep_and_prune(benchmark::State& state) {
  broad_phase_runs(
      state, [] { return lab06::SweepAndPrune{}; },
      [](lab06::SweepAndPrune& sweep, const std::vector<Sphere>& spheres) { return sweep.update(spheres); });
}

#ifdef LABKIT_HAS_NANOFLANN
// nanoflann: a k-d tree over the centres, rebuilt every frame (the spheres move), then a
// radius search around each centre out to its radius plus the largest radius; the pairs
// within r_i + r_j are kept, each once (j > i). Its tests are the candidates it returns.
struct Centres {
  const std::vector<Sphere>& spheres;
  std::size_t kdtree_get_point_count() const { return spheres.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t axis) const { return spheres[i].center[int(axis)]; }
  template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};
using CentreTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Centres>, Centres, 3>;

std::vector<std::array<int, 2>> nanoflann_pairs(const std::vector<Sphere>& s, long long& tests) {
  const Centres centres{s};
  const CentreTree tree(3, centres, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  double largest = 0;
  for (const Sphere& x : s) largest = std::max(largest, x.radius);
  std::vector<std::array<int, 2>> pairs;
  std::vector<std::pair<unsigned, double>> near;  // (index, squared distance)
  const nanoflann::SearchParams unsorted(32, 0, false);
  for (std::size_t i = 0; i < s.size(); ++i) {
    near.clear();
    const double reach = s[i].radius + largest;
    tree.radiusSearch(s[i].center.data(), reach * reach * (1 + 1e-12), near, unsorted);  // squared; a hair wider
    tests += static_cast<long long>(near.size());
    for (const auto& found : near) {
      const unsigned j = found.first;
      if (j > i && (s[i].center - s[j].center).norm() <= s[i].radius + s[j].radius) pairs.push_back({int(i), int(j)});
    }
  }
  return pairs;
}

void broad_phase_nanoflann(benchmark::State& state) {
  const int n = int(state.range(0));
  const Spheres& in = spheres(n);
  std::vector<Sphere> current;
  long long tests = 0, frames = 0;
  std::vector<std::array<int, 2>> last;
  for (auto _ : state)
    for (int f = 0; f < kFrames; ++f) {
      in.frame(f, current);
      std::vector<std::array<int, 2>> pairs = nanoflann_pairs(current, tests);
      ++frames;
      if (f == kFrames - 1) last = std::move(pairs);
    }
  state.SetItemsProcessed(state.iterations() * kFrames * (int64_t(n) * (n - 1) / 2));
  in.frame(kFrames - 1, current);
  state.counters["disagree"] = disagreements(last, current, n);
  state.counters["tests_per_query"] = double(tests) / double(frames);  // candidates per frame
}
#endif

// One frame per iteration (brute force over kFrames frames would take minutes). At 100k
// (5e9 pairs a frame), brute force covers the first kBruteSubset spheres: its
// items are the pairs it tested, so its pairs per second stand for the whole frame's.
void broad_phase_brute_force(benchmark::State& state) {
  const int n = int(state.range(0)), m = std::min(n, kBruteSubset);
  const Spheres& in = spheres(n);
  std::vector<Sphere> s;
  long long frames = 0, found = 0;
  for (auto _ : state) {
    in.frame(int(frames++ % kFrames), s);
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j) found += (s[i].center - s[j].center).norm() <= s[i].radius + s[j].radius;
  }
  benchmark::DoNotOptimize(found);
  state.SetItemsProcessed(state.iterations() * (int64_t(m) * (m - 1) / 2));
  state.counters["disagree"] = 0;  // the yardstick
  state.counters["tests_per_query"] = double(int64_t(m) * (m - 1) / 2);
}

// ---- BSP (lab 06 step 3) ------------------------------------------------------------------------

// The auto-partition over a closed convex mesh, gen::sphere_mesh(SIZE): every triangle's
// plane has the rest of the mesh behind it, so the tree is a chain as long as the mesh and
// the build is O(n^2). Sizes stop at 10k (20k takes about 20 s).
const Mesh& sphere(int n) {
  static std::map<int, Mesh> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, labkit::gen::sphere_mesh(n, Vec3(0.5, 0.5, 0.5), 0.5)).first;
  return it->second;
}

void bsp_build(benchmark::State& state) {
  const Mesh& mesh = sphere(int(state.range(0)));
  std::size_t nodes = 0;
  for (auto _ : state) {
    const lab06::BspTree tree = lab06::build_bsp(mesh);
    nodes = tree.nodes.size();
    benchmark::DoNotOptimize(tree.nodes.data());
  }
  state.SetItemsProcessed(state.iterations() * int64_t(mesh.size()));
  state.counters["nodes"] = double(nodes);
}

// Classify: inside or outside for 10,000 points spread over the sphere's box (about half
// inside), the BSP against CGAL's Side_of_triangle_mesh (an AABB tree and ray parity,
// exact predicates) on the same mesh; both built before the timing.
using SurfaceMesh = CGAL::Surface_mesh<Epick::Point_3>;

std::vector<Vec3> box_points(int count) {
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points(std::size_t(count), Vec3::Zero());
  for (Vec3& p : points) p = Vec3(unit(random), unit(random), unit(random));
  return points;
}

SurfaceMesh surface_of(const Mesh& mesh) {
  SurfaceMesh surface;
  std::vector<SurfaceMesh::Vertex_index> corner;
  for (const Vec3& v : mesh.vertices) corner.push_back(surface.add_vertex(Epick::Point_3(v.x(), v.y(), v.z())));
  for (const auto& t : mesh.triangles) surface.add_face(corner[t[0]], corner[t[1]], corner[t[2]]);
  return surface;
}

std::vector<bool> cgal_inside(const Mesh& mesh, const std::vector<Vec3>& points) {
  const SurfaceMesh surface = surface_of(mesh);
  const CGAL::Side_of_triangle_mesh<SurfaceMesh, Epick> side(surface);
  std::vector<bool> inside;
  for (const Vec3& p : points) inside.push_back(side(Epick::Point_3(p.x(), p.y(), p.z())) != CGAL::ON_UNBOUNDED_SIDE);
  return inside;
}

void bsp_classify_reference(benchmark::State& state) {
  const Mesh& mesh = sphere(int(state.range(0)));
  const std::vector<Vec3> points = box_points(kQueries);
  const lab06::BspTree tree = lab06::build_bsp(mesh);
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(lab06::classify(tree, points[k++ % points.size()]));
  state.SetItemsProcessed(state.iterations());
  const std::vector<bool> exact = cgal_inside(mesh, points);
  int differ = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    differ += (lab06::classify(tree, points[i]) != lab06::Where::outside) != exact[i];
  state.counters["disagree"] = differ;
}

void bsp_classify_cgal(benchmark::State& state) {
  const Mesh& mesh = sphere(int(state.range(0)));
  const std::vector<Vec3> points = box_points(kQueries);
  const SurfaceMesh surface = surface_of(mesh);
  const CGAL::Side_of_triangle_mesh<SurfaceMesh, Epick> side(surface);
  std::size_t k = 0;
  for (auto _ : state) {
    const Vec3& p = points[k++ % points.size()];
    benchmark::DoNotOptimize(side(Epick::Point_3(p.x(), p.y(), p.z())));
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["disagree"] = 0;  // the yardstick
}

}  // namespace

// Names group/implementation/SIZE: the report fits the scaling exponent over SIZE.
#define LABKIT_TREE_SIZES(function, name)                                      \
  BENCHMARK(function)->Name(name)->Arg(10000)->Unit(benchmark::kMillisecond);  \
  BENCHMARK(function)->Name(name)->Arg(100000)->Unit(benchmark::kMillisecond); \
  BENCHMARK(function)->Name(name)->Arg(1000000)->Unit(benchmark::kMillisecond)

LABKIT_TREE_SIZES(first_hit_reference, "tree_first_hit/reference");
LABKIT_TREE_SIZES(first_hit_cgal, "tree_first_hit/cgal_aabb_tree");
#ifdef LABKIT_HAS_EMBREE
LABKIT_TREE_SIZES(first_hit_embree, "tree_first_hit/embree");
#endif
LABKIT_TREE_SIZES(first_hit_brute_force, "tree_first_hit/brute_force");
LABKIT_TREE_SIZES(build_reference, "tree_build/reference");
LABKIT_TREE_SIZES(build_cgal, "tree_build/cgal_aabb_tree");
#ifdef LABKIT_HAS_EMBREE
LABKIT_TREE_SIZES(build_embree, "tree_build/embree");
#endif

BENCHMARK(bsp_build)->Name("bsp_build/reference")->Arg(2500)->Arg(5000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(bsp_classify_reference)->Name("bsp_classify/reference")->Arg(10000);
BENCHMARK(bsp_classify_cgal)->Name("bsp_classify/cgal_side_of_triangle_mesh")->Arg(10000);

BENCHMARK(broad_phase_reference)->Name("broad_phase/reference")->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(broad_phase_sweep_and_prune)
    ->Name("broad_phase/sweep_and_prune")
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);
#ifdef LABKIT_HAS_NANOFLANN
BENCHMARK(broad_phase_nanoflann)->Name("broad_phase/nanoflann")->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
#endif
BENCHMARK(broad_phase_brute_force)
    ->Name("broad_phase/brute_force")
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);
