#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "analysis/report.h"
#include "app/commands.h"
#include "app/help.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "core/text_file.h"
#include "experiments/sweep_mpi.h"

namespace canopy::app {

int reproduceCommand(Args& args) {
  std::string out;
  int trials = 40;
  int jobs = std::max(1u, std::thread::hardware_concurrency());
  std::uint64_t seed = 1;
  bool mpi = false;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--out") {
      out = args.outputDirValue(arg);
    } else if (arg == "--trials") {
      trials = args.intValue(arg, 1, 100000);
    } else if (arg == "--jobs") {
      jobs = args.intValue(arg, 1, 1024);
    } else if (arg == "--seed") {
      seed = args.unsignedValue(arg);
    } else if (arg == "--mpi") {
      mpi = true;
    } else {
      unknownOption("reproduce", arg);
    }
  }
  if (out.empty()) usageError("reproduce", "expected --out DIR");
  const bool analyses = !mpi || (experiments::mpiAvailable() && experiments::mpiWorld().rank == 0);
  const auto start = std::chrono::steady_clock::now();
  std::vector<analysis::ExperimentResult> results;
  int ran = 0;
  auto runAll = [&](const std::vector<analysis::Experiment>& experiments) {
    std::vector<analysis::ExperimentResult> done;
    for (const analysis::Experiment& experiment : experiments) {
      const std::filesystem::path dir = std::filesystem::path(out) / experiment.scenario;
      checkOutputDirectories(dir / "analysis", out);  // no links planted in DIR
      ran += mpi ? runSweepOverMpi(experiment.sweep, dir, jobs)
                 : runSweepWithProgress(experiment.sweep, dir, jobs);
      if (!analyses) continue;  // under MPI only rank 0 analyses and reports
      analysis::SweepAnalysis analysed = analysis::analyseSweep(dir);
      analysis::writeTables(analysed, dir / "analysis");
      analysis::writeFigures(analysed, dir / "analysis", experiment.maps);
      done.push_back({experiment, std::move(analysed), experiment.scenario + "/analysis"});
    }
    return done;
  };
  results = runAll(analysis::paperExperiments(trials, seed));
  // The sensitivity maps: half the trials per cell (at least 1), on the same seed.
  const std::vector<analysis::ExperimentResult> studies =
      runAll(analysis::sensitivityStudies(std::max(1, trials / 2), seed));
  if (mpi) ran = experiments::sumOverRanks(ran);  // the trials every rank ran now
  if (!analyses) return kExitOk;
  analysis::ReportContext context;
  context.trials = trials;
  context.seed = seed;
  context.jobs = jobs;
  context.ranks = mpi ? experiments::mpiWorld().size : 1;
  context.trials_run = ran;
  context.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::filesystem::path report = std::filesystem::path(out) / "report.md";
  writeFileAtomically(report, analysis::reportMarkdown(results, context, studies));
  std::printf("reproduce: %d trials run in %.1f s → %s\n", ran, context.wall_seconds,
              printable(report.string()).c_str());
  return kExitOk;
}

}  // namespace canopy::app
