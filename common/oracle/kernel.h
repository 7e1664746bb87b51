// Private to the oracle's .cpp files: the CGAL kernels and conversions. Nothing outside
// common/oracle/ includes this (or any CGAL header).
#pragma once

#include "common/geometry.h"
#include "common/oracle/not_finite.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

namespace oracle::kernel {

// Exact predicates on double input: fast, and exact for every sign it returns.
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
// Exact constructions: every new point is an exact rational, rounded only on the way out.
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Epeck::FT;

// Every double enters the exact world through these: a NaN or an infinity throws
// NotFinite (not_finite.h) instead of making GMP abort the judge's process.
inline FT ft(double x) { return FT(finite(x)); }
inline const FT& ft(const FT& x) { return x; }
using oracle::finite;
inline const labkit::Vec3& finite(const labkit::Vec3& v) {
  if (!v.allFinite()) throw NotFinite();
  return v;
}

inline Epick::Point_3 fast(const labkit::Vec3& v) { return {finite(v.x()), finite(v.y()), finite(v.z())}; }
inline Epeck::Point_3 exact(const labkit::Vec3& v) { return {finite(v.x()), finite(v.y()), finite(v.z())}; }
inline Epeck::Triangle_3 exact(const labkit::Triangle& t) { return {exact(t.v0), exact(t.v1), exact(t.v2)}; }
inline Epeck::Segment_3 exact(const labkit::Segment& s) { return {exact(s.a), exact(s.b)}; }

// Rounds an exact number to a double within a relative 1e-12 of it (usually the nearest
// one): the lazy kernel's interval is used when it is that tight, and the exact rational
// is computed only when it is not (near zero, or after cancellation). 1e-12 is a
// thousand times below every tolerance in the kit.
inline double rounded(const FT& x) {
  thread_local const bool precision_set = [] {
    FT::set_relative_precision_of_to_double(1e-12);
    return true;
  }();
  (void)precision_set;
  return CGAL::to_double(x);
}
inline labkit::Vec3 rounded(const Epeck::Point_3& p) { return {rounded(p.x()), rounded(p.y()), rounded(p.z())}; }

inline int sign_of(CGAL::Sign s) { return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0); }

}  // namespace oracle::kernel
