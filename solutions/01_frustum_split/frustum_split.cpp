// Lab 01 reference: view-frustum clipping by triangle splitting.
//
// The one idea that makes it robust, as in lab 02: decide with signs, then construct.
// A corner of the clipped polygon is never classified by its rounded position. It is
// kept as what defines it (a vertex, an edge cut by a plane, or the point where two
// planes cross the triangle), and its side of another plane is the sign of a small
// expression in the vertices' plane values, which come from the input alone: on
// small-integer input every sign is exact. Positions and colours are built at the end.
#include "frustum_split.h"

#include "common/preconditions.h"

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace labkit::lab01 {

namespace {

// ---- Preconditions (the header's) ------------------------------------------------------
// Invalid input is named, never answered: a NaN has no side, and a zero normal no plane.

using namespace preconditions;

// A plane needs a direction: a zero normal has no side.
void require_plane(const Plane& p, const char* query, const std::string& name) {
  require_finite(query, name + ".normal", p.normal);
  require_finite(query, name + ".offset", p.offset);
  require(p.normal != Vec3::Zero(), query, name + ".normal", "be non-zero", p.normal);
}
void require_frustum(const Frustum& f, const char* query) {
  static const char* names[6] = {"left", "right", "bottom", "top", "near", "far"};
  for (int k = 0; k < 6; ++k)
    require_plane(f.planes[std::size_t(k)], query, "frustum.planes[" + std::to_string(k) + "] (" + names[k] + ")");
}

// mutant magic_epsilon (step 1, "exact sign", "magic epsilon"):
//   `0 ? Side::in : (value < 0`
//   -> `1e-9 ? Side::in : (value < -1e-9`
Side side_of(double value) { return value > 0 ? Side::in : (value < 0 ? Side::out : Side::on); }

//   Derivation. A point x of the triangle's plane has homogeneous barycentric weights
//   w = (w0, w1, w2): x = (w0 v0 + w1 v1 + w2 v2) / (w0 + w1 + w2). A plane's value is
//   affine in x, so with d = (value(v0), value(v1), value(v2)) its value at x is
//   (w . d) / (w0 + w1 + w2). The corners of the clipped polygon have weights made of
//   the d's of the planes that define them:
//
//     vertex i                              w = e_i
//     edge a -> b cut by plane k            w = d^k_a e_b - d^k_b e_a
//     planes k and l crossing the triangle  w = d^k x d^l
//
//   The edge cut is the lecture's point: a + t (b - a) with t = d_a / (d_a - d_b) is
//   (-d_b a + d_a b) / (d_a - d_b). Where k and l cross, w . d^k = w . d^l = 0 (a cross
//   product is perpendicular to both factors), so the point is on both planes.
//   Its side of plane m is the sign of w . d^m: a sum of products of two d's (edge cut)
//   or a 3x3 determinant of d's (two planes), never a rounded point.
struct Corner {
  Vec3 w = Vec3::Zero();  // homogeneous barycentric weights, oriented so w0 + w1 + w2 > 0
  int vertex = -1;        // 0, 1 or 2 when the corner is that vertex of the triangle
  unsigned edges = 0;     // bit e: it lies on the edge from vertex e to vertex e + 1
  unsigned planes = 0;    // bit k: it lies on plane k
};

// A convex polygon clipped by one plane gains at most one corner: at most 3 + 6 = 9
// for the frustum. The spare room is for corners within rounding of a plane on general
// input, whose signs need not agree with a convex polygon's.
struct Polygon {
  static constexpr int capacity = 16;
  std::array<Corner, capacity> corner;
  int size = 0;

  void add(const Corner& c) {
    if (size < capacity) corner[std::size_t(size++)] = c;
  }
};

Corner oriented(Corner c) {
  if (c.w.sum() < 0) c.w = -c.w;
  return c;
}

// The corner where plane m cuts the side p -> q (their signs at m are strictly
// opposite). The side lies on an edge of the triangle or along an earlier plane, and
// the new corner is that edge's or that plane's crossing with m.
Corner cut(const Corner& p, const Corner& q, int m, const std::array<Vec3, 6>& d) {
  Corner c;
  c.planes = 1u << m;
  if (const unsigned common = p.edges & q.edges) {
    const int a = common & 1u ? 0 : (common & 2u ? 1 : 2), b = (a + 1) % 3;
    // mutant cut_t_from_wrong_end (step 2, "cut point", "measured from p"):
    //   `b] = d[std::size_t(m)][a]; c.w[a`
    //   -> `a] = d[std::size_t(m)][a]; c.w[b`
    c.w[b] = d[std::size_t(m)][a];
    c.w[a] = -d[std::size_t(m)][b];
    c.edges = 1u << a;
  } else if (const unsigned common_planes = p.planes & q.planes) {
    int k = 0;
    while (!(common_planes & (1u << k))) ++k;
    c.w = d[std::size_t(k)].cross(d[std::size_t(m)]);
    c.planes |= 1u << k;
  }  // (every side lies on an edge or a plane: the rule never leaves one without)
  return oriented(c);
}

// The corner's point, and any per-vertex attribute, with the corner's weights.
Vec3 blend(const Corner& c, const Vec3& a0, const Vec3& a1, const Vec3& a2) {
  if (c.vertex >= 0) return c.vertex == 0 ? a0 : (c.vertex == 1 ? a1 : a2);
  return (c.w[0] * a0 + c.w[1] * a1 + c.w[2] * a2) / c.w.sum();
}

// Sutherland-Hodgman on closed half-spaces, plane after plane: keep each corner with
// value >= 0, add a cut on each side whose ends are strictly on opposite sides.
Polygon clip_polygon(const Triangle& t, const Plane* planes, int count) {
  std::array<Vec3, 6> d;  // d[k][i]: the value of plane k at vertex i
  Polygon polygon;
  for (int i = 0; i < 3; ++i) {
    Corner c;
    c.w[i] = 1;
    c.vertex = i;
    c.edges = (1u << i) | (1u << ((i + 2) % 3));  // the edges i -> i+1 and i-1 -> i
    polygon.add(c);
  }
  for (int k = 0; k < count; ++k) {
    const Plane& plane = planes[k];
    d[std::size_t(k)] = Vec3(plane.value(t.v0), plane.value(t.v1), plane.value(t.v2));
    // A plane holding the whole triangle keeps all of it (and crosses no side).
    if (d[std::size_t(k)] == Vec3::Zero()) continue;

    Side sides[Polygon::capacity];
    // mutant classify_rounded_points (step 6, "rounded cut point"):
    //   `sides[i] = side_of(polygon.corner[std::size_t(i)].w.dot(d[std::size_t(k)]));`
    //   -> `sides[i] = side_of(plane.value(blend(polygon.corner[std::size_t(i)], t.v0, t.v1, t.v2)));`
    for (int i = 0; i < polygon.size; ++i) sides[i] = side_of(polygon.corner[std::size_t(i)].w.dot(d[std::size_t(k)]));
    Polygon next;
    for (int i = 0; i < polygon.size; ++i) {
      // A step 2 written from the four configurations, and a polygon loop for step 4 that
      // walks the sides i -> i + 1 only: the closing side is cut by the first plane alone.
      // mutant closing_side_not_cut (step 4, "closing side"):
      //   `(i + 1) % polygon.size`
      //   -> `k == 0 || i + 1 < polygon.size ? (i + 1) % polygon.size : i`
      const int j = (i + 1) % polygon.size;
      Corner p = polygon.corner[std::size_t(i)];
      if (sides[i] == Side::on) p.planes |= 1u << k;  // the polygon may now have a side along plane k
      // mutant strict_keep (step 2, "closed", "value 0 is in"): `!= Side::out` -> `== Side::in`
      if (sides[i] != Side::out) next.add(p);
      if ((sides[i] == Side::in && sides[j] == Side::out) || (sides[i] == Side::out && sides[j] == Side::in)) {
        const Corner c = cut(p, polygon.corner[std::size_t(j)], k, d);
        if (c.w.sum() > 0) next.add(c);  // zero only by rounding, for lines that (nearly) never meet
      }
    }
    // A point or a segment has no area left to cut.
    if (next.size < 3) return {};
    polygon = next;
  }
  return polygon;
}

// A convex polygon as a fan from its first corner: m corners, m - 2 triangles, each
// turning the way the polygon turns, which is the way the input triangle turns.
std::vector<Triangle> fan(const Polygon& polygon, const Triangle& t) {
  std::vector<Triangle> out;
  if (polygon.size < 3) return out;
  const auto point = [&](int i) { return blend(polygon.corner[std::size_t(i)], t.v0, t.v1, t.v2); };
  const Vec3 first = point(0);
  Vec3 previous = point(1);
  for (int i = 2; i < polygon.size; ++i) {
    const Vec3 current = point(i);
    // mutant winding_lost (step 2, "wind like the input"): `previous, current` -> `current, previous`
    out.push_back({first, previous, current});
    previous = current;
  }
  return out;
}

}  // namespace

double signed_distance(const Plane& plane, const Vec3& x) {
  require_plane(plane, "signed_distance", "plane");
  require_finite("signed_distance", "x", x);
  // mutant distance_not_normalized (step 1, "divide by |n|"):
  //   `return plane.value(x) / plane.normal.norm();`
  //   -> `return plane.value(x);`
  return plane.value(x) / plane.normal.norm();
}

std::array<Side, 3> classify(const Plane& plane, const Triangle& triangle) {
  require_plane(plane, "classify", "plane");
  require_valid("classify", "triangle", triangle);
  return {side_of(plane.value(triangle.v0)), side_of(plane.value(triangle.v1)), side_of(plane.value(triangle.v2))};
}

std::vector<Triangle> split_triangle(const Triangle& triangle, const Plane& plane) {
  require_valid("split_triangle", "triangle", triangle);
  require_plane(plane, "split_triangle", "plane");
  return fan(clip_polygon(triangle, &plane, 1), triangle);
}

//   Derivation. With f, r, u the camera's unit forward, right and up, the view at depth
//   z reaches ty z above and below the axis (ty = tan(fov_y / 2)) and tx z = aspect ty z
//   to either side. The left plane holds u and the left edge's direction f - tx r; the
//   vector r + tx f is perpendicular to both and points in (its f part is positive), so
//   the left plane is (r + tx f) / |...| through the eye. The others alike; near and far
//   are f and -f through eye + near f and eye + far f.
Frustum frustum_from_camera(const Camera& camera) {
  const char* q = "frustum_from_camera";
  require_finite(q, "camera.eye", camera.eye);
  require_finite(q, "camera.forward", camera.forward);
  require_finite(q, "camera.up", camera.up);
  require(camera.forward != Vec3::Zero(), q, "camera.forward", "be non-zero", camera.forward);
  require(camera.up != Vec3::Zero(), q, "camera.up", "be non-zero", camera.up);
  require(camera.forward.normalized().cross(camera.up.normalized()) != Vec3::Zero(), q, "camera.up",
          "not be parallel to camera.forward", "up " + text(camera.up) + " and forward " + text(camera.forward));
  require(camera.fov_y > 0 && camera.fov_y < M_PI, q, "camera.fov_y", "be in (0, pi)", camera.fov_y);
  require_positive(q, "camera.aspect", camera.aspect);
  require(camera.near > 0, q, "camera.near", "be > 0", camera.near);
  if (!(camera.far > camera.near && std::isfinite(camera.far)))
    reject(q, "camera.far", "be finite and > near = " + text(camera.near), text(camera.far));
  const Vec3 f = camera.forward.normalized();
  const Vec3 r = f.cross(camera.up).normalized();
  const Vec3 u = r.cross(f);
  // mutant full_angle_tangent (step 3, "full angle", "fov_y / 2"):
  //   `const double ty = std::tan(camera.fov_y / 2);`
  //   -> `const double ty = std::tan(camera.fov_y);`
  const double ty = std::tan(camera.fov_y / 2);
  const double tx = camera.aspect * ty;
  const auto through = [](const Vec3& normal, const Vec3& point) {
    // mutant outward_normals (step 3, "point into the frustum"):
    //   `n = normal.normalized()`
    //   -> `n = -normal.normalized()`
    const Vec3 n = normal.normalized();
    return Plane{n, -n.dot(point)};
  };
  Frustum frustum;
  frustum.planes[Frustum::left] = through(r + tx * f, camera.eye);
  frustum.planes[Frustum::right] = through(-r + tx * f, camera.eye);
  frustum.planes[Frustum::bottom] = through(u + ty * f, camera.eye);
  frustum.planes[Frustum::top] = through(-u + ty * f, camera.eye);
  frustum.planes[Frustum::near] = through(f, camera.eye + camera.near * f);
  frustum.planes[Frustum::far] = through(-f, camera.eye + camera.far * f);
  return frustum;
}

//   Derivation (Gribb and Hartmann). With (x, y, z, w) = M (p, 1), the point p is seen
//   when -w <= x, that is (r3 + r0) . (p, 1) >= 0: a plane whose coefficients are the
//   sum of rows 3 and 0. Each of the six inequalities gives one plane this way.
Frustum frustum_from_matrix(const Mat4& view_projection) {
  require(view_projection.allFinite(), "frustum_from_matrix", "view_projection", "be finite", "a NaN or an infinity");
  static const char* names[6] = {"left r3 + r0", "right r3 - r0", "bottom r3 + r1",
                                 "top r3 - r1",  "near r3 + r2",  "far r3 - r2"};
  const auto plane = [&](int row, double sign) {
    // mutant columns_not_rows (step 3, "rows"):
    //   `(view_projection.row(3) + sign * view_projection.row(row)).transpose()`
    //   -> `view_projection.col(3) + sign * view_projection.col(row)`
    const Vec4 c = (view_projection.row(3) + sign * view_projection.row(row)).transpose();
    const double length = c.head<3>().norm();
    require(length > 0, "frustum_from_matrix",
            std::string("view_projection: the ") + names[2 * row + (sign < 0)] + " plane's normal (a, b, c)",
            "be non-zero", Vec3(c.head<3>()));
    // mutant matrix_planes_not_normalized (step 3, "unit length"): `/ length, c[3] / length` -> `, c[3]`
    return Plane{c.head<3>() / length, c[3] / length};
  };
  Frustum frustum;
  frustum.planes[Frustum::left] = plane(0, 1);
  frustum.planes[Frustum::right] = plane(0, -1);
  frustum.planes[Frustum::bottom] = plane(1, 1);
  frustum.planes[Frustum::top] = plane(1, -1);
  frustum.planes[Frustum::near] = plane(2, 1);
  frustum.planes[Frustum::far] = plane(2, -1);
  return frustum;
}

std::vector<Triangle> clip_triangle(const Triangle& triangle, const Frustum& frustum) {
  require_valid("clip_triangle", "triangle", triangle);
  require_frustum(frustum, "clip_triangle");
  // mutant side_planes_only (step 4, "all six planes"): `data(), 6` -> `data(), 4`
  return fan(clip_polygon(triangle, frustum.planes.data(), 6), triangle);
}

// Vertices of the input stay where they are (pieces use them by their index); each cut
// point is a new vertex, its colour blended with the same weights as its position.
ClippedMesh clip_mesh(const ColoredMesh& in, const Frustum& frustum) {
  const char* q = "clip_mesh";
  const std::size_t n = in.mesh.vertices.size();
  require(in.colors.size() == n, q, "mesh.colors", "have one colour per vertex",
          std::to_string(in.colors.size()) + " colours for " + std::to_string(n) + " vertices");
  for (std::size_t i = 0; i < n; ++i) {
    if (in.mesh.vertices[i].allFinite() && in.colors[i].allFinite()) continue;  // names built only to reject
    require_finite(q, "mesh.mesh.vertices[" + std::to_string(i) + "]", in.mesh.vertices[i]);
    require_finite(q, "mesh.colors[" + std::to_string(i) + "]", in.colors[i]);
  }
  for (std::size_t k = 0; k < in.mesh.size(); ++k)
    for (int i : in.mesh.triangles[k])
      if (!(i >= 0 && std::size_t(i) < n))
        reject(q, "mesh.mesh.triangles[" + std::to_string(k) + "]", "index the vertices (0 to vertices.size() - 1)",
               text(i));
  require_frustum(frustum, q);
  ClippedMesh out;
  out.mesh.vertices = in.mesh.vertices;
  out.colors = in.colors;
  for (std::size_t k = 0; k < in.mesh.size(); ++k) {
    const std::array<int, 3>& face = in.mesh.triangles[k];
    const Triangle t = in.mesh.triangle(k);
    const Polygon polygon = clip_polygon(t, frustum.planes.data(), 6);
    int index[Polygon::capacity];
    for (int i = 0; i < polygon.size; ++i) {
      const Corner& c = polygon.corner[std::size_t(i)];
      if (c.vertex >= 0) {
        index[i] = face[std::size_t(c.vertex)];
        continue;
      }
      index[i] = int(out.mesh.vertices.size());
      out.mesh.vertices.push_back(blend(c, t.v0, t.v1, t.v2));
      // mutant colour_from_wrong_vertices (step 5, "same t", "same vertices"):
      //   `out.colors.push_back( blend(c, in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])],
      //     in.colors[std::size_t(face[2])]));`
      //   -> `out.colors.push_back(blend(c, in.colors[std::size_t(face[1])], in.colors[std::size_t(face[2])],
      //     in.colors[std::size_t(face[0])]));`
      // c_b + t (c_a - c_b): the colour's t measured from the other end of the edge.
      // mutant colour_t_from_wrong_end (step 5, "same t", "other end"):
      //   `out.colors.push_back( blend(c, in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])],
      //     in.colors[std::size_t(face[2])]));`
      //   -> `Corner mirrored = c; if (c.edges) { const int a = c.edges & 1u ? 0 : (c.edges & 2u ? 1 : 2);
      //     std::swap(mirrored.w[a], mirrored.w[(a + 1) % 3]); } out.colors.push_back(blend(mirrored,
      //     in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])], in.colors[std::size_t(face[2])]));`
      // mutant new_vertex_without_colour (step 5, "every vertex needs a colour"):
      //   `out.colors.push_back( blend(c, in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])],
      //     in.colors[std::size_t(face[2])]));`
      //   -> ``
      out.colors.push_back(
          blend(c, in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])], in.colors[std::size_t(face[2])]));
    }
    for (int i = 2; i < polygon.size; ++i) {
      out.mesh.triangles.push_back({index[0], index[i - 1], index[i]});
      out.source.push_back(int(k));
    }
  }
  return out;
}

}  // namespace labkit::lab01
