#include "common/harness/codec.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace labkit {

std::string fmt(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  return std::string(buffer, end);
}

std::string fmt(const Vec2& v) { return "(" + fmt(v.x()) + ", " + fmt(v.y()) + ")"; }
std::string fmt(const Vec3& v) { return "(" + fmt(v.x()) + ", " + fmt(v.y()) + ", " + fmt(v.z()) + ")"; }

namespace codec {

double Reader::real() {
  if (next_ >= numbers_.size())
    throw BadToken("it ends after " + std::to_string(numbers_.size()) + " numbers; more are needed");
  // Every input of every lab is finite (each header's preconditions): a token with nan or
  // inf is not a case any generator draws, and the exact oracle has no answer for it.
  const double x = numbers_[next_++];
  if (!std::isfinite(x))
    throw BadToken("number " + std::to_string(next_) + " of the case is " + fmt(x) +
                   ": the labs' inputs are finite numbers (each header's preconditions)");
  return x;
}

std::size_t Reader::count(std::size_t limit) {
  const double x = real();
  if (!(x >= 0) || x != std::floor(x) || x > double(limit))
    throw BadToken("number " + std::to_string(next_) + " (" + fmt(x) + ") should be a count from 0 to " +
                   std::to_string(limit));
  return std::size_t(x);
}

void encode(Writer& w, const Vec3& v) {
  w.real(v.x());
  w.real(v.y());
  w.real(v.z());
}
void decode(Reader& r, Vec3& v) {
  v.x() = r.real();
  v.y() = r.real();
  v.z() = r.real();
}
void encode(Writer& w, const Vec2& v) {
  w.real(v.x());
  w.real(v.y());
}
void decode(Reader& r, Vec2& v) {
  v.x() = r.real();
  v.y() = r.real();
}

void encode(Writer& w, const Mesh& m) {
  w.count(m.vertices.size());
  for (const Vec3& v : m.vertices) encode(w, v);
  w.count(m.triangles.size());
  for (const auto& f : m.triangles)
    for (int i : f) w.count(std::size_t(i));
}

void decode(Reader& r, Mesh& m) {
  m.vertices.resize(r.count());
  for (Vec3& v : m.vertices) decode(r, v);
  m.triangles.resize(r.count());
  const std::size_t last = m.vertices.empty() ? 0 : m.vertices.size() - 1;
  for (auto& f : m.triangles)
    for (int& i : f) i = int(r.count(last));
}

// The 3x4 matrix [R | t], row by row: exact, where a quaternion would round.
void encode(Writer& w, const RigidTransform& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      if (j < 3)
        w.unit(m.matrix()(i, j));
      else
        w.real(m.matrix()(i, j));
    }
}
void decode(Reader& r, RigidTransform& m) {
  m.setIdentity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) m.matrix()(i, j) = r.real();
}

// A projection matrix mixes lengths and unit-free entries; all are perturbed relative to 1.
void encode(Writer& w, const Mat4& m) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) w.unit(m(i, j));
}
void decode(Reader& r, Mat4& m) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m(i, j) = r.real();
}

void encode(Writer& w, const Mat3& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) w.unit(m(i, j));
}
void decode(Reader& r, Mat3& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r.real();
}
void encode(Writer& w, const Rectangle& rect) {
  encode(w, rect.center);
  for (int i = 0; i < 3; ++i) w.unit(rect.u[i]);
  for (int i = 0; i < 3; ++i) w.unit(rect.v[i]);
  w.real(rect.half_u);
  w.real(rect.half_v);
}
void decode(Reader& r, Rectangle& rect) {
  decode(r, rect.center);
  decode(r, rect.u);
  decode(r, rect.v);
  rect.half_u = r.real();
  rect.half_v = r.real();
}

}  // namespace codec

std::string describe(double x) { return fmt(x); }
std::string describe(int x) { return std::to_string(x); }
std::string describe(bool x) { return x ? "true" : "false"; }
std::string describe(const Vec2& v) { return fmt(v); }
std::string describe(const Vec3& v) { return fmt(v); }
std::string describe(const Segment& s) { return "a=" + fmt(s.a) + " b=" + fmt(s.b); }
std::string describe(const Triangle& t) { return "v0=" + fmt(t.v0) + " v1=" + fmt(t.v1) + " v2=" + fmt(t.v2); }
std::string describe(const Plane& p) { return "normal=" + fmt(p.normal) + " offset=" + fmt(p.offset); }

std::string describe(const Frustum& f) {
  static const char* names[6] = {"left", "right", "bottom", "top", "near", "far"};
  std::string s;
  for (int i = 0; i < 6; ++i) s += std::string(i ? "; " : "") + names[i] + " " + describe(f.planes[i]);
  return s;
}

std::string describe(const Mesh& m) {
  std::string s = std::to_string(m.vertices.size()) + " vertices, " + std::to_string(m.triangles.size()) + " triangles";
  const std::size_t shown = m.size() <= 12 ? m.size() : 6;
  for (std::size_t i = 0; i < shown; ++i) s += "\n    triangle " + std::to_string(i) + ": " + describe(m.triangle(i));
  if (shown < m.size()) s += "\n    ... (the replay token holds all of them)";
  return s;
}

std::string describe(const RigidTransform& m) {
  std::string s = "[";
  for (int i = 0; i < 3; ++i) {
    s += i ? "; " : "";
    for (int j = 0; j < 4; ++j) s += (j ? " " : "") + fmt(m.matrix()(i, j));
  }
  return s + "]";
}

std::string describe(const Mat4& m) {
  std::string s = "[";
  for (int i = 0; i < 4; ++i) {
    s += i ? "; " : "";
    for (int j = 0; j < 4; ++j) s += (j ? " " : "") + fmt(m(i, j));
  }
  return s + "]";
}

std::string describe(const Mat3& m) {
  std::string s = "[";
  for (int i = 0; i < 3; ++i) {
    s += i ? "; " : "";
    for (int j = 0; j < 3; ++j) s += (j ? " " : "") + fmt(m(i, j));
  }
  return s + "]";
}
std::string describe(const Sphere& s) { return "center=" + fmt(s.center) + " radius=" + fmt(s.radius); }
std::string describe(const Capsule& c) { return describe(c.axis) + " radius=" + fmt(c.radius); }
std::string describe(const Rectangle& r) {
  return "center=" + fmt(r.center) + " u=" + fmt(r.u) + " v=" + fmt(r.v) + " half_u=" + fmt(r.half_u) +
         " half_v=" + fmt(r.half_v);
}
std::string describe(const Lozenge& l) { return describe(l.rectangle) + " radius=" + fmt(l.radius); }
std::string describe(const Box& b) {
  return "center=" + fmt(b.center) + " axes=" + describe(b.axes) + " half_extents=" + fmt(b.half_extents);
}
std::string describe(const Aabb& b) { return "min=" + fmt(b.min) + " max=" + fmt(b.max); }

ParsedToken parse_token(const std::string& token) {
  const auto colon = token.find(':');
  if (colon == std::string::npos || colon == 0)
    throw BadToken("a replay case looks like 'query:1,2,3', and '" + token.substr(0, 40) +
                   "' has no 'query:' in front");
  ParsedToken parsed;
  parsed.query = token.substr(0, colon);
  const std::string rest = token.substr(colon + 1);
  std::size_t begin = 0;
  while (begin <= rest.size() && !rest.empty()) {
    std::size_t end = rest.find(',', begin);
    if (end == std::string::npos) end = rest.size();
    const std::string item = rest.substr(begin, end - begin);
    double x = 0;
    const auto result = std::from_chars(item.data(), item.data() + item.size(), x);
    if (item.empty() || result.ec != std::errc() || result.ptr != item.data() + item.size()) {
      // from_chars does not read "inf"/"nan" in every library; accept them by hand.
      if (item == "inf")
        x = INFINITY;
      else if (item == "-inf")
        x = -INFINITY;
      else if (item == "nan")
        x = NAN;
      else
        throw BadToken("number " + std::to_string(parsed.numbers.size() + 1) + " of the replay case, '" +
                       item.substr(0, 30) + "', is not a number");
    }
    parsed.numbers.push_back(x);
    begin = end + 1;
  }
  return parsed;
}

}  // namespace labkit
