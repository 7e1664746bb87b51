// The RapidCheck generators of meshes.h: small closed solids, soups, terrains and piles at
// every scale, points and segments near a mesh, and sets of spheres. In the tests'
// generators (labkit_generators); meshes.cpp holds the plain builders the viewer shares.
#include "common/generators/meshes.h"

#include "common/generators/generators.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace labkit::gen {

// ---- RapidCheck generators ---------------------------------------------------------------

namespace {

// Integer-times-power-of-two placement of a lattice solid: scale s, offset a lattice point
// (far from the origin one time in eight).
struct Placement {
  double s = 1.0;
  Vec3 offset = Vec3::Zero();
};

rc::Gen<Placement> placement() {
  return rc::gen::exec([] {
    const double s = *scale();
    const bool far = *rc::gen::inRange(0, 8) == 0;
    const Vec3 offset = far ? Vec3(*lattice_point(s * 64, 15)) : Vec3(*lattice_point(s, 4));
    return Placement{s, offset};
  });
}

Mesh moved(Mesh m, const Placement& p) {
  for (Vec3& v : m.vertices) v = p.offset + p.s * v;
  return m;
}

rc::Gen<Mesh> lattice_box() {
  return rc::gen::exec([] {
    const Placement p = *placement();
    const Vec3 lo(*integer(4), *integer(4), *integer(4));
    const Vec3 size(*rc::gen::inRange(1, 9), *rc::gen::inRange(1, 9), *rc::gen::inRange(1, 9));
    return moved(box_mesh({lo, lo + size}), p);
  });
}

rc::Gen<Mesh> lattice_octahedron() {
  return rc::gen::exec([] {
    const Placement p = *placement();
    const double r = *rc::gen::inRange(1, 9);
    Mesh m;
    m.vertices = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return moved(m, p);
  });
}

// 1 to 8 cubes in a 3 x 3 x 2 block, grown from one cube so that most shapes are one
// piece; edge-only contacts happen.
rc::Gen<Mesh> lattice_voxels() {
  return rc::gen::exec([] {
    const Placement p = *placement();
    const int count = *rc::gen::inRange(1, 9);
    std::vector<std::array<int, 3>> cubes{{0, 0, 0}};
    while (int(cubes.size()) < count) {
      // rapidcheck scales inRange with the size, down to the lower end at size 0: a cell
      // already taken moves on to the next free one (of 18), or the loop never ends.
      int cell = *rc::gen::inRange(0, 3) * 6 + *rc::gen::inRange(0, 3) * 2 + *rc::gen::inRange(0, 2);
      const auto of = [](int k) { return std::array<int, 3>{k / 6, k / 2 % 3, k % 2}; };
      while (std::find(cubes.begin(), cubes.end(), of(cell)) != cubes.end()) cell = (cell + 1) % 18;
      cubes.push_back(of(cell));
    }
    return moved(voxel_mesh(cubes, Vec3::Zero(), 1.0), p);
  });
}

rc::Gen<Mesh> coarse_sphere() {
  return rc::gen::exec([] {
    const Placement p = *placement();
    const int triangles = *rc::gen::element(8, 24, 48);
    return moved(sphere_mesh(triangles, Vec3::Zero(), *rc::gen::inRange(1, 9)), p);
  });
}

rc::Gen<Mesh> coarse_torus() {
  return rc::gen::exec([] {
    const Placement p = *placement();
    const double minor = *rc::gen::inRange(1, 3);
    return moved(torus_mesh(*rc::gen::element(18, 32, 72), Vec3::Zero(), minor + *rc::gen::inRange(1, 6), minor), p);
  });
}

// A lattice terrain with flat stretches: heights from {0, 0, 1, 2}, so that whole faces lie
// in the plane z = 0.
rc::Gen<Mesh> flat_terrain() {
  return rc::gen::exec([] {
    const Placement p = *placement();
    const int n = *rc::gen::inRange(1, 5);
    const Mesh m = height_field(n, 0, n, 0, n, [](double, double) { return double(*rc::gen::element(0, 0, 1, 2)); });
    return moved(m, p);
  });
}

// The same triangle many times over: no split can ever separate them.
rc::Gen<Mesh> pile() {
  return rc::gen::exec([] {
    const Triangle t = *triangle(*scale());
    Mesh m;
    m.vertices = {t.v0, t.v1, t.v2};
    const int n = *rc::gen::inRange(2, 24);
    for (int i = 0; i < n; ++i) m.triangles.push_back({0, 1, 2});
    return m;
  });
}

// The largest |coordinate| of a mesh: the scale S of its tolerances.
double size_of(const Mesh& m) { return std::max(scale_of(m), 1e-300); }

// Lab 06's domain reaches from S = 1e-50 to S = 1e50: the same shape moved to either
// end by a power of two (exact), so that only the scale changes.
double to_range_end(double s, bool huge) {
  return std::ldexp(1.0, (huge ? 165 : -166) - std::ilogb(std::max(s, 1e-300)));
}

rc::Gen<Mesh> at_range_ends(const rc::Gen<Mesh>& g) {
  return rc::gen::exec([g] {
    Mesh m = *g;
    const double factor = to_range_end(size_of(m), *rc::gen::arbitrary<bool>());
    for (Vec3& v : m.vertices) v *= factor;
    return m;
  });
}

// Needles: triangles whose height is up to 2^-27 (about 1e-8) of their longest side, in
// every orientation and position: the third vertex near an end (a spike) or near the
// middle (a cap), a dyadic hair off the line of the other two.
rc::Gen<Mesh> needles() {
  return rc::gen::exec([] {
    const double s = *scale();
    Mesh m;
    const int n = *rc::gen::inRange(1, 9);
    for (int i = 0; i < n; ++i) {
      const Vec3 a = *point(s), along = *direction(s), across = *direction(s);
      const double where = *rc::gen::element(0.0, 0.125, 0.5, 0.875, 1.0);
      const Vec3 c = a + where * along + *tiny(0, 27) * across;
      const int base = int(m.vertices.size());
      m.vertices.insert(m.vertices.end(), {a, a + along, c});
      m.triangles.push_back({base, base + 1, base + 2});
    }
    return m;
  });
}

// A decisive hair: k 2^-j S with k in 1..4 and j in 12..24, at least 2^-24 S (about 60
// tol): near-degenerate, yet farther than any perturbation of tol can reach.
rc::Gen<double> hair(double s) {
  return rc::gen::exec([s] { return *rc::gen::element(1.0, -1.0) * *rc::gen::inRange(1, 5) * *tiny(12, 24) * s; });
}

Aabb bounds_of(const Mesh& m) {
  Aabb b{Vec3::Zero(), Vec3::Zero()};
  if (m.vertices.empty()) return b;
  b.min = b.max = m.vertices[0];
  for (const Vec3& v : m.vertices) {
    b.min = b.min.cwiseMin(v);
    b.max = b.max.cwiseMax(v);
  }
  return b;
}

// A power of two near an eighth of the mesh's largest extent: the length unit of the
// segments aimed at it, whatever its distance from the origin.
double unit_of(const Mesh& m) {
  const Aabb b = bounds_of(m);
  const double extent = (b.max - b.min).maxCoeff();
  return extent > 0 ? std::ldexp(1.0, std::ilogb(extent) - 3)
                    : std::max(std::ldexp(1.0, std::ilogb(size_of(m)) - 3), 1e-300);
}

// The step of a lattice mesh: the largest power of two that divides all its coordinates,
// or 0 when that step is far below the mesh's extent (the mesh is not on a lattice).
double lattice_step(const Mesh& m) {
  const double unit = unit_of(m);
  double step = 64 * unit;
  for (const Vec3& v : m.vertices)
    for (int i = 0; i < 3; ++i)
      while (step >= unit / 512 && std::fmod(v[i], step) != 0) step /= 2;
  return step >= unit / 512 ? step : 0.0;
}

// A lattice point of the mesh's box, grown by one step: often on a face, an edge, a
// vertex or the plane of a face.
rc::Gen<Vec3> lattice_point_in(const Mesh& m, double step) {
  const Aabb b = bounds_of(m);
  return rc::gen::exec([b, step] {
    Vec3 p;
    for (int i = 0; i < 3; ++i) {
      const double lo = std::floor(b.min[i] / step) - 1, hi = std::ceil(b.max[i] / step) + 1;
      p[i] = step * (lo + *rc::gen::inRange(0, int(hi - lo) + 1));
    }
    return p;
  });
}

rc::Gen<Triangle> face_of(const Mesh& m) {
  return rc::gen::map(rc::gen::inRange(0, int(m.size())), [m](int i) { return m.triangle(std::size_t(i)); });
}

}  // namespace

rc::Gen<Mesh> closed_mesh() {
  const rc::Gen<Mesh> solids = rc::gen::weightedOneOf<Mesh>({{2, lattice_box()},
                                                             {2, lattice_octahedron()},
                                                             {3, lattice_voxels()},
                                                             {2, coarse_sphere()},
                                                             {2, coarse_torus()}});
  return rc::gen::weightedOneOf<Mesh>({{9, solids}, {1, at_range_ends(solids)}});
}

rc::Gen<Mesh> exact_closed_mesh() {
  return rc::gen::weightedOneOf<Mesh>({{1, lattice_box()}, {1, lattice_octahedron()}, {3, lattice_voxels()}});
}

rc::Gen<Mesh> any_mesh() {
  const rc::Gen<Mesh> any = rc::gen::weightedOneOf<Mesh>({{4, rc::gen::exec([] { return *mesh(*scale()); })},
                                                          {3, closed_mesh()},
                                                          {2, flat_terrain()},
                                                          {1, pile()},
                                                          {1, needles()}});
  return rc::gen::weightedOneOf<Mesh>({{9, any}, {1, at_range_ends(any)}});
}

rc::Gen<Mesh> exact_mesh() {
  return rc::gen::weightedOneOf<Mesh>({{1, lattice_box()}, {3, lattice_voxels()}, {2, flat_terrain()}});
}

rc::Gen<Vec3> point_near(const Mesh& m, bool exact) {
  if (m.size() == 0) return rc::gen::just(Vec3(Vec3::Zero()));
  const double step = lattice_step(m);
  const rc::Gen<Vec3> on_face = rc::gen::mapcat(face_of(m), [](const Triangle& t) { return point_in_triangle(t); });
  const rc::Gen<Vec3> vertex = rc::gen::elementOf(m.vertices);
  const rc::Gen<Vec3> lattice = step > 0 ? lattice_point_in(m, step) : on_face;
  if (exact) return rc::gen::weightedOneOf<Vec3>({{3, on_face}, {1, vertex}, {4, lattice}});
  const Aabb b = bounds_of(m);
  const double s = size_of(m);
  const rc::Gen<Vec3> anywhere = rc::gen::exec([b] {
    const Vec3 margin = 0.25 * (b.max - b.min);
    Vec3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = b.min[i] - margin[i] +
             (b.max[i] - b.min[i] + 2 * margin[i]) * *rc::gen::inRange(0, 1 << 20) / double(1 << 20);
    return p;
  });
  // A point of a face (often on an edge or a vertex) moved off it along its normal by a
  // decisive hair. Points exactly on the surface belong to the exact families.
  const rc::Gen<Vec3> off_face = rc::gen::exec([m, s] {
    const Triangle t = *face_of(m);
    const Vec3 n = t.normal() == Vec3::Zero() ? Vec3(Vec3::UnitZ()) : Vec3(t.normal().normalized());
    return Vec3(*point_in_triangle(t) + *hair(s) * n);
  });
  // A vertex or a lattice point (often on faces, edges and their planes) moved by hairs of
  // 1, 2 and 4 units with any signs: never along a lattice face's plane (axis or (1, 1, 1)
  // normals: +-1 +-2 +-4 is never 0).
  const auto nudged = [s](const rc::Gen<Vec3>& near) {
    return rc::gen::exec([near, s] {
      const double h = *hair(s);
      return Vec3(*near + h * Vec3(*rc::gen::element(1, -1), *rc::gen::element(2, -2), *rc::gen::element(4, -4)));
    });
  };
  return rc::gen::weightedOneOf<Vec3>({{1, nudged(vertex)}, {2, nudged(lattice)}, {4, anywhere}, {4, off_face}});
}

rc::Gen<Segment> segment_near(const Mesh& m) {
  if (m.size() == 0) return rc::gen::exec([] { return Segment{*point(1.0), *point(1.0)}; });
  const double s = size_of(m), unit = unit_of(m);
  // Through a point of a face, pulled off its edges toward the centroid by 2^-1 to 2^-12
  // of the way (near an edge, not on it): from any side, at any length, sometimes aimed
  // at a vertex of that face a step off its plane, so that it runs nearly along the face.
  const rc::Gen<Segment> through = rc::gen::exec([m, unit] {
    const Triangle t = *face_of(m);
    const Vec3 centroid = (t.v0 + t.v1 + t.v2) / 3;
    const Vec3 p = *point_in_triangle(t);
    const Vec3 x = p + *tiny(1, 12) * (centroid - p);
    Vec3 d = *direction(unit);
    if (*rc::gen::inRange(0, 4) == 0)
      d = t[*rc::gen::inRange(0, 3)] - x + *rc::gen::element(1, -1, 2, -2) * unit * t.normal().cwiseSign();
    if (d == Vec3::Zero()) d = unit * Vec3::UnitX();
    const int k = *rc::gen::inRange(1, 17);
    return Segment{x + d, x - (k / 8.0) * d};
  });
  const rc::Gen<Segment> between = rc::gen::exec([m] { return Segment{*point_near(m, false), *point_near(m, false)}; });
  // Short segments a decisive hair off a face, along it or ending just before it.
  const rc::Gen<Segment> grazing = rc::gen::exec([m, s, unit] {
    const Triangle t = *face_of(m);
    const Vec3 x = *point_in_triangle(t);
    const Vec3 n = t.normal() == Vec3::Zero() ? Vec3(Vec3::UnitZ()) : Vec3(t.normal().normalized());
    const double h = std::abs(*hair(s));
    const Vec3 d = *direction(unit / 2);
    return *rc::gen::element(Segment{x + n * h, x + n * h + d}, Segment{x + n * (h + unit), x + n * h});
  });
  return rc::gen::weightedOneOf<Segment>({{4, through}, {3, between}, {2, grazing}});
}

rc::Gen<Segment> exact_segment_near(const Mesh& m) {
  const double step = lattice_step(m) > 0 ? lattice_step(m) : unit_of(m);
  return rc::gen::exec([m, step] {
    // An anchor on the lattice, a vertex or a point of a face with eighths weights (the
    // lattice of exact meshes is a multiple of 8 steps only for boxes and cubes; halves
    // and quarters are safe everywhere).
    Vec3 x = *lattice_point_in(m, step);
    if (m.size() > 0 && *rc::gen::inRange(0, 2) == 0) {
      const Triangle t = *face_of(m);
      const int p = *rc::gen::inRange(0, 5), q = *rc::gen::inRange(0, 5 - p);
      x = (p * t.v0 + q * t.v1 + (4 - p - q) * t.v2) / 4;
    }
    // A direction whose largest |component| is a power of two: along an axis, along a
    // face diagonal, or slanted with small integer parts.
    const int major = *rc::gen::inRange(0, 3);
    Vec3 d = Vec3::Zero();
    d[major] = (*rc::gen::element(1, -1)) * step * *rc::gen::element(1, 2, 4, 8);
    const int kind = *rc::gen::inRange(0, 3);
    if (kind >= 1) d[(major + 1) % 3] = step * *integer(int(std::abs(d[major]) / step));
    if (kind == 2) d[(major + 2) % 3] = step * *integer(int(std::abs(d[major]) / step));
    // Both ends, one end or neither on the anchor.
    switch (*rc::gen::inRange(0, 3)) {
      case 0: return Segment{x - d, x + d};
      case 1: return Segment{x, x + d};
      default: return Segment{x - d, x};
    }
  });
}

// ---- Spheres ---------------------------------------------------------------------------

namespace {

rc::Gen<Sphere> sphere_at(double s, int magnitude, int max_radius) {
  return rc::gen::exec([=] { return Sphere{*lattice_point(s, magnitude), s * *rc::gen::inRange(0, max_radius + 1)}; });
}

// Spheres that touch in a chain, exactly: along an axis or along a lattice direction
// of integer length L ((3, 4, 0): L = 5; (2, 3, 6): L = 7). Radii are multiples of s L
// and each step between centres is (r + r') / L times the direction: exactly r + r'.
rc::Gen<std::vector<Sphere>> touching_chain(double s) {
  return rc::gen::exec([s] {
    const Vec3 dir = *rc::gen::element(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(3, 4, 0), Vec3(2, -3, 6));
    const double length = dir.norm();
    std::vector<Sphere> out;
    Vec3 c = *lattice_point(s, 4);
    const int n = *rc::gen::inRange(2, 9);
    int k = *rc::gen::inRange(0, 4);
    for (int i = 0; i < n; ++i) {
      out.push_back({c, s * length * k});
      const int next = *rc::gen::inRange(0, 4);
      c += s * (k + next) * dir;
      k = next;
    }
    return out;
  });
}

// The families above make many pairs touch exactly: the robustness step's input. Here
// each is moved a decisive hair apart or together: a radius changes by 2^-20 S (about
// 1000 tol) until no pair is within 64 tol of touching. Near-touching stays, ambiguity
// goes.
void make_decisive(std::vector<Sphere>& spheres) {
  double size = 1e-300;
  for (const Sphere& sp : spheres) size = std::max({size, sp.center.cwiseAbs().maxCoeff(), sp.radius});
  const double band = 64e-9 * size, step = std::ldexp(size, -20);
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const bool shrink = i % 2 == 1 && spheres[i].radius >= 16 * step;  // apart, or together
    for (int attempt = 0; attempt < 16; ++attempt) {
      bool close = false;
      for (std::size_t j = 0; j < i && !close; ++j)
        close =
            std::abs((spheres[i].center - spheres[j].center).norm() - (spheres[i].radius + spheres[j].radius)) <= band;
      if (!close) break;
      spheres[i].radius += shrink ? -step : step;
    }
  }
}

}  // namespace

rc::Gen<std::vector<Sphere>> sphere_set() {
  return rc::gen::exec([] {
    const double s = *scale();
    const int kind = *rc::gen::inRange(0, 7);
    std::vector<Sphere> out;
    const int n = *rc::gen::inRange(0, 61);
    switch (kind) {
      case 0:  // spread out: few overlaps
        for (int i = 0; i < n; ++i) out.push_back({*point(s * 4), s * *rc::gen::inRange(0, 1 << 20) / double(1 << 19)});
        break;
      case 1:  // clustered: many overlaps
        for (int i = 0; i < n; ++i) out.push_back({*point(s / 4), s * *rc::gen::inRange(0, 1 << 20) / double(1 << 18)});
        break;
      case 2: {  // all on the plane x = const: a sweep along x sees every pair overlap
        const double x = (*point(s)).x();
        for (int i = 0; i < n; ++i) {
          Vec3 c = *point(s);
          c.x() = x;
          out.push_back({c, s * *rc::gen::inRange(0, 1 << 20) / double(1 << 20)});
        }
        break;
      }
      case 3:  // exact chains, mixed with loose spheres
        out = *touching_chain(s);
        for (int i = 0; i < n / 4; ++i) out.push_back(*sphere_at(s, 8, 3));
        break;
      case 4:  // coincident centres and zero radii
        for (int i = 0; i < n / 2; ++i) {
          const Sphere a = *sphere_at(s, 4, 2);
          out.push_back(a);
          out.push_back({a.center, s * *rc::gen::inRange(0, 3)});
        }
        break;
      case 5: {  // one huge sphere among small ones
        for (int i = 0; i < n; ++i) out.push_back({*point(s * 4), s * *rc::gen::inRange(0, 1 << 20) / double(1 << 20)});
        out.insert(out.begin() + *rc::gen::inRange(0, int(out.size()) + 1),
                   Sphere{*point(s), s * *rc::gen::inRange(8, 40)});
        break;
      }
      default:  // lattice spheres: touching and exactly tangent pairs happen often
        for (int i = 0; i < n; ++i) out.push_back(*sphere_at(s, 6, 3));
    }
    if (*rc::gen::inRange(0, 8) == 0) {  // far from the origin
      const Vec3 offset = *lattice_point(s * 1024, 64);
      for (Sphere& sp : out) sp.center += offset;
    }
    if (*rc::gen::inRange(0, 10) == 0) {  // at an end of the domain, S near 1e50 or 1e-50
      double size = 1e-300;
      for (const Sphere& sp : out) size = std::max({size, sp.center.cwiseAbs().maxCoeff(), sp.radius});
      const double factor = to_range_end(size, *rc::gen::arbitrary<bool>());
      for (Sphere& sp : out) sp = {sp.center * factor, sp.radius * factor};
    }
    make_decisive(out);
    return out;
  });
}

rc::Gen<std::vector<Sphere>> exact_sphere_set() {
  return rc::gen::exec([] {
    const double s = *scale();
    std::vector<Sphere> out = *touching_chain(s);
    const std::vector<Sphere> more = *touching_chain(s);
    out.insert(out.end(), more.begin(), more.end());
    const int loose = *rc::gen::inRange(0, 20);
    for (int i = 0; i < loose; ++i) out.push_back(*sphere_at(s, 6, 3));
    std::vector<Sphere> shuffled;
    for (const Sphere& sp : out) shuffled.insert(shuffled.begin() + *rc::gen::inRange(0, int(shuffled.size()) + 1), sp);
    return shuffled;
  });
}

}  // namespace labkit::gen
