// Lab 06 scene: BSP and k-d trees, pair reduction (handouts/06_spatial_trees.md).
//
// A replay token's query picks the mode:
//   k-d tree   build_kd_tree, first_hit, any_hit, all_hits (and robust.*)    steps 1-2
//   BSP tree   build_bsp, classify, back_to_front (and robust.*)             steps 3-4
//   spheres    overlapping_pairs (and robust.*)                              step 5
//   frames     sweep_frames (and robust.*): the last two frames' ends on x     step 6
//              (handles move the last frame's spheres; the swapped ends are orange)
//   OBB trees  colliding_triangles: two meshes, the leaf boxes reached, the pairs step 7
//   hash       hashed_pairs: each ball's cell, coloured by its bucket, the pairs  step 11
//   octree     build_octree, balls_in_box: the leaves, the box, the leaves reached step 12
// In the k-d tree mode the segment's ends are handles: the leaves whose cells it meets
// are drawn as boxes, the student's first hit in its verdict's colour, the exact hits
// (the toggle) as violet rings. When step 1 is still a stub, the queries run on the
// checker's own tree, as the tests do.
#include "viewer/scenes/06_spatial_trees.h"
#include "viewer/scenes/scenes.h"

#include "common/generators/meshes.h"
#include "common/given/segment_triangle.h"
#include "common/given/served.h"
#include "common/oracle/oracle.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace viewer::spatial_trees {

const std::vector<Preset> kPresets = {
    {"torus", "a k-d tree over a torus of 2,048 triangles: the leaves a segment visits, front to back", nullptr, false,
     -50, 35, 2},
    {"walk",
     "step 2: the leaves a segment meets, numbered front to back; first_hit stops in leaf 8, after its hit at t = "
     "0.676 (grey: never visited)",
     nullptr, true, -90, 89, 2},
    {"handout", "step 2's example: a hit beyond the first leaf's end does not end the search", nullptr, false, -80, 20,
     2},
    {"terrain", "a terrain of 20,000 triangles, a long segment across it", nullptr, false, -40, 30, 2},
    {"bsp", "a BSP tree of an L of three cubes: classify a point, paint back to front", nullptr, false, -35, 25, 3},
    {"split", "step 3: the floor's plane z = 0, the root's, cuts the wall in two: a piece in front, one behind",
     nullptr, true, -75, 18, 3},
    {"spheres", "sort and sweep: 60 spheres, the pairs that meet", nullptr, false, -60, 30, 5},
    {"sweep", "step 5: the intervals on x, ends A0 A1 R0 B0 R1 C0 C1 B1; two pairs tested", nullptr, true, -90, 89, 5},
    {"bvh", "step 7: two OBB trees; the leaf boxes whose pairs the traversal reaches, the triangles that meet", nullptr,
     true, -60, 30, 7},
    {"coherence",
     "step 6: C moves 2 to the left; its end C0 = 6 passes R1 = 7: one swap, and {R, C} joins the pairs on x", nullptr,
     true, -90, 89, 6},
    {"hash",
     "step 11: cells of side 2 in a table of 4 buckets, each ball's cell in its bucket's colour: one colour, "
     "several cells",
     nullptr, true, -90, 89, 11},
    {"octree",
     "step 12: an octree of capacity 2 over two groups of 8 balls and a lone one, from above; the query box, the "
     "leaves it reaches (yellow)",
     nullptr, true, -90, 89, 12},
};

// ---- setup ---------------------------------------------------------------------------

SpatialTreesScene::SpatialTreesScene(const Setup& setup) {
  const Preset* preset = view_preset(kPresets, setup);
  if (setup.token.empty() && (!preset || !preset->token)) {
    figure_ = preset ? preset->name : "torus";
    set_up_figure(figure_);
  } else {
    load(parse_token(starting_token(setup, kPresets, "")));
  }
  frame_inputs();
}

// A replay token, or a preset's: the input of the query it names.
void SpatialTreesScene::load(const ParsedToken& token) {
  const auto frames = [&](std::vector<std::vector<Sphere>> f) {
    mode_ = Mode::frames, frames_ = std::move(f);
    if (frames_.empty()) frames_.push_back({});
    spheres_ = frames_.back();
  };
  load_token(
      "06", query::table, token,
      Loaders{[&](auto, const TreeQuery& in) { mesh_ = in.mesh, segment_ = in.segment, tree_seed_ = in.tree; },
              [&](auto q, const Mesh& in) {
    mesh_ = in;
    if (q == query::build_bsp) {
      mode_ = Mode::bsp;
      if (!mesh_.vertices.empty()) point_ = mesh_.vertices[0];
    } else if (mesh_.size() > 0) {
      segment_ = {mesh_.vertices[0] - Vec3(1, 1, 1), mesh_.vertices.back() + Vec3(1, 1, 1)};
    }
              },
              [&](auto, const PointQuery& in) { mode_ = Mode::bsp, mesh_ = in.mesh, point_ = in.point; },
              [&](auto, const SphereSet& in) { mode_ = Mode::spheres, spheres_ = in.spheres; },
              [&](auto, const BvhQuery& in) {
    mode_ = Mode::bvh, mesh_ = in.a, mesh_b_ = in.b, tree_seed_ = in.tree_a, tree_seed_b_ = in.tree_b;
      },
      [&](auto, const SweepCase& in) { frames(in.frames); },
      [&](auto, const HashCase& in) {
    mode_ = Mode::hash, spheres_ = in.spheres, hash_cell_ = in.cell, hash_buckets_ = in.buckets;
      },
      [&](auto, const OctreeCase& in) {
    mode_ = Mode::octree, spheres_ = in.spheres, capacity_ = in.capacity, max_depth_ = in.max_depth;
    query_box_ = in.box;
  },
      [&](auto, const MovingSpheres& in) { frames(sweep_of(in).frames); }});
}

void SpatialTreesScene::frame_inputs() {
  const char* names[] = {"k-d tree and segment", "BSP tree and point", "spheres",
                         "spheres over frames",  "two OBB trees",      "spheres in a hash table",
                         "an octree and a box"};
  mode = names[int(mode_)];
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh_.vertices) box.extend(v);
  for (const Vec3& v : mesh_b_.vertices) box.extend(v);
  if (mode_ == Mode::kd) box.extend(segment_.a), box.extend(segment_.b);
  if (mode_ == Mode::bsp) box.extend(point_);
  if (mode_ == Mode::octree) box.extend(query_box_.min), box.extend(query_box_.max);
  for (const Sphere& s : spheres_)
    box.extend(s.center + Vec3::Constant(s.radius)), box.extend(s.center - Vec3::Constant(s.radius));
  if (figure_ == "sweep") box.extend(Vec3(0, -7.5, 0));
  if (mode_ == Mode::frames && !box.isEmpty())
    box.extend(Vec3(box.min().x(), box.min().y() - 0.3 * box.diagonal().norm(), 0));
  if (box.isEmpty()) box.extend(Vec3::Zero()), box.extend(Vec3::Ones());
  frame(box);
}

std::string SpatialTreesScene::token() const {
  switch (mode_) {
    case Mode::kd: return replay_token(query::first_hit, TreeQuery{mesh_, segment_, tree_seed_});
    case Mode::bsp: return replay_token(query::classify, PointQuery{mesh_, point_});
    case Mode::bvh:
      return replay_token(query::colliding_triangles, BvhQuery{mesh_, mesh_b_, tree_seed_, tree_seed_b_, true});
    case Mode::frames: return replay_token(query::sweep_frames, SweepCase{frames_});
    case Mode::hash: return replay_token(query::hashed_pairs, HashCase{spheres_, hash_cell_, hash_buckets_, false});
    case Mode::octree:
      return replay_token(query::balls_in_box, OctreeCase{spheres_, capacity_, max_depth_, query_box_, false});
    case Mode::spheres: break;
  }
  return replay_token(query::overlapping_pairs, SphereSet{spheres_});
}

// ---- update --------------------------------------------------------------------------

void SpatialTreesScene::update() {
  steps.clear();
  if (mode_ == Mode::kd) update_kd();
  if (mode_ == Mode::bsp) update_bsp();
  if (mode_ == Mode::spheres) update_spheres();
  if (mode_ == Mode::frames) update_frames();
  if (mode_ == Mode::bvh) update_bvh();
  if (mode_ == Mode::hash) update_hash();
  if (mode_ == Mode::octree) update_octree();
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
  Step s2 = judged("L06S2",
                   std::string("first_hit, any_hit, all_hits on ") + (tree_is_students_   ? "your tree"
                                                                      : figure_ == "walk" ? "a median tree"
                                                                                          : "the checker's tree"),
                   first_, [&](const KdHit& got) { return judge::first_hit(in, tree_, got, calls[0]); });
  join(s2, any_, [&](const KdHit& got) { return judge::any_hit(in, tree_, got, calls[1]); });
  join(s2, all_, [&](const KdHits& got) { return judge::all_hits(in, tree_, got, calls[2]); });
  int met = 0;
  for (const LeafBox& l : leaves_) met += segment_meets(l.cell, segment_);
  const auto hit_text = [](const Attempt<KdHit>& h) {
    return h ? (h->hit ? std::to_string(h->triangle) + " at t = " + num(h->t) : std::string("none")) : std::string();
  };
  s2.rows = {
      {"first hit", hit_text(first_),
       exact_hits_.empty() ? "none" : std::to_string(exact_hits_[0].triangle) + " at t = " + num(exact_hits_[0].t)},
      {"any hit", any_ ? yes_no(any_->hit) : "", yes_no(!exact_hits_.empty())},
      {"all hits", all_ ? std::to_string(all_->hits.size()) : "", std::to_string(exact_hits_.size())},
      {"tests: first / any / all",
       first_ && any_ && all_
           ? std::to_string(first_->tests) + " / " + std::to_string(any_->tests) + " / " + std::to_string(all_->tests)
           : "",
       "brute force: " + std::to_string(mesh_.size())},
      {"leaves the segment meets", std::to_string(met), "of " + std::to_string(leaves_.size())}};
  // Whose tree is drawn and queried, said where the verdicts are: never "agrees" beside a
  // tree that is not the student's without the reason.
  if (!tree_is_students_ && s2.note.empty())
    s2.note = figure_ == "walk" ? "the walk figure draws a median tree, 5 levels deep, not yours"
              : !built_         ? "step 1 is not done: the queries run on the checker's tree"
                                : "your tree breaks step 1's rule: the queries run on the checker's tree";
  verdict_[2] = s2.verdict;
  steps.push_back(s2);
}

namespace {

// Does every edge belong to an even number of triangles, as around a solid? Only then
// has the mesh an inside, and classify an answer (the header's "closed mesh").
bool closed(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  return std::all_of(uses.begin(), uses.end(), [](const auto& edge) { return edge.second % 2 == 0; });
}

}  // namespace

void SpatialTreesScene::update_bsp() {
  bsp_ = attempt([&] { return build_bsp(mesh_); });
  const PointQuery in{mesh_, point_};
  closed_ = closed(mesh_);
  exact_where_ = closed_ ? oracle::point_in_solid(point_, mesh_) : 0;
  const Where exact = exact_where_ > 0 ? Where::inside : (exact_where_ < 0 ? Where::outside : Where::on);
  Step s3 =
      judged("L06S3", "build_bsp, classify", bsp_, [&](const BspTree& got) { return judge::bsp_tree(mesh_, got); });
  if (bsp_) {
    where_ = attempt([&] { return classify(*bsp_, point_); });
    if (closed_) join(s3, where_, [&](Where got) { return judge::classify(in, got); });
    s3.rows = {{"nodes, pieces", std::to_string(bsp_->nodes.size()) + ", " + std::to_string(bsp_->pieces.size()), ""},
               {"the point is", where_ ? describe(*where_) : "", closed_ ? describe(exact) : "(open mesh)"}};
    if (!closed_ && s3.note.empty())
      s3.note =
          "classify is judged on a closed mesh only (every edge shared by an even number of triangles): this "
          "one is open, so it has no inside";
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
  // The viewer runs the code in its own process: the given tests count here.
  const std::uint64_t before = given::local_calls("given_balls_meet");
  pairs_ = attempt([&] { return overlapping_pairs(spheres_); });
  const long long calls = (long long)(given::local_calls("given_balls_meet") - before);
  exact_pairs_ = oracle::meeting_pairs(spheres_);
  const SphereSet in{spheres_};
  Step s5 = judged("L06S5", "overlapping_pairs", pairs_,
                   [&](const SpherePairs& got) { return judge::overlapping_pairs(in, got, calls); });
  const long long n = (long long)spheres_.size();
  s5.rows = {
      {"pairs", pairs_ ? std::to_string(pairs_->pairs.size()) : "", std::to_string(exact_pairs_.size())},
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
      const std::uint64_t compared = given::local_calls("compare_ends"),
                          tested = given::local_calls("given_balls_meet");
      SweepRun r;
      r.frame = sweep.update(spheres);
      r.comparisons = (long long)(given::local_calls("compare_ends") - compared);
      r.ball_tests = (long long)(given::local_calls("given_balls_meet") - tested);
      runs.push_back(r);
    }
    return runs;
  });
  exact_pairs_ = oracle::meeting_pairs(spheres_);
  Step s6 = judged("L06S6", "SweepAndPrune::update, frame after frame", runs_,
                   [&](const SweepRuns& got) { return judge::sweep_frames(in, got); });
  if (runs_ && !runs_->empty()) {
    const SweepRun& last = runs_->back();
    const std::size_t k = frames_.size();
    const long long changed = k > 1 ? judge::changed_order(frames_[k - 2], frames_[k - 1]) : 0;
    s6.rows = {{"pairs (last frame)", std::to_string(last.frame.pairs.size()), std::to_string(exact_pairs_.size())},
               {"swaps", std::to_string(last.frame.swaps),
                k > 1 ? "at most " + std::to_string(changed) + " (ends whose order changed)" : "first frame: any sort"},
               {"compare_ends calls", std::to_string(last.comparisons),
                k > 1 ? "at most " + std::to_string(2 * spheres_.size() + std::size_t(changed)) : ""},
               {"tests", std::to_string(last.frame.tests),
                "brute force: " + std::to_string(spheres_.size() * (spheres_.size() - 1) / 2)}};
  }
  verdict_[6] = s6.verdict;
  steps.push_back(s6);
}

void SpatialTreesScene::update_bvh() {
  tree_a_ = judge::obb_tree(mesh_, tree_seed_), tree_b_ = judge::obb_tree(mesh_b_, tree_seed_b_);
  const BvhQuery in{mesh_, mesh_b_, tree_seed_, tree_seed_b_, true};
  bvh_ = attempt([&] {
    BvhRun r;
    const std::uint64_t boxes = given::local_calls("given_boxes_overlap");
    const std::uint64_t triangles = given::local_calls("given_triangles_meet");
    r.answer = colliding_triangles(tree_a_, tree_b_, true);
    r.box_calls = (long long)(given::local_calls("given_boxes_overlap") - boxes);
    r.triangle_calls = (long long)(given::local_calls("given_triangles_meet") - triangles);
    return r;
  });
  Step s7 = judged("L06S7", "colliding_triangles on the checker's OBB trees", bvh_,
                   [&](const BvhRun& got) { return judge::colliding_triangles(in, tree_a_, tree_b_, got); });
  leaf_pairs_ = judge::header_walk(tree_a_, tree_b_).leaf_pairs;
  if (bvh_)
    s7.rows = {{"pairs that meet", std::to_string(bvh_->answer.pairs.size()), ""},
               {"box tests", std::to_string(bvh_->answer.box_tests),
                "brute force: no boxes, " + std::to_string(mesh_.size() * mesh_b_.size()) + " triangle pairs"},
               {"triangle tests", std::to_string(bvh_->answer.triangle_tests),
                "leaf pairs reached: " + std::to_string(leaf_pairs_.size())}};
  verdict_[7] = s7.verdict;
  steps.push_back(s7);
}

// ---- draw: in 06_spatial_trees.draw.cpp, with inputs() and handles() ----------------

}  // namespace viewer::spatial_trees

LABKIT_SCENE(spatial_trees, SpatialTreesScene)
