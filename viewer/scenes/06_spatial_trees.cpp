// Lab 06 scene: BSP and k-d trees, pair reduction (handouts/06_spatial_trees.md).
//
// A replay token's query picks the mode:
//   k-d tree   build_kd_tree, first_hit, any_hit, all_hits (and robust.*)    steps 1-2
//   BSP tree   build_bsp, classify, back_to_front (and robust.*)             steps 3-4
//   spheres    overlapping_pairs (and robust.*)                              step 5
//   frames     sweep_frames (and robust.*): the last two frames' ends on x     step 6
//              (handles move the last frame's spheres; the swapped ends are orange)
//   OBB trees  colliding_triangles: two meshes, the leaf boxes reached, the pairs step 7
// In the k-d tree mode the segment's ends are handles: the leaves whose cells it meets
// are drawn as boxes, the student's first hit in its verdict's colour, the exact hits
// (the toggle) as violet rings. When step 1 is still a stub, the queries run on the
// checker's own tree, as the tests do.
#include "viewer/scenes/scenes.h"

#include "06_spatial_trees.judge.h"
#include "common/generators/meshes.h"
#include "common/given/segment_triangle.h"
#include "common/oracle/oracle.h"
#include "spatial_trees.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace viewer {
namespace {

using namespace labkit;
using namespace labkit::lab06;

enum class Mode { kd, bsp, spheres, frames, bvh };

const std::vector<Preset> kPresets = {
    {"torus", "a k-d tree over a torus of 2,048 triangles: the leaves a segment visits, front to back", nullptr, false, -50, 35, 2},
    {"walk", "step 2: the leaves a segment meets, numbered front to back; first_hit stops in leaf 8, after its hit at t = 0.676 (grey: never visited)", nullptr, true, -90, 89, 2},
    {"handout", "step 2's example: a hit beyond the first leaf's end does not end the search", nullptr, false, -80, 20, 2},
    {"terrain", "a terrain of 20,000 triangles, a long segment across it", nullptr, false, -40, 30, 2},
    {"bsp", "a BSP tree of an L of three cubes: classify a point, paint back to front", nullptr, false, -35, 25, 3},
    {"split", "step 3: the floor's plane z = 0, the root's, cuts the wall in two: a piece in front, one behind", nullptr, true, -75, 18, 3},
    {"spheres", "sort and sweep: 60 spheres, the pairs that meet", nullptr, false, -60, 30, 5},
    {"sweep", "step 5: the intervals on x, ends A0 A1 R0 B0 R1 C0 C1 B1; two pairs tested", nullptr, true, -90, 89, 5},
    {"bvh", "step 7: two OBB trees; the leaf boxes whose pairs the traversal reaches, the triangles that meet", nullptr, true, -60, 30, 7},
    {"coherence", "step 6: C moves 2 to the left; its end C0 = 6 passes R1 = 7: one swap, and {R, C} joins the pairs on x", nullptr, true, -90, 89, 6},
};

// The leaves of a k-d tree with their cells, or why the tree cannot be walked.
struct LeafBox {
  int node;
  Aabb cell;
};

std::vector<LeafBox> leaves_of(const KdTree& tree) {
  std::vector<LeafBox> out;
  if (tree.nodes.empty()) return out;
  struct Todo {
    int node;
    Aabb cell;
    int depth;
  };
  std::vector<Todo> todo{{0, tree.bounds, 0}};
  while (!todo.empty() && out.size() < 200000) {
    const Todo t = todo.back();
    todo.pop_back();
    if (t.node < 0 || std::size_t(t.node) >= tree.nodes.size() || t.depth > kMaxDepth) continue;  // malformed: the judge says why
    const KdNode& n = tree.nodes[std::size_t(t.node)];
    if (n.axis == kLeaf || n.axis < 0 || n.axis > 2) {
      out.push_back({t.node, t.cell});
      continue;
    }
    Aabb below = t.cell, above = t.cell;
    below.max[n.axis] = above.min[n.axis] = n.split;
    todo.push_back({n.index, above, t.depth + 1});
    todo.push_back({t.node + 1, below, t.depth + 1});
  }
  return out;
}

// A k-d tree for the "walk" figure: the cell halved in x, then y, then x..., `depth`
// levels, triangles sent by their boxes (step 1's rule). No split in z, so that seen from
// above every leaf is one rectangle.
KdTree median_tree(const Mesh& mesh, int depth) {
  KdTree tree;
  tree.triangles.resize(mesh.size());
  std::vector<int> all(mesh.size());
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    tree.triangles[i] = mesh.triangle(i), all[i] = int(i);
    for (int k = 0; k < 3; ++k) {
      const Vec3& v = tree.triangles[i][k];
      tree.bounds.min = i + std::size_t(k) == 0 ? v : Vec3(tree.bounds.min.cwiseMin(v));
      tree.bounds.max = i + std::size_t(k) == 0 ? v : Vec3(tree.bounds.max.cwiseMax(v));
    }
  }
  const auto build = [&](auto&& self, const Aabb& cell, const std::vector<int>& list, int level) -> void {
    const std::size_t at = tree.nodes.size();
    tree.nodes.push_back({});
    if (level == depth) {
      tree.nodes[at].index = int(tree.items.size());
      tree.items.push_back(int(list.size()));
      tree.items.insert(tree.items.end(), list.begin(), list.end());
      return;
    }
    const int axis = level % 2;
    const double split = 0.5 * (cell.min[axis] + cell.max[axis]);
    std::vector<int> below, above;
    for (int i : list) {
      const Triangle& t = tree.triangles[std::size_t(i)];
      const double lo = std::min({t.v0[axis], t.v1[axis], t.v2[axis]}), hi = std::max({t.v0[axis], t.v1[axis], t.v2[axis]});
      if (lo <= split) below.push_back(i);
      if (hi >= split) above.push_back(i);
    }
    Aabb b = cell, a = cell;
    b.max[axis] = a.min[axis] = split;
    tree.nodes[at].axis = axis, tree.nodes[at].split = split;
    self(self, b, below, level + 1);
    tree.nodes[at].index = int(tree.nodes.size());
    self(self, a, above, level + 1);
  };
  build(build, tree.bounds, all, 0);
  return tree;
}

// The part [t0, t1] of the segment inside the closed box (t0 > t1: it misses the box).
// Slab by slab, as the handout clips.
std::array<double, 2> segment_span(const Aabb& box, const Segment& s) {
  double t0 = 0, t1 = 1;
  const Vec3 d = s.b - s.a;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0) {
      if (s.a[i] < box.min[i] || s.a[i] > box.max[i]) return {1, 0};
      continue;
    }
    double enter = (box.min[i] - s.a[i]) / d[i], leave = (box.max[i] - s.a[i]) / d[i];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter), t1 = std::min(t1, leave);
  }
  return {t0, t1};
}

bool segment_meets(const Aabb& box, const Segment& s) {
  const auto span = segment_span(box, s);
  return span[0] <= span[1];
}

void draw_box(Renderer& r, const Aabb& b, Color c, float width) {
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int k = 0; k < 4; ++k) {
      Vec3 p = b.min, q;
      if (k & 1) p[u] = b.max[u];
      if (k & 2) p[v] = b.max[v];
      q = p;
      q[axis] = b.max[axis];
      r.line(p, q, c, width);
    }
  }
}

// A sphere as three great circles.
void draw_sphere(Renderer& r, const Sphere& s, Color c, float width) {
  constexpr int kSegments = 32;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 u = Vec3::Unit((axis + 1) % 3), v = Vec3::Unit((axis + 2) % 3);
    for (int k = 0; k < kSegments; ++k) {
      const double a0 = 2 * M_PI * k / kSegments, a1 = 2 * M_PI * (k + 1) / kSegments;
      r.line(s.center + s.radius * (std::cos(a0) * u + std::sin(a0) * v), s.center + s.radius * (std::cos(a1) * u + std::sin(a1) * v),
             c, width);
    }
  }
}


class SpatialTreesScene : public Scene {
 public:
  explicit SpatialTreesScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void frame_inputs();
  void update_kd();
  void update_bsp();
  void update_spheres();
  void update_frames();
  void update_bvh();
  void draw_bvh(Frame& f);
  void draw_frames(Frame& f);
  void draw_kd(Frame& f);
  void draw_bsp(Frame& f);
  void draw_spheres(Frame& f);

  Mode mode_ = Mode::kd;
  Mesh mesh_;
  Segment segment_{{-0.2, 0.3, 0.8}, {1.2, 0.7, 0.3}};
  Vec3 point_ = Vec3::Zero();
  std::vector<Sphere> spheres_;
  int tree_seed_ = 0;
  std::string figure_;  // the preset's name: "walk", "split" and "sweep" draw the handout's figures
  std::optional<KdTree> given_tree_;  // a replayed example's hand-made tree: none here, the checker's otherwise

  // Step 1 and 2: the tree the queries ran on, and the answers.
  Attempt<KdTree> built_;
  KdTree tree_;
  bool tree_is_students_ = false;
  std::vector<LeafBox> leaves_;
  Attempt<KdHit> first_, any_;
  Attempt<KdHits> all_;
  std::vector<oracle::Crossing> exact_hits_;
  // Steps 3 and 4.
  Attempt<BspTree> bsp_;
  Attempt<Where> where_;
  Attempt<std::vector<int>> order_;
  int exact_where_ = 0;
  // Step 5.
  Attempt<SpherePairs> pairs_;
  std::vector<std::array<int, 2>> exact_pairs_;
  // Step 6: the frames (the last one is spheres_, which the handles move) and the runs.
  std::vector<std::vector<Sphere>> frames_;
  Attempt<SweepRuns> runs_;
  // Step 7: the second mesh, the checker's trees, the answer, the leaf pairs reached.
  Mesh mesh_b_;
  int tree_seed_b_ = 0;
  ObbTree tree_a_, tree_b_;
  Attempt<BvhRun> bvh_;
  std::vector<std::array<int, 2>> leaf_pairs_;
  Verdict verdict_[10] = {};
};

// ---- setup ---------------------------------------------------------------------------

SpatialTreesScene::SpatialTreesScene(const Setup& setup) {
  const Preset* preset = view_preset(kPresets, setup);
  if (setup.token.empty() && (!preset || !preset->token)) {
    const std::string name = preset ? preset->name : "torus";
    figure_ = name;
    if (name == "walk") {  // 48 small tilted triangles in a thin slab, seen from above: the cells are rectangles
      std::uint64_t state = 7;
      const auto next = [&state] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return double(state >> 11) / double(1ULL << 53);
      };
      for (int i = 0; i < 24; ++i) {
        const double x = 0.5 + 7 * next(), y = 0.3 + 3.4 * next(), a = 2 * M_PI * next();  // in this order
        const Vec3 c(x, y, 0);
        const int base = int(mesh_.vertices.size());
        for (int k = 0; k < 3; ++k)
          mesh_.vertices.push_back(c + Vec3(0.35 * std::cos(a + 2.1 * k), 0.35 * std::sin(a + 2.1 * k), 0.12 * (k - 1)));
        mesh_.triangles.push_back({base, base + 1, base + 2});
      }
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
    } else if (name == "spheres") {
      mode_ = Mode::spheres;
      spheres_ = gen::spread_spheres(60, 10, 0.3, 1.2, 5);
    } else {
      mesh_ = gen::torus_mesh(2048, Vec3(0.5, 0.5, 0.5), 0.35, 0.12);
    }
    frame_inputs();
    return;
  }
  const ParsedToken token = parse_token(starting_token(setup, kPresets, ""));
  std::string q = token.query;
  if (q.rfind("robust.", 0) == 0) q = q.substr(7);
  if (q == "first_hit" || q == "any_hit" || q == "all_hits" || q == "segment_queries") {
    const auto in = input_from_token<TreeQuery>(token);
    mesh_ = in.mesh, segment_ = in.segment, tree_seed_ = in.tree;
  } else if (q == "build_kd_tree" || q == "build_kd_tree.lattice") {
    mesh_ = input_from_token<Mesh>(token);
    if (mesh_.size() > 0) segment_ = {mesh_.vertices[0] - Vec3(1, 1, 1), mesh_.vertices.back() + Vec3(1, 1, 1)};
  } else if (q == "build_bsp") {
    mode_ = Mode::bsp;
    mesh_ = input_from_token<Mesh>(token);
    if (!mesh_.vertices.empty()) point_ = mesh_.vertices[0];
  } else if (q == "classify" || q == "back_to_front") {
    mode_ = Mode::bsp;
    const auto in = input_from_token<PointQuery>(token);
    mesh_ = in.mesh, point_ = in.point;
  } else if (q == "overlapping_pairs") {
    mode_ = Mode::spheres;
    spheres_ = input_from_token<SphereSet>(token).spheres;
  } else if (q == "colliding_triangles") {
    mode_ = Mode::bvh;
    const auto in = input_from_token<BvhQuery>(token);
    mesh_ = in.a, mesh_b_ = in.b, tree_seed_ = in.tree_a, tree_seed_b_ = in.tree_b;
  } else if (q == "sweep_frames" || q == "sweep_frames.moving") {
    mode_ = Mode::frames;
    frames_ = q == "sweep_frames" ? input_from_token<SweepCase>(token).frames : judge::moving_spheres(input_from_token<MovingSpheres>(token)).frames;
    if (frames_.empty()) frames_.push_back({});
    spheres_ = frames_.back();
  } else {
    throw unknown_query("06", token.query, "build_kd_tree, first_hit, any_hit, all_hits, build_bsp, classify, back_to_front, "
                                           "overlapping_pairs, sweep_frames, colliding_triangles (and their robust. forms)");
  }
  frame_inputs();
}

void SpatialTreesScene::frame_inputs() {
  const char* names[] = {"k-d tree and segment", "BSP tree and point", "spheres", "spheres over frames", "two OBB trees"};
  mode = names[int(mode_)];
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh_.vertices) box.extend(v);
  for (const Vec3& v : mesh_b_.vertices) box.extend(v);
  if (mode_ == Mode::kd) box.extend(segment_.a), box.extend(segment_.b);
  if (mode_ == Mode::bsp) box.extend(point_);
  for (const Sphere& s : spheres_) box.extend(s.center + Vec3::Constant(s.radius)), box.extend(s.center - Vec3::Constant(s.radius));
  if (figure_ == "sweep") box.extend(Vec3(0, -7.5, 0));
  if (mode_ == Mode::frames && !box.isEmpty()) box.extend(Vec3(box.min().x(), box.min().y() - 0.3 * box.diagonal().norm(), 0));
  if (box.isEmpty()) box.extend(Vec3::Zero()), box.extend(Vec3::Ones());
  frame(box);
}

// ---- update --------------------------------------------------------------------------

void SpatialTreesScene::update() {
  steps.clear();
  if (mode_ == Mode::kd) update_kd();
  if (mode_ == Mode::bsp) update_bsp();
  if (mode_ == Mode::spheres) update_spheres();
  if (mode_ == Mode::frames) update_frames();
  if (mode_ == Mode::bvh) update_bvh();
}

void SpatialTreesScene::update_kd() {
  // Step 1: the student's tree, judged against the exact rule (only on small meshes: the
  // judge tests every triangle against every leaf).
  built_ = attempt([&] { return build_kd_tree(mesh_); });
  Step s1 = judged("L06S1", "build_kd_tree", built_, [&](const KdTree& got) {
    return mesh_.size() <= 5000 ? judge::kd_tree(mesh_, got) : check::pass();
  });
  if (built_) {
    s1.rows = {{"nodes", std::to_string(built_->nodes.size()), ""},
               {"items (counts and indices)", std::to_string(built_->items.size()), ""},
               {"leaves", std::to_string(leaves_of(*built_).size()), ""}};
    if (mesh_.size() > 5000) s1.note = "a big mesh: the tree's rule is checked only up to 5,000 triangles";
  }
  verdict_[1] = s1.verdict;
  steps.push_back(s1);
  tree_is_students_ = built_ && s1.verdict != Verdict::disagree;
  tree_ = tree_is_students_ ? *built_ : judge::checker_tree(mesh_, tree_seed_);
  if (figure_ == "walk") tree_ = median_tree(mesh_, 5), tree_is_students_ = false;  // a tree drawn flat
  leaves_ = leaves_of(tree_);

  // Step 2: the three queries, with the given test's calls counted.
  const TreeQuery in{mesh_, segment_, tree_seed_};
  std::uint64_t calls[3] = {};
  const auto counted = [&](int k, auto&& call) {
    const std::uint64_t before = given::segment_triangle_calls();
    auto a = attempt(call);
    calls[k] = given::segment_triangle_calls() - before;
    return a;
  };
  first_ = counted(0, [&] { return first_hit(tree_, segment_); });
  any_ = counted(1, [&] { return any_hit(tree_, segment_); });
  all_ = counted(2, [&] { return all_hits(tree_, segment_); });
  exact_hits_ = oracle::segment_mesh_crossings(segment_, mesh_);
  Step s2 = judged("L06S2", std::string("first_hit, any_hit, all_hits on ") + (tree_is_students_ ? "your tree" : "the checker's tree"),
                   first_, [&](const KdHit& got) { return judge::first_hit(in, tree_, got, calls[0]); });
  join(s2, any_, [&](const KdHit& got) { return judge::any_hit(in, tree_, got, calls[1]); });
  join(s2, all_, [&](const KdHits& got) { return judge::all_hits(in, tree_, got, calls[2]); });
  int met = 0;
  for (const LeafBox& l : leaves_) met += segment_meets(l.cell, segment_);
  const auto hit_text = [](const Attempt<KdHit>& h) {
    return h ? (h->hit ? std::to_string(h->triangle) + " at t = " + num(h->t) : std::string("none")) : std::string();
  };
  s2.rows = {{"first hit", hit_text(first_), exact_hits_.empty() ? "none" : std::to_string(exact_hits_[0].triangle) + " at t = " + num(exact_hits_[0].t)},
             {"any hit", any_ ? yes_no(any_->hit) : "", yes_no(!exact_hits_.empty())},
             {"all hits", all_ ? std::to_string(all_->hits.size()) : "", std::to_string(exact_hits_.size())},
             {"tests: first / any / all", first_ && any_ && all_ ? std::to_string(first_->tests) + " / " + std::to_string(any_->tests) + " / " +
                                                                       std::to_string(all_->tests)
                                                                 : "",
              "brute force: " + std::to_string(mesh_.size())},
             {"leaves the segment meets", std::to_string(met), "of " + std::to_string(leaves_.size())}};
  if (!tree_is_students_ && s2.note.empty()) s2.note = "step 1 is not done: the queries run on the checker's tree";
  verdict_[2] = s2.verdict;
  steps.push_back(s2);
}

void SpatialTreesScene::update_bsp() {
  bsp_ = attempt([&] { return build_bsp(mesh_); });
  const PointQuery in{mesh_, point_};
  exact_where_ = oracle::point_in_solid(point_, mesh_);
  const Where exact = exact_where_ > 0 ? Where::inside : (exact_where_ < 0 ? Where::outside : Where::on);
  Step s3 = judged("L06S3", "build_bsp, classify", bsp_, [&](const BspTree& got) { return judge::bsp_tree(mesh_, got); });
  if (bsp_) {
    where_ = attempt([&] { return classify(*bsp_, point_); });
    join(s3, where_, [&](Where got) { return judge::classify(in, got); });
    s3.rows = {{"nodes, pieces", std::to_string(bsp_->nodes.size()) + ", " + std::to_string(bsp_->pieces.size()), ""},
               {"the point is", where_ ? describe(*where_) : "", describe(exact)}};
  }
  verdict_[3] = s3.verdict;
  steps.push_back(s3);
  if (!bsp_ || s3.verdict == Verdict::disagree || verdict_[3] == Verdict::stub) {
    steps.push_back({"L06S4", "back_to_front", Verdict::none, {}, "needs a valid BSP tree (step 3) first"});
    verdict_[4] = Verdict::none;
    order_ = {};
    return;
  }
  order_ = attempt([&] { return back_to_front(*bsp_, point_); });
  Step s4 = judged("L06S4", "back_to_front from the point as eye", order_,
                   [&](const std::vector<int>& got) { return judge::back_to_front(in, *bsp_, got); });
  if (order_) s4.rows = {{"pieces listed", std::to_string(order_->size()), std::to_string(bsp_->pieces.size())}};
  verdict_[4] = s4.verdict;
  steps.push_back(s4);
}

void SpatialTreesScene::update_spheres() {
  pairs_ = attempt([&] { return overlapping_pairs(spheres_); });
  exact_pairs_ = oracle::meeting_pairs(spheres_);
  const SphereSet in{spheres_};
  Step s5 = judged("L06S5", "overlapping_pairs", pairs_, [&](const SpherePairs& got) { return judge::overlapping_pairs(in, got); });
  const long long n = (long long)spheres_.size();
  s5.rows = {{"pairs", pairs_ ? std::to_string(pairs_->pairs.size()) : "", std::to_string(exact_pairs_.size())},
             {"pair tests", pairs_ ? std::to_string(pairs_->tests) : "", "brute force: " + std::to_string(n * (n - 1) / 2)}};
  verdict_[5] = s5.verdict;
  steps.push_back(s5);
}

void SpatialTreesScene::update_frames() {
  frames_.back() = spheres_;
  const SweepCase in{frames_};
  runs_ = attempt([&] {
    SweepAndPrune sweep;
    SweepRuns runs;
    for (const std::vector<Sphere>& spheres : frames_) {
      const long long before = compare_ends_calls();
      SweepRun r;
      r.frame = sweep.update(spheres);
      r.comparisons = compare_ends_calls() - before;
      runs.push_back(r);
    }
    return runs;
  });
  exact_pairs_ = oracle::meeting_pairs(spheres_);
  Step s6 = judged("L06S6", "SweepAndPrune::update, frame after frame", runs_, [&](const SweepRuns& got) { return judge::sweep_frames(in, got); });
  if (runs_ && !runs_->empty()) {
    const SweepRun& last = runs_->back();
    const std::size_t k = frames_.size();
    const long long changed = k > 1 ? judge::changed_order(frames_[k - 2], frames_[k - 1]) : 0;
    s6.rows = {{"pairs (last frame)", std::to_string(last.frame.pairs.size()), std::to_string(exact_pairs_.size())},
               {"swaps", std::to_string(last.frame.swaps), k > 1 ? "at most " + std::to_string(changed) + " (ends whose order changed)" : "first frame: any sort"},
               {"compare_ends calls", std::to_string(last.comparisons), k > 1 ? "at most " + std::to_string(2 * spheres_.size() + std::size_t(changed)) : ""},
               {"tests", std::to_string(last.frame.tests), "brute force: " + std::to_string(spheres_.size() * (spheres_.size() - 1) / 2)}};
  }
  verdict_[6] = s6.verdict;
  steps.push_back(s6);
}

// The last two frames: the spheres now (the previous centres as faint points), and below
// them each frame's ends on x, the ends whose order changed in orange.
void SpatialTreesScene::draw_frames(Frame& f) {
  Renderer& r = f.render;
  const std::vector<Sphere>& now = frames_.back();
  const std::vector<Sphere>& was = frames_.size() > 1 ? frames_[frames_.size() - 2] : frames_.back();
  const bool figure = figure_ == "coherence";
  const auto name = [&](std::size_t i) { return figure && i < 4 ? std::string(1, "ARBC"[i]) : std::to_string(i); };
  const Color c = colour(verdict_[6]);
  std::vector<char> paired(now.size(), 0);
  if (runs_ && !runs_->empty())
    for (const auto& p : runs_->back().frame.pairs)
      if (p[0] >= 0 && p[1] >= 0 && std::size_t(p[0]) < now.size() && std::size_t(p[1]) < now.size()) {
        paired[std::size_t(p[0])] = paired[std::size_t(p[1])] = 1;
        r.line(now[std::size_t(p[0])].center, now[std::size_t(p[1])].center, c, 3);
      }
  double low = 0, left = 0, right = 1;
  for (std::size_t i = 0; i < now.size(); ++i) {
    const Sphere& b = now[i];
    constexpr int kCircle = 48;
    for (int k = 0; k < kCircle; ++k) {
      const double a0 = 2 * M_PI * k / kCircle, a1 = 2 * M_PI * (k + 1) / kCircle;
      r.line(b.center + b.radius * Vec3(std::cos(a0), std::sin(a0), 0), b.center + b.radius * Vec3(std::cos(a1), std::sin(a1), 0),
             paired[i] ? c : palette::surface, paired[i] ? 2.0f : 1.2f);
    }
    if (was[i].center != b.center) r.point(was[i].center, palette::muted, 3), r.arrow(was[i].center, b.center, palette::muted, 1.5f);
    if (now.size() <= 16) r.label(b.center, name(i), palette::input, 6, -6);
    low = i == 0 ? b.center.y() - b.radius : std::min(low, b.center.y() - b.radius);
    left = i == 0 ? b.center.x() - b.radius : std::min({left, b.center.x() - b.radius, was[i].center.x() - was[i].radius});
    right = i == 0 ? b.center.x() + b.radius : std::max({right, b.center.x() + b.radius, was[i].center.x() + was[i].radius});
  }
  if (now.empty() || now.size() > 64) return;
  // The ends of both frames on two axes; an end is orange when its order against some other end changed.
  const double gap = 0.08 * (right - left + 1e-300);
  const double y_was = low - 2 * gap, y_now = low - 5 * gap;
  std::vector<char> moved(2 * now.size(), 0);
  const auto value = [](const std::vector<Sphere>& s, std::size_t e) { return e % 2 ? s[e / 2].center.x() + s[e / 2].radius : s[e / 2].center.x() - s[e / 2].radius; };
  for (std::size_t p = 0; p < moved.size(); ++p)
    for (std::size_t q = 0; q < moved.size(); ++q) {
      const double a = value(was, p) - value(was, q), b = value(now, p) - value(now, q);
      if ((a > 0) - (a < 0) != (b > 0) - (b < 0)) moved[p] = 1;
    }
  const Color swapped{0.95f, 0.62f, 0.20f};
  for (const auto& [y, frame, title] : {std::tuple{y_was, &was, "previous frame"}, std::tuple{y_now, &now, "this frame"}}) {
    r.arrow({left - gap, y, 0}, {right + 2 * gap, y, 0}, palette::muted, 1.2f);
    r.label({right + 2 * gap, y, 0}, title, palette::muted, 8, -6);
    for (std::size_t e = 0; e < moved.size(); ++e) {
      const double x = value(*frame, e);
      const Color col = moved[e] && frame == &now ? swapped : palette::input;
      r.point({x, y, 0}, col, 4);
      if (now.size() <= 12) r.label({x, y, 0}, name(e / 2) + (e % 2 ? "1" : "0"), col, -8, (e % 2 ? 8.0f : -22.0f));
    }
  }
  for (std::size_t e = 0; e < moved.size(); ++e)
    if (moved[e]) r.dashed({value(was, e), y_was, 0}, {value(now, e), y_now, 0}, swapped, 1.5f);
}

void SpatialTreesScene::update_bvh() {
  tree_a_ = judge::obb_tree(mesh_, tree_seed_), tree_b_ = judge::obb_tree(mesh_b_, tree_seed_b_);
  const BvhQuery in{mesh_, mesh_b_, tree_seed_, tree_seed_b_, true};
  bvh_ = attempt([&] {
    BvhRun r;
    const long long boxes = given_box_tests(), triangles = given_triangle_tests();
    r.answer = colliding_triangles(tree_a_, tree_b_, true);
    r.box_calls = given_box_tests() - boxes, r.triangle_calls = given_triangle_tests() - triangles;
    return r;
  });
  Step s7 = judged("L06S7", "colliding_triangles on the checker's OBB trees", bvh_,
                   [&](const BvhRun& got) { return judge::colliding_triangles(in, tree_a_, tree_b_, got); });
  // The leaf pairs the header's traversal reaches with overlapping boxes: drawn as boxes.
  leaf_pairs_.clear();
  if (!tree_a_.nodes.empty() && !tree_b_.nodes.empty()) {
    std::vector<std::array<int, 2>> todo{{0, 0}};
    while (!todo.empty()) {
      const auto [i, j] = todo.back();
      todo.pop_back();
      const ObbNode& na = tree_a_.nodes[std::size_t(i)];
      const ObbNode& nb = tree_b_.nodes[std::size_t(j)];
      if (!given_boxes_overlap(na.box, nb.box)) continue;
      const bool leaf_a = na.left < 0, leaf_b = nb.left < 0;
      if (leaf_a && leaf_b) {
        leaf_pairs_.push_back({i, j});
        continue;
      }
      const auto volume = [](const ObbNode& n) { return n.box.half_extents[0] * n.box.half_extents[1] * n.box.half_extents[2]; };
      if (leaf_b || (!leaf_a && volume(na) >= volume(nb))) {
        todo.push_back({na.right, j}), todo.push_back({na.left, j});
      } else {
        todo.push_back({i, nb.right}), todo.push_back({i, nb.left});
      }
    }
  }
  if (bvh_)
    s7.rows = {{"pairs that meet", std::to_string(bvh_->answer.pairs.size()), ""},
               {"box tests", std::to_string(bvh_->answer.box_tests), "brute force: no boxes, " + std::to_string(mesh_.size() * mesh_b_.size()) + " triangle pairs"},
               {"triangle tests", std::to_string(bvh_->answer.triangle_tests), "leaf pairs reached: " + std::to_string(leaf_pairs_.size())}};
  verdict_[7] = s7.verdict;
  steps.push_back(s7);
}

void SpatialTreesScene::draw_bvh(Frame& f) {
  Renderer& r = f.render;
  const Color other{0.95f, 0.62f, 0.20f};
  for (std::size_t i = 0; i < mesh_.size(); ++i) {
    const Triangle t = mesh_.triangle(i);
    r.triangle(t.v0, t.v1, t.v2, palette::surface.with_alpha(0.35f));
  }
  for (std::size_t i = 0; i < mesh_b_.size(); ++i) {
    const Triangle t = mesh_b_.triangle(i);
    r.triangle(t.v0, t.v1, t.v2, other.with_alpha(0.35f));
  }
  const auto draw_obb = [&](const Box& b, Color c, float width) {
    for (int i = 0; i < 8; ++i)
      for (int k = 0; k < 3; ++k)
        if (!((i >> k) & 1)) r.line(b.corner(i), b.corner(i | (1 << k)), c, width);
  };
  if (!tree_a_.nodes.empty()) {
    draw_obb(tree_a_.nodes[0].box, palette::surface, 1.5f);
    const Box& b = tree_a_.nodes[0].box;
    int left = 0;
    for (int i = 1; i < 8; ++i) left = b.corner(i).x() < b.corner(left).x() ? i : left;
    r.label(b.corner(left), "a's root box", palette::surface, -100, -8);
  }
  if (!tree_b_.nodes.empty()) {
    draw_obb(tree_b_.nodes[0].box, other, 1.5f);
    const Box& b = tree_b_.nodes[0].box;
    int right = 0;
    for (int i = 1; i < 8; ++i) right = b.corner(i).x() > b.corner(right).x() ? i : right;
    r.label(b.corner(right), "b's root box", other, 8, -8);
  }
  for (const auto& [i, j] : leaf_pairs_) {
    draw_obb(tree_a_.nodes[std::size_t(i)].box, palette::surface.with_alpha(0.8f), 1.0f);
    draw_obb(tree_b_.nodes[std::size_t(j)].box, other.with_alpha(0.8f), 1.0f);
  }
  const Color c = colour(verdict_[7]);
  if (bvh_)
    for (const auto& p : bvh_->answer.pairs) {
      if (p[0] < 0 || p[1] < 0 || std::size_t(p[0]) >= mesh_.size() || std::size_t(p[1]) >= mesh_b_.size()) continue;
      const Triangle s = mesh_.triangle(std::size_t(p[0])), t = mesh_b_.triangle(std::size_t(p[1]));
      r.triangle(s.v0, s.v1, s.v2, c.with_alpha(0.8f)), r.triangle(t.v0, t.v1, t.v2, c.with_alpha(0.8f));
    }
}

// ---- draw ----------------------------------------------------------------------------

void SpatialTreesScene::draw_kd(Frame& f) {
  Renderer& r = f.render;
  const bool edges = mesh_.size() <= 20000;
  for (std::size_t i = 0; i < mesh_.size(); ++i) {
    const Triangle t = mesh_.triangle(i);
    r.triangle(t.v0, t.v1, t.v2, palette::surface.with_alpha(0.55f));
    if (edges) r.line(t.v0, t.v1, {0.30f, 0.40f, 0.55f}, 1), r.line(t.v1, t.v2, {0.30f, 0.40f, 0.55f}, 1), r.line(t.v2, t.v0, {0.30f, 0.40f, 0.55f}, 1);
  }
  if (figure_ == "walk") {  // the leaves the segment meets, numbered in the walk's order
    std::vector<std::pair<double, Aabb>> met;
    for (const LeafBox& l : leaves_) {
      const auto span = segment_span(l.cell, segment_);
      if (span[0] <= span[1]) met.push_back({span[0], l.cell});
    }
    std::sort(met.begin(), met.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    const double stop = first_ && first_->hit ? first_->t : 2.0;
    int k = 0;
    for (const auto& [t0, cell] : met) {
      const bool visited = t0 <= stop;
      draw_box(r, cell, visited ? palette::agree.with_alpha(0.9f) : palette::muted.with_alpha(0.6f), visited ? 1.8f : 1.0f);
      const Vec3 at(0.5 * (cell.min.x() + cell.max.x()), 0.5 * (cell.min.y() + cell.max.y()), cell.max.z());
      r.label(at, std::to_string(++k), visited ? palette::agree : palette::muted, -4, -8);
    }
    draw_box(r, tree_.bounds, palette::muted, 1);
    if (first_ && first_->hit) {
      r.ring(first_->point, palette::agree, 12, 2.5f);
      r.label(first_->point, "first hit, t = " + num(first_->t) + ": the walk stops", palette::agree, 10, 28);
    }
    r.line(segment_.a, segment_.b, palette::input, 2.5f);
    r.point(segment_.a, palette::input, 6), r.point(segment_.b, palette::input, 6);
    r.label(segment_.a, "a", palette::input), r.label(segment_.b, "b", palette::input);
    return;
  }
  // The leaves the segment meets: the cells a front-to-back walk may visit.
  const Color cells = f.shows(1) || f.shows(2) ? colour(tree_is_students_ ? verdict_[1] : Verdict::none) : palette::muted;
  for (const LeafBox& l : leaves_)
    if (segment_meets(l.cell, segment_)) draw_box(r, l.cell, cells.with_alpha(0.8f), 1.2f);
  draw_box(r, tree_.bounds, palette::muted, 1);
  if (f.shows(2)) {
    const Color c = colour(verdict_[2]);
    if (all_)
      for (const KdHit& h : all_->hits) r.point(h.point, c, 4);
    if (first_ && first_->hit) {
      if (first_->triangle >= 0 && std::size_t(first_->triangle) < mesh_.size()) {
        const Triangle t = mesh_.triangle(std::size_t(first_->triangle));
        r.triangle(t.v0, t.v1, t.v2, c.with_alpha(0.7f));
      }
      r.ring(first_->point, c, 14, 2.5f);
      r.label(first_->point, "first hit  t = " + num(first_->t) + "  (" + std::to_string(first_->tests) + " tests)", c, 18, -16);
    }
    if (f.show_exact) {
      for (const oracle::Crossing& h : exact_hits_) r.ring(segment_.a + h.t * (segment_.b - segment_.a), palette::exact, 9);
      if (!exact_hits_.empty()) {
        const Triangle t = mesh_.triangle(std::size_t(exact_hits_[0].triangle));
        for (int i = 0; i < 3; ++i) r.line(t[i], t[(i + 1) % 3], palette::exact, 2);
      }
    }
  }
  r.line(segment_.a, segment_.b, palette::input, 2.5f);
  r.point(segment_.a, palette::input, 6), r.point(segment_.b, palette::input, 6);
  r.label(segment_.a, "a", palette::input), r.label(segment_.b, "b", palette::input);
}

void SpatialTreesScene::draw_bsp(Frame& f) {
  Renderer& r = f.render;
  if (figure_ == "split" && bsp_ && !bsp_->nodes.empty()) {  // the root's plane and the pieces on each side
    const BspTree& t = *bsp_;
    const Triangle& splitter = t.triangles[std::size_t(t.nodes[0].plane)];
    const Vec3 n = (splitter.v1 - splitter.v0).cross(splitter.v2 - splitter.v0);
    const Vec3 u = (splitter.v1 - splitter.v0).normalized(), v = n.normalized().cross(u);
    const Vec3 c = center - n.dot(center - splitter.v0) / n.squaredNorm() * n;
    const double h = 0.9 * radius;
    const Color plane{0.95f, 0.72f, 0.25f};
    r.triangle(c - h * u - h * v, c + h * u - h * v, c + h * u + h * v, plane.with_alpha(0.12f));
    r.triangle(c - h * u - h * v, c + h * u + h * v, c - h * u + h * v, plane.with_alpha(0.12f));
    for (int k = 0; k < 4; ++k) {
      const double s0 = (k == 0 || k == 3) ? -h : h, s1 = k < 2 ? -h : h, s2 = (k == 0 || k == 1) ? h : -h, s3 = (k == 1 || k == 2) ? h : -h;
      r.dashed(c + s0 * u + s1 * v, c + s2 * u + s3 * v, plane, 1.5f);
    }
    r.label(c - h * u - h * v, "the root's plane", plane, 8, -8);
    const auto side = [&](const Vec3& x) { return n.dot(x - splitter.v0); };
    for (std::size_t i = 0; i < t.pieces.size(); ++i) {
      const Triangle& p = t.pieces[i].triangle;
      const Vec3 mid = (p.v0 + p.v1 + p.v2) / 3;
      const double d = side(mid);
      const bool at_root = int(i) >= t.nodes[0].first && int(i) < t.nodes[0].first + t.nodes[0].count;
      const Color col = at_root ? plane : d > 0 ? palette::agree : palette::surface;
      r.triangle(p.v0, p.v1, p.v2, col.with_alpha(0.45f));
      for (int e = 0; e < 3; ++e) r.line(p[e], p[(e + 1) % 3], col, 2);
      r.label(at_root ? p.v1 : mid, "piece " + std::to_string(i) + (at_root ? ": the splitter" : d > 0 ? ": front" : ": back"), col,
              at_root ? -40.0f : 14.0f, at_root ? 18.0f : 0.0f);
      for (int e = 0; e < 3; ++e) {  // the cut points: on the plane, not a vertex of the mesh
        bool vertex = false;
        for (const Vec3& m : mesh_.vertices) vertex |= (m - p[e]).norm() == 0;
        if (!vertex && !at_root && side(p[e]) == 0) r.point(p[e], palette::input, 5);
      }
    }
    return;
  }
  if (order_ && bsp_ && f.shows(4)) {  // pieces shaded by their place in the painter's order: dark first, light last
    const std::size_t n = order_->size();
    for (std::size_t k = 0; k < n; ++k) {
      const int piece = (*order_)[k];
      if (piece < 0 || std::size_t(piece) >= bsp_->pieces.size()) continue;
      const float w = n > 1 ? float(k) / float(n - 1) : 1.0f;
      const Triangle& t = bsp_->pieces[std::size_t(piece)].triangle;
      r.triangle(t.v0, t.v1, t.v2, Color{0.20f + 0.6f * w, 0.30f + 0.5f * w, 0.55f + 0.4f * w, 0.75f});
      r.line(t.v0, t.v1, palette::muted, 1), r.line(t.v1, t.v2, palette::muted, 1), r.line(t.v2, t.v0, palette::muted, 1);
    }
  } else {
    for (std::size_t i = 0; i < mesh_.size(); ++i) {
      const Triangle t = mesh_.triangle(i);
      r.triangle(t.v0, t.v1, t.v2, palette::surface.with_alpha(0.45f));
      r.line(t.v0, t.v1, palette::muted, 1), r.line(t.v1, t.v2, palette::muted, 1), r.line(t.v2, t.v0, palette::muted, 1);
    }
  }
  const Color c = colour(verdict_[3]);
  r.point(point_, palette::input, 6);
  if (where_) r.label(point_, "p: " + describe(*where_), c, 12, -12);
  if (f.show_exact) {
    r.ring(point_, palette::exact, 10);
    r.label(point_, "exact: " + std::string(exact_where_ > 0 ? "inside" : exact_where_ < 0 ? "outside" : "on"), palette::exact, 12, 8);
  }
}

void SpatialTreesScene::draw_spheres(Frame& f) {
  Renderer& r = f.render;
  if (figure_ == "sweep") {  // circles in z = 0 seen from above, their x intervals below, the ends on one axis
    const char* names[] = {"A", "R", "B", "C"};
    const Color col[] = {palette::surface, palette::agree, {0.95f, 0.72f, 0.25f}, {0.85f, 0.50f, 0.85f}};
    constexpr int kCircle = 64;
    for (std::size_t i = 0; i < spheres_.size() && i < 4; ++i) {
      const Sphere& b = spheres_[i];
      for (int k = 0; k < kCircle; ++k) {
        const double a0 = 2 * M_PI * k / kCircle, a1 = 2 * M_PI * (k + 1) / kCircle;
        r.line(b.center + b.radius * Vec3(std::cos(a0), std::sin(a0), 0), b.center + b.radius * Vec3(std::cos(a1), std::sin(a1), 0), col[i], 2);
      }
      r.point(b.center, col[i], 4);
      r.label(b.center, names[i], col[i], 6, -6);
      const double y = -2.2 - 1.1 * double(i), lo = b.center.x() - b.radius, hi = b.center.x() + b.radius;
      r.line({lo, y, 0}, {hi, y, 0}, col[i], 4);
      r.dashed({lo, y, 0}, {lo, -7, 0}, col[i].with_alpha(0.5f), 1);
      r.dashed({hi, y, 0}, {hi, -7, 0}, col[i].with_alpha(0.5f), 1);
      r.label({hi, y, 0}, std::string(names[i]) + " [" + num(lo) + ", " + num(hi) + "]", col[i], 8, -8);
      r.label({lo, -7, 0}, std::string(names[i]) + "0", col[i], -8, 6);
      r.label({hi, -7, 0}, std::string(names[i]) + "1", col[i], -8, 6);
    }
    r.arrow({-0.5, -7, 0}, {14, -7, 0}, palette::muted, 1.5f);
    r.label({14, -7, 0}, "x", palette::muted, 6, -6);
    if (spheres_.size() >= 4) {
      r.line(spheres_[1].center, spheres_[2].center, palette::agree, 3);
      r.label(0.5 * (spheres_[1].center + spheres_[2].center), "R, B tested: |(4, 3, 0)| = 5 <= 2 + 4, meet", palette::agree, 8, 8);
      r.dashed(spheres_[2].center, spheres_[3].center, palette::muted, 2);
      r.label(0.5 * (spheres_[2].center + spheres_[3].center), "B, C tested: 6 > 4 + 1, apart", palette::muted, 8, -8);
    }
    return;
  }
  std::vector<char> paired(spheres_.size(), 0);
  const Color c = colour(verdict_[5]);
  if (pairs_)
    for (const auto& p : pairs_->pairs)
      if (p[0] >= 0 && p[1] >= 0 && std::size_t(p[0]) < spheres_.size() && std::size_t(p[1]) < spheres_.size()) {
        paired[std::size_t(p[0])] = paired[std::size_t(p[1])] = 1;
        r.line(spheres_[std::size_t(p[0])].center, spheres_[std::size_t(p[1])].center, c, 3);
      }
  for (std::size_t i = 0; i < spheres_.size(); ++i) draw_sphere(r, spheres_[i], paired[i] ? c : palette::surface, paired[i] ? 1.8f : 1.0f);
  if (f.show_exact)
    for (const auto& p : exact_pairs_) r.dashed(spheres_[std::size_t(p[0])].center, spheres_[std::size_t(p[1])].center, palette::exact, 1.5f);
}

void SpatialTreesScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::kd) draw_kd(f);
  if (mode_ == Mode::bsp) draw_bsp(f);
  if (mode_ == Mode::spheres) draw_spheres(f);
  if (mode_ == Mode::frames) draw_frames(f);
  if (mode_ == Mode::bvh) draw_bvh(f);
}

bool SpatialTreesScene::inputs() {
  bool changed = false;
  if (mode_ == Mode::kd) {
    changed |= edit("a", segment_.a, 0.01f) | edit("b", segment_.b, 0.01f);
    ImGui::TextDisabled("mesh: %zu triangles", mesh_.size());
  }
  if (mode_ == Mode::bsp) changed |= edit("point (and eye)", point_);
  if (mode_ == Mode::spheres) ImGui::TextDisabled("%zu spheres", spheres_.size());
  if (mode_ == Mode::frames) ImGui::TextDisabled("%zu spheres, %zu frames: the handles move the last", spheres_.size(), frames_.size());
  return changed;
}

std::vector<Handle> SpatialTreesScene::handles() {
  if (mode_ == Mode::kd) return {{&segment_.a, "a"}, {&segment_.b, "b"}};
  if (mode_ == Mode::bsp) return {{&point_, "p"}};
  if (mode_ == Mode::bvh) return {};
  std::vector<Handle> h;
  for (std::size_t i = 0; i < spheres_.size() && i < 64; ++i) h.push_back({&spheres_[i].center, "sphere " + std::to_string(i)});
  return h;
}

std::string SpatialTreesScene::token() const {
  switch (mode_) {
    case Mode::kd: return replay_token("first_hit", TreeQuery{mesh_, segment_, tree_seed_});
    case Mode::bsp: return replay_token("classify", PointQuery{mesh_, point_});
    case Mode::bvh: return replay_token("colliding_triangles", BvhQuery{mesh_, mesh_b_, tree_seed_, tree_seed_b_, true});
    case Mode::frames: return replay_token("sweep_frames", SweepCase{frames_});
    case Mode::spheres: break;
  }
  return replay_token("overlapping_pairs", SphereSet{spheres_});
}

}  // namespace

std::unique_ptr<Scene> make_spatial_trees(const Setup& setup) { return std::make_unique<SpatialTreesScene>(setup); }
const std::vector<Preset>& spatial_trees_presets() { return kPresets; }

}  // namespace viewer
