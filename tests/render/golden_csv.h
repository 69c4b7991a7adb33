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

inline std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    std::vector<std::string>& row = rows.emplace_back();
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(cell);
  }
  return rows;
}

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
