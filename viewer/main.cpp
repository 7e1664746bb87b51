// labkit-viewer: every lab's scene, the student's answer beside the exact one.
//
//   labkit-viewer [NN] [--case TOKEN | --preset NAME | --figure NAME]
//                 [--screenshot FILE [--frames N]] [--size WxH] [--benchmark K]
//   labkit-viewer --list-presets
//
// labkit-viewer links the student's code; labkit-viewer-reference, built from the same
// objects, links the reference solutions (the handouts' figures come from it).
#include "viewer/app.h"

#include <cstdio>
#include <iostream>
#include <string>

namespace {

const char* kUsage =
    "usage: labkit-viewer [NN] [--case TOKEN | --preset NAME | --figure NAME]\n"
    "                     [--screenshot FILE [--frames N]] [--size WxH] [--benchmark K]\n"
    "       labkit-viewer --list-presets\n"
    "\n"
    "  NN               the lab whose scene opens (default: the first); keys 1-9 switch\n"
    "  --case TOKEN     open exactly the case a failure report printed ('query:v1,v2,...')\n"
    "  --preset NAME    open one of the scene's examples (see --list-presets)\n"
    "  --figure NAME    the same, drawn as a handout figure (no panel, a caption)\n"
    "  --screenshot F   draw N frames (--frames, default 4) offscreen, write the PNG F, exit\n"
    "  --size WxH       the window's size (default 1280x800)\n"
    "  --benchmark K    draw K frames offscreen, print the time per frame, exit\n";

int usage_error(const std::string& message) {
  std::cerr << "labkit-viewer: " << message << " (labkit-viewer --help lists the options)\n";
  return 2;
}

std::string scene_list() {
  std::string s;
  for (const viewer::SceneInfo& info : viewer::kScenes) s += (s.empty() ? "" : ", ") + std::string(info.stem);
  return s;
}

// "2", "02" and "02_segment_triangle" all name lab 02.
int find_scene(const std::string& name) {
  for (int i = 0; i < int(std::size(viewer::kScenes)); ++i) {
    const std::string lab = viewer::kScenes[i].lab, stem = viewer::kScenes[i].stem;
    if (name == lab || name == stem || (name.size() == 1 && "0" + name == lab)) return i;
  }
  return -1;
}

bool whole_number(const std::string& text, int& out, int low, int high) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 6) return false;
  out = std::stoi(text);
  return out >= low && out <= high;
}

// The scene whose lab has the token's query, when no lab was named.
int scene_for_token(const std::string& token) {
  for (int i = 0; i < int(std::size(viewer::kScenes)); ++i) {
    try {
      viewer::kScenes[i].make({token, ""});
      return i;
    } catch (const viewer::UnknownQuery&) {
      continue;
    } catch (const std::exception&) {
      return i;  // its query, but the numbers are wrong: that scene reports it
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  viewer::Options options;
  std::string lab;
  bool list = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&](std::string& out) {
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    std::string v;
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      return 0;
    } else if (arg == "--list-presets") {
      list = true;
    } else if (arg == "--lab") {
      if (!value(lab)) return usage_error("--lab needs a lab number");
    } else if (arg == "--case") {
      if (!value(options.setup.token))
        return usage_error("--case needs a replay token, e.g. --case 'segment_plane:1,1,3,...'");
    } else if (arg == "--preset" || arg == "--figure") {
      if (!value(options.setup.preset)) return usage_error(arg + " needs a name (labkit-viewer --list-presets)");
      options.figure = arg == "--figure";
    } else if (arg == "--screenshot") {
      if (!value(options.screenshot)) return usage_error("--screenshot needs a file name, e.g. --screenshot out.png");
    } else if (arg == "--frames") {
      if (!value(v) || !whole_number(v, options.frames, 1, 10000))
        return usage_error("--frames needs a number from 1 to 10000");
    } else if (arg == "--benchmark") {
      if (!value(v) || !whole_number(v, options.benchmark, 1, 100000))
        return usage_error("--benchmark needs a number of frames");
    } else if (arg == "--size") {
      const std::size_t x = value(v) ? v.find('x') : std::string::npos;
      if (x == std::string::npos || !whole_number(v.substr(0, x), options.width, 64, 8192) ||
          !whole_number(v.substr(x + 1), options.height, 64, 8192))
        return usage_error("--size needs WIDTHxHEIGHT, each from 64 to 8192, e.g. --size 1280x800");
    } else if (!arg.empty() && arg[0] != '-' && lab.empty()) {
      lab = arg;
    } else {
      return usage_error("unknown option '" + arg + "'");
    }
  }

  if (list) {
    for (const viewer::SceneInfo& info : viewer::kScenes)
      for (const viewer::Preset& p : info.presets())
        std::cout << info.stem << " " << p.name << (p.figure ? " figure " : " - ") << p.description << "\n";
    return 0;
  }
  if (!lab.empty()) {
    options.scene = find_scene(lab);
    if (options.scene < 0) {
      std::cerr << "labkit-viewer: no lab '" << lab << "' has a scene (the scenes: " << scene_list() << ")\n";
      return 2;
    }
  } else if (!options.setup.token.empty()) {
    options.scene = scene_for_token(options.setup.token);
  }
  if (!options.setup.token.empty() && !options.setup.preset.empty())
    return usage_error("--case and --preset/--figure each choose the input: give one");
  if (!options.setup.preset.empty() &&
      !viewer::find_preset(viewer::kScenes[options.scene].presets(), options.setup.preset))
    return usage_error("lab " + std::string(viewer::kScenes[options.scene].lab) + " has no preset '" +
                       options.setup.preset + "' (labkit-viewer --list-presets)");
  return viewer::run(options);
}
