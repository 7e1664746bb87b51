// Lab 01's judge, the pieces: a triangle split by a plane or clipped to a frustum, and a
// clipped mesh with its colours, all held to the header's "Pieces" rules.
#include "01_frustum_split/judge.h"
#include "01_frustum_split/judge_internal.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab01::judge {

namespace {

using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;

std::vector<Plane> planes_of(const Frustum& f) { return {f.planes.begin(), f.planes.end()}; }

double longest_edge(const Triangle& t) {
  return std::max({(t.v1 - t.v0).norm(), (t.v2 - t.v1).norm(), (t.v0 - t.v2).norm()});
}

std::string count_of(std::size_t n, const std::string& what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

std::string describe_pieces(const std::vector<Triangle>& pieces) {
  double area = 0;
  for (const Triangle& p : pieces) area += p.area();
  std::string s = count_of(pieces.size(), "triangle") + ", area " + fmt(area);
  for (std::size_t i = 0; i < pieces.size() && i < 8; ++i) s += "\n    " + describe(pieces[i]);
  return s;
}

std::string describe_polygon(const oracle::ClippedPolygon& p) {
  std::string s = count_of(std::size_t(p.triangles()), "triangle") + ", area " + fmt(p.area) + " (a polygon with " +
                  count_of(p.corners.size(), "corner") + ")";
  for (const Vec3& c : p.corners) s += "\n    " + fmt(c);
  return s;
}

std::vector<Plane> shifted(const std::vector<Plane>& planes, double by) {
  std::vector<Plane> out = planes;
  for (Plane& p : out) p.offset += by * p.normal.norm();
  return out;
}

// Is the triangle clear of the planes by more than 8 tol (wholly inside all of them, or
// wholly outside one)? Then the exact answer is the triangle or nothing, for certain.
enum class Clear { inside, outside, no };
Clear clearance(const Triangle& t, const std::vector<Plane>& planes, double tol) {
  bool inside = true;
  for (const Plane& p : planes) {
    const double margin = 2 * kMargin * tol * p.normal.norm();
    const double a = p.value(t.v0), b = p.value(t.v1), c = p.value(t.v2);
    if (a < -margin && b < -margin && c < -margin) return Clear::outside;
    inside = inside && a > margin && b > margin && c > margin;
  }
  return inside ? Clear::inside : Clear::no;
}

// Certainly within tol of the closed triangle? A double computation, conservative: its
// rounding error (some 1e-16 S) is far below the tol / 2 it is held to. false: ask the
// exact oracle. Corners near an edge (vertices and cut points) and corners well inside a
// triangle that is not thin (where two planes cross it) are settled here.
bool surely_near(const Vec3& p, const Triangle& t, double tol) {
  for (int i = 0; i < 3; ++i) {
    const Vec3& a = t[i];
    const Vec3 d = t[(i + 1) % 3] - a;
    const double length2 = d.squaredNorm();
    const double s = length2 > 0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
    if ((a + s * d - p).norm() <= tol / 2) return true;
  }
  const Vec3 n = t.normal();
  const double n2 = n.squaredNorm(), longest = longest_edge(t);
  if (!(std::sqrt(n2) >= 1e-6 * longest * longest)) return false;
  for (int i = 0; i < 3; ++i)
    if (!((t[(i + 1) % 3] - p).cross(t[(i + 2) % 3] - p).dot(n) / n2 >= 1e-6)) return false;
  return std::abs((p - t.v0).dot(n)) / std::sqrt(n2) <= tol / 2;
}

bool same_triangle(const Triangle& a, const Triangle& b) {
  for (int turn = 0; turn < 3; ++turn)
    if (a.v0 == b[turn] && a.v1 == b[(turn + 1) % 3] && a.v2 == b[(turn + 2) % 3]) return true;
  return false;
}

// Why a count is wrong, when a corner of the exact polygon is missing: a vertex on a
// plane (value 0 is in), or a cut point (a side with strictly opposite signs is cut).
std::string missing_corner(const Triangle& t, const std::vector<Plane>& planes, const std::vector<Triangle>& got,
                           const oracle::ClippedPolygon& exact, double tol) {
  for (const Vec3& c : exact.corners) {
    bool found = false;
    for (const Triangle& p : got)
      for (int j = 0; j < 3; ++j) found = found || (p[j] - c).norm() <= 8 * tol;
    if (found) continue;
    for (int i = 0; i < 3; ++i)
      if (t[i] == c)
        for (const Plane& p : planes)
          if (p.value(c) == 0)
            return ": the corner v" + std::to_string(i) + " = " + fmt(c) +
                   " is missing; its value is 0, and the sets are closed: "
                   "a vertex with value 0 is in, kept";
    return ": the corner " + fmt(c) +
           " is missing; it is where a plane cuts a side whose ends have strictly opposite "
           "signs: every such side is cut, the closing side from the last corner back to the first included";
  }
  return "";
}

// Why an area is wrong, when a corner is neither a vertex of the input nor on a plane.
std::string stray_corner(const Triangle& t, const std::vector<Plane>& planes, const std::vector<Triangle>& got,
                         double tol) {
  for (const Triangle& p : got)
    for (int j = 0; j < 3; ++j) {
      bool explained = p[j] == t.v0 || p[j] == t.v1 || p[j] == t.v2;
      for (const Plane& plane : planes) explained = explained || oracle::within(p[j], plane, tol);
      if (!explained)
        return "; the corner " + fmt(p[j]) +
               " is neither an input vertex nor on a plane: a cut point lies on the "
               "cutting plane, at t = d_p / (d_p - d_q) measured from p";
    }
  return "";
}

// One answer of pieces of one triangle, and what the checks below share.
struct PiecesCase {
  const Triangle& t;
  const std::vector<Plane>& planes;
  const std::vector<Triangle>& got;
  Rules rules;
  double tol, area_tol;
  bool flat;
  oracle::ClippedPolygon exact;
};

// Where the corners are: in every plane, and in the input triangle ("" when so).
std::string corners_problem(const PiecesCase& c) {
  static const char* plane_names[6] = {"left", "right", "bottom", "top", "near", "far"};
  for (std::size_t i = 0; i < c.got.size(); ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3& p = c.got[i][j];
      for (std::size_t k = 0; k < c.planes.size(); ++k)
        if (!oracle::inside_all(p, {c.planes[k]}, c.tol))
          return "the pieces must lie in every plane: corner " + fmt(p) + " of triangle " + std::to_string(i) +
                 " is outside " +
                 (c.planes.size() == 6 ? std::string("the ") + plane_names[k] + " plane" : "the plane") + " by " +
                 fmt(-oracle::signed_distance(c.planes[k], p)) + " (tolerance " + fmt(c.tol) + ")" +
                 (c.planes.size() == 6 && k >= 4 ? ": clip by all six planes, near and far included" : "");
      if (!surely_near(p, c.t, c.tol) && !oracle::within(p, c.t, c.tol))
        return "the pieces must lie in the input triangle: corner " + fmt(p) + " of triangle " + std::to_string(i) +
               " is " + fmt(oracle::distance(p, c.t)) + " from it (tolerance " + fmt(c.tol) + ")";
    }
  return "";
}

// How many pieces: exact, unless a small change of the input could change it (`doubt`).
std::string count_problem(const PiecesCase& c, bool doubt) {
  if (c.flat || int(c.got.size()) == c.exact.triangles() || doubt) return "";
  std::string cause = missing_corner(c.t, c.planes, c.got, c.exact, c.tol);
  if (cause.empty() && c.rules == Rules::exact)
    cause = " (this input is exact: decide every sign from the vertices' plane values, never from a rounded cut point)";
  return (c.exact.has_area ? "triangle ∩ planes has " + count_of(c.exact.corners.size(), "corner") + ", so " +
                                 count_of(std::size_t(c.exact.triangles()), "triangle") +
                                 (c.exact.triangles() == 1 ? " is" : " are") + " expected, not "
                           : std::string("triangle ∩ planes has no area, so no triangle is expected, not ")) +
         std::to_string(c.got.size()) + cause;
}

// How much they cover: the exact area, or (random input) between the areas the planes
// shifted out and in by the margin give.
std::string area_problem(const PiecesCase& c) {
  double area = 0;
  for (const Triangle& p : c.got) area += p.area();
  if (std::abs(area - c.exact.area) <= c.area_tol) return "";
  if (c.rules == Rules::random) {
    const double out = oracle::clip(c.t, shifted(c.planes, kMargin * c.tol)).area;
    const double in = oracle::clip(c.t, shifted(c.planes, -kMargin * c.tol)).area;
    if (area >= in - c.area_tol && area <= out + c.area_tol) return "";
  }
  return "the pieces must cover triangle ∩ planes: their areas sum to " + fmt(area) + ", its area is " +
         fmt(c.exact.area) + " (tolerance " + fmt(c.area_tol) + ")" + stray_corner(c.t, c.planes, c.got, c.tol);
}

// No overlaps, and the input's winding.
std::string layout_problem(const PiecesCase& c) {
  const Vec3 normal = c.t.normal();
  for (std::size_t i = 0; i < c.got.size(); ++i) {
    if (!c.flat && c.got[i].area() > c.area_tol && !(c.got[i].normal().dot(normal) > 0))
      return "every piece must wind like the input, (v1 - v0) x (v2 - v0) pointing the same way: triangle " +
             std::to_string(i) + "'s normal " + fmt(c.got[i].normal()) + " points away from the input's " + fmt(normal);
    for (std::size_t j = 0; j < i; ++j) {
      const double overlap = oracle::overlap_area(c.got[i], c.got[j], c.t);
      if (!(overlap <= c.area_tol))
        return "the pieces must not overlap: triangles " + std::to_string(j) + " and " + std::to_string(i) +
               " overlap by an area of " + fmt(overlap) + " (tolerance " + fmt(c.area_tol) + ")";
    }
  }
  return "";
}

// The checks every answer made of pieces of one triangle must pass: the header's
// "Pieces" rules. S comes from the caller (a mesh's S covers all of its vertices).
Outcome pieces(const Triangle& t, const std::vector<Plane>& planes, const std::vector<Triangle>& got, double S,
               Rules rules) {
  const double tol = kRelative * S;
  for (std::size_t i = 0; i < got.size(); ++i)
    for (int j = 0; j < 3; ++j)
      if (!got[i][j].allFinite())
        return fail("finite corners", describe_pieces(got),
                    "every corner must be a finite point: corner " + fmt(got[i][j]) + " of triangle " +
                        std::to_string(i) + " is not");
  // The usual cases, settled without exact arithmetic.
  const Clear clear = clearance(t, planes, tol);
  if (clear == Clear::inside && got.size() == 1 && same_triangle(got[0], t)) return pass();
  if (clear == Clear::outside && got.empty()) return pass();

  const PiecesCase c{
      t, planes, got, rules, tol, kRelative * S * longest_edge(t), oracle::is_degenerate(t), oracle::clip(t, planes)};
  const std::string expected = describe_polygon(c.exact), answer = describe_pieces(got);
  const bool doubt = rules == Rules::random && !c.flat && oracle::clip_in_doubt(t, planes, tol);
  for (const std::string& why : {corners_problem(c), count_problem(c, doubt)})
    if (!why.empty()) return fail(expected, answer, why);
  for (const auto& check : {area_problem, layout_problem})
    if (const std::string why = check(c); !why.empty()) return fail(expected, answer, why);
  return doubt ? ambiguous() : pass();
}

// The colour that linear interpolation over t gives at x (its projection onto t's
// plane), and how fast a colour component can change across t: long double is far
// below the tolerance 1e-9 (C + G S), whose G S term covers the rounding of x itself.
struct Interpolation {
  bool defined = false;
  Vec3 value = Vec3::Zero();
  double slope = 0;  // G
};

Interpolation interpolate(const Triangle& t, const std::array<Vec3, 3>& colors, const Vec3& x) {
  const Long3 v[3] = {widen(t.v0), widen(t.v1), widen(t.v2)};
  const Long3 n = (v[1] - v[0]).cross(v[2] - v[0]);
  const long double n2 = n.squaredNorm();
  Interpolation out;
  if (oracle::is_degenerate(t) || !(n2 > 0)) return out;
  const Long3 p = widen(x);
  Eigen::Matrix<long double, 3, 1> value = Long3::Zero(), gradient[3] = {Long3::Zero(), Long3::Zero(), Long3::Zero()};
  for (int i = 0; i < 3; ++i) {
    const Long3& a = v[(i + 1) % 3];
    const Long3& b = v[(i + 2) % 3];
    const long double lambda = (a - p).cross(b - p).dot(n) / n2;
    const Long3 grad = n.cross(b - a) / n2;  // the gradient of lambda_i in the plane
    const Long3 c = widen(colors[std::size_t(i)]);
    value += lambda * c;
    for (int k = 0; k < 3; ++k) gradient[k] += c[k] * grad;
  }
  out.defined = true;
  out.value = value.cast<double>();
  for (const Long3& g : gradient) out.slope = std::max(out.slope, double(g.norm()));
  return out;
}

// A likely cause of a wrong colour at x: t measured from the other end of the edge x is
// on, or colours blended from other vertices than the position.
std::string colour_hint(const Triangle& t, const std::array<Vec3, 3>& colors, const Vec3& x, const Vec3& got,
                        double tol) {
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3;
    const Vec3 edge = t[b] - t[a];
    const double s = edge.squaredNorm() > 0 ? (x - t[a]).dot(edge) / edge.squaredNorm() : -1;
    if (s <= 0 || s >= 1 || (t[a] + s * edge - x).norm() > 1e-9 * edge.norm()) continue;
    const Vec3 other_end = colors[std::size_t(b)] + s * (colors[std::size_t(a)] - colors[std::size_t(b)]);
    if ((got - other_end).norm() <= tol)
      return ": it is the colour at t measured from the other end, c_b + t (c_a - c_b) with t = " + fmt(s) + " from a";
  }
  return ": is it blended from the same vertices, with the same weights, as the position?";
}

}  // namespace

Outcome split_triangle(const TrianglePlane& in, const std::vector<Triangle>& got, Rules rules) {
  const std::vector<Plane> planes = {in.plane};
  return pieces(in.triangle, planes, got, scale_of_input({in.triangle.v0, in.triangle.v1, in.triangle.v2}, planes),
                rules);
}

Outcome clip_triangle(const TriangleFrustum& in, const std::vector<Triangle>& got, Rules rules) {
  const std::vector<Plane> planes = planes_of(in.frustum);
  return pieces(in.triangle, planes, got, scale_of_input({in.triangle.v0, in.triangle.v1, in.triangle.v2}, planes),
                rules);
}

Outcome clip_mesh(const MeshFrustum& in, const ClippedMesh& got, Rules rules) {
  const std::vector<Plane> planes = planes_of(in.frustum);
  double S = scale_of(in.mesh);
  S = std::max(S, scale_of_input({}, planes));
  const std::size_t n = got.mesh.vertices.size(), count = got.mesh.size();
  const std::string sizes = std::to_string(n) + " vertices, " + std::to_string(got.colors.size()) + " colours, " +
                            std::to_string(count) + " triangles, " + std::to_string(got.source.size()) + " sources";
  if (got.colors.size() != n)
    return fail("one colour per vertex", sizes,
                "every vertex needs a colour, the new cut points included: " + std::to_string(n) + " vertices, " +
                    count_of(got.colors.size(), "colour"));
  if (got.source.size() != count)
    return fail("one source per triangle", sizes,
                "every triangle needs its source, the input triangle it is a piece of: " + count_of(count, "triangle") +
                    ", " + count_of(got.source.size(), "source"));
  std::vector<std::vector<Triangle>> pieces_of(in.mesh.size());
  std::vector<std::vector<std::size_t>> indices_of(in.mesh.size());
  for (std::size_t k = 0; k < count; ++k) {
    for (int i : got.mesh.triangles[k])
      if (i < 0 || std::size_t(i) >= n)
        return fail("indices into the vertices", "index " + std::to_string(i),
                    "every index must name one of the " + std::to_string(n) + " vertices: triangle " +
                        std::to_string(k) + " has " + std::to_string(i));
    const int s = got.source[k];
    if (s < 0 || std::size_t(s) >= in.mesh.size())
      return fail("an input triangle's index", "source " + std::to_string(s),
                  "every source must name one of the " + std::to_string(in.mesh.size()) +
                      " input triangles: triangle " + std::to_string(k) + " has " + std::to_string(s));
    pieces_of[std::size_t(s)].push_back(got.mesh.triangle(k));
    indices_of[std::size_t(s)].push_back(k);
  }
  bool doubt = false;
  for (std::size_t s = 0; s < in.mesh.size(); ++s) {
    const Triangle t = in.mesh.triangle(s);
    const Outcome o = pieces(t, planes, pieces_of[s], S, rules);
    if (o.verdict == Outcome::Verdict::fail)
      return fail(o.expected, o.got, "input triangle " + std::to_string(s) + ": " + o.why);
    doubt = doubt || o.verdict == Outcome::Verdict::ambiguous;

    // Colours at every corner of its pieces.
    const auto& face = in.mesh.triangles[s];
    const std::array<Vec3, 3> colors = {in.colors[std::size_t(face[0])], in.colors[std::size_t(face[1])],
                                        in.colors[std::size_t(face[2])]};
    const double C =
        std::max({colors[0].cwiseAbs().maxCoeff(), colors[1].cwiseAbs().maxCoeff(), colors[2].cwiseAbs().maxCoeff()});
    for (std::size_t k : indices_of[s])
      for (int i : got.mesh.triangles[k]) {
        const Vec3& x = got.mesh.vertices[std::size_t(i)];
        const Interpolation f = interpolate(t, colors, x);
        if (!f.defined) continue;  // a zero-area triangle has no plane to interpolate over
        const double color_tol = kRelative * (C + f.slope * S);
        const Vec3& c = got.colors[std::size_t(i)];
        if (!((c - f.value).norm() <= color_tol))
          return fail("colour " + fmt(f.value), "colour " + fmt(c),
                      "a cut point's colour is interpolated with the same t as its position: at vertex " +
                          std::to_string(i) + " " + fmt(x) + " of a piece of input triangle " + std::to_string(s) +
                          ", linear interpolation gives " + fmt(f.value) + ", not " + fmt(c) + " (tolerance " +
                          fmt(color_tol) + ")" + colour_hint(t, colors, x, c, color_tol));
      }
  }
  return doubt ? ambiguous() : pass();
}

}  // namespace labkit::lab01::judge
