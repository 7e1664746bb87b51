// The exact oracle takes finite numbers only: GMP cannot make a rational of NaN or an
// infinity (it raises SIGFPE and aborts). Every conversion of a double in common/oracle/
// goes through kernel.h's checks, which throw this instead. The cases' inputs are always
// finite, so a judge that meets it was handed a number computed from an answer: the
// harness fails that case, saying so (common/harness/check.h).
#pragma once

#include <stdexcept>

namespace oracle {

struct NotFinite : std::domain_error {
  NotFinite() : std::domain_error("a number that is not finite (NaN or an infinity) reached the exact oracle") {}
};

}  // namespace oracle
