#pragma once
// splitmix64 (Steele, Lea and Flood, 2014): a tiny, portable stream of random numbers
// from a seed, the same on every machine and compiler. The kit's one definition: lab 07's
// emitters draw from it (labkit::lab07::Random), the harness mixes seeds with it, and
// inputs that must be fixed by a number of their own use it (meshes drawn from a seed,
// the efficiency segments, the checker's trees, the benchmarks' inputs), apart from
// RapidCheck's random cases.
#include <cstdint>

namespace labkit {

struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t x = (state += 0x9e3779b97f4a7c15ull);
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
  }
  int below(int n) { return int(next() % std::uint64_t(n)); }                  // [0, n)
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }                // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }  // [lo, hi)
};

}  // namespace labkit
