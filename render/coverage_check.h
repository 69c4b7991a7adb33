#pragma once
// Comparing a coverage CSV (coverageCsvHeader/Row) with a golden one, within a tolerance: what
// `canopy coverage --check` and the golden tests both use.
#include <cstddef>
#include <string>
#include <vector>

namespace canopy::render {

/// Pixel columns (covered_px, visible_px, multi_px) may differ by `tolerance`·aoi_px, fraction
/// columns by `tolerance` (plus their printing, 1e-6); every other column (step, t, aoi_px, the
/// per-target flags) must be the same text.
inline constexpr double kDefaultCoverageTolerance = 0.001;

/// A coverage CSV's limits, checked before anything is compared (a golden file is user input):
/// its size, a line, a cell, its rows; and the length of one listed difference.
inline constexpr std::size_t kMaxCoverageCsvBytes = std::size_t{64} << 20;
inline constexpr std::size_t kMaxCoverageLineBytes = 64 * 1024;
inline constexpr std::size_t kMaxCoverageCellBytes = 256;  // a number, or a column's name
inline constexpr int kMaxCoverageRows = 10'000'001;  // steps: at most 10⁷ of dt, plus step 0
inline constexpr std::size_t kMaxListedLine = 400;

struct CoverageComparison {
  std::string bad_input;  // non-empty when either text is not a coverage CSV: what is wrong
  int rows = 0;           // data rows compared
  int differing = 0;      // of them, rows outside the tolerance (or a header/length mismatch: 1)
  std::vector<std::string> first;  // the first differences, one line each ("line 12 (step 10): …")

  bool matches() const { return bad_input.empty() && differing == 0; }
};

/// A CSV text as rows of cells (blank lines skipped, a trailing '\r' dropped; no quoting: the
/// coverage CSV has none).
std::vector<std::vector<std::string>> parseCsv(const std::string& text);

/// Compares `actual` with `expected` (both whole CSV texts); `max_listed` bounds `first`.
/// `expected_name` and `actual_name` name the texts in bad_input.
CoverageComparison compareCoverageCsv(const std::string& expected, const std::string& actual,
                                      double tolerance = kDefaultCoverageTolerance,
                                      int max_listed = 5,
                                      const std::string& expected_name = "the golden file",
                                      const std::string& actual_name = "the run's coverage");

}  // namespace canopy::render
