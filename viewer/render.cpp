#include "viewer/render.h"

#include <epoxy/gl.h>
#include <imgui.h>

#include <cmath>
#include <cstddef>

namespace viewer {

namespace {

// One shader for everything. Lit vertices (a non-zero normal) get a headlight from the
// camera's side on either face; unlit ones (lines, markers) keep their colour and are
// pulled a hair toward the camera so that an edge drawn on a face is not hidden by it.
const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
uniform mat4 view_projection;
uniform vec3 light;
out vec4 shade;
void main() {
  gl_Position = view_projection * vec4(position, 1.0);
  float n = length(normal);
  if (n > 0.0) {
    float diffuse = abs(dot(normal / n, light));
    shade = vec4(color.rgb * (0.42 + 0.58 * diffuse), color.a);
  } else {
    shade = color;
    gl_Position.z -= 0.0006 * gl_Position.w;
  }
}
)";

const char* kFragmentShader = R"(#version 330 core
in vec4 shade;
out vec4 fragment;
void main() { fragment = shade; }
)";

Vec3f f(const labkit::Vec3& v) { return v.cast<float>(); }

bool compile(unsigned shader, const char* source, std::string& error) {
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return true;
  char log[1024] = {};
  glGetShaderInfoLog(shader, sizeof log, nullptr, log);
  error = std::string("the viewer's shader does not compile: ") + log;
  return false;
}

// A unit ball, 8 rings of 12 quads: round enough for a marker a few pixels wide.
std::vector<Vec3f> unit_ball() {
  std::vector<Vec3f> out;
  const int rings = 8, segments = 12;
  const auto at = [&](int i, int j) {
    const float theta = float(M_PI) * float(i) / float(rings), phi = 2 * float(M_PI) * float(j) / float(segments);
    return Vec3f(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const Vec3f a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      out.insert(out.end(), {a, b, c, a, c, d});
    }
  return out;
}

}  // namespace

Renderer::~Renderer() {
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (program_) glDeleteProgram(program_);
}

bool Renderer::init(std::string& error) {
  const unsigned vertex = glCreateShader(GL_VERTEX_SHADER), fragment = glCreateShader(GL_FRAGMENT_SHADER);
  if (!compile(vertex, kVertexShader, error) || !compile(fragment, kFragmentShader, error)) return false;
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    error = "the viewer's shader does not link";
    return false;
  }
  view_projection_location_ = glGetUniformLocation(program_, "view_projection");
  light_location_ = glGetUniformLocation(program_, "light");

  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, color)));
  glBindVertexArray(0);
  sphere_ = unit_ball();
  return true;
}

void Renderer::begin(const View& view) {
  view_ = view;
  opaque_.clear();
  translucent_.clear();
  labels_.clear();
}

float Renderer::pixels(const labkit::Vec3& p, float px) const {
  const float depth = std::max((f(p) - view_.eye).dot(view_.forward), 1e-6f);
  return px * depth * view_.pixel_slope;
}

void Renderer::push(std::vector<Vertex>& to, const Vec3f& p, const Vec3f& n, Color c) {
  to.push_back({{p.x(), p.y(), p.z()}, {n.x(), n.y(), n.z()}, {c.r, c.g, c.b, c.a}});
}

void Renderer::quad(const Vec3f& a0, const Vec3f& a1, const Vec3f& b0, const Vec3f& b1, Color c) {
  std::vector<Vertex>& to = c.a < 1 ? translucent_ : opaque_;
  const Vec3f none = Vec3f::Zero();
  for (const Vec3f* p : {&a0, &b0, &b1, &a0, &b1, &a1}) push(to, *p, none, c);
}

// A band of constant pixel width from a to b, turned to face the camera.
void Renderer::ribbon(const Vec3f& a, const Vec3f& b, Color c, float width_px) {
  const Vec3f along = b - a;
  Vec3f side = along.cross(0.5f * (a + b) - view_.eye);
  if (side.squaredNorm() < 1e-30f) side = view_.right;
  side.normalize();
  const float wa = pixels(a.cast<double>(), width_px / 2), wb = pixels(b.cast<double>(), width_px / 2);
  quad(a - wa * side, a + wa * side, b - wb * side, b + wb * side, c);
}

void Renderer::line(const labkit::Vec3& a, const labkit::Vec3& b, Color c, float width_px) {
  ribbon(f(a), f(b), c, width_px);
}

void Renderer::dashed(const labkit::Vec3& a, const labkit::Vec3& b, Color c, float width_px, float dash_px) {
  const double length = (b - a).norm();
  const double dash = pixels(0.5 * (a + b), dash_px);
  if (length == 0 || dash <= 0) return;
  const int count = std::min(200, int(length / dash));
  if (count < 2) return line(a, b, c, width_px);
  for (int i = 0; i < count; i += 2)
    line(a + (b - a) * (double(i) / count), a + (b - a) * (double(i + 1) / count), c, width_px);
}

void Renderer::triangle(const labkit::Vec3& a, const labkit::Vec3& b, const labkit::Vec3& c, Color color) {
  triangle(a, b, c, color, color, color);
}

void Renderer::triangle(const labkit::Vec3& a, const labkit::Vec3& b, const labkit::Vec3& c, Color ca, Color cb,
                        Color cc) {
  const Vec3f pa = f(a), pb = f(b), pc = f(c);
  Vec3f n = (pb - pa).cross(pc - pa);
  if (!(n.squaredNorm() > 0)) n = view_.forward;  // zero area: still visible as an edge-on sliver
  std::vector<Vertex>& to = (ca.a < 1 || cb.a < 1 || cc.a < 1) ? translucent_ : opaque_;
  push(to, pa, n, ca);
  push(to, pb, n, cb);
  push(to, pc, n, cc);
}

void Renderer::point(const labkit::Vec3& p, Color c, float radius_px) {
  const Vec3f center = f(p);
  const float r = pixels(p, radius_px);
  std::vector<Vertex>& to = c.a < 1 ? translucent_ : opaque_;
  for (const Vec3f& v : sphere_) push(to, center + r * v, v, c);
}

void Renderer::ring(const labkit::Vec3& p, Color c, float radius_px, float width_px) {
  const Vec3f center = f(p);
  const float r = pixels(p, radius_px), w = pixels(p, width_px / 2);
  const int segments = 28;
  for (int i = 0; i < segments; ++i) {
    const float t0 = 2 * float(M_PI) * float(i) / segments, t1 = 2 * float(M_PI) * float(i + 1) / segments;
    const Vec3f d0 = std::cos(t0) * view_.right + std::sin(t0) * view_.up;
    const Vec3f d1 = std::cos(t1) * view_.right + std::sin(t1) * view_.up;
    quad(center + (r - w) * d0, center + (r + w) * d0, center + (r - w) * d1, center + (r + w) * d1, c);
  }
}

void Renderer::arrow(const labkit::Vec3& from, const labkit::Vec3& to, Color c, float width_px) {
  const Vec3f a = f(from), b = f(to);
  const float length = (b - a).norm();
  if (!(length > 0)) return;
  const Vec3f d = (b - a) / length;
  const float head = std::min(pixels(to, 5 * width_px + 6), 0.4f * length);
  const Vec3f base = b - head * d;
  ribbon(a, base, c, width_px);
  // The head: a flat triangle facing the camera.
  Vec3f side = d.cross(b - view_.eye);
  if (side.squaredNorm() < 1e-30f) side = view_.right;
  side = side.normalized() * (0.45f * head);
  std::vector<Vertex>& list = c.a < 1 ? translucent_ : opaque_;
  for (const Vec3f& p : {Vec3f(base - side), Vec3f(base + side), b}) push(list, p, Vec3f::Zero(), c);
}

void Renderer::label(const labkit::Vec3& p, const std::string& text, Color c, float dx_px, float dy_px) {
  labels_.push_back({f(p), text, c, dx_px, dy_px});
}

void Renderer::grid(double spacing, int count) {
  const double half = spacing * count;
  for (int i = -count; i <= count; ++i) {
    const Color c = (i % 5 == 0) ? Color{0.30f, 0.33f, 0.38f} : Color{0.21f, 0.235f, 0.27f};
    line({i * spacing, -half, 0}, {i * spacing, half, 0}, c, 1.0f);
    line({-half, i * spacing, 0}, {half, i * spacing, 0}, c, 1.0f);
  }
}

void Renderer::axes() {
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const ImVec2 origin(42, float(view_.height) - 42);
  const std::pair<Vec3f, const char*> axes[] = {{Vec3f::UnitX(), "x"}, {Vec3f::UnitY(), "y"}, {Vec3f::UnitZ(), "z"}};
  const ImU32 colours[] = {IM_COL32(205, 107, 107, 255), IM_COL32(115, 184, 115, 255), IM_COL32(115, 148, 224, 255)};
  for (int i = 0; i < 3; ++i) {
    const Vec3f& d = axes[i].first;
    const ImVec2 tip(origin.x + 28 * d.dot(view_.right), origin.y - 28 * d.dot(view_.up));
    list->AddLine(origin, tip, colours[i], 2.0f);
    list->AddText(ImVec2(tip.x + 3 * (tip.x - origin.x) / 28 - 4, tip.y + 3 * (tip.y - origin.y) / 28 - 8), colours[i],
                  axes[i].second);
  }
}

void Renderer::end() {
  const std::size_t count = opaque_.size() + translucent_.size();
  last_triangles_ = count / 3;
  if (count > 0) {
    glUseProgram(program_);
    glUniformMatrix4fv(view_projection_location_, 1, GL_FALSE, view_.view_projection.data());
    const Vec3f light = (-view_.forward + 0.35f * view_.up + 0.2f * view_.right).normalized();
    glUniform3f(light_location_, light.x(), light.y(), light.z());
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    // One upload per frame: opaque vertices, then translucent ones.
    const std::size_t bytes = count * sizeof(Vertex);
    if (bytes > capacity_) {
      capacity_ = bytes + bytes / 2;
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacity_), nullptr, GL_STREAM_DRAW);
    }
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(opaque_.size() * sizeof(Vertex)), opaque_.data());
    glBufferSubData(GL_ARRAY_BUFFER, GLintptr(opaque_.size() * sizeof(Vertex)),
                    GLsizeiptr(translucent_.size() * sizeof(Vertex)), translucent_.data());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(opaque_.size()));
    // Translucent faces: blended over what is already there, without hiding each other.
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glDrawArrays(GL_TRIANGLES, GLint(opaque_.size()), GLsizei(translucent_.size()));
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
  }

  // Labels: projected to the screen, drawn with a dark outline so they read on anything.
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const ImVec2 size(float(view_.width), float(view_.height));
  for (const Label& l : labels_) {
    const Eigen::Vector4f clip = view_.view_projection * l.position.homogeneous();
    if (clip.w() <= 0) continue;
    const float x = (clip.x() / clip.w() * 0.5f + 0.5f) * size.x + l.dx;
    const float y = (0.5f - clip.y() / clip.w() * 0.5f) * size.y + l.dy - ImGui::GetFontSize() / 2;
    const ImU32 shadow = IM_COL32(15, 17, 20, 230);
    for (const ImVec2& o : {ImVec2(-1, 0), ImVec2(1, 0), ImVec2(0, -1), ImVec2(0, 1), ImVec2(1, 1)})
      list->AddText(ImVec2(x + o.x, y + o.y), shadow, l.text.c_str());
    list->AddText(ImVec2(x, y), ImGui::ColorConvertFloat4ToU32(ImVec4(l.color.r, l.color.g, l.color.b, 1)),
                  l.text.c_str());
  }
}

}  // namespace viewer
