#include "common/generators/meshes.h"

#include "common/splitmix.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace labkit::gen {

namespace {

constexpr double kPi = 3.14159265358979323846;

using Random = SplitMix64;

// Adds vertices once each, so that faces of a closed surface share them.
class Builder {
 public:
  int vertex(const Vec3& p) {
    const auto [it, added] = index_.try_emplace({p.x(), p.y(), p.z()}, int(mesh_.vertices.size()));
    if (added) mesh_.vertices.push_back(p);
    return it->second;
  }
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    mesh_.triangles.push_back({vertex(a), vertex(b), vertex(c)});
  }
  Mesh take() { return std::move(mesh_); }

 private:
  Mesh mesh_;
  std::map<std::array<double, 3>, int> index_;
};

Vec3 unit(int axis) { return Vec3::Unit(axis); }

// The square face of the cube at `corner` (its lowest corner, side `s`) on axis k, on the
// high side (+1) or the low side (-1). With u, v the next two axes, u x v = e_k: the quad
// o, o + u, o + u + v, o + v winds around +e_k, and the low face is wound backwards.
void add_cube_face(Builder& b, const Vec3& corner, double s, int k, int side) {
  const Vec3 u = s * unit((k + 1) % 3), v = s * unit((k + 2) % 3);
  const Vec3 o = side > 0 ? Vec3(corner + s * unit(k)) : corner;
  if (side > 0) {
    b.triangle(o, o + u, o + u + v);
    b.triangle(o, o + u + v, o + v);
  } else {
    b.triangle(o, o + u + v, o + u);
    b.triangle(o, o + v, o + u + v);
  }
}

}  // namespace

// ---- Builders of adjustable size ------------------------------------------------------

// Rings of latitude k = 1 .. stacks - 1 between two poles, `slices` vertices each, with
// slices = 2 stacks: 2 slices (stacks - 1) = 4 stacks (stacks - 1) triangles. A quad
// (k, j) (k+1, j) (k+1, j+1) (k, j+1) runs down, then east: outward.
Mesh sphere_mesh(int triangles, const Vec3& center, double radius) {
  const int stacks = std::max(2, int(std::lround((1 + std::sqrt(1.0 + triangles)) / 2)));
  const int slices = 2 * stacks;
  Mesh m;
  m.vertices.push_back(center + radius * Vec3::UnitZ());
  for (int k = 1; k < stacks; ++k)
    for (int j = 0; j < slices; ++j) {
      const double theta = kPi * k / stacks, phi = 2 * kPi * j / slices;
      m.vertices.push_back(
          center + radius * Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)));
    }
  m.vertices.push_back(center - radius * Vec3::UnitZ());
  const int south = int(m.vertices.size()) - 1;
  const auto ring = [slices](int k, int j) { return 1 + (k - 1) * slices + (j % slices); };
  for (int j = 0; j < slices; ++j) {
    m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
    for (int k = 1; k + 1 < stacks; ++k) {
      m.triangles.push_back({ring(k, j), ring(k + 1, j), ring(k + 1, j + 1)});
      m.triangles.push_back({ring(k, j), ring(k + 1, j + 1), ring(k, j + 1)});
    }
    m.triangles.push_back({ring(stacks - 1, j), south, ring(stacks - 1, j + 1)});
  }
  return m;
}

// p(alpha, beta) = ((R + r cos beta) cos alpha, (R + r cos beta) sin alpha, r sin beta):
// dp/dalpha x dp/dbeta points out of the tube, so each quad runs alpha first.
Mesh torus_mesh(int triangles, const Vec3& center, double major, double minor) {
  const int around = std::max(3, int(std::lround(std::sqrt(triangles / 4.0))));  // tube cross-sections
  const int ring = 2 * around;                                                   // around the main ring
  Mesh m;
  for (int i = 0; i < ring; ++i)
    for (int j = 0; j < around; ++j) {
      const double alpha = 2 * kPi * i / ring, beta = 2 * kPi * j / around;
      const double w = major + minor * std::cos(beta);
      m.vertices.push_back(center + Vec3(w * std::cos(alpha), w * std::sin(alpha), minor * std::sin(beta)));
    }
  const auto at = [=](int i, int j) { return (i % ring) * around + (j % around); };
  for (int i = 0; i < ring; ++i)
    for (int j = 0; j < around; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// A few waves with random directions and phases: smooth hills, no two seeds alike.
Mesh terrain_mesh(int triangles, std::uint64_t seed) {
  const int n = std::max(1, int(std::lround(std::sqrt(triangles / 2.0))));
  Random random{seed};
  struct Wave {
    double kx, ky, phase, amplitude;
  };
  std::vector<Wave> waves;
  for (int i = 0; i < 6; ++i)
    waves.push_back({random.uniform(-12, 12), random.uniform(-12, 12), random.uniform(0, 2 * kPi), 0.04 / (1 + i % 3)});
  return height_field(n, 0, 1, 0, 1, [&](double x, double y) {
    double z = 0;
    for (const Wave& w : waves) z += w.amplitude * std::sin(w.kx * x + w.ky * y + w.phase);
    return z;
  });
}

Mesh height_field(int n, double x0, double x1, double y0, double y1,
                  const std::function<double(double, double)>& height) {
  Mesh m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = x0 + (x1 - x0) * i / n, y = y0 + (y1 - y0) * j / n;
      m.vertices.push_back({x, y, height(x, y)});
    }
  m.triangles = grid_triangles(n);
  return m;
}

std::vector<std::array<int, 3>> grid_triangles(int n) {
  std::vector<std::array<int, 3>> triangles;
  const auto at = [n](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return triangles;
}

void add_square(Mesh& mesh, double side, double z) {
  const int base = int(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), {{0, 0, z}, {side, 0, z}, {side, side, z}, {0, side, z}});
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
}

Mesh soup_mesh(int triangles, std::uint64_t seed) {
  Random random{seed};
  const double size = 1.0 / std::cbrt(std::max(1, triangles));
  Mesh m;
  for (int i = 0; i < triangles; ++i) {
    const Vec3 c(random.uniform(), random.uniform(), random.uniform());
    for (int k = 0; k < 3; ++k)
      m.vertices.push_back(c + size * Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)));
    m.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  return m;
}

const char* name_of(MeshKind kind) {
  switch (kind) {
    case MeshKind::sphere: return "sphere";
    case MeshKind::torus: return "torus";
    case MeshKind::terrain: return "terrain";
    case MeshKind::soup: return "soup";
  }
  return "?";
}

Mesh mesh_of_kind(MeshKind kind, int triangles, std::uint64_t seed) {
  switch (kind) {
    case MeshKind::sphere: return sphere_mesh(triangles, Vec3(0.5, 0.5, 0.5), 0.5);
    case MeshKind::torus: return torus_mesh(triangles, Vec3(0.5, 0.5, 0.5), 0.35, 0.12);
    case MeshKind::terrain: return terrain_mesh(triangles, seed);
    case MeshKind::soup: return soup_mesh(triangles, seed);
  }
  return {};
}

// ---- Closed lattice solids ---------------------------------------------------------------

Mesh box_mesh(const Aabb& box) {
  // A box is one stretched cube: build the unit cube's faces, then move its corners.
  Builder b;
  for (int k = 0; k < 3; ++k)
    for (int side : {-1, 1}) add_cube_face(b, Vec3::Zero(), 1.0, k, side);
  Mesh m = b.take();
  for (Vec3& p : m.vertices) p = box.min + p.cwiseProduct(box.max - box.min);
  return m;
}

Mesh voxel_mesh(const std::vector<std::array<int, 3>>& cubes, const Vec3& origin, double scale) {
  const std::set<std::array<int, 3>> filled(cubes.begin(), cubes.end());
  Builder b;
  for (const auto& c : filled) {
    const Vec3 corner = origin + scale * Vec3(c[0], c[1], c[2]);
    for (int k = 0; k < 3; ++k)
      for (int side : {-1, 1}) {
        std::array<int, 3> neighbour = c;
        neighbour[std::size_t(k)] += side;
        if (!filled.count(neighbour)) add_cube_face(b, corner, scale, k, side);
      }
  }
  return b.take();
}

std::vector<Sphere> spread_spheres(int n, double side, double r_min, double r_max, std::uint64_t seed) {
  Random random{seed};
  std::vector<Sphere> out;
  for (int i = 0; i < n; ++i) {
    const Vec3 c(random.uniform(0, side), random.uniform(0, side), random.uniform(0, side));
    out.push_back({c, random.uniform(r_min, r_max)});
  }
  return out;
}

}  // namespace labkit::gen
