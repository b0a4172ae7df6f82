#pragma once
// What report.cpp and report_figures.cpp share: how the bench report writes a number.

#include <string>

namespace cavewall::bench::detail {

// `v` with `digits` significant digits ("%g"); inf, -inf and nan spelled so.
std::string num(double v, int digits = 6);

}  // namespace cavewall::bench::detail
