#include "06_spatial_trees/judge.h"

#include "common/generators/generators.h"

#include <algorithm>
#include <cmath>

namespace labkit::gen {

rc::Gen<lab06::TreeQuery> tree_query() {
  return rc::gen::exec([] {
    lab06::TreeQuery q;
    q.mesh = *any_mesh();  // lab 02's soups, terrains and octahedra among others
    q.segment = *segment_near(q.mesh);
    q.tree = *rc::gen::inRange(0, 1000000);
    return q;
  });
}

rc::Gen<lab06::TreeQuery> exact_tree_query() {
  return rc::gen::exec([] {
    lab06::TreeQuery q;
    q.mesh = *exact_mesh();
    q.segment = *exact_segment_near(q.mesh);
    q.tree = *rc::gen::inRange(0, 1000000);
    return q;
  });
}

rc::Gen<Mesh> bsp_mesh() { return any_mesh(); }

namespace {
// A mesh drawn from `meshes`, then a point near it (on the exact lattice or not).
rc::Gen<lab06::PointQuery> point_near_mesh(rc::Gen<Mesh> meshes, bool exact) {
  return rc::gen::exec([meshes, exact] {
    const Mesh m = *meshes;
    return lab06::PointQuery{m, *point_near(m, exact)};
  });
}
}  // namespace

rc::Gen<lab06::PointQuery> point_query() { return point_near_mesh(closed_mesh(), false); }
rc::Gen<lab06::PointQuery> exact_point_query() { return point_near_mesh(exact_closed_mesh(), true); }
rc::Gen<lab06::PointQuery> eye_query() { return point_near_mesh(any_mesh(), false); }
rc::Gen<lab06::PointQuery> exact_eye_query() {
  return point_near_mesh(rc::gen::oneOf(exact_mesh(), exact_closed_mesh()), true);
}

rc::Gen<lab06::SphereSet> sphere_set_case() {
  return rc::gen::map(sphere_set(), [](std::vector<Sphere> s) { return lab06::SphereSet{std::move(s)}; });
}
rc::Gen<lab06::SphereSet> exact_sphere_set_case() {
  return rc::gen::map(exact_sphere_set(), [](std::vector<Sphere> s) { return lab06::SphereSet{std::move(s)}; });
}

// Step 6: a set of spheres (step 5's kinds), then frames in which every centre moves a
// little: up to a few hundredths of the set's scale, so the order of ends changes in a
// few places per frame. Radii stay.
rc::Gen<lab06::SweepCase> sweep_case() {
  return rc::gen::exec([] {
    lab06::SweepCase c;
    c.frames.push_back(*sphere_set());
    double s = 0;
    for (const Sphere& b : c.frames[0]) s = std::max({s, b.center.cwiseAbs().maxCoeff(), b.radius});
    if (s == 0) s = 1;
    const int frames = *rc::gen::inRange(2, 7);
    for (int k = 1; k < frames; ++k) {
      std::vector<Sphere> next = c.frames.back();
      for (Sphere& b : next)
        for (int i = 0; i < 3; ++i) b.center[i] += s * *rc::gen::inRange(-1024, 1024) / 32768.0;
      c.frames.push_back(next);
    }
    return c;
  });
}

// Exact: step 5's exact spheres (touching chains on integers), moved by whole units
// of their scale along x and y, so ends meet and pass exactly, and balls come to touch.
rc::Gen<lab06::SweepCase> exact_sweep_case() {
  return rc::gen::exec([] {
    lab06::SweepCase c;
    c.frames.push_back(*exact_sphere_set());
    double unit = 0;
    for (const Sphere& b : c.frames[0]) unit = std::max(unit, b.radius);
    if (unit == 0) unit = 1;
    const int frames = *rc::gen::inRange(2, 6);
    for (int k = 1; k < frames; ++k) {
      std::vector<Sphere> next = c.frames.back();
      for (Sphere& b : next)
        b.center.x() += unit * *rc::gen::inRange(-1, 2), b.center.y() += unit * *rc::gen::inRange(-1, 2);
      c.frames.push_back(next);
    }
    return c;
  });
}

// Step 7: two small meshes (soups, spheres, terrains) placed so that they overlap in part,
// the checker's trees over them, every pair or one.
rc::Gen<lab06::BvhQuery> bvh_query() {
  return rc::gen::exec([] {
    lab06::BvhQuery q;
    const auto small = [] {
      const int kind = *rc::gen::inRange(0, 3);
      const int n = *rc::gen::inRange(1, 40);
      const std::uint64_t seed = std::uint64_t(*rc::gen::inRange(1, 1 << 20));
      if (kind == 0) return soup_mesh(n, seed);
      if (kind == 1) return terrain_mesh(std::max(n, 2), seed);
      return sphere_mesh(std::max(n, 8), Vec3(0.5, 0.5, 0.5), 0.4);
    };
    q.a = small(), q.b = small();
    const double scale = std::pow(2.0, *rc::gen::inRange(-20, 21));
    const Vec3 shift(*rc::gen::inRange(-8, 9) / 16.0, *rc::gen::inRange(-8, 9) / 16.0, *rc::gen::inRange(-8, 9) / 16.0);
    for (Vec3& v : q.a.vertices) v *= scale;
    for (Vec3& v : q.b.vertices) v = (v + shift) * scale;
    q.tree_a = *rc::gen::inRange(0, 100), q.tree_b = *rc::gen::inRange(0, 100);
    q.every = *rc::gen::inRange(0, 4) != 0;
    return q;
  });
}

}  // namespace labkit::gen

namespace labkit::gen {

namespace {

// The smallest power of two >= x (x > 0).
double power_of_two_at_least(double x) {
  int e = 0;
  const double m = std::frexp(x, &e);  // x = m 2^e, m in [0.5, 1)
  return m == 0.5 ? x : std::ldexp(1.0, e);
}

}  // namespace

// Step 11. Half the cases are sparse worlds: up to five clusters of step 10's exact
// spheres (touching chains on integers), each moved by whole multiples of 2^30 to 2^40
// of its unit, so that a dense grid could never be allocated and a cell's coordinates
// pass 2^31. Within a cluster every number is an integer times the unit, far below 2^53:
// given_balls_meet is exact there and the case is judged exactly. The other half are
// step 5's sets (judged with the ambiguity rule). The cell is the smallest power of two
// holding the largest diameter, or 2 or 4 times that, and never so small that a centre's
// cell coordinate passes the header's 2^60; the buckets from 1 (every cell in one bucket)
// to thousands.
rc::Gen<lab06::HashCase> hash_case() {
  return rc::gen::exec([] {
    lab06::HashCase c;
    c.exact = *rc::gen::inRange(0, 2) == 0;
    if (c.exact) {
      const int clusters = *rc::gen::inRange(1, 6);
      const double far = std::ldexp(1.0, *rc::gen::inRange(30, 41));
      for (int k = 0; k < clusters; ++k) {
        std::vector<Sphere> cluster = *exact_sphere_set();
        double unit = 0;
        for (const Sphere& s : cluster) unit = std::max({unit, s.radius, s.center.cwiseAbs().maxCoeff()});
        if (unit == 0) unit = 1;
        unit = power_of_two_at_least(unit);
        const Vec3 offset =
            far * unit * Vec3(*rc::gen::inRange(-8, 9), *rc::gen::inRange(-8, 9), *rc::gen::inRange(-8, 9));
        for (Sphere& s : cluster) c.spheres.push_back({s.center + offset, s.radius});
      }
    } else {
      c.spheres = *sphere_set();
    }
    double r_max = 0, reach = 0;
    for (const Sphere& s : c.spheres)
      r_max = std::max(r_max, s.radius), reach = std::max(reach, s.center.cwiseAbs().maxCoeff());
    c.cell = r_max > 0 ? power_of_two_at_least(2 * r_max) : power_of_two_at_least(std::max(reach, 1.0) / 64);
    c.cell *= *rc::gen::element(1.0, 1.0, 2.0, 4.0);
    // The header's bound, |coordinate| / cell <= 2^60: a cluster far out and a tiny ball
    // elsewhere would break it. A larger cell (still a power of two >= 2 r_max) keeps it.
    while (reach / c.cell > std::ldexp(1.0, 60)) c.cell *= 2;
    c.buckets = *rc::gen::element(1, 2, 3, 7, 64, 1021, 4096);
    return c;
  });
}

}  // namespace labkit::gen

namespace labkit::gen {

// Step 12. Two cases in three: 1 to 3 clusters of balls, each within a unit of its
// centre, the centres spread over 128 units, so the tree cuts deep around the clusters
// and leaves the space between them whole; the query box near some ball. One in three:
// balls and a box on integers, where balls touch each other, the cuts and the box
// exactly (judged exactly).
rc::Gen<lab06::OctreeCase> octree_case() {
  return rc::gen::exec([] {
    lab06::OctreeCase c;
    const double s = *scale();
    c.exact = *rc::gen::inRange(0, 3) == 0;
    c.capacity = *rc::gen::element(1, 2, 4, 8);
    c.max_depth = *rc::gen::inRange(0, 7);
    if (c.exact) {
      // Radii 0 or 1 on a lattice of 17^3 points: a ball's box spans few of the deepest
      // cells, so the tree stays small (an answer crosses the process boundary).
      const int n = *rc::gen::inRange(0, 40);
      for (int i = 0; i < n; ++i) c.spheres.push_back({*lattice_point(s, 8), s * *rc::gen::inRange(0, 2)});
      c.max_depth = std::min(c.max_depth, 4);
      const Vec3 a = *lattice_point(s, 10), b = *lattice_point(s, 10);
      c.box = {a.cwiseMin(b), a.cwiseMax(b)};
      return c;
    }
    const int clusters = *rc::gen::inRange(1, 4);
    for (int k = 0; k < clusters; ++k) {
      const Vec3 centre = *point(s * 4);
      const int n = *rc::gen::inRange(1, 25);
      for (int i = 0; i < n; ++i)
        c.spheres.push_back({centre + *point(s / 16), s * *rc::gen::inRange(0, 1 << 20) / double(1 << 23)});
    }
    const Vec3 near = c.spheres[std::size_t(*rc::gen::inRange(0, int(c.spheres.size())))].center + *point(s / 16);
    Vec3 half;
    for (int i = 0; i < 3; ++i) half[i] = s * *rc::gen::inRange(0, 1 << 20) / double(1 << 19);
    c.box = {near - half, near + half};
    return c;
  });
}

}  // namespace labkit::gen
