#include "analysis/findings.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace canopy::analysis {
namespace {

// Per trial, the fraction of the Sankey columns L/4 … L at which it is in M*; their mean over
// trials (the mean over those columns of the fraction of trials in M*) says how early and how
// often the team is in the cooperative state.
Estimate cooperation(const ConfigStatistics& s) {
  const auto m_star = std::find(s.states.begin(), s.states.end(), "M*") - s.states.begin();
  std::vector<double> per_trial;
  for (const std::array<int, 5>& columns : s.trial_states) {
    int in = 0;
    for (int c = 1; c < 5; ++c) in += columns[c] == m_star;
    per_trial.push_back(in / 4.0);
  }
  return boundedMeanOf(per_trial, 0.0, 1.0);
}

const OcclusionStatistics* episode(const ConfigStatistics& s, int target) {
  for (const OcclusionStatistics& o : s.occlusions) {
    if (o.target == target) return &o;
  }
  return nullptr;
}

int targetIndex(const SweepAnalysis& a, const std::string& name) {
  if (a.specs.empty()) return -1;
  const auto& targets = a.specs.front().targets;
  for (int t = 0; t < static_cast<int>(targets.size()); ++t) {
    if (targets[t].name == name) return t;
  }
  return -1;
}

std::string targetName(const SweepAnalysis& a, int target) {
  return a.specs.empty() ? std::to_string(target) : a.specs.front().targets[target].name;
}

std::vector<HorizonCase> horizonCases(const std::vector<ExperimentResult>& results) {
  std::vector<HorizonCase> cases;
  for (const char* scenario : {"trajectory_handover", "resource_allocation"}) {
    const ExperimentResult* r = findExperiment(results, scenario);
    if (!r) continue;
    for (const PlannerVariant& planner : kPlanners) {
      // The paper's claim is about its planners; the learned one is reported beside them only.
      if (std::string(planner.algorithm) == "learned") continue;
      const ConfigStatistics* h1 =
          findConfig(*r, "planner", planner.axis_value, "planner.horizon", "1");
      const ConfigStatistics* h5 =
          findConfig(*r, "planner", planner.axis_value, "planner.horizon", "5");
      if (h1 && h5) cases.push_back({scenario, planner.label, cooperation(*h5), cooperation(*h1)});
    }
  }
  return cases;
}

std::vector<WastedCoverageCase> wastedCases(const std::vector<ExperimentResult>& results) {
  std::vector<WastedCoverageCase> cases;
  for (const char* scenario : {"joint_effect", "occlusion_sharing"}) {
    const ExperimentResult* r = findExperiment(results, scenario);
    if (!r) continue;
    for (const DecisionPeriod& period : decisionPeriods()) {
      const ConfigStatistics* none = findOcclusionConfig(*r, "none", period.seconds);
      if (!none) continue;
      for (const OcclusionStatistics& o : none->occlusions) {
        for (const char* map : {"a_priori", "dynamic"}) {
          const ConfigStatistics* s = findOcclusionConfig(*r, map, period.seconds);
          if (!s) continue;
          cases.push_back({scenario, targetName(r->analysis, o.target), map, period.label,
                           s->coverageOver(o.target, o.hidden),
                           none->coverageOver(o.target, o.hidden)});
        }
      }
    }
  }
  return cases;
}

// Occlusion Sharing's coverage of `target` while it is hidden (its first occluded interval under
// the a-priori map), per map: a-priori, dynamic, none; nothing when a piece is missing.
struct CoverageByMap {
  Estimate a_priori, dynamic, none;
};

std::optional<CoverageByMap> sharingCoverageWhileHidden(const std::vector<ExperimentResult>& results,
                                                        const std::string& target_name,
                                                        double decision_period_s) {
  const ExperimentResult* os = findExperiment(results, "occlusion_sharing");
  if (!os) return std::nullopt;
  const int target = targetIndex(os->analysis, target_name);
  const ConfigStatistics* apr = findOcclusionConfig(*os, "a_priori", decision_period_s);
  const ConfigStatistics* dyn = findOcclusionConfig(*os, "dynamic", decision_period_s);
  const ConfigStatistics* none = findOcclusionConfig(*os, "none", decision_period_s);
  const OcclusionStatistics* hidden = apr && target >= 0 ? episode(*apr, target) : nullptr;
  if (!apr || !dyn || !none || !hidden) return std::nullopt;
  return CoverageByMap{apr->coverageOver(target, hidden->hidden),
                       dyn->coverageOver(target, hidden->hidden),
                       none->coverageOver(target, hidden->hidden)};
}

std::vector<CatchUpFinding> catchUp(const std::vector<ExperimentResult>& results) {
  std::vector<CatchUpFinding> findings;
  for (const DecisionPeriod& period : decisionPeriods()) {
    if (const auto c = sharingCoverageWhileHidden(results, "III", period.seconds))
      findings.push_back({period.label, c->a_priori, c->dynamic, c->none});
  }
  return findings;
}

std::vector<FirstOcclusionRanking> firstRanking(const std::vector<ExperimentResult>& results) {
  std::vector<FirstOcclusionRanking> findings;
  for (const DecisionPeriod& period : decisionPeriods()) {
    if (const auto c = sharingCoverageWhileHidden(results, "I", period.seconds))
      findings.push_back({period.label, c->a_priori, c->dynamic, c->none});
  }
  return findings;
}

// The bootstrap's stream: one seed for the report, so the same trials give the same intervals.
constexpr std::uint64_t kBootstrapSeed = 1;

std::vector<ReactionRow> reactionRows(const std::vector<ExperimentResult>& results) {
  std::vector<ReactionRow> rows;
  const ExperimentResult* je = findExperiment(results, "joint_effect");
  const int I = je ? targetIndex(je->analysis, "I") : -1;
  if (I < 0) return rows;
  for (const DecisionPeriod& period : decisionPeriods()) {
    for (const char* map : {"a_priori", "dynamic", "none"}) {
      const ConfigStatistics* s = findOcclusionConfig(*je, map, period.seconds);
      if (!s) continue;
      const OcclusionStatistics* hidden = episode(*s, I);
      rows.push_back({map, period.label, firstCrossing(*s, I, 0.9, kBootstrapSeed),
                      firstCrossing(*s, I, 0.5, kBootstrapSeed),
                      hidden ? s->coverageOver(I, hidden->hidden) : Estimate{}});
    }
  }
  return rows;
}

const ReactionRow* reactionOf(const std::vector<ReactionRow>& rows, const std::string& map,
                              const std::string& decisions) {
  for (const ReactionRow& row : rows) {
    if (row.map == map && row.decisions == decisions) return &row;
  }
  return nullptr;
}

FailureSymptoms symptoms(const std::vector<ExperimentResult>& results,
                         const std::vector<ReactionRow>& reaction,
                         const std::vector<FirstOcclusionRanking>& ranking) {
  FailureSymptoms f;
  if (const ExperimentResult* ra = findExperiment(results, "resource_allocation")) {
    const ConfigStatistics* s =
        findConfig(*ra, "planner", "dec_pomdp_global", "planner.horizon", "5");
    f.single_swarm_never = s && s->stateFraction("M*", 4) == 0.0;
  }
  const std::string every_second = decisionPeriods().front().label;
  const std::optional<Verdict> before = reactsBeforeHiding(reaction, every_second);
  f.reaction_late = before && *before != Verdict::holds;
  for (const FirstOcclusionRanking& r : ranking) {
    if (r.decisions == every_second) f.first_occlusion_unranked = r.verdict() != Verdict::holds;
  }
  return f;
}

}  // namespace

const char* verdictText(Verdict v) {
  switch (v) {
    case Verdict::holds:
      return "holds";
    case Verdict::consistent:
      return "consistent";
    case Verdict::fails:
      return "fails";
    case Verdict::too_few_trials:
      return "too few trials";
  }
  return "";
}

Verdict claimAbove(const ConfidenceInterval& above, const ConfidenceInterval& below) {
  // An interval unbounded on both sides: no interval at all.
  const auto none = [](const ConfidenceInterval& ci) {
    return std::isinf(ci.low) && std::isinf(ci.high);
  };
  if (none(above) || none(below)) return Verdict::too_few_trials;
  if (above.low > below.high) return Verdict::holds;
  if (above.high < below.low) return Verdict::fails;
  return Verdict::consistent;
}

Verdict allOf(std::initializer_list<Verdict> parts) {
  for (const Verdict v : {Verdict::too_few_trials, Verdict::fails, Verdict::consistent}) {
    if (std::find(parts.begin(), parts.end(), v) != parts.end()) return v;
  }
  return Verdict::holds;
}

ConfidenceInterval CatchUpFinding::threshold() const {
  return {0.75 * a_priori.ci.low + 0.25 * none.ci.low,
          0.75 * a_priori.ci.high + 0.25 * none.ci.high};
}

Verdict CatchUpFinding::verdict() const {
  return allOf({claimAbove(none.ci, a_priori.ci), claimAbove(threshold(), dynamic.ci)});
}

const ExperimentResult* findExperiment(const std::vector<ExperimentResult>& results,
                                       const std::string& scenario) {
  for (const ExperimentResult& r : results) {
    if (r.experiment.scenario == scenario) return &r;
  }
  return nullptr;
}

std::string axisText(const ConfigStatistics& s, const std::string& path) {
  std::string v = s.axisValue(path);
  if (v.size() >= 2 && v.front() == '"') v = v.substr(1, v.size() - 2);
  return v;
}

const ConfigStatistics* findConfig(const ExperimentResult& r, const std::string& path,
                                   const std::string& value, const std::string& path2,
                                   const std::string& value2) {
  for (const ConfigStatistics& s : r.analysis.configs) {
    if (axisText(s, path) == value && (path2.empty() || axisText(s, path2) == value2)) return &s;
  }
  return nullptr;
}

const ConfigStatistics* findOcclusionConfig(const ExperimentResult& r, const std::string& map,
                                            double decision_period_s) {
  for (const ConfigStatistics& s : r.analysis.configs) {
    const std::string period = axisText(s, "planner.replan_period");
    const double seconds = period.empty() ? 1.0 : std::strtod(period.c_str(), nullptr);
    if (axisText(s, "planner.occlusion_map") == map && seconds == decision_period_s) return &s;
  }
  return nullptr;
}

std::optional<Verdict> dynamicReactsLater(const std::vector<ReactionRow>& rows,
                                          const std::string& decisions) {
  const ReactionRow* a_priori = reactionOf(rows, "a_priori", decisions);
  const ReactionRow* dynamic = reactionOf(rows, "dynamic", decisions);
  if (!a_priori || !dynamic || !a_priori->half.time_s || !dynamic->half.time_s) return std::nullopt;
  return claimAbove(dynamic->half.ci, a_priori->half.ci);
}

std::optional<Verdict> reactsBeforeHiding(const std::vector<ReactionRow>& rows,
                                          const std::string& decisions) {
  const ReactionRow* a_priori = reactionOf(rows, "a_priori", decisions);
  if (!a_priori) return std::nullopt;
  if (!a_priori->onset.time_s) return Verdict::fails;  // never leaves I
  return claimAbove({kJointEffectHiding, kJointEffectHiding}, a_priori->onset.ci);
}

Findings computeFindings(const std::vector<ExperimentResult>& results) {
  Findings f;
  f.horizon = horizonCases(results);
  f.wasted = wastedCases(results);
  f.catch_up = catchUp(results);
  f.first_ranking = firstRanking(results);
  f.reaction = reactionRows(results);
  f.symptoms = symptoms(results, f.reaction, f.first_ranking);
  return f;
}

}  // namespace canopy::analysis
