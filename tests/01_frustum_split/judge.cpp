// Lab 01's judge, the planes: signed distances, classification, and the frustum's six
// planes from a camera or a matrix (the pieces of a clipped triangle: judge.pieces.cpp).
#include "01_frustum_split/judge.h"
#include "01_frustum_split/judge_internal.h"

#include "common/oracle/oracle.h"

#include <cmath>

namespace labkit::lab01 {

std::string describe(Side s) { return s == Side::in ? "in" : (s == Side::out ? "out" : "on"); }

CameraParameters parameters_of(const Camera& c) { return {c.eye, c.forward, c.up, c.fov_y, c.aspect, c.near, c.far}; }

namespace judge {

namespace {

using check::ambiguous;
using check::fail;
using check::pass;

// Long double plane value, for corners.
long double value_at(const Plane& p, const Vec3& x) { return widen(p.normal).dot(widen(x)) + p.offset; }

}  // namespace

Outcome signed_distance(const TrianglePlane& in, const std::array<double, 3>& got) {
  const double tol = kRelative * scale_of_input({in.triangle.v0, in.triangle.v1, in.triangle.v2}, {in.plane});
  const double length = in.plane.normal.norm();
  for (int i = 0; i < 3; ++i) {
    const double exact = oracle::signed_distance(in.plane, in.triangle[i]), g = got[std::size_t(i)];
    if (std::abs(g - exact) <= tol) continue;
    const std::string v = "v" + std::to_string(i);
    std::string hint;
    if (std::abs(length - 1) > 1e-6 && std::abs(g - exact * length) <= tol * length)
      hint = ": yours is |n| = " + fmt(length) + " times it, the plane's value: divide by |n|";
    else if (std::abs(g + exact) <= tol)
      hint = ": yours has the other sign; the distance is positive on the side n points to";
    return fail("distance of " + v + " = " + fmt(exact), "distance of " + v + " = " + fmt(g),
                "the signed distance is (n . x + offset) / |n|: for " + v + " it is " + fmt(exact) + ", not " + fmt(g) +
                    " (tolerance " + fmt(tol) + ")" + hint);
  }
  return pass();
}

Outcome classify(const TrianglePlane& in, const std::array<Side, 3>& got, Rules rules) {
  const double tol = kRelative * scale_of_input({in.triangle.v0, in.triangle.v1, in.triangle.v2}, {in.plane});
  std::array<Side, 3> expected{};
  bool doubt = false;
  for (int i = 0; i < 3; ++i) {
    expected[std::size_t(i)] = Side(oracle::side(in.plane, in.triangle[i]));
    doubt = doubt || (rules == Rules::random && oracle::within(in.triangle[i], in.plane, kMargin * tol));
  }
  for (int i = 0; i < 3; ++i) {
    const Side e = expected[std::size_t(i)], g = got[std::size_t(i)];
    if (g == e || (rules == Rules::random && oracle::within(in.triangle[i], in.plane, kMargin * tol))) continue;
    const double distance = oracle::signed_distance(in.plane, in.triangle[i]);
    return fail(
        labkit::describe(expected), labkit::describe(got),
        "a vertex's class is the exact sign of its value, with no tolerance: v" + std::to_string(i) + " is " +
            fmt(distance) + " from the plane (value " + (e == Side::on ? "0" : (e == Side::in ? "> 0" : "< 0")) +
            "), so it is " + describe(e) + ", not " + describe(g) + (g == Side::on ? " (a magic epsilon?)" : "") +
            (rules == Rules::exact ? "" : "; it is more than 8 tol = " + fmt(kMargin * tol) + " from the plane"));
  }
  return doubt ? ambiguous() : pass();
}

// Are the side planes those of tan(fov_y) instead of tan(fov_y / 2)?
bool full_angle(const Camera& c, const Frustum& got) {
  const Vec3 f = c.forward.normalized(), r = f.cross(c.up).normalized(), u = r.cross(f);
  const double ty = std::tan(c.fov_y), tx = c.aspect * ty;
  const Vec3 wrong[4] = {r + tx * f, -r + tx * f, u + ty * f, -u + ty * f};
  for (int i = 0; i < 4; ++i)
    if (!((got.planes[std::size_t(i)].normal - wrong[i].normalized()).norm() <= 1e-6)) return false;
  return true;
}

Outcome frustum_from_camera(const Camera& in, const Frustum& got) {
  const CameraParameters c = parameters_of(in);
  const std::array<Vec3, 8> corners = frustum_corners(c);
  double S = scale_of({in.eye});
  for (const Vec3& k : corners) S = std::max(S, scale_of({k}));
  const double tol = kRelative * S;
  const Frustum expected = frustum_of(c);
  const Vec3 center = in.eye + in.forward.normalized() * ((in.near + in.far) / 2);
  static const char* names[6] = {"left", "right", "bottom", "top", "near", "far"};
  // The corners on each plane: bit 0 of a corner's index is right, bit 1 top, bit 2 far.
  static const int bit[6] = {0, 0, 1, 1, 2, 2}, set[6] = {0, 1, 0, 1, 0, 1};
  for (int i = 0; i < 6; ++i) {
    const Plane& p = got.planes[std::size_t(i)];
    const std::string name = names[i];
    const std::string want = describe(expected.planes[std::size_t(i)]), have = describe(p);
    if (!(std::abs(p.normal.norm() - 1) <= kRelative))
      return fail(
          name + ": " + want, name + ": " + have,
          "every plane built must have a unit normal: the " + name + " plane's has length " + fmt(p.normal.norm()));
    if (!(value_at(p, center) > tol))
      return fail(name + ": " + want, name + ": " + have,
                  "every normal must point into the frustum: the " + name +
                      " plane's points out, the frustum's centre eye + forward (near + far) / 2 is behind it (value " +
                      fmt(double(value_at(p, center))) + ")");
    for (int k = 0; k < 8; ++k) {
      if (((k >> bit[i]) & 1) != set[i]) continue;
      const long double v = value_at(p, corners[std::size_t(k)]);
      if (!(std::abs(v) <= tol))
        return fail(
            name + ": " + want, name + ": " + have,
            "each plane passes through its four corners of the frustum: the corner " + fmt(corners[std::size_t(k)]) +
                " is " + fmt(double(v)) + " from the " + name + " plane (tolerance " + fmt(tol) + ")" +
                (i < 4 && full_angle(in, got) ? "; these side planes open by tan(fov_y), and fov_y is the full angle: "
                                                "use tan(fov_y / 2)"
                                              : ""));
    }
  }
  return pass();
}

Outcome frustum_from_matrix(const Mat4& in, const Frustum& got) {
  const std::array<Plane, 6> exact = oracle::frustum_planes(in);
  const double a = in.leftCols<3>().cwiseAbs().maxCoeff(), b = in.col(3).cwiseAbs().maxCoeff();
  static const char* names[6] = {"left", "right", "bottom", "top", "near", "far"};
  for (int i = 0; i < 6; ++i) {
    const Plane& p = got.planes[std::size_t(i)];
    const Plane& e = exact[std::size_t(i)];
    const Vec4 raw = (in.row(3) + (i % 2 == 0 ? 1.0 : -1.0) * in.row(i / 2)).transpose();
    const double length = raw.head<3>().norm();
    if (!(length > 0)) continue;  // no plane to compare with
    const double normal_tol = kRelative * a / length;
    const double offset_tol = kRelative * (b + a * std::abs(raw[3]) / length) / length;
    const std::string name = names[i], want = name + ": " + describe(e), have = name + ": " + describe(p);
    static const char* rows[6] = {"r3 + r0", "r3 - r0", "r3 + r1", "r3 - r1", "r3 + r2", "r3 - r2"};
    if (!(std::abs(p.normal.norm() - 1) <= kRelative))
      return fail(want, have,
                  "each plane (a, b, c, d) must be divided by |(a, b, c)| so that its normal has unit length: the " +
                      name + " plane's has length " + fmt(p.normal.norm()));
    const double off = (p.normal - e.normal).norm(), offset_off = std::abs(p.offset - e.offset);
    if (off <= normal_tol && offset_off <= offset_tol) continue;
    const Plane columns = oracle::frustum_planes(in.transpose())[std::size_t(i)];
    const bool transposed = (p.normal - columns.normal).norm() <= 1e-6 &&
                            std::abs(p.offset - columns.offset) <= 1e-6 * (1 + std::abs(columns.offset));
    return fail(want, have,
                "the " + name + " plane is the rows' combination " + rows[i] + " over |(a, b, c)|: normal " +
                    fmt(e.normal) + ", offset " + fmt(e.offset) + "; yours is off by " + fmt(off) + " and " +
                    fmt(offset_off) + " (tolerances " + fmt(normal_tol) + ", " + fmt(offset_tol) + ")" +
                    (transposed ? ": yours combines the columns; the planes come from the rows of M, as points are "
                                  "columns multiplied on the right, M (p, 1)"
                                : ""));
  }
  return pass();
}

}  // namespace judge
}  // namespace labkit::lab01
