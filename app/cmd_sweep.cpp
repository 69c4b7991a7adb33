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
#include "core/number_text.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "core/progress.h"
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

}  // namespace

int defaultJobs() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void checkSweepOutputs(const experiments::SweepSpec& sweep, const std::filesystem::path& out) {
  checkOutputEntries(out);
  for (const experiments::SweepConfig& config : experiments::configurations(sweep)) {
    checkOutputDirectories(out / "trials" / config.id, out);
    checkOutputEntries(out / "trials" / config.id);
  }
}

int runSweepWithProgress(const experiments::SweepSpec& sweep, const std::filesystem::path& out,
                         int jobs, const experiments::Shard& shard) {
  // runSweep makes DIR/trials/CONFIG/ as it goes and follows what is there: links planted in DIR
  // would lead the trial files out of it; a device, FIFO or socket in DIR is not ours to
  // replace. Refused before anything is written.
  checkSweepOutputs(sweep, out);
  // The bar shows the sweep; a trial's own stages ("running steps") would break into it.
  const StagesSilenced quiet;
  ProgressBar bar(shard.whole() ? sweep.name
                                : sweep.name + " shard " + std::to_string(shard.index) + "/" +
                                      std::to_string(shard.count));
  return experiments::runSweep(
      sweep, {out, jobs, [&bar](const experiments::SweepProgress& p) { bar.update(p); }, shard});
}

int runSweepOverMpi(const experiments::SweepSpec& sweep, const std::filesystem::path& out,
                    int jobs) {
  if (!experiments::mpiAvailable()) usageError("--mpi", experiments::mpiProblem());
  checkSweepOutputs(sweep, out);
  return experiments::runSweepMpi(sweep, out, jobs);
}

namespace {

// "I/N" with 0 <= I < N <= 1000000.
std::optional<experiments::Shard> readShard(const std::string& text) {
  // Plain decimal digits on both sides: no blanks, signs or leading zeros (' 1/2', '+1/2').
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos || text[0] == '-') return std::nullopt;
  const std::optional<long long> index = strictInteger(text.substr(0, slash), 0, 999999);
  const std::optional<long long> count = strictInteger(text.substr(slash + 1), 1, 1000000);
  if (!index || !count || *index >= *count) return std::nullopt;
  return experiments::Shard{static_cast<int>(*index), static_cast<int>(*count)};
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

class Sweep : public Command {
 public:
  explicit Sweep(CLI::App& canopy)
      : Command(canopy, "sweep", "canopy sweep SWEEP.json --out DIR [options]",
                "Monte Carlo trials of a sweep file on a thread pool, a shard or MPI ranks; "
                "resumable.") {
    CLI::App& o = options();
    o.add_option("SWEEP.json", file_, "the sweep file, or a built-in sweep's name");
    addOutputDir(o, "--out", out_, "the sweep's folder (resumable)")->default_str("required");
    addValue(o, "--jobs", "N", jobs_, integerIn(1, 1024), "trials run at once")
        ->default_str("the number of cores");
    addValue(o, "--shard", "I/N", shard_,
             Reader<experiments::Shard>{readShard, "I/N with 0 <= I < N <= 1000000"},
             "run only shard I of N (0 <= I < N)")
        ->default_str("all trials");
    o.add_flag("--mpi", mpi_, "deal trials over the ranks of mpirun");
    o.add_option("--status", status_, "count the finished trials in DIR and exit")
        ->type_name("DIR")
        ->default_str("none");
    addLoadOptions(o, load_);
  }
  int run() override;

 private:
  std::string file_, out_, status_;
  int jobs_ = defaultJobs();
  experiments::Shard shard_;
  bool mpi_ = false;
  spec::LoadOptions load_;
};

int Sweep::run() {
  if (!status_.empty()) {
    if (!file_.empty() || !out_.empty() || mpi_ || !shard_.whole())
      usageError("--status", "expected only --status DIR");
    return statusCommand(status_);
  }
  if (file_.empty() || out_.empty()) usageError("sweep", "expected SWEEP.json and --out DIR");
  if (mpi_ && !shard_.whole()) usageError("--mpi", "expected either --mpi or --shard, not both");
  const experiments::SweepSpec sweep =
      experiments::loadSweep(experiments::resolveSweep(file_).string(), load_);
  const auto start = std::chrono::steady_clock::now();
  const int ran =
      mpi_ ? runSweepOverMpi(sweep, out_, jobs_) : runSweepWithProgress(sweep, out_, jobs_, shard_);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (mpi_) {
    std::printf("%s: rank %d of %d ran %d trials in %.1f s with %d jobs → %s/trials/\n",
                printable(sweep.name, 200).c_str(), experiments::mpiWorld().rank,
                experiments::mpiWorld().size, ran, seconds, jobs_, printable(out_).c_str());
  } else if (!shard_.whole()) {
    std::printf(
        "%s: shard %d/%d ran %d trials in %.1f s with %d jobs → %s/trials/ (run without "
        "--shard to finish)\n",
        printable(sweep.name, 200).c_str(), shard_.index, shard_.count, ran, seconds, jobs_,
        printable(out_).c_str());
  } else {
    std::printf("%s: ran %d trials in %.1f s with %d jobs → %s/trials/\n",
                printable(sweep.name, 200).c_str(), ran, seconds, jobs_, printable(out_).c_str());
  }
  return kExitOk;
}

class Analyze : public Command {
 public:
  explicit Analyze(CLI::App& canopy)
      : Command(canopy, "analyze", "canopy analyze DIR [options]",
                "Behaviour statistics of a sweep with 95 % intervals: CSV tables and figures.") {
    CLI::App& o = options();
    o.add_option("DIR", dir_, "the sweep's folder");
    addOutputDir(o, "--out", out_, "where tables and figures go")->default_str("DIR/analysis");
    o.add_option("--state", maps_.state, "the state the sensitivity maps count at L")
        ->type_name("NAME")
        ->default_str("M* (or hidden coverage for occlusion scenarios)");
    addValue(o, "--before-hiding", "S", maps_.before_hiding_s,
             finiteNumber("a window in seconds, in (0, 1e6]",
                          [](double s) { return s > 0.0 && s <= 1e6; }),
             "maps: coverage in the S seconds before the target is hidden")
        ->default_str("off");
    addStyleOption(o, style_);
    addLoadOptions(o, load_);
  }
  int run() override;

 private:
  std::string dir_, out_;
  std::string style_;
  analysis::HeatmapRequest maps_;
  spec::LoadOptions load_;
};

int Analyze::run() {
  if (dir_.empty()) usageError("analyze", "expected a sweep directory");
  if (out_.empty()) {
    out_ = dir_ + "/analysis";
    checkOutputDir(out_, "--out (default, DIR/analysis)");
    checkOutputDirectories(out_, dir_);  // not a link planted in the sweep's directory
  }
  checkOutputEntries(out_);  // a device, FIFO or socket where a table would go: refused first
  const analysis::FigureStyle style = readStyleOption(style_);  // a bad file: exit 2 first
  const analysis::SweepAnalysis result = analysis::analyseSweep(dir_, load_);
  analysis::heatmapMetric(result, maps_);  // a bad --state fails before anything is written
  analysis::writeTables(result, out_);
  analysis::writeFigures(result, out_, maps_, style);
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
  const replay::TrialReplays replays = replay::writeTrialReplays(result, out_);
  for (const replay::TrialReplay& r : replays.replays) {
    std::printf("replay of %s, %s at L: %s/%s\n", printable(r.config, 200).c_str(),
                printable(r.state, 100).c_str(), printable(out_).c_str(),
                printable(r.page.string()).c_str());
  }
  for (const replay::TrialPair& p : replays.pairs) {
    std::printf("trial %d under %s and %s side by side: %s/%s\n", p.trial,
                printable(p.config_a, 200).c_str(), printable(p.config_b, 200).c_str(),
                printable(out_).c_str(), printable(p.page.string()).c_str());
  }
  std::printf(
      "tables and figures → %s/ (replays.html links one replay per behaviour, and pairs of "
      "trials side by side)\n",
      printable(out_).c_str());
  return kExitOk;
}

}  // namespace

std::unique_ptr<Command> makeSweep(CLI::App& canopy) {
  return std::make_unique<Sweep>(canopy);
}

std::unique_ptr<Command> makeAnalyze(CLI::App& canopy) {
  return std::make_unique<Analyze>(canopy);
}

}  // namespace canopy::app
