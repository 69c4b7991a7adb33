#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "analysis/report.h"
#include "app/commands.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "core/progress.h"
#include "core/text_file.h"
#include "experiments/sweep_mpi.h"

namespace canopy::app {

namespace {

class Reproduce : public Command {
 public:
  explicit Reproduce(CLI::App& canopy)
      : Command(canopy, "reproduce", "canopy reproduce --out DIR [options]",
                "The paper's experiment table, four sensitivity studies, the learned planner's "
                "held-out variants and each planner's decision time per agent → DIR/report.md.") {
    CLI::App& o = options();
    addOutputDir(o, "--out", out_, "where the sweeps and report.md go")->default_str("required");
    addValue(o, "--trials", "N", trials_, integerIn(1, 100000),
             "trials per configuration (sensitivity maps: N/2)")
        ->default_str(std::to_string(trials_));
    addValue(o, "--jobs", "N", jobs_, integerIn(1, 1024), "trials run at once")
        ->default_str("the number of cores");
    addValue(o, "--seed", "S", seed_, nonNegativeInteger(), "the sweeps' seed")
        ->default_str(std::to_string(seed_));
    addValue(o, "--timing-trials", "N", timing_trials_, integerIn(0, 100000),
             "trials per planner configuration run again, one at a time, to time each agent's "
             "decisions (at most --trials; 0: none)")
        ->default_str(std::to_string(timing_trials_));
    o.add_flag("--mpi", mpi_, "deal trials over the ranks of mpirun");
    addStyleOption(o, style_);
  }
  int run() override;

 private:
  std::string out_;
  int trials_ = 40;
  int jobs_ = defaultJobs();
  std::uint64_t seed_ = 1;
  int timing_trials_ = 5;
  bool mpi_ = false;
  std::string style_;
};

int Reproduce::run() {
  if (out_.empty()) usageError("reproduce", "expected --out DIR");
  const analysis::FigureStyle style = readStyleOption(style_);  // a bad file: exit 2 first
  // Every folder it will write into, before the first trial runs.
  checkOutputFile(std::filesystem::path(out_) / "report.md");
  const StagesSilenced quiet;  // the sweeps' bars say how far it got
  // The sensitivity maps: half the trials per cell (at least 1), on the same seed.
  const std::vector<analysis::Experiment> paper = analysis::paperExperiments(trials_, seed_);
  const std::vector<analysis::Experiment> sensitivity =
      analysis::sensitivityStudies(std::max(1, trials_ / 2), seed_);
  const std::vector<analysis::Experiment> learned = analysis::learnedStudies(trials_, seed_);
  for (const auto* experiments : {&paper, &sensitivity, &learned}) {
    for (const analysis::Experiment& experiment : *experiments) {
      const std::filesystem::path dir = std::filesystem::path(out_) / experiment.scenario;
      checkSweepOutputs(experiment.sweep, dir);
      checkOutputEntries(dir / "analysis");
    }
  }
  const bool analyses = !mpi_ || (experiments::mpiAvailable() && experiments::mpiWorld().rank == 0);
  const auto start = std::chrono::steady_clock::now();
  std::vector<analysis::ExperimentResult> results;
  int ran = 0;
  auto runAll = [&](const std::vector<analysis::Experiment>& experiments) {
    std::vector<analysis::ExperimentResult> done;
    for (const analysis::Experiment& experiment : experiments) {
      const std::filesystem::path dir = std::filesystem::path(out_) / experiment.scenario;
      checkOutputDirectories(dir / "analysis", out_);  // no links planted in DIR
      ran += mpi_ ? runSweepOverMpi(experiment.sweep, dir, jobs_)
                  : runSweepWithProgress(experiment.sweep, dir, jobs_);
      if (!analyses) continue;  // under MPI only rank 0 analyses and reports
      analysis::SweepAnalysis analysed = analysis::analyseSweep(dir);
      analysis::writeTables(analysed, dir / "analysis");
      analysis::writeFigures(analysed, dir / "analysis", experiment.maps, style);
      done.push_back({experiment, std::move(analysed), experiment.scenario + "/analysis", {}});
    }
    return done;
  };
  results = runAll(paper);
  const std::vector<analysis::ExperimentResult> studies = runAll(sensitivity);
  std::vector<analysis::ExperimentResult> held_out = runAll(learned);
  if (mpi_) ran = experiments::sumOverRanks(ran);  // the trials every rank ran now
  if (!analyses) return kExitOk;
  // Each agent's decision time: the first trials of every timed configuration again, one at a
  // time on this thread (the sweeps ran several at once), every planning call timed.
  const int timing_trials = std::min(timing_trials_, trials_);
  for (auto* set : {&results, &held_out}) {
    for (analysis::ExperimentResult& r : *set) {
      if (!r.experiment.timed || timing_trials == 0) continue;
      for (std::size_t c = 0; c < r.analysis.configs.size(); ++c) {
        const std::vector<std::uint64_t>& seeds = r.analysis.configs[c].trial_seeds;
        r.decision_times.push_back(analysis::timeDecisions(
            r.analysis.specs[c],
            {seeds.begin(), seeds.begin() + std::min<std::ptrdiff_t>(
                                                timing_trials, std::ssize(seeds))}));
      }
      std::fprintf(stderr, "reproduce: timed the decisions of %s\n",
                   printable(r.experiment.scenario).c_str());
    }
  }
  analysis::ReportContext context;
  context.trials = trials_;
  context.seed = seed_;
  context.jobs = jobs_;
  context.ranks = mpi_ ? experiments::mpiWorld().size : 1;
  context.trials_run = ran;
  context.timing_trials = timing_trials;
  context.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::filesystem::path report = std::filesystem::path(out_) / "report.md";
  writeFileAtomically(report, analysis::reportMarkdown(results, context, studies, held_out));
  std::printf("reproduce: %d trials run in %.1f s → %s\n", ran, context.wall_seconds,
              printable(report.string()).c_str());
  return kExitOk;
}

}  // namespace

std::unique_ptr<Command> makeReproduce(CLI::App& canopy) {
  return std::make_unique<Reproduce>(canopy);
}

}  // namespace canopy::app
