#pragma once
// report.md's learned-planner parts (issue 54): the decision time per agent of every timed
// planner, which of the paper's cooperative behaviours the learned policy keeps against SMA-NBO,
// and how it does on held-out variants.
#include <ostream>
#include <string>
#include <vector>

#include "analysis/findings.h"
#include "analysis/report.h"

namespace canopy::analysis {

/// "4.8 µs [4.1, 5.5]" or "3.90 ms [3.12, 4.71]": the mean per call with its interval; "—"
/// when not timed.
std::string decisionTimeText(const DecisionTime& t);

/// The decision time of configuration `s` of `r`; nullptr when `r` is not timed.
const DecisionTime* decisionTimeOf(const ExperimentResult& r, const ConfigStatistics& s);

/// How the learned planner compares with SMA-NBO on one behaviour, from the two intervals:
/// "lost" when learned's lies below SMA-NBO's, "higher than SMA-NBO" when above, "kept (the
/// intervals overlap)" otherwise, "too few trials" without intervals.
std::string keptText(const Estimate& sma, const Estimate& learned);

/// Every timed configuration's decision time per agent: mean with its interval, median, 90th
/// percentile and maximum, and its ratio to the learned planner's in the same setting.
void writeDecisionTimes(std::ostream& md, const std::vector<ExperimentResult>& results,
                        const std::vector<ExperimentResult>& learned, const ReportContext& ctx);

/// Ownership_Change (M* at L in TH and RA), Occlusion_Aware and Occlusion_Share (P[OA], P[OA | e]
/// in JE and OS, per trajectory, map and decision period): SMA-NBO beside the learned planner.
void writeLearnedBehaviours(std::ostream& md, const std::vector<ExperimentResult>& results);

/// The held-out variants (learnedStudies): M* at L per variant, SMA-NBO beside learned.
void writeLearnedHeldOut(std::ostream& md, const std::vector<ExperimentResult>& learned);

}  // namespace canopy::analysis
