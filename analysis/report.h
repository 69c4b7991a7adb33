#pragma once
// `canopy reproduce`'s report.md: every figure, our numbers beside the paper's, the qualitative
// findings checked one by one, the configuration used, and where we differ.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/decision_time.h"
#include "analysis/experiments.h"
#include "analysis/sweep_analysis.h"

namespace canopy::analysis {

struct ExperimentResult {
  Experiment experiment;
  SweepAnalysis analysis;
  std::string figures;  // directory of its figures, relative to the report
  // Per configuration (analysis.configs order) when the experiment is timed, else empty.
  std::vector<DecisionTime> decision_times;
};

struct ReportContext {
  int trials = 0;          // per configuration
  std::uint64_t seed = 0;  // the sweeps' seed
  int jobs = 1;   // threads per process
  int ranks = 1;  // MPI processes (1 without --mpi)
  double wall_seconds = 0;  // of the whole reproduction (sweeps run now, analysis, figures)
  int trials_run = 0;       // trials run now (the rest were resumed from disk)
  int timing_trials = 0;    // trials per configuration run again to time the decisions
};

/// Mean of `curve` over the inclusive steps of `hidden`.
double meanOver(const std::vector<double>& curve, const Interval& hidden);

/// results: the paper's experiment table (paperExperiments); studies: the sensitivity studies
/// (sensitivityStudies), drawn as maps under "Where the behaviour emerges"; learned: the learned
/// planner's held-out variants (learnedStudies).
std::string reportMarkdown(const std::vector<ExperimentResult>& results,
                           const ReportContext& context,
                           const std::vector<ExperimentResult>& studies = {},
                           const std::vector<ExperimentResult>& learned = {});

}  // namespace canopy::analysis
