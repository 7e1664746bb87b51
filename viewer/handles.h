// Handles: the points of a scene's input that the mouse can grab. A click picks the
// handle nearest the cursor within a few pixels; dragging moves it in the plane through
// it that faces the camera (or in the handle's own plane, for a point that must stay
// on a triangle), snapped to a lattice so that exact degenerate cases are easy to make.
#pragma once

#include "viewer/camera.h"

#include <string>
#include <vector>

namespace viewer {

struct Handle {
  labkit::Vec3* point = nullptr;
  std::string name;
  const labkit::Plane* slide = nullptr;  // if set, the point stays in this plane
};

class HandleDrag {
 public:
  // Follows the mouse (ImGui's view of it) for one frame. `mouse_free` is false when an
  // ImGui window has the mouse. Returns true when a handle moved.
  bool update(const std::vector<Handle>& handles, const OrbitCamera& camera, int width, int height, bool mouse_free,
              double snap);
  // A ring on the handle under the cursor (or being dragged), and its name.
  void draw(const std::vector<Handle>& handles, Renderer& render) const;
  bool dragging() const { return active_ >= 0; }
  bool hovering() const { return hovered_ >= 0; }
  void release() { active_ = hovered_ = -1; }

 private:
  int hovered_ = -1, active_ = -1;
  Vec3f plane_normal_ = Vec3f::UnitZ();
  Vec3f plane_point_ = Vec3f::Zero();
  Vec3f offset_ = Vec3f::Zero();
};

}  // namespace viewer
