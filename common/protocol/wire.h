// The bytes that cross between the judge's process and the process that runs the code
// under test (common/protocol/answerer.h). Everything is copied bit for bit: a double
// arrives as the same double, so the judge sees exactly the answer that was computed.
//
//   wire::Writer w;  wire::put(w, segment);  wire::put(w, triangle);
//   wire::Reader r(w.bytes());  wire::get(r, segment);  ...
//
// A struct crosses field by field when it lists its fields (LABKIT_FIELDS, common/fields.h):
// the geometry types of common/geometry.h and each lab's own. The reader trusts nothing: every count and size is
// checked against what is left, and a short or malformed message throws wire::Error
// instead of reading past the end.
#pragma once

#include "common/geometry.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace labkit::wire {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Matches any field list; used only to detect whether a type has one.
struct AnyField {
  template <class F> void operator()(const char*, F&) const {}
};
template <class T> using HasFields = decltype(fields(std::declval<T&>(), AnyField{}));
template <class T, class = void> struct HasFieldList : std::false_type {};
template <class T> struct HasFieldList<T, std::void_t<HasFields<T>>> : std::true_type {};
template <class T> struct IsVector : std::false_type {};
template <class T, class A> struct IsVector<std::vector<T, A>> : std::true_type {};
template <class T> struct IsArray : std::false_type {};
template <class T, std::size_t N> struct IsArray<std::array<T, N>> : std::true_type {};
template <class T> struct IsMatrix : std::false_type {};
template <int R, int C, int O> struct IsMatrix<Eigen::Matrix<double, R, C, O, R, C>> : std::true_type {};

class Writer {
 public:
  void raw(const void* data, std::size_t size) { bytes_.append(static_cast<const char*>(data), size); }
  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : at_(bytes.data()), end_(bytes.data() + bytes.size()) {}
  void raw(void* data, std::size_t size) {
    if (size > left())
      throw Error("a message ended early (" + std::to_string(left()) + " bytes left, " + std::to_string(size) +
                  " needed)");
    std::memcpy(data, at_, size);
    at_ += size;
  }
  // A count of elements of at least `element_bytes` each: never more than what is left
  // could hold, so a forged count cannot make the reader allocate without end.
  std::size_t count(std::size_t element_bytes) {
    std::uint64_t n = 0;
    raw(&n, sizeof n);
    if (n > left() / std::max<std::size_t>(element_bytes, 1))
      throw Error("a message claims " + std::to_string(n) + " elements but holds " + std::to_string(left()) + " bytes");
    return std::size_t(n);
  }
  std::size_t left() const { return std::size_t(end_ - at_); }
  std::string rest() const { return std::string(at_, end_); }  // what is still to read
  bool done() const { return at_ == end_; }

 private:
  const char* at_;
  const char* end_;
};

// ---- Numbers, flags, enums, text ------------------------------------------------------

template <class T, std::enable_if_t<std::is_arithmetic_v<T> || std::is_enum_v<T>, int> = 0>
void put(Writer& w, const T& x) {
  w.raw(&x, sizeof x);
}
template <class T, std::enable_if_t<std::is_arithmetic_v<T> || std::is_enum_v<T>, int> = 0> void get(Reader& r, T& x) {
  r.raw(&x, sizeof x);
  if constexpr (std::is_same_v<T, bool>) {
    unsigned char byte;
    std::memcpy(&byte, &x, 1);
    if (byte > 1) throw Error("a flag holds " + std::to_string(byte) + ", neither true nor false");
  }
}

inline void put(Writer& w, const std::string& s) {
  const std::uint64_t n = s.size();
  w.raw(&n, sizeof n);
  w.raw(s.data(), s.size());
}
inline void get(Reader& r, std::string& s) {
  s.resize(r.count(1));
  r.raw(s.data(), s.size());
}

// ---- Eigen: fixed-size matrices and rigid transforms, their doubles in order ----------

template <int R, int C, int O> void put(Writer& w, const Eigen::Matrix<double, R, C, O, R, C>& m) {
  w.raw(m.data(), sizeof(double) * R * C);
}
template <int R, int C, int O> void get(Reader& r, Eigen::Matrix<double, R, C, O, R, C>& m) {
  r.raw(m.data(), sizeof(double) * R * C);
}
inline void put(Writer& w, const RigidTransform& m) { put(w, m.matrix()); }
inline void get(Reader& r, RigidTransform& m) { get(r, m.matrix()); }

// ---- Containers -----------------------------------------------------------------------

// A type with no field list (a class with private state, a std::function) joins in by
// specialising Codec<T> with static put and get (see tests/04_bisection/wire.h).
template <class T> struct Codec {};
template <class T> auto put(Writer& w, const T& x) -> decltype(Codec<T>::put(w, x)) { Codec<T>::put(w, x); }
template <class T> auto get(Reader& r, T& x) -> decltype(Codec<T>::get(r, x)) { Codec<T>::get(r, x); }

template <class T, std::size_t N> void put(Writer& w, const std::array<T, N>& xs);
template <class T, std::size_t N> void get(Reader& r, std::array<T, N>& xs);
template <class T> void put(Writer& w, const std::vector<T>& xs);
template <class T> void get(Reader& r, std::vector<T>& xs);
template <class T, class = HasFields<T>> void put(Writer& w, const T& x);
template <class T, class = HasFields<T>> void get(Reader& r, T& x);

template <class T, std::size_t N> void put(Writer& w, const std::array<T, N>& xs) {
  for (const T& x : xs) put(w, x);
}
template <class T, std::size_t N> void get(Reader& r, std::array<T, N>& xs) {
  for (T& x : xs) get(r, x);
}
template <class T> void put(Writer& w, const std::vector<T>& xs) {
  const std::uint64_t n = xs.size();
  w.raw(&n, sizeof n);
  for (const T& x : xs) put(w, x);
}
template <class T> void get(Reader& r, std::vector<T>& xs) {
  // Every element takes at least one byte on the wire.
  xs.resize(r.count(1));
  for (T& x : xs) get(r, x);
}

// Structs that list their fields.
template <class T, class> void put(Writer& w, const T& x) {
  fields(const_cast<T&>(x), [&](const char*, auto& field) { put(w, field); });
}
template <class T, class> void get(Reader& r, T& x) {
  fields(x, [&](const char*, auto& field) { get(r, field); });
}

}  // namespace labkit::wire
