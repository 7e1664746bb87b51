// Lab 06 scene, its drawing: the mesh and the leaves a segment meets, the BSP's pieces,
// the spheres and their pairs, the frames' ends on x, the OBB trees' boxes, the
// student's answers in their verdict's colour; and the panel.
#include "viewer/scenes/06_spatial_trees.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace viewer::spatial_trees {

// ---- draw ----------------------------------------------------------------------------

void draw_box(Renderer& r, const Aabb& b, Color c, float width) {
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int k = 0; k < 4; ++k) {
      Vec3 p = b.min, q;
      if (k & 1) p[u] = b.max[u];
      if (k & 2) p[v] = b.max[v];
      q = p;
      q[axis] = b.max[axis];
      r.line(p, q, c, width);
    }
  }
}

// The last two frames: the spheres now (the previous centres as faint points), and below
// them each frame's ends on x, the ends whose order changed in orange.
void SpatialTreesScene::draw_frames(Frame& f) {
  Renderer& r = f.render;
  const std::vector<Sphere>& now = frames_.back();
  const std::vector<Sphere>& was = frames_.size() > 1 ? frames_[frames_.size() - 2] : frames_.back();
  const bool figure = figure_ == "coherence";
  const auto name = [&](std::size_t i) { return figure && i < 4 ? std::string(1, "ARBC"[i]) : std::to_string(i); };
  const Color c = colour(verdict_[6]);
  std::vector<char> paired(now.size(), 0);
  if (runs_ && !runs_->empty())
    for (const auto& p : runs_->back().frame.pairs)
      if (p[0] >= 0 && p[1] >= 0 && std::size_t(p[0]) < now.size() && std::size_t(p[1]) < now.size()) {
        paired[std::size_t(p[0])] = paired[std::size_t(p[1])] = 1;
        r.line(now[std::size_t(p[0])].center, now[std::size_t(p[1])].center, c, 3);
      }
  double low = 0, left = 0, right = 1;
  for (std::size_t i = 0; i < now.size(); ++i) {
    const Sphere& b = now[i];
    draw_circle(r, b.center, Vec3::UnitX(), Vec3::UnitY(), b.radius, paired[i] ? c : palette::surface,
                paired[i] ? 2.0f : 1.2f);
    if (was[i].center != b.center)
      r.point(was[i].center, palette::muted, 3), r.arrow(was[i].center, b.center, palette::muted, 1.5f);
    if (now.size() <= 16) r.label(b.center, name(i), palette::input, 6, -6);
    low = i == 0 ? b.center.y() - b.radius : std::min(low, b.center.y() - b.radius);
    left =
        i == 0 ? b.center.x() - b.radius : std::min({left, b.center.x() - b.radius, was[i].center.x() - was[i].radius});
    right = i == 0 ? b.center.x() + b.radius
                   : std::max({right, b.center.x() + b.radius, was[i].center.x() + was[i].radius});
  }
  if (now.empty() || now.size() > 64) return;
  // The ends of both frames on two axes; an end is orange when its order against some other end changed.
  const double gap = 0.08 * (right - left + 1e-300);
  const double y_was = low - 2 * gap, y_now = low - 5 * gap;
  std::vector<char> moved(2 * now.size(), 0);
  const auto value = [](const std::vector<Sphere>& s, std::size_t e) {
    return e % 2 ? s[e / 2].center.x() + s[e / 2].radius : s[e / 2].center.x() - s[e / 2].radius;
  };
  for (std::size_t p = 0; p < moved.size(); ++p)
    for (std::size_t q = 0; q < moved.size(); ++q) {
      const double a = value(was, p) - value(was, q), b = value(now, p) - value(now, q);
      if ((a > 0) - (a < 0) != (b > 0) - (b < 0)) moved[p] = 1;
    }
  const Color swapped{0.95f, 0.62f, 0.20f};
  for (const auto& [y, frame, title] :
       {std::tuple{y_was, &was, "previous frame"}, std::tuple{y_now, &now, "this frame"}}) {
    r.arrow({left - gap, y, 0}, {right + 2 * gap, y, 0}, palette::muted, 1.2f);
    r.label({right + 2 * gap, y, 0}, title, palette::muted, 8, -6);
    for (std::size_t e = 0; e < moved.size(); ++e) {
      const double x = value(*frame, e);
      const Color col = moved[e] && frame == &now ? swapped : palette::input;
      r.point({x, y, 0}, col, 4);
      if (now.size() <= 12) r.label({x, y, 0}, name(e / 2) + (e % 2 ? "1" : "0"), col, -8, (e % 2 ? 8.0f : -22.0f));
    }
  }
  for (std::size_t e = 0; e < moved.size(); ++e)
    if (moved[e]) r.dashed({value(was, e), y_was, 0}, {value(now, e), y_now, 0}, swapped, 1.5f);
}

void SpatialTreesScene::draw_bvh(Frame& f) {
  Renderer& r = f.render;
  const Color other{0.95f, 0.62f, 0.20f};
  for (std::size_t i = 0; i < mesh_.size(); ++i) {
    const Triangle t = mesh_.triangle(i);
    r.triangle(t.v0, t.v1, t.v2, palette::surface.with_alpha(0.35f));
  }
  for (std::size_t i = 0; i < mesh_b_.size(); ++i) {
    const Triangle t = mesh_b_.triangle(i);
    r.triangle(t.v0, t.v1, t.v2, other.with_alpha(0.35f));
  }
  if (!tree_a_.nodes.empty()) {
    draw_box(r, tree_a_.nodes[0].box, palette::surface, 1.5f);
    const Box& b = tree_a_.nodes[0].box;
    int left = 0;
    for (int i = 1; i < 8; ++i) left = b.corner(i).x() < b.corner(left).x() ? i : left;
    r.label(b.corner(left), "a's root box", palette::surface, -100, -8);
  }
  if (!tree_b_.nodes.empty()) {
    draw_box(r, tree_b_.nodes[0].box, other, 1.5f);
    const Box& b = tree_b_.nodes[0].box;
    int right = 0;
    for (int i = 1; i < 8; ++i) right = b.corner(i).x() > b.corner(right).x() ? i : right;
    r.label(b.corner(right), "b's root box", other, 8, -8);
  }
  for (const auto& [i, j] : leaf_pairs_) {
    draw_box(r, tree_a_.nodes[std::size_t(i)].box, palette::surface.with_alpha(0.8f), 1.0f);
    draw_box(r, tree_b_.nodes[std::size_t(j)].box, other.with_alpha(0.8f), 1.0f);
  }
  const Color c = colour(verdict_[7]);
  if (bvh_)
    for (const auto& p : bvh_->answer.pairs) {
      if (p[0] < 0 || p[1] < 0 || std::size_t(p[0]) >= mesh_.size() || std::size_t(p[1]) >= mesh_b_.size()) continue;
      const Triangle s = mesh_.triangle(std::size_t(p[0])), t = mesh_b_.triangle(std::size_t(p[1]));
      r.triangle(s.v0, s.v1, s.v2, c.with_alpha(0.8f)), r.triangle(t.v0, t.v1, t.v2, c.with_alpha(0.8f));
    }
}

void SpatialTreesScene::draw_kd(Frame& f) {
  Renderer& r = f.render;
  draw_mesh(r, mesh_, palette::surface.with_alpha(0.55f));
  if (figure_ == "walk") {  // the leaves the segment meets, numbered in the walk's order
    std::vector<std::pair<double, Aabb>> met;
    for (const LeafBox& l : leaves_) {
      const auto span = segment_span(l.cell, segment_);
      if (span[0] <= span[1]) met.push_back({span[0], l.cell});
    }
    std::sort(met.begin(), met.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    const double stop = first_ && first_->hit ? first_->t : 2.0;
    int k = 0;
    for (const auto& [t0, cell] : met) {
      const bool visited = t0 <= stop;
      draw_box(r, cell, visited ? palette::agree.with_alpha(0.9f) : palette::muted.with_alpha(0.6f),
               visited ? 1.8f : 1.0f);
      const Vec3 at(0.5 * (cell.min.x() + cell.max.x()), 0.5 * (cell.min.y() + cell.max.y()), cell.max.z());
      r.label(at, std::to_string(++k), visited ? palette::agree : palette::muted, -4, -8);
    }
    draw_box(r, tree_.bounds, palette::muted, 1);
    if (first_ && first_->hit) {
      r.ring(first_->point, palette::agree, 12, 2.5f);
      r.label(first_->point, "first hit, t = " + num(first_->t) + ": the walk stops", palette::agree, 10, 28);
    }
    draw_segment(r, segment_);
    return;
  }
  // The leaves the segment meets: the cells a front-to-back walk may visit.
  const Color cells =
      f.shows(1) || f.shows(2) ? colour(tree_is_students_ ? verdict_[1] : Verdict::none) : palette::muted;
  for (const LeafBox& l : leaves_)
    if (segment_meets(l.cell, segment_)) draw_box(r, l.cell, cells.with_alpha(0.8f), 1.2f);
  draw_box(r, tree_.bounds, palette::muted, 1);
  if (f.shows(2)) {
    const Color c = colour(verdict_[2]);
    if (all_)
      for (const KdHit& h : all_->hits) r.point(h.point, c, 4);
    if (first_ && first_->hit) {
      if (first_->triangle >= 0 && std::size_t(first_->triangle) < mesh_.size()) {
        const Triangle t = mesh_.triangle(std::size_t(first_->triangle));
        r.triangle(t.v0, t.v1, t.v2, c.with_alpha(0.7f));
      }
      r.ring(first_->point, c, 14, 2.5f);
      r.label(first_->point, "first hit  t = " + num(first_->t) + "  (" + std::to_string(first_->tests) + " tests)", c,
              18, -16);
    }
    if (f.show_exact) {
      for (const oracle::Crossing& h : exact_hits_)
        r.ring(segment_.a + h.t * (segment_.b - segment_.a), palette::exact, 9);
      if (!exact_hits_.empty()) {
        const Triangle t = mesh_.triangle(std::size_t(exact_hits_[0].triangle));
        for (int i = 0; i < 3; ++i) r.line(t[i], t[(i + 1) % 3], palette::exact, 2);
      }
    }
  }
  draw_segment(r, segment_);
}

void SpatialTreesScene::draw_bsp(Frame& f) {
  Renderer& r = f.render;
  if (figure_ == "split" && bsp_ && !bsp_->nodes.empty()) {  // the root's plane and the pieces on each side
    const BspTree& t = *bsp_;
    const Triangle& splitter = t.triangles[std::size_t(t.nodes[0].plane)];
    const Vec3 n = (splitter.v1 - splitter.v0).cross(splitter.v2 - splitter.v0);
    const Vec3 u = (splitter.v1 - splitter.v0).normalized(), v = n.normalized().cross(u);
    const Vec3 c = center - n.dot(center - splitter.v0) / n.squaredNorm() * n;
    const double h = 0.9 * radius;
    const Color plane{0.95f, 0.72f, 0.25f};
    const Square q = square_around(c, -u, -v, h);  // from c - h u - h v around
    fill(r, q, plane.with_alpha(0.12f));
    outline(r, q, plane, 1.5f, true);
    r.label(c - h * u - h * v, "the root's plane", plane, 8, -8);
    const auto side = [&](const Vec3& x) { return n.dot(x - splitter.v0); };
    for (std::size_t i = 0; i < t.pieces.size(); ++i) {
      const Triangle& p = t.pieces[i].triangle;
      const Vec3 mid = (p.v0 + p.v1 + p.v2) / 3;
      const double d = side(mid);
      const bool at_root = int(i) >= t.nodes[0].first && int(i) < t.nodes[0].first + t.nodes[0].count;
      const Color col = at_root ? plane : d > 0 ? palette::agree : palette::surface;
      r.triangle(p.v0, p.v1, p.v2, col.with_alpha(0.45f));
      for (int e = 0; e < 3; ++e) r.line(p[e], p[(e + 1) % 3], col, 2);
      r.label(at_root ? p.v1 : mid,
              "piece " + std::to_string(i) +
                  (at_root ? ": the splitter"
                   : d > 0 ? ": front"
                           : ": back"),
              col, at_root ? -40.0f : 14.0f, at_root ? 18.0f : 0.0f);
      for (int e = 0; e < 3; ++e) {  // the cut points: on the plane, not a vertex of the mesh
        bool vertex = false;
        for (const Vec3& m : mesh_.vertices) vertex |= (m - p[e]).norm() == 0;
        if (!vertex && !at_root && side(p[e]) == 0) r.point(p[e], palette::input, 5);
      }
    }
    return;
  }
  if (order_ && bsp_ && f.shows(4)) {  // pieces shaded by their place in the painter's order: dark first, light last
    const std::size_t n = order_->size();
    for (std::size_t k = 0; k < n; ++k) {
      const int piece = (*order_)[k];
      if (piece < 0 || std::size_t(piece) >= bsp_->pieces.size()) continue;
      const float w = n > 1 ? float(k) / float(n - 1) : 1.0f;
      const Triangle& t = bsp_->pieces[std::size_t(piece)].triangle;
      r.triangle(t.v0, t.v1, t.v2, Color{0.20f + 0.6f * w, 0.30f + 0.5f * w, 0.55f + 0.4f * w, 0.75f});
      r.line(t.v0, t.v1, palette::muted, 1), r.line(t.v1, t.v2, palette::muted, 1),
          r.line(t.v2, t.v0, palette::muted, 1);
    }
  } else {
    for (std::size_t i = 0; i < mesh_.size(); ++i) {
      const Triangle t = mesh_.triangle(i);
      r.triangle(t.v0, t.v1, t.v2, palette::surface.with_alpha(0.45f));
      r.line(t.v0, t.v1, palette::muted, 1), r.line(t.v1, t.v2, palette::muted, 1),
          r.line(t.v2, t.v0, palette::muted, 1);
    }
  }
  const Color c = colour(verdict_[3]);
  r.point(point_, palette::input, 6);
  if (where_) r.label(point_, "p: " + describe(*where_), c, 12, -12);
  if (f.show_exact && closed_) {
    r.ring(point_, palette::exact, 10);
    r.label(point_,
            "exact: " + std::string(exact_where_ > 0   ? "inside"
                                    : exact_where_ < 0 ? "outside"
                                                       : "on"),
            palette::exact, 12, 8);
  }
}

void SpatialTreesScene::draw_spheres(Frame& f) {
  Renderer& r = f.render;
  if (figure_ == "sweep") {  // circles in z = 0 seen from above, their x intervals below, the ends on one axis
    const char* names[] = {"A", "R", "B", "C"};
    const Color col[] = {palette::surface, palette::agree, {0.95f, 0.72f, 0.25f}, {0.85f, 0.50f, 0.85f}};
    for (std::size_t i = 0; i < spheres_.size() && i < 4; ++i) {
      const Sphere& b = spheres_[i];
      draw_circle(r, b.center, Vec3::UnitX(), Vec3::UnitY(), b.radius, col[i], 2, 64);
      r.point(b.center, col[i], 4);
      r.label(b.center, names[i], col[i], 6, -6);
      const double y = -2.2 - 1.1 * double(i), lo = b.center.x() - b.radius, hi = b.center.x() + b.radius;
      r.line({lo, y, 0}, {hi, y, 0}, col[i], 4);
      r.dashed({lo, y, 0}, {lo, -7, 0}, col[i].with_alpha(0.5f), 1);
      r.dashed({hi, y, 0}, {hi, -7, 0}, col[i].with_alpha(0.5f), 1);
      r.label({hi, y, 0}, std::string(names[i]) + " [" + num(lo) + ", " + num(hi) + "]", col[i], 8, -8);
      r.label({lo, -7, 0}, std::string(names[i]) + "0", col[i], -8, 6);
      r.label({hi, -7, 0}, std::string(names[i]) + "1", col[i], -8, 6);
    }
    r.arrow({-0.5, -7, 0}, {14, -7, 0}, palette::muted, 1.5f);
    r.label({14, -7, 0}, "x", palette::muted, 6, -6);
    if (spheres_.size() >= 4) {
      r.line(spheres_[1].center, spheres_[2].center, palette::agree, 3);
      r.label(0.5 * (spheres_[1].center + spheres_[2].center), "R, B tested: |(4, 3, 0)| = 5 <= 2 + 4, meet",
              palette::agree, 8, 8);
      r.dashed(spheres_[2].center, spheres_[3].center, palette::muted, 2);
      r.label(0.5 * (spheres_[2].center + spheres_[3].center), "B, C tested: 6 > 4 + 1, apart", palette::muted, 8, -8);
    }
    return;
  }
  std::vector<char> paired(spheres_.size(), 0);
  const Color c = colour(verdict_[5]);
  if (pairs_)
    for (const auto& p : pairs_->pairs)
      if (p[0] >= 0 && p[1] >= 0 && std::size_t(p[0]) < spheres_.size() && std::size_t(p[1]) < spheres_.size()) {
        paired[std::size_t(p[0])] = paired[std::size_t(p[1])] = 1;
        r.line(spheres_[std::size_t(p[0])].center, spheres_[std::size_t(p[1])].center, c, 3);
      }
  for (std::size_t i = 0; i < spheres_.size(); ++i)
    draw_sphere(r, spheres_[i].center, spheres_[i].radius, paired[i] ? c : palette::surface, paired[i] ? 1.8f : 1.0f,
                32);
  if (f.show_exact)
    for (const auto& p : exact_pairs_)
      r.dashed(spheres_[std::size_t(p[0])].center, spheres_[std::size_t(p[1])].center, palette::exact, 1.5f);
}

void SpatialTreesScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::kd) draw_kd(f);
  if (mode_ == Mode::bsp) draw_bsp(f);
  if (mode_ == Mode::spheres) draw_spheres(f);
  if (mode_ == Mode::frames) draw_frames(f);
  if (mode_ == Mode::bvh) draw_bvh(f);
  if (mode_ == Mode::hash) draw_hash(f);
  if (mode_ == Mode::octree) draw_octree(f);
}

bool SpatialTreesScene::inputs() {
  bool changed = false;
  if (mode_ == Mode::kd) {
    changed |= edit("a", segment_.a, 0.01f) | edit("b", segment_.b, 0.01f);
    ImGui::TextDisabled("mesh: %zu triangles", mesh_.size());
  }
  if (mode_ == Mode::bsp) changed |= edit("point (and eye)", point_);
  if (mode_ == Mode::spheres) ImGui::TextDisabled("%zu spheres", spheres_.size());
  if (mode_ == Mode::hash) {
    changed |= ImGui::InputInt("buckets", &hash_buckets_);
    hash_buckets_ = std::clamp(hash_buckets_, 1, 1 << 20);
    ImGui::TextDisabled("%zu spheres, cells of side %g", spheres_.size(), hash_cell_);
  }
  if (mode_ == Mode::octree) {
    changed |= ImGui::SliderInt("capacity", &capacity_, 1, 16) | ImGui::SliderInt("max_depth", &max_depth_, 0, 10);
    changed |= edit("box min", query_box_.min, 0.01f) | edit("box max", query_box_.max, 0.01f);
    query_box_.max = query_box_.max.cwiseMax(query_box_.min);
  }
  if (mode_ == Mode::frames)
    ImGui::TextDisabled("%zu spheres, %zu frames: the handles move the last", spheres_.size(), frames_.size());
  return changed;
}

std::vector<Handle> SpatialTreesScene::handles() {
  if (mode_ == Mode::kd) return {{&segment_.a, "a"}, {&segment_.b, "b"}};
  if (mode_ == Mode::bsp) return {{&point_, "p"}};
  if (mode_ == Mode::bvh) return {};
  std::vector<Handle> h;
  for (std::size_t i = 0; i < spheres_.size() && i < 64; ++i)
    h.push_back({&spheres_[i].center, "sphere " + std::to_string(i)});
  return h;
}

}  // namespace viewer::spatial_trees
