// Lab 06 scene: BSP and k-d trees, pair reduction. What its files share:
// 06_spatial_trees.cpp sets the scene up and runs the steps,
// 06_spatial_trees.draw.cpp draws it and edits its inputs, 06_spatial_trees.trees.cpp
// walks the trees for the picture, 06_spatial_trees.extensions.cpp runs and draws the
// extensions of steps 11 (a spatial hash) and 12 (an octree).
#pragma once

#include "viewer/scenes/scenes.h"
#include "viewer/shapes.h"

#include "06_spatial_trees/judge.h"  // the inputs: TreeQuery, PointQuery, SphereSet, ...
#include "common/oracle/oracle.h"
#include "spatial_trees.h"

namespace viewer::spatial_trees {

using namespace labkit;
using namespace labkit::lab06;

enum class Mode { kd, bsp, spheres, frames, bvh, hash, octree };

// The leaves of a k-d tree with their cells, or why the tree cannot be walked.
struct LeafBox {
  int node;
  Aabb cell;
};

// The trees the picture walks (06_spatial_trees.trees.cpp).
std::vector<LeafBox> leaves_of(const KdTree& tree);
// A k-d tree for the "walk" figure: the cell halved in x, then y, `depth` levels.
KdTree median_tree(const Mesh& mesh, int depth);
// The part [t0, t1] of the segment inside the closed box (t0 > t1: it misses the box).
std::array<double, 2> segment_span(const Aabb& box, const Segment& s);
bool segment_meets(const Aabb& box, const Segment& s);
// A box's 12 edges (06_spatial_trees.draw.cpp).
void draw_box(Renderer& r, const Aabb& b, Color c, float width);

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
  void set_up_figure(const std::string& preset);  // a preset without a token
  void load(const ParsedToken& token);            // a replay token, or a preset's
  void update_kd();
  void update_bsp();
  void update_spheres();
  void update_frames();
  void update_bvh();
  void set_up_extension(const std::string& preset);  // the "hash" and "octree" figures
  void update_hash();
  void update_octree();
  void draw_hash(Frame& f);
  void draw_octree(Frame& f);
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
  std::string figure_;                // the preset's name: "walk", "split" and "sweep" draw the handout's figures
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
  bool closed_ = true;  // the mesh has an inside (every edge shared by an even number of triangles)
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
  // Step 11: the hash's cell side and buckets (the spheres are spheres_), the answer.
  double hash_cell_ = 2;
  int hash_buckets_ = 4;
  Attempt<SpherePairs> hashed_;
  // Step 12: the octree's rule, the query box, the student's tree, the checker's (the
  // query runs on it), the query's answer and the leaves the header's walk reaches.
  int capacity_ = 2, max_depth_ = 5;
  Aabb query_box_{Vec3::Zero(), Vec3::Ones()};
  Attempt<Octree> octree_;
  Octree checker_octree_;
  Attempt<OctreeRun> box_run_;
  std::vector<int> exact_balls_;
  judge::OctreeWalk walk_;
  Verdict verdict_[13] = {};
};

}  // namespace viewer::spatial_trees
