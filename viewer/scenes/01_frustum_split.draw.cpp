// Lab 01 scene, its drawing: the plane or the frustum, the student's pieces in their
// verdict's colour, the exact polygon (the toggle) as a violet outline; and the panel.
#include "viewer/scenes/01_frustum_split.h"

#include "common/oracle/oracle.h"

#include <imgui.h>

#include <cmath>

namespace viewer::frustum_split {

// ---- draw ----------------------------------------------------------------------------

void draw_frustum(Renderer& r, const Frustum& f, Color c, float width, bool faces) {
  Corners p;
  if (!corners(f, p)) return;
  draw_edges(r, p, c, width);
  if (faces) draw_faces(r, p, palette::surface.with_alpha(0.07f));
}

Color side_colour(Side s) {
  return s == Side::in ? Color{0.35f, 0.62f, 1.0f} : (s == Side::out ? Color{0.40f, 0.40f, 0.44f} : Color{1, 1, 1});
}

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
  for (std::size_t i = 0; i < e.corners.size(); ++i)
    r.line(e.corners[i], e.corners[(i + 1) % e.corners.size()], palette::exact, width);
}

// Step 1-2: one triangle against one plane, its vertices' sides and the cut points.
void FrustumSplitScene::draw_plane(Frame& f) const {
  Renderer& r = f.render;
  const Triangle& t = split_.triangle;
  const Plane& p = split_.plane;
  const double size = std::max({(t.v1 - t.v0).norm(), (t.v2 - t.v1).norm(), (t.v0 - t.v2).norm(), 1e-9});
  if (p.normal != Vec3::Zero()) {  // the plane: a translucent square around its handle, its normal pointing in
    const Vec3 n = p.normal.normalized(), u = n.unitOrthogonal(), c = anchor_;
    const Square q = square_around(c, u, n.cross(u), size);
    fill(r, q, palette::surface.with_alpha(0.22f));
    outline(r, q, palette::surface, 1);
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
}

// Steps 3-4: the frustum (the answer's, the exact one) and one triangle split by it.
void FrustumSplitScene::draw_frustum_triangle(Frame& f, const std::vector<Plane>& planes) const {
  Renderer& r = f.render;
  const Triangle& t = triangle_;
  r.triangle(t.v0, t.v1, t.v2, palette::surface.with_alpha(0.18f));
  for (int i = 0; i < 3; ++i) {
    r.dashed(t[i], t[(i + 1) % 3], palette::muted, 1.5f);
    r.point(t[i], palette::input, 6), r.label(t[i], "v" + std::to_string(i), palette::input);
  }
  if (pieces_ && f.shows(4)) draw_pieces(r, *pieces_, verdict_[4]);
  if (f.show_exact && f.shows(4)) draw_exact(r, t, planes);
}

// Step 5: the mesh and its clipped, coloured pieces.
void FrustumSplitScene::draw_mesh(Frame& f, const std::vector<Plane>& planes) const {
  Renderer& r = f.render;
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
    r.triangle(out.vertices[std::size_t(face[0])], out.vertices[std::size_t(face[1])],
               out.vertices[std::size_t(face[2])], colour_of(face[0]), colour_of(face[1]), colour_of(face[2]));
    const Triangle t = out.triangle(i);
    for (int k = 0; k < 3; ++k) r.line(t[k], t[(k + 1) % 3], colour(verdict_[5]), 1.5f);
  }
}

void FrustumSplitScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::plane) return draw_plane(f);
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
  if (mode_ == Mode::frustum) return draw_frustum_triangle(f, planes);
  draw_mesh(f, planes);
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
    changed |=
        edit("fov_y (radians)", camera_.fov_y, 0.01f, 0.05, 3.0) | edit("aspect", camera_.aspect, 0.01f, 0.1, 10);
    changed |=
        edit("near", camera_.near, 0.01f, 1e-3, camera_.far) | edit("far", camera_.far, 0.05f, camera_.near, 1e6);
    if (changed) look_ = last_look_ = camera_.eye + camera_.forward.normalized() * 0.5 * (camera_.near + camera_.far);
  } else {
    ImGui::TextDisabled(source_ == Source::matrix ? "the frustum: from a view-projection matrix"
                                                  : "the frustum: six planes");
  }
  if (mode_ == Mode::frustum)
    changed |= edit("v0", triangle_.v0) | edit("v1", triangle_.v1) | edit("v2", triangle_.v2);
  else
    ImGui::TextDisabled("mesh: %zu vertices, %zu triangles", mesh_.mesh.vertices.size(), mesh_.mesh.size());
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

}  // namespace viewer::frustum_split
