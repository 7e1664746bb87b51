// Lab 06's extensions beyond the core: step 11, a spatial hash over spheres, judged
// against the exact brute force, its tests bounded by the pairs in neighbouring cells
// (counted on the judge's side, as step 5's).
#include "06_spatial_trees/judge_internal.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab06::judge {

// ---- Step 11 -----------------------------------------------------------------------------------

namespace {

// The header's cell of a point: p / cell is exact (cell a power of two), and so its floor.
Cell cell_at(const Vec3& p, double cell) {
  return {std::int64_t(std::floor(p.x() / cell)), std::int64_t(std::floor(p.y() / cell)),
          std::int64_t(std::floor(p.z() / cell))};
}

bool neighbours(const Cell& a, const Cell& b) {
  const auto near = [](std::int64_t u, std::int64_t v) { return u - v >= -1 && u - v <= 1; };
  return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z);
}

std::string cell_text(const Cell& c) { return "(" + str(c.x) + ", " + str(c.y) + ", " + str(c.z) + ")"; }

}  // namespace

long long neighbour_pairs(const HashCase& in) {
  std::vector<Cell> cells;
  for (const Sphere& s : in.spheres) cells.push_back(cell_at(s.center, in.cell));
  long long n = 0;
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (std::size_t j = i + 1; j < cells.size(); ++j) n += neighbours(cells[i], cells[j]);
  return n;
}

Outcome hashed_pairs(const HashCase& in, const SpherePairs& got, long long calls, Rules rules) {
  if (in.exact) rules = Rules::exact;
  const std::vector<Sphere>& spheres = in.spheres;
  const int n = int(spheres.size());
  const std::vector<std::array<int, 2>> exact = oracle::meeting_pairs(spheres);
  const std::string expected = describe_pairs(exact), answer = describe_pairs(got.pairs);
  if (got.tests != calls)
    return fail("tests = " + str(calls) + " (your calls of given_balls_meet, as the kit counted them)",
                "tests = " + str(got.tests),
                "tests counts the pairs you tested, each with one call of given_balls_meet");
  const long long bound = neighbour_pairs(in);
  if (calls > bound)
    return fail("at most " + str(bound) + " tests (the pairs of balls in neighbouring cells)",
                str(calls) + " calls of given_balls_meet",
                "a spatial hash tests each pair of balls in neighbouring cells (cells that differ by at most 1 along "
                "each axis) at most once: take from a bucket only the entries whose key is the cell you look for "
                "(distinct cells share buckets, " +
                    str(in.buckets) +
                    " here), and test each pair once, from its smaller index; a brute force, or a whole bucket, "
                    "tests more");
  for (std::size_t k = 0; k < got.pairs.size(); ++k) {
    const auto& p = got.pairs[k];
    if (p[0] < 0 || p[1] >= n || p[0] >= p[1])
      return fail(expected, answer, "{" + str(p[0]) + ", " + str(p[1]) + "} is not a pair i < j of spheres");
    if (k > 0 && !(got.pairs[k - 1] < p))
      return fail(expected, answer,
                  "each pair once, sorted: a pair is reported twice when a bucket reached from two of the 27 cells "
                  "yields its entries twice (take only the entries whose key is the cell you look for)");
  }
  if (calls < (long long)got.pairs.size())
    return fail(expected + ", each tested", answer + " after " + str(calls) + " calls of given_balls_meet",
                "a pair is reported only after given_balls_meet said its balls meet: test every pair you report");
  // Step 5's band: within 6 tol of touching a perturbation may part them or make them meet.
  const double tol = tolerance_of(SphereSet{spheres});
  const auto gap_of = [&](const std::array<int, 2>& p) {
    const Sphere& a = spheres[std::size_t(p[0])];
    const Sphere& b = spheres[std::size_t(p[1])];
    return (a.center - b.center).norm() - (a.radius + b.radius);
  };
  const auto in_doubt = [&](const std::array<int, 2>& p) {
    return rules == Rules::random && std::abs(gap_of(p)) <= 6 * tol;
  };
  const auto cells_of = [&](const std::array<int, 2>& p) {
    return cell_text(cell_at(spheres[std::size_t(p[0])].center, in.cell)) + " and " +
           cell_text(cell_at(spheres[std::size_t(p[1])].center, in.cell));
  };
  bool doubt = false;
  std::size_t i = 0, j = 0;
  while (i < exact.size() || j < got.pairs.size()) {
    if (j == got.pairs.size() || (i < exact.size() && exact[i] < got.pairs[j])) {  // missing
      if (!in_doubt(exact[i]))
        return fail(expected, answer,
                    "closed balls meet when |c_i - c_j| <= r_i + r_j (touching counts): spheres " + str(exact[i][0]) +
                        " and " + str(exact[i][1]) + " meet (gap " + fmt(gap_of(exact[i])) +
                        "), yet the pair is missing. Their centres lie in the cells " + cells_of(exact[i]) +
                        ", neighbours: look in all 27 cells around a ball's own (dx, dy, dz from -1 to 1), since "
                        "each pair is kept from its smaller index and its other ball may lie on any side; compute a "
                        "cell with floor (not a cast toward zero) in 64-bit integers");
      doubt = true;
      ++i;
    } else if (i == exact.size() || got.pairs[j] < exact[i]) {  // extra
      if (!in_doubt(got.pairs[j]))
        return fail(expected, answer,
                    "closed balls meet when |c_i - c_j| <= r_i + r_j: spheres " + str(got.pairs[j][0]) + " and " +
                        str(got.pairs[j][1]) + " have |c_i - c_j| - (r_i + r_j) = " + fmt(gap_of(got.pairs[j])) +
                        " > 0: apart");
      doubt = true;
      ++j;
    } else {
      doubt = doubt || in_doubt(exact[i]);
      ++i, ++j;
    }
  }
  return doubt ? ambiguous() : pass();
}

}  // namespace labkit::lab06::judge
