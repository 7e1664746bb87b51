// Lab 06 scene, its extensions: step 11's spatial hash (each ball's cell drawn in the
// colour of its bucket, so cells that share a bucket share a colour) and step 12's octree
// (its leaves, the query box, the leaves the header's walk reaches, the balls found).
#include "viewer/scenes/06_spatial_trees.h"

#include "common/given/served.h"

#include <algorithm>
#include <cmath>

namespace viewer::spatial_trees {

namespace {

const Color kBucketColours[] = {{0.95f, 0.55f, 0.25f}, {0.35f, 0.75f, 0.95f}, {0.85f, 0.45f, 0.85f},
                                {0.95f, 0.85f, 0.30f}, {0.45f, 0.85f, 0.65f}, {0.95f, 0.45f, 0.55f},
                                {0.60f, 0.60f, 0.95f}, {0.75f, 0.75f, 0.55f}};

Cell cell_at(const Vec3& p, double side) {
  return {std::int64_t(std::floor(p.x() / side)), std::int64_t(std::floor(p.y() / side)),
          std::int64_t(std::floor(p.z() / side))};
}

}  // namespace

// ---- update --------------------------------------------------------------------------

void SpatialTreesScene::update_hash() {
  // The viewer runs the code in its own process: the given tests count here.
  const std::uint64_t before = given::local_calls("given_balls_meet");
  hashed_ = attempt([&] { return hashed_pairs(spheres_, hash_cell_, hash_buckets_); });
  const long long calls = (long long)(given::local_calls("given_balls_meet") - before);
  exact_pairs_ = oracle::meeting_pairs(spheres_);
  const HashCase in{spheres_, hash_cell_, hash_buckets_, false};
  Step s11 = judged("L06S11", "hashed_pairs", hashed_,
                    [&](const SpherePairs& got) { return judge::hashed_pairs(in, got, calls); });
  const long long n = (long long)spheres_.size();
  s11.rows = {{"pairs", hashed_ ? std::to_string(hashed_->pairs.size()) : "", std::to_string(exact_pairs_.size())},
              {"pair tests", hashed_ ? std::to_string(hashed_->tests) : "",
               "at most " + std::to_string(judge::neighbour_pairs(in)) + " (neighbouring cells); brute force " +
                   std::to_string(n * (n - 1) / 2)}};
  verdict_[11] = s11.verdict;
  steps.push_back(s11);
}

void SpatialTreesScene::update_octree() {
  const OctreeCase in{spheres_, capacity_, max_depth_, query_box_, false};
  octree_ = attempt([&] { return build_octree(spheres_, capacity_, max_depth_); });
  checker_octree_ = judge::octree_of(spheres_, capacity_, max_depth_);
  Step built = judged("L06S12", "build_octree", octree_, [&](const Octree& got) { return judge::octree(in, got); });
  box_run_ = attempt([&] {
    OctreeRun run;
    const std::uint64_t cells = given::local_calls("given_cell_meets_box"),
                        balls = given::local_calls("given_ball_meets_box");
    run.answer = balls_in_box(checker_octree_, query_box_);
    run.cell_calls = (long long)(given::local_calls("given_cell_meets_box") - cells);
    run.ball_calls = (long long)(given::local_calls("given_ball_meets_box") - balls);
    return run;
  });
  join(built, box_run_, [&](const OctreeRun& got) { return judge::balls_in_box(in, checker_octree_, got); });
  built.title = "build_octree; balls_in_box on the checker's tree";
  walk_ = judge::octree_walk(checker_octree_, query_box_);
  exact_balls_ = oracle::balls_meeting_box(spheres_, query_box_);
  int leaves = 0;
  for (const OctNode& node : checker_octree_.nodes) leaves += node.child < 0;
  built.rows = {{"nodes, leaves", octree_ ? std::to_string(octree_->nodes.size()) : "",
                 std::to_string(checker_octree_.nodes.size()) + ", " + std::to_string(leaves)},
                {"balls in the box", box_run_ ? std::to_string(box_run_->answer.balls.size()) : "",
                 std::to_string(exact_balls_.size())},
                {"cell tests", box_run_ ? std::to_string(box_run_->answer.cell_tests) : "",
                 "at most " + std::to_string(walk_.cell_tests)},
                {"ball tests", box_run_ ? std::to_string(box_run_->answer.ball_tests) : "",
                 "at most " + std::to_string(walk_.ball_tests) + "; brute force " + std::to_string(spheres_.size())}};
  verdict_[12] = built.verdict;
  steps.push_back(built);
}

// ---- draw ----------------------------------------------------------------------------

void SpatialTreesScene::draw_hash(Frame& f) {
  Renderer& r = f.render;
  const bool figure = figure_ == "hash";
  // Each occupied cell once, in its bucket's colour, labelled with its key and bucket.
  std::vector<Cell> drawn;
  for (const Sphere& s : spheres_) {
    const Cell c = cell_at(s.center, hash_cell_);
    if (std::any_of(drawn.begin(), drawn.end(), [&](const Cell& d) { return d.x == c.x && d.y == c.y && d.z == c.z; }))
      continue;
    drawn.push_back(c);
    const std::size_t bucket = std::size_t(cell_hash(c) % std::uint64_t(std::max(hash_buckets_, 1)));
    const Color col = kBucketColours[bucket % 8];
    const Vec3 low = hash_cell_ * Vec3(double(c.x), double(c.y), double(c.z));
    const Aabb cell{low, low + Vec3::Constant(hash_cell_)};
    draw_box(r, cell, col.with_alpha(0.8f), 2);
    r.label(low + Vec3(0.08, 0.1, 0) * hash_cell_,
            "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ") -> " + std::to_string(bucket), col, 4, -4);
  }
  std::vector<char> paired(spheres_.size(), 0);
  const Color c = colour(verdict_[11]);
  if (hashed_)
    for (const auto& p : hashed_->pairs)
      if (p[0] >= 0 && p[1] >= 0 && std::size_t(p[0]) < spheres_.size() && std::size_t(p[1]) < spheres_.size()) {
        paired[std::size_t(p[0])] = paired[std::size_t(p[1])] = 1;
        r.line(spheres_[std::size_t(p[0])].center, spheres_[std::size_t(p[1])].center, c, 3);
      }
  for (std::size_t i = 0; i < spheres_.size(); ++i) {
    const Sphere& s = spheres_[i];
    if (figure)
      draw_circle(r, s.center, Vec3::UnitX(), Vec3::UnitY(), s.radius, paired[i] ? c : palette::input, 2, 48);
    else
      draw_sphere(r, s.center, s.radius, paired[i] ? c : palette::surface, paired[i] ? 1.8f : 1.0f, 32);
    r.label(s.center, std::to_string(i), palette::input, 4, 4);
  }
  if (f.show_exact)
    for (const auto& p : exact_pairs_)
      r.dashed(spheres_[std::size_t(p[0])].center, spheres_[std::size_t(p[1])].center, palette::exact, 1.5f);
}

void SpatialTreesScene::draw_octree(Frame& f) {
  Renderer& r = f.render;
  const bool figure = figure_ == "octree";
  const Octree& tree = checker_octree_;
  std::vector<char> reached(tree.nodes.size(), 0);
  for (int leaf : walk_.leaves) reached[std::size_t(leaf)] = 1;
  for (std::size_t k = 0; k < tree.nodes.size(); ++k)
    if (tree.nodes[k].child < 0 && !reached[k]) draw_box(r, tree.nodes[k].cell, palette::muted.with_alpha(0.55f), 1);
  for (int leaf : walk_.leaves) draw_box(r, tree.nodes[std::size_t(leaf)].cell, palette::ambiguous, 2);
  draw_box(r, query_box_, palette::input, 3);
  r.label(query_box_.max, "query box", palette::input, 6, -6);
  const Color c = colour(verdict_[12]);
  std::vector<char> found(spheres_.size(), 0);
  if (box_run_)
    for (int b : box_run_->answer.balls)
      if (b >= 0 && std::size_t(b) < spheres_.size()) found[std::size_t(b)] = 1;
  for (std::size_t i = 0; i < spheres_.size(); ++i) {
    const Sphere& s = spheres_[i];
    const Color col = found[i] ? c : palette::surface;
    if (figure)
      draw_circle(r, s.center, Vec3::UnitX(), Vec3::UnitY(), s.radius, col, found[i] ? 3 : 2, 40);
    else
      draw_sphere(r, s.center, s.radius, col, found[i] ? 1.8f : 1.0f, 32);
  }
  if (f.show_exact)
    for (int b : exact_balls_) r.point(spheres_[std::size_t(b)].center, palette::exact, 6);
}

}  // namespace viewer::spatial_trees
