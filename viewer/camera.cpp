#include "viewer/camera.h"

#include <algorithm>
#include <cmath>

namespace viewer {

void OrbitCamera::frame(const labkit::Vec3& center, double radius, float yaw_deg, float pitch_deg) {
  home_.target = center.cast<float>();
  home_.yaw = yaw_deg * float(M_PI) / 180;
  home_.pitch = pitch_deg * float(M_PI) / 180;
  // Far enough that the ball fills most of the height of the view.
  home_.distance = std::max(float(radius), 1e-6f) / std::sin(fov_y_ / 2) * 1.05f;
  pose_ = home_;
}

void OrbitCamera::rotate(float dx_px, float dy_px) {
  pose_.yaw -= dx_px * 0.008f;
  pose_.pitch = std::clamp(pose_.pitch + dy_px * 0.008f, -1.55f, 1.55f);
}

void OrbitCamera::pan(float dx_px, float dy_px, int viewport_height) {
  const View v = view(viewport_height, viewport_height);
  const float scale = 2 * pose_.distance * std::tan(fov_y_ / 2) / float(viewport_height);
  pose_.target += (-dx_px * v.right + dy_px * v.up) * scale;
}

void OrbitCamera::zoom(float wheel_steps) {
  pose_.distance = std::clamp(pose_.distance * std::pow(0.88f, wheel_steps), 1e-9f, 1e12f);
}

Vec3f OrbitCamera::eye() const {
  const Vec3f back(std::cos(pose_.pitch) * std::cos(pose_.yaw), std::cos(pose_.pitch) * std::sin(pose_.yaw),
                   std::sin(pose_.pitch));
  return pose_.target + pose_.distance * back;
}

View OrbitCamera::view(int width, int height) const {
  View v;
  v.width = std::max(width, 1);
  v.height = std::max(height, 1);
  v.eye = eye();
  v.forward = (pose_.target - v.eye).normalized();
  v.right = v.forward.cross(Vec3f::UnitZ()).normalized();
  v.up = v.right.cross(v.forward);

  Mat4f look = Mat4f::Identity();
  look.block<1, 3>(0, 0) = v.right.transpose();
  look.block<1, 3>(1, 0) = v.up.transpose();
  look.block<1, 3>(2, 0) = -v.forward.transpose();
  look(0, 3) = -v.right.dot(v.eye);
  look(1, 3) = -v.up.dot(v.eye);
  look(2, 3) = v.forward.dot(v.eye);

  const float near = pose_.distance * 0.01f, far = pose_.distance * 100.0f;
  const float t = 1.0f / std::tan(fov_y_ / 2), aspect = float(v.width) / float(v.height);
  Mat4f projection = Mat4f::Zero();
  projection(0, 0) = t / aspect;
  projection(1, 1) = t;
  projection(2, 2) = -(far + near) / (far - near);
  projection(2, 3) = -2 * far * near / (far - near);
  projection(3, 2) = -1;
  v.view_projection = projection * look;
  v.pixel_slope = 2 * std::tan(fov_y_ / 2) / float(v.height);
  return v;
}

void OrbitCamera::ray(float x_px, float y_px, int width, int height, Vec3f& origin, Vec3f& direction) const {
  const View v = view(width, height);
  const float h = std::tan(fov_y_ / 2);
  const float sx = (2 * x_px / float(v.width) - 1) * h * float(v.width) / float(v.height);
  const float sy = (1 - 2 * y_px / float(v.height)) * h;
  origin = v.eye;
  direction = (v.forward + sx * v.right + sy * v.up).normalized();
}

}  // namespace viewer
