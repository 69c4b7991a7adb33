#include "analysis/report_learned.h"

#include <cstdio>
#include <sstream>

#include "analysis/report_numbers.h"

namespace canopy::analysis {
namespace {

// "4.8 µs" below a millisecond, else "3.90 ms"; `us` in microseconds.
std::string timeText(double us, bool unit = true) {
  char text[32];
  if (us < 1000.0)
    std::snprintf(text, sizeof text, unit ? "%.1f µs" : "%.1f", us);
  else
    std::snprintf(text, sizeof text, unit ? "%.2f ms" : "%.2f", us / 1000.0);
  return text;
}

// The planner a configuration flies: the TH/RA planner axis's label, else its algorithm's.
std::string plannerOf(const ConfigStatistics& s) {
  const std::string axis = axisText(s, "planner");
  for (const PlannerVariant& p : kPlanners) {
    if (axis == p.axis_value) return p.label;
  }
  const std::string algorithm = axisText(s, "planner.algorithm");
  for (const PlannerVariant& p : kPlanners) {
    if (algorithm == p.axis_value) return p.label;
  }
  return algorithm.empty() ? "—" : algorithm;
}

bool isLearned(const ConfigStatistics& s) {
  return axisText(s, "planner") == "learned" || axisText(s, "planner.algorithm") == "learned";
}

// Everything but the planner: the held-out variant (when there is one) and H.
std::string settingOf(const ConfigStatistics& s) {
  const std::string variant = axisText(s, "variant");
  const std::string horizon = axisText(s, "planner.horizon");
  return (variant.empty() ? "" : variant + ", ") + "H = " + (horizon.empty() ? "5" : horizon);
}

// The learned configuration of `r` in the same setting as `s`.
const ConfigStatistics* learnedBeside(const ExperimentResult& r, const ConfigStatistics& s) {
  for (const ConfigStatistics& other : r.analysis.configs) {
    if (isLearned(other) && settingOf(other) == settingOf(s)) return &other;
  }
  return nullptr;
}

void writeTimedRows(std::ostream& md, const ExperimentResult& r) {
  for (const ConfigStatistics& s : r.analysis.configs) {
    const DecisionTime* t = decisionTimeOf(r, s);
    if (!t || !t->timed()) continue;
    const ConfigStatistics* learned = learnedBeside(r, s);
    const DecisionTime* base = learned ? decisionTimeOf(r, *learned) : nullptr;
    md << "| " << r.experiment.scenario << " | " << settingOf(s) << " | " << plannerOf(s) << " | "
       << t->trials << " | " << t->calls << " | " << decisionTimeText(*t) << " | "
       << timeText(t->median_us) << " | " << timeText(t->p90_us) << " | "
       << timeText(t->max_us) << " | "
       << (base && base->timed() && base->mean_us.value > 0.0 && base->median_us > 0.0
               ? num(t->mean_us.value / base->mean_us.value, "%.0f") + "× / " +
                     num(t->median_us / base->median_us, "%.0f") + "×"
               : std::string("—"))
       << " |\n";
  }
}

const OcclusionStatistics* sameEpisode(const ConfigStatistics& s, const OcclusionStatistics& o) {
  for (const OcclusionStatistics& other : s.occlusions) {
    if (other.target == o.target && other.hidden.first == o.hidden.first) return &other;
  }
  return nullptr;
}

}  // namespace

std::string decisionTimeText(const DecisionTime& t) {
  if (!t.timed()) return "—";
  const double scale = t.mean_us.value < 1000.0 ? 1.0 : 1000.0;
  const char* unit = scale == 1.0 ? " µs" : " ms";
  const Estimate e{t.mean_us.value / scale,
                   {t.mean_us.ci.low / scale, t.mean_us.ci.high / scale},
                   t.mean_us.trials};
  std::string text = numberWithInterval(e, scale == 1.0 ? "%.1f" : "%.2f");
  const std::size_t bracket = text.find(" [");
  return text.substr(0, bracket) + unit + text.substr(bracket);
}

const DecisionTime* decisionTimeOf(const ExperimentResult& r, const ConfigStatistics& s) {
  for (std::size_t c = 0; c < r.analysis.configs.size() && c < r.decision_times.size(); ++c) {
    if (&r.analysis.configs[c] == &s) return &r.decision_times[c];
  }
  return nullptr;
}

std::string keptText(const Estimate& sma, const Estimate& learned) {
  switch (claimAbove(sma.ci, learned.ci)) {
    case Verdict::holds: return "**lost**";
    case Verdict::fails: return "higher than SMA-NBO";
    case Verdict::consistent: return "kept (the intervals overlap)";
    case Verdict::too_few_trials: break;
  }
  return "too few trials";
}

void writeDecisionTimes(std::ostream& md, const std::vector<ExperimentResult>& results,
                        const std::vector<ExperimentResult>& learned, const ReportContext& ctx) {
  if (ctx.timing_trials <= 0) return;
  md << "## Decision time per agent\n\n";
  md << "Wall time of one agent's planning decision at one epoch: SMA-NBO's particle-swarm "
        "search over its own plan, Dec-POMDP's search over the joint plan (every agent runs its "
        "own), the learned planner's observation and network (steady_clock around the call; "
        "DAgger's labelling is not part of a flight). "
     << "Measured after the sweeps, outside them: the first " << ctx.timing_trials
     << " trials of every configuration (the same seeds, so the same decisions as the sweep's "
        "trials) run again one at a time on one thread, every planning call timed. In brackets "
        "the 95 % Student-t interval of the mean over those trials' own means (a trial's calls "
        "share its states and its load); median, 90th percentile (nearest rank) and maximum over "
        "every call show the spread (one slow call, the machine busy elsewhere, moves a mean of few "
        "trials far more than the median). \"× learned\" divides the mean, then the median, by "
        "the learned planner's in the same setting. Wall times depend on the machine and its load (other processes are "
        "not stopped), the ratios much less.\n\n";
  md << "| experiment | setting | planner | trials | calls | mean per call [95 %] | median | "
        "90th pct | max | × learned (mean / median) |\n";
  md << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto* set : {&results, &learned}) {
    for (const ExperimentResult& r : *set) writeTimedRows(md, r);
  }
  md << "\n";
}

void writeLearnedBehaviours(std::ostream& md, const std::vector<ExperimentResult>& results) {
  std::ostringstream rows;
  for (const char* scenario : {"trajectory_handover", "resource_allocation"}) {
    const ExperimentResult* r = findExperiment(results, scenario);
    if (!r) continue;
    for (const char* horizon : {"5", "1"}) {
      const ConfigStatistics* sma = findConfig(*r, "planner", "sma", "planner.horizon", horizon);
      const ConfigStatistics* lrn = findConfig(*r, "planner", "learned", "planner.horizon", horizon);
      if (!sma || !lrn) continue;
      const Estimate a = sma->stateEstimate("M*", 4), b = lrn->stateEstimate("M*", 4);
      rows << "| Ownership_Change (M* at L) | " << scenario << " | H = " << horizon << " | "
           << percentWithInterval(a) << " (" << sma->trials << ") | " << percentWithInterval(b)
           << " (" << lrn->trials << ") | " << keptText(a, b) << " |\n";
    }
  }
  for (const char* scenario : {"joint_effect", "occlusion_sharing"}) {
    const ExperimentResult* r = findExperiment(results, scenario);
    const ExperimentResult* l = findExperiment(results, std::string(scenario) + "_learned");
    if (!r || !l) continue;
    for (const DecisionPeriod& period : decisionPeriods()) {
      for (const char* map : {"a_priori", "dynamic", "none"}) {
        const ConfigStatistics* sma = findOcclusionConfig(*r, map, period.seconds);
        const ConfigStatistics* lrn = findOcclusionConfig(*l, map, period.seconds);
        if (!sma || !lrn) continue;
        for (const OcclusionStatistics& o : sma->occlusions) {
          const OcclusionStatistics* lo = sameEpisode(*lrn, o);
          if (!lo) continue;
          const std::string setting = r->analysis.specs.front().targets[o.target].name + " " +
                                      num(o.hidden.first * sma->dt, "%.1f") + "–" +
                                      num(o.hidden.last * sma->dt, "%.1f") + " s, " + map +
                                      ", " + period.label;
          rows << "| Occlusion_Aware (P[OA]) | " << scenario << " | " << setting << " | "
               << percentWithInterval(o.awareEstimate()) << " (" << o.trials << ") | "
               << percentWithInterval(lo->awareEstimate()) << " (" << lo->trials << ") | "
               << keptText(o.awareEstimate(), lo->awareEstimate()) << " |\n";
          if (o.with_event == 0 || lo->with_event == 0) continue;
          rows << "| Occlusion_Share (P[OA \\| e]) | " << scenario << " | " << setting << " | "
               << percentWithInterval(o.awareGivenEventEstimate()) << " (" << o.with_event
               << ") | " << percentWithInterval(lo->awareGivenEventEstimate()) << " ("
               << lo->with_event << ") | "
               << keptText(o.awareGivenEventEstimate(), lo->awareGivenEventEstimate()) << " |\n";
        }
      }
    }
  }
  if (rows.str().empty()) return;
  md << "## Which cooperative behaviours the learned planner keeps\n\n";
  md << "The learned planner (not in the paper; docs/imitation.md) flies each scenario's shipped "
        "policy, trained on SMA-NBO's decisions in that scenario with its own seeds 1–20 "
        "(the sweeps' trial seeds are drawn from the sweep seed, so these trials are held out). "
        "Each behaviour's frequency with its 95 % Wilson interval and, in parentheses, the "
        "trials it is over (for Occlusion_Share the trials with the detection event e). "
        "**lost**: the learned planner's interval lies below SMA-NBO's; kept: the intervals "
        "overlap (these trials cannot tell them apart).\n\n";
  md << "| behaviour | scenario | setting | SMA-NBO | learned | learned |\n";
  md << "|---|---|---|---:|---:|---|\n";
  md << rows.str() << "\n";
}

void writeLearnedHeldOut(std::ostream& md, const std::vector<ExperimentResult>& learned) {
  for (const ExperimentResult& r : learned) {
    if (r.analysis.configs.empty()) continue;
    md << "## The learned planner on held-out variants\n\n";
    md << "scenarios/sweeps/learned_heldout.json (written by make_learned_heldout.py): "
          "Trajectory Handover as trained (new seeds), turned by 90°, every length scaled by 0.8 "
          "and 1.2, and two and three copies of it 60 m apart (4 and 6 UAVs, 8 and 12 people; M* "
          "is every copy's zone defence at once). The shipped policy saw only the calibrated "
          "layout with 2 UAVs (seeds 1–20). "
       << r.analysis.configs.front().trials
       << " trials per configuration from sweep seed " << r.experiment.sweep.seed
       << "; 95 % Wilson intervals; \"ends in\" is the most frequent state at L.\n\n";
    md << "| variant | UAVs | planner | trials | M* at L | reached M* by L | ends in | decision "
          "time per agent |\n";
    md << "|---|---:|---|---:|---:|---:|---|---:|\n";
    for (const ConfigStatistics& s : r.analysis.configs) {
      std::size_t most = 0;
      for (std::size_t i = 0; i < s.states.size(); ++i) {
        if (s.state_counts[4][i] > s.state_counts[4][most]) most = i;
      }
      const DecisionTime* t = decisionTimeOf(r, s);
      md << "| " << axisText(s, "variant") << " | " << s.uavs << " | " << plannerOf(s) << " | "
         << s.trials << " | " << percentWithInterval(s.stateEstimate("M*", 4)) << " | "
         << percentWithInterval(proportion(s.reachedBy("M*", s.columns[4]), s.trials)) << " | "
         << (s.states.empty() ? "—" : s.states[most] + " " + percentWithInterval(
                                          proportion(s.state_counts[4][most], s.trials)))
         << " | " << (t ? decisionTimeText(*t) : "—") << " |\n";
    }
    md << "\n";
  }
}

}  // namespace canopy::analysis
