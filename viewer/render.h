// Immediate-mode 3D drawing on OpenGL 3.3 core: scenes call line(), triangle(), point(),
// ring(), arrow() and label() every frame; end() uploads one vertex buffer and draws it
// in two calls (opaque, then translucent), depth-tested. Lines and markers are built as
// camera-facing triangles whose size is given in pixels, so they read the same at any
// zoom; triangles are lit from the camera, on both sides.
#pragma once

#include "common/geometry.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace viewer {

using Vec3f = Eigen::Vector3f;
using Mat4f = Eigen::Matrix4f;

struct Color {
  float r = 1, g = 1, b = 1, a = 1;
  Color with_alpha(float alpha) const { return {r, g, b, alpha}; }
};

// The colours every scene uses, so that they mean the same thing in every lab.
namespace palette {
constexpr Color agree{0.30f, 0.85f, 0.40f};      // the student's answer matches the exact one
constexpr Color disagree{0.95f, 0.22f, 0.20f};   // it does not
constexpr Color ambiguous{1.00f, 0.72f, 0.10f};  // the exact answer flips under a 1e-9 nudge
constexpr Color stub{0.55f, 0.55f, 0.58f};       // not implemented yet
constexpr Color exact{0.78f, 0.40f, 1.00f};      // the exact oracle's answer (the toggle)
constexpr Color input{0.92f, 0.92f, 0.95f};      // the scene's inputs: segments, handles
constexpr Color surface{0.45f, 0.62f, 0.85f};    // triangles and meshes given as input
constexpr Color muted{0.60f, 0.63f, 0.68f};      // construction lines, labels of inputs
constexpr Color background{0.125f, 0.14f, 0.17f};
}  // namespace palette

struct View {
  Mat4f view_projection = Mat4f::Identity();
  Vec3f eye = Vec3f::Zero();
  Vec3f right = Vec3f::UnitX(), up = Vec3f::UnitY(), forward = -Vec3f::UnitZ();
  float pixel_slope = 0.001f;  // the world size of one pixel at distance 1 along forward
  int width = 1, height = 1;   // viewport, in pixels
};

class Renderer {
 public:
  Renderer() = default;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  ~Renderer();

  // Compiles the shader and makes the buffers; false (with the reason) if GL refuses.
  bool init(std::string& error);

  void begin(const View& view);
  void line(const labkit::Vec3& a, const labkit::Vec3& b, Color c, float width_px = 2.0f);
  void dashed(const labkit::Vec3& a, const labkit::Vec3& b, Color c, float width_px = 1.5f, float dash_px = 8.0f);
  void triangle(const labkit::Vec3& a, const labkit::Vec3& b, const labkit::Vec3& c, Color color);
  // A triangle with one colour per vertex (lab 01's interpolated attributes).
  void triangle(const labkit::Vec3& a, const labkit::Vec3& b, const labkit::Vec3& c, Color ca, Color cb, Color cc);
  void point(const labkit::Vec3& p, Color c, float radius_px = 6.0f);  // a lit ball
  void ring(const labkit::Vec3& p, Color c, float radius_px = 10.0f, float width_px = 2.0f);
  void arrow(const labkit::Vec3& from, const labkit::Vec3& to, Color c, float width_px = 2.5f);
  void label(const labkit::Vec3& p, const std::string& text, Color c, float dx_px = 8, float dy_px = -8);
  // The ground grid on z = 0, `count` cells each way of `spacing`, and the x, y, z axes.
  void grid(double spacing, int count);
  // The x, y, z directions as seen now, drawn small in the view's lower left corner.
  void axes();

  // Draws everything queued since begin(); labels go to ImGui's background draw list,
  // so end() must run inside an ImGui frame.
  void end();

  const View& view() const { return view_; }
  // The world length of `px` pixels at p.
  float pixels(const labkit::Vec3& p, float px) const;
  std::size_t triangles_drawn() const { return last_triangles_; }

 private:
  struct Vertex {
    float position[3];
    float normal[3];  // zero: unlit (lines and markers), drawn a hair in front
    float color[4];
  };
  struct Label {
    Vec3f position;
    std::string text;
    Color color;
    float dx, dy;
  };
  void push(std::vector<Vertex>& to, const Vec3f& p, const Vec3f& n, Color c);
  void quad(const Vec3f& a0, const Vec3f& a1, const Vec3f& b0, const Vec3f& b1, Color c);
  void ribbon(const Vec3f& a, const Vec3f& b, Color c, float width_px);

  View view_;
  std::vector<Vertex> opaque_, translucent_;
  std::vector<Label> labels_;
  std::vector<Vec3f> sphere_;  // a unit ball as a triangle list
  unsigned program_ = 0, vao_ = 0, vbo_ = 0;
  int view_projection_location_ = -1, light_location_ = -1;
  std::size_t capacity_ = 0, last_triangles_ = 0;
};

}  // namespace viewer
