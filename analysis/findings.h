#pragma once
// The report's qualitative findings as values: each computed from the experiments into a small
// struct with its numbers and its verdict, so that report.md only renders them (and tests check
// the computation without reading prose).
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "analysis/reaction.h"
#include "analysis/report.h"

namespace canopy::analysis {

/// How report.md decides a claim from the 95 % intervals printed beside it (docs/design-notes.md,
/// "Verdicts"): it "holds" when the intervals separate in the claimed direction, "fails" when they
/// separate the other way, and is "consistent" when they overlap (the trials cannot tell); a
/// number with no interval (one trial, or too few agreeing trials) gives "too few trials".
enum class Verdict { holds, consistent, fails, too_few_trials };
const char* verdictText(Verdict v);
/// The claim "`above` is greater than `below`": holds when above.low > below.high, fails when
/// above.high < below.low. An interval end at ±∞ bounds nothing on that side.
Verdict claimAbove(const ConfidenceInterval& above, const ConfidenceInterval& below);
/// A claim made of several: too few trials when any part is, fails when any part fails, holds when
/// every part holds, consistent otherwise.
Verdict allOf(std::initializer_list<Verdict> parts);

/// Finding 1: a longer horizon is more cooperative. Per scenario and planner, the mean over
/// trials of the fraction of the Sankey columns L/4 … L spent in M*, at H = 5 and H = 1.
struct HorizonCase {
  std::string scenario, planner;
  Estimate h5, h1;
  Verdict verdict() const { return claimAbove(h5.ci, h1.ci); }
};

/// Finding 2: a map cuts the wasted coverage of an occluded trajectory (footprints on it while
/// it is hidden), against no map, at the same decision period.
struct WastedCoverageCase {
  std::string scenario, target, map, decisions;  // decisions: DecisionPeriod::label
  Estimate with_map, without_map;
  Verdict verdict() const { return claimAbove(without_map.ci, with_map.ci); }
};

/// Finding 3 (Occlusion Sharing, III): the dynamic map closes at least 75 % of the gap between
/// no map and the a-priori map: there is a gap (no map above a-priori) and the dynamic map is
/// below the threshold T = a_priori + 0.25 (none − a_priori) = 0.75 a_priori + 0.25 none, whose
/// interval is taken as [0.75 a.low + 0.25 n.low, 0.75 a.high + 0.25 n.high] (each end from the
/// same end of both intervals: wider than T's own interval, so the verdict errs towards
/// "consistent").
struct CatchUpFinding {
  std::string decisions;
  Estimate a_priori, dynamic, none;
  ConfidenceInterval threshold() const;
  Verdict verdict() const;
};

/// Finding 5 (Occlusion Sharing, I's 0.8 s occlusion): the maps ranked in the order of their
/// awareness, a-priori below dynamic below no map in footprints on hidden I.
struct FirstOcclusionRanking {
  std::string decisions;
  Estimate a_priori, dynamic, none;
  /// Both steps of the ranking: dynamic above a-priori, and no map above dynamic.
  Verdict verdict() const {
    return allOf({claimAbove(dynamic.ci, a_priori.ci), claimAbove(none.ci, dynamic.ci)});
  }
};

/// Joint Effect's reaction to I hiding, per map and decision period: the first time the mean
/// coverage of I is below 0.9 (onset) and below 0.5 (half), each with its bootstrap interval.
struct ReactionRow {
  std::string map, decisions;
  CrossingTime onset, half;
  Estimate while_hidden;  // mean footprints on I over its hidden steps (no map: "keeps trying")
};

/// With no map the UAVs keep observing hidden I: at least this many footprints on it while it
/// is hidden, on average (docs/calibration.md's rule).
inline constexpr double kKeepsObserving = 0.8;

/// Finding 4: the dynamic map reacts later than the a-priori map (half-way times, by their
/// bootstrap intervals) at the given decision period; nothing when either map never gets there.
std::optional<Verdict> dynamicReactsLater(const std::vector<ReactionRow>& rows,
                                          const std::string& decisions);

/// The a-priori onset of a row set at one decision period is before I hides (2.2 s, the
/// paper's interval), as the paper's ≈ 1.6 s is: holds when the onset's interval ends before
/// 2.2 s, fails when it starts after 2.2 s (or the curve never crosses), consistent when it
/// reaches 2.2 s; nothing when the decision period was not run.
std::optional<Verdict> reactsBeforeHiding(const std::vector<ReactionRow>& rows,
                                          const std::string& decisions);

/// Symptoms behind the findings that fail, each with the numbers that show it.
struct FailureSymptoms {
  bool single_swarm_never = false;  // Dec-POMDP, the paper's one swarm, H = 5: 0 in M* at L (RA)
  bool reaction_late = false;  // JE, decisions every 1 s: the a-priori onset not before 2.2 s
  bool first_occlusion_unranked = false;  // OS, decisions every 1 s: finding 5 does not hold
};

struct Findings {
  std::vector<HorizonCase> horizon;
  std::vector<WastedCoverageCase> wasted;
  std::vector<CatchUpFinding> catch_up;            // one per decision period run
  std::vector<FirstOcclusionRanking> first_ranking;  // one per decision period run
  std::vector<ReactionRow> reaction;  // empty when Joint Effect was not run
  FailureSymptoms symptoms;
};

Findings computeFindings(const std::vector<ExperimentResult>& results);

// Lookups shared with report.cpp.
const ExperimentResult* findExperiment(const std::vector<ExperimentResult>& results,
                                       const std::string& scenario);
/// The configuration whose value on `path` (and `path2`, when given) is as asked, unquoted.
const ConfigStatistics* findConfig(const ExperimentResult& r, const std::string& path,
                                   const std::string& value, const std::string& path2 = "",
                                   const std::string& value2 = "");
/// The value a configuration gives an axis or path, unquoted ("planner.horizon" → "5").
std::string axisText(const ConfigStatistics& s, const std::string& path);
/// The occlusion experiment's configuration with this map and decision period (s); a
/// configuration with no planner.replan_period axis decides every 1 s.
const ConfigStatistics* findOcclusionConfig(const ExperimentResult& r, const std::string& map,
                                            double decision_period_s);

/// The planners of the TH and RA experiments (the sweep axis "planner", experiments.cpp).
struct PlannerVariant {
  const char* axis_value;  // the axis value
  const char* algorithm;   // the paper's algorithm it stands for
  const char* label;
};
inline constexpr PlannerVariant kPlanners[] = {
    {"sma", "sma", "SMA-NBO"},
    {"dec_pomdp", "dec_pomdp", "Dec-POMDP"},
    {"dec_pomdp_global", "dec_pomdp", "Dec-POMDP, the paper's one swarm"},
    {"dec_pomdp_local", "dec_pomdp", "Dec-POMDP, local-best swarm"},
    {"learned", "learned", "learned (imitates SMA-NBO)"},
};

}  // namespace canopy::analysis
