#include "viewer/shapes.h"

#include <cmath>

namespace viewer {

using labkit::Vec3;

void draw_mesh(Renderer& r, const labkit::Mesh& mesh, Color c, bool filled, const labkit::RigidTransform& pose) {
  const bool edges = mesh.size() <= 20000;
  const Color edge = filled ? Color{0.30f, 0.40f, 0.55f} : c;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const labkit::Triangle t = mesh.triangle(i);
    const Vec3 a = pose * t.v0, b = pose * t.v1, d = pose * t.v2;
    if (filled) r.triangle(a, b, d, c);
    if (edges) r.line(a, b, edge, 1), r.line(b, d, edge, 1), r.line(d, a, edge, 1);
  }
}

Corners corners_of(const labkit::Box& b) {
  Corners p;
  for (int i = 0; i < 8; ++i) p[std::size_t(i)] = b.corner(i);
  return p;
}

void draw_edges(Renderer& r, const Corners& p, Color c, float width) {
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t bit : {1, 2, 4})
      if (!(i & bit)) r.line(p[i], p[i | bit], c, width);
}

void draw_faces(Renderer& r, const Corners& p, Color c) {
  static const int faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& q : faces) {
    r.triangle(p[std::size_t(q[0])], p[std::size_t(q[1])], p[std::size_t(q[2])], c);
    r.triangle(p[std::size_t(q[0])], p[std::size_t(q[2])], p[std::size_t(q[3])], c);
  }
}

void draw_circle(Renderer& r, const Vec3& c, const Vec3& e1, const Vec3& e2, double radius, Color col, float width,
                 int sides) {
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * M_PI * i / sides, b = 2 * M_PI * (i + 1) / sides;
    r.line(c + radius * (std::cos(a) * e1 + std::sin(a) * e2), c + radius * (std::cos(b) * e1 + std::sin(b) * e2), col,
           width);
  }
}

void draw_sphere(Renderer& r, const Vec3& c, double radius, Color col, float width, int sides,
                 const labkit::Mat3& axes) {
  for (int axis = 0; axis < 3; ++axis)
    draw_circle(r, c, axes.col((axis + 1) % 3), axes.col((axis + 2) % 3), radius, col, width, sides);
}

Square square_around(const Vec3& c, const Vec3& u, const Vec3& w, double half) {
  return {c + half * (u + w), c + half * (-u + w), c + half * (-u - w), c + half * (u - w)};
}

void fill(Renderer& r, const Square& q, Color c) {
  r.triangle(q[0], q[1], q[2], c);
  r.triangle(q[0], q[2], q[3], c);
}

void outline(Renderer& r, const Square& q, Color c, float width, bool dashed) {
  for (std::size_t i = 0; i < 4; ++i) {
    if (dashed)
      r.dashed(q[i], q[(i + 1) % 4], c, width);
    else
      r.line(q[i], q[(i + 1) % 4], c, width);
  }
}

void draw_segment(Renderer& r, const labkit::Segment& s) {
  r.line(s.a, s.b, palette::input, 2.5f);
  r.point(s.a, palette::input, 6), r.point(s.b, palette::input, 6);
  r.label(s.a, "a", palette::input), r.label(s.b, "b", palette::input);
}

}  // namespace viewer
