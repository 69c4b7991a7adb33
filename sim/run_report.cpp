#include "sim/run_report.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/printable.h"

namespace canopy::sim {
namespace {

using Json = nlohmann::json;

// Touching something for this long in a row gets a warning: sliding along a wall or brushing a
// trunk while passing takes a second or two.
constexpr double kStuckSeconds = 5.0;

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

double number(const Json& object, const char* key) {
  return object.contains(key) && object[key].is_number() ? object[key].get<double>() : 0.0;
}

}  // namespace

std::string runTable(const std::string& summary_json) {
  const Json summary = Json::parse(summary_json);
  std::size_t width = 6;  // "target"
  for (const Json& t : summary.at("targets"))
    width = std::max(width, printable(t.at("name").get<std::string>(), 40).size());
  std::string text = "target" + std::string(width - 6, ' ') + "  visible  covered\n";
  for (const Json& t : summary.at("targets")) {
    std::string name = printable(t.at("name").get<std::string>(), 40);
    name.resize(width, ' ');
    text += name + format("  %6.1f %%  %5.1f %%\n", 100.0 * number(t, "visible_fraction"),
                          100.0 * number(t, "in_footprint_fraction"));
  }
  const Json& team = summary.at("team");
  text += format("OSPA %.3g m", number(team, "ospa_mean_m"));
  if (team.contains("gospa_mean_m")) text += format(", GOSPA %.3g m", number(team, "gospa_mean_m"));
  text += format(" (mean over UAVs and steps; cut-off %g m, order %g)\n",
                 number(team, "ospa_cutoff_m"), number(team, "ospa_order"));
  if (team.contains("team_ospa_mean_m")) {
    text += format("team OSPA %.3g m, people held %.1f %% of the time",
                   number(team, "team_ospa_mean_m"), 100.0 * number(team, "held_fraction"));
    text += format(" (a track within %g m whose 99 %% ellipse holds it; mean over steps)\n",
                   number(team, "held_distance_m"));
  }
  const Json& planning = summary.at("timing").at("planning");
  if (planning.empty()) {
    text += "planning: none (scripted paths)\n";
  } else {
    double epochs = 0, weighted = 0, worst = 0;
    for (const Json& p : planning) {
      epochs += number(p, "epochs");
      weighted += number(p, "epochs") * number(p, "mean_s");
      worst = std::max(worst, number(p, "max_s"));
    }
    text +=
        format("planning: %.3g s per epoch on average, %.3g s at most (%g epochs over all UAVs)\n",
               epochs > 0 ? weighted / epochs : 0.0, worst, epochs);
  }
  return text;
}

std::vector<std::string> runWarnings(const std::string& summary_json) {
  const Json summary = Json::parse(summary_json);
  std::vector<std::string> warnings;
  if (summary.contains("fusion_diagnostics")) {
    const double failures = number(summary["fusion_diagnostics"], "numerical_failures");
    if (failures > 0) {
      warnings.push_back(
          format("fusion had %g numerical failures (summary.json: "
                 "fusion_diagnostics.numerical_failures)",
                 failures));
    }
  }
  // An agent against a wall, a trunk or another agent for seconds on end is most likely stuck
  // (issue 51: a rover stayed against a wall for 170 steps and the run said nothing).
  const double dt = number(summary, "dt");
  for (const Json& uav : summary.at("uavs")) {
    const double stuck = number(uav, "longest_contact_steps");
    if (dt > 0.0 && stuck * dt >= kStuckSeconds) {
      const double from = number(uav, "longest_contact_from_step");
      warnings.push_back(printable(uav.at("name").get<std::string>(), 40) +
                         format(": against something solid for %g steps in a row (%g s from "
                                "t = %g s): stuck?",
                                stuck, stuck * dt, from * dt) +
                         " (summary.json: uavs[].longest_contact_steps; what it touched: "
                         "record.jsonl uavs[].contacts; a scripted path into a wall: canopy "
                         "validate)");
    }
  }
  for (const Json& uav : summary.at("uavs")) {
    if (!uav.contains("tracking_diagnostics")) continue;
    const double bad = number(uav["tracking_diagnostics"], "non_positive_covariances");
    if (bad > 0) {
      warnings.push_back(printable(uav.at("name").get<std::string>(), 40) +
                         format(": %g covariances were not positive definite (summary.json: "
                                "tracking_diagnostics.non_positive_covariances)",
                                bad));
    }
  }
  return warnings;
}

}  // namespace canopy::sim
