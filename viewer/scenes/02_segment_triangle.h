// Lab 02 scene: segment against triangle and mesh. What its two files share:
// 02_segment_triangle.cpp sets the scene up and runs the steps,
// 02_segment_triangle.draw.cpp draws it and edits its inputs.
#pragma once

#include "viewer/scenes/scenes.h"
#include "viewer/shapes.h"

#include "02_segment_triangle/queries.h"  // the inputs, their generators and the verdicts
#include "common/oracle/moving_meshes.h"
#include "common/oracle/oracle.h"
#include "segment_triangle.h"

namespace viewer::segment_triangle {

using namespace labkit;
using namespace labkit::lab02;

enum class Mode { triangle, point, mesh, moving, contact };

class SegmentTriangleScene : public Scene {
 public:
  explicit SegmentTriangleScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void frame_inputs();
  void update_triangle();
  void update_point();
  void update_probe();
  void update_mesh();
  void update_moving();
  void update_contact();
  void draw_triangle(Renderer& r, bool plane) const;
  void draw_steps_1_to_4(Frame& f) const;
  void draw_hits(Frame& f) const;
  void draw_contact(Frame& f) const;

  Mode mode_ = Mode::triangle;
  Segment segment_{{1, 1, 3}, {1, 1, -1}};
  Triangle triangle_{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  Vec3 x_ = Vec3::Zero();  // point mode: the point tested
  Mesh mesh_;
  RigidTransform m0_ = RigidTransform::Identity(), m1_ = RigidTransform::Identity();
  Plane plane_;                            // the triangle's plane, where x slides
  std::optional<Triangle> last_triangle_;  // point mode: x follows the plane when it moves

  // The student's answers, the exact ones, and each step's verdict.
  Attempt<PlaneCrossing> crossing_;
  Attempt<bool> inside_edges_, inside_barycentric_, test_, any_;
  Attempt<Barycentric> barycentric_;
  Attempt<SegmentTriangleHit> find_;
  Attempt<MeshHit> first_;
  Attempt<std::vector<MeshHit>> all_;
  MovingMeshes meshes_;  // contact mode: the two meshes and their velocities
  Attempt<MeshContact> contact_;
  oracle::MeshContact exact_contact_;
  std::optional<Vec3> probe_;  // the point steps 2 and 3 test
  oracle::PlaneCrossing exact_crossing_;
  oracle::SegmentHit exact_hit_;
  std::vector<oracle::SegmentHit> exact_hits_;
  Verdict verdict_[9] = {};
};

}  // namespace viewer::segment_triangle
