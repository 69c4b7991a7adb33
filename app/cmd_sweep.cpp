#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "analysis/heatmap.h"
#include "analysis/intervals.h"
#include "analysis/sweep_analysis.h"
#include "app/commands.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "scenarios/sweep.h"

namespace canopy::app {
namespace {

// A one-line progress bar on stderr: redrawn in place on a terminal, a line per 10 % otherwise.
class ProgressBar {
 public:
  explicit ProgressBar(const std::string& label)
      : label_(printable(label, 100)), tty_(isatty(STDERR_FILENO)) {}
  void update(const scenarios::SweepProgress& p) {
    if (p.total == 0) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const int ran = p.done - p.resumed;
    const double rate = elapsed > 0 ? ran / elapsed : 0.0;
    const double eta = rate > 0 ? (p.total - p.done) / rate : 0.0;
    const int decile = 10 * p.done / p.total;
    if (!tty_ && decile == last_decile_ && p.done != p.total) return;
    last_decile_ = decile;
    char bar[31];
    const int filled = 30 * p.done / p.total;
    for (int i = 0; i < 30; ++i) bar[i] = i < filled ? '#' : '.';
    bar[30] = '\0';
    std::fprintf(stderr, "%s%s [%s] %d/%d trials (%d resumed), %.1f trials/s, ETA %.0f s%s",
                 tty_ ? "\r" : "", label_.c_str(), bar, p.done, p.total, p.resumed, rate, eta,
                 tty_ && p.done < p.total ? "" : "\n");
  }

 private:
  std::string label_;
  bool tty_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

int defaultJobs() {
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace

int runSweepWithProgress(const scenarios::SweepSpec& sweep, const std::filesystem::path& out,
                         int jobs) {
  // runSweep makes DIR/trials/CONFIG/ as it goes and follows what is there: links planted in DIR
  // would lead the trial files out of it. Refused before anything is written.
  for (const scenarios::SweepConfig& config : scenarios::configurations(sweep))
    checkOutputDirectories(out / "trials" / config.id, out);
  ProgressBar bar(sweep.name);
  return scenarios::runSweep(
      sweep, {out, jobs, [&bar](const scenarios::SweepProgress& p) { bar.update(p); }});
}

int sweepCommand(Args& args) {
  std::string file, out;
  int jobs = defaultJobs();
  scenarios::LoadOptions load;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--out") {
      out = args.outputDirValue(arg);
    } else if (arg == "--jobs") {
      jobs = args.intValue(arg, 1, 1024);
    } else if (takeLoadOption(args, arg, load)) {
    } else if (!arg.empty() && arg[0] == '-') {
      usageError(arg, "unknown option for `canopy sweep`");
    } else if (file.empty()) {
      file = arg;
    } else {
      usageError(arg, "expected one sweep file, got a second one");
    }
  }
  if (file.empty() || out.empty()) usageError("sweep", "expected SWEEP.json and --out DIR");
  const scenarios::SweepSpec sweep = scenarios::loadSweep(file, load);
  const auto start = std::chrono::steady_clock::now();
  const int ran = runSweepWithProgress(sweep, out, jobs);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: ran %d trials in %.1f s with %d jobs → %s/trials/\n",
              printable(sweep.name, 200).c_str(), ran, seconds, jobs, printable(out).c_str());
  return kExitOk;
}

int analyzeCommand(Args& args) {
  std::string dir, out;
  analysis::HeatmapRequest maps;
  scenarios::LoadOptions load;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--out") {
      out = args.outputDirValue(arg);
    } else if (takeLoadOption(args, arg, load)) {
    } else if (arg == "--state") {
      maps.state = args.value(arg);
    } else if (arg == "--before-hiding") {
      maps.before_hiding_s = args.doubleValue(arg);
      if (!(maps.before_hiding_s > 0.0) || maps.before_hiding_s > 1e6)
        usageError(arg, "expected a window in seconds, in (0, 1e6]");
    } else if (!arg.empty() && arg[0] == '-') {
      usageError(arg, "unknown option for `canopy analyze`");
    } else if (dir.empty()) {
      dir = arg;
    } else {
      usageError(arg, "expected one sweep directory, got a second one");
    }
  }
  if (dir.empty()) usageError("analyze", "expected a sweep directory");
  const analysis::SweepAnalysis result = analysis::analyseSweep(dir, load);
  analysis::heatmapMetric(result, maps);  // a bad --state fails before anything is written
  if (out.empty()) {
    out = dir + "/analysis";
    checkOutputDir(out, "--out (default, DIR/analysis)");
    checkOutputDirectories(out, dir);  // not a link planted in the sweep's directory
  }
  analysis::writeTables(result, out);
  analysis::writeFigures(result, out, maps);
  for (const analysis::ConfigStatistics& config : result.configs) {
    std::printf("%-40s %3d trials  at L:", printable(config.id, 200).c_str(), config.trials);
    for (std::size_t i = 0; i < config.states.size(); ++i) {
      if (config.state_counts[4][i] > 0) {
        const analysis::Estimate e = analysis::proportion(config.state_counts[4][i], config.trials);
        std::printf("  %s %.0f%% [%.0f, %.0f]", printable(config.states[i], 100).c_str(),
                    100.0 * e.value, 100.0 * e.ci.low, 100.0 * e.ci.high);
      }
    }
    std::printf("\n");
  }
  std::printf("tables and figures → %s/\n", printable(out).c_str());
  return kExitOk;
}

}  // namespace canopy::app
