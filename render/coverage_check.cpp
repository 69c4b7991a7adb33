#include "render/coverage_check.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string_view>

#include "core/number_text.h"
#include "core/printable.h"

namespace canopy::render {
namespace {

// One line at a time over a CSV text, as views into it (no copy of the text): blank lines
// skipped, a trailing '\r' dropped; `number` is the line's 1-based number in the text.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
  bool next(std::string_view& line, int& number) {
    while (at_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', at_), text_.size());
      line = text_.substr(at_, end - at_);
      at_ = end + 1;
      ++number_;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (line.empty()) continue;
      number = number_;
      return true;
    }
    return false;
  }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  int number_ = 0;
};

// The cells of one line (views into it).
std::vector<std::string_view> cellsOf(std::string_view line) {
  std::vector<std::string_view> cells;
  for (std::size_t at = 0;;) {
    const std::size_t comma = line.find(',', at);
    cells.push_back(line.substr(at, comma == std::string_view::npos ? line.npos : comma - at));
    if (comma == std::string_view::npos) break;
    at = comma + 1;
  }
  return cells;
}

bool isNumber(std::string_view cell, double& x) {
  const std::optional<double> number = strictNumber(cell);
  if (number) x = *number;
  return number.has_value();
}

std::string quoted(std::string_view text) {
  return "'" + printable(std::string(text.substr(0, 100)), 60) + "'";
}

// Empty when `text` is a coverage CSV within the limits (a header starting "step,t,covered_px",
// numeric rows as wide as it, no cell or line longer than its limit), else what is wrong,
// naming the text and the line.
std::string shapeError(std::string_view text, const std::string& name) {
  if (text.size() > kMaxCoverageCsvBytes) {
    return name + ": expected at most " + std::to_string(kMaxCoverageCsvBytes >> 20) +
           " MiB (a coverage CSV), got " + std::to_string(text.size()) + " bytes";
  }
  Lines lines(text);
  std::string_view line;
  int number = 0;
  if (!lines.next(line, number))
    return name + " is empty (expected the CSV `canopy coverage` prints)";
  std::size_t columns = 0;
  int rows = 0;
  do {
    const std::string where = name + ": line " + std::to_string(number) + ": ";
    if (line.size() > kMaxCoverageLineBytes) {
      return where + "expected a line of at most " + std::to_string(kMaxCoverageLineBytes) +
             " characters (a coverage CSV row), got " + std::to_string(line.size());
    }
    const std::vector<std::string_view> cells = cellsOf(line);
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (cells[c].size() > kMaxCoverageCellBytes) {
        return where + "column " + std::to_string(c + 1) + ": expected at most " +
               std::to_string(kMaxCoverageCellBytes) + " characters, got " +
               std::to_string(cells[c].size());
      }
    }
    if (columns == 0) {
      const std::vector<std::string_view> start = {"step", "t", "covered_px"};
      if (cells.size() < start.size() || !std::equal(start.begin(), start.end(), cells.begin()))
        return where + "expected the header of `canopy coverage` (step,t,covered_px,…)";
      columns = cells.size();
      continue;
    }
    if (++rows > kMaxCoverageRows) {
      return where + "expected at most " + std::to_string(kMaxCoverageRows) + " rows";
    }
    if (cells.size() != columns) {
      return where + "expected " + std::to_string(columns) + " columns, got " +
             std::to_string(cells.size());
    }
    for (std::size_t c = 0; c < columns; ++c) {
      double x = 0;
      if (!isNumber(cells[c], x))
        return where + "column " + std::to_string(c + 1) + ": expected a number, got " +
               quoted(cells[c]);
    }
  } while (lines.next(line, number));
  return "";
}

bool isPixelColumn(std::string_view name) {
  return name == "covered_px" || name == "visible_px" || name == "multi_px";
}

bool isFractionColumn(std::string_view name) {
  return name == "covered_fraction" || name == "visible_fraction";
}

}  // namespace

std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  Lines lines(text);
  std::string_view line;
  int number = 0;
  while (lines.next(line, number)) {
    std::vector<std::string>& row = rows.emplace_back();
    for (std::string_view cell : cellsOf(line)) row.emplace_back(cell);
  }
  return rows;
}

CoverageComparison compareCoverageCsv(const std::string& expected, const std::string& actual,
                                      double tolerance, int max_listed,
                                      const std::string& expected_name,
                                      const std::string& actual_name) {
  CoverageComparison out;
  out.bad_input = shapeError(expected, expected_name);
  if (out.bad_input.empty()) out.bad_input = shapeError(actual, actual_name);
  if (!out.bad_input.empty()) return out;
  auto note = [&](const std::string& line) {
    if (static_cast<int>(out.first.size()) < max_listed)
      out.first.push_back(printable(line, kMaxListedLine));
  };
  // Both are valid CSVs: one line of each at a time.
  Lines e_lines(expected), a_lines(actual);
  std::string_view e_line, a_line;
  int e_number = 0, a_number = 0;
  e_lines.next(e_line, e_number);
  a_lines.next(a_line, a_number);
  const std::vector<std::string_view> header = cellsOf(e_line);
  if (e_line != a_line) {
    // Another run's columns (other targets), or a renamed or added column: not this run's golden.
    out.bad_input = expected_name + ": line " + std::to_string(e_number) +
                    ": expected the columns of this run's coverage, " +
                    printable(std::string(a_line), 200) + "; got " +
                    printable(std::string(e_line), 200);
    return out;
  }
  std::size_t aoi_column = 0;
  for (std::size_t c = 0; c < header.size(); ++c)
    aoi_column = header[c] == "aoi_px" ? c : aoi_column;
  int e_rows = 0, a_rows = 0;
  for (;;) {
    const bool e_more = e_lines.next(e_line, e_number);
    const bool a_more = a_lines.next(a_line, a_number);
    e_rows += e_more;
    a_rows += a_more;
    if (!e_more || !a_more) {
      while (e_lines.next(e_line, e_number)) ++e_rows;
      while (a_lines.next(a_line, a_number)) ++a_rows;
      break;
    }
    ++out.rows;
    const std::vector<std::string_view> e = cellsOf(e_line), a = cellsOf(a_line);
    if (out.rows == 1 && header[aoi_column] == "aoi_px" && e[aoi_column] != a[aoi_column]) {
      // The area of interest covers another number of pixels: the golden was rendered at
      // another --size, and every row would differ (issue 51: "151 of 151 rows outside").
      out.bad_input = expected_name + ": rendered at another size (aoi_px " +
                      std::string(e[aoi_column]) + ", the run's coverage " +
                      std::string(a[aoi_column]) + "): pass the --size the golden was made with";
      return out;
    }
    double aoi = 0.0;
    isNumber(e[aoi_column], aoi);
    std::string differences;
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (e[c] == a[c]) continue;
      double x = 0.0, y = 0.0;
      isNumber(e[c], x);
      isNumber(a[c], y);
      if (isPixelColumn(header[c]) && std::abs(x - y) <= tolerance * aoi) continue;
      if (isFractionColumn(header[c]) && std::abs(x - y) <= tolerance + 1e-6) continue;
      if (differences.size() < kMaxListedLine) {
        differences += (differences.empty() ? "" : ", ") + std::string(header[c]) + " expected " +
                       std::string(e[c]) + ", got " + std::string(a[c]);
      }
    }
    if (differences.empty()) continue;
    ++out.differing;
    note("line " + std::to_string(e_number) + " (step " + std::string(e[0]) + "): " + differences);
  }
  if (e_rows != a_rows) {
    out.differing = std::max(out.differing, 1);
    note("expected " + std::to_string(e_rows) + " rows, got " + std::to_string(a_rows));
  }
  return out;
}

}  // namespace canopy::render
