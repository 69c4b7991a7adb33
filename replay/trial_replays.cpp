#include "replay/trial_replays.h"

#include <stdexcept>

#include "analysis/trial_behaviour.h"
#include "core/text_file.h"
#include "experiments/trial.h"
#include "replay/replay_page.h"
#include "sim/run.h"

namespace canopy::replay {
namespace {

namespace fs = std::filesystem;

// A state's name as one file name component: letters, digits, '.', '-' kept, others '_'.
std::string safeName(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '-';
    out += keep ? c : '_';
  }
  return out;
}

std::string indexPage(const analysis::SweepAnalysis& analysis,
                      const std::vector<TrialReplay>& replays) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<link rel=\"icon\" href=\"data:,\">\n<title>replays: " +
      htmlEscaped(analysis.name) +
      "</title>\n<style>body{font:14px/1.4 sans-serif;margin:1.5em;color:#141414}"
      "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:3px 8px;text-align:left}"
      "</style>\n</head>\n<body>\n<h1>" +
      htmlEscaped(analysis.name) +
      ": one replay per behaviour</h1>\n<p>For each configuration and each ownership state at the "
      "last step L (the Sankey diagram's last column), the first trial that ended in it, run "
      "again with its seed. Open a replay to see what the team did.</p>\n<table>\n<tr><th>"
      "configuration</th><th>state at L</th><th>trials in it</th><th>trial (seed)</th><th>replay"
      "</th></tr>\n";
  for (const TrialReplay& r : replays) {
    html += "<tr><td>" + htmlEscaped(r.config) + "</td><td>" + htmlEscaped(r.state) + "</td><td>" +
            std::to_string(r.trials_in_state) + " of " + std::to_string(r.trials) + "</td><td>" +
            std::to_string(r.trial) + " (" + std::to_string(r.seed) + ")</td><td><a href=\"" +
            htmlEscaped(r.page.generic_string()) + "\">replay</a></td></tr>\n";
  }
  return html + "</table>\n</body>\n</html>\n";
}

}  // namespace

std::vector<TrialReplay> writeTrialReplays(const analysis::SweepAnalysis& analysis,
                                           const fs::path& out_dir) {
  std::vector<TrialReplay> replays;
  for (std::size_t c = 0; c < analysis.configs.size(); ++c) {
    const analysis::ConfigStatistics& config = analysis.configs[c];
    for (std::size_t s = 0; s < config.states.size(); ++s) {
      const int in_state = config.state_counts[4][s];
      if (in_state == 0) continue;
      int trial = 0;
      while (config.trial_states[static_cast<std::size_t>(trial)][4] != static_cast<int>(s))
        ++trial;
      TrialReplay r{config.id, config.states[s],
                    in_state,  config.trials,
                    trial,     config.trial_seeds[static_cast<std::size_t>(trial)],
                    {}};
      const fs::path folder =
          fs::path("replays") / config.id / (std::to_string(s) + "_" + safeName(r.state));
      spec::ScenarioSpec spec = analysis.specs[c];
      spec.seed = r.seed;
      // The run again, its trial collected beside the record to check it is the same trial.
      experiments::TrialCollector collector(spec);
      sim::RunOptions options;
      options.out_dir = out_dir / folder;
      options.command_line = "canopy analyze (replay of trial " + std::to_string(trial) + ")";
      options.observers.push_back(&collector);
      sim::runScenario(spec, options);
      const analysis::TrialBehaviour again = analysis::analyseTrial(collector.take(), spec);
      if (again.states[4] != r.state) {
        throw std::logic_error("trial " + std::to_string(trial) + " of " + config.id +
                               " run again ends in " + again.states[4] + ", not " + r.state);
      }
      writeReplay(out_dir / folder, out_dir / folder / "replay.html");
      r.page = folder / "replay.html";
      replays.push_back(std::move(r));
    }
  }
  writeFileAtomically(out_dir / "replays.html", indexPage(analysis, replays));
  return replays;
}

}  // namespace canopy::replay
