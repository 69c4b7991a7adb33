#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "analysis/heatmap.h"
#include "analysis/intervals.h"
#include "analysis/sweep_analysis.h"
#include "app/commands.h"
#include "app/help.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "experiments/sweep.h"
#include "experiments/sweep_mpi.h"
#include "replay/trial_replays.h"

namespace canopy::app {
namespace {

// A one-line progress bar on stderr: redrawn in place on a terminal, a line per 10 % otherwise.
class ProgressBar {
 public:
  explicit ProgressBar(const std::string& label)
      : label_(printable(label, 100)), tty_(isatty(STDERR_FILENO)) {}
  void update(const experiments::SweepProgress& p) {
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

int runSweepWithProgress(const experiments::SweepSpec& sweep, const std::filesystem::path& out,
                         int jobs, const experiments::Shard& shard) {
  // runSweep makes DIR/trials/CONFIG/ as it goes and follows what is there: links planted in DIR
  // would lead the trial files out of it. Refused before anything is written.
  for (const experiments::SweepConfig& config : experiments::configurations(sweep))
    checkOutputDirectories(out / "trials" / config.id, out);
  ProgressBar bar(shard.whole() ? sweep.name
                                : sweep.name + " shard " + std::to_string(shard.index) + "/" +
                                      std::to_string(shard.count));
  return experiments::runSweep(
      sweep, {out, jobs, [&bar](const experiments::SweepProgress& p) { bar.update(p); }, shard});
}

int runSweepOverMpi(const experiments::SweepSpec& sweep, const std::filesystem::path& out,
                    int jobs) {
  if (!experiments::mpiAvailable())
    usageError("--mpi",
               "this canopy was built without MPI: install the Debian packages "
               "libopenmpi-dev and openmpi-bin, then rebuild (./canopy does both)");
  for (const experiments::SweepConfig& config : experiments::configurations(sweep))
    checkOutputDirectories(out / "trials" / config.id, out);
  return experiments::runSweepMpi(sweep, out, jobs);
}

namespace {

// "I/N" with 0 <= I < N.
experiments::Shard shardValue(Args& args, const std::string& name) {
  const std::string text = args.value(name);
  experiments::Shard shard;
  const std::size_t slash = text.find('/');
  char* end = nullptr;
  const long index = slash == std::string::npos ? -1 : std::strtol(text.c_str(), &end, 10);
  const bool index_ok = slash != std::string::npos && end == text.c_str() + slash && slash > 0;
  const long count = index_ok ? std::strtol(text.c_str() + slash + 1, &end, 10) : 0;
  if (!index_ok || *end != '\0' || slash + 1 == text.size() || count < 1 || count > 1000000 ||
      index < 0 || index >= count) {
    usageError(name, "expected I/N with 0 <= I < N <= 1000000, got '" + printable(text, 100) + "'");
  }
  shard.index = static_cast<int>(index);
  shard.count = static_cast<int>(count);
  return shard;
}

int statusCommand(const std::string& dir) {
  const experiments::SweepStatus status = experiments::sweepStatus(dir);
  int done = 0;
  for (const auto& [id, finished] : status.finished) {
    std::printf("%-50s %d/%d\n", printable(id, 200).c_str(), finished, status.trials_per_config);
    done += finished;
  }
  const int total = status.trials_per_config * static_cast<int>(status.finished.size());
  std::printf("%s: %d/%d trials done%s\n", printable(status.name, 200).c_str(), done, total,
              done == total ? "" : "; run `canopy sweep FILE --out DIR` to finish");
  return kExitOk;
}

}  // namespace

int sweepCommand(Args& args) {
  std::string file, out, status;
  int jobs = defaultJobs();
  experiments::Shard shard;
  bool mpi = false;
  spec::LoadOptions load;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--out") {
      out = args.outputDirValue(arg);
    } else if (arg == "--jobs") {
      jobs = args.intValue(arg, 1, 1024);
    } else if (arg == "--shard") {
      shard = shardValue(args, arg);
    } else if (arg == "--mpi") {
      mpi = true;
    } else if (arg == "--status") {
      status = args.value(arg);
    } else if (takeLoadOption(args, arg, load)) {
    } else if (!arg.empty() && arg[0] == '-') {
      unknownOption("sweep", arg);
    } else if (file.empty()) {
      file = arg;
    } else {
      usageError(arg, "expected one sweep file, got a second one");
    }
  }
  if (!status.empty()) {
    if (!file.empty() || !out.empty() || mpi || !shard.whole())
      usageError("--status", "expected only --status DIR");
    return statusCommand(status);
  }
  if (file.empty() || out.empty()) usageError("sweep", "expected SWEEP.json and --out DIR");
  if (mpi && !shard.whole()) usageError("--mpi", "expected either --mpi or --shard, not both");
  const experiments::SweepSpec sweep = experiments::loadSweep(file, load);
  const auto start = std::chrono::steady_clock::now();
  const int ran =
      mpi ? runSweepOverMpi(sweep, out, jobs) : runSweepWithProgress(sweep, out, jobs, shard);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (mpi) {
    std::printf("%s: rank %d of %d ran %d trials in %.1f s with %d jobs → %s/trials/\n",
                printable(sweep.name, 200).c_str(), experiments::mpiWorld().rank,
                experiments::mpiWorld().size, ran, seconds, jobs, printable(out).c_str());
  } else if (!shard.whole()) {
    std::printf(
        "%s: shard %d/%d ran %d trials in %.1f s with %d jobs → %s/trials/ (run without "
        "--shard to finish)\n",
        printable(sweep.name, 200).c_str(), shard.index, shard.count, ran, seconds, jobs,
        printable(out).c_str());
  } else {
    std::printf("%s: ran %d trials in %.1f s with %d jobs → %s/trials/\n",
                printable(sweep.name, 200).c_str(), ran, seconds, jobs, printable(out).c_str());
  }
  return kExitOk;
}

int analyzeCommand(Args& args) {
  std::string dir, out;
  analysis::HeatmapRequest maps;
  spec::LoadOptions load;
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
      unknownOption("analyze", arg);
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
  std::printf(
      "Ownership state at the last step L, per configuration: the share of trials in each state "
      "with its 95 %% Wilson interval.\nA state is the sets of targets each UAV owns (m-ownership: "
      "kept in its footprint over the window; docs/design-notes.md, \"Behaviour analysis\");\n"
      "named states (M*, …) come from the scenario's analysis.states; \"Miss 1\" / \"Miss >1\": "
      "one / several targets owned by no UAV; \"Other\": every target owned, in no named "
      "state.\n");
  if (!result.specs.empty() && result.specs.front().analysis.states.empty()) {
    std::printf(
        "note: the scenario names no analysis.states, so every trial that misses no "
        "target is \"Other\"; name states in its analysis section to tell them apart.\n");
  }
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
  const std::vector<replay::TrialReplay> replays = replay::writeTrialReplays(result, out);
  for (const replay::TrialReplay& r : replays) {
    std::printf("replay of %s, %s at L: %s/%s\n", printable(r.config, 200).c_str(),
                printable(r.state, 100).c_str(), printable(out).c_str(),
                printable(r.page.string()).c_str());
  }
  std::printf("tables and figures → %s/ (replays.html links one replay per behaviour)\n",
              printable(out).c_str());
  return kExitOk;
}

}  // namespace canopy::app
