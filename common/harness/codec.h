// Text for inputs and answers. Two forms:
//  - describe(x): what a person reads in a failure report ("a=(0, 0, -1) b=(0, 0, 1)").
//  - a replay token "query:v1,v2,...": every double of the input in its shortest exact
//    text, so `./labkit check --case TOKEN` and the viewer rebuild the input bit for bit.
// A lab's input struct joins in by listing its fields once (common/fields.h):
//
//   struct SegmentTriangleInput { Segment segment; Triangle triangle; };
//   LABKIT_FIELDS(SegmentTriangleInput, segment, triangle)
#pragma once

#include "common/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace labkit {

// Shortest text that reads back as the same double: "0.1", "-3", "1e-06", "inf".
std::string fmt(double x);
std::string fmt(const Vec2& v);
std::string fmt(const Vec3& v);

// A malformed replay token; the message says what was wrong and where.
struct BadToken : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

namespace codec {

// Matches any field list; used only to detect whether a type has one.
struct AnyFieldVisitor {
  template <class F> void operator()(const char*, F&) const {}
};
template <class T> using HasFields = decltype(fields(std::declval<T&>(), AnyFieldVisitor{}));

// The flat list of numbers behind an input, each with its kind: a length (a coordinate,
// perturbed by the ambiguity check relative to the input's scale S), a unit-free number
// (a rotation entry, perturbed relative to 1), or a count or flag (never perturbed).
enum class Kind : unsigned char { length, unit, count };

struct Values {
  std::vector<double> numbers;
  std::vector<Kind> kinds;

  // The input's length scale S: its largest |length| (0 when it has none). A length that
  // is not finite makes S infinite (or NaN), unless `finite_only`, which leaves it out.
  // The ambiguity check, the domain check and the scaling of cases into the domain all
  // measure S with this one definition.
  double largest_length(bool finite_only = false) const {
    double s = 0;
    for (std::size_t i = 0; i < numbers.size(); ++i) {
      if (kinds[i] != Kind::length) continue;
      if (!std::isfinite(numbers[i])) {
        if (finite_only) continue;
        return std::abs(numbers[i]);
      }
      s = std::max(s, std::abs(numbers[i]));
    }
    return s;
  }
};

class Writer {
 public:
  void real(double x) { add(x, Kind::length); }
  void unit(double x) { add(x, Kind::unit); }
  void count(std::size_t n) { add(double(n), Kind::count); }
  const Values& values() const { return values_; }

 private:
  void add(double x, Kind kind) {
    values_.numbers.push_back(x);
    values_.kinds.push_back(kind);
  }
  Values values_;
};

class Reader {
 public:
  explicit Reader(std::vector<double> numbers) : numbers_(std::move(numbers)) {}
  double real();
  std::size_t count(std::size_t limit = 1000000);
  bool done() const { return next_ == numbers_.size(); }
  std::size_t position() const { return next_; }

 private:
  std::vector<double> numbers_;
  std::size_t next_ = 0;
};

template <class T, std::size_t N> void encode(Writer& w, const std::array<T, N>& xs);
template <class T, std::size_t N> void decode(Reader& r, std::array<T, N>& xs);
template <class T> void encode(Writer& w, const std::vector<T>& xs);
template <class T> void decode(Reader& r, std::vector<T>& xs);
template <class T, class = HasFields<T>> void encode(Writer& w, const T& x);
template <class T, class = HasFields<T>> void decode(Reader& r, T& x);

// Numbers, and the geometry types whose numbers are more than their fields in order: a
// mesh's counts and indices, a rectangle's and a matrix's unit-free entries. The other
// geometry types list their fields (common/geometry.h) and go field by field.
inline void encode(Writer& w, double x) { w.real(x); }
inline void decode(Reader& r, double& x) { x = r.real(); }
inline void encode(Writer& w, int x) { w.count(std::size_t(x < 0 ? 0 : x)); }
inline void decode(Reader& r, int& x) { x = int(r.count()); }
inline void encode(Writer& w, bool x) { w.count(x ? 1 : 0); }
inline void decode(Reader& r, bool& x) { x = r.count(1) != 0; }
void encode(Writer& w, const Vec3& v);
void decode(Reader& r, Vec3& v);
void encode(Writer& w, const Vec2& v);
void decode(Reader& r, Vec2& v);
void encode(Writer& w, const Mesh& m);
void decode(Reader& r, Mesh& m);
void encode(Writer& w, const RigidTransform& m);
void decode(Reader& r, RigidTransform& m);
void encode(Writer& w, const Mat4& m);
void decode(Reader& r, Mat4& m);
void encode(Writer& w, const Mat3& m);  // unit-free entries (rotations)
void decode(Reader& r, Mat3& m);
void encode(Writer& w, const Rectangle& r);
void decode(Reader& r, Rectangle& rect);

template <class T, std::size_t N> void encode(Writer& w, const std::array<T, N>& xs) {
  for (const T& x : xs) encode(w, x);
}
template <class T, std::size_t N> void decode(Reader& r, std::array<T, N>& xs) {
  for (T& x : xs) decode(r, x);
}
template <class T> void encode(Writer& w, const std::vector<T>& xs) {
  w.count(xs.size());
  for (const T& x : xs) encode(w, x);
}
template <class T> void decode(Reader& r, std::vector<T>& xs) {
  xs.resize(r.count());
  for (T& x : xs) decode(r, x);
}

// Structs that list their fields (see the top of this file).
template <class T, class> void encode(Writer& w, const T& x) {
  fields(const_cast<T&>(x), [&](const char*, auto& field) { encode(w, field); });
}
template <class T, class> void decode(Reader& r, T& x) {
  fields(x, [&](const char*, auto& field) { decode(r, field); });
}

}  // namespace codec

// describe(): readable text.
template <class T, std::size_t N> std::string describe(const std::array<T, N>& xs);
template <class T> std::string describe(const std::vector<T>& xs);
template <class T, class = codec::HasFields<T>> std::string describe(const T& x);
std::string describe(double x);
std::string describe(int x);
std::string describe(bool x);
std::string describe(const Vec2& v);
std::string describe(const Vec3& v);
std::string describe(const Segment& s);
std::string describe(const Triangle& t);
std::string describe(const Plane& p);
std::string describe(const Frustum& f);
std::string describe(const Mesh& m);
std::string describe(const RigidTransform& m);
std::string describe(const Mat4& m);
std::string describe(const Mat3& m);
std::string describe(const Sphere& s);
std::string describe(const Capsule& c);
std::string describe(const Rectangle& r);
std::string describe(const Lozenge& l);
std::string describe(const Box& b);
std::string describe(const Aabb& b);

template <class T, std::size_t N> std::string describe(const std::array<T, N>& xs) {
  std::string s = "[";
  for (std::size_t i = 0; i < N; ++i) s += (i ? ", " : "") + describe(xs[i]);
  return s + "]";
}
template <class T> std::string describe(const std::vector<T>& xs) {
  std::string s = "[";
  for (std::size_t i = 0; i < xs.size(); ++i) s += (i ? ", " : "") + describe(xs[i]);
  return s + "]";
}
template <class T, class> std::string describe(const T& x) {
  std::string s;
  fields(const_cast<T&>(x), [&](const char* name, auto& field) {
    s += (s.empty() ? "" : "\n") + std::string(name) + ": " + describe(field);
  });
  return s;
}

// The numbers of an input, and the input rebuilt from them.
template <class T> codec::Values values_of(const T& x) {
  codec::Writer w;
  codec::encode(w, x);
  return w.values();
}

template <class T> T from_numbers(std::vector<double> numbers) {
  codec::Reader r(std::move(numbers));
  T x{};
  codec::decode(r, x);
  if (!r.done())
    throw BadToken("the case has " + std::to_string(r.position()) +
                   " numbers too few for its query, or extra numbers at the end");
  return x;
}

// "query:v1,v2,..." and back.
template <class T> std::string replay_token(const std::string& query, const T& x) {
  std::string s = query + ":";
  const auto v = values_of(x);
  for (std::size_t i = 0; i < v.numbers.size(); ++i) s += (i ? "," : "") + fmt(v.numbers[i]);
  return s;
}

struct ParsedToken {
  std::string query;
  std::vector<double> numbers;
};
// Throws BadToken with a one-line reason.
ParsedToken parse_token(const std::string& token);

template <class T> T input_from_token(const ParsedToken& token) {
  try {
    return from_numbers<T>(token.numbers);
  } catch (const BadToken& e) {
    throw BadToken("replay case for " + token.query + ": " + e.what());
  }
}

}  // namespace labkit
