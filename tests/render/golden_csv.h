#pragma once
// Comparing coverage CSVs (render/coverage.h) with a stated tolerance, for the golden tests.
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "core/text_file.h"

namespace canopy::render::testing {

/// covered_px and multi_px may drift by this fraction of aoi_px; every other column must match
/// (step, aoi_px and the per-target flags exactly, t and covered_fraction to their printing).
inline constexpr double kGoldenPixelTolerance = 0.001;

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

/// Empty when `actual` matches `expected` within the tolerance, else the first difference.
inline std::string compareCoverageCsv(const std::string& expected, const std::string& actual) {
  const auto e = parseCsv(expected), a = parseCsv(actual);
  if (e.empty()) return "the golden file is empty";
  if (e.size() != a.size()) {
    return "expected " + std::to_string(e.size()) + " lines, got " + std::to_string(a.size());
  }
  if (e[0] != a[0]) return "the headers differ";
  for (std::size_t i = 1; i < e.size(); ++i) {
    const std::string where = "line " + std::to_string(i + 1) + ": ";
    if (e[i].size() != a[i].size()) return where + "the number of columns differs";
    const double aoi = std::atof(e[i][4].c_str());
    for (std::size_t c = 0; c < e[i].size(); ++c) {
      if (e[i][c] == a[i][c]) continue;
      const double x = std::atof(e[i][c].c_str()), y = std::atof(a[i][c].c_str());
      const bool pixels = c == 2 || c == 3;
      const bool fraction = c == 5;
      if (pixels && std::abs(x - y) <= kGoldenPixelTolerance * aoi) continue;
      if (fraction && std::abs(x - y) <= kGoldenPixelTolerance + 1e-6) continue;
      return where + e[0][c] + " expected " + e[i][c] + ", got " + a[i][c];
    }
  }
  return "";
}

}  // namespace canopy::render::testing
