// Lab 05 scene, its drawing: the cores and their radii as wire hulls, or the moving shapes
// with their paths, the student's answers in their verdict's colour; and the panel.
#include "viewer/scenes/05_sphere_sweeps.h"

#include <imgui.h>

#include <cmath>

namespace viewer::sphere_sweeps {

// ---- draw ----------------------------------------------------------------------------

Vec3 perpendicular(const Vec3& d) {
  const Vec3 x = std::abs(d.x()) < 0.9 * d.norm() ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 n = d.cross(x);
  return n == Vec3::Zero() ? Vec3::UnitZ() : Vec3(n.normalized());
}

// Half a circle: from e1 through e2 to -e1 (e2 points to the half drawn).
void arc(Renderer& r, const Vec3& c, const Vec3& e1, const Vec3& e2, double radius, Color col, float width = 1.2f) {
  constexpr int kSides = 24;
  for (int i = 0; i < kSides; ++i) {
    const double a = M_PI * i / kSides, b = M_PI * (i + 1) / kSides;
    r.line(c + radius * (std::cos(a) * e1 + std::sin(a) * e2), c + radius * (std::cos(b) * e1 + std::sin(b) * e2), col,
           width);
  }
}

// A capsule as a wire hull: the side's four lines, a ring at each end, and each end's
// hemispherical cap (two half circles across it, facing outward).
// `across`: a direction across the axis to draw the side's lines along (default: any).
void capsule_hull(Renderer& r, const Segment& axis, double radius, Color hull, float width = 1.2f,
                  const Vec3& across = Vec3::Zero());

void ball(Renderer& r, const Vec3& c, double radius, Color col, float width = 1.2f) {
  if (radius > 0) draw_sphere(r, c, radius, col, width);
}

void capsule_hull(Renderer& r, const Segment& axis, double radius, Color hull, float width, const Vec3& across) {
  if (radius <= 0) return;
  const Vec3 d = axis.b - axis.a;
  if (d == Vec3::Zero()) {
    ball(r, axis.a, radius, hull, width);
    return;
  }
  const Vec3 along = d.normalized();
  const Vec3 side = across - across.dot(along) * along;
  const Vec3 e1 =
      side.norm() > 1e-9 * across.norm() && across != Vec3::Zero() ? Vec3(side.normalized()) : perpendicular(d);
  const Vec3 e2 = along.cross(e1).normalized();
  for (const Vec3& end : {axis.a, axis.b}) draw_circle(r, end, e1, e2, radius, hull, width);
  for (const Vec3& off : {e1, Vec3(-e1), e2, Vec3(-e2)})
    r.line(axis.a + radius * off, axis.b + radius * off, hull, width);
  for (const Vec3& e : {e1, e2}) {
    arc(r, axis.a, e, -along, radius, hull, width);
    arc(r, axis.b, e, along, radius, hull, width);
  }
}

// The core in `core`, its radius as a wire hull in `hull`.
void draw_shape(Renderer& r, const Shape& s, const char* name, Color core, Color hull) {
  switch (s.kind) {
    case Core::point:
      r.point(s.p, core, 6);
      r.label(s.p, name, core);
      ball(r, s.p, s.radius, hull);
      break;
    case Core::segment: {
      r.line(s.s.a, s.s.b, core, 2.5f);
      r.point(s.s.a, core, 5), r.point(s.s.b, core, 5);
      r.label(s.s.a, std::string(name) + ".a", core), r.label(s.s.b, std::string(name) + ".b", core);
      capsule_hull(r, s.s, s.radius, hull);
      break;
    }
    case Core::rectangle: {
      const Vec3 c[4] = {corner(s.r, 0), corner(s.r, 1), corner(s.r, 3), corner(s.r, 2)};  // around the border
      r.triangle(c[0], c[1], c[2], palette::surface.with_alpha(0.6f));
      r.triangle(c[0], c[2], c[3], palette::surface.with_alpha(0.6f));
      for (int i = 0; i < 4; ++i) r.line(c[i], c[(i + 1) % 4], core, 2);
      r.label(s.r.center, name, core);
      if (s.radius <= 0) break;
      const Vec3 n = s.r.u.cross(s.r.v).normalized();
      for (double side : {-1.0, 1.0})
        for (int i = 0; i < 4; ++i)
          r.line(c[i] + side * s.radius * n, c[(i + 1) % 4] + side * s.radius * n, hull, 1.2f);
      for (int i = 0; i < 4; ++i) draw_circle(r, c[i], s.r.u, s.r.v, s.radius, hull, 1.2f);
      break;
    }
  }
}

// A square of the plane around `near`, `size` across, and its normal.
void draw_plane(Renderer& r, const Plane& given, const Vec3& near, double size) {
  const Plane p = drawable(given);
  const double nn = p.normal.squaredNorm();
  if (nn == 0) return;
  const Vec3 n = p.normal / std::sqrt(nn), foot = near - p.value(near) / nn * p.normal;
  const Vec3 e1 = perpendicular(n), e2 = n.cross(e1);
  const Square q = square_around(foot, e1, e2, size);
  fill(r, q, palette::surface.with_alpha(0.35f));
  outline(r, q, palette::surface, 1.5f);
  r.arrow(foot, foot + 0.3 * size * n, palette::muted, 2);
  r.label(foot + 0.3 * size * n, "n", palette::muted);
}

void SphereSweepsScene::draw_cores(Frame& f) const {
  Renderer& r = f.render;
  const bool hulls = f.shows(3);
  const Color hull = verdict_[3] == Verdict::none ? palette::muted : colour(verdict_[3]).with_alpha(0.8f);
  Shape a = a_, b = b_;
  if (!hulls) a.radius = b.radius = 0;
  draw_shape(r, a, "0", palette::input, hull);
  draw_shape(r, b, "1", palette::input, hull);
  const int distance = a_.kind == Core::rectangle || b_.kind == Core::rectangle ? 2 : 1;
  if (closest0_ && closest1_ && (f.shows(distance) || f.shows(3))) {
    const Color c = colour(verdict_[distance]);
    r.line(*closest0_, *closest1_, c, 3);
    r.point(*closest0_, c, 5), r.point(*closest1_, c, 5);
    r.label(0.5 * (*closest0_ + *closest1_), "d = " + num((*closest0_ - *closest1_).norm()), c, 10, 8);
  }
  // Two segments whose lines' closest pair lies outside: the classic mistake clamps both
  // parameters into [0, 1] at once. Its pair (dashed, red) is farther apart than the
  // closest pair, which re-projects the clamped end onto the other segment.
  if (a_.kind == Core::segment && b_.kind == Core::segment && f.shows(1)) {
    const Vec3 d0 = a_.s.b - a_.s.a, d1 = b_.s.b - b_.s.a, w = b_.s.a - a_.s.a, n = d0.cross(d1);
    const double nn = n.squaredNorm();
    if (nn > 1e-12 * d0.squaredNorm() * d1.squaredNorm()) {
      const double s = w.cross(d1).dot(n) / nn, t = w.cross(d0).dot(n) / nn;
      const Vec3 p = a_.s.a + std::clamp(s, 0.0, 1.0) * d0, q = b_.s.a + std::clamp(t, 0.0, 1.0) * d1;
      const double wrong = (p - q).norm(), right = oracle::squared_distance(a_.s, b_.s).distance();
      if ((s < 0 || s > 1 || t < 0 || t > 1) && wrong > right * (1 + 1e-9) + 1e-12) {
        r.dashed(p, q, palette::disagree, 2.5f);
        r.point(p, palette::disagree, 4), r.point(q, palette::disagree, 4);
        r.label(q,
                "wrong, clamped: s = " + num(std::clamp(s, 0.0, 1.0)) + ", t = " + num(std::clamp(t, 0.0, 1.0)) +
                    ", d = " + num(wrong),
                palette::disagree, 12, -14);
      }
    }
  }
  const Vec3 anchor = a_.kind == Core::point ? a_.p : a_.kind == Core::segment ? a_.s.a : a_.r.center;
  if (meet_ && hulls) r.label(anchor, *meet_ ? "they meet" : "apart", colour(verdict_[3]), 12, -28);
  // The exact answer is a number (the panel's exact column); the closest points are
  // ringed when the judge accepts them as a closest pair.
  if (f.show_exact && closest0_ && closest1_ && verdict_[distance] == Verdict::agree)
    r.ring(*closest0_, palette::exact, 9), r.ring(*closest1_, palette::exact, 9);
}

// Step 6: the capsule (its axis and hull), and the Minkowski sum the centre runs into: the
// same axis grown to R = r + rc, dashed ends of the slab where the side stops.
void SphereSweepsScene::draw_grown_capsule(Renderer& r) const {
  const Segment& axis = capsule_.axis;
  const double R = capsule_.radius + s0_.radius;
  r.line(axis.a, axis.b, palette::surface, 2.5f);
  r.point(axis.a, palette::surface, 5), r.point(axis.b, palette::surface, 5);
  r.label(axis.a, "a", palette::surface), r.label(axis.b, "b", palette::surface);
  // Across the axis toward the sphere's start, so that a view along the motion's plane
  // shows the side's lines, the slab's ends and the caps in profile.
  const Vec3 d = axis.b - axis.a;
  Vec3 e1 = d == Vec3::Zero() ? Vec3::UnitY() : perpendicular(d);
  if (d != Vec3::Zero()) {
    const Vec3 off = (s0_.center - axis.a) - (s0_.center - axis.a).dot(d) / d.squaredNorm() * d;
    if (off.norm() > 1e-9 * d.norm()) e1 = off.normalized();
  }
  capsule_hull(r, axis, capsule_.radius, palette::surface, 1.8f, e1);
  capsule_hull(r, axis, R, palette::muted.with_alpha(0.8f), 1.2f, e1);
  if (d != Vec3::Zero()) {
    r.label(axis.a - R * e1, "grown capsule: R = r + rc = " + num(R), palette::muted, -40, 22);
    // The slab's end planes, across the grown capsule: the side counts only between them.
    for (const Vec3& end : {axis.a, axis.b}) r.dashed(end - 1.5 * R * e1, end + 1.5 * R * e1, palette::muted, 1.5f);
    // The side's root (the infinite cylinder's), when it falls outside the slab.
    const Vec3 m = s0_.center - axis.a, md = m.cross(d), vd = v0_.cross(d);
    const double qa = vd.squaredNorm(), qb = md.dot(vd), qc = md.squaredNorm() - R * R * d.squaredNorm();
    if (qa > 0 && qb < 0 && qc > 0 && qb * qb - qa * qc >= 0) {
      const double t = qc / (-qb + std::sqrt(qb * qb - qa * qc));
      const Vec3 x = s0_.center + t * v0_;
      const double along = (x - axis.a).dot(d) / d.squaredNorm();
      if (t <= duration_ && (along < 0 || along > 1)) {
        r.point(x, palette::disagree, 5);
        r.label(x, "cylinder's root t = " + num(t) + ": outside the slab", palette::disagree, 30, -6);
      }
    }
  }
}

// The student's contact: the shapes then, and the point; or what the answer said instead.
void SphereSweepsScene::draw_answer(Renderer& r, const Vec3& start0, const Color& c) const {
  if (sweep_ && sweep_->status == SweepStatus::contact && std::isfinite(sweep_->time)) {
    const double t = sweep_->time;
    if (mode_ == Mode::box_plane) {
      Box then = box_;
      then.center = box_.center + t * v0_;
      draw_box(r, then, c, 2.5f);
    } else {
      ball(r, s0_.center + t * v0_, s0_.radius, c, 2);
      if (mode_ == Mode::sphere_capsule) r.point(s0_.center + t * v0_, c, 4);
      if (mode_ == Mode::sphere_sphere) ball(r, s1_.center + t * v1_, s1_.radius, c, 2);
    }
    r.point(sweep_->point, c, 6);
    r.label(sweep_->point, "contact  t = " + num(t), c, 12, 10);
  } else if (sweep_) {
    r.label(start0, sweep_->status == SweepStatus::overlapping ? "overlapping at t = 0" : "no contact", c, 12, -24);
  }
}

void SphereSweepsScene::draw_sweep(Frame& f) const {
  Renderer& r = f.render;
  const int step = step_of(mode_);
  const Color c = colour(verdict_[step]);
  const Vec3 start0 = mode_ == Mode::box_plane ? box_.center : s0_.center;
  if (mode_ == Mode::sphere_plane || mode_ == Mode::box_plane)
    draw_plane(r, plane_, start0 + 0.5 * duration_ * v0_, radius);
  if (mode_ == Mode::sphere_capsule) draw_grown_capsule(r);
  // The shapes at t = 0 (input colours) and at T (faint), and their paths.
  r.dashed(start0, end0_, palette::muted, 1.5f);
  r.label(end0_, "t = T", palette::muted);
  if (mode_ == Mode::box_plane) {
    draw_box(r, box_, palette::input, 2);
    Box at_end = box_;
    at_end.center = end0_;
    draw_box(r, at_end, palette::muted.with_alpha(0.5f), 1);
  } else {
    ball(r, s0_.center, s0_.radius, palette::input, 1.8f);
    ball(r, end0_, s0_.radius, palette::muted.with_alpha(0.5f), 1);
    r.point(s0_.center, palette::input, 5);
  }
  if (mode_ == Mode::sphere_sphere) {
    ball(r, s1_.center, s1_.radius, palette::surface, 1.8f);
    ball(r, end1_, s1_.radius, palette::muted.with_alpha(0.5f), 1);
    r.point(s1_.center, palette::surface, 5);
    r.dashed(s1_.center, end1_, palette::muted, 1.5f);
  }
  draw_answer(r, start0, c);
  if (f.show_exact && exact_time_ >= 0) {  // the exact first contact: the centres then
    r.ring(start0 + exact_time_ * v0_, palette::exact, 9);
    if (mode_ == Mode::sphere_sphere) r.ring(s1_.center + exact_time_ * v1_, palette::exact, 9);
  }
}

void SphereSweepsScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::cores)
    draw_cores(f);
  else
    draw_sweep(f);
}

bool SphereSweepsScene::inputs() {
  bool changed = false;
  const auto shape = [&](const char* name, Shape& s) {
    ImGui::PushID(name);
    ImGui::TextDisabled("%s", name);
    if (s.kind == Core::point) changed |= edit("centre", s.p);
    if (s.kind == Core::segment) changed |= edit("a", s.s.a) | edit("b", s.s.b);
    if (s.kind == Core::rectangle) {
      changed |= edit("centre", s.r.center) | edit("half u", s.r.half_u, 0.05f, 0, 1e9) |
                 edit("half v", s.r.half_v, 0.05f, 0, 1e9);
      Vec3 u = s.r.u;
      if (edit("u", u, 0.01f) && u != Vec3::Zero()) {  // keep u, v orthonormal
        s.r.u = u.normalized();
        const Vec3 v = s.r.v - s.r.v.dot(s.r.u) * s.r.u;
        s.r.v = v == Vec3::Zero() ? perpendicular(s.r.u) : Vec3(v.normalized());
        changed = true;
      }
    }
    changed |= edit("radius", s.radius, 0.02f, 0, 1e9);
    ImGui::PopID();
  };
  if (mode_ == Mode::cores) {
    shape("core 0", a_), shape("core 1", b_);
    return changed;
  }
  if (mode_ == Mode::box_plane) {
    changed |= edit("box centre", box_.center) | edit("half extents", box_.half_extents);
    if (edit("turn about z (deg)", turn_, 0.5f) | edit("tilt about x (deg)", tilt_, 0.5f)) {
      box_.axes =
          (Eigen::AngleAxisd(turn_ * M_PI / 180, Vec3::UnitZ()) * Eigen::AngleAxisd(tilt_ * M_PI / 180, Vec3::UnitX()))
              .toRotationMatrix();
      changed = true;
    }
  } else {
    changed |= edit("centre 0", s0_.center) | edit("radius 0", s0_.radius, 0.02f, 0, 1e9);
  }
  changed |= edit(mode_ == Mode::sphere_sphere ? "velocity 0" : "velocity", v0_);
  if (mode_ == Mode::sphere_capsule)
    changed |= edit("capsule a", capsule_.axis.a) | edit("capsule b", capsule_.axis.b) |
               edit("capsule radius", capsule_.radius, 0.02f, 0, 1e9);
  else if (mode_ == Mode::sphere_sphere)
    changed |= edit("centre 1", s1_.center) | edit("radius 1", s1_.radius, 0.02f, 0, 1e9) | edit("velocity 1", v1_);
  else
    changed |= edit("plane normal", plane_.normal, 0.01f) | edit("plane offset", plane_.offset);
  changed |= edit("duration T", duration_, 0.02f, 0, 1e9);
  if (changed) {  // the handles follow the edited values
    const Vec3 c = mode_ == Mode::box_plane ? box_.center : s0_.center;
    end0_ = last_end0_ = c + duration_ * v0_;
    end1_ = last_end1_ = s1_.center + duration_ * v1_;
    last_plane_point_ = plane_point_;
  }
  return changed;
}

std::vector<Handle> SphereSweepsScene::handles() {
  std::vector<Handle> h;
  const auto shape = [&](Shape& s, const std::string& name) {
    if (s.kind == Core::point) h.push_back({&s.p, name});
    if (s.kind == Core::segment) h.insert(h.end(), {{&s.s.a, name + ".a"}, {&s.s.b, name + ".b"}});
    if (s.kind == Core::rectangle) h.push_back({&s.r.center, name + " centre"});
  };
  if (mode_ == Mode::cores) {
    shape(a_, "0"), shape(b_, "1");
    return h;
  }
  h.push_back({mode_ == Mode::box_plane ? &box_.center : &s0_.center, "centre"});
  h.push_back({&end0_, "centre at T"});
  if (mode_ == Mode::sphere_sphere)
    h.insert(h.end(), {{&s1_.center, "centre 1"}, {&end1_, "centre 1 at T"}});
  else if (mode_ == Mode::sphere_capsule)
    h.insert(h.end(), {{&capsule_.axis.a, "capsule a"}, {&capsule_.axis.b, "capsule b"}});
  else
    h.push_back({&plane_point_, "plane", &plane_});
  return h;
}

}  // namespace viewer::sphere_sweeps
