// The orbit camera: it turns around a target point, z up. Left-drag turns it,
// right- or middle-drag pans, the wheel zooms, and reset() goes back to where the
// scene framed it.
#pragma once

#include "viewer/render.h"

namespace viewer {

class OrbitCamera {
 public:
  // Looks at a ball (center, radius) from the given angles (degrees), and makes that
  // the pose reset() returns to.
  void frame(const labkit::Vec3& center, double radius, float yaw_deg = -60, float pitch_deg = 28);
  void reset() { pose_ = home_; }

  void rotate(float dx_px, float dy_px);
  void pan(float dx_px, float dy_px, int viewport_height);
  void zoom(float wheel_steps);

  View view(int width, int height) const;
  // The ray through a pixel (origin, unit direction), for picking.
  void ray(float x_px, float y_px, int width, int height, Vec3f& origin, Vec3f& direction) const;

 private:
  struct Pose {
    Vec3f target = Vec3f::Zero();
    float yaw = -1.0f, pitch = 0.5f, distance = 10.0f;
  };
  Vec3f eye() const;
  Pose pose_, home_;
  float fov_y_ = 0.70f;  // 40 degrees
};

}  // namespace viewer
