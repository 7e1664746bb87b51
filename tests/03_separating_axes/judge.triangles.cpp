// Lab 03's judge, the triangles: the interval method and the triangle-triangle test.
#include "03_separating_axes/judge.h"
#include "03_separating_axes/judge_internal.h"

#include "common/oracle/oracle.h"
#include "common/oracle/predicates.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab03::judge {

namespace {

// Longest edge over smallest height: how much of a needle the triangle is.
double aspect(const Triangle& t) {
  const double longest =
      std::max({(t.v1 - t.v0).squaredNorm(), (t.v2 - t.v1).squaredNorm(), (t.v0 - t.v2).squaredNorm()});
  const double n = t.normal().norm();
  return n == 0 ? 0.0 : longest / n;
}

// The largest distance of `of`'s vertices from t's plane, over S (rounded; for hints).
double off_plane(const Triangle& t, const Triangle& of, double size) {
  const Vec3 n = t.normal().normalized();
  double d = 0.0;
  for (int k = 0; k < 3; ++k) d = std::max(d, std::abs((of[k] - t.v0).dot(n)));
  return d / size;
}

bool coplanar(const TrianglePair& in) {
  for (int k = 0; k < 3; ++k)
    if (oracle::orientation(in.t0.v0, in.t0.v1, in.t0.v2, in.t1[k]) != 0) return false;
  return true;
}

std::string why_triangles(const TrianglePair& in, bool expected) {
  const double size = std::max(scale_of(in), 1e-300);
  if (expected) {
    if (coplanar(in))
      return "coplanar triangles intersect when they overlap in their plane, and these do; your answer says they do "
             "not (all volumes d = 0 is coplanar, not \"all on one side\")";
    if (oracle::triangle_pair_in_doubt(in.t0, in.t1, 1e-12 * size))
      return "the triangles touch (at a point or along a segment): closed triangles that touch intersect, and an "
             "interval end equal to the other's (orient = 0) is an overlap; your answer says they do not";
    std::string why =
        "the triangles intersect: their segments on the line where the planes meet overlap; your "
        "answer says they do not";
    if (std::max(off_plane(in.t0, in.t1, size), off_plane(in.t1, in.t0, size)) < 1e-12)
      why += "; they are coplanar up to rounding: a volume d within its rounding is in the plane (sign 0)";
    return why;
  }
  if (oracle::is_degenerate(in.t0) || oracle::is_degenerate(in.t1))
    return "a zero-area triangle has no plane and never intersects anything; your answer says they intersect";
  std::string why = "the triangles are apart: they share no point; your answer says they intersect";
  const double needle = std::max(aspect(in.t0), aspect(in.t1));
  if (needle > 1e4)
    why += "; one is a needle (aspect " + fmt(needle) +
           "): take its normal from its two shortest edges and count a "
           "vertex in its plane only within that construction's rounding, not a bound relative to its long edges";
  else if (std::min(off_plane(in.t0, in.t1, size), off_plane(in.t1, in.t0, size)) < 1e-12)
    why +=
        "; they are coplanar up to rounding: volumes d of rounding size have noise signs; a vertex counts as in "
        "the plane when |d| is within its rounding";
  return why;
}

// The interval method's domain (in_interval_domain): no needle, and crossing each other.
bool fat(const Triangle& t) {
  const double longest =
      std::max({(t.v1 - t.v0).squaredNorm(), (t.v2 - t.v1).squaredNorm(), (t.v0 - t.v2).squaredNorm()});
  return 100 * t.normal().norm() >= longest;  // smallest height >= longest edge / 100
}

// Every vertex of `of` at least `reach` off t's plane, on both sides of it.
bool straddles_by(const Triangle& t, const Triangle& of, double reach) {
  const Vec3 n = t.normal().normalized();
  bool above = false, below = false;
  for (int k = 0; k < 3; ++k) {
    const double d = n.dot(of[k] - t.v0);
    if (std::abs(d) < reach) return false;
    (d > 0 ? above : below) = true;
  }
  return above && below;
}

}  // namespace

bool in_interval_domain(const TrianglePair& p) {
  const double reach = scale_of(p) / 100;
  return fat(p.t0) && fat(p.t1) && straddles_by(p.t0, p.t1, reach) && straddles_by(p.t1, p.t0, reach);
}

Outcome triangles_by_intervals(const TrianglePair& in, const LineIntervals& got, Rules rules) {
  if (!in_interval_domain(in)) return pass();  // outside the method's domain: not graded
  const double tol = position_tolerance(in);
  const std::string answer = got.crossing ? "axis " + std::to_string(got.axis) + ", t0 in [" + fmt(got.low0) + ", " +
                                                fmt(got.high0) + "], t1 in [" + fmt(got.low1) + ", " + fmt(got.high1) +
                                                "], " + (got.overlap ? "overlap" : "apart")
                                          : "not crossing";
  const Vec3 D = oracle::planes_line_direction(in.t0, in.t1), m = D.cwiseAbs();
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (m[i] > m[k]) k = i;
  if (!got.crossing)
    return fail("crossing", answer,
                "each triangle has vertices strictly on both sides of the other's plane (no d_i is "
                "0): the lecture's general case, crossing = true");
  if (got.axis < 0 || got.axis > 2 || m[got.axis] < m[k] * (1 - 1e-9)) {
    std::string why = "the line of the planes, D = n0 x n1 = " + fmt(D) +
                      ", is read on the coordinate where |D_k| is "
                      "largest, axis " +
                      std::to_string(k);
    if (got.axis >= 0 && got.axis <= 2)
      why += "; yours, axis " + std::to_string(got.axis) + ", has |D_" + std::to_string(got.axis) +
             "| = " + fmt(m[got.axis]) +
             (m[got.axis] == 0 ? ": every point of the line has the same coordinate there" : "");
    return fail("axis " + std::to_string(k), answer, why);
  }
  if (got.low0 > got.high0 || got.low1 > got.high1)
    return fail("low <= high for both intervals", answer,
                "an interval's two ends come in either order (edge p q's may be the larger): sort them, low <= high");
  const oracle::TriangleIntervals exact = oracle::triangle_intervals(in.t0, in.t1, got.axis);
  const std::string expected = "axis " + std::to_string(got.axis) + ", t0 in [" + fmt(exact.low0) + ", " +
                               fmt(exact.high0) + "], t1 in [" + fmt(exact.low1) + ", " + fmt(exact.high1) + "]";
  for (int t = 0; t < 2; ++t) {
    const double low = t ? got.low1 : got.low0, high = t ? got.high1 : got.high0;
    const double exact_low = t ? exact.low1 : exact.low0, exact_high = t ? exact.high1 : exact.high0;
    if (std::abs(low - exact_low) <= tol && std::abs(high - exact_high) <= tol) continue;
    const Triangle& mine = t ? in.t1 : in.t0;
    const Triangle& other = t ? in.t0 : in.t1;
    int side[3];
    for (int i = 0; i < 3; ++i) side[i] = oracle::orientation(other.v0, other.v1, other.v2, mine[i]);
    const int p = side[0] == side[1] ? 2 : (side[0] == side[2] ? 1 : 0);
    const std::string me = t ? "t1" : "t0", it = t ? "t0" : "t1";
    return fail(expected, answer,
                me + "'s segment in " + it + "'s plane covers [" + fmt(exact_low) + ", " + fmt(exact_high) +
                    "] (tolerance " + fmt(tol) +
                    "): its ends are where the two edges from the vertex alone on its "
                    "side, " +
                    me + ".v" + std::to_string(p) + ", cross the plane, x = p + (q - p) d_p / (d_p - d_q)");
  }
  const bool expected_overlap = oracle::triangles_intersect(in.t0, in.t1);
  const bool doubt = rules == Rules::random && oracle::triangle_pair_in_doubt(in.t0, in.t1, tol);
  Outcome o = verdict(got.overlap, expected_overlap, doubt, rules, "overlap", "apart");
  if (o.verdict == Outcome::Verdict::fail)
    o.why = expected_overlap ? "the intervals share a point, so the triangles intersect; ends that touch count "
                               "(low0 <= high1 and low1 <= high0)"
                             : "the intervals are apart, so the triangles do not intersect: one interval ends before "
                               "the other begins";
  return o;
}

Outcome test_triangles(const TrianglePair& in, bool got, Rules rules) {
  const bool expected = oracle::triangles_intersect(in.t0, in.t1);
  bool doubt = false;
  if (rules == Rules::random) {
    const double tol = position_tolerance(in);
    doubt = oracle::triangle_pair_in_doubt(in.t0, in.t1, tol);
    // Sampling as well, for triangles whose boxes come near each other: a flip it finds
    // would mean the conservative test above missed one.
    if (!doubt) {
      const Vec3 low0 = in.t0.v0.cwiseMin(in.t0.v1).cwiseMin(in.t0.v2),
                 high0 = in.t0.v0.cwiseMax(in.t0.v1).cwiseMax(in.t0.v2);
      const Vec3 low1 = in.t1.v0.cwiseMin(in.t1.v1).cwiseMin(in.t1.v2),
                 high1 = in.t1.v0.cwiseMax(in.t1.v1).cwiseMax(in.t1.v2);
      const bool near =
          ((low0.array() - 8 * tol) <= high1.array()).all() && ((low1.array() - 8 * tol) <= high0.array()).all();
      if (near)
        doubt = check::flips_under_perturbation(
            in, [](const TrianglePair& p) { return oracle::triangles_intersect(p.t0, p.t1); });
    }
  }
  Outcome o = verdict(got, expected, doubt, rules, "intersecting", "not intersecting");
  if (o.verdict == Outcome::Verdict::fail) o.why = why_triangles(in, expected);
  return o;
}

}  // namespace labkit::lab03::judge
