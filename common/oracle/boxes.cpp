#include "common/oracle/boxes.h"
#include "common/oracle/not_finite.h"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace oracle {

namespace {

// Exact decisions are filtered: run in interval arithmetic first (every comparison
// whose answer the intervals prove), and only when a comparison is too close to call
// (CGAL throws Uncertain_conversion_exception) run again with Mpzf, CGAL's exact
// floating-point type. Only ring operations are needed (+, -, *): no rationals.
using Interval = CGAL::Interval_nt<false>;
using Exact = CGAL::Mpzf;

template <class NT> using V3 = std::array<NT, 3>;

template <class NT> V3<NT> vec(const Vec3& v) { return {number<NT>(v.x()), number<NT>(v.y()), number<NT>(v.z())}; }
template <class NT> NT dot(const V3<NT>& u, const V3<NT>& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
template <class NT> V3<NT> cross(const V3<NT>& u, const V3<NT>& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

Interval smaller(const Interval& x, const Interval& y) { return CGAL::min(x, y); }
Interval larger(const Interval& x, const Interval& y) { return CGAL::max(x, y); }
Exact smaller(const Exact& x, const Exact& y) { return y < x ? y : x; }
Exact larger(const Exact& x, const Exact& y) { return x < y ? y : x; }

// One box, exactly: its corners and axes.
template <class NT> struct ExactBox {
  std::array<V3<NT>, 8> corners;
  std::array<V3<NT>, 3> axes;

  explicit ExactBox(const Box& box) {
    for (int k = 0; k < 3; ++k) axes[k] = vec<NT>(box.axes.col(k));
    const V3<NT> c = vec<NT>(box.center);
    for (int i = 0; i < 8; ++i)
      for (int d = 0; d < 3; ++d) {
        NT x = c[d];
        for (int k = 0; k < 3; ++k) {
          const NT step = number<NT>(box.half_extents[k]) * axes[k][d];
          x = (i >> k) & 1 ? x + step : x - step;
        }
        corners[i][d] = x;
      }
  }

  // The corners' projections onto u: [lo, hi].
  void project(const V3<NT>& u, NT& lo, NT& hi) const {
    lo = hi = dot(corners[0], u);
    for (int i = 1; i < 8; ++i) {
      const NT p = dot(corners[i], u);
      lo = smaller(lo, p);
      hi = larger(hi, p);
    }
  }
};

// a b == c d, exactly: each product is a double plus its exact rounding error (a
// fused multiply-add gives the error), and that pair is unique to the product.
bool equal_products(double a, double b, double c, double d) {
  const double ab = a * b, cd = c * d;
  return ab == cd && std::fma(a, b, -ab) == std::fma(c, d, -cd);
}

bool parallel(const Vec3& u, const Vec3& v) {
  return equal_products(u.y(), v.z(), u.z(), v.y()) && equal_products(u.z(), v.x(), u.x(), v.z()) &&
         equal_products(u.x(), v.y(), u.y(), v.x());
}

// a b - c d with one rounding error (Kahan's algorithm with fused multiply-adds): the
// components of a cross product to a relative 2e-16, however much they cancel.
double difference_of_products(double a, double b, double c, double d) {
  const double cd = c * d;
  const double error = std::fma(-c, d, cd);  // cd - c d, exactly
  return std::fma(a, b, -cd) + error;
}

Vec3 rounded_cross(const Vec3& u, const Vec3& v) {
  return {difference_of_products(u.y(), v.z(), u.z(), v.y()), difference_of_products(u.z(), v.x(), u.x(), v.z()),
          difference_of_products(u.x(), v.y(), u.y(), v.x())};
}

// The facet normals of A ⊕ (-B) (see boxes.h), and with a motion W the six more of the
// swept boxes, as pairs of vectors whose cross product is the normal. Exactly zero ones
// (parallel pairs) are left out: such an axis separates nothing and bounds no time.
struct AxisSet {
  std::array<std::array<Vec3, 2>, 21> pairs;
  int size = 0;

  AxisSet(const Box& a, const Box& b, const Vec3* motion = nullptr) {
    for (int k = 0; k < 3; ++k) add(a.axes.col((k + 1) % 3), a.axes.col((k + 2) % 3));
    for (int k = 0; k < 3; ++k) add(b.axes.col((k + 1) % 3), b.axes.col((k + 2) % 3));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) add(a.axes.col(i), b.axes.col(j));
    if (motion)
      for (const Box* box : {&a, &b})
        for (int k = 0; k < 3; ++k) add(*motion, box->axes.col(k));
  }
  void add(const Vec3& u, const Vec3& v) {
    if (!parallel(u, v)) pairs[size++] = {u, v};
  }
  template <class NT> V3<NT> exact(int k) const { return cross(vec<NT>(pairs[k][0]), vec<NT>(pairs[k][1])); }
  Vec3 rounded(int k) const { return rounded_cross(pairs[k][0], pairs[k][1]); }
};

template <class NT> bool intersect(const Box& box_a, const Box& box_b) {
  const ExactBox<NT> a(box_a), b(box_b);
  const AxisSet axes(box_a, box_b);
  for (int k = 0; k < axes.size; ++k) {
    const V3<NT> axis = axes.exact<NT>(k);
    NT lo_a, hi_a, lo_b, hi_b;
    a.project(axis, lo_a, hi_a);
    b.project(axis, lo_b, hi_b);
    if (hi_a < lo_b || hi_b < lo_a) return false;
  }
  return true;
}

template <class NT> bool apart_along(const Box& box_a, const Box& box_b, const Vec3& direction, bool either_way) {
  const ExactBox<NT> a(box_a), b(box_b);
  const V3<NT> u = vec<NT>(direction);
  NT lo_a, hi_a, lo_b, hi_b;
  a.project(u, lo_a, hi_a);
  b.project(u, lo_b, hi_b);
  return hi_a < lo_b || (either_way && hi_b < lo_a);
}

// Runs `f` on intervals, and exactly when the intervals cannot decide.
template <class F> bool filtered(F&& f) {
  try {
    CGAL::Protect_FPU_rounding<true> rounding;
    return f(Interval());
  } catch (const CGAL::Uncertain_conversion_exception&) {}
  return f(Exact());
}

// Values in double: corners rounded, axes rounded once from exact.
struct RoundedBox {
  std::array<Vec3, 8> corners;
  explicit RoundedBox(const Box& box) {
    for (int i = 0; i < 8; ++i) corners[i] = box.corner(i);
  }
  void project(const Vec3& u, double& lo, double& hi) const {
    lo = hi = corners[0].dot(u);
    for (int i = 1; i < 8; ++i) {
      const double p = corners[i].dot(u);
      lo = std::min(lo, p);
      hi = std::max(hi, p);
    }
  }
};

// The margin over the given axes, B's projection widened by `sweep` along each (the
// relative displacement over the motion): the largest gap, or minus the least overlap.
double margin(const Box& box_a, const Box& box_b, const Vec3* sweep) {
  const RoundedBox a(box_a), b(box_b);
  const AxisSet axes(box_a, box_b, sweep);
  double best = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < axes.size; ++k) {
    const Vec3 axis = axes.rounded(k);
    const Vec3 u = axis / axis.norm();
    double lo_a, hi_a, lo_b, hi_b;
    a.project(u, lo_a, hi_a);
    b.project(u, lo_b, hi_b);
    if (sweep) {
      const double d = sweep->dot(u);
      lo_b += std::min(0.0, d);
      hi_b += std::max(0.0, d);
    }
    best = std::max(best, std::max(lo_b - hi_a, lo_a - hi_b));
  }
  return best;
}

// A time bound num / den, den > 0, compared by cross-multiplying.
template <class NT> struct Fraction { NT num, den; };
template <class NT> bool less(const Fraction<NT>& x, const Fraction<NT>& y) { return x.num * y.den < y.num * x.den; }

// The times t in [from, to] at which, on every facet normal L, the projections are
// apart by at most slack |L| (lengths |L| rounded). On each axis that is two linear
// conditions, alpha + t beta >= 0:
//   hi_A - lo_B + slack |L| + t (v_A - v_B) . L >= 0,   hi_B - lo_A + slack |L| + t (v_B - v_A) . L >= 0.
template <class NT>
bool meet(const Box& box_a, const Vec3& va, const Box& box_b, const Vec3& vb, double from, double to, double slack,
          Fraction<NT>* first = nullptr, Fraction<NT>* last = nullptr) {
  const ExactBox<NT> a(box_a), b(box_b);
  const AxisSet axes(box_a, box_b);
  const V3<NT> relative = {number<NT>(vb.x()) - number<NT>(va.x()), number<NT>(vb.y()) - number<NT>(va.y()),
                           number<NT>(vb.z()) - number<NT>(va.z())};
  Fraction<NT> lower{number<NT>(from), number<NT>(1)}, upper{number<NT>(to), number<NT>(1)};
  if (upper.num < lower.num) return false;
  for (int k = 0; k < axes.size; ++k) {
    const V3<NT> axis = axes.exact<NT>(k);
    NT lo_a, hi_a, lo_b, hi_b;
    a.project(axis, lo_a, hi_a);
    b.project(axis, lo_b, hi_b);
    const NT extra = number<NT>(slack) * number<NT>(axes.rounded(k).norm());
    const NT speed = dot(relative, axis);  // d/dt of B's projection minus A's
    const NT alphas[2] = {hi_a - lo_b + extra, hi_b - lo_a + extra};
    const NT betas[2] = {-speed, speed};
    for (int c = 0; c < 2; ++c) {
      const NT& alpha = alphas[c];
      const NT& beta = betas[c];
      if (beta == 0) {
        if (alpha < 0) return false;  // never on this side, at any time
      } else if (0 < beta) {
        const Fraction<NT> bound{-alpha, beta};  // t >= -alpha / beta
        if (less(lower, bound)) lower = bound;
      } else {
        const Fraction<NT> bound{alpha, -beta};  // t <= alpha / -beta
        if (less(bound, upper)) upper = bound;
      }
    }
    if (less(upper, lower)) return false;
  }
  if (first) *first = lower;
  if (last) *last = upper;
  return true;
}

double value(const Fraction<Exact>& f) { return f.num.to_double() / f.den.to_double(); }

}  // namespace

bool boxes_intersect(const Box& a, const Box& b) {
  return filtered([&](auto nt) { return intersect<decltype(nt)>(a, b); });
}

bool boxes_separated_along(const Box& a, const Box& b, const Vec3& u) {
  return filtered([&](auto nt) { return apart_along<decltype(nt)>(a, b, u, true); });
}

bool box_beyond_along(const Box& a, const Box& b, const Vec3& u) {
  return filtered([&](auto nt) { return apart_along<decltype(nt)>(a, b, u, false); });
}

BoxProjection box_projection(const Box& box, const Vec3& u) {
  const RoundedBox corners(box);
  double lo, hi;
  corners.project(u, lo, hi);
  const double center = box.center.dot(u);
  return {center, std::max(hi - center, center - lo)};
}

Vec3 box_pair_axis(const Box& a, const Box& b, int index) {
  if (index < 3) return a.axes.col(index);
  if (index < 6) return b.axes.col(index - 3);
  return rounded_cross(a.axes.col((index - 6) / 3), b.axes.col((index - 6) % 3));
}

double box_depth_along(const Box& a, const Box& b, const Vec3& u) {
  const double length = u.norm();
  if (length == 0) return 0.0;
  const RoundedBox ra(a), rb(b);
  double lo_a, hi_a, lo_b, hi_b;
  ra.project(u / length, lo_a, hi_a);
  rb.project(u / length, lo_b, hi_b);
  return hi_a - lo_b;
}

double box_pair_margin(const Box& a, const Box& b) { return margin(a, b, nullptr); }

double moving_boxes_swept_margin(const Box& a, const Vec3& va, const Box& b, const Vec3& vb, double duration) {
  const Vec3 sweep = duration * (vb - va);
  return margin(a, b, &sweep);
}

bool moving_boxes_meet(const Box& a, const Vec3& va, const Box& b, const Vec3& vb, double from, double to,
                       double slack) {
  return filtered([&](auto nt) { return meet<decltype(nt)>(a, va, b, vb, from, to, slack); });
}

ContactTimes moving_boxes_contact(const Box& a, const Vec3& va, const Box& b, const Vec3& vb, double duration) {
  ContactTimes times;
  // The decision is exact; the ends are then computed once more, exactly, to round them.
  times.contact = moving_boxes_meet(a, va, b, vb, 0.0, duration, 0.0);
  if (!times.contact) return times;
  Fraction<Exact> first, last;
  meet<Exact>(a, va, b, vb, 0.0, duration, 0.0, &first, &last);
  times.first = value(first);
  times.last = value(last);
  return times;
}

}  // namespace oracle
