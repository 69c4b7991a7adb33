#pragma once
// What `canopy run` prints: a short table of the outcome read from summary.json, and the warnings
// it deserves (stderr).
#include <string>
#include <vector>

namespace canopy::sim {

/// Per target its visible and covered (in a footprint) percentages; the team's OSPA and GOSPA;
/// planning time per epoch. `summary_json` is the text of summary.json.
std::string runTable(const std::string& summary_json);

/// One line per diagnostic of the summary that a user should look at (numerical failures in
/// fusion or tracking, an agent against something solid for 5 s or more in a row: stuck); empty
/// when there is none.
std::vector<std::string> runWarnings(const std::string& summary_json);

}  // namespace canopy::sim
