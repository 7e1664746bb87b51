// Answerers that do no geometry, for the kit's test of its own scoring and of its judges
// (`labkit-runner fake`, runner/fake.cpp). One program per lab, built from the lab's list
// of calls like common/protocol/lab_answerer.cpp; its first argument says how it answers:
//
//   nothing   every call answers its result type's default (no hit, false, zeros):
//             a file that does nothing must earn nothing
//   random    every call answers a random value of its result type: chance earns nothing
//   garbage   random values at their worst (NaN, infinities, huge and negative numbers,
//             indices and enums out of range, long lists): no judge may crash on them
//   examples  FILE: the reference's answer to every request whose hash FILE lists (the
//             handout's worked examples, recorded by the judge), the default elsewhere:
//             hard-coding the public examples earns almost nothing
#define LABKIT_IN_ANSWERER
#include LABKIT_LAB_QUERIES

#include "common/protocol/calls.h"
#include "common/text.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace {

using namespace labkit;

enum class Mode { nothing, random, garbage, examples };

struct Fake {
  Mode mode = Mode::nothing;
  std::unordered_set<std::string> examples;  // request hashes (remote::request_hash)
  std::mt19937_64 random{20261127};
};
Fake fake;

using wire::HasFieldList;
using wire::IsArray;
using wire::IsMatrix;
using wire::IsVector;

std::uint64_t draw(std::uint64_t n) { return fake.random() % n; }

double number() {
  if (fake.mode == Mode::garbage) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double worst[] = {std::numeric_limits<double>::quiet_NaN(), kInf, -kInf, 1e308, -1e308, 1e-308, -0.0, 0.0,
                            std::numeric_limits<double>::denorm_min()};
    if (draw(2) == 0) return worst[draw(std::size(worst))];
  }
  return std::uniform_real_distribution<double>(-10.0, 10.0)(fake.random);
}

template <class T> T integer() {
  if (fake.mode == Mode::garbage && draw(2) == 0) {
    const T worst[] = {std::numeric_limits<T>::max(), std::numeric_limits<T>::min(), T(-1), T(1 << 20)};
    return worst[draw(std::size(worst))];
  }
  return T(draw(8));
}

// Lists are short, and in garbage mode now and then long; an answer holds at most
// kElements elements in all (lists of lists would otherwise multiply their lengths).
constexpr std::size_t kElements = 3000;
std::size_t elements_left = kElements;

std::size_t length() {
  std::size_t n = fake.mode == Mode::garbage && draw(8) == 0 ? 500 + draw(2500) : draw(6);
  n = std::min(n, elements_left);
  elements_left -= n;
  return n;
}

template <class T> void fill(T& x);

template <class T> void fill(T& x) {
  if constexpr (std::is_same_v<T, bool>) {
    x = draw(2) == 1;
  } else if constexpr (std::is_enum_v<T>) {
    using U = std::underlying_type_t<T>;
    x = T(fake.mode == Mode::garbage ? U(integer<int>()) : U(draw(3)));
  } else if constexpr (std::is_integral_v<T>) {
    x = integer<T>();
  } else if constexpr (std::is_floating_point_v<T>) {
    x = T(number());
  } else if constexpr (IsVector<T>::value) {
    x.resize(length());
    for (auto& e : x) fill(e);
  } else if constexpr (IsArray<T>::value) {
    for (auto& e : x) fill(e);
  } else if constexpr (IsMatrix<T>::value) {
    for (int i = 0; i < x.size(); ++i) x.data()[i] = number();
  } else if constexpr (std::is_same_v<T, RigidTransform>) {
    fill(x.matrix());
  } else if constexpr (HasFieldList<T>::value) {
    fields(x, [](const char*, auto& field) { fill(field); });
  }  // anything else (a Random, a std::function) keeps its default
}

// The call's whole request, as the judge's process sent it and hashed it.
std::string request_of(const std::string& id, const wire::Reader& in) {
  wire::Writer w;
  wire::put(w, id);
  const std::string rest = in.rest();
  w.raw(rest.data(), rest.size());
  return w.take();
}

template <class R, class... P, std::size_t... I>
void answer(R (*function)(P...), const std::string& id, wire::Reader& in, wire::Writer& out,
            std::index_sequence<I...> order) {
  if (fake.mode == Mode::examples && fake.examples.count(remote::request_hash(request_of(id, in))))
    return remote::run_call(function, in, out, order);
  std::tuple<std::decay_t<P>...> args;
  (wire::get(in, std::get<I>(args)), ...);
  if (!in.done()) throw wire::Error("extra bytes after the arguments");
  if constexpr (!std::is_void_v<R>) {
    R result{};
    elements_left = kElements;
    if (fake.mode == Mode::random || fake.mode == Mode::garbage) fill(result);
    wire::put(out, result);
  }
  (remote::put_out<P>(out, std::get<I>(args)), ...);
}

template <class R, class... P> remote::Handler handler(R (*function)(P...), std::string id) {
  return [function, id](wire::Reader& in, wire::Writer& out) {
    answer(function, id, in, out, std::index_sequence_for<P...>{});
  };
}

}  // namespace

#define LABKIT_FAKE_CALL(R, name, params) \
  table[LABKIT_CALL_ID(R, name, params)] = handler<R, LABKIT_UNPAREN params>(&name, LABKIT_CALL_ID(R, name, params));
#define LABKIT_FAKE_METHOD(Class, name, params)                                    \
  table[#Class "::" #name #params] = handler<void, Class&, LABKIT_UNPAREN params>( \
      +[](Class& self, LABKIT_NAMED params) { self.name(LABKIT_ARGS params); }, #Class "::" #name #params);

int main(int argc, char* argv[]) {
  using namespace labkit::LABKIT_LAB_NAMESPACE;
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "nothing") {
    fake.mode = Mode::nothing;
  } else if (mode == "random") {
    fake.mode = Mode::random;
  } else if (mode == "garbage") {
    fake.mode = Mode::garbage;
  } else if (mode == "examples" && argc > 2) {
    fake.mode = Mode::examples;
    std::istringstream lines(labkit::read_file(argv[2]));
    for (std::string line; std::getline(lines, line);)
      if (!line.empty()) fake.examples.insert(line);
  } else {
    std::fprintf(stderr, "usage: %s nothing | random | garbage | examples FILE\n", argv[0]);
    return 2;
  }
  labkit::remote::Table table;
  LABKIT_LAB_CALLS(LABKIT_FAKE_CALL, LABKIT_FAKE_METHOD)
#ifdef LABKIT_LAB_SERVED
  return labkit::remote::serve(table, true);
#else
  return labkit::remote::serve(table, false);
#endif
}
