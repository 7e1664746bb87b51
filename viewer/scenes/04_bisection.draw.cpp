// Lab 04 scene, its drawing: the bodies along their motion, at the student's times in
// their verdict's colour and at the exact first contact in violet, the time axis under
// them; and the panel.
#include "viewer/scenes/04_bisection.h"

#include <imgui.h>

#include <cmath>

namespace viewer::bisection {

// ---- draw ----------------------------------------------------------------------------

void BisectionScene::layout() {
  const SearchTimes& T = case_.times;
  Eigen::AlignedBox3d& box = bodies_;
  box.setEmpty();
  for (int k = 0; k <= 32; ++k) {
    const double t = T.t0 + (T.t1 - T.t0) * k / 32;
    for (const MovingBody* b : {&case_.a, &case_.b}) {
      const RigidTransform p = pose_at(b->motion, t);
      const double reach = b->is_box ? b->box.half_extents.norm() : b->sphere.radius;
      const Vec3 c = p * (b->is_box ? b->box.center : b->sphere.center);
      box.extend(c - Vec3::Constant(reach)), box.extend(c + Vec3::Constant(reach));
    }
  }
  const double size = std::max(box.diagonal().norm(), 1e-9);
  width_ = std::max(box.sizes().x(), 0.6 * size);
  left_ = box.center().x() - 0.5 * width_;
  y0_ = box.min().y() - 0.12 * size;
  row_ = 0.04 * size;
  z_ = box.center().z();
}

// A sphere as three great circles (and a translucent ball), a box as its 12 edges (and
// its faces).
void BisectionScene::draw_body(Renderer& r, const MovingBody& body, const RigidTransform& pose, Color c,
                               bool filled) const {
  const float width = filled ? 2.0f : 1.0f;
  if (!body.is_box) {
    const Vec3 o = pose * body.sphere.center;
    const double rad = body.sphere.radius;
    if (rad <= 0) {
      r.point(o, c, 4);
      return;
    }
    draw_sphere(r, o, rad, c, width, 48, pose.linear());
    if (filled) {
      const int m = 12;
      const auto at = [&](int i, int j) {
        const double th = M_PI * i / m, ph = 2 * M_PI * j / (2 * m);
        return Vec3(o + rad * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
      };
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < 2 * m; ++j) {
          r.triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1), c.with_alpha(0.25f));
          r.triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1), c.with_alpha(0.25f));
        }
    }
    return;
  }
  const Corners p = corners_of(Box{pose * body.box.center, pose.linear() * body.box.axes, body.box.half_extents});
  draw_edges(r, p, c, width);
  if (filled) draw_faces(r, p, c.with_alpha(0.30f));
}

void BisectionScene::draw_pair(Renderer& r, double t, Color c, bool filled) const {
  draw_body(r, case_.a, pose_a(t), c, filled);
  const bool b_moves = case_.b.motion.velocity != Vec3::Zero() || case_.b.motion.acceleration != Vec3::Zero() ||
                       case_.b.motion.spin != 0;
  if (b_moves) draw_body(r, case_.b, pose_b(t), c, false);
}

// The time axis under the bodies, along world x: t0 at the left of the picture, t1 at
// the right. Row 0 holds the tested times; the rows below it the bracket after each test.
void BisectionScene::draw_timeline(Frame& f) const {
  Renderer& r = f.render;
  const SearchTimes& T = case_.times;
  const auto at = [&](double t, int k) {
    const double u = T.t1 > T.t0 ? (t - T.t0) / (T.t1 - T.t0) : 0.5;
    return Vec3(left_ + u * width_, y0_ - row_ * k, z_);
  };
  r.line(at(T.t0, 0), at(T.t1, 0), palette::muted, 2);
  r.label(at(T.t0, 0), "t0 = " + num(T.t0), palette::muted, -70, -8);
  r.label(at(T.t1, 0), "t1 = " + num(T.t1), palette::muted, 10, -8);
  const double tick = 0.4 * row_;
  // The tests, numbered in the order the search asked, coloured by the exact overlap. In
  // bisection the ends carry the axis's t0 and t1, and the midpoints are numbered as the
  // lecture numbers its iterations (1 to 5 in its example). Labels that would overlap are
  // stacked upward, each on a thin leader down to its tick.
  const std::size_t shown = std::min<std::size_t>(tested_.size(), 40);
  const double pixel = r.pixels(at(T.t0, 0), 1);              // world length of a pixel on the axis
  std::vector<std::vector<std::pair<double, double>>> taken;  // per stacking level: label spans, in pixels
  int number = 0;
  for (std::size_t i = 0; i < shown; ++i) {
    const Color c = tested_overlap_[i] ? palette::surface : palette::input;
    const Vec3 top = at(tested_[i], 0) + Vec3(0, tick, 0);
    r.line(at(tested_[i], 0) - Vec3(0, tick, 0), top, c, 2.5f);
    const bool end = mode_ == Mode::bisect && (tested_[i] == T.t0 || tested_[i] == T.t1);
    if (end) continue;
    ++number;
    if (shown > 24) continue;
    const std::string text = std::to_string(number);
    const double w = 7.0 * double(text.size()) + 2, x = (top.x() - left_) / pixel - 0.5 * w;
    const auto clashes = [&](const std::pair<double, double>& s) { return x < s.second + 3 && s.first < x + w + 3; };
    std::size_t level = 0;
    while (level < taken.size() && std::any_of(taken[level].begin(), taken[level].end(), clashes)) ++level;
    if (level == taken.size()) taken.emplace_back();
    taken[level].push_back({x, x + w});
    const float lift = 14.0f * float(level);
    if (level > 0) r.line(top, top + Vec3(0, pixel * (lift + 2), 0), c.with_alpha(0.5f), 1);
    r.label(top, text, c, float(-0.5 * w), -18 - lift);
  }
  // The bracket the tests imply: the earliest overlapping time tested, and the latest
  // clear time tested before it.
  std::vector<std::pair<double, double>> brackets;
  for (std::size_t i = 0; i < tested_.size(); ++i) {
    double hi = INFINITY, lo = -INFINITY;
    for (std::size_t j = 0; j <= i; ++j)
      if (tested_overlap_[j]) hi = std::min(hi, tested_[j]);
    if (!std::isfinite(hi) || hi == tested_[0]) continue;
    for (std::size_t j = 0; j <= i; ++j)
      if (!tested_overlap_[j] && tested_[j] < hi) lo = std::max(lo, tested_[j]);
    if (std::isfinite(lo) && (brackets.empty() || brackets.back() != std::make_pair(lo, hi)))
      brackets.push_back({lo, hi});
  }
  const std::size_t first = brackets.size() > kRows ? brackets.size() - kRows : 0;
  for (std::size_t i = first; i < brackets.size(); ++i) {
    const int k = int(i - first) + 1;
    r.line(at(brackets[i].first, k), at(brackets[i].second, k), palette::muted, 3);
    r.label(at(brackets[i].second, k), "[" + num(brackets[i].first) + ", " + num(brackets[i].second) + "]",
            palette::muted, 8, -7);
  }
  // The student's final bracket, and the exact first contact.
  const int last = int(brackets.size() - first) + 1;
  if (search_ && search_->hit && f.shows(search_step_)) {
    const Color c = colour(search_verdict_);
    r.line(at(search_->t, last), at(search_->t_contact, last), c, 5);
    r.label(at(search_->t, last), "yours: t = " + num(search_->t), c, -40, 10);
  } else if (search_ && f.shows(search_step_)) {
    r.label(at(T.t1, last), "yours: no hit", colour(search_verdict_), -40, 10);
  }
  if (f.show_exact && exact_hit_) {
    r.ring(at(exact_hi_, 0), palette::exact, 9, 2.5f);
    r.label(at(exact_hi_, last + 1), "exact first contact " + num(exact_hi_), palette::exact, -40, 10);
  }
}

void BisectionScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::rule) {
    r.label(Vec3::Zero(), "the sub-step rule has no picture: see the panel", palette::muted);
    return;
  }
  if (mode_ == Mode::point) {
    const MovingBody box{true, Sphere{}, point_box_.box, {}};
    draw_body(r, box, RigidTransform::Identity(), palette::surface, true);
    r.point(point_box_.point, palette::input, 6);
    r.label(point_box_.point, "p", palette::input);
    if (closest_) {
      const Color c = colour(closest_verdict_);
      r.dashed(point_box_.point, *closest_, c, 2);
      r.point(*closest_, c, 5);
      r.label(*closest_, "q", c, 10, 10);
    }
    return;
  }
  const SearchTimes& T = case_.times;
  // The paths of the body's centres, and both bodies at t0 (faint) and t1.
  for (const MovingBody* b : {&case_.a, &case_.b}) {
    const Vec3 local = b->is_box ? b->box.center : b->sphere.center;
    for (int k = 0; k < 48; ++k) {
      const double s0 = T.t0 + (T.t1 - T.t0) * k / 48, s1 = T.t0 + (T.t1 - T.t0) * (k + 1) / 48;
      r.line(pose_at(b->motion, s0) * local, pose_at(b->motion, s1) * local, palette::muted.with_alpha(0.7f), 1);
    }
  }
  draw_body(r, case_.b, pose_b(T.t0), palette::surface, true);
  draw_body(r, case_.a, pose_a(T.t0), palette::input, false);
  r.label(pose_a(T.t0) * case_.a.sphere.center, "t0", palette::input, 8, -8);
  draw_body(r, case_.a, pose_a(T.t1), palette::muted, false);
  r.label(pose_a(T.t1) * case_.a.sphere.center, "t1", palette::muted, 8, -8);
  // Every tested time, faint: where the search looked.
  if (tested_.size() <= 64)
    for (std::size_t i = 0; i < tested_.size(); ++i)
      draw_body(r, case_.a, pose_a(tested_[i]),
                (tested_overlap_[i] ? palette::surface : palette::input).with_alpha(0.35f), false);
  if (search_ && search_->hit && f.shows(search_step_)) {
    const Color c = colour(search_verdict_);
    draw_pair(r, search_->t, c, true);
    if (search_->t_contact != search_->t) draw_pair(r, search_->t_contact, c.with_alpha(0.6f), false);
    r.label(pose_a(search_->t) * case_.a.sphere.center, "t = " + num(search_->t), c, -30, 16);
  }
  if (f.show_exact && exact_hit_) {
    draw_pair(r, exact_hi_, palette::exact, false);
    r.ring(pose_a(exact_hi_) * case_.a.sphere.center, palette::exact, 9);
  }
  draw_timeline(f);
}

bool BisectionScene::inputs() {
  bool changed = false;
  if (mode_ == Mode::rule) {
    changed |= edit("max speed", rule_.max_speed, 0.05f, 0, 1e12) | edit("step", rule_.step, 0.01f, 0, 1e6) |
               edit("smallest size", rule_.smallest_size, 0.01f, 0, 1e6);
    return changed;
  }
  if (mode_ == Mode::point) {
    changed |= edit("p", point_box_.point) | edit("box centre", point_box_.box.center) |
               edit("half extents", point_box_.box.half_extents, 0.02f);
    point_box_.box.half_extents = point_box_.box.half_extents.cwiseAbs();
    return changed;
  }
  ImGui::TextDisabled("a: a sphere");
  changed |= edit("a radius", case_.a.sphere.radius, 0.01f, 0, 1e9);
  changed |= edit("a start", case_.a.motion.start) | edit("a velocity", case_.a.motion.velocity) |
             edit("a acceleration", case_.a.motion.acceleration) | edit("a spin", case_.a.motion.spin, 0.02f);
  bool box = case_.b.is_box;
  if (ImGui::Checkbox("b is a box", &box)) {
    case_.b.is_box = box, changed = true;
    if (box && case_.b.box.half_extents == Vec3::Zero())
      case_.b.box.half_extents = Vec3::Constant(case_.b.sphere.radius);
    if (!box && case_.b.sphere.radius == 0) case_.b.sphere.radius = case_.b.box.half_extents.maxCoeff();
  }
  if (case_.b.is_box) {
    changed |= edit("b half extents", case_.b.box.half_extents, 0.02f);
    case_.b.box.half_extents = case_.b.box.half_extents.cwiseAbs();
  } else {
    changed |= edit("b radius", case_.b.sphere.radius, 0.01f, 0, 1e9);
  }
  changed |= edit("b start", case_.b.motion.start) | edit("b velocity", case_.b.motion.velocity) |
             edit("b spin", case_.b.motion.spin, 0.02f) | edit("b spin axis", case_.b.motion.axis);
  if (case_.b.motion.axis == Vec3::Zero()) case_.b.motion.axis = Vec3::UnitZ();
  ImGui::TextDisabled("the search");
  changed |= edit("t0", case_.times.t0, 0.01f) | edit("t1", case_.times.t1, 0.01f) |
             edit("tolerance", case_.times.tolerance, 0.001f, 1e-12, 1e6);
  if (mode_ == Mode::sampled) changed |= ImGui::SliderInt("sub-steps n", &substeps_, 1, 64);
  if (mode_ == Mode::advance) changed |= edit("bound factor", speed_factor_, 0.01f, 1, 100);
  return changed;
}

std::vector<Handle> BisectionScene::handles() {
  if (mode_ == Mode::point) return {{&point_box_.point, "p"}, {&point_box_.box.center, "box centre"}};
  if (mode_ == Mode::rule) return {};
  return {{&case_.a.motion.start, "a at t = 0"}, {&case_.b.motion.start, "b at t = 0"}};
}

}  // namespace viewer::bisection
