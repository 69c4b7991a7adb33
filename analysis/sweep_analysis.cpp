#include "analysis/sweep_analysis.h"

#include <algorithm>
#include <sstream>

#include "analysis/configuration_summary.h"
#include "analysis/figure_png.h"
#include "analysis/heatmap.h"
#include "analysis/plots.h"
#include "core/output_file.h"
#include "core/text_file.h"
#include "experiments/sweep.h"
#include "spec/loader.h"

namespace canopy::analysis {
namespace fs = std::filesystem;

SweepAnalysis analyseSweep(const fs::path& sweep_dir, const spec::LoadOptions& load) {
  const experiments::SweepResults results = experiments::loadSweepResults(sweep_dir, load);
  SweepAnalysis analysis;
  analysis.name = results.sweep.name;
  analysis.dir = sweep_dir;
  analysis.axes = results.sweep.axes;
  for (std::size_t c = 0; c < results.configs.size(); ++c) {
    if (results.trials[c].empty()) continue;
    const experiments::SweepConfig& config = results.configs[c];
    spec::LoadOptions config_load = load;
    config_load.overrides = config.overrides;
    analysis.specs.push_back(spec::loadScenario(results.sweep.scenario, config_load));
    analysis.configs.push_back(
        summarise(results.trials[c], analysis.specs.back(), config.id, config.overrides));
    analysis.configs.back().point = config.point;
  }
  return analysis;
}

namespace {

// A table built in memory and written whole (writeFileAtomically) by write().
struct Csv {
  fs::path path;
  std::ostringstream text;
  Csv(fs::path file, const char* header) : path(std::move(file)) { text << header << '\n'; }
  void write() const { writeFileAtomically(path, text.str()); }
};

// A CSV field in quotes, its own quotes doubled (RFC 4180).
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// "value,low,high" in the stream's default format (empty low and high where too few trials
// bound the interval).
std::string estimate(const Estimate& e) {
  return csvNumber(e.value) + ',' + csvNumber(e.ci.low) + ',' + csvNumber(e.ci.high);
}

}  // namespace

bool hasTeamFigures(const SweepAnalysis& analysis) {
  return !analysis.configs.empty() &&
         std::all_of(analysis.configs.begin(), analysis.configs.end(),
                     [](const ConfigStatistics& s) { return !s.trial_team_ospa.empty(); });
}

void writeTables(const SweepAnalysis& analysis, const fs::path& out_dir) {
  makeOutputDirectories(out_dir, out_dir);
  Csv states_csv(out_dir / "ownership_states.csv",
                 "config,column,step,t_s,state,trials,fraction,fraction_low,fraction_high,"
                 "reached_trials,reached_fraction,reached_low,reached_high");
  Csv flows_csv(out_dir / "ownership_flows.csv",
                "config,from_column,to_column,from_state,to_state,trials");
  Csv changes_csv(out_dir / "ownership_changes.csv",
                  "config,from_uav,to_uav,target,trials,fraction,fraction_low,fraction_high");
  Csv aware_csv(out_dir / "occlusion_aware.csv",
                "config,target,hidden_from_s,hidden_to_s,trials,p_aware,p_aware_low,p_aware_"
                "high,trials_with_event,p_aware_given_event,p_aware_given_event_low,p_aware_"
                "given_event_high,mean_coverage_hidden,mean_coverage_hidden_low,mean_"
                "coverage_hidden_high");
  Csv coverage_csv(out_dir / "coverage.csv",
                   "config,target,step,t_s,mean_coverage,mean_coverage_low,mean_coverage_"
                   "high,occluded");
  Csv tracking_csv(out_dir / "tracking.csv",
                   "config,step,t_s,mean_ospa_m,mean_ospa_low_m,mean_ospa_high_m,mean_trace_"
                   "pos_m2,mean_trace_pos_low_m2,mean_trace_pos_high_m2,mean_team_ospa_m,mean_"
                   "team_ospa_low_m,mean_team_ospa_high_m,mean_held,mean_held_low,mean_held_high");
  std::ostringstream &states = states_csv.text, &flows = flows_csv.text,
                     &changes = changes_csv.text, &aware = aware_csv.text,
                     &coverage = coverage_csv.text, &tracking = tracking_csv.text;

  for (std::size_t c = 0; c < analysis.configs.size(); ++c) {
    const ConfigStatistics& s = analysis.configs[c];
    const spec::ScenarioSpec& spec = analysis.specs[c];
    const std::string id = quoted(s.id);
    const std::size_t named = spec.analysis.states.size();
    for (int col = 0; col < 5; ++col) {
      for (std::size_t i = 0; i < s.states.size(); ++i) {
        states << id << ',' << col << ',' << s.columns[col] << ',' << s.columns[col] * s.dt << ','
               << quoted(s.states[i]) << ',' << s.state_counts[col][i] << ','
               << estimate(s.stateEstimate(s.states[i], col)) << ',';
        if (i < named) {  // "reached by": the trials in state i at some step k ≤ this column's
          const int reached = s.reachedBy(s.states[i], s.columns[col]);
          states << reached << ',' << estimate(proportion(reached, s.trials)) << '\n';
        } else {
          states << ",,,\n";  // only named states have a first step
        }
      }
    }
    for (int g = 0; g < 4; ++g) {
      for (std::size_t a = 0; a < s.states.size(); ++a) {
        for (std::size_t b = 0; b < s.states.size(); ++b) {
          if (s.flows[g][a][b] == 0) continue;
          flows << id << ',' << g << ',' << g + 1 << ',' << quoted(s.states[a]) << ','
                << quoted(s.states[b]) << ',' << s.flows[g][a][b] << '\n';
        }
      }
    }
    for (const ChangeCount& change : s.changes) {
      changes << id << ',' << quoted(spec.uavs[change.change.from].name) << ','
              << quoted(spec.uavs[change.change.to].name) << ','
              << quoted(spec.targets[change.change.target].name) << ',' << change.trials << ','
              << estimate(proportion(change.trials, s.trials)) << '\n';
    }
    std::vector<std::vector<bool>> occluded(spec.targets.size(),
                                            std::vector<bool>(s.ospa.size(), false));
    for (const OcclusionStatistics& o : s.occlusions) {
      aware << id << ',' << quoted(spec.targets[o.target].name) << ',' << o.hidden.first * s.dt
            << ',' << o.hidden.last * s.dt << ',' << o.trials << ',' << estimate(o.awareEstimate())
            << ',' << o.with_event << ',' << estimate(o.awareGivenEventEstimate()) << ','
            << estimate(s.coverageOver(o.target, o.hidden)) << '\n';
      for (int k = o.hidden.first; k <= o.hidden.last; ++k) occluded[o.target][k] = true;
    }
    for (std::size_t t = 0; t < s.coverage.size(); ++t) {
      for (int k = 0; k < static_cast<int>(s.coverage[t].size()); ++k) {
        coverage << id << ',' << quoted(spec.targets[t].name) << ',' << k << ',' << k * s.dt << ','
                 << estimate({s.coverage[t][k], s.coverage_ci[t][k]}) << ','
                 << (occluded[t][k] ? 1 : 0) << '\n';
      }
    }
    for (int k = 0; k < static_cast<int>(s.ospa.size()); ++k) {
      tracking << id << ',' << k << ',' << k * s.dt << ',' << estimate({s.ospa[k], s.ospa_ci[k]})
               << ',' << estimate({s.trace[k], s.trace_ci[k]});
      if (k < static_cast<int>(s.team_ospa.size())) {  // trials that carry the team's figures
        tracking << ',' << estimate({s.team_ospa[k], s.team_ospa_ci[k]}) << ','
                 << estimate({s.held[k], s.held_ci[k]});
      } else {
        tracking << ",,,,,,";
      }
      tracking << '\n';
    }
  }
  for (const Csv* csv :
       {&states_csv, &flows_csv, &changes_csv, &aware_csv, &coverage_csv, &tracking_csv}) {
    csv->write();
  }
  if (!hasTeamFigures(analysis)) return;
  // The team per configuration (issue 53), the numbers of team_figures.
  Csv team_csv(out_dir / "team.csv",
               "config,trials,coverage,coverage_low,coverage_high,team_ospa_m,team_ospa_low_m,"
               "team_ospa_high_m,held,held_low,held_high");
  for (const ConfigurationSummary& row : summariseConfigurations(analysis)) {
    team_csv.text << quoted(row.config) << ',' << row.coverage.trials << ','
                  << estimate(row.coverage) << ',' << estimate(row.team_ospa) << ','
                  << estimate(row.held) << '\n';
  }
  team_csv.write();
}

}  // namespace canopy::analysis

namespace canopy::analysis {

void writeFigures(const SweepAnalysis& analysis, const fs::path& out_dir,
                  const HeatmapRequest& maps, const FigureStyle& style) {
  makeOutputDirectories(out_dir, out_dir);
  std::vector<const ConfigStatistics*> configs;
  std::vector<std::string> labels;
  for (const ConfigStatistics& s : analysis.configs) {
    writeFigure(sankeyFigure(s, analysis.name + ": ownership, " + s.id),
                out_dir / ("sankey_" + s.id), style);
    configs.push_back(&s);
    labels.push_back(s.id);
  }
  if (!analysis.specs.empty()) {
    std::vector<std::string> targets;
    for (const auto& target : analysis.specs.front().targets) targets.push_back(target.name);
    writeFigure(
        coverageFigure(configs, labels, targets, analysis.name + ": coverage per trajectory"),
        out_dir / "coverage", style);
  }
  writeHeatmaps(analysis, out_dir, maps, style);
  if (hasTeamFigures(analysis)) {  // the team per configuration (issue 53)
    writeFigure(configurationFigure(summariseConfigurations(analysis),
                                    analysis.name + ": the team per configuration"),
                out_dir / kTeamSummaryStem, style);
  }
}

}  // namespace canopy::analysis
