#include "common/generators/generators.h"
#include "07_particles/judge.h"
#include "common/generators/grid.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace labkit::gen {

namespace {

// Where a family draws from (its Grid): the fine dyadic lattice at the particles'
// scales, or (exact) integers that are multiples of 8 at the common scales.
rc::Gen<Vec3> grid_point(const Grid& g) { return g.exact ? lattice_point(8 * g.s, 16) : point(g.s); }
rc::Gen<Vec3> grid_direction(const Grid& g) { return direction(g.exact ? 8 * g.s : g.s, 8); }
double unit_of(const Grid& g) { return g.exact ? 8 * g.s : g.s; }

rc::Gen<Vec3> integer_normal(int magnitude) { return direction(1.0, magnitude); }

Plane through(const Vec3& p, const Vec3& n) { return Plane{n, -n.dot(p)}; }

// Two lattice vectors lying in the plane with normal n (exactly: n . u = 0).
std::array<Vec3, 2> in_plane(const Vec3& n) {
  const Vec3 axis = std::abs(n.x()) <= std::abs(n.y()) && std::abs(n.x()) <= std::abs(n.z()) ? Vec3::UnitX()
                    : std::abs(n.y()) <= std::abs(n.z())                                     ? Vec3::UnitY()
                                                                                             : Vec3::UnitZ();
  const Vec3 u = n.cross(axis);
  return {u, n.cross(u)};
}

// p/8 steps: every constructed point stays on a dyadic grid, exact in doubles.
Vec3 eighths(const Vec3& origin, const Vec3& u, int p, const Vec3& v, int q) {
  return origin + (p / 8.0) * u + (q / 8.0) * v;
}

// The planes of one scene, all through `anchor`: none, one, a crease of two, a corner of
// three, a floor and two walls, or a crack (two planes facing each other, k/8 apart).
// Every normal has a positive part along one direction, so that the space in front of all
// of them has room in it (three planes through a point can otherwise leave only a line).
std::vector<Plane> plane_set(const Grid& g, const Vec3& anchor) {
  const int kind = *rc::gen::inRange(0, 6);
  const Vec3 inside = *integer_normal(2);
  const auto toward_inside = [&](Vec3 n) {
    if (n.dot(inside) == 0) n += inside;
    return n.dot(inside) < 0 ? Vec3(-n) : n;
  };
  const auto normal = [] {
    return *rc::gen::weightedOneOf<Vec3>({{1, rc::gen::just(Vec3(Vec3::UnitZ()))}, {3, integer_normal(3)}});
  };
  std::vector<Plane> planes;
  switch (kind) {
    case 0: break;
    case 1: planes.push_back(through(anchor, normal())); break;
    case 2:
    case 3:
      for (int i = 0; i < kind; ++i) {
        Vec3 n = toward_inside(normal());
        // No two parallel: through one point they would be one plane, or leave no room.
        for (int k = 0; k < 3; ++k)
          if (std::any_of(planes.begin(), planes.end(),
                          [&](const Plane& p) { return p.normal.cross(n) == Vec3::Zero(); }))
            n = toward_inside(n + Vec3::Unit(k));
        planes.push_back(through(anchor, n));
      }
      break;
    case 4:
      for (int k = 0; k < 3; ++k)
        planes.push_back(through(anchor, inside[k] < 0 ? Vec3(-Vec3::Unit(k)) : Vec3(Vec3::Unit(k))));
      break;
    default: {
      const Vec3 n = normal();
      const int k = *rc::gen::inRange(1, 9);
      planes = {through(anchor, n), through(anchor + (k / 8.0) * unit_of(g) * n, -n)};
    }
  }
  return planes;
}

// A point exactly on feature `which` of the planes: on one plane, on the crease of two,
// or at the common corner.
Vec3 on_planes(const Grid& g, const std::vector<Plane>& planes, const Vec3& anchor) {
  const double u = unit_of(g);
  const int which = *rc::gen::inRange(0, 3);
  if (which == 0 || planes.size() < 2) {
    const Plane& p = planes[std::size_t(*rc::gen::inRange(0, int(planes.size())))];
    const auto [a, b] = in_plane(p.normal);
    // Planes of a crack do not pass through the anchor: step from a point on this one.
    const Vec3 base = anchor - (p.value(anchor) / p.normal.squaredNorm()) * p.normal;
    return eighths(base, u * a, *rc::gen::inRange(-16, 17), u * b, *rc::gen::inRange(-16, 17));
  }
  if (which == 1) {
    const Vec3 line = planes[0].normal.cross(planes[1].normal);
    if (line != Vec3::Zero() && planes[0].value(anchor) == 0 && planes[1].value(anchor) == 0)
      return eighths(anchor, u * line, *rc::gen::inRange(-8, 9), Vec3::Zero(), 0);
  }
  return anchor;
}

// A point exactly in the plane of a mesh triangle: inside it (edges and vertices too) or
// outside it, as an affine combination (p v0 + q v1 + r v2) / 8 with p + q + r = 8.
Vec3 on_triangle_plane(const Triangle& t, bool inside) {
  const int low = inside ? 0 : -8;
  const int p = *rc::gen::inRange(low, 9);
  const int q = *rc::gen::inRange(low, 9 - std::max(p, 0));
  const int r = 8 - p - q;
  return (p * t.v0 + q * t.v1 + r * t.v2) / 8.0;
}

// A flat square of two triangles at the height of the floor through `anchor`: a plane
// and a triangle hit at the same t.
Mesh flat_square(const Grid& g, const Vec3& anchor) {
  const double size = unit_of(g) * *rc::gen::inRange(1, 5);
  Mesh m;
  m.vertices = {anchor, anchor + Vec3(size, 0, 0), anchor + Vec3(size, size, 0), anchor + Vec3(0, size, 0)};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// A segment through x: crossing, starting on it, ending on it, or (with an in-plane
// vector) sliding along and nearly along.
Segment through_point(const Grid& g, const Vec3& x, const Vec3& normal) {
  const Vec3 d = *grid_direction(g);
  const int k = *rc::gen::inRange(1, 17);
  switch (*rc::gen::inRange(0, g.exact ? 5 : 7)) {
    case 0: return {x + d, x - (k / 8.0) * d};
    case 1: return {x, x + d};
    case 2: return {x, x - d};
    case 3: return {x + d, x};
    case 4: {
      auto [u, v] = in_plane(normal);
      // A triangle's normal (large): only roughly in its plane, but a is on it. Exact cases
      // (planes only, normals up to 5) keep the integer vectors: b exactly in the plane.
      if (!g.exact && normal.cwiseAbs().maxCoeff() > 3) {
        u.normalize();
        v.normalize();
      }
      return {x, eighths(x, unit_of(g) * u, *rc::gen::inRange(-16, 17), unit_of(g) * v, *rc::gen::inRange(-16, 17))};
    }
    case 5: {  // nearly along: lifted by tiny amounts
      const auto [u, v] = in_plane(normal);
      const double size = scale_of({x}) + unit_of(g);
      const Vec3 lift = normal.normalized() * size;
      const Vec3 b = eighths(x, unit_of(g) * u.normalized(), *rc::gen::inRange(1, 17), Vec3::Zero(), 0);
      return {x + *integer(4) * *tiny(20, 50) * lift, b + *integer(4) * *tiny(20, 50) * lift};
    }
    default: return {x, x};
  }
}

StepSurfaces surfaces(bool exact) {
  const Grid g = *grid(exact, exact ? scale() : particle_scale());
  const Vec3 anchor = *grid_point(g);
  StepSurfaces c;
  c.planes = plane_set(g, anchor);
  const int mesh_kind = exact ? 0 : *rc::gen::inRange(0, 4);  // 0: none, 1: flat square, 2-3: gen::mesh
  if (mesh_kind == 1) c.mesh = flat_square(g, anchor);
  if (mesh_kind >= 2) c.mesh = *mesh(g.s);

  const bool aim_at_mesh = !c.mesh.triangles.empty() && (c.planes.empty() || *rc::gen::inRange(0, 2) == 0);
  if (aim_at_mesh) {
    const Triangle t = c.mesh.triangle(std::size_t(*rc::gen::inRange(0, int(c.mesh.size()))));
    const Vec3 x =
        *rc::gen::weightedOneOf<Vec3>({{3, point_in_triangle(t)}, {1, rc::gen::just(on_triangle_plane(t, false))}});
    c.step = through_point(g, x, t.normal() == Vec3::Zero() ? Vec3(Vec3::UnitZ()) : t.normal());
  } else if (!c.planes.empty() && *rc::gen::inRange(0, 5) != 0) {
    const Vec3 x = on_planes(g, c.planes, anchor);
    const Plane& p = c.planes[std::size_t(*rc::gen::inRange(0, int(c.planes.size())))];
    c.step = through_point(g, x, p.normal);
    // Mostly from the plane's open side, where it can be hit.
    if (p.value(c.step.a) < p.value(c.step.b) && *rc::gen::inRange(0, 4) != 0) std::swap(c.step.a, c.step.b);
  } else {
    c.step = {*grid_point(g), *grid_point(g)};
  }
  return c;
}

// Exact: planes only, or one triangle whose plane the step starts on.
StepSurfaces exact_surfaces() {
  if (*rc::gen::inRange(0, 4) != 0) return surfaces(true);
  const Grid g = *grid(true);
  const Triangle t = *rc::gen::suchThat(rc::gen::exec([g] {
                                          return Triangle{*grid_point(g), *grid_point(g), *grid_point(g)};
                                        }),
                                        [](const Triangle& tri) { return tri.normal() != Vec3::Zero(); });
  StepSurfaces c;
  c.mesh.vertices = {t.v0, t.v1, t.v2};
  c.mesh.triangles = {{0, 1, 2}};
  const Vec3 a = on_triangle_plane(t, *rc::gen::inRange(0, 2) == 0);
  c.step = {a, *rc::gen::oneOf(rc::gen::just(Vec3(a + *grid_direction(g))), grid_point(g))};
  return c;
}

// Any case moved far from the origin: large coordinates, small features.
StepSurfaces far_away(StepSurfaces c) {
  double size = scale_of({c.step.a, c.step.b});
  for (const Vec3& v : c.mesh.vertices) size = std::max(size, v.cwiseAbs().maxCoeff());
  const Vec3 offset = *lattice_point(size * 1024.0, 64);  // at the case's own scale, however small
  c.step.a += offset;
  c.step.b += offset;
  for (Vec3& v : c.mesh.vertices) v += offset;
  for (Plane& p : c.planes) p.offset -= p.normal.dot(offset);
  return c;
}

}  // namespace

rc::Gen<double> particle_scale() {
  return rc::gen::weightedOneOf<double>(
      {{9, scale()},
       {1, rc::gen::element(std::ldexp(1.0, -100), std::ldexp(1.0, -60), std::ldexp(1.0, 60), std::ldexp(1.0, 100))}});
}

rc::Gen<Plane> plane_through(const Vec3& point, int magnitude) {
  return rc::gen::map(integer_normal(magnitude), [point](const Vec3& n) { return through(point, n); });
}

bool cracks_in_domain(const std::vector<Plane>& planes, double scale) {
  for (const Plane& p : planes)
    if (p.normal != Vec3::Zero()) scale = std::max(scale, std::abs(p.offset) / p.normal.norm());
  for (std::size_t i = 0; i < planes.size(); ++i)
    for (std::size_t j = i + 1; j < planes.size(); ++j) {
      const Plane &p = planes[i], &q = planes[j];
      if (p.normal == Vec3::Zero() || q.normal == Vec3::Zero() || p.normal.cross(q.normal) != Vec3::Zero() ||
          p.normal.dot(q.normal) >= 0)
        continue;
      const double gap = std::abs(p.offset / p.normal.norm() + q.offset / q.normal.norm());
      if (gap < std::ldexp(scale, -40)) return false;
    }
  return true;
}

namespace {

// The step's ends and the mesh's vertices are the case's points.
bool step_in_domain(const StepSurfaces& c) {
  double s = scale_of({c.step.a, c.step.b});
  for (const Vec3& v : c.mesh.vertices) s = std::max(s, v.cwiseAbs().maxCoeff());
  return cracks_in_domain(c.planes, s);
}

}  // namespace

rc::Gen<StepSurfaces> step_surfaces() {
  const rc::Gen<StepSurfaces> near = rc::gen::exec([] { return surfaces(false); });
  return rc::gen::suchThat(
      rc::gen::weightedOneOf<StepSurfaces>({{7, near}, {1, rc::gen::exec([near] { return far_away(*near); })}}),
      step_in_domain);
}

rc::Gen<StepSurfaces> exact_step_surfaces() {
  return rc::gen::exec([] { return exact_surfaces(); });
}

}  // namespace labkit::gen
