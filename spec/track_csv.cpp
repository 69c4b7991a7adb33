#include "spec/track_csv.h"

#include <cmath>
#include <sstream>

#include "core/printable.h"
#include "spec/error.h"

namespace canopy::spec {

std::vector<world::TimedPoint> parseTrackCsv(const std::string& text, const std::string& source) {
  std::vector<world::TimedPoint> points;
  std::istringstream in(text);
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF files
    if (line.empty() || line[0] == '#') continue;
    double t = 0, x = 0, y = 0;
    char c1 = 0, c2 = 0;
    std::istringstream row(line);
    const bool parsed = static_cast<bool>(row >> t >> c1 >> x >> c2 >> y) && c1 == ',' &&
                        c2 == ',' && (row >> std::ws).eof();
    if (!parsed || !std::isfinite(t) || !std::isfinite(x) || !std::isfinite(y)) {
      if (points.empty() && number == 1) continue;  // a header
      throw ScenarioError(
          source, "line " + std::to_string(number),
          "expected \"t,x,y\" with three finite numbers, got \"" + printable(line, 40) + "\"");
    }
    if (t < 0.0) {
      throw ScenarioError(source, "line " + std::to_string(number),
                          "expected a time >= 0 s, got " + std::to_string(t));
    }
    if (!points.empty() && !(t > points.back().t)) {
      throw ScenarioError(source, "line " + std::to_string(number),
                          "expected a time greater than the previous line's; times must increase "
                          "strictly");
    }
    points.push_back({t, Vec2(x, y)});
  }
  if (points.empty()) {
    throw ScenarioError(source, "", "expected a track file with at least one \"t,x,y\" line");
  }
  return points;
}

}  // namespace canopy::spec
