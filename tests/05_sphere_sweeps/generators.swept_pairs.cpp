// Step 3's inputs (lab 05): two sphere-swept volumes, the distance steps' cores with
// radii around their exact distance, or canonical cores exactly touching by construction.
#include "05_sphere_sweeps/judge.h"

#include "common/generators/generators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace labkit::gen {

using lab05::CapsuleLozenge;
using lab05::CapsulePair;
using lab05::LozengePair;
using lab05::SphereCapsule;
using lab05::SphereLozenge;
using lab05::SpherePair;

namespace {

// A hair just outside the doubt band of the tests (20 tol = 20e-9 S): m * 1e-9 S for m
// from 24 to 2^24, log-uniform. The near cases stay decisive; exactly touching radii
// belong to step 7.
double decisive_hair(double S) {
  return 24 * std::ldexp(1.0, *rc::gen::inRange(0, 20)) * (1 + *rc::gen::inRange(0, 8) / 8.0) * 1e-9 * S;
}

// Radii around the cores' exact distance d (S: the pair's scale without the radii): a
// hair inside or outside, clearly apart or overlapping, or a plain lattice length.
double radius_total(double d, double size) {
  switch (*rc::gen::weightedElement<int>({{4, 1}, {2, 2}, {2, 3}})) {
    case 1: {
      const double hair = decisive_hair(std::max(size, d) * 1.01);
      return d > hair && *rc::gen::arbitrary<bool>() ? d - hair : d + hair;
    }
    // Cores that meet (d = 0) with radii 0 touch exactly: step 7's; here they overlap.
    case 2: return d > 0 ? d * *rc::gen::element(0.5, 0.875, 1.125, 2.0) : decisive_hair(size);
    default: return *rc::gen::inRange(1, 9) / 4.0 * std::max(size, 1e-300);
  }
}

// Exact families: radii that sum to an integer (times the scale) at or next to d.
double exact_radius_total(double d, double unit) {
  const double k = std::floor(d / unit);
  return std::max(0.0, *rc::gen::element(k - 1, k, k + 1, k + 2) * unit);
}

// The unit of an exact family's lattice: the largest power of two dividing every
// coordinate (so integers times it).
double lattice_unit(const std::vector<double>& numbers) {
  double unit = std::ldexp(1.0, 30);
  for (double x : numbers) {
    if (x == 0) continue;
    int e = 0;
    std::frexp(x, &e);
    double low = std::ldexp(1.0, e);  // halve until it divides x: x's lowest set bit
    while (std::fmod(std::abs(x), low) != 0) low /= 2;
    unit = std::min(unit, low);
  }
  return unit;
}

// Exactly touching cores: both in parallel planes h apart (z = 0 and z = h in a
// canonical frame), each through a common point P of the xy-plane, so their distance is
// exactly h; then a signed permutation of the axes and an integer shift.
struct Canonical {
  Mat3 frame = Mat3::Identity();
  Vec3 shift = Vec3::Zero();
  double s = 1.0, h = 1.0;
  Vec3 P = Vec3::Zero();
  Vec3 at(const Vec3& x) const { return frame * x + shift; }
};

Canonical canonical() {
  Canonical c;
  c.s = *scale();
  c.h = *rc::gen::inRange(0, 5) * c.s;
  c.P = Vec3(*integer(8), *integer(8), 0) * c.s;
  std::array<int, 3> order{0, 1, 2};
  std::rotate(order.begin(), order.begin() + *rc::gen::inRange(0, 3), order.end());
  c.frame = Mat3::Zero();
  for (int i = 0; i < 3; ++i) c.frame(order[i], i) = *rc::gen::element(-1.0, 1.0);
  c.shift = *lattice_point(c.s, 16);
  return c;
}

Vec3 in_plane(const Canonical& c, double z) { return Vec3(*integer(4), *integer(4), 0) * c.s + Vec3(0, 0, z); }

Vec3 canonical_point(const Canonical& c, double z) { return c.at(c.P + Vec3(0, 0, z)); }
Segment canonical_segment(const Canonical& c, double z) {
  const Vec3 d = in_plane(c, 0);
  const int k = *rc::gen::inRange(0, 3);
  return {c.at(c.P + Vec3(0, 0, z) + k * d), c.at(c.P + Vec3(0, 0, z) - d)};
}
Rectangle canonical_rectangle(const Canonical& c, double z) {
  const double hu = *rc::gen::inRange(0, 5) * c.s, hv = *rc::gen::inRange(0, 5) * c.s;
  const Vec3 offset(*rc::gen::inRange(-int(hu / c.s), int(hu / c.s) + 1) * c.s,
                    *rc::gen::inRange(-int(hv / c.s), int(hv / c.s) + 1) * c.s, 0);
  return {c.at(c.P + Vec3(0, 0, z) + offset), c.frame.col(0) * *rc::gen::element(-1.0, 1.0),
          c.frame.col(1) * *rc::gen::element(-1.0, 1.0), hu, hv};
}

template <class Pair> Pair with_radii(Pair p, double total) {
  const auto [r0, r1] = *split_radius(total);
  p.a.radius = r0;
  p.b.radius = r1;
  return p;
}

// The numbers of a shape's core (coordinates and half-sizes), for the exact families'
// lattice unit and for the scale of the near-touching radii.
void core_numbers(const Sphere& x, std::vector<double>& out) {
  out.insert(out.end(), x.center.data(), x.center.data() + 3);
}
void core_numbers(const Capsule& x, std::vector<double>& out) {
  out.insert(out.end(), x.axis.a.data(), x.axis.a.data() + 3);
  out.insert(out.end(), x.axis.b.data(), x.axis.b.data() + 3);
}
void core_numbers(const Lozenge& x, std::vector<double>& out) {
  out.insert(out.end(), x.rectangle.center.data(), x.rectangle.center.data() + 3);
  out.push_back(x.rectangle.half_u);
  out.push_back(x.rectangle.half_v);
}

// One generator per pair type: the distance steps' cores with radii around their exact
// distance, or (more often in the exact families) canonical cores exactly h apart with
// radii summing to h.
template <class Pair, class Cores, class FromCores, class Canon>
rc::Gen<Pair> pair_generator(const rc::Gen<Cores>& cores, bool exact, FromCores from_cores, Canon canon) {
  const rc::Gen<Pair> around = rc::gen::exec([=] {
    const Pair p = from_cores(*cores);
    std::vector<double> numbers;
    core_numbers(p.a, numbers);
    core_numbers(p.b, numbers);
    double size = 0;
    for (double x : numbers) size = std::max(size, std::abs(x));
    const double d = core_distance(p).distance();
    return with_radii(p, exact ? exact_radius_total(d, lattice_unit(numbers)) : radius_total(d, size));
  });
  // Cores exactly h apart: radii summing to h (exact, step 7), or a decisive hair off it.
  const rc::Gen<Pair> touching = rc::gen::exec([=] {
    const Canonical k = canonical();
    const Pair p = canon(k);
    if (exact) return with_radii(p, k.h);
    std::vector<double> numbers;
    core_numbers(p.a, numbers);
    core_numbers(p.b, numbers);
    double size = k.h;
    for (double x : numbers) size = std::max(size, std::abs(x));
    return with_radii(p, radius_total(k.h, size));
  });
  return rc::gen::weightedOneOf<Pair>({{exact ? 1 : 6, around}, {1, touching}});
}

// Parallel axes exactly n apart where finding the closest pair needs a division: the
// first axis runs along an integer d, the second starts at an integer w whose projection
// onto the first, t = (w . d) / |d|^2, lies inside it but is not a dyadic fraction, and
// |w|^2 |d|^2 - (w . d)^2 = n^2 |d|^2 for an integer n. The constructed closest points
// are rounded, so a rounded distance can come out a hair above r0 + r1 = n: only exact
// products of the input decide it. (The small table of such d and w is searched once.)
CapsulePair parallel_touching() {
  struct Triple {
    Vec3 d, w;
    double n;
  };
  static const std::vector<Triple> table = [] {
    std::vector<Triple> out;
    for (int i = 0; i < 9 * 9 * 9 * 9 * 9 * 9; ++i) {
      int c[6], k = i;
      for (int& x : c) x = k % 9 - 4, k /= 9;
      const long dd = c[0] * c[0] + c[1] * c[1] + c[2] * c[2], ww = c[3] * c[3] + c[4] * c[4] + c[5] * c[5];
      const long wd = c[0] * c[3] + c[1] * c[4] + c[2] * c[5];
      if (dd == 0 || (dd & (dd - 1)) == 0 || wd <= 0 || wd >= dd || (ww * dd - wd * wd) % dd != 0) continue;
      const long n2 = (ww * dd - wd * wd) / dd, n = std::lround(std::sqrt(double(n2)));
      if (n > 0 && n * n == n2) out.push_back({Vec3(c[0], c[1], c[2]), Vec3(c[3], c[4], c[5]), double(n)});
    }
    return out;
  }();
  const Triple& x = *rc::gen::elementOf(table);
  const double s = *scale();
  const Vec3 a = *lattice_point(s, 8);
  const double along = *rc::gen::element(-2.0, -1.0, 1.0, 2.0);
  const CapsulePair p{{{a, a + s * x.d}, 0}, {{a + s * x.w, a + s * (x.w + along * x.d)}, 0}};
  return with_radii(p, x.n * s);
}

}  // namespace

rc::Gen<SpherePair> sphere_pair(bool exact) {
  return pair_generator<SpherePair>(
      point_segment(exact), exact,
      [](const PointSegmentPair& c) {
    return SpherePair{{c.p, 0}, {c.segment.b, 0}};
      },
      [](const Canonical& k) {
    return SpherePair{{canonical_point(k, 0), 0}, {canonical_point(k, k.h), 0}};
  });
}
rc::Gen<SphereCapsule> sphere_capsule(bool exact) {
  return pair_generator<SphereCapsule>(
      point_segment(exact), exact,
      [](const PointSegmentPair& c) {
    return SphereCapsule{{c.p, 0}, {c.segment, 0}};
      },
      [](const Canonical& k) {
    return SphereCapsule{{canonical_point(k, k.h), 0}, {canonical_segment(k, 0), 0}};
  });
}
rc::Gen<SphereLozenge> sphere_lozenge(bool exact) {
  return pair_generator<SphereLozenge>(
      point_rectangle(exact), exact,
      [](const PointRectanglePair& c) {
    return SphereLozenge{{c.p, 0}, {c.rectangle, 0}};
      },
      [](const Canonical& k) {
    return SphereLozenge{{canonical_point(k, k.h), 0}, {canonical_rectangle(k, 0), 0}};
  });
}
rc::Gen<CapsulePair> capsule_pair(bool exact) {
  const rc::Gen<CapsulePair> families = pair_generator<CapsulePair>(
      segment_pair(exact), exact,
      [](const SegmentPair& c) {
    return CapsulePair{{c.first, 0}, {c.second, 0}};
      },
      [](const Canonical& k) {
    return CapsulePair{{canonical_segment(k, 0), 0}, {canonical_segment(k, k.h), 0}};
  });
  if (!exact) return families;
  return rc::gen::weightedOneOf<CapsulePair>({{4, families}, {1, rc::gen::exec(parallel_touching)}});
}
rc::Gen<CapsuleLozenge> capsule_lozenge(bool exact) {
  return pair_generator<CapsuleLozenge>(
      segment_rectangle(exact), exact,
      [](const SegmentRectanglePair& c) {
    return CapsuleLozenge{{c.segment, 0}, {c.rectangle, 0}};
      },
      [](const Canonical& k) {
    return CapsuleLozenge{{canonical_segment(k, k.h), 0}, {canonical_rectangle(k, 0), 0}};
  });
}
rc::Gen<LozengePair> lozenge_pair(bool exact) {
  return pair_generator<LozengePair>(
      rectangle_pair(exact), exact,
      [](const RectanglePair& c) {
    return LozengePair{{c.first, 0}, {c.second, 0}};
      },
      [](const Canonical& k) {
    return LozengePair{{canonical_rectangle(k, 0), 0}, {canonical_rectangle(k, k.h), 0}};
  });
}

}  // namespace labkit::gen
