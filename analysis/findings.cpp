#include "analysis/findings.h"

#include <algorithm>

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
  Estimate e = meanOf(per_trial);
  e.ci = clipped(e.ci, 0.0, 1.0);
  return e;
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
    const ConfigStatistics* none = r ? findConfig(*r, "planner.occlusion_map", "none") : nullptr;
    if (!none) continue;
    for (const OcclusionStatistics& o : none->occlusions) {
      for (const char* map : {"a_priori", "dynamic"}) {
        const ConfigStatistics* s = findConfig(*r, "planner.occlusion_map", map);
        if (!s) continue;
        cases.push_back({scenario, targetName(r->analysis, o.target), map,
                         s->coverageOver(o.target, o.hidden),
                         none->coverageOver(o.target, o.hidden)});
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
                                                        const std::string& target_name) {
  const ExperimentResult* os = findExperiment(results, "occlusion_sharing");
  if (!os) return std::nullopt;
  const int target = targetIndex(os->analysis, target_name);
  const ConfigStatistics* apr = findConfig(*os, "planner.occlusion_map", "a_priori");
  const ConfigStatistics* dyn = findConfig(*os, "planner.occlusion_map", "dynamic");
  const ConfigStatistics* none = findConfig(*os, "planner.occlusion_map", "none");
  const OcclusionStatistics* hidden = apr && target >= 0 ? episode(*apr, target) : nullptr;
  if (!apr || !dyn || !none || !hidden) return std::nullopt;
  return CoverageByMap{apr->coverageOver(target, hidden->hidden),
                       dyn->coverageOver(target, hidden->hidden),
                       none->coverageOver(target, hidden->hidden)};
}

std::optional<CatchUpFinding> catchUp(const std::vector<ExperimentResult>& results) {
  const auto c = sharingCoverageWhileHidden(results, "III");
  if (!c) return std::nullopt;
  return CatchUpFinding{c->a_priori, c->dynamic, c->none};
}

std::optional<FirstOcclusionRanking> firstRanking(const std::vector<ExperimentResult>& results) {
  const auto c = sharingCoverageWhileHidden(results, "I");
  if (!c) return std::nullopt;
  return FirstOcclusionRanking{c->a_priori, c->dynamic, c->none};
}

std::vector<ReactionRow> reactionRows(const std::vector<ExperimentResult>& results) {
  std::vector<ReactionRow> rows;
  const ExperimentResult* je = findExperiment(results, "joint_effect");
  const int I = je ? targetIndex(je->analysis, "I") : -1;
  if (I < 0) return rows;
  for (const char* map : {"a_priori", "dynamic", "none"}) {
    const ConfigStatistics* s = findConfig(*je, "planner.occlusion_map", map);
    if (!s) continue;
    ReactionRow row{map, std::nullopt, std::nullopt};
    if (const int k = firstBelow(s->coverage[I], 0.9); k >= 0) row.onset_s = k * s->dt;
    if (const int k = firstBelow(s->coverage[I], 0.5); k >= 0) row.half_s = k * s->dt;
    rows.push_back(row);
  }
  return rows;
}

FailureSymptoms symptoms(const std::vector<ExperimentResult>& results,
                         const std::vector<ReactionRow>& reaction,
                         const std::optional<FirstOcclusionRanking>& ranking) {
  FailureSymptoms f;
  if (const ExperimentResult* ra = findExperiment(results, "resource_allocation")) {
    const ConfigStatistics* s = findConfig(*ra, "planner", "dec_pomdp", "planner.horizon", "5");
    f.single_swarm_never = s && s->stateFraction("M*", 4) == 0.0;
  }
  for (const ReactionRow& row : reaction) {
    if (row.map == "a_priori") f.reaction_late = !row.onset_s || *row.onset_s >= 2.2;
  }
  f.first_occlusion_unranked = ranking && !ranking->holds();
  return f;
}

}  // namespace

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

std::optional<bool> dynamicReactsLater(const std::vector<ReactionRow>& rows) {
  std::optional<double> a_priori, dynamic;
  for (const ReactionRow& row : rows) {
    if (row.map == "a_priori") a_priori = row.half_s;
    if (row.map == "dynamic") dynamic = row.half_s;
  }
  if (!a_priori || !dynamic) return std::nullopt;
  return *dynamic > *a_priori;
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
