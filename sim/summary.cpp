#include "sim/summary.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <nlohmann/json.hpp>

namespace canopy::sim {

SummaryBuilder::SummaryBuilder(const spec::ScenarioSpec& spec)
    : names_{spec.name, spec.seed, spec.dt, spec.trees.size(), {}, {}, {}},
      targets_(spec.targets.size()),
      uavs_(spec.uavs.size()),
      ospa_(spec.uavs.size()),
      gospa_(spec.uavs.size()),
      interest_range_(spec.fusion.interest_range),
      roi_ospa_(spec.uavs.size()),
      steps_held_(spec.targets.size(), 0),
      false_tracks_(spec.uavs.size(), 0),
      plan_seconds_(spec.uavs.size()) {
  for (const spec::TargetSpec& target : spec.targets) {
    names_.targets.push_back(target.name);
    names_.target_labels.push_back(spec.labels[target.label]);
  }
  for (const spec::UavSpec& uav : spec.uavs) names_.uavs.push_back(uav.name);
}

namespace {
double mean(const std::vector<double>& x) {
  double sum = 0.0;
  for (const double v : x) sum += v;
  return x.empty() ? 0.0 : sum / static_cast<double>(x.size());
}
double median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}
}  // namespace

void SummaryBuilder::onStep(const StepRecord& record) {
  if (!last_uav_position_.empty()) {
    for (std::size_t i = 0; i < uavs_.size(); ++i) {
      uavs_[i].distance += (record.uavs[i].position - last_uav_position_[i]).norm();
    }
  }
  last_uav_position_.clear();
  for (const UavRecord& uav : record.uavs) last_uav_position_.push_back(uav.position);
  for (std::size_t i = 0; i < uavs_.size(); ++i) {
    uavs_[i].contacts += record.uavs[i].contacts_begun;
    UavTally& tally = uavs_[i];
    const bool touching = !record.uavs[i].contacts.empty();
    tally.steps_in_contact += touching;
    tally.contact_run = touching ? tally.contact_run + 1 : 0;
    if (tally.contact_run > tally.longest_contact) {
      tally.longest_contact = tally.contact_run;
      tally.longest_contact_from = record.step - tally.contact_run + 1;
    }
  }

  visible_by_.assign(targets_.size(), 0);
  in_footprint_of_.assign(targets_.size(), 0);
  for (const UavRecord& uav : record.uavs) {
    const sensing::Scan& scan = uav.scan;
    UavTally& tally = uavs_[scan.uav];
    tally.visible += static_cast<long>(scan.visible.size());
    tally.observations += static_cast<long>(scan.observations.size());
    for (const int t : scan.visible) ++visible_by_[t];
    for (const int t : scan.in_footprint) ++in_footprint_of_[t];
  }
  for (std::size_t t = 0; t < targets_.size(); ++t) {
    targets_[t].steps_visible += visible_by_[t] > 0;
    targets_[t].steps_in_footprint += in_footprint_of_[t] > 0;
    targets_[t].coverage += in_footprint_of_[t];
  }

  truth_positions_.clear();
  for (const TargetRecord& target : record.targets) truth_positions_.push_back(target.position);
  truth_grid_.build(truth_positions_, assignment_.cutoff());  // one grid for every agent's solve
  solved_estimates_.clear();
  bool solved_any = false;
  for (std::size_t i = 0; i < record.beliefs.size(); ++i) {
    estimates_.clear();
    for (const agents::TrackEstimate& track : record.beliefs[i].tracks) {
      estimates_.push_back(track.belief.x.head<2>());
    }
    // Agents that agree hold the same positions, bit for bit, in the same order; the solve of the
    // same input gives the same figures, so the last solve's are reused.
    const bool as_last_solved =
        solved_any && estimates_.size() == solved_estimates_.size() &&
        (estimates_.empty() || std::memcmp(estimates_.data(), solved_estimates_.data(),
                                           estimates_.size() * sizeof(Vec2)) == 0);
    if (!as_last_solved) {
      assignment_.solve(truth_grid_, estimates_);  // one assignment for every metric
      solved_ = {assignment_.ospa(), assignment_.gospa(), assignment_.parts().false_estimates};
      solved_estimates_ = estimates_;
      solved_any = true;
    }
    ospa_[i].push_back(solved_.ospa);
    gospa_[i].push_back(solved_.gospa);
    false_tracks_[i] += solved_.false_estimates;
    if (!std::isfinite(interest_range_)) continue;
    // The agent's region of interest: people and tracks within interest_range of its UAV.
    const Vec2& centre = record.uavs[i].position;
    auto inside = [&](const Vec2& p) { return (p - centre).norm() <= interest_range_; };
    roi_truth_.clear();
    roi_estimates_.clear();
    std::copy_if(truth_positions_.begin(), truth_positions_.end(), std::back_inserter(roi_truth_),
                 inside);
    std::copy_if(estimates_.begin(), estimates_.end(), std::back_inserter(roi_estimates_), inside);
    assignment_.solve(roi_truth_, roi_estimates_);
    roi_ospa_[i].push_back(assignment_.ospa());
  }
  team_.push_back(team_metrics_.compute(truth_positions_, record.beliefs, &held_));
  for (std::size_t t = 0; t < held_.size(); ++t) steps_held_[t] += held_[t];
  if (record.plan) {
    for (const auto& report : record.plan->reports)
      plan_seconds_[report.agent].push_back(report.seconds);
  }
  counts_at_end_ = record.counts;
  fusion_at_end_ = record.fusion;
  intentions_at_end_ = record.intentions;
  ++steps_;
}

std::string SummaryBuilder::json(double wall_seconds) const {
  using Json = nlohmann::json;
  const double steps = std::max(1, steps_);
  Json summary;
  summary["scenario"] = names_.scenario;
  summary["seed"] = names_.seed;
  summary["steps"] = steps_;
  summary["dt"] = names_.dt;
  summary["trees"] = names_.trees;
  Json targets = Json::array();
  double visible_sum = 0.0;
  for (std::size_t t = 0; t < targets_.size(); ++t) {
    const TargetTally& tally = targets_[t];
    visible_sum += tally.steps_visible / steps;
    targets.push_back({{"name", names_.targets[t]},
                       {"label", names_.target_labels[t]},
                       {"visible_fraction", tally.steps_visible / steps},
                       {"in_footprint_fraction", tally.steps_in_footprint / steps},
                       {"mean_coverage", static_cast<double>(tally.coverage) / steps},
                       {"held_fraction", steps_held_[t] / steps}});
  }
  summary["targets"] = targets;
  Json uavs = Json::array();
  double ospa_sum = 0.0, gospa_sum = 0.0;
  long false_track_steps = 0, contacts = 0;
  Json plan_timing = Json::array();
  for (std::size_t i = 0; i < uavs_.size(); ++i) {
    Json uav = {
        {"name", names_.uavs[i]},
        {"distance_m", uavs_[i].distance},
        {"mean_visible_targets", static_cast<double>(uavs_[i].visible) / steps},
        {"observations", uavs_[i].observations},
        {"ospa_mean_m", mean(ospa_[i])},
        {"ospa_m", ospa_[i]},
        {"gospa_mean_m", mean(gospa_[i])},
        {"gospa_m", gospa_[i]},
        {"roi_ospa_mean_m", std::isfinite(interest_range_) ? mean(roi_ospa_[i]) : mean(ospa_[i])},
        {"false_track_steps", false_tracks_[i]},
        {"false_tracks_mean", static_cast<double>(false_tracks_[i]) / steps},
        {"contacts", uavs_[i].contacts},
        {"steps_in_contact", uavs_[i].steps_in_contact},
        {"longest_contact_steps", uavs_[i].longest_contact},
        {"longest_contact_from_step", uavs_[i].longest_contact_from}};
    if (i < counts_at_end_.size()) {
      const AgentCounts& end = counts_at_end_[i];
      uav["tracks_at_end"] = end.tracks;
      uav["trees_in_map_at_end"] = end.trees_in_map;
      uav["tracking_diagnostics"] = {
          {"births", end.tracking.births},
          {"deletions", end.tracking.deletions},
          {"merges", end.tracking.merges},
          {"approximated_clusters", end.tracking.approximated_clusters},
          {"non_positive_covariances", end.tracking.non_positive_covariances}};
    }
    uavs.push_back(std::move(uav));
    ospa_sum += mean(ospa_[i]);
    false_track_steps += false_tracks_[i];
    contacts += uavs_[i].contacts;
    gospa_sum += mean(gospa_[i]);
    if (!plan_seconds_[i].empty()) {
      plan_timing.push_back(
          {{"name", names_.uavs[i]},
           {"epochs", plan_seconds_[i].size()},
           {"mean_s", mean(plan_seconds_[i])},
           {"median_s", median(plan_seconds_[i])},
           {"max_s", *std::max_element(plan_seconds_[i].begin(), plan_seconds_[i].end())}});
    }
  }
  summary["uavs"] = uavs;
  summary["team"] = {
      {"mean_visible_fraction",
       targets_.empty() ? 0.0 : visible_sum / static_cast<double>(targets_.size())},
      {"ospa_mean_m", uavs_.empty() ? 0.0 : ospa_sum / static_cast<double>(uavs_.size())},
      {"ospa_cutoff_m", 50.0},
      {"ospa_order", 2},
      {"gospa_mean_m", uavs_.empty() ? 0.0 : gospa_sum / static_cast<double>(uavs_.size())},
      {"gospa_alpha", 2},
      // False confirmed tracks: GOSPA's false part (a confirmed track with no target closer than
      // the cut-off in the assignment), summed over agents and steps.
      {"false_track_steps", false_track_steps},
      // Contacts begun, summed over agents (a contact between two agents counts for both).
      {"contacts", contacts}};
  // The team's figures (sim/team_metrics.h): per step, and their means over the run.
  std::vector<double> team_ospa, team_gospa, held_fraction;
  std::vector<int> team_estimates;
  const double people = static_cast<double>(std::max<std::size_t>(1, targets_.size()));
  for (const TeamFigures& f : team_) {
    team_ospa.push_back(f.ospa);
    team_gospa.push_back(f.gospa);
    held_fraction.push_back(targets_.empty() ? 1.0 : f.held / people);
    team_estimates.push_back(f.estimates);
  }
  summary["team"]["team_ospa_mean_m"] = mean(team_ospa);
  summary["team"]["team_gospa_mean_m"] = mean(team_gospa);
  summary["team"]["held_fraction"] = mean(held_fraction);
  summary["team"]["held_at_end"] = team_.empty() ? 0 : team_.back().held;
  summary["team"]["held_distance_m"] = kHeldDistance;
  summary["team"]["held_gate_chi2"] = kHeldGate;
  summary["team"]["interest_range_m"] =
      std::isfinite(interest_range_) ? Json(interest_range_) : Json(nullptr);
  summary["team_by_step"] = {{"ospa_m", team_ospa},
                             {"gospa_m", team_gospa},
                             {"held_fraction", held_fraction},
                             {"estimates", team_estimates}};
  if (steps_ > 0) {
    const agents::fusion::FusionDiagnostics& d = fusion_at_end_;
    summary["fusion_diagnostics"] = {{"messages", d.messages},
                                     {"lost_messages", d.lost_messages},
                                     {"adoptions", d.adoptions},
                                     {"rekeys", d.rekeys},
                                     {"numerical_failures", d.numerical_failures}};
    // Per kind, on links within comm_range: sent, of which lost, and of those that arrived, late
    // (read at a later step than sent: fusion.comm_latency > 0).
    const agents::planning::MessageCounts& p = intentions_at_end_;
    summary["messages"] = {
        {"consensus", {{"sent", d.messages}, {"lost", d.lost_messages}, {"late", d.late_messages}}},
        {"intentions", {{"sent", p.sent}, {"lost", p.lost}, {"late", p.late}}}};
  }
  summary["timing"] = {{"wall_seconds", wall_seconds}, {"planning", plan_timing}};
  return summary.dump(2);
}

}  // namespace canopy::sim
