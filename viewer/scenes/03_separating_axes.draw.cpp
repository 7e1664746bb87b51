// Lab 03 scene, its drawing: the boxes or triangles, the intervals on the axis or on the
// line of the planes, the student's answers in their verdict's colour; and the panel.
#include "viewer/scenes/03_separating_axes.h"

#include <imgui.h>

#include <cmath>

namespace viewer::separating_axes {

// ---- draw ----------------------------------------------------------------------------

// A box's edges, and its faces when alpha > 0.
void draw_shaded_box(Renderer& r, const Box& b, Color c, float alpha, float width = 2) {
  draw_edges(r, corners_of(b), c, width);
  if (alpha > 0) draw_faces(r, corners_of(b), c.with_alpha(alpha));
}

// Step 1: the line through the origin along L, below the boxes, with each box's interval
// drawn on it (in world units: the projections divided by |L|).
void SeparatingAxesScene::draw_projection(Frame& f) const {
  Renderer& r = f.render;
  const double n = axis_.norm();
  if (n == 0) return;
  const Vec3 u = axis_ / n;
  // Beside the boxes as seen: across L in the picture (perpendicular to L and to the view).
  Vec3 side = r.view().forward.cast<double>().cross(u);
  if (side.norm() < 0.2) side = std::abs(u.z()) < 0.9 ? u.cross(Vec3::UnitZ()) : u.cross(Vec3::UnitX());
  side.normalize();
  const Vec3 base = side * (0.8 * radius) + center - u * u.dot(center);
  r.line(base - 1.6 * radius * u, base + 1.6 * radius * u, palette::muted, 1.5f);
  r.label(base + 1.6 * radius * u, "L", palette::muted);
  const Color c = colour(verdict_[1]);
  const auto interval = [&](const Attempt<Projection>& p, const Box& b, double lift, const char* name) {
    const Vec3 up = -side * lift;  // between the line and the boxes
    if (p) {
      const double lo = (p->center - p->radius) / n, hi = (p->center + p->radius) / n;
      r.line(base + up + lo * u, base + up + hi * u, c, 5);
      r.label(base + up + hi * u, std::string(name) + " [" + num(lo) + ", " + num(hi) + "]", c);
      // The two corners that project to the ends, and their projectors.
      for (const double end : {-1.0, 1.0}) {
        Vec3 corner = b.center;
        for (int k = 0; k < 3; ++k)
          corner += end * (b.axes.col(k).dot(u) >= 0 ? 1 : -1) * b.half_extents[k] * b.axes.col(k);
        r.dashed(corner, base + up + corner.dot(u) * u, palette::muted, 1.0f, 5.0f);
      }
    }
    if (f.show_exact) {
      const oracle::BoxProjection e = oracle::box_projection(b, axis_);
      r.ring(base + up + (e.center - e.radius) / n * u, palette::exact, 6);
      r.ring(base + up + (e.center + e.radius) / n * u, palette::exact, 6);
    }
  };
  interval(proj_a_, a_, 0.08 * radius, "A");
  interval(proj_b_, b_, 0.16 * radius, "B");
  if (proj_a_ && proj_b_) {
    // The gap between the intervals (or their overlap), on the line itself.
    const bool b_after = proj_b_->center >= proj_a_->center;
    const Projection& first = b_after ? *proj_a_ : *proj_b_;
    const Projection& second = b_after ? *proj_b_ : *proj_a_;
    const double from = (first.center + first.radius) / n, to = (second.center - second.radius) / n;
    r.line(base + from * u, base + to * u, c, 7);
    r.point(base + from * u, c, 4), r.point(base + to * u, c, 4);
    const std::string verdict = separated_ ? (*separated_ ? ": separated along L" : ": not separated along L") : "";
    r.label(base + 0.5 * (from + to) * u, (from < to ? "gap " + num(to - from) : "overlap " + num(from - to)) + verdict,
            c, 8, 18);
  }
}

// Step 4, the lecture's method: the line of the two planes, and on it each triangle's
// interval from the student's triangles_by_intervals, drawn a little inside its own
// triangle (t0's in t0's plane, t1's in t1's) so that both show where they overlap.
void SeparatingAxesScene::draw_line_intervals(Frame& f) const {
  if (!line_ || !line_->crossing || line_->axis < 0 || line_->axis > 2) return;
  Renderer& r = f.render;
  const Vec3 n0 = t0_.normal(), n1 = t1_.normal(), D = n0.cross(n1);
  const int k = line_->axis;
  if (D[k] == 0) return;
  // A point of both planes: n0 . x = h0, n1 . x = h1.
  const double h0 = n0.dot(t0_.v0), h1 = n1.dot(t1_.v0);
  const Vec3 origin = (h0 * n1.cross(D) + h1 * D.cross(n0)) / D.squaredNorm();
  const auto at = [&](double value) -> Vec3 { return origin + (value - origin[k]) / D[k] * D; };
  const double lo = std::min(line_->low0, line_->low1), hi = std::max(line_->high0, line_->high1);
  const double pad = 0.25 * (hi - lo) + 1e-12;
  const char* coordinate[] = {"x", "y", "z"};
  r.dashed(at(lo - pad), at(hi + pad), palette::muted, 1.5f);
  r.label(at(hi + pad), std::string("line of the planes, read on ") + coordinate[k], palette::muted);
  const Color c = colour(verdict_[4]);
  const auto interval = [&](double low, double high, const Vec3& normal, const char* name, bool label_low) {
    const Vec3 inside = D.cross(normal).normalized() * (0.06 * radius);
    const Vec3 toward = (t0_.v0 + t0_.v1 + t0_.v2 + t1_.v0 + t1_.v1 + t1_.v2) / 6 - at(low);
    const Vec3 shift = inside.dot(toward) < 0 ? Vec3(-inside) : inside;
    r.line(at(low) + shift, at(high) + shift, c, 5);
    r.point(at(low), c, 5), r.point(at(high), c, 5);
    const std::string text = std::string(name) + " [" + num(low) + ", " + num(high) + "]";
    r.label((label_low ? at(low) : at(high)) + 2 * shift, text, c, label_low ? -110 : 10, 0);
  };
  interval(line_->low0, line_->high0, n0, "t0", false);
  interval(line_->low1, line_->high1, n1, "t1", true);
  if (f.show_exact) {
    const oracle::TriangleIntervals e = oracle::triangle_intervals(t0_, t1_, k);
    for (const double v : {e.low0, e.high0, e.low1, e.high1})
      if (e.crossing) r.ring(at(v), palette::exact, 8);
  }
}

// Step 4: two triangles, their vertices named with the text's roles p, q, r.
void SeparatingAxesScene::draw_triangles(Frame& f) const {
  Renderer& r = f.render;
  const Color c = tri_ ? colour(verdict_[4]) : palette::surface;
  r.triangle(t0_.v0, t0_.v1, t0_.v2, palette::surface.with_alpha(0.6f));
  r.triangle(t1_.v0, t1_.v1, t1_.v2, palette::input.with_alpha(0.45f));
  // The header's names, t0.v0 ... t1.v2, and where each triangle straddles the other's
  // plane, the vertex roles of the text: p alone on its side, then q and r.
  // (The header's rule: p alone on its side, q and r on the other side or in the plane;
  // or p in the plane and q, r strictly on one side.)
  const auto sides = [](const Triangle& t, const Triangle& other, int side[3]) {
    for (int i = 0; i < 3; ++i) side[i] = oracle::orientation(other.v0, other.v1, other.v2, t[i]);
    const bool one_side = (side[0] > 0 && side[1] > 0 && side[2] > 0) || (side[0] < 0 && side[1] < 0 && side[2] < 0);
    return !one_side && (side[0] != 0 || side[1] != 0 || side[2] != 0);
  };
  const auto roles = [](const int side[3], std::string names[3]) {
    for (int k = 0; k < 3; ++k)
      for (const int flip : {1, -1}) {
        const int p = flip * side[k], q = flip * side[(k + 1) % 3], r = flip * side[(k + 2) % 3];
        if (p >= 0 && q <= 0 && r <= 0 && (p > 0 || (q < 0 && r < 0))) {
          names[k] += " = p", names[(k + 1) % 3] += " = q", names[(k + 2) % 3] += " = r";
          return;
        }
      }
  };
  std::string n0[3], n1[3];
  for (int i = 0; i < 3; ++i) n0[i] = "t0.v" + std::to_string(i), n1[i] = "t1.v" + std::to_string(i);
  int s0[3], s1[3];
  if (t0_.normal() != Vec3::Zero() && t1_.normal() != Vec3::Zero() && sides(t0_, t1_, s0) && sides(t1_, t0_, s1))
    roles(s0, n0), roles(s1, n1);
  for (int i = 0; i < 3; ++i) {
    r.line(t0_[i], t0_[(i + 1) % 3], palette::surface, 2);
    r.line(t1_[i], t1_[(i + 1) % 3], c, 2.5f);
    r.label(t0_[i], n0[i], palette::surface);
    r.label(t1_[i], n1[i], palette::input);
  }
  draw_line_intervals(f);
  if (tri_) r.label((t1_.v0 + t1_.v1 + t1_.v2) / 3, *tri_ ? "intersect" : "apart", c, 12, 34);
  if (f.show_exact && oracle::triangles_intersect(t0_, t1_))
    r.ring((t0_.v0 + t0_.v1 + t0_.v2) / 3, palette::exact, 9);  // violet: they do intersect
}

// Step 5: the moving boxes, at the shown time and at the answer's first contact.
void SeparatingAxesScene::draw_moving(Frame& f) const {
  Renderer& r = f.render;
  // The start (faint), the end (faint, dashed path), the boxes at the shown time, and
  // B at the student's first contact time.
  draw_shaded_box(r, a_, palette::muted, 0, 1);
  draw_shaded_box(r, b_, palette::muted, 0, 1);
  r.dashed(b_.center, b_.center + duration_ * vb_, palette::muted);
  if (va_ != Vec3::Zero()) r.dashed(a_.center, a_.center + duration_ * va_, palette::muted);
  const auto moved = [](Box b, const Vec3& v, double t) {
    b.center += t * v;
    return b;
  };
  draw_shaded_box(r, moved(a_, va_, shown_time_), palette::surface, 0.35f);
  draw_shaded_box(r, moved(b_, vb_, shown_time_), palette::input, 0.25f);
  r.label(b_.center + shown_time_ * vb_, "t = " + num(shown_time_), palette::input);
  if (interval_ && interval_->contact && f.shows(5)) {
    const Color c = colour(verdict_[5]);
    draw_shaded_box(r, moved(b_, vb_ - va_, interval_->first), c, 0, 2.5f);
    r.label(b_.center + interval_->first * (vb_ - va_), "first " + num(interval_->first) + " (seen from A)", c, 10, 14);
  }
  if (interval_ && !interval_->contact && f.shows(5))
    r.label(b_.center + 0.5 * duration_ * vb_, "no contact in [0, " + num(duration_) + "]", colour(verdict_[5]), 12,
            14);
  if (f.show_exact && exact_times_.contact) r.ring(b_.center + exact_times_.first * (vb_ - va_), palette::exact, 9);
}

void SeparatingAxesScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::triangles) return draw_triangles(f);
  if (mode_ == Mode::moving) return draw_moving(f);
  draw_shaded_box(r, a_, palette::surface, 0.35f);
  draw_shaded_box(r, b_, palette::input, 0.2f);
  r.label(a_.center, "A", palette::surface), r.label(b_.center, "B", palette::input);
  if (f.shows(1) || f.shows(2) || f.shows(3)) draw_projection(f);  // steps 2 and 3 work on these intervals too
  if (find_ && f.shows(3)) {
    const Color c = colour(verdict_[3]);
    const double len = std::max(std::abs(find_->depth), 0.3 * radius);
    r.arrow(a_.center, a_.center + len * find_->axis, c, 3);
    r.label(a_.center + len * find_->axis, "axis " + axis_name(find_->axis_index) + ", depth " + num(find_->depth), c,
            10, -10);
  }
  if (f.show_exact && exact_index_ >= 0 && (f.shows(3) || f.shows(2)))
    r.arrow(a_.center, a_.center + 0.8 * std::max(std::abs(exact_depth_), 0.3 * radius) * exact_axis_, palette::exact,
            1.5f);
  if (test_ && f.shows(2))
    r.label(b_.center, *test_ ? "test: intersecting" : "test: separated", colour(verdict_[2]), 12, 14);
}

bool SeparatingAxesScene::inputs() {
  bool changed = false;
  if (mode_ == Mode::triangles) {
    for (int i = 0; i < 3; ++i) changed |= edit(("t0.v" + std::to_string(i)).c_str(), t0_[i]);
    for (int i = 0; i < 3; ++i) changed |= edit(("t1.v" + std::to_string(i)).c_str(), t1_[i]);
    return changed;
  }
  changed |= edit("A centre", a_.center) | edit("A half extents", a_.half_extents);
  if (edit("A turn (z, y, x degrees)", angles_a_, 1.0f)) a_.axes = axes_of(angles_a_), changed = true;
  changed |= edit("B centre", b_.center) | edit("B half extents", b_.half_extents);
  if (edit("B turn (z, y, x degrees)", angles_b_, 1.0f)) b_.axes = axes_of(angles_b_), changed = true;
  a_.half_extents = a_.half_extents.cwiseMax(0.0), b_.half_extents = b_.half_extents.cwiseMax(0.0);
  if (mode_ == Mode::boxes) changed |= edit("L (step 1)", axis_);
  if (mode_ == Mode::moving) {
    changed |= edit("A velocity", va_) | edit("B velocity", vb_) | edit("duration", duration_, 0.05f, 0, 100);
    edit("shown time", shown_time_, 0.01f, 0, duration_);
  }
  return changed;
}

std::vector<Handle> SeparatingAxesScene::handles() {
  if (mode_ == Mode::triangles)
    return {{&t0_.v0, "t0.v0"}, {&t0_.v1, "t0.v1"}, {&t0_.v2, "t0.v2"},
            {&t1_.v0, "t1.v0"}, {&t1_.v1, "t1.v1"}, {&t1_.v2, "t1.v2"}};
  return {{&a_.center, "A"}, {&b_.center, "B"}};
}

}  // namespace viewer::separating_axes
