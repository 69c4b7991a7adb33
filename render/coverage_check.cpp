#include "render/coverage_check.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace canopy::render {
namespace {

using Rows = std::vector<std::vector<std::string>>;

bool isNumber(const std::string& cell, double& x) {
  char* end = nullptr;
  x = std::strtod(cell.c_str(), &end);
  return !cell.empty() && *end == '\0' && std::isfinite(x);
}

// Empty when `rows` is a coverage CSV (a header starting "step,t," and numeric rows as wide as
// it), else what is wrong, naming the text and the line.
std::string shapeError(const Rows& rows, const std::string& name) {
  if (rows.empty()) return name + " is empty (expected the CSV `canopy coverage` prints)";
  const std::vector<std::string>& header = rows[0];
  const std::vector<std::string> start = {"step", "t", "covered_px"};
  if (header.size() < start.size() || !std::equal(start.begin(), start.end(), header.begin())) {
    return name + ": line 1: expected the header of `canopy coverage` (step,t,covered_px,…)";
  }
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const std::string where = name + ": line " + std::to_string(i + 1) + ": ";
    if (rows[i].size() != header.size()) {
      return where + "expected " + std::to_string(header.size()) + " columns, got " +
             std::to_string(rows[i].size());
    }
    for (std::size_t c = 0; c < header.size(); ++c) {
      double x = 0;
      if (!isNumber(rows[i][c], x)) return where + header[c] + ": expected a number";
    }
  }
  return "";
}

bool isPixelColumn(const std::string& name) {
  return name == "covered_px" || name == "visible_px" || name == "multi_px";
}

bool isFractionColumn(const std::string& name) {
  return name == "covered_fraction" || name == "visible_fraction";
}

}  // namespace

std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string>& row = rows.emplace_back();
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(cell);
  }
  return rows;
}

CoverageComparison compareCoverageCsv(const std::string& expected, const std::string& actual,
                                      double tolerance, int max_listed,
                                      const std::string& expected_name,
                                      const std::string& actual_name) {
  CoverageComparison out;
  const Rows e = parseCsv(expected), a = parseCsv(actual);
  out.bad_input = shapeError(e, expected_name);
  if (out.bad_input.empty()) out.bad_input = shapeError(a, actual_name);
  if (!out.bad_input.empty()) return out;
  auto note = [&](const std::string& line) {
    if (static_cast<int>(out.first.size()) < max_listed) out.first.push_back(line);
  };
  if (e[0] != a[0]) {
    out.differing = 1;
    std::string want, got;
    for (const std::string& c : e[0]) want += (want.empty() ? "" : ",") + c;
    for (const std::string& c : a[0]) got += (got.empty() ? "" : ",") + c;
    note("line 1: the columns differ: expected " + want + ", got " + got);
    return out;
  }
  const std::vector<std::string>& header = e[0];
  std::size_t aoi_column = 0;
  for (std::size_t c = 0; c < header.size(); ++c)
    aoi_column = header[c] == "aoi_px" ? c : aoi_column;
  if (e.size() != a.size()) {
    out.differing = 1;
    note("expected " + std::to_string(e.size() - 1) + " rows, got " + std::to_string(a.size() - 1));
  }
  const std::size_t n = std::min(e.size(), a.size());
  for (std::size_t i = 1; i < n; ++i) {
    ++out.rows;
    const double aoi = std::atof(e[i][aoi_column].c_str());
    std::string differences;
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (e[i][c] == a[i][c]) continue;
      const double x = std::atof(e[i][c].c_str()), y = std::atof(a[i][c].c_str());
      if (isPixelColumn(header[c]) && std::abs(x - y) <= tolerance * aoi) continue;
      if (isFractionColumn(header[c]) && std::abs(x - y) <= tolerance + 1e-6) continue;
      differences += (differences.empty() ? "" : ", ") + header[c] + " expected " + e[i][c] +
                     ", got " + a[i][c];
    }
    if (differences.empty()) continue;
    ++out.differing;
    note("line " + std::to_string(i + 1) + " (step " + e[i][0] + "): " + differences);
  }
  return out;
}

}  // namespace canopy::render
