#include "common/oracle/posed_shapes.h"
#include "common/oracle/not_finite.h"

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <array>
#include <cmath>
#include <optional>

namespace oracle {

namespace {

// Each predicate is written once, for a number type NT, and run twice: first with
// interval arithmetic (fast; a comparison it cannot decide throws), then, only when an
// interval comparison was uncertain, with Mpzf, CGAL's exact floating-point type. The
// inputs are doubles and the predicates use +, - and * only (a quotient is kept as a
// numerator over a positive denominator), so the exact run is exact, and it needs no
// rationals: no gcd after every product.
using Interval = CGAL::Interval_nt<false>;  // needs the rounding mode set by the caller
using Exact = CGAL::Mpzf;

template <class NT> using V = std::array<NT, 3>;

template <class NT> V<NT> operator-(const V<NT>& a, const V<NT>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
template <class NT> V<NT> operator+(const V<NT>& a, const V<NT>& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
template <class NT> V<NT> operator*(const NT& s, const V<NT>& a) { return {s * a[0], s * a[1], s * a[2]}; }
template <class NT> NT dot(const V<NT>& a, const V<NT>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class NT> V<NT> cross(const V<NT>& a, const V<NT>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class NT> NT det(const V<NT>& a, const V<NT>& b, const V<NT>& c) { return dot(a, cross(b, c)); }

// R x + p (translate = true) or R x, exactly.
template <class NT> V<NT> apply(const RigidTransform& pose, const labkit::Vec3& x, bool translate) {
  const auto& m = pose.matrix();
  V<NT> r;
  for (int i = 0; i < 3; ++i) {
    r[i] = number<NT>(m(i, 0)) * number<NT>(x[0]) + number<NT>(m(i, 1)) * number<NT>(x[1]) +
           number<NT>(m(i, 2)) * number<NT>(x[2]);
    if (translate) r[i] += number<NT>(m(i, 3));
  }
  return r;
}

// The sphere's centre relative to the box's centre, w, and the box's posed half edges
// u_k = R (h_k axis_k): the box is { w' : w' = sum s_k u_k, |s_k| <= 1 } around it.
template <class NT> struct Relative {
  V<NT> w;
  std::array<V<NT>, 3> u;
};

template <class NT>
Relative<NT> relative(const Sphere& a, const RigidTransform& pose_a, const Box& b, const RigidTransform& pose_b) {
  Relative<NT> r;
  r.w = apply<NT>(pose_a, a.center, true) - apply<NT>(pose_b, b.center, true);
  for (int k = 0; k < 3; ++k) {
    const V<NT> axis = apply<NT>(pose_b, b.axes.col(k), false);
    r.u[k] = number<NT>(b.half_extents[k]) * axis;
  }
  return r;
}

// A squared distance num / den, with den > 0, kept as the two numbers so that comparing
// two of them needs no division.
template <class NT> struct Squared { NT num, den; };
template <class NT> bool operator<=(const Squared<NT>& a, const NT& b) { return a.num <= b * a.den; }
template <class NT> bool operator<(const Squared<NT>& a, const Squared<NT>& b) { return a.num * b.den < b.num * a.den; }

// The squared distance from w to the parallelepiped is the least, over its faces of
// every dimension, of the squared distance to the face's affine hull, counted only when
// the foot of the perpendicular lies in the face: the nearest point of a convex
// polytope lies inside one face, and there it is that face's foot. `visit` gets each
// such candidate (0 when w is inside) and returns true to stop. `skip(value)` says that
// a value is not worth the face test (so an interval run decides fewer comparisons).
template <class NT, class Skip, class Visit> void candidates(const Relative<NT>& r, Skip&& skip, Visit&& visit) {
  const NT zero(0), one(1);
  const auto& u = r.u;
  const V<NT>& w = r.w;
  // Inside (a solid box only): Cramer's rule for w = sum s_k u_k, |s_k| <= 1, i.e.
  // |det with column k replaced by w| <= |det|.
  const NT whole = det(u[0], u[1], u[2]);
  if (!CGAL::is_zero(whole)) {
    const NT bound = CGAL::abs(whole);
    if (CGAL::abs(det(w, u[1], u[2])) <= bound && CGAL::abs(det(u[0], w, u[2])) <= bound &&
        CGAL::abs(det(u[0], u[1], w)) <= bound)
      if (visit(Squared<NT>{zero, one})) return;
  }
  const int signs[2] = {-1, 1};
  // Faces: normal direction k, side sk; the face spans u_i and u_j. The squared distance
  // to its plane is height^2 / gram.
  for (int k = 0; k < 3; ++k) {
    const V<NT>& ui = u[(k + 1) % 3];
    const V<NT>& uj = u[(k + 2) % 3];
    const NT gii = dot(ui, ui), gij = dot(ui, uj), gjj = dot(uj, uj);
    const NT gram = gii * gjj - gij * gij;  // |ui x uj|^2
    if (CGAL::is_zero(gram)) continue;      // a flat face: its edges stand in for it
    const V<NT> n = cross(ui, uj);
    for (int sk : signs) {
      const V<NT> v = w - number<NT>(sk) * u[k];
      const NT height = dot(v, n);
      const Squared<NT> value{height * height, gram};
      if (skip(value)) continue;
      // The foot v = a ui + b uj: the Gram system, solved by Cramer's rule.
      const NT bi = dot(v, ui), bj = dot(v, uj);
      if (CGAL::abs(bi * gjj - bj * gij) <= gram && CGAL::abs(gii * bj - gij * bi) <= gram)
        if (visit(value)) return;
    }
  }
  // Edges: direction k, at the corner signs of the other two axes. The squared distance
  // to the edge's line is |v|^2 - along^2 / length2.
  for (int k = 0; k < 3; ++k) {
    const NT length2 = dot(u[k], u[k]);
    if (CGAL::is_zero(length2)) continue;  // a zero-length edge: its ends stand in for it
    for (int si : signs)
      for (int sj : signs) {
        const V<NT> v = w - number<NT>(si) * u[(k + 1) % 3] - number<NT>(sj) * u[(k + 2) % 3];
        const NT along = dot(v, u[k]);
        const Squared<NT> value{dot(v, v) * length2 - along * along, length2};
        if (skip(value)) continue;
        if (CGAL::abs(along) <= length2)
          if (visit(value)) return;
      }
  }
  // Vertices.
  for (int i = 0; i < 8; ++i) {
    V<NT> v = w;
    for (int k = 0; k < 3; ++k) v = v - number<NT>((i >> k) & 1 ? 1 : -1) * u[k];
    if (visit(Squared<NT>{dot(v, v), one})) return;
  }
}

template <class NT> bool within(const Relative<NT>& r, const NT& radius2) {
  bool found = false;
  candidates(
      r, [&](const Squared<NT>& value) { return !(value <= radius2); },
      [&](const Squared<NT>& value) { return found = value <= radius2; });
  return found;
}

template <class NT> Squared<NT> least(const Relative<NT>& r) {
  std::optional<Squared<NT>> best;
  candidates(
      r, [&](const Squared<NT>& value) { return best && !(value < *best); },
      [&](const Squared<NT>& value) {
    if (!best || value < *best) best = value;
    return CGAL::is_zero(value.num);
      });
  return *best;  // the vertices always visit
}

template <class NT>
NT centres_squared(const Sphere& a, const RigidTransform& pose_a, const Sphere& b, const RigidTransform& pose_b) {
  const V<NT> d = apply<NT>(pose_a, a.center, true) - apply<NT>(pose_b, b.center, true);
  return dot(d, d);
}

// Runs `decide` with intervals, and again exactly when they could not decide.
template <class Decide> bool filtered(Decide&& decide) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    try {
      return decide(Interval());
    } catch (const CGAL::Uncertain_conversion_exception&) {}
  }
  return decide(Exact());
}

// An exact value, rounded once (through a rational: a numerator can be far beyond a
// double's range when its quotient is not).
double rounded(const Exact& x) { return CGAL::to_double(CGAL::Gmpq(x)); }
double rounded(const Squared<Exact>& x) { return CGAL::to_double(CGAL::Gmpq(x.num) / CGAL::Gmpq(x.den)); }

}  // namespace

bool spheres_overlap(const Sphere& a, const RigidTransform& pose_a, const Sphere& b, const RigidTransform& pose_b) {
  return filtered([&](auto zero) {
    using NT = decltype(zero);
    const NT reach = number<NT>(a.radius) + number<NT>(b.radius);
    return bool(centres_squared<NT>(a, pose_a, b, pose_b) <= reach * reach);
  });
}

bool sphere_box_overlap(const Sphere& a, const RigidTransform& pose_a, const Box& b, const RigidTransform& pose_b) {
  return filtered([&](auto zero) {
    using NT = decltype(zero);
    const NT r(a.radius);
    return within(relative<NT>(a, pose_a, b, pose_b), r * r);
  });
}

double spheres_distance(const Sphere& a, const RigidTransform& pose_a, const Sphere& b, const RigidTransform& pose_b) {
  if (spheres_overlap(a, pose_a, b, pose_b)) return 0.0;
  return std::sqrt(rounded(centres_squared<Exact>(a, pose_a, b, pose_b))) - (a.radius + b.radius);
}

double sphere_box_distance(const Sphere& a, const RigidTransform& pose_a, const Box& b, const RigidTransform& pose_b) {
  if (sphere_box_overlap(a, pose_a, b, pose_b)) return 0.0;
  return std::sqrt(rounded(least(relative<Exact>(a, pose_a, b, pose_b)))) - a.radius;
}

}  // namespace oracle
