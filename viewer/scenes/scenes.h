// The viewer's scenes: one per lab (viewer/scenes/NN_name.cpp; a long one is split by
// role into NN_name.draw.cpp and the like, with NN_name.h for what its files share),
// listed in this one table. Number keys and the list in the window switch between them.
// Adding lab 08's scene: write viewer/scenes/08_name.cpp with the same shape as the
// others, and add its line here.
#pragma once

#include "viewer/scene.h"

#include "common/harness/titles.h"

#include <memory>
#include <vector>

namespace viewer {

struct SceneInfo {
  const char* lab;                                     // "02": what `./labkit view 02` and the number keys select
  const char* stem;                                    // "02_segment_triangle": the stem of the lab's files and figures
  const char* title;                                   // from grading/manifest.json (common/harness/titles.h)
  std::unique_ptr<Scene> (*make)(const Setup& setup);  // throws labkit::BadToken
  const std::vector<Preset>& (*presets)();
};

std::unique_ptr<Scene> make_frustum_split(const Setup& setup);
const std::vector<Preset>& frustum_split_presets();
std::unique_ptr<Scene> make_segment_triangle(const Setup& setup);
const std::vector<Preset>& segment_triangle_presets();
std::unique_ptr<Scene> make_separating_axes(const Setup& setup);
const std::vector<Preset>& separating_axes_presets();
std::unique_ptr<Scene> make_bisection(const Setup& setup);
const std::vector<Preset>& bisection_presets();
std::unique_ptr<Scene> make_sphere_sweeps(const Setup& setup);
const std::vector<Preset>& sphere_sweeps_presets();
std::unique_ptr<Scene> make_spatial_trees(const Setup& setup);
const std::vector<Preset>& spatial_trees_presets();
std::unique_ptr<Scene> make_particles(const Setup& setup);
const std::vector<Preset>& particles_presets();

// What each scene file ends with, LABKIT_SCENE(frustum_split, FrustumSplitScene): the
// two functions its row below names, made from its class and its kPresets.
#define LABKIT_SCENE(name, Class)                                                                         \
  namespace viewer {                                                                                      \
  std::unique_ptr<Scene> make_##name(const Setup& setup) { return std::make_unique<name::Class>(setup); } \
  const std::vector<Preset>& name##_presets() { return name::kPresets; }                                  \
  }

inline const SceneInfo kScenes[] = {
    {"01", "01_frustum_split", LABKIT_LAB_TITLE_01, make_frustum_split, frustum_split_presets},
    {"02", "02_segment_triangle", LABKIT_LAB_TITLE_02, make_segment_triangle, segment_triangle_presets},
    {"03", "03_separating_axes", LABKIT_LAB_TITLE_03, make_separating_axes, separating_axes_presets},
    {"04", "04_bisection", LABKIT_LAB_TITLE_04, make_bisection, bisection_presets},
    {"05", "05_sphere_sweeps", LABKIT_LAB_TITLE_05, make_sphere_sweeps, sphere_sweeps_presets},
    {"06", "06_spatial_trees", LABKIT_LAB_TITLE_06, make_spatial_trees, spatial_trees_presets},
    {"07", "07_particles", LABKIT_LAB_TITLE_07, make_particles, particles_presets},
};

}  // namespace viewer
