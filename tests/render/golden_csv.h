#pragma once
// Reading coverage CSVs in the golden tests; comparing them as `canopy coverage --check` does.
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "core/text_file.h"
#include "render/coverage_check.h"

namespace canopy::render::testing {

using render::parseCsv;  // the parser `canopy coverage --check` uses

/// The file's text, empty when it cannot be read (compareCoverageCsv then reports an empty golden).
inline std::string readFile(const std::string& path) {
  return readTextFile(path).value_or("");
}

/// Empty when `actual` matches `expected` within the default tolerance (render/coverage_check.h,
/// the code `canopy coverage --check` runs), else what is wrong or the first difference.
inline std::string compareCoverageCsv(const std::string& expected, const std::string& actual) {
  const CoverageComparison result = render::compareCoverageCsv(expected, actual);
  if (!result.bad_input.empty()) return result.bad_input;
  return result.matches() ? "" : result.first.at(0);
}

}  // namespace canopy::render::testing
