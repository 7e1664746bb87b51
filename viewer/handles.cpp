#include "viewer/handles.h"

#include "common/harness/codec.h"

#include <imgui.h>

#include <cmath>

namespace viewer {

namespace {

constexpr float kPickRadiusPx = 12.0f;

bool to_screen(const View& v, const Vec3f& p, float& x, float& y) {
  const Eigen::Vector4f clip = v.view_projection * p.homogeneous();
  if (clip.w() <= 0) return false;
  x = (clip.x() / clip.w() * 0.5f + 0.5f) * float(v.width);
  y = (0.5f - clip.y() / clip.w() * 0.5f) * float(v.height);
  return true;
}

}  // namespace

bool HandleDrag::update(const std::vector<Handle>& handles, const OrbitCamera& camera, int width, int height,
                        bool mouse_free, double snap) {
  const ImGuiIO& io = ImGui::GetIO();
  const View v = camera.view(width, height);
  if (active_ >= int(handles.size())) active_ = -1;

  if (active_ < 0) {
    hovered_ = -1;
    if (!mouse_free) return false;
    float best = kPickRadiusPx * kPickRadiusPx;
    for (std::size_t i = 0; i < handles.size(); ++i) {
      float x, y;
      if (!to_screen(v, handles[i].point->cast<float>(), x, y)) continue;
      const float d2 = (x - io.MousePos.x) * (x - io.MousePos.x) + (y - io.MousePos.y) * (y - io.MousePos.y);
      if (d2 <= best) {
        best = d2;
        hovered_ = int(i);
      }
    }
    if (hovered_ < 0 || !io.MouseClicked[0]) return false;
    // Grab it: remember the plane to drag in and where in it the cursor held the handle.
    const Handle& h = handles[std::size_t(hovered_)];
    active_ = hovered_;
    plane_point_ = h.point->cast<float>();
    plane_normal_ = h.slide ? h.slide->normal.cast<float>().normalized() : v.forward;
  }

  if (!io.MouseDown[0]) {
    active_ = -1;
    return false;
  }
  Vec3f origin, direction;
  camera.ray(io.MousePos.x, io.MousePos.y, width, height, origin, direction);
  const float facing = direction.dot(plane_normal_);
  if (std::abs(facing) < 1e-6f) return false;  // the plane is seen edge-on
  const Vec3f hit = origin + direction * ((plane_point_ - origin).dot(plane_normal_) / facing);
  if (io.MouseClicked[0]) offset_ = plane_point_ - hit;

  const Handle& h = handles[std::size_t(active_)];
  labkit::Vec3 p = (hit + offset_).cast<double>();
  if (snap > 0)
    for (int k = 0; k < 3; ++k) p[k] = std::round(p[k] / snap) * snap;
  if (h.slide) {  // back into its plane, which snapping may have left
    const labkit::Plane& s = *h.slide;
    p -= s.value(p) / s.normal.squaredNorm() * s.normal;
  }
  if (p == *h.point) return false;
  *h.point = p;
  return true;
}

void HandleDrag::draw(const std::vector<Handle>& handles, Renderer& render) const {
  const int i = active_ >= 0 ? active_ : hovered_;
  if (i < 0 || i >= int(handles.size())) return;
  const Handle& h = handles[std::size_t(i)];
  render.ring(*h.point, palette::input, 11, 2);
  render.label(*h.point, h.name + " = " + labkit::fmt(*h.point), palette::input, 14, 14);
}

}  // namespace viewer
