// Lab 01 scene: view-frustum clipping by triangle splitting (handouts/01_frustum_split.md).
//
// A replay token's query picks the mode:
//   triangle and plane    signed_distance, classify, split_triangle        steps 1-2
//   triangle and frustum  frustum_from_camera/_matrix, clip_triangle       steps 3-4
//   mesh and frustum      clip_mesh                                        step 5
// Vertices are coloured by the student's class (in: blue, on: white, out: dark), the
// student's pieces by their verdict; the exact polygon (the toggle) is a violet outline.
#include "viewer/scenes/01_frustum_split.h"
#include "viewer/scenes/scenes.h"

#include "common/generators/meshes.h"
#include "common/oracle/oracle.h"

#include <cmath>

namespace viewer::frustum_split {

// The lecture's four configurations: one tilted triangle (heights -1, 1, 3) and the
// plane z = c, "in" above it.
const std::vector<Preset> kPresets = {
    {"all-in", "all three vertices in: the triangle is kept", "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,2", true,
     -65, 14},
    {"one-in", "one vertex in: one triangle (c0 v2 c1)", "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,-2", true, -65,
     14},
    {"two-in", "two vertices in: a quadrilateral, cut into two triangles",
     "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,0", true, -65, 14},
    {"none-in", "no vertex in: the triangle is culled", "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,-4", true, -65,
     14},
    {"on-plane", "a vertex exactly on the plane is in, and no edge through it is cut",
     "split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,-1"},
    {"frustum", "a triangle clipped to a camera's frustum: a polygon of five corners", nullptr, true, -40, 30, 4},
    {"matrix", "the frustum's planes from a view-projection matrix", nullptr},
    {"mesh", "a coloured mesh clipped to the frustum: colours interpolated at the cuts", nullptr, true, -40, 30, 5},
};

// A small terrain in front of the camera, coloured by position.
ColoredMesh terrain() {
  const int n = 6;
  ColoredMesh m{
      gen::height_field(n, -4, 4, 0.5, 7.5, [](double x, double y) { return 0.5 * std::sin(x) * std::cos(0.8 * y); }),
      {}};
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double y = m.mesh.vertices[std::size_t(i * (n + 1) + j)].y();
      m.colors.push_back({double(i) / n, 0.35 + 0.3 * std::sin(y), double(j) / n});
    }
  return m;
}

bool corners(const Frustum& f, Corners& out) {
  for (int i = 0; i < 8; ++i) {
    Mat3 a;
    Vec3 b;
    const int pick[3] = {i & 1 ? Frustum::right : Frustum::left, i & 2 ? Frustum::top : Frustum::bottom,
                         i & 4 ? Frustum::far : Frustum::near};
    for (int k = 0; k < 3; ++k)
      a.row(k) = f.planes[std::size_t(pick[k])].normal.transpose(), b[k] = -f.planes[std::size_t(pick[k])].offset;
    if (std::abs(a.determinant()) < 1e-12 * std::pow(a.norm(), 3)) return false;
    out[std::size_t(i)] = a.partialPivLu().solve(b);
  }
  return true;
}

std::string side_name(Side s) { return s == Side::in ? "in" : (s == Side::out ? "out" : "on"); }
double area(const std::vector<Triangle>& pieces) {
  double a = 0;
  for (const Triangle& t : pieces) a += t.area();
  return a;
}
std::string pieces_text(std::size_t n, double a) {
  return std::to_string(n) + (n == 1 ? " triangle, area " : " triangles, area ") + num(a);
}

// ---- setup ---------------------------------------------------------------------------

FrustumSplitScene::FrustumSplitScene(const Setup& setup) {
  const Preset* preset = view_preset(kPresets, setup);
  look_ = camera_.eye + camera_.forward.normalized() * 0.5 * (camera_.near + camera_.far);
  if (setup.token.empty() && preset && !preset->token) {
    mode_ = preset->name == std::string("mesh") ? Mode::mesh : Mode::frustum;
    if (mode_ == Mode::mesh) mesh_ = terrain();
    if (preset->name == std::string("matrix"))
      source_ = Source::matrix, matrix_ = view_projection(parameters_of(camera_));
    frame_inputs();
    return;
  }
  const ParsedToken token = parse_token(starting_token(setup, kPresets, kPresets[2].token));
  load_token("01", query::table, token,
             Loaders{[&](auto, const TrianglePlane& in) { split_ = in; },
                     [&](auto, const Camera& in) {
    mode_ = Mode::frustum, camera_ = in;
    look_ = camera_.eye + camera_.forward.normalized() * 0.5 * (camera_.near + camera_.far);
                     },
                     [&](auto, const Mat4& in) { mode_ = Mode::frustum, source_ = Source::matrix, matrix_ = in; },
                     [&](auto, const TriangleFrustum& in) {
    mode_ = Mode::frustum, source_ = Source::planes, triangle_ = in.triangle, planes_ = in.frustum;
             },
             [&](auto, const MeshFrustum& in) {
    mode_ = Mode::mesh, source_ = Source::planes, mesh_ = {in.mesh, in.colors}, planes_ = in.frustum;
  }});
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
    Corners p8;
    if (corners(exact_frustum(), p8))
      for (const Vec3& v : p8) box.extend(v);
    for (const Vec3& v :
         mode_ == Mode::mesh ? mesh_.mesh.vertices : std::vector<Vec3>{triangle_.v0, triangle_.v1, triangle_.v2})
      box.extend(v);
  }
  frame(box);
}

Frustum FrustumSplitScene::exact_frustum() const {
  if (source_ == Source::camera) return frustum_of(parameters_of(camera_));
  if (source_ == Source::matrix) return Frustum{oracle::frustum_planes(matrix_)};
  return planes_;
}

std::string FrustumSplitScene::token() const {
  if (mode_ == Mode::plane) return replay_token(query::split_triangle, split_);
  if (mode_ == Mode::frustum) return replay_token(query::clip_triangle, TriangleFrustum{triangle_, exact_frustum()});
  return replay_token(query::clip_mesh, MeshFrustum{mesh_.mesh, mesh_.colors, exact_frustum()});
}

// ---- update --------------------------------------------------------------------------

void FrustumSplitScene::update() {
  steps.clear();
  switch (mode_) {
    case Mode::plane: update_plane(); break;
    case Mode::frustum: update_frustum(); break;
    case Mode::mesh: update_mesh(); break;
  }
}

// Steps 1 and 2: the vertices' distances and sides, and the triangle split by the plane.
void FrustumSplitScene::update_plane() {
  Plane& plane = split_.plane;  // the anchor moves the plane; editing the plane moves the anchor
  if (anchor_ != last_anchor_)
    plane.offset = -plane.normal.dot(anchor_);
  else if (plane.normal != Vec3::Zero())
    anchor_ -= plane.value(anchor_) / plane.normal.squaredNorm() * plane.normal;
  last_anchor_ = anchor_;
  const Triangle& t = split_.triangle;
  distances_ = attempt([&] {
    return std::array<double, 3>{signed_distance(plane, t.v0), signed_distance(plane, t.v1),
                                 signed_distance(plane, t.v2)};
  });
  sides_ = attempt([&] { return classify(plane, t); });
  Step one = judged("L01S1", "signed_distance, classify", distances_,
                    [&](const std::array<double, 3>& got) { return judge::signed_distance(split_, got); });
  join(one, sides_, [&](const std::array<Side, 3>& got) { return judge::classify(split_, got); });
  for (int i = 0; i < 3; ++i) {
    const int s = oracle::side(plane, t[i]);
    one.rows.push_back({"v" + std::to_string(i),
                        (distances_ ? num((*distances_)[std::size_t(i)]) : "") +
                            (sides_ ? ", " + side_name((*sides_)[std::size_t(i)]) : ""),
                        num(oracle::signed_distance(plane, t[i])) + ", " +
                            (s > 0   ? "in"
                             : s < 0 ? "out"
                                     : "on")});
  }
  pieces_ = attempt([&] { return split_triangle(t, plane); });
  Step two = judged("L01S2", "split_triangle", pieces_,
                    [&](const std::vector<Triangle>& got) { return judge::split_triangle(split_, got); });
  const oracle::ClippedPolygon exact = oracle::clip(t, {plane});
  two.rows = {{"kept", pieces_ ? pieces_text(pieces_->size(), area(*pieces_)) : "",
               pieces_text(std::size_t(exact.triangles()), exact.area)}};
  verdict_[1] = one.verdict, verdict_[2] = two.verdict;
  steps = {one, two};
}

// Step 3: the frustum's planes from the camera or the matrix; the steps after it clip to
// the exact frustum, which it returns.
Frustum FrustumSplitScene::update_planes() {
  if (source_ == Source::camera && (look_ != last_look_ || camera_.eye != last_eye_))
    camera_.forward = look_ - camera_.eye;
  last_look_ = look_, last_eye_ = camera_.eye;
  const Frustum exact = exact_frustum();
  if (source_ == Source::planes) {
    steps.push_back({"L01S3", "the frustum's planes", Verdict::none, {}, "this case gives the planes themselves"});
    frustum_.value.reset();
  } else {
    frustum_ = attempt(
        [&] { return source_ == Source::camera ? frustum_from_camera(camera_) : frustum_from_matrix(matrix_); });
    Step three = judged("L01S3", source_ == Source::camera ? "frustum_from_camera" : "frustum_from_matrix", frustum_,
                        [&](const Frustum& got) {
      return source_ == Source::camera ? judge::frustum_from_camera(camera_, got)
                                       : judge::frustum_from_matrix(matrix_, got);
    });
    const char* names[] = {"left", "right", "bottom", "top", "near", "far"};
    for (int k = 0; k < 6; ++k) {
      const Plane& e = exact.planes[std::size_t(k)];
      const std::string yours =
          frustum_ ? num(frustum_->planes[std::size_t(k)].normal) + " " + num(frustum_->planes[std::size_t(k)].offset)
                   : "";
      three.rows.push_back({names[k], yours, num(e.normal) + " " + num(e.offset)});
    }
    verdict_[3] = three.verdict;
    steps.push_back(three);
  }
  return exact;
}

void FrustumSplitScene::update_frustum() {
  const Frustum exact = update_planes();
  const std::vector<Plane> planes(exact.planes.begin(), exact.planes.end());
  pieces_ = attempt([&] { return clip_triangle(triangle_, exact); });
  Step four = judged("L01S4", "clip_triangle (to the exact frustum)", pieces_, [&](const std::vector<Triangle>& got) {
    return judge::clip_triangle({triangle_, exact}, got);
  });
  const oracle::ClippedPolygon e = oracle::clip(triangle_, planes);
  four.rows = {{"kept", pieces_ ? pieces_text(pieces_->size(), area(*pieces_)) : "",
                pieces_text(std::size_t(e.triangles()), e.area)},
               {"corners", pieces_ ? "" : "", std::to_string(e.corners.size())}};
  verdict_[4] = four.verdict;
  steps.push_back(four);
}

void FrustumSplitScene::update_mesh() {
  const Frustum exact = update_planes();
  const std::vector<Plane> planes(exact.planes.begin(), exact.planes.end());
  clipped_ = attempt([&] { return clip_mesh(mesh_, exact); });
  Step five = judged("L01S5", "clip_mesh (to the exact frustum)", clipped_, [&](const ClippedMesh& got) {
    return judge::clip_mesh({mesh_.mesh, mesh_.colors, exact}, got);
  });
  std::size_t count = 0;
  double total = 0;
  for (std::size_t i = 0; i < mesh_.mesh.size(); ++i) {
    const oracle::ClippedPolygon e = oracle::clip(mesh_.mesh.triangle(i), planes);
    count += std::size_t(e.triangles()), total += e.area;
  }
  double got = 0;
  if (clipped_)
    for (std::size_t i = 0; i < clipped_->mesh.size(); ++i) got += clipped_->mesh.triangle(i).area();
  five.rows = {{"kept", clipped_ ? pieces_text(clipped_->mesh.size(), got) : "", pieces_text(count, total)}};
  verdict_[5] = five.verdict;
  steps.push_back(five);
}

// ---- draw: in 01_frustum_split.draw.cpp, with inputs() and handles() ----------------

}  // namespace viewer::frustum_split

LABKIT_SCENE(frustum_split, FrustumSplitScene)
