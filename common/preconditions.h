// The header's preconditions, checked the same way in every lab: invalid input is
// refused with std::invalid_argument whose message names the function, the argument and
// the rule, then the value it got ("segment_plane: segment.a must be finite, got (nan, 0,
// 0)"). A NaN would otherwise fail every comparison and pass for an answer. These are the
// checks every lab shares, written once; a lab's own rules (a plane's normal non-zero, a
// tolerance's floor) are built from them.
//
// The references use them, and so may your file: like the geometry types, this header is
// one a lab file may include. No step grades invalid input, so checking is your choice.
// Their code is in preconditions.cpp, compiled once with the geometry types: a file that
// calls them does not compile their strings again at every save.
#pragma once

#include "common/geometry.h"

#include <string>

namespace labkit::preconditions {

// A value as it is, to 17 digits: a value one ulp off shows.
std::string text(double x);
std::string text(const Vec3& v);
inline std::string text(const std::string& s) { return s; }
std::string text(int i);

// "query: argument must rule, got value".
[[noreturn]] void reject(const std::string& query, const std::string& argument, const std::string& rule,
                         const std::string& got);

// Rejects unless ok; the message (and its strings) is built only then.
template <class Value>
void require(bool ok, const char* query, const std::string& argument, const char* rule, const Value& got) {
  if (!ok) reject(query, argument, rule, text(got));
}

void require_finite(const char* query, const std::string& argument, double x);
void require_finite(const char* query, const std::string& argument, const Vec3& v);
// A length, a radius, a duration: finite and >= 0.
void require_size(const char* query, const std::string& argument, double x);
// A mass, a tolerance: finite and > 0.
void require_positive(const char* query, const std::string& argument, double x);
// "Unit length" and "perpendicular" are checked to 1e-6: loose enough for any rounded
// rotation, tight enough to catch a forgotten normalisation.
void require_unit(const char* query, const std::string& argument, const Vec3& v);
void require_perpendicular(const char* query, const std::string& argument, const Vec3& a, const Vec3& b);
// A box's axes: the columns unit length and pairwise perpendicular (to 1e-6).
void require_orthonormal(const char* query, const std::string& argument, const Mat3& axes);

// The geometry types' own rules, the argument named `name` ("segment", "pair.a"). Each
// checks first and builds the names only for the part that breaks a rule: a query on a
// valid input spends a few comparisons here, never a string.
void require_valid(const char* query, const std::string& name, const Segment& s);
void require_valid(const char* query, const std::string& name, const Triangle& t);
void require_valid(const char* query, const std::string& name, const Sphere& s);
// A box: its centre finite, its half extents finite and >= 0, its axes orthonormal.
void require_valid(const char* query, const std::string& name, const Box& b);
// A mesh has thousands of vertices: each is checked, and a name is built only for the
// one that breaks the rule.
void require_valid(const char* query, const std::string& name, const Mesh& mesh);
// A pose: finite, and rigid (its linear part a rotation to 1e-6: orthonormal, determinant
// positive, no mirror).
void require_valid(const char* query, const std::string& name, const RigidTransform& pose);

}  // namespace labkit::preconditions
