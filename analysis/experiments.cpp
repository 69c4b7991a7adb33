#include "analysis/experiments.h"

namespace canopy::analysis {

std::vector<Experiment> paperExperiments(int trials, std::uint64_t seed) {
  std::vector<Experiment> experiments;
  for (const char* scenario : {"trajectory_handover", "resource_allocation"}) {
    scenarios::SweepSpec sweep;
    sweep.name = scenario;
    sweep.scenario = scenario;
    sweep.trials = trials;
    sweep.seed = seed;
    sweep.axes = {{"planner.algorithm", {"\"sma\"", "\"dec_pomdp\""}, {}},
                  {"planner.horizon", {"1", "5"}, {}}};
    experiments.push_back({scenario, sweep, true});
  }
  for (const char* scenario : {"joint_effect", "occlusion_sharing"}) {
    scenarios::SweepSpec sweep;
    sweep.name = scenario;
    sweep.scenario = scenario;
    sweep.trials = trials;
    sweep.seed = seed;
    sweep.fixed = {"planner.algorithm=\"sma\"", "planner.horizon=5"};
    sweep.axes = {{"planner.occlusion_map", {"\"a_priori\"", "\"dynamic\"", "\"none\""}, {}}};
    experiments.push_back({scenario, sweep, false});
  }
  for (Experiment& e : experiments) {
    // The same effective text a sweep file would give, so DIR/<scenario>/sweep.json reloads.
    std::string axes;
    for (const auto& axis : e.sweep.axes) {
      std::string values;
      for (const auto& v : axis.values) values += (values.empty() ? "" : ", ") + v;
      axes += std::string(axes.empty() ? "" : ", ") + "{\"path\": \"" + axis.path +
              "\", \"values\": [" + values + "]}";
    }
    std::string fixed;
    for (const auto& f : e.sweep.fixed) {
      const auto eq = f.find('=');
      fixed += std::string(fixed.empty() ? "" : ", ") + "\"" + f.substr(0, eq) +
               "\": " + f.substr(eq + 1);
    }
    const std::string text = "{\"name\": \"" + e.sweep.name + "\", \"scenario\": \"" +
                             e.sweep.scenario + "\", \"trials\": " + std::to_string(trials) +
                             ", \"seed\": " + std::to_string(seed) + ", \"set\": {" + fixed +
                             "}, \"axes\": [" + axes + "]}";
    e.sweep = scenarios::loadSweepText(text, e.scenario + ".json");
  }
  return experiments;
}

const std::vector<PaperOwnership>& paperOwnership() {
  static const std::vector<PaperOwnership> table = {
      {"trajectory_handover", "dec_pomdp", 5, 0.975, 1.0,
       "H = 5: 100 % at L for both; 97.5 % vs 85 % at L/2"},
      {"trajectory_handover", "sma", 5, 0.85, 1.0, ""},
      {"trajectory_handover", "dec_pomdp", 1, std::nullopt, std::nullopt, "not stated"},
      {"trajectory_handover", "sma", 1, std::nullopt, 0.85, "15 % end in a less cooperative state"},
      {"resource_allocation", "dec_pomdp", 5, std::nullopt, 0.5, "about half reach M*"},
      {"resource_allocation", "sma", 5, std::nullopt, 0.5, "about half reach M*"},
      {"resource_allocation", "dec_pomdp", 1, std::nullopt, 0.05, ""},
      {"resource_allocation", "sma", 1, std::nullopt, 0.125, ""},
  };
  return table;
}

}  // namespace canopy::analysis
