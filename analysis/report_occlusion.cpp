#include "analysis/report_occlusion.h"

#include <cstdio>
#include <string>

#include "analysis/report_numbers.h"

namespace canopy::analysis {
namespace {

std::string decisionsOf(const ConfigStatistics& s) {
  const std::string period = axisText(s, "planner.replan_period");
  return period.empty() ? "1" : num(std::strtod(period.c_str(), nullptr), "%g");
}

// "[0.62, 0.71]": the catch-up threshold's interval.
std::string thresholdText(const CatchUpFinding& c) {
  const ConfidenceInterval t = c.threshold();
  if (!t.bounded()) return "[too few trials]";
  return "[" + num(t.low) + ", " + num(t.high) + "]";
}

const char* paperReaction(const std::string& map) {
  return map == "a_priori" ? "≈ 1.6 s" : map == "dynamic" ? "≈ 2.2 s" : "keeps observing";
}

}  // namespace

void writeOcclusion(std::ostream& md, const std::vector<ExperimentResult>& results) {
  md << "## Occlusion awareness: Joint Effect and Occlusion Sharing\n\n";
  md << "Mean number of footprints on the occluded trajectory while it is hidden (wasted "
        "coverage), and the frequency of Occlusion_Aware (margin h = 1 s), with SMA-NBO, H = 5 "
        "(and the learned planner flying the scenario's shipped policy, not in the paper), "
        "per occlusion map and decision period: every 1 s (the first design's, "
        "docs/design-notes.md) or at every 0.2 s "
        "step with 1 s actions (the paper's \"generates a plan … at every time step\"; "
        "docs/design-notes.md, planner.replan_period).\n\n";
  md << "In brackets the 95 % interval: for the coverage, Student t over the trials' own means "
        "on the logit scale of coverage / UAVs (so that it stays inside [0, UAVs]), for the "
        "frequencies Wilson.\n\n";
  md << "| scenario | planner | trajectory | hidden | map | decisions every (s) | trials | mean "
        "coverage while hidden | P[OA] | P[OA \\| e] (trials with e) |\n";
  md << "|---|---|---|---|---|---:|---:|---:|---:|---:|\n";
  for (const ExperimentResult& r : results) {
    if (r.experiment.ownership) continue;
    for (const ConfigStatistics& s : r.analysis.configs) {
      for (const OcclusionStatistics& o : s.occlusions) {
        md << "| " << r.experiment.sweep.scenario << " | "
           << (axisText(s, "planner.algorithm") == "learned" ? "learned" : "SMA-NBO") << " | "
           << r.analysis.specs.front().targets[o.target].name << " | "
           << num(o.hidden.first * s.dt, "%.1f") << "–" << num(o.hidden.last * s.dt, "%.1f")
           << " s | " << axisText(s, "planner.occlusion_map") << " | " << decisionsOf(s) << " | "
           << o.trials << " | " << numberWithInterval(s.coverageOver(o.target, o.hidden)) << " | "
           << percentWithInterval(o.awareEstimate()) << " | "
           << (o.with_event ? percentWithInterval(o.awareGivenEventEstimate()) : "—") << " ("
           << o.with_event << ") |\n";
      }
    }
  }
  md << "\n";
  for (const ExperimentResult& r : results) {
    if (r.experiment.ownership) continue;
    md << "### " << r.experiment.scenario << "\n\n![coverage](" << r.figures
       << "/coverage.png)\n\n";
  }
}

void writeReaction(std::ostream& md, const Findings& findings) {
  if (findings.reaction.empty()) return;
  md << "### Reaction to the occlusion (Joint Effect, trajectory I)\n\n";
  md << "First time the mean coverage of I falls below 0.9 (the onset: a tenth of the trials "
        "have left I) and below 0.5 (half of them have); I is hidden from "
     << num(kJointEffectHiding, "%.1f")
     << " s. In brackets a 95 % percentile-bootstrap interval over the trials (2000 resamples, "
        "seeded; \"never\": more than 2.5 % of the resamples never cross). \"Paper inside?\" "
        "compares the paper's time with our onset's interval, Δ = paper − ours.\n\n";
  md << "With no map the paper's UAV keeps observing I: that row's verdict is whether at least "
     << num(kKeepsObserving, "%.1f")
     << " footprints stay on I while it is hidden, on average: holds when the interval lies "
        "above "
     << num(kKeepsObserving, "%.1f") << ", fails when below, consistent when it spans it.\n\n";
  md << "| decisions | map | onset (ours) | half (ours) | I while hidden | paper | paper inside? "
        "|\n";
  md << "|---|---|---:|---:|---:|---:|---|\n";
  for (const ReactionRow& row : findings.reaction) {
    const double paper = row.map == "a_priori" ? kPaperReactionAPriori : kPaperReactionDynamic;
    md << "| " << row.decisions << " | " << row.map << " | " << timeWithInterval(row.onset) << " | "
       << timeWithInterval(row.half) << " | " << numberWithInterval(row.while_hidden) << " | "
       << paperReaction(row.map) << " | "
       << (row.map != "none"
               ? timeVerdict(paper, row.onset)
               : verdictText(claimAbove(row.while_hidden.ci, {kKeepsObserving, kKeepsObserving})))
       << " |\n";
  }
  md << "\n";
}

void writeWastedCoverageFinding(std::ostream& md, const Findings& findings) {
  md << "2. **A-priori and dynamic maps cut wasted coverage of occluded trajectories** — "
     << verdictOf(findings.wasted) << ":\n";
  for (const WastedCoverageCase& c : findings.wasted) {
    md << "  - " << c.scenario << ", " << c.target << ", " << c.map << ", " << c.decisions << ": "
       << numberWithInterval(c.with_map) << " vs " << numberWithInterval(c.without_map)
       << " with no map — " << verdictText(c.verdict()) << "\n";
  }
  md << "\n";
}

void writeCatchUpFinding(std::ostream& md, const Findings& findings) {
  if (findings.catch_up.empty()) return;
  md << "3. **The dynamic map catches up with the a-priori map on the second occlusion (III)** — "
     << verdictOf(findings.catch_up)
     << "; the criterion is that the dynamic map closes at least 75 % of the gap between no map "
        "and the a-priori map: no map above a-priori, and dynamic below the threshold "
        "0.75 · a-priori + 0.25 · no map (its interval from the same ends of both intervals). "
        "Mean coverage of III while hidden:\n";
  for (const CatchUpFinding& c : findings.catch_up) {
    md << "  - " << c.decisions << ": " << numberWithInterval(c.dynamic) << " (dynamic) vs "
       << numberWithInterval(c.a_priori) << " (a-priori) and " << numberWithInterval(c.none)
       << " (no map); threshold " << thresholdText(c) << " — " << verdictText(c.verdict()) << "\n";
  }
  md << "\n";
}

void writeReactionOrderFinding(std::ostream& md, const Findings& findings) {
  if (findings.reaction.empty()) return;
  md << "4. **The dynamic map reacts after the a-priori map, which reacts before I hides** "
        "(Joint Effect; the paper: ≈ 1.6 s and ≈ 2.2 s, I hidden from 2.2 s):\n";
  for (const DecisionPeriod& period : decisionPeriods()) {
    const std::optional<Verdict> later = dynamicReactsLater(findings.reaction, period.label);
    const std::optional<Verdict> before = reactsBeforeHiding(findings.reaction, period.label);
    std::string onsets;
    for (const ReactionRow& row : findings.reaction) {
      if (row.decisions != period.label || row.map == "none") continue;
      onsets += std::string(onsets.empty() ? "" : ", ") + row.map + " onset " +
                timeWithInterval(row.onset) + ", half " + timeWithInterval(row.half);
    }
    if (onsets.empty()) continue;
    md << "  - " << period.label << ": the a-priori map reacts before I hides — "
       << (before ? verdictText(*before) : "cannot be checked")
       << "; the dynamic map later (half-way times) — "
       << (later ? verdictText(*later) : "cannot be checked") << " (" << onsets << ")\n";
  }
  md << "\n";
}

void writeFirstRankingFinding(std::ostream& md, const Findings& findings) {
  if (findings.first_ranking.empty()) return;
  md << "5. **Occlusion Sharing, I's first occlusion: the maps ranked a-priori, dynamic, none** "
        "(mean coverage of I while hidden):\n";
  for (const FirstOcclusionRanking& r : findings.first_ranking) {
    md << "  - " << r.decisions << ": " << verdictText(r.verdict()) << " — "
       << numberWithInterval(r.a_priori) << " (a-priori), " << numberWithInterval(r.dynamic)
       << " (dynamic), " << numberWithInterval(r.none) << " (no map)\n";
  }
  md << "\n";
}

}  // namespace canopy::analysis
