// Lab 01 scene: view-frustum clipping by triangle splitting (handouts/01_frustum_split.md).
//
// A replay token's query picks the mode:
//   triangle and plane    signed_distance, classify, split_triangle        steps 1-2
//   triangle and frustum  frustum_from_camera/_matrix, clip_triangle       steps 3-4
//   mesh and frustum      clip_mesh                                        step 5
// Vertices are coloured by the student's class (in: blue, on: white, out: dark), the
// student's pieces by their verdict; the exact polygon (the toggle) is a violet outline.
#include "viewer/scenes/scenes.h"

#include "01_frustum_split.judge.h"
#include "common/oracle/oracle.h"
#include "frustum_split.h"

#include <imgui.h>

#include <cmath>

namespace viewer {
namespace {

using namespace labkit;
using namespace labkit::lab01;

enum class Mode { plane, frustum, mesh };
enum class Source { camera, matrix, planes };  // where the frustum comes from

// The lecture's four configurations: one tilted triangle (heights -1, 1, 3) and the
// plane z = c, "in" above it.
const std::vector<Preset> kPresets = {
    {"all-in", "all three vertices in: the triangle is kept", "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,2", true, -65, 14},
    {"one-in", "one vertex in: one triangle (c0 v2 c1)", "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,-2", true, -65, 14},
    {"two-in", "two vertices in: a quadrilateral, cut into two triangles",
     "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,0", true, -65, 14},
    {"none-in", "no vertex in: the triangle is culled", "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,-4", true, -65, 14},
    {"on-plane", "a vertex exactly on the plane is in, and no edge through it is cut",
     "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,-1"},
    {"frustum", "a triangle clipped to a camera's frustum: a polygon of five corners", nullptr, true, -40, 30, 4},
    {"matrix", "the frustum's planes from a view-projection matrix", nullptr},
    {"mesh", "a coloured mesh clipped to the frustum: colours interpolated at the cuts", nullptr, true, -40, 30, 5},
};

// The default camera: at (0, -1, 1.5), looking along +y, z up (the viewer's up).
Camera default_camera() {
  Camera c;
  c.eye = {0, -1, 1.5};
  c.forward = {0, 1, -0.1};
  c.up = {0, 0, 1};
  c.fov_y = 0.9;
  c.aspect = 1.4;
  c.near = 1;
  c.far = 7;
  return c;
}

// A small terrain in front of the camera, coloured by position.
ColoredMesh terrain() {
  ColoredMesh m;
  const int n = 6;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = -4 + 8.0 * i / n, y = 0.5 + 7.0 * j / n;
      m.mesh.vertices.push_back({x, y, 0.5 * std::sin(x) * std::cos(0.8 * y)});
      m.colors.push_back({double(i) / n, 0.35 + 0.3 * std::sin(y), double(j) / n});
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int v = i * (n + 1) + j;
      m.mesh.triangles.push_back({v, v + n + 1, v + n + 2});
      m.mesh.triangles.push_back({v, v + n + 2, v + 1});
    }
  return m;
}

// The eight corners of a frustum given by its planes (bit 0: right, 1: top, 2: far);
// false when three planes do not meet in a point.
bool corners(const Frustum& f, Vec3 (&out)[8]) {
  for (int i = 0; i < 8; ++i) {
    Mat3 a;
    Vec3 b;
    const int pick[3] = {i & 1 ? Frustum::right : Frustum::left, i & 2 ? Frustum::top : Frustum::bottom,
                         i & 4 ? Frustum::far : Frustum::near};
    for (int k = 0; k < 3; ++k) a.row(k) = f.planes[std::size_t(pick[k])].normal.transpose(), b[k] = -f.planes[std::size_t(pick[k])].offset;
    if (std::abs(a.determinant()) < 1e-12 * std::pow(a.norm(), 3)) return false;
    out[i] = a.partialPivLu().solve(b);
  }
  return true;
}

void draw_frustum(Renderer& r, const Frustum& f, Color c, float width, bool faces) {
  Vec3 p[8];
  if (!corners(f, p)) return;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) r.line(p[i], p[i | bit], c, width);
  if (!faces) return;
  const int quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    r.triangle(p[q[0]], p[q[1]], p[q[2]], palette::surface.with_alpha(0.07f));
    r.triangle(p[q[0]], p[q[2]], p[q[3]], palette::surface.with_alpha(0.07f));
  }
}

std::string side_name(Side s) { return s == Side::in ? "in" : (s == Side::out ? "out" : "on"); }
Color side_colour(Side s) {
  return s == Side::in ? Color{0.35f, 0.62f, 1.0f} : (s == Side::out ? Color{0.40f, 0.40f, 0.44f} : Color{1, 1, 1});
}
double area(const std::vector<Triangle>& pieces) {
  double a = 0;
  for (const Triangle& t : pieces) a += t.area();
  return a;
}
std::string pieces_text(std::size_t n, double a) { return std::to_string(n) + (n == 1 ? " triangle, area " : " triangles, area ") + num(a); }

class FrustumSplitScene : public Scene {
 public:
  explicit FrustumSplitScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void frame_inputs();
  Frustum exact_frustum() const;
  void draw_pieces(Renderer& r, const std::vector<Triangle>& pieces, Verdict v) const;
  void draw_exact(Renderer& r, const Triangle& t, const std::vector<Plane>& planes) const;

  Mode mode_ = Mode::plane;
  Source source_ = Source::camera;
  TrianglePlane split_;           // plane mode
  Vec3 anchor_, last_anchor_;     // plane mode: the plane's handle, a point on it
  Camera camera_ = default_camera();
  Vec3 look_, last_look_, last_eye_;  // frustum modes: the camera's look-at handle
  Mat4 matrix_ = Mat4::Identity();
  Frustum planes_;                // Source::planes: the token's frustum
  Triangle triangle_{{-4, 2.5, 0.2}, {3.5, 3.5, 0}, {-0.5, 5.5, 3.8}};
  ColoredMesh mesh_;

  Attempt<std::array<double, 3>> distances_;
  Attempt<std::array<Side, 3>> sides_;
  Attempt<std::vector<Triangle>> pieces_;
  Attempt<Frustum> frustum_;
  Attempt<ClippedMesh> clipped_;
  Verdict verdict_[7] = {};
};

// ---- setup ---------------------------------------------------------------------------

FrustumSplitScene::FrustumSplitScene(const Setup& setup) {
  const Preset* preset = view_preset(kPresets, setup);
  look_ = camera_.eye + camera_.forward.normalized() * 0.5 * (camera_.near + camera_.far);
  if (setup.token.empty() && preset && !preset->token) {
    mode_ = preset->name == std::string("mesh") ? Mode::mesh : Mode::frustum;
    if (mode_ == Mode::mesh) mesh_ = terrain();
    if (preset->name == std::string("matrix")) source_ = Source::matrix, matrix_ = view_projection(parameters_of(camera_));
    frame_inputs();
    return;
  }
  const ParsedToken token = parse_token(starting_token(setup, kPresets, kPresets[2].token));
  const std::string& q = token.query;
  if (q == "signed_distance" || q == "classify" || q == "split_triangle" || q == "robust.classify" ||
      q == "robust.split_triangle") {
    split_ = input_from_token<TrianglePlane>(token);
  } else if (q == "frustum_from_camera") {
    mode_ = Mode::frustum, camera_ = input_from_token<Camera>(token);
    look_ = camera_.eye + camera_.forward.normalized() * 0.5 * (camera_.near + camera_.far);
  } else if (q == "frustum_from_matrix") {
    mode_ = Mode::frustum, source_ = Source::matrix, matrix_ = input_from_token<Mat4>(token);
  } else if (q == "clip_triangle" || q == "robust.clip_triangle") {
    const auto in = input_from_token<TriangleFrustum>(token);
    mode_ = Mode::frustum, source_ = Source::planes, triangle_ = in.triangle, planes_ = in.frustum;
  } else if (q == "clip_mesh") {
    const auto in = input_from_token<MeshFrustum>(token);
    mode_ = Mode::mesh, source_ = Source::planes, mesh_ = {in.mesh, in.colors}, planes_ = in.frustum;
  } else {
    throw unknown_query("01", q, "signed_distance, classify, split_triangle, frustum_from_camera, "
                                  "frustum_from_matrix, clip_triangle, clip_mesh");
  }
  frame_inputs();
}

void FrustumSplitScene::frame_inputs() {
  const char* names[] = {"triangle and plane", "triangle and frustum", "mesh and frustum"};
  mode = names[int(mode_)];
  const Triangle& t = split_.triangle;
  const Vec3 c = (t.v0 + t.v1 + t.v2) / 3;
  const Plane& p = split_.plane;
  anchor_ = last_anchor_ = p.normal == Vec3::Zero() ? c : Vec3(c - p.value(c) / p.normal.squaredNorm() * p.normal);
  last_look_ = look_, last_eye_ = camera_.eye;
  Eigen::AlignedBox3d box;
  if (mode_ == Mode::plane) {
    for (const Vec3& v : {t.v0, t.v1, t.v2, anchor_}) box.extend(v);
  } else {
    Vec3 p8[8];
    if (corners(exact_frustum(), p8))
      for (const Vec3& v : p8) box.extend(v);
    for (const Vec3& v : mode_ == Mode::mesh ? mesh_.mesh.vertices : std::vector<Vec3>{triangle_.v0, triangle_.v1, triangle_.v2})
      box.extend(v);
  }
  frame(box);
}

Frustum FrustumSplitScene::exact_frustum() const {
  if (source_ == Source::camera) return frustum_of(parameters_of(camera_));
  if (source_ == Source::matrix) return Frustum{oracle::frustum_planes(matrix_)};
  return planes_;
}

// ---- update --------------------------------------------------------------------------

void FrustumSplitScene::update() {
  steps.clear();
  if (mode_ == Mode::plane) {
    Plane& plane = split_.plane;  // the anchor moves the plane; editing the plane moves the anchor
    if (anchor_ != last_anchor_) plane.offset = -plane.normal.dot(anchor_);
    else if (plane.normal != Vec3::Zero()) anchor_ -= plane.value(anchor_) / plane.normal.squaredNorm() * plane.normal;
    last_anchor_ = anchor_;
    const Triangle& t = split_.triangle;
    distances_ = attempt([&] {
      return std::array<double, 3>{signed_distance(plane, t.v0), signed_distance(plane, t.v1), signed_distance(plane, t.v2)};
    });
    sides_ = attempt([&] { return classify(plane, t); });
    Step one = judged("L01S1", "signed_distance, classify", distances_,
                      [&](const std::array<double, 3>& got) { return judge::signed_distance(split_, got); });
    const Step classes = judged("", "", sides_, [&](const std::array<Side, 3>& got) { return judge::classify(split_, got); });
    join(one, classes);
    for (int i = 0; i < 3; ++i) {
      const int s = oracle::side(plane, t[i]);
      one.rows.push_back({"v" + std::to_string(i),
                          (distances_ ? num((*distances_)[std::size_t(i)]) : "") + (sides_ ? ", " + side_name((*sides_)[std::size_t(i)]) : ""),
                          num(oracle::signed_distance(plane, t[i])) + ", " + (s > 0 ? "in" : s < 0 ? "out" : "on")});
    }
    pieces_ = attempt([&] { return split_triangle(t, plane); });
    Step two = judged("L01S2", "split_triangle", pieces_, [&](const std::vector<Triangle>& got) { return judge::split_triangle(split_, got); });
    const oracle::ClippedPolygon exact = oracle::clip(t, {plane});
    two.rows = {{"kept", pieces_ ? pieces_text(pieces_->size(), area(*pieces_)) : "", pieces_text(std::size_t(exact.triangles()), exact.area)}};
    verdict_[1] = one.verdict, verdict_[2] = two.verdict;
    steps = {one, two};
    return;
  }

  if (source_ == Source::camera && (look_ != last_look_ || camera_.eye != last_eye_)) camera_.forward = look_ - camera_.eye;
  last_look_ = look_, last_eye_ = camera_.eye;
  const Frustum exact = exact_frustum();
  if (source_ == Source::planes) {
    steps.push_back({"L01S3", "the frustum's planes", Verdict::none, {}, "this case gives the planes themselves"});
    frustum_.value.reset();
  } else {
    frustum_ = attempt([&] { return source_ == Source::camera ? frustum_from_camera(camera_) : frustum_from_matrix(matrix_); });
    Step three = judged("L01S3", source_ == Source::camera ? "frustum_from_camera" : "frustum_from_matrix", frustum_,
                        [&](const Frustum& got) {
                          return source_ == Source::camera ? judge::frustum_from_camera(camera_, got) : judge::frustum_from_matrix(matrix_, got);
                        });
    const char* names[] = {"left", "right", "bottom", "top", "near", "far"};
    for (int k = 0; k < 6; ++k) {
      const Plane& e = exact.planes[std::size_t(k)];
      const std::string yours = frustum_ ? num(frustum_->planes[std::size_t(k)].normal) + " " + num(frustum_->planes[std::size_t(k)].offset) : "";
      three.rows.push_back({names[k], yours, num(e.normal) + " " + num(e.offset)});
    }
    verdict_[3] = three.verdict;
    steps.push_back(three);
  }
  const std::vector<Plane> planes(exact.planes.begin(), exact.planes.end());
  if (mode_ == Mode::frustum) {
    pieces_ = attempt([&] { return clip_triangle(triangle_, exact); });
    Step four = judged("L01S4", "clip_triangle (to the exact frustum)", pieces_,
                       [&](const std::vector<Triangle>& got) { return judge::clip_triangle({triangle_, exact}, got); });
    const oracle::ClippedPolygon e = oracle::clip(triangle_, planes);
    four.rows = {{"kept", pieces_ ? pieces_text(pieces_->size(), area(*pieces_)) : "", pieces_text(std::size_t(e.triangles()), e.area)},
                 {"corners", pieces_ ? "" : "", std::to_string(e.corners.size())}};
    verdict_[4] = four.verdict;
    steps.push_back(four);
  } else {
    clipped_ = attempt([&] { return clip_mesh(mesh_, exact); });
    Step five = judged("L01S5", "clip_mesh (to the exact frustum)", clipped_,
                       [&](const ClippedMesh& got) { return judge::clip_mesh({mesh_.mesh, mesh_.colors, exact}, got); });
    std::size_t count = 0;
    double total = 0;
    for (std::size_t i = 0; i < mesh_.mesh.size(); ++i) {
      const oracle::ClippedPolygon e = oracle::clip(mesh_.mesh.triangle(i), planes);
      count += std::size_t(e.triangles()), total += e.area;
    }
    double got = 0;
    if (clipped_) for (std::size_t i = 0; i < clipped_->mesh.size(); ++i) got += clipped_->mesh.triangle(i).area();
    five.rows = {{"kept", clipped_ ? pieces_text(clipped_->mesh.size(), got) : "", pieces_text(count, total)}};
    verdict_[5] = five.verdict;
    steps.push_back(five);
  }
}

// ---- draw ----------------------------------------------------------------------------

void FrustumSplitScene::draw_pieces(Renderer& r, const std::vector<Triangle>& pieces, Verdict v) const {
  const Color c = colour(v);
  for (const Triangle& p : pieces) {
    r.triangle(p.v0, p.v1, p.v2, c.with_alpha(0.55f));
    for (int i = 0; i < 3; ++i) r.line(p[i], p[(i + 1) % 3], c, 1.5f);
  }
}

void FrustumSplitScene::draw_exact(Renderer& r, const Triangle& t, const std::vector<Plane>& planes) const {
  const oracle::ClippedPolygon e = oracle::clip(t, planes);
  if (!e.has_area) return;
  const float width = mode_ == Mode::mesh ? 1.2f : 3.0f;
  for (std::size_t i = 0; i < e.corners.size(); ++i) r.line(e.corners[i], e.corners[(i + 1) % e.corners.size()], palette::exact, width);
}

void FrustumSplitScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::plane) {
    const Triangle& t = split_.triangle;
    const Plane& p = split_.plane;
    const double size = std::max({(t.v1 - t.v0).norm(), (t.v2 - t.v1).norm(), (t.v0 - t.v2).norm(), 1e-9});
    if (p.normal != Vec3::Zero()) {  // the plane: a translucent square around its handle, its normal pointing in
      const Vec3 n = p.normal.normalized(), u = n.unitOrthogonal(), w = n.cross(u), c = anchor_;
      const Vec3 q[4] = {c + size * (u + w), c + size * (-u + w), c + size * (-u - w), c + size * (u - w)};
      r.triangle(q[0], q[1], q[2], palette::surface.with_alpha(0.22f));
      r.triangle(q[0], q[2], q[3], palette::surface.with_alpha(0.22f));
      for (int i = 0; i < 4; ++i) r.line(q[i], q[(i + 1) % 4], palette::surface, 1);
      r.arrow(c, c + 0.35 * size * n, palette::muted, 2);
      r.label(c + 0.35 * size * n, "in", palette::muted);
    }
    for (int i = 0; i < 3; ++i) r.dashed(t[i], t[(i + 1) % 3], palette::muted, 1.5f);
    if (pieces_ && f.shows(2)) draw_pieces(r, *pieces_, verdict_[2]);
    if (f.show_exact && f.shows(2)) draw_exact(r, t, {p});
    // The cut points, named as the handout and the lecture's figure name them: c0, c1 in
    // the order the walk v0 -> v1 -> v2 -> v0 meets them (only sides whose ends have
    // strictly opposite signs are cut). Each label sits away from the triangle's middle.
    const Vec3 middle = (t.v0 + t.v1 + t.v2) / 3;
    int cuts = 0;
    for (int i = 0; i < 3; ++i) {
      const Vec3 &a = t[i], &b = t[(i + 1) % 3];
      const double da = p.value(a), db = p.value(b);
      if (!((da > 0 && db < 0) || (da < 0 && db > 0))) continue;
      const Vec3 c = (da * b - db * a) / (da - db);
      const bool left = (c - middle).dot(r.view().right.cast<double>()) < 0;
      const bool below = (c - middle).dot(r.view().up.cast<double>()) < 0;
      r.point(c, palette::muted, 4);
      r.label(c, "c" + std::to_string(cuts++), palette::input, left ? -24 : 8, below ? 2 : -8);
    }
    for (int i = 0; i < 3; ++i) {
      const Side side = sides_ ? (*sides_)[std::size_t(i)] : Side::on;
      r.point(t[i], sides_ && f.shows(1) ? side_colour(side) : palette::input, 7);
      std::string text = "v" + std::to_string(i);
      if (distances_ && f.shows(1)) text += "   d = " + num((*distances_)[std::size_t(i)]);
      if (sides_ && f.shows(1)) text += ", " + side_name(side);
      r.label(t[i], text, f.shows(1) ? colour(verdict_[1]) : palette::muted);
      const int exact = oracle::side(p, t[i]);
      if (sides_ && f.shows(1) && exact != int((*sides_)[std::size_t(i)])) r.ring(t[i], palette::disagree, 12, 2.5f);
    }
    return;
  }

  const Frustum exact = exact_frustum();
  const std::vector<Plane> planes(exact.planes.begin(), exact.planes.end());
  draw_frustum(r, exact, frustum_ && f.shows(3) ? palette::muted.with_alpha(0.5f) : palette::muted, 1.5f, true);
  if (frustum_ && f.shows(3)) draw_frustum(r, *frustum_, colour(verdict_[3]), 2.5f, false);
  if (f.show_exact && f.shows(3) && source_ != Source::planes) draw_frustum(r, exact, palette::exact, 1.2f, false);
  if (source_ == Source::camera) {
    r.point(camera_.eye, palette::input, 6), r.label(camera_.eye, "eye", palette::input);
    r.dashed(camera_.eye, look_, palette::input, 1.5f);
    r.point(look_, palette::input, 5), r.label(look_, "look", palette::input);
  }
  if (mode_ == Mode::frustum) {
    const Triangle& t = triangle_;
    r.triangle(t.v0, t.v1, t.v2, palette::surface.with_alpha(0.18f));
    for (int i = 0; i < 3; ++i) {
      r.dashed(t[i], t[(i + 1) % 3], palette::muted, 1.5f);
      r.point(t[i], palette::input, 6), r.label(t[i], "v" + std::to_string(i), palette::input);
    }
    if (pieces_ && f.shows(4)) draw_pieces(r, *pieces_, verdict_[4]);
    if (f.show_exact && f.shows(4)) draw_exact(r, t, planes);
    return;
  }
  const Mesh& m = mesh_.mesh;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Triangle t = m.triangle(i);
    for (int k = 0; k < 3; ++k) r.line(t[k], t[(k + 1) % 3], palette::muted.with_alpha(0.45f), 1);
    if (f.show_exact && f.shows(5)) draw_exact(r, t, planes);
  }
  if (!clipped_ || !f.shows(5)) return;
  const Mesh& out = clipped_->mesh;
  const auto colour_of = [&](int v) {
    const Vec3 c = std::size_t(v) < clipped_->colors.size() ? clipped_->colors[std::size_t(v)] : Vec3(1, 0, 1);
    return Color{float(c.x()), float(c.y()), float(c.z())};
  };
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto& face = out.triangles[i];
    r.triangle(out.vertices[std::size_t(face[0])], out.vertices[std::size_t(face[1])], out.vertices[std::size_t(face[2])],
               colour_of(face[0]), colour_of(face[1]), colour_of(face[2]));
    const Triangle t = out.triangle(i);
    for (int k = 0; k < 3; ++k) r.line(t[k], t[(k + 1) % 3], colour(verdict_[5]), 1.5f);
  }
}

bool FrustumSplitScene::inputs() {
  bool changed = false;
  if (mode_ == Mode::plane) {
    Triangle& t = split_.triangle;
    changed |= edit("v0", t.v0) | edit("v1", t.v1) | edit("v2", t.v2);
    changed |= edit("plane normal", split_.plane.normal) | edit("plane offset", split_.plane.offset);
    return changed;
  }
  if (source_ == Source::camera) {
    changed |= edit("eye", camera_.eye) | edit("forward", camera_.forward) | edit("up", camera_.up);
    changed |= edit("fov_y (radians)", camera_.fov_y, 0.01f, 0.05, 3.0) | edit("aspect", camera_.aspect, 0.01f, 0.1, 10);
    changed |= edit("near", camera_.near, 0.01f, 1e-3, camera_.far) | edit("far", camera_.far, 0.05f, camera_.near, 1e6);
    if (changed) look_ = last_look_ = camera_.eye + camera_.forward.normalized() * 0.5 * (camera_.near + camera_.far);
  } else {
    ImGui::TextDisabled(source_ == Source::matrix ? "the frustum: from a view-projection matrix" : "the frustum: six planes");
  }
  if (mode_ == Mode::frustum) changed |= edit("v0", triangle_.v0) | edit("v1", triangle_.v1) | edit("v2", triangle_.v2);
  else ImGui::TextDisabled("mesh: %zu vertices, %zu triangles", mesh_.mesh.vertices.size(), mesh_.mesh.size());
  return changed;
}

std::vector<Handle> FrustumSplitScene::handles() {
  if (mode_ == Mode::plane) {
    Triangle& t = split_.triangle;
    return {{&t.v0, "v0"}, {&t.v1, "v1"}, {&t.v2, "v2"}, {&anchor_, "plane"}};
  }
  std::vector<Handle> h;
  if (source_ == Source::camera) h = {{&camera_.eye, "eye"}, {&look_, "look"}};
  if (mode_ == Mode::frustum) h.insert(h.end(), {{&triangle_.v0, "v0"}, {&triangle_.v1, "v1"}, {&triangle_.v2, "v2"}});
  return h;
}

std::string FrustumSplitScene::token() const {
  if (mode_ == Mode::plane) return replay_token("split_triangle", split_);
  if (mode_ == Mode::frustum) return replay_token("clip_triangle", TriangleFrustum{triangle_, exact_frustum()});
  return replay_token("clip_mesh", MeshFrustum{mesh_.mesh, mesh_.colors, exact_frustum()});
}

}  // namespace

std::unique_ptr<Scene> make_frustum_split(const Setup& setup) { return std::make_unique<FrustumSplitScene>(setup); }
const std::vector<Preset>& frustum_split_presets() { return kPresets; }

}  // namespace viewer
