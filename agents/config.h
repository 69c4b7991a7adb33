#pragma once
// Settings of the per-UAV stack, as read from a scenario's `tracking`, `fusion` and `planner`
// sections. Every default is the one algorithms.md states.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/enum_names.h"
#include "core/types.h"

namespace canopy::agents {

/// How a tentative track is confirmed (and a track deleted): by its probability of existence
/// (JIPDA, Mušicki & Evans 2004), or by the M-of-N rule — confirm_hits hits within the first
/// confirm_window scans — with deletion by delete_trace and delete_misses only.
enum class TrackConfirmation { existence, m_of_n };
inline constexpr EnumNames<TrackConfirmation, 2> kTrackConfirmationNames{{
    {TrackConfirmation::existence, "existence"},
    {TrackConfirmation::m_of_n, "m_of_n"},
}};

/// Local tracking (algorithms.md §4).
struct TrackingConfig {
  double sigma_a = 1.0;            // m/s², NCV process-noise intensity σ_a
  double gate_probability = 0.98;  // P_G; the χ²₂ gate is −2 ln(1 − P_G) = 7.824
  // A measurement starts a track only outside every track's wider birth gate (χ²₂ at this
  // probability, 18.4 at 0.9999): a target's own measurements that miss its association gate
  // would otherwise start confirmed duplicates (agents/tracking/jpdaf.h has the measurement).
  double birth_gate_probability = 0.9999;
  double p_detect = 0.9;                 // P_D assumed by the JPDAF
  double clutter_density = 1e-4;         // 1/m², spatial density of false detections λ
  int max_hypotheses = 10000;            // exact joint-event enumeration up to this many events
  double birth_velocity_sigma = 1.0;     // m/s, σ of the velocity of a newborn track
  int confirm_hits = 2;                  // confirmed after this many hits ...
  int confirm_window = 3;                // ... within the first this many scans
  double delete_trace = 400.0;           // m², delete when tr(P_pos) exceeds this
  int delete_misses = 0;                 // > 0: also delete after this many expected-visible misses
  bool preseed = true;                   // start every agent with a confirmed track per target
  Vec4 preseed_variance = Vec4::Ones();  // m², m², m²/s², m²/s²: diagonal of P₀ for pre-seeds
  double tree_min_radius = 0.1;          // m, a tree estimate's radius never goes below this
  // JIPDA: every track carries a probability of existence r (agents/tracking/existence.h).
  TrackConfirmation confirmation = TrackConfirmation::existence;
  double survival_probability = 0.95;  // a target's p_S over 1 s; per scan p_S^dt (trees: 1)
  double birth_existence = 0.1;        // r of a track born from a measurement
  double confirm_existence = 0.9;      // confirmed once r reaches this (existence confirmation)
  double delete_existence = 0.05;      // deleted once r falls below this (existence confirmation)
  // Duplicates (target tracks; agents/tracking/duplicates.h): two confirmed tracks merge after
  // merge_scans consecutive scans in which both are certain (tr(P_pos) ≤ 2·merge_distance²),
  // their means lie within merge_distance, the track-to-track distance
  // d² = Δxᵀ (P_a + P_b)⁻¹ Δx (4-D state) is at most merge_gate (χ²₄; 7.78 is its 90 % quantile),
  // and the own scan's strongest measurement of both is the same one. merge_scans = 0: never.
  double merge_gate = 7.78;
  int merge_scans = 3;
  double merge_distance = 2.0;  // m
  // Known people (pre-seeded tracks; agents/tracking/known_people.h) are never deleted: unseen, a
  // track becomes lost (tr(P_pos) > delete_trace) and its velocity's σ stays within walk_speed,
  // its position's within the area's (a uniform spread over it), its mean inside the area.
  double walk_speed = 2.0;  // m/s
  // A target track that a scan gave no measurement loses the mass its camera would have seen
  // (agents/tracking/missed_detection.h); false: it keeps its prediction (plain JPDA).
  bool negative_information = false;
  // Not a scenario field: the scenario's area of interest (the loader's aoi), the bound above.
  Aabb area{Vec2(-1e6, -1e6), Vec2(1e6, 1e6)};
};

enum class FusionMethod { ci, hcmci, observer_average };
inline constexpr EnumNames<FusionMethod, 3> kFusionMethodNames{{
    {FusionMethod::ci, "ci"},
    {FusionMethod::hcmci, "hcmci"},
    {FusionMethod::observer_average, "observer_average"},
}};

/// Distributed fusion (algorithms.md §5).
struct FusionConfig {
  FusionMethod method = FusionMethod::ci;
  int rounds = 5;                                               // L consensus rounds per step
  double comm_range = std::numeric_limits<double>::infinity();  // m, neighbours within this range
  double comm_drop = 0.0;  // probability that a message is lost
  // Simulation steps a message is in flight: intention messages (SMA-NBO's plans, the centralised
  // leader's orders) and consensus messages alike (docs/design-notes.md).
  int comm_latency = 0;
  double association_gate = 9.21;  // χ²₂ (99 %) gate on the position Mahalanobis distance
  // m: after each fusion step an agent forgets the target tracks and trees farther than this from
  // it (a swarm's beliefs stay local; docs/design-notes.md "Cost scope"); ∞: keeps everything.
  double interest_range = std::numeric_limits<double>::infinity();
};

namespace planning {
struct PolicyNetwork;  // agents/planning/policy_network.h
}

// learned: each agent flies a network trained to imitate SMA-NBO (issue 54, docs/imitation.md).
enum class PlannerAlgorithm { none, sma, dec_pomdp, centralized, learned };
inline constexpr EnumNames<PlannerAlgorithm, 5> kPlannerAlgorithmNames{{
    {PlannerAlgorithm::none, "none"},
    {PlannerAlgorithm::sma, "sma"},
    {PlannerAlgorithm::dec_pomdp, "dec_pomdp"},
    {PlannerAlgorithm::centralized, "centralized"},
    {PlannerAlgorithm::learned, "learned"},
}};
enum class OcclusionMapMode { a_priori, dynamic, none };
inline constexpr EnumNames<OcclusionMapMode, 3> kOcclusionMapModeNames{{
    {OcclusionMapMode::a_priori, "a_priori"},
    {OcclusionMapMode::dynamic, "dynamic"},
    {OcclusionMapMode::none, "none"},
}};
/// What the NBO cost of one agent's planning call sums over (docs/design-notes.md, "Cost scope").
/// team: every track of its belief and every UAV of the team (the paper's cost); reach: only the
/// tracks that a free UAV's footprint can reach within the horizon, and only the teammates whose
/// footprints can reach those tracks.
enum class CostScope { team, reach };
inline constexpr EnumNames<CostScope, 2> kCostScopeNames{{
    {CostScope::team, "team"},
    {CostScope::reach, "reach"},
}};

/// How Dec-POMDP and centralised planning search the joint plan (docs/design-notes.md, "Dec-POMDP's
/// joint search"): block coordinate descent (the default) — one swarm per UAV's 2·H variables in
/// `order`, the others held at their current plans, for `joint_rounds` rounds, every evaluation
/// the joint cost; or one swarm over all 2·N·H variables, either the paper's global-best swarm or
/// a local-best (ring) swarm with warm starts and restarts.
enum class JointSearch { global_best, local_best, block_coordinate };
inline constexpr EnumNames<JointSearch, 3> kJointSearchNames{{
    {JointSearch::global_best, "global_best"},
    {JointSearch::local_best, "local_best"},
    {JointSearch::block_coordinate, "block_coordinate"},
}};

/// Which blocks a Dec-POMDP agent's block coordinate descent optimises (docs/design-notes.md,
/// "Dec-POMDP at swarm size"): the UAVs whose plans can interact with its own within the horizon
/// (agents/planning/interaction.h; the others keep their previous plans), or every UAV.
enum class JointBlocks { interacting, all };
inline constexpr EnumNames<JointBlocks, 2> kJointBlocksNames{{
    {JointBlocks::interacting, "interacting"},
    {JointBlocks::all, "all"},
}};

/// The particle swarm (algorithms.md §6).
struct PsoConfig {
  int particles_per_step = 20;  // particles = this · H
  double inertia = 0.9;         // w
  double c1 = 0.5;              // cognitive weight
  double c2 = 0.3;              // social weight
  double ftol = 5e-4;           // relative change of the best cost counted as a stall
  int stall_iterations = 50;    // stop after this many stalled iterations in a row
  int max_iterations = 1000;    // hard cap
  bool warm_start = true;       // one particle starts at the previous plan shifted by one step
};

/// Nominal belief optimisation (algorithms.md §6).
struct PlannerConfig {
  PlannerAlgorithm algorithm = PlannerAlgorithm::none;  // none: UAVs follow scripted paths
  int horizon = 5;                                      // H planning steps
  double plan_period = 1.0;                             // s, Δ: the length of each planned action
  // s, between planning epochs; the loader defaults it to plan_period (the paper's setting). A
  // shorter period re-plans inside an action: the actions stay Δ long, intentions and warm starts
  // are shifted by the time elapsed (docs/design-notes.md).
  double replan_period = 1.0;
  OcclusionMapMode occlusion_map = OcclusionMapMode::dynamic;
  double discount = 1.0;    // γ
  bool full_trace = false;  // cost on tr(P) instead of tr(P_pos)
  // cost_trace "custody": the stage cost is exp(−r²/tr(P_pos)), the probability that a track is
  // more than r = custody_radius off (agents/planning/nominal_cost.h).
  bool custody = false;
  double custody_radius = 5.0;  // m
  bool terminal_penalty = true;
  double terminal_penalty_weight = 0.5;  // w
  CostScope cost_scope = CostScope::team;
  PsoConfig pso;
  std::vector<int> order;  // SMA planning order (UAV indices); empty: 0..N−1
  int cost_substeps = 1;   // samples of the nominal trajectory per action (1: plan instants)
  JointSearch joint_search = JointSearch::block_coordinate;  // Dec-POMDP and centralised only
  int joint_rounds = 2;                                 // block coordinate rounds over all UAVs
  JointBlocks joint_blocks = JointBlocks::interacting;  // Dec-POMDP's blocks
  // m: a ground robot's nominal pose keeps this much more than its radius from the trunks and
  // walls of its map, and the sum of the radii plus this from another robot's intended pose
  // (docs/design-notes.md, "Plans that keep clear").
  double clearance = 0.2;
  // learned: the network (read from planner.policy by the loader; null for other algorithms).
  std::shared_ptr<const planning::PolicyNetwork> policy;
};

/// Simulation steps between plan instants: replan_period / dt, rounded, at least 1.
inline int stepsPerReplan(const PlannerConfig& config, double dt) {
  return std::max(1, static_cast<int>(std::lround(config.replan_period / dt)));
}

}  // namespace canopy::agents
