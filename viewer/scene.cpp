#include "viewer/scene.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace viewer {

bool edit(const char* label, labkit::Vec3& v, float speed) {
  return ImGui::DragScalarN(label, ImGuiDataType_Double, v.data(), 3, speed, nullptr, nullptr, "%.4g");
}

bool edit(const char* label, double& x, float speed, double low, double high) {
  const bool bounded = low < high;
  return ImGui::DragScalar(label, ImGuiDataType_Double, &x, speed, bounded ? &low : nullptr, bounded ? &high : nullptr,
                           "%.4g", bounded ? ImGuiSliderFlags_AlwaysClamp : 0);
}

std::string num(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text[0] == '-' && std::string(text) == "-0" ? "0" : text;
}

std::string num(const labkit::Vec3& v) { return "(" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + ")"; }

const Preset* find_preset(const std::vector<Preset>& presets, const std::string& name) {
  for (const Preset& p : presets)
    if (name == p.name) return &p;
  return nullptr;
}

std::string starting_token(const Setup& setup, const std::vector<Preset>& presets, const std::string& fallback) {
  if (!setup.token.empty()) return setup.token;
  const Preset* p = find_preset(presets, setup.preset);
  return p && p->token ? p->token : fallback;
}

void join(Step& step, const Step& other) {
  step.verdict = worse(step.verdict, other.verdict);
  if (step.note.empty()) step.note = other.note;
}

const Preset* Scene::view_preset(const std::vector<Preset>& presets, const Setup& setup) {
  const Preset* p = find_preset(presets, setup.preset);
  if (p) yaw = p->yaw, pitch = p->pitch, focus = p->focus;
  return p;
}

void Scene::frame(const Eigen::AlignedBox3d& box, double share) {
  center = box.center();
  radius = std::max(share * box.diagonal().norm(), 1e-9);
}

void Scene::draw_ground(Renderer& r) const {
  const double spacing = std::pow(10.0, std::floor(std::log10(radius)));
  r.grid(spacing, int(std::ceil(1.5 * radius / spacing)) + 2);
  r.axes();
}

UnknownQuery unknown_query(const std::string& lab, const std::string& query, const std::string& shown, bool listed) {
  if (listed)
    return UnknownQuery("lab " + lab + "'s scene does not draw '" + query + "'; ./labkit check " + lab +
                        " --case with the same case replays it in your terminal (the scene draws " + shown + ")");
  return UnknownQuery("lab " + lab + " has no query '" + query + "' (its scene draws " + shown + ")");
}

}  // namespace viewer
