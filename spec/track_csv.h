#pragma once
// Recorded target tracks as CSV text: one "t,x,y" row per line (s, m, m); blank lines and lines
// starting with '#' are skipped, and so is a first line that is not a row (a header).
#include <string>
#include <vector>

#include "world/path.h"

namespace canopy::spec {

/// The rows of `text`, times strictly increasing and every number finite. Throws ScenarioError
/// naming `source` and the line; quoted content is cut and escaped (core/printable.h).
std::vector<world::TimedPoint> parseTrackCsv(const std::string& text, const std::string& source);

}  // namespace canopy::spec
