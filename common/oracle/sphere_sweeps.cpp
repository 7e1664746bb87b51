#include "common/oracle/sphere_sweeps.h"
#include "common/oracle/kernel.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

namespace oracle {

using namespace kernel;

// The exact squared distance, computed only when needed: a certified interval around it
// (interval arithmetic, filled when every comparison on the way was certain) settles
// most questions; the exact number is built from `compute` otherwise.
struct SquaredDistance::Exact {
  bool bounded = false;
  double low = 0.0, high = 0.0;
  std::function<FT()> compute;
  mutable std::optional<FT> value;
  const FT& exact() const {
    if (!value) value = compute();
    return *value;
  }
};

namespace {

using Point = Epeck::Point_3;
using Vector = Epeck::Vector_3;
using Interval = CGAL::Interval_nt<false>;
using IK = CGAL::Simple_cartesian<Interval>;  // interval arithmetic: certified bounds, or an exception
// Exact rationals without the lazy kernel's bookkeeping, for a distance the intervals
// could not bound: it is wanted exactly, so there is nothing to put off.
using EK = CGAL::Simple_cartesian<FT::ET>;

Vector exact_vector(const Vec3& v) {
  finite(v);
  return {v.x(), v.y(), v.z()};
}

FT squared(const FT& x) { return x * x; }

template <class K> typename K::Point_3 point_of(const Vec3& v) {
  finite(v);
  return {v.x(), v.y(), v.z()};
}
template <class K> typename K::Vector_3 vector_of(const Vec3& v) {
  finite(v);
  return {v.x(), v.y(), v.z()};
}
template <class K> typename K::Segment_3 segment_of(const Segment& s) { return {point_of<K>(s.a), point_of<K>(s.b)}; }

template <class K> typename K::FT distance2(const typename K::Point_3& p, const typename K::Segment_3& s) {
  if (s.is_degenerate()) return CGAL::squared_distance(p, s.source());
  return CGAL::squared_distance(p, s);
}

template <class K> typename K::FT distance2(const typename K::Segment_3& s0, const typename K::Segment_3& s1) {
  if (s0.is_degenerate()) return distance2<K>(s0.source(), s1);
  if (s1.is_degenerate()) return distance2<K>(s1.source(), s0);
  return CGAL::squared_distance(s0, s1);
}

// The rectangle as the exact parallelogram of its numbers: corner k has signs
// (k & 1 ? + : -) half_u along u and (k & 2 ? + : -) half_v along v.
//
//    c2 ------- c3        sides, in order: c0 c1, c1 c3, c3 c2, c2 c0
//    |     v ^   |        triangles: c0 c1 c3 and c0 c3 c2
//    |       +-> u
//    c0 ------- c1
template <class K> struct RectangleOf {
  using P = typename K::Point_3;
  std::array<P, 4> corner;
  bool flat = false;  // half_u == 0 or half_v == 0: a segment (or a point)

  explicit RectangleOf(const Rectangle& r) {
    const P c = point_of<K>(r.center);
    const typename K::Vector_3 u = vector_of<K>(r.u) * typename K::FT(r.half_u),
                               v = vector_of<K>(r.v) * typename K::FT(r.half_v);
    for (int k = 0; k < 4; ++k) corner[k] = c + (k & 1 ? u : -u) + (k & 2 ? v : -v);
    flat = r.half_u == 0 || r.half_v == 0;
  }
  // A flat rectangle is the segment between opposite corners.
  typename K::Segment_3 diagonal() const { return {corner[0], corner[3]}; }
  typename K::Segment_3 side(int i) const {
    static const int from[4] = {0, 1, 3, 2}, to[4] = {1, 3, 2, 0};
    return {corner[from[i]], corner[to[i]]};
  }
  typename K::Triangle_3 triangle(int i) const {
    return i == 0 ? typename K::Triangle_3(corner[0], corner[1], corner[3])
                  : typename K::Triangle_3(corner[0], corner[3], corner[2]);
  }
};

// The smallest of several squared distances ("items"), found by branch and bound so
// that exact arithmetic is rarely needed:
//  1. each item comes with a certified lower bound (the squared gap between the two
//     objects' bounding boxes) and upper bound (the squared distance between a vertex of
//     each);
//  2. items are visited by lower bound; one whose lower bound is above the best upper
//     bound so far cannot be the minimum and is dropped unevaluated;
//  3. the others are evaluated in interval arithmetic, or, when that meets an uncertain
//     comparison (degenerate input: a point exactly on an edge, parallel segments),
//     exactly at once;
//  4. the exact minimum of the survivors is computed only if a comparison needs it.
class Minimum {
 public:
  // a, b: the two objects in interval arithmetic (for their boxes and a vertex each);
  // bound(): the squared distance in interval arithmetic (may throw); exact(): exactly.
  template <class A, class B, class Bound, class Exact> void add(const A& a, const B& b, Bound&& bound, Exact&& exact) {
    CGAL::Protect_FPU_rounding<true> rounding;
    Item item;
    item.lower = box_gap2(a.bbox(), b.bbox());
    item.upper = CGAL::squared_distance(vertex(a), vertex(b)).sup();
    item.bound = std::forward<Bound>(bound);
    item.exact = std::forward<Exact>(exact);
    items_.push_back(std::move(item));
  }
  // An intersection test of a segment and a triangle: meeting makes the distance 0.
  template <class A, class B, class Bound, class Exact>
  void meets(const A& a, const B& b, Bound&& bound, Exact&& exact) {
    if (zero_) return;
    bool certain = false, meet = false;
    {
      CGAL::Protect_FPU_rounding<true> rounding;
      if (box_gap2(a.bbox(), b.bbox()) > 0) return;  // their boxes are apart
      try {
        meet = bound();
        certain = true;
      } catch (const CGAL::Uncertain_conversion_exception&) {}
    }
    if (!certain) meet = exact();
    zero_ = zero_ || meet;
  }
  bool zero() const { return zero_; }

  SquaredDistance result() {
    auto e = std::make_shared<SquaredDistance::Exact>();
    e->bounded = true;
    if (zero_) {
      e->compute = [] { return ft(0); };
      return SquaredDistance(std::move(e));
    }
    double best = std::numeric_limits<double>::infinity();
    for (const Item& i : items_) best = std::min(best, i.upper);
    std::sort(items_.begin(), items_.end(), [](const Item& x, const Item& y) { return x.lower < y.lower; });
    std::vector<Item> kept;
    for (Item& i : items_) {
      if (i.lower > best) break;  // this one and every later one: above an upper bound
      evaluate(i);
      best = std::min(best, i.interval.sup());
      kept.push_back(std::move(i));
    }
    double low = std::numeric_limits<double>::infinity();
    std::vector<Item> survivors;
    for (Item& i : kept)
      if (i.interval.inf() <= best) {
        low = std::min(low, i.interval.inf());
        survivors.push_back(std::move(i));
      }
    e->low = low;
    e->high = best;
    e->compute = [survivors = std::move(survivors)]() mutable {
      FT m = survivors[0].value ? *survivors[0].value : survivors[0].exact();
      for (std::size_t k = 1; k < survivors.size(); ++k)
        m = CGAL::min(m, survivors[k].value ? *survivors[k].value : survivors[k].exact());
      return m;
    };
    return SquaredDistance(std::move(e));
  }

 private:
  struct Item {
    double lower = 0.0, upper = 0.0;
    std::function<Interval()> bound;
    std::function<FT()> exact;
    Interval interval = Interval(0);
    std::optional<FT> value;
  };
  static IK::Point_3 vertex(const IK::Point_3& p) { return p; }
  static IK::Point_3 vertex(const IK::Segment_3& s) { return s.source(); }
  static IK::Point_3 vertex(const IK::Triangle_3& t) { return t[0]; }
  // A lower bound of the squared distance between two boxes (rounding upward: the
  // gaps' lower ends are taken from -(lower - upper)).
  static double box_gap2(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b) {
    Interval sum(0);
    for (int k = 0; k < 3; ++k) {
      const double gap = std::max(
          {0.0, -(Interval(a.max(k)) - Interval(b.min(k))).sup(), -(Interval(b.max(k)) - Interval(a.min(k))).sup()});
      sum += CGAL::square(Interval(gap));
    }
    return sum.inf();
  }
  static void evaluate(Item& i) {
    {
      CGAL::Protect_FPU_rounding<true> rounding;
      try {
        i.interval = i.bound();
        return;
      } catch (const CGAL::Uncertain_conversion_exception&) {}
    }
    i.value = i.exact();
    i.interval = CGAL::to_interval(*i.value);
  }
  std::vector<Item> items_;
  bool zero_ = false;
};

// A rectangle of the input, with its exact corners built on first use and then shared by
// every exact item of one distance query (two rectangles' query may need them dozens of
// times). Copied by value, like the items that hold it.
class SharedRectangle {
 public:
  SharedRectangle() = default;
  explicit SharedRectangle(const Rectangle& r) : shared_(std::make_shared<Shared>(Shared{r, std::nullopt})) {}
  const Rectangle& numbers() const { return shared_->numbers; }
  template <class K> decltype(auto) get() const {
    if constexpr (std::is_same_v<K, EK>) {
      if (!shared_->exact) shared_->exact.emplace(shared_->numbers);
      return static_cast<const RectangleOf<EK>&>(*shared_->exact);
    } else {
      return RectangleOf<K>(shared_->numbers);
    }
  }

 private:
  struct Shared {
    Rectangle numbers;
    std::optional<RectangleOf<EK>> exact;
  };
  std::shared_ptr<Shared> shared_;
};

// A point or a segment of the input: given by doubles, or a corner or side of a
// rectangle (exact rationals). Copied by value: exact items may be computed later.
struct PointSource {
  Vec3 p = Vec3::Zero();
  SharedRectangle rect;
  int corner = -1;  // -1: p itself
  template <class K> typename K::Point_3 get() const {
    return corner < 0 ? point_of<K>(p) : rect.get<K>().corner[corner];
  }
};
struct SegmentSource {
  Segment s;
  SharedRectangle rect;
  int side = -1;  // -1: s itself
  template <class K> typename K::Segment_3 get() const {
    return side < 0 ? segment_of<K>(s) : rect.get<K>().side(side);
  }
  PointSource end(int k) const {
    static const int from[4] = {0, 1, 3, 2}, to[4] = {1, 3, 2, 0};
    if (side < 0) return {k == 0 ? s.a : s.b, {}, -1};
    return {Vec3::Zero(), rect, k == 0 ? from[side] : to[side]};
  }
  // Exactly zero length: a == b, or a side along a zero half-size.
  bool degenerate() const {
    if (side < 0) return s.a == s.b;
    return side % 2 == 0 ? rect.numbers().half_u == 0 : rect.numbers().half_v == 0;
  }
};

bool flat(const Rectangle& r) { return r.half_u == 0 || r.half_v == 0; }

// The point against the closed rectangle: its two triangles (a flat one is a segment).
void add_point_rectangle(Minimum& m, const PointSource& p, const SharedRectangle& r) {
  CGAL::Protect_FPU_rounding<true> rounding;  // interval arithmetic below
  const IK::Point_3 pi = p.get<IK>();
  const RectangleOf<IK> ri = r.get<IK>();
  if (flat(r.numbers())) {
    const IK::Segment_3 d = ri.diagonal();
    m.add(
        pi, d, [pi, d] { return distance2<IK>(pi, d); },
        [p, r] { return FT(distance2<EK>(p.get<EK>(), r.get<EK>().diagonal())); });
    return;
  }
  for (int i = 0; i < 2; ++i) {
    const IK::Triangle_3 t = ri.triangle(i);
    m.add(
        pi, t, [pi, t] { return CGAL::squared_distance(pi, t); },
        [p, r, i] { return FT(CGAL::squared_distance(p.get<EK>(), r.get<EK>().triangle(i))); });
  }
}

// A segment against a closed rectangle. If they meet, 0. Otherwise a closest pair has an
// end of the segment or a point of the rectangle's border in it (both are convex): the
// ends against the rectangle, the segment against the four sides. With `ends` = false
// the caller covers the ends itself.
void add_segment_rectangle(Minimum& m, const SegmentSource& s, const SharedRectangle& r, bool ends = true) {
  if (s.degenerate()) {
    if (ends) add_point_rectangle(m, s.end(0), r);
    return;
  }
  CGAL::Protect_FPU_rounding<true> rounding;  // interval arithmetic below
  const IK::Segment_3 si = s.get<IK>();
  const RectangleOf<IK> ri = r.get<IK>();
  if (flat(r.numbers())) {
    const IK::Segment_3 d = ri.diagonal();
    m.add(
        si, d, [si, d] { return distance2<IK>(si, d); },
        [s, r] { return FT(distance2<EK>(s.get<EK>(), r.get<EK>().diagonal())); });
    return;
  }
  for (int i = 0; i < 2; ++i) {
    const IK::Triangle_3 t = ri.triangle(i);
    m.meets(
        si, t, [&] { return bool(CGAL::do_intersect(si, t)); },
        [&] { return bool(CGAL::do_intersect(s.get<EK>(), r.get<EK>().triangle(i))); });
  }
  if (m.zero()) return;
  if (ends) {
    add_point_rectangle(m, s.end(0), r);
    add_point_rectangle(m, s.end(1), r);
  }
  for (int i = 0; i < 4; ++i) {
    const IK::Segment_3 side = ri.side(i);
    m.add(
        si, side, [si, side] { return distance2<IK>(si, side); },
        [s, r, i] { return FT(distance2<EK>(s.get<EK>(), r.get<EK>().side(i))); });
  }
}

// `bound` computes the distance in interval arithmetic (it may throw when a comparison
// is uncertain: then there is no bound); `exact` in exact arithmetic, when asked.
template <class A, class B, class Bound>
SquaredDistance make(const A& a, const B& b, Bound&& bound, std::function<FT()> exact) {
  Minimum m;
  m.add(a, b, std::forward<Bound>(bound), std::move(exact));
  return m.result();
}

int sign_of_compare(const FT& a, const FT& b) { return CGAL::compare(a, b) == CGAL::SMALLER ? -1 : (a == b ? 0 : 1); }

// sign(sqrt(d2) - length), exactly.
int distance_sign(const FT& d2, const FT& length) {
  if (CGAL::is_negative(length)) return 1;
  return sign_of_compare(d2, length * length);
}

// sign(x - e sqrt(nn)), exactly (nn > 0).
int sign_minus_root(const FT& x, const FT& e, const FT& nn) {
  if (!CGAL::is_negative(e)) {
    if (!CGAL::is_positive(x)) return CGAL::is_zero(x) && CGAL::is_zero(e) ? 0 : -1;
    return sign_of_compare(x * x, e * e * nn);
  }
  if (!CGAL::is_negative(x)) return 1;
  return sign_of_compare(e * e * nn, x * x);
}

FT sum(double a, double b, double c = 0.0) { return ft(a) + ft(b) + ft(c); }

// ---- Sweeps ---------------------------------------------------------------------------

struct Relative {  // A + t B, R
  Vector A, B;
  FT R;
};
Relative relative(const SphereSphereSweep& in) {
  return {exact(in.s0.center) - exact(in.s1.center), exact_vector(in.v0) - exact_vector(in.v1),
          ft(in.s0.radius) + ft(in.s1.radius)};
}

FT plane_value(const Plane& plane, const Point& x) {
  return exact_vector(plane.normal) * (x - CGAL::ORIGIN) + ft(plane.offset);
}
FT normal2(const Plane& plane) { return exact_vector(plane.normal).squared_length(); }

// The plane's value at the moving centre: f(t) = f0 + t g.
struct Linear {
  FT f0, g;
  FT at(const FT& t) const { return f0 + t * g; }
  // The smallest |f| over [0, t_end].
  FT smallest_abs(const FT& t_end) const {
    const FT f1 = at(t_end);
    if (sign_of(CGAL::sign(f0)) * sign_of(CGAL::sign(f1)) <= 0) return ft(0);
    return CGAL::min(CGAL::abs(f0), CGAL::abs(f1));
  }
};
Linear linear(const Plane& plane, const Vec3& center, const Vec3& velocity) {
  return {plane_value(plane, exact(center)), exact_vector(plane.normal) * exact_vector(velocity)};
}

// |normal| times the box's radius along the normal: sum_i h_i |n . axis_i|.
FT projected_radius(const Box& box, const Plane& plane) {
  const Vector n = exact_vector(plane.normal);
  FT rho = 0;
  for (int i = 0; i < 3; ++i) rho += ft(box.half_extents[i]) * CGAL::abs(n * exact_vector(box.axes.col(i)));
  return rho;
}

// The first root of a t^2 + 2 b t + c = 0 in doubles (reports only).
double first_root(double a, double b, double c) {
  const double disc = std::max(0.0, b * b - a * c);
  const double q = -b + std::sqrt(disc);
  return q > 0 ? c / q : 0.0;
}

bool exact_double(const FT& x, double d) { return std::isfinite(d) && x == ft(d); }

// Are x . y's products and partial sums exact in double, so that any order of summing
// gives the exact value?
bool dot_exact(const Vec3& x, const Vec3& y) {
  const double p[3] = {x[0] * y[0], x[1] * y[1], x[2] * y[2]};
  for (int i = 0; i < 3; ++i)
    if (!exact_double(ft(x[i]) * ft(y[i]), p[i])) return false;
  return exact_double(ft(p[0]) + ft(p[1]), p[0] + p[1]) && exact_double(ft(p[0]) + ft(p[2]), p[0] + p[2]) &&
         exact_double(ft(p[1]) + ft(p[2]), p[1] + p[2]) &&
         exact_double(ft(p[0]) + ft(p[1]) + ft(p[2]), p[0] + p[1] + p[2]);
}

}  // namespace

// ---- Distances --------------------------------------------------------------------------

double SquaredDistance::value() const {
  if (exact_->bounded && exact_->high <= 0) return 0.0;
  if (exact_->bounded && exact_->high - exact_->low <= 1e-13 * exact_->high) return 0.5 * (exact_->low + exact_->high);
  return rounded(exact_->exact());
}

double SquaredDistance::distance() const { return std::sqrt(value()); }

int SquaredDistance::compare(double l0, double l1, double l2) const {
  if (exact_->bounded) {
    CGAL::Protect_FPU_rounding<true> upward;
    const Interval length = Interval(l0) + Interval(l1) + Interval(l2);
    if (length.sup() < 0) return 1;
    if (length.inf() >= 0) {
      const Interval length2 = CGAL::square(length);
      if (exact_->high < length2.inf()) return -1;
      if (exact_->low > length2.sup()) return 1;
    }
  }
  return distance_sign(exact_->exact(), sum(l0, l1, l2));
}

SquaredDistance squared_distance(const Vec3& p, const Vec3& q) {
  const IK::Point_3 a = point_of<IK>(p), b = point_of<IK>(q);
  return make(
      a, b, [a, b] { return CGAL::squared_distance(a, b); },
      [p, q] { return FT(CGAL::squared_distance(point_of<EK>(p), point_of<EK>(q))); });
}
SquaredDistance squared_distance(const Vec3& p, const Segment& s) {
  const IK::Point_3 a = point_of<IK>(p);
  const IK::Segment_3 b = segment_of<IK>(s);
  return make(
      a, b, [a, b] { return distance2<IK>(a, b); },
      [p, s] { return FT(distance2<EK>(point_of<EK>(p), segment_of<EK>(s))); });
}
SquaredDistance squared_distance(const Segment& s0, const Segment& s1) {
  const IK::Segment_3 a = segment_of<IK>(s0), b = segment_of<IK>(s1);
  return make(
      a, b, [a, b] { return distance2<IK>(a, b); },
      [s0, s1] { return FT(distance2<EK>(segment_of<EK>(s0), segment_of<EK>(s1))); });
}
SquaredDistance squared_distance(const Vec3& p, const Rectangle& r) {
  Minimum m;
  add_point_rectangle(m, {p, {}, -1}, SharedRectangle(r));
  return m.result();
}
SquaredDistance squared_distance(const Segment& s, const Rectangle& r) {
  Minimum m;
  add_segment_rectangle(m, {s, {}, -1}, SharedRectangle(r));
  return m.result();
}
// Two rectangles: a closest pair has a point of some side of one of them (if both points
// were inside, the rectangles would be parallel there, and a side gets as close), and a
// side that meets the other rectangle has distance 0. So: the eight sides, each against
// the other rectangle (the corners once each rather than twice, as sides' ends).
SquaredDistance squared_distance(const Rectangle& r0, const Rectangle& r1) {
  Minimum m;
  const SharedRectangle a(r0), b(r1);
  for (int k = 0; k < 4; ++k) add_point_rectangle(m, {Vec3::Zero(), a, k}, b);
  for (int k = 0; k < 4; ++k) add_point_rectangle(m, {Vec3::Zero(), b, k}, a);
  for (int i = 0; i < 4 && !m.zero(); ++i) add_segment_rectangle(m, {{}, a, i}, b, false);
  for (int i = 0; i < 4 && !m.zero(); ++i) add_segment_rectangle(m, {{}, b, i}, a, false);
  return m.result();
}

bool rectangle_point_reproduces(const Rectangle& r, double s, double t, const Vec3& x, double tolerance) {
  const Point p = exact(r.center) + exact_vector(r.u) * ft(s) + exact_vector(r.v) * ft(t);
  return CGAL::squared_distance(p, exact(x)) <= squared(ft(tolerance));
}

// ---- Sweeps -------------------------------------------------------------------------------

int gap_sign(const SphereSphereSweep& in, double t, double extra) {
  const Relative m = relative(in);
  return distance_sign((m.A + m.B * ft(t)).squared_length(), m.R + ft(extra));
}

int min_gap_sign(const SphereSphereSweep& in, double t_end, double extra) {
  // |A + t B|^2 = a t^2 + 2 b t + |A|^2 is smallest at t = -b / a, clamped to [0, t_end].
  const Relative m = relative(in);
  const FT a = m.B.squared_length(), b = m.A * m.B;
  FT t = 0;
  if (CGAL::is_positive(a)) t = CGAL::min(CGAL::max(-b / a, ft(0)), ft(t_end));
  return distance_sign((m.A + m.B * t).squared_length(), m.R + ft(extra));
}

int gap_sign(const SpherePlaneSweep& in, double t, double extra) {
  const FT f = linear(in.plane, in.sphere.center, in.velocity).at(ft(t));
  return distance_sign(f * f / normal2(in.plane), ft(in.sphere.radius) + ft(extra));
}

int min_gap_sign(const SpherePlaneSweep& in, double t_end, double extra) {
  const FT f = linear(in.plane, in.sphere.center, in.velocity).smallest_abs(ft(t_end));
  return distance_sign(f * f / normal2(in.plane), ft(in.sphere.radius) + ft(extra));
}

int gap_sign(const BoxPlaneSweep& in, double t, double extra) {
  const FT f = linear(in.plane, in.box.center, in.velocity).at(ft(t));
  return sign_minus_root(CGAL::abs(f) - projected_radius(in.box, in.plane), ft(extra), normal2(in.plane));
}

int min_gap_sign(const BoxPlaneSweep& in, double t_end, double extra) {
  const FT f = linear(in.plane, in.box.center, in.velocity).smallest_abs(ft(t_end));
  return sign_minus_root(f - projected_radius(in.box, in.plane), ft(extra), normal2(in.plane));
}

double first_contact(const SphereSphereSweep& in, double t_end) {
  if (gap_sign(in, 0.0, 0.0) <= 0) return 0.0;
  if (min_gap_sign(in, t_end, 0.0) > 0) return -1.0;
  const Relative m = relative(in);
  const double a = rounded(m.B.squared_length()), b = rounded(m.A * m.B), c = rounded(m.A.squared_length() - m.R * m.R);
  return std::clamp(first_root(a, b, c), 0.0, t_end);
}

double first_contact(const SpherePlaneSweep& in, double t_end) {
  if (gap_sign(in, 0.0, 0.0) <= 0) return 0.0;
  if (min_gap_sign(in, t_end, 0.0) > 0) return -1.0;
  // t = (|f0| - r |n|) / |g|, each term divided by |g| exactly before rounding, so that
  // normals of any length (|n|^2 beyond the doubles) still give the right number.
  const Linear f = linear(in.plane, in.sphere.center, in.velocity);
  const double t = rounded(CGAL::abs(f.f0) / CGAL::abs(f.g)) -
                   in.sphere.radius * std::sqrt(rounded(normal2(in.plane) / (f.g * f.g)));
  return std::clamp(t, 0.0, t_end);
}

double first_contact(const BoxPlaneSweep& in, double t_end) {
  if (gap_sign(in, 0.0, 0.0) <= 0) return 0.0;
  if (min_gap_sign(in, t_end, 0.0) > 0) return -1.0;
  const Linear f = linear(in.plane, in.box.center, in.velocity);
  return std::clamp(rounded((CGAL::abs(f.f0) - projected_radius(in.box, in.plane)) / CGAL::abs(f.g)), 0.0, t_end);
}

// The moving centre c + t v, exactly.
Point centre_at(const SphereCapsuleSweep& in, const FT& t) {
  return exact(in.sphere.center) + exact_vector(in.velocity) * t;
}
FT grown_radius(const SphereCapsuleSweep& in) { return ft(in.sphere.radius) + ft(in.capsule.radius); }

int gap_sign(const SphereCapsuleSweep& in, double t, double extra) {
  return distance_sign(distance2<Epeck>(centre_at(in, ft(t)), exact(in.capsule.axis)), grown_radius(in) + ft(extra));
}

int min_gap_sign(const SphereCapsuleSweep& in, double t_end, double extra) {
  // The smallest distance over [0, t_end] is that of the path's segment to the axis.
  const Epeck::Segment_3 path(centre_at(in, ft(0)), centre_at(in, ft(t_end)));
  return distance_sign(distance2<Epeck>(path, exact(in.capsule.axis)), grown_radius(in) + ft(extra));
}

double first_contact(const SphereCapsuleSweep& in, double t_end) {
  if (gap_sign(in, 0.0, 0.0) <= 0) return 0.0;
  if (min_gap_sign(in, t_end, 0.0) > 0) return -1.0;
  // Exact decisions found contact; the time (reports only) in long double: the first
  // root of the side (inside the slab) and of the two end spheres.
  using L = long double;
  const auto v = [](const Vec3& x) { return Eigen::Matrix<L, 3, 1>(x.x(), x.y(), x.z()); };
  const Eigen::Matrix<L, 3, 1> c = v(in.sphere.center), w = v(in.velocity), a = v(in.capsule.axis.a),
                               d = v(in.capsule.axis.b) - a;
  const L R = L(in.sphere.radius) + L(in.capsule.radius), R2 = R * R;
  L best = std::numeric_limits<L>::infinity();
  const auto quadratic = [&](L qa, L qb, L qc) -> L {  // first root of qa t^2 + 2 qb t + qc, qc > 0
    if (qa <= 0 || qb >= 0) return std::numeric_limits<L>::infinity();
    const L disc = qb * qb - qa * qc;
    if (disc < 0) return std::numeric_limits<L>::infinity();
    return qc / (-qb + std::sqrt(disc));
  };
  for (const auto& end : {a, Eigen::Matrix<L, 3, 1>(a + d)}) {
    const Eigen::Matrix<L, 3, 1> m = c - end;
    best = std::min(best, quadratic(w.squaredNorm(), m.dot(w), m.squaredNorm() - R2));
  }
  if (d.squaredNorm() > 0) {
    const Eigen::Matrix<L, 3, 1> md = (c - a).cross(d), wd = w.cross(d);
    const L t = quadratic(wd.squaredNorm(), md.dot(wd), md.squaredNorm() - R2 * d.squaredNorm());
    const L along = std::isfinite(t) ? (c - a + t * w).dot(d) : L(-1);
    if (along >= 0 && along <= d.squaredNorm()) best = std::min(best, t);
  }
  if (best <= L(t_end)) return std::clamp(double(best), 0.0, t_end);
  // A graze lost to rounding: bisection on the exact sign of the smallest gap over [0, t].
  double low = 0.0, high = t_end;
  for (int i = 0; i < 60 && high - low > 1e-15 * t_end; ++i) {
    const double mid = 0.5 * (low + high);
    (min_gap_sign(in, mid, 0.0) <= 0 ? high : low) = mid;
  }
  return high;
}

bool within_capsule(const Capsule& capsule, const Vec3& x, double tolerance) {
  return distance_sign(distance2<Epeck>(exact(x), exact(capsule.axis)), ft(capsule.radius) + ft(tolerance)) <= 0;
}

bool sphere_sweep_exact_and_steep(const SphereSphereSweep& in) {
  const Vec3 A = in.s0.center - in.s1.center, B = in.v0 - in.v1;
  const double R = in.s0.radius + in.s1.radius;
  for (int i = 0; i < 3; ++i) {
    if (!exact_double(ft(in.s0.center[i]) - ft(in.s1.center[i]), A[i])) return false;
    if (!exact_double(ft(in.v0[i]) - ft(in.v1[i]), B[i])) return false;
  }
  if (!exact_double(ft(in.s0.radius) + ft(in.s1.radius), R) || !exact_double(ft(R) * ft(R), R * R)) return false;
  if (!dot_exact(A, A) || !dot_exact(A, B) || !dot_exact(B, B)) return false;
  if (!exact_double(ft(A.dot(A)) - ft(R * R), A.dot(A) - R * R)) return false;
  const FT a = ft(B.dot(B)), b = ft(A.dot(B)), c = ft(A.dot(A)) - ft(R * R);
  return CGAL::is_positive(c) && CGAL::is_negative(b) && CGAL::is_positive(a) && 3 * b * b >= 4 * a * c;
}

bool within_moving_sphere(const Sphere& s, const Vec3& v, double t, const Vec3& x, double tolerance) {
  const Point c = exact(s.center) + exact_vector(v) * ft(t);
  return distance_sign(CGAL::squared_distance(c, exact(x)), ft(s.radius) + ft(tolerance)) <= 0;
}

bool within_plane(const Plane& plane, const Vec3& x, double tolerance) {
  return squared(plane_value(plane, exact(x))) <= squared(ft(tolerance)) * normal2(plane);
}

bool within_moving_box(const Box& box, const Vec3& v, double t, const Vec3& x, double tolerance) {
  const Vector d = exact(x) - (exact(box.center) + exact_vector(v) * ft(t));
  for (int i = 0; i < 3; ++i) {
    const Vector axis = exact_vector(box.axes.col(i));
    if (CGAL::abs(d * axis) > (ft(box.half_extents[i]) + ft(tolerance)) * axis.squared_length()) return false;
  }
  return true;
}

}  // namespace oracle
