#include "replay/trial_replays.h"

#include <algorithm>
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

std::string indexPage(const analysis::SweepAnalysis& analysis, const TrialReplays& all) {
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
  for (const TrialReplay& r : all.replays) {
    html += "<tr><td>" + htmlEscaped(r.config) + "</td><td>" + htmlEscaped(r.state) + "</td><td>" +
            std::to_string(r.trials_in_state) + " of " + std::to_string(r.trials) + "</td><td>" +
            std::to_string(r.trial) + " (" + std::to_string(r.seed) + ")</td><td><a href=\"" +
            htmlEscaped(r.page.generic_string()) + "\">replay</a></td></tr>\n";
  }
  html += "</table>\n";
  if (!all.pairs.empty()) {
    html +=
        "<h2>The same trial under two configurations</h2>\n<p>Each trial above of a configuration "
        "after the first, beside the same trial (the same seed) of the first configuration, on "
        "one clock with linked views.</p>\n<table>\n<tr><th>trial (seed)</th><th>configuration A"
        "</th><th>state at L</th><th>configuration B</th><th>state at L</th><th>side by side"
        "</th></tr>\n";
    for (const TrialPair& p : all.pairs) {
      html += "<tr><td>" + std::to_string(p.trial) + " (" + std::to_string(p.seed) + ")</td><td>" +
              htmlEscaped(p.config_a) + "</td><td>" + htmlEscaped(p.state_a) + "</td><td>" +
              htmlEscaped(p.config_b) + "</td><td>" + htmlEscaped(p.state_b) +
              "</td><td><a href=\"" + htmlEscaped(p.page.generic_string()) +
              "\">side by side</a></td></tr>\n";
    }
    html += "</table>\n";
  }
  return html + "</body>\n</html>\n";
}

// Runs trial `trial` of configuration c again into out_dir / folder (a run folder with its
// replay.html); throws when it does not end in the state its trial file recorded.
void runAgain(const analysis::SweepAnalysis& analysis, std::size_t c, int trial,
              const fs::path& out_dir, const fs::path& folder) {
  const analysis::ConfigStatistics& config = analysis.configs[c];
  const std::string& state =
      config.states[static_cast<std::size_t>(config.trial_states[static_cast<std::size_t>(trial)][4])];
  spec::ScenarioSpec spec = analysis.specs[c];
  spec.seed = config.trial_seeds[static_cast<std::size_t>(trial)];
  // The run again, its trial collected beside the record to check it is the same trial.
  experiments::TrialCollector collector(spec);
  sim::RunOptions options;
  options.out_dir = out_dir / folder;
  options.command_line = "canopy analyze (replay of trial " + std::to_string(trial) + ")";
  options.observers.push_back(&collector);
  sim::runScenario(spec, options);
  const analysis::TrialBehaviour again = analysis::analyseTrial(collector.take(), spec);
  if (again.states[4] != state) {
    throw std::logic_error("trial " + std::to_string(trial) + " of " + config.id +
                           " run again ends in " + again.states[4] + ", not " + state);
  }
  writeReplay(out_dir / folder, out_dir / folder / "replay.html");
}

}  // namespace

TrialReplays writeTrialReplays(const analysis::SweepAnalysis& analysis, const fs::path& out_dir) {
  TrialReplays all;
  // The folder each (configuration, trial) was run again into.
  std::vector<std::vector<fs::path>> folders(analysis.configs.size());
  for (std::size_t c = 0; c < analysis.configs.size(); ++c) {
    const analysis::ConfigStatistics& config = analysis.configs[c];
    folders[c].resize(static_cast<std::size_t>(config.trials));
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
      runAgain(analysis, c, trial, out_dir, folder);
      folders[c][static_cast<std::size_t>(trial)] = folder;
      r.page = folder / "replay.html";
      all.replays.push_back(std::move(r));
    }
  }
  // Pairs: each replayed trial of a later configuration beside the same trial of the first.
  if (!analysis.configs.empty()) {
    const analysis::ConfigStatistics& first = analysis.configs[0];
    for (const TrialReplay& r : all.replays) {
      if (r.config == first.id || r.trial >= first.trials) continue;
      const auto t = static_cast<std::size_t>(r.trial);
      if (first.trial_seeds[t] != r.seed) continue;  // not the same trial (a sweep gives one seed)
      fs::path& base = folders[0][t];
      if (base.empty()) {
        base = fs::path("replays") / first.id / ("trial_" + std::to_string(r.trial));
        runAgain(analysis, 0, r.trial, out_dir, base);
      }
      const std::size_t c = static_cast<std::size_t>(
          std::find_if(analysis.configs.begin(), analysis.configs.end(),
                       [&](const analysis::ConfigStatistics& x) { return x.id == r.config; }) -
          analysis.configs.begin());
      const fs::path page = fs::path("replays") / "pairs" /
                            (safeName(r.config) + "_trial_" + std::to_string(r.trial) + ".html");
      fs::create_directories(out_dir / page.parent_path());
      writeSideBySide(out_dir / base, out_dir / folders[c][t], out_dir / page);
      all.pairs.push_back(TrialPair{
          first.id, r.config,
          first.states[static_cast<std::size_t>(first.trial_states[t][4])], r.state, r.trial,
          r.seed, page});
    }
  }
  writeFileAtomically(out_dir / "replays.html", indexPage(analysis, all));
  return all;
}

}  // namespace canopy::replay
