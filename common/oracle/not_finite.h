// The exact oracle takes finite numbers only: GMP cannot make a rational of NaN or an
// infinity (it raises SIGFPE and aborts). Every conversion of a double in common/oracle/
// goes through kernel.h's checks, which throw this instead. The cases' inputs are always
// finite, so a judge that meets it was handed a number computed from an answer: the
// harness fails that case, saying so (common/harness/check.h).
#pragma once

#include <cmath>
#include <stdexcept>

namespace oracle {

struct NotFinite : std::domain_error {
  NotFinite() : std::domain_error("a number that is not finite (NaN or an infinity) reached the exact oracle") {}
};

// x, when it is finite; else it throws NotFinite.
inline double finite(double x) {
  if (!std::isfinite(x)) throw NotFinite();
  return x;
}
// The number type NT (a rational, an interval) of a double, checked first.
template <class NT> NT number(double x) { return NT(finite(x)); }

}  // namespace oracle
