#pragma once
// A figure as PDF, drawn with cairo (Debian libcairo2-dev): vector output a paper takes as it
// is, from the same shapes as the SVG and the PNG (issue 51).
#include <string>

#include "analysis/figure.h"

namespace canopy::analysis {

/// The figure as a one-page PDF document of figure.width × figure.height points (1 px = 1 pt);
/// throws std::runtime_error when cairo fails.
std::string toPdf(const Figure& figure);

}  // namespace canopy::analysis
