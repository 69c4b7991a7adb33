#include "analysis/sweep_analysis.h"

#include <fstream>
#include <stdexcept>

#include "analysis/figure_png.h"
#include "analysis/plots.h"
#include "scenarios/loader.h"
#include "scenarios/sweep.h"

namespace canopy::analysis {
namespace fs = std::filesystem;

SweepAnalysis analyseSweep(const fs::path& sweep_dir) {
  const scenarios::SweepResults results = scenarios::loadSweepResults(sweep_dir);
  SweepAnalysis analysis;
  analysis.name = results.sweep.name;
  for (std::size_t c = 0; c < results.configs.size(); ++c) {
    if (results.trials[c].empty()) continue;
    const scenarios::SweepConfig& config = results.configs[c];
    analysis.specs.push_back(
        scenarios::loadScenario(results.sweep.scenario, {config.overrides, std::nullopt}));
    analysis.configs.push_back(
        summarise(results.trials[c], analysis.specs.back(), config.id, config.overrides));
  }
  return analysis;
}

namespace {

std::ofstream openCsv(const fs::path& path, const char* header) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << header << '\n';
  return out;
}

std::string quoted(const std::string& text) {
  return "\"" + text + "\"";
}

}  // namespace

void writeTables(const SweepAnalysis& analysis, const fs::path& out_dir) {
  fs::create_directories(out_dir);
  auto states =
      openCsv(out_dir / "ownership_states.csv", "config,column,step,t_s,state,trials,fraction");
  auto flows = openCsv(out_dir / "ownership_flows.csv",
                       "config,from_column,to_column,from_state,to_state,trials");
  auto changes =
      openCsv(out_dir / "ownership_changes.csv", "config,from_uav,to_uav,target,trials,fraction");
  auto aware = openCsv(out_dir / "occlusion_aware.csv",
                       "config,target,hidden_from_s,hidden_to_s,trials,p_aware,trials_with_event,p_"
                       "aware_given_event");
  auto coverage =
      openCsv(out_dir / "coverage.csv", "config,target,step,t_s,mean_coverage,occluded");
  auto tracking =
      openCsv(out_dir / "tracking.csv", "config,step,t_s,mean_ospa_m,mean_trace_pos_m2");

  for (std::size_t c = 0; c < analysis.configs.size(); ++c) {
    const ConfigStatistics& s = analysis.configs[c];
    const scenarios::ScenarioSpec& spec = analysis.specs[c];
    const std::string id = quoted(s.id);
    for (int col = 0; col < 5; ++col) {
      for (std::size_t i = 0; i < s.states.size(); ++i) {
        states << id << ',' << col << ',' << s.columns[col] << ',' << s.columns[col] * s.dt << ','
               << quoted(s.states[i]) << ',' << s.state_counts[col][i] << ','
               << static_cast<double>(s.state_counts[col][i]) / s.trials << '\n';
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
              << static_cast<double>(change.trials) / s.trials << '\n';
    }
    std::vector<std::vector<bool>> occluded(spec.targets.size(),
                                            std::vector<bool>(s.ospa.size(), false));
    for (const OcclusionStatistics& o : s.occlusions) {
      aware << id << ',' << quoted(spec.targets[o.target].name) << ',' << o.hidden.first * s.dt
            << ',' << o.hidden.last * s.dt << ',' << o.trials << ',' << o.pAware() << ','
            << o.with_event << ',' << o.pAwareGivenEvent() << '\n';
      for (int k = o.hidden.first; k <= o.hidden.last; ++k) occluded[o.target][k] = true;
    }
    for (std::size_t t = 0; t < s.coverage.size(); ++t) {
      for (int k = 0; k < static_cast<int>(s.coverage[t].size()); ++k) {
        coverage << id << ',' << quoted(spec.targets[t].name) << ',' << k << ',' << k * s.dt << ','
                 << s.coverage[t][k] << ',' << (occluded[t][k] ? 1 : 0) << '\n';
      }
    }
    for (int k = 0; k < static_cast<int>(s.ospa.size()); ++k) {
      tracking << id << ',' << k << ',' << k * s.dt << ',' << s.ospa[k] << ',' << s.trace[k]
               << '\n';
    }
  }
}

}  // namespace canopy::analysis

namespace canopy::analysis {

void writeFigures(const SweepAnalysis& analysis, const fs::path& out_dir) {
  fs::create_directories(out_dir);
  auto write = [&](const fs::path& stem, const Figure& figure) {
    std::ofstream out(stem.string() + ".svg", std::ios::trunc);
    out << toSvg(figure);
    if (!out) throw std::runtime_error("cannot write " + stem.string() + ".svg");
    writeFigurePng(figure, stem.string() + ".png");
  };
  std::vector<const ConfigStatistics*> configs;
  std::vector<std::string> labels;
  for (const ConfigStatistics& s : analysis.configs) {
    write(out_dir / ("sankey_" + s.id), sankeyFigure(s, analysis.name + ": ownership, " + s.id));
    configs.push_back(&s);
    labels.push_back(s.id);
  }
  if (!analysis.specs.empty()) {
    std::vector<std::string> targets;
    for (const auto& target : analysis.specs.front().targets) targets.push_back(target.name);
    write(out_dir / "coverage",
          coverageFigure(configs, labels, targets, analysis.name + ": coverage per trajectory"));
  }
}

}  // namespace canopy::analysis
