// Lab 01 scene: view-frustum clipping by triangle splitting. What its two files share:
// 01_frustum_split.cpp sets the scene up and runs the steps, 01_frustum_split.draw.cpp
// draws it and edits its inputs.
#pragma once

#include "viewer/scenes/scenes.h"
#include "viewer/shapes.h"

#include "01_frustum_split/judge.h"  // the inputs: TrianglePlane, TriangleFrustum, MeshFrustum
#include "frustum_split.h"

namespace viewer::frustum_split {

using namespace labkit;
using namespace labkit::lab01;

enum class Mode { plane, frustum, mesh };
enum class Source { camera, matrix, planes };  // where the frustum comes from

// The default camera: at (0, -1, 1.5), looking along +y, z up (the viewer's up).
inline Camera default_camera() {
  Camera c;
  c.eye = {0, -1, 1.5};
  c.forward = {0, 1, -0.1};
  c.up = {0, 0, 1};
  c.fov_y = 0.9;
  c.aspect = 1.4;
  c.near = 1;
  c.far = 7;
  return c;
}

// The eight corners of a frustum given by its planes (bit 0: right, 1: top, 2: far);
// false when three planes do not meet in a point.
bool corners(const Frustum& f, Corners& out);
std::string side_name(Side s);

class FrustumSplitScene : public Scene {
 public:
  explicit FrustumSplitScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void frame_inputs();
  Frustum exact_frustum() const;
  void update_plane();
  Frustum update_planes();
  void update_frustum();
  void update_mesh();
  void draw_plane(Frame& f) const;
  void draw_frustum_triangle(Frame& f, const std::vector<Plane>& planes) const;
  void draw_mesh(Frame& f, const std::vector<Plane>& planes) const;
  void draw_pieces(Renderer& r, const std::vector<Triangle>& pieces, Verdict v) const;
  void draw_exact(Renderer& r, const Triangle& t, const std::vector<Plane>& planes) const;

  Mode mode_ = Mode::plane;
  Source source_ = Source::camera;
  TrianglePlane split_;        // plane mode
  Vec3 anchor_, last_anchor_;  // plane mode: the plane's handle, a point on it
  Camera camera_ = default_camera();
  Vec3 look_, last_look_, last_eye_;  // frustum modes: the camera's look-at handle
  Mat4 matrix_ = Mat4::Identity();
  Frustum planes_;  // Source::planes: the token's frustum
  Triangle triangle_{{-4, 2.5, 0.2}, {3.5, 3.5, 0}, {-0.5, 5.5, 3.8}};
  ColoredMesh mesh_;

  Attempt<std::array<double, 3>> distances_;
  Attempt<std::array<Side, 3>> sides_;
  Attempt<std::vector<Triangle>> pieces_;
  Attempt<Frustum> frustum_;
  Attempt<ClippedMesh> clipped_;
  Verdict verdict_[7] = {};
};

}  // namespace viewer::frustum_split
