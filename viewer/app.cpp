#include "viewer/app.h"

// libepoxy's gl.h first: GLFW's would otherwise bring in the system's.
#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <stb_image_write.h>

#include <sys/resource.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <utility>
#include <vector>

namespace viewer {

namespace {

constexpr float kPanelWidth = 420;  // the right-hand column; the 3D view has the rest
std::string glfw_error;

void remember_glfw_error(int, const char* description) { glfw_error = description ? description : "unknown"; }

int fail(const std::string& message) {
  std::cerr << "labkit-viewer: " << message << "\n";
  return 1;
}

ImVec4 im(Color c) { return {c.r, c.g, c.b, c.a}; }

// Multisampling smooths edges. A software renderer (Mesa's llvmpipe) pays for it with
// 2.5 times the CPU time per frame, so there it is off unless LABKIT_VIEWER_SAMPLES asks
// for it (./labkit figures does: the handouts' figures are drawn once).
int samples(bool software) {
  const char* s = std::getenv("LABKIT_VIEWER_SAMPLES");
  if (s && *s) return std::clamp(std::atoi(s), 0, 8);
  return software ? 0 : 4;
}
bool software_renderer() {
  const char* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return r &&
         (std::string(r).find("llvmpipe") != std::string::npos || std::string(r).find("softpipe") != std::string::npos);
}

// A filled dot in the colour of a verdict, on the current line.
void dot(Color c) {
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float r = ImGui::GetFontSize() * 0.3f;
  ImGui::GetWindowDrawList()->AddCircleFilled(ImVec2(p.x + r + 1, p.y + ImGui::GetFontSize() * 0.55f), r,
                                              ImGui::ColorConvertFloat4ToU32(im(c)));
  ImGui::Dummy(ImVec2(2 * r + 2, ImGui::GetFontSize()));
}

void colour_key() {
  const std::pair<Color, const char*> keys[] = {{palette::agree, "agrees"},
                                                {palette::disagree, "disagrees"},
                                                {palette::ambiguous, "ambiguous"},
                                                {palette::stub, "not implemented"},
                                                {palette::exact, "exact answer"}};
  for (const auto& [c, text] : keys) {
    dot(c);
    ImGui::SameLine();
    ImGui::TextColored(im(c), "%s", text);
    ImGui::SameLine();
  }
  ImGui::NewLine();
}

// An offscreen target for --screenshot and --benchmark: drawn with 4x multisampling
// like the window, then resolved into a plain one that glReadPixels reads.
struct Offscreen {
  GLuint msaa = 0, resolved = 0, buffers[3] = {0, 0, 0};
  int width = 0, height = 0;

  bool make(int w, int h, int samples) {
    width = w;
    height = h;
    glGenFramebuffers(1, &msaa);
    glGenFramebuffers(1, &resolved);
    glGenRenderbuffers(3, buffers);
    glBindRenderbuffer(GL_RENDERBUFFER, buffers[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, buffers[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, msaa);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, buffers[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, buffers[1]);
    const bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindRenderbuffer(GL_RENDERBUFFER, buffers[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, resolved);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, buffers[2]);
    return ok && glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  }

  std::vector<unsigned char> read() {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, resolved);
    std::vector<unsigned char> rgba(std::size_t(width) * std::size_t(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    // GL's rows go bottom-up, PNG's top-down; the picture is opaque.
    std::vector<unsigned char> flipped(rgba.size());
    const std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y)
      std::copy_n(&rgba[std::size_t(height - 1 - y) * row], row, &flipped[std::size_t(y) * row]);
    for (std::size_t i = 3; i < flipped.size(); i += 4) flipped[i] = 255;
    return flipped;
  }
};

class App {
 public:
  App(const Options& options, std::unique_ptr<Scene> scene) : options_(options), scene_(std::move(scene)) {
    index_ = options.scene;
  }
  int run(GLFWwindow* window);

 private:
  void frame_camera();
  void switch_to(int index, const Setup& setup);
  void input(int view_width, int view_height);
  void panel();
  void caption();
  void steps_table();
  void draw_frame(GLFWwindow* window, bool offscreen, GLuint framebuffer, double& update_ms);
  int write_offscreen(Offscreen& target, double ms_per_frame, double cpu_ms_per_frame, double update_ms);
  void print_steps() const;

  Options options_;
  std::unique_ptr<Scene> scene_;
  int index_ = 0;
  bool dirty_ = true, show_exact_ = true, snap_ = true;
  int focus_ = 0;  // the step whose quantities the picture shows (0: all)
  OrbitCamera camera_;
  HandleDrag drag_;
  Renderer render_;
  std::string error_;
};

void App::frame_camera() {
  camera_.frame(scene_->center, scene_->radius, scene_->yaw, scene_->pitch);
  focus_ = scene_->focus;
}

void App::switch_to(int index, const Setup& setup) {
  try {
    scene_ = kScenes[index].make(setup);
    index_ = index;
    error_.clear();
  } catch (const std::exception& e) {
    error_ = e.what();
    return;
  }
  drag_.release();
  dirty_ = true;
  scene_->update();
  dirty_ = false;
  frame_camera();
}

// Mouse and keys, unless an ImGui window has them.
void App::input(int view_width, int view_height) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool in_view = io.MousePos.x < float(view_width);
  const bool mouse_free = !io.WantCaptureMouse && in_view;
  std::vector<Handle> handles = scene_->handles();
  if (drag_.update(handles, camera_, view_width, view_height, mouse_free, snap_ ? 1.0 / 16 : 0)) dirty_ = true;
  if (!drag_.dragging() && mouse_free) {
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left) && !drag_.hovering())
      camera_.rotate(io.MouseDelta.x, io.MouseDelta.y);
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle))
      camera_.pan(io.MouseDelta.x, io.MouseDelta.y, view_height);
    if (io.MouseWheel != 0) camera_.zoom(io.MouseWheel);
  }
  if (io.WantCaptureKeyboard) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_E, false)) show_exact_ = !show_exact_;
  if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) camera_.reset();
  for (int i = 0; i < int(std::size(kScenes)) && i < 9; ++i)
    if (ImGui::IsKeyPressed(GLFW_KEY_1 + i, false) && i != index_) switch_to(i, {});
}

void App::steps_table() {
  for (const Step& s : scene_->steps) {
    ImGui::PushID(s.tag.c_str());
    dot(colour(s.verdict));
    ImGui::SameLine();
    // Clicking a step draws only its quantities; clicking it again draws every step's.
    const int number = s.tag.empty() ? 0 : s.tag.back() - '0';
    if (ImGui::Selectable((s.tag + "  " + s.title).c_str(), focus_ == number, 0,
                          ImGui::CalcTextSize((s.tag + "  " + s.title).c_str())))
      focus_ = focus_ == number ? 0 : number;
    if (s.verdict != Verdict::none) {
      ImGui::SameLine();
      if (ImGui::CalcTextSize(word(s.verdict)).x > ImGui::GetContentRegionAvail().x) ImGui::NewLine();
      ImGui::TextColored(im(colour(s.verdict)), "%s", word(s.verdict));
    }
    if (!s.rows.empty() && ImGui::BeginTable("rows", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
      ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch, 0.8f);
      ImGui::TableSetupColumn("yours", ImGuiTableColumnFlags_WidthStretch, 1.3f);
      ImGui::TableSetupColumn("exact", ImGuiTableColumnFlags_WidthStretch, 1.3f);
      ImGui::TableHeadersRow();
      for (const Row& r : s.rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextDisabled("%s", r.quantity.c_str());
        ImGui::TableNextColumn();
        const bool differs = s.verdict == Verdict::disagree && r.yours != r.exact;
        if (differs)
          ImGui::TextColored(im(palette::disagree), "%s", r.yours.c_str());
        else
          ImGui::TextUnformatted(r.yours.c_str());
        ImGui::TableNextColumn();
        ImGui::TextColored(im(palette::exact), "%s", r.exact.c_str());
      }
      ImGui::EndTable();
    }
    if (!s.note.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, s.verdict == Verdict::disagree ? im(palette::disagree) : im(palette::muted));
      ImGui::TextWrapped("%s", s.note.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::Spacing();
    ImGui::PopID();
  }
}

void App::panel() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kPanelWidth, 0));
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, io.DisplaySize.y));
  ImGui::Begin(
      "labkit viewer", nullptr,
      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar);
  ImGui::TextDisabled("labkit viewer   labs (keys 1-%d):", int(std::size(kScenes)));
  for (int i = 0; i < int(std::size(kScenes)); ++i) {
    const std::string name = std::string(kScenes[i].lab) + "  " + kScenes[i].title;
    if (ImGui::Selectable(name.c_str(), i == index_) && i != index_) switch_to(i, {});
  }
  ImGui::TextDisabled("drag: turn, right-drag: pan, wheel: zoom, drag a ball: move it");
  colour_key();
  ImGui::Separator();
  const SceneInfo& info = kScenes[index_];
  ImGui::Text("Lab %s: %s", info.lab, scene_->mode.c_str());
  const std::vector<Preset>& presets = info.presets();
  if (ImGui::BeginCombo("example", "choose an example...")) {
    for (const Preset& p : presets)
      if (ImGui::Selectable(p.description)) switch_to(index_, {"", p.name});
    ImGui::EndCombo();
  }
  ImGui::Checkbox("exact answer (E)", &show_exact_);
  ImGui::SameLine();
  ImGui::Checkbox("snap to 1/16", &snap_);
  ImGui::SameLine();
  if (ImGui::Button("camera (R)")) camera_.reset();
  if (!error_.empty()) ImGui::TextColored(im(palette::disagree), "%s", error_.c_str());

  if (ImGui::CollapsingHeader("inputs (drag the balls, or edit)", ImGuiTreeNodeFlags_DefaultOpen) && scene_->inputs())
    dirty_ = true;
  if (ImGui::CollapsingHeader("steps: your answer beside the exact one", ImGuiTreeNodeFlags_DefaultOpen)) steps_table();
  if (ImGui::CollapsingHeader("replay this case")) {
    const std::string command = "./labkit check " + std::string(info.lab) + " --case '" + scene_->token() + "'";
    ImGui::TextWrapped("%s", command.c_str());
    if (ImGui::Button("copy the command")) ImGui::SetClipboardText(command.c_str());
  }
  ImGui::End();
}

// A handout figure's caption: the lab, the preset's words, and the colour key.
void App::caption() {
  ImGui::SetNextWindowPos(ImVec2(10, 10));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("caption", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
  const Preset* p = find_preset(kScenes[index_].presets(), options_.setup.preset);
  ImGui::Text("Lab %s: %s", kScenes[index_].lab, p ? p->description : scene_->mode.c_str());
  ImGui::TextColored(im(palette::agree), "green: the answer (the reference solution's)");
  ImGui::TextColored(im(palette::exact), "violet: the exact answer, from the oracle");
  ImGui::End();
}

void App::print_steps() const {
  std::cout << "lab " << kScenes[index_].lab << " (" << scene_->mode << ")\n";
  for (const Step& s : scene_->steps) {
    std::cout << "  " << s.tag << "  " << s.title << ": " << (s.verdict == Verdict::none ? "-" : word(s.verdict));
    if (!s.note.empty()) std::cout << " (" << s.note << ")";
    std::cout << "\n";
  }
}

// One frame: the panel or the caption, the scene brought up to date, drawn into
// `framebuffer` (0: the window) with the handles and the interface on top.
void App::draw_frame(GLFWwindow* window, bool offscreen, GLuint framebuffer, double& update_ms) {
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  int fb_width, fb_height, win_width, win_height;
  glfwGetFramebufferSize(window, &fb_width, &fb_height);
  glfwGetWindowSize(window, &win_width, &win_height);
  if (offscreen) fb_width = win_width = options_.width, fb_height = win_height = options_.height;
  const bool show_panel = !options_.figure;
  const int view_width = std::max(1, win_width - (show_panel ? int(kPanelWidth) : 0));
  const float scale = float(fb_width) / float(std::max(win_width, 1));
  if (!offscreen) input(view_width, win_height);
  if (show_panel)
    panel();
  else
    caption();
  if (dirty_) {
    const auto u0 = std::chrono::steady_clock::now();
    scene_->update();
    update_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - u0).count();
    dirty_ = false;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, fb_width, fb_height);
  glClearColor(palette::background.r, palette::background.g, palette::background.b, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glViewport(0, 0, int(float(view_width) * scale), fb_height);
  render_.begin(camera_.view(view_width, win_height));
  Frame f{render_, show_exact_, options_.figure, focus_};
  scene_->draw(f);
  drag_.draw(scene_->handles(), render_);
  render_.end();
  glViewport(0, 0, fb_width, fb_height);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

// The last offscreen frame: the benchmark's line, and the screenshot with each step's
// verdict.
int App::write_offscreen(Offscreen& target, double ms, double cpu, double update_ms) {
  if (options_.benchmark > 0)
    std::printf(
        "lab %s (%s): %.1f ms/frame (%.0f frames per second), %.1f ms of CPU per frame, over %d frames at "
        "%dx%d, %zu triangles drawn, update %.1f ms, on %s\n",
        kScenes[index_].lab, scene_->mode.c_str(), ms, 1000 / ms, cpu, options_.benchmark, options_.width,
        options_.height, render_.triangles_drawn(), update_ms, reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  if (!options_.screenshot.empty()) {
    const std::vector<unsigned char> pixels = target.read();
    if (!stbi_write_png(options_.screenshot.c_str(), options_.width, options_.height, 4, pixels.data(),
                        options_.width * 4))
      return fail("cannot write " + options_.screenshot);
    std::cout << "wrote " << options_.screenshot << " (" << options_.width << "x" << options_.height << ")\n";
    print_steps();
  }
  return 0;
}

int App::run(GLFWwindow* window) {
  if (!render_.init(error_)) return fail(error_);
  const bool offscreen = !options_.screenshot.empty() || options_.benchmark > 0;
  Offscreen target;
  if (offscreen && !target.make(options_.width, options_.height, samples(software_renderer())))
    return fail("cannot make an offscreen framebuffer of " + std::to_string(options_.width) + "x" +
                std::to_string(options_.height));
  scene_->update();
  dirty_ = false;
  frame_camera();
  // CPU time of the whole process (llvmpipe's threads too): the work a frame costs,
  // whatever else the machine is doing.
  const auto cpu_ms = [] {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return 1e3 * double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-3 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  };
  double update_ms = 0, cpu_from = 0;
  auto timed_from = std::chrono::steady_clock::now();
  const int warm_up = 3;
  const int last = options_.benchmark > 0 ? warm_up + options_.benchmark : options_.frames;
  for (int frame = 0; !glfwWindowShouldClose(window); ++frame) {
    draw_frame(window, offscreen, offscreen ? target.msaa : 0, update_ms);
    if (!offscreen) {
      glfwSwapBuffers(window);
      continue;
    }
    glFinish();
    if (frame + 1 == warm_up) timed_from = std::chrono::steady_clock::now(), cpu_from = cpu_ms();
    if (frame + 1 < last) continue;
    const int frames = std::max(1, options_.benchmark);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - timed_from).count() / frames;
    return write_offscreen(target, ms, (cpu_ms() - cpu_from) / frames, update_ms);
  }
  return 0;
}

}  // namespace

int run(const Options& options) {
  // Inputs first: a bad token fails before any window is made.
  std::unique_ptr<Scene> scene;
  try {
    scene = kScenes[options.scene].make(options.setup);
  } catch (const std::exception& e) {
    return fail(e.what());
  }

  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland))
    return fail(
        "no display (DISPLAY is not set): run it from a desktop session, or headless under "
        "xvfb-run (./labkit view does that for --screenshot)");
  glfwSetErrorCallback(remember_glfw_error);
  if (!glfwInit())
    return fail("cannot open the display " + std::string(display ? display : "") + " (" + glfw_error + ")");

  const bool offscreen = !options.screenshot.empty() || options.benchmark > 0;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, samples(std::getenv("LIBGL_ALWAYS_SOFTWARE") != nullptr));
  glfwWindowHint(GLFW_VISIBLE, offscreen ? GLFW_FALSE : GLFW_TRUE);
  const std::string title = std::string("labkit viewer: lab ") + kScenes[options.scene].lab;
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, title.c_str(), nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    return fail("cannot make an OpenGL 3.3 core context (" + glfw_error +
                "); the viewer needs OpenGL 3.3: update the graphics driver, or use Mesa's software renderer "
                "(LIBGL_ALWAYS_SOFTWARE=1)");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(offscreen ? 0 : 1);
  if (epoxy_gl_version() < 33) {
    glfwDestroyWindow(window);
    glfwTerminate();
    return fail("the OpenGL context is version " + std::to_string(epoxy_gl_version() / 10) + "." +
                std::to_string(epoxy_gl_version() % 10) + "; the viewer needs 3.3");
  }

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left in the student's folder
  const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  if (std::ifstream(font).good()) io.Fonts->AddFontFromFileTTF(font, 15.0f);
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 0;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int status;
  {
    App app(options, std::move(scene));
    status = app.run(window);
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

}  // namespace viewer
