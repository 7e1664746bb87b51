// The viewer's window: GLFW, OpenGL 3.3 core through libepoxy, Dear ImGui, the frame
// loop, the panel, and the headless modes (--screenshot, --benchmark).
#pragma once

#include "viewer/scenes/scenes.h"

#include <string>

namespace viewer {

struct Options {
  int scene = 0;           // index into kScenes
  Setup setup;             // a replay token or a preset
  bool figure = false;     // a handout figure: the picture and a caption, no panel
  std::string screenshot;  // write this PNG after `frames` frames, then exit
  int frames = 4;
  int width = 1280, height = 800;
  int benchmark = 0;  // time this many frames and print ms/frame, then exit
};

// Runs the viewer; returns the exit status. Errors are one line on stderr.
int run(const Options& options);

}  // namespace viewer
