// Colours when the output is a terminal (and NO_COLOR is unset), plain text otherwise.
#pragma once

#include "common/text.h"

#include <string>

namespace runner::term {

void use_colour(bool on);
std::string bold(const std::string& s);
std::string green(const std::string& s);
std::string red(const std::string& s);
std::string yellow(const std::string& s);
std::string dim(const std::string& s);
// Pads to `width` columns (counting UTF-8 characters, not bytes).
std::string pad(const std::string& s, std::size_t width);
// Indents every line after the first by `prefix`.
using labkit::indent;

}  // namespace runner::term
