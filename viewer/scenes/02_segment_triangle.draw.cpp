// Lab 02 scene, its drawing: the triangle and its plane or the mesh, the student's
// answers in their verdict's colour beside the exact ones (the toggle); and the panel.
#include "viewer/scenes/02_segment_triangle.h"

#include <imgui.h>

#include <cmath>

namespace viewer::segment_triangle {

// ---- draw ----------------------------------------------------------------------------

void SegmentTriangleScene::draw_triangle(Renderer& r, bool plane) const {
  const Triangle& t = triangle_;
  const Vec3 c = (t.v0 + t.v1 + t.v2) / 3, n = oracle::unit_normal(t);
  const double size = std::max({(t.v1 - t.v0).norm(), (t.v2 - t.v1).norm(), (t.v0 - t.v2).norm()});
  if (plane && n != Vec3::Zero()) {  // a faint square of the triangle's plane around it
    const Vec3 u = (t.v1 - t.v0).normalized();
    fill(r, square_around(c, u, n.cross(u), size), palette::surface.with_alpha(0.10f));
  }
  r.triangle(t.v0, t.v1, t.v2, palette::surface.with_alpha(0.72f));
  for (int i = 0; i < 3; ++i) {
    r.line(t[i], t[(i + 1) % 3], palette::surface, 2);
    r.label(t[i], "v" + std::to_string(i), palette::muted);
  }
  if (n != Vec3::Zero()) {
    r.arrow(c, c + 0.3 * size * n, palette::muted, 2);
    r.label(c + 0.3 * size * n, "n", palette::muted);
  }
}

void SegmentTriangleScene::draw_steps_1_to_4(Frame& f) const {
  Renderer& r = f.render;
  const Triangle& t = triangle_;
  const Vec3 n = oracle::unit_normal(t);
  const Segment& s = segment_;
  if (mode_ == Mode::triangle && crossing_ && f.shows(1)) {  // step 1: the distances as drops to the plane
    const Color c = colour(verdict_[1]);
    r.dashed(s.a, s.a - crossing_->d_a * n, c, 2);
    r.dashed(s.b, s.b - crossing_->d_b * n, c, 2);
    r.label(s.a - 0.5 * crossing_->d_a * n, "d_a = " + num(crossing_->d_a), c);
    r.label(s.b - 0.5 * crossing_->d_b * n, "d_b = " + num(crossing_->d_b), c);
    if (crossing_->crosses) {
      r.point(crossing_->point, c, 5);
      r.label(crossing_->point, "x   t = " + num(crossing_->t), c, 12, 10);
    }
  }
  if (f.show_exact && mode_ == Mode::triangle && exact_crossing_.crosses && (f.shows(1) || f.shows(4)))
    r.ring(exact_crossing_.point, palette::exact, 9);
  if (probe_ && barycentric_ && barycentric_->dropped_axis >= 0 && f.shows(3)) {  // step 3: x = v0 + alpha e1 + beta e2
    const Color c = colour(verdict_[3]);
    const Vec3 p = t.v0 + barycentric_->alpha * (t.v1 - t.v0);
    r.arrow(t.v0, p, c, 2.5f);
    r.arrow(p, p + barycentric_->beta * (t.v2 - t.v0), c, 2.5f);
    r.label(0.5 * (t.v0 + p), "alpha = " + num(barycentric_->alpha), c, 4, 10);
    r.label(p + 0.5 * barycentric_->beta * (t.v2 - t.v0), "beta = " + num(barycentric_->beta), c, 8, 0);
  }
  if (probe_ && inside_edges_ && f.shows(2))
    r.label(*probe_, *inside_edges_ ? "inside" : "outside", colour(verdict_[2]), 12, mode_ == Mode::point ? 12 : -28);
  if (mode_ == Mode::point && f.show_exact) r.ring(x_, palette::exact, 9);
  if (mode_ != Mode::triangle || !f.shows(4)) return;
  const double size = std::max((t.v1 - t.v0).norm(), (t.v2 - t.v0).norm());
  if (find_ && find_->hit) {  // step 4: the hit and its normal
    const Color c = colour(verdict_[4]);
    r.ring(find_->point, c, 15, 2.5f);
    r.arrow(find_->point, find_->point + 0.3 * size * find_->normal, c, 2.5f);
  } else if (find_) {
    r.label(0.5 * (s.a + s.b), "find: miss", colour(verdict_[4]), 12, 0);
  }
  if (f.show_exact && exact_hit_.hit)
    r.arrow(exact_hit_.point, exact_hit_.point + 0.3 * size * n, palette::exact, 1.5f);
}

void SegmentTriangleScene::draw_hits(Frame& f) const {
  Renderer& r = f.render;
  const Color c = colour(verdict_[mode_ == Mode::mesh ? 5 : 6]);
  const RigidTransform& pose = mode_ == Mode::moving ? m1_ : RigidTransform::Identity();
  if (all_ && mode_ == Mode::mesh)
    for (std::size_t k = 0; k < all_->size(); ++k) {
      r.point((*all_)[k].point, c, 5);
      r.label((*all_)[k].point, std::to_string(k + 1), c, 10, 8);
    }
  if (first_ && first_->hit) {
    if (first_->triangle >= 0 && std::size_t(first_->triangle) < mesh_.size()) {
      const Triangle t = mesh_.triangle(std::size_t(first_->triangle));
      r.triangle(pose * t.v0, pose * t.v1, pose * t.v2, c.with_alpha(0.45f));
    }
    r.point(first_->point, c, 5);
    r.ring(first_->point, c, 15, 2.5f);
    r.label(first_->point, "first hit   t = " + num(first_->t), c, 18, -16);
  }
  if (!f.show_exact) return;
  for (const oracle::SegmentHit& h : exact_hits_) r.ring(h.point, palette::exact, 9);
  if (!exact_hits_.empty()) {
    const Triangle t = mesh_.triangle(std::size_t(exact_hits_[0].triangle));
    for (int i = 0; i < 3; ++i) r.line(pose * t[i], pose * t[(i + 1) % 3], palette::exact, 2);
  }
}

// Step 7: A and B at t = 0 (outlines) and at the contact time (filled); the vertex paths
// of the contact's family, or the parallelogram its edge of A sweeps, seen from B.
void SegmentTriangleScene::draw_contact(Frame& f) const {
  Renderer& r = f.render;
  const MovingMeshes& in = meshes_;
  const Vec3 d = in.velocity_a - in.velocity_b;
  const bool got = contact_ && contact_->hit;
  const double t = got ? contact_->t : exact_contact_.hit ? exact_contact_.t : 1.0;
  const Color c = colour(verdict_[7]);
  RigidTransform at0 = RigidTransform::Identity(), a_t = at0, b_t = at0;
  a_t.translation() = t * in.velocity_a, b_t.translation() = t * in.velocity_b;
  draw_mesh(r, in.a, palette::muted.with_alpha(0.7f), false, at0);
  draw_mesh(r, in.b, palette::muted.with_alpha(0.7f), false, at0);
  if (!in.a.vertices.empty()) r.label(in.a.vertices[0], "A at t = 0", palette::muted);
  draw_mesh(r, in.b, palette::surface, true, b_t);
  draw_mesh(r, in.a, palette::input.with_alpha(0.55f), true, a_t);
  if (!in.a.vertices.empty()) r.label(a_t * in.a.vertices[0], "A at t = " + num(t), palette::input);
  if (!in.b.vertices.empty()) r.label(b_t * in.b.vertices[0], "B", palette::surface);
  const auto centre = [](const Mesh& m) {
    Vec3 sum = Vec3::Zero();
    for (const Vec3& v : m.vertices) sum += v;
    return m.vertices.empty() ? sum : Vec3(sum / double(m.vertices.size()));
  };
  if (in.velocity_a != Vec3::Zero())
    r.arrow(centre(in.a), centre(in.a) + in.velocity_a, palette::input, 2),
        r.label(centre(in.a) + in.velocity_a, "va", palette::input);
  if (in.velocity_b != Vec3::Zero())
    r.arrow(centre(in.b), centre(in.b) + in.velocity_b, palette::surface, 2),
        r.label(centre(in.b) + in.velocity_b, "vb", palette::surface);
  const oracle::MeshContact& e = exact_contact_;
  if (e.hit && e.kind == 2) {  // the swept parallelogram of the contact's edge of A, in B's frame (B still)
    const auto edge = in.a.edges()[std::size_t(e.feature_a)];
    const Vec3 p0 = in.a.vertices[std::size_t(edge[0])], p1 = in.a.vertices[std::size_t(edge[1])];
    const Vec3 o = t * in.velocity_b;  // drawn where B is at the contact
    r.triangle(o + p0, o + p1, o + p1 + d, palette::exact.with_alpha(0.22f));
    r.triangle(o + p0, o + p1 + d, o + p0 + d, palette::exact.with_alpha(0.16f));
    r.dashed(o + p1, o + p0 + d, palette::exact, 1.5f);
    r.line(o + p0 + d, o + p1 + d, palette::exact, 1.5f);
    r.label(o + p1 + d, "p1 + d", palette::exact);
    r.label(o + p0 + d, "p0 + d", palette::exact);
  } else if (e.hit && e.kind <= 1) {  // the vertex's path seen from the other mesh
    const Vec3 p = e.kind == 0 ? in.a.vertices[std::size_t(e.feature_a)] : in.b.vertices[std::size_t(e.feature_b)];
    const Vec3 o = t * (e.kind == 0 ? in.velocity_b : in.velocity_a);
    r.dashed(o + p, o + p + (e.kind == 0 ? d : Vec3(-d)), palette::exact, 1.5f);
  }
  if (got) {
    r.point(contact_->point, c, 5);
    r.ring(contact_->point, c, 15, 2.5f);
    r.label(contact_->point, "contact   t = " + num(contact_->t), c, 18, -16);
    // The normal, from B toward A, drawn a fifth of the scene's size long.
    const double reach = 0.2 * std::max(1.0, d.norm());
    r.arrow(contact_->point, contact_->point + reach * contact_->normal, c, 2);
    r.label(contact_->point + reach * contact_->normal, "n", c);
  }
  if (f.show_exact && e.hit) r.ring(e.point, palette::exact, 9);
}

void SegmentTriangleScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::contact) {
    draw_contact(f);
    return;
  }
  if (mode_ <= Mode::point) {
    draw_triangle(r, mode_ == Mode::triangle);
    draw_steps_1_to_4(f);
  } else {
    if (mode_ == Mode::moving) {  // the mesh at m0, faint; the particle's path in the mesh's frame
      draw_mesh(r, mesh_, palette::muted.with_alpha(0.6f), false, m0_);
      if (!mesh_.vertices.empty()) r.label(m0_ * mesh_.vertices[0], "the mesh at m0", palette::muted);
      if (!mesh_.vertices.empty()) r.label(m1_ * mesh_.vertices[0], "at m1", palette::surface);
      const Vec3 a = m1_ * (m0_.inverse() * segment_.a);
      r.dashed(a, segment_.b, palette::muted, 1.5f);
      r.label(a, "a seen from the mesh", palette::muted);
    }
    draw_mesh(r, mesh_, palette::surface, true, mode_ == Mode::moving ? m1_ : RigidTransform::Identity());
    draw_hits(f);
  }
  if (mode_ != Mode::point) {
    draw_segment(r, segment_);
  } else {
    r.point(x_, palette::input, 6);
    r.label(x_, "x", palette::input);
  }
}

bool SegmentTriangleScene::inputs() {
  bool changed = false;
  if (mode_ != Mode::point) changed |= edit("a", segment_.a) | edit("b", segment_.b);
  if (mode_ == Mode::point) changed |= edit("x", x_);
  if (mode_ <= Mode::point) changed |= edit("v0", triangle_.v0) | edit("v1", triangle_.v1) | edit("v2", triangle_.v2);
  if (mode_ == Mode::contact) return edit("velocity_a", meshes_.velocity_a) | edit("velocity_b", meshes_.velocity_b);
  if (mode_ >= Mode::mesh)
    ImGui::TextDisabled("mesh: %zu vertices, %zu triangles", mesh_.vertices.size(), mesh_.size());
  if (mode_ == Mode::moving) {
    Vec3 t0 = m0_.translation(), t1 = m1_.translation();
    if (edit("m0 translation", t0)) m0_.translation() = t0, changed = true;
    if (edit("m1 translation", t1)) m1_.translation() = t1, changed = true;
  }
  return changed;
}

std::vector<Handle> SegmentTriangleScene::handles() {
  std::vector<Handle> h;
  if (mode_ == Mode::contact) return h;
  if (mode_ == Mode::point)
    h.push_back({&x_, "x", &plane_});
  else
    h.insert(h.end(), {{&segment_.a, "a"}, {&segment_.b, "b"}});
  if (mode_ <= Mode::point) h.insert(h.end(), {{&triangle_.v0, "v0"}, {&triangle_.v1, "v1"}, {&triangle_.v2, "v2"}});
  return h;
}

}  // namespace viewer::segment_triangle
