#pragma once
// The NBO cost of a joint plan (algorithms.md §6; paper eqs. 5–6), evaluated on nominal target
// trajectories. Built once per planning call (prepare), then evaluated many times by the swarm
// without allocating.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "agents/config.h"
#include "agents/gaussian.h"
#include "agents/occlusion_map.h"
#include "agents/planning/covariance_lanes.h"
#include "agents/planning/nearby_uavs.h"
#include "agents/planning/plan.h"
#include "agents/planning/sensing_lanes.h"
#include "agents/planning/symmetric_covariance.h"
#include "agents/planning/uav_state.h"
#include "core/cpu.h"
#include "core/task_pool.h"
#include "core/types.h"
#include "sensing/camera.h"
#include "sensing/footprint.h"

namespace canopy::agents::planning {

/// The cost's settings, from the scenario's `planner` section and the tracker's σ_a.
struct CostSettings {
  int horizon = 5;                       // H planning steps
  double period = 1.0;                   // s, Δ between planning steps
  double discount = 1.0;                 // γ (dimensionless)
  bool full_trace = false;               // tr(P) instead of tr(P_pos) in the stage cost
  double custody_radius = 0.0;           // m, r > 0: the stage cost is exp(−r²/tr(P_pos))
  bool terminal_penalty = true;          // Miller et al. 2009 penalty at m = H
  double terminal_penalty_weight = 0.5;  // w, 1/m
  int substeps = 1;        // S samples per action (1: the plan instants only, the paper's setting)
  double sigma_a = 1.0;    // m/s², NCV process-noise intensity σ_a
  double clearance = 0.2;  // m, c: ground robots keep radius + c from mapped trunks and walls
  bool keep_clear = true;  // charge the clearance term (off only to measure what it costs)
  CostScope scope = CostScope::team;  // reach: only the tracks and teammates within reach

  static CostSettings from(const PlannerConfig& config, double sigma_a);
};

/// One agent's planning problem at an epoch: its belief, the team's UAVs, its map.
struct PlanningProblem {
  std::span<const TargetGaussian> targets;  // the agent's fused OOI tracks ξ_j (m, m/s), P_j
  std::span<const UavState> uavs;           // every UAV of the team, by index i
  const OcclusionMap* map = nullptr;  // the planner's occlusion map; nullptr: nothing occludes
  CostSettings settings;
};

/// J(a) = Σ_{m=1..H} γ^{m−1} Σ_j tr(P_{j,m}) + terminal penalty, as a function of the actions of
/// the "free" UAVs; the other UAVs follow fixed plans given to prepare().
///
/// With cost_trace "custody" (custody_radius r > 0) each tr(P_{j,m}) becomes exp(−r²/tr(P_{j,m}[pos])),
/// the probability that track j is more than r off its person (a Rayleigh tail: the position error
/// taken isotropic), so J counts the people expected not held, and the terminal penalty weighs a
/// track by that probability at m = H instead of its trace. A track already lost costs about 1
/// whatever the plan; one at risk of being lost costs the most to neglect (docs/design-notes.md).
///
/// The covariance recursion is the information update
///   P_{j,m} = (P⁻_{j,m}⁻¹ + Σ_{i∈V_{j,m}} Hᵀ R_i⁻¹ H)⁻¹,  P⁻_{j,m} = F P_{j,m−1} Fᵀ + Q(Δ),
/// evaluated in its exact Kalman form, one measurement at a time: for each i ∈ V_{j,m},
///   P ← P − C S⁻¹ Cᵀ,  C = P Hᵀ (4x2),  S = H P Hᵀ + R_i (2x2, solved by its LDLᵀ factors).
/// The two agree by the matrix inversion lemma, and sequential processing equals the summed
/// information because the nominal measurements are independent given the state. The fixed UAVs'
/// measurements at (j, m) are fused beforehand into one, R_fix = (Σ R_i⁻¹)⁻¹.
///
/// With S = `substeps` > 1 each action of Δ is sampled S times, every τ = Δ/S: the covariance is
/// predicted with F(τ), Q(τ) and updated at every sample at which a footprint holds the nominal
/// position and the map does not hide it, with S·R_i (so that a target in view throughout an
/// action gains about the information of the single measurement of S = 1); the stage cost is
/// still tr(P) at the plan instants t_m. Occlusions and footprint exits shorter than Δ then reach
/// the cost (docs/design-notes.md). S = 1 is the recursion above exactly.
///
/// Precomputed per call: nominal trajectories z_{j,m} = H F(Δ)^m ξ_j, occlusion flags, the fixed
/// UAVs' paths, footprints and R_fix, which free UAVs can reach each z_{j,m} at all, and each
/// track's recursion up to the first step a free UAV could see it. evaluate() then runs four
/// candidate plans side by side, one per lane (covariance_lanes.h, sensing_lanes.h), each with the
/// bits it has alone. A commanded speed above v_max is clamped, as the world does; a ground robot
/// follows each action as the world's unicycle (world/unicycle.h: turn toward it, then drive), its
/// sector turning with it.
///
/// Plans that keep clear (docs/design-notes.md): a free ground robot f of radius r_f is charged,
/// for each sample t, the segment σ_t from its pose at the sample before to its pose at t (the
/// unicycle drives straight between samples), each solid part s of the map (a wall's polygon, a
/// trunk's disc) and each other robot g, which moves straight from q_{g,t−1} to its intended
/// q_{g,t} over the same interval, so that their closest approach on it is
/// δ_{fg,t} = min_{s∈[0,1]} |(1 − s)·(p_{f,t−1} − q_{g,t−1}) + s·(p_{f,t} − q_{g,t})|:
///   K₀ + K₁·(r_f + c − d(σ_t, s))          when d(σ_t, s) < r_f + c,
///   K₀ + K₁·(r_f + r_g + c − δ_{fg,t})     when δ_{fg,t} < r_f + r_g + c,
/// with K₀ = 10⁶ m² and K₁ = 10⁶ m²/m: more than any plan's information cost, so a plan that
/// comes that close to a known solid is never chosen over one that does not, and deeper is worse.
/// A UAV with a body (radius r_f > 0) is charged the second term for each other UAV with a body
/// (they fly above every solid and every robot); UAVs of radius 0 are not charged.
///
/// Height (issue 53): an agent with a camera (UavState::camera) flies at an altitude h_{i,t}:
/// its own z, or, where its altitude is free (altitudeFree), z after the candidate's climb
/// rates c_{i,m} (clamped to ±climb_rate as the world does), h_t = clamp(h_{t−1} + c_m·τ, z_min,
/// z_max). Its footprint at h is the one at z scaled by h/z (a pinhole camera's ground footprint
/// is proportional to the altitude): z_{j,t} is held when z_{j,t} − p lies in φ(z) after scaling
/// by z/h. Its R is the sensor's, (ℓ(h)/ℓ(h_ref))·R(z_{j,t}, p) with ℓ(h) = √(|z − p|² + h²)
/// (sensing/camera.h). An agent whose occlusion model is `volumes` sees z_{j,t} when the 3-D
/// segment from its camera (h, or 0.5 m on a ground robot) to the head 1.7 m above z_{j,t} passes
/// through no crown volume of the map (OcclusionMap::blocksSight), as its sensor does; a head
/// inside a crown's volume is hidden from all, and under a crown whose base is above the head
/// only from the agents of the other models (they hide all that lies under a crown).
class NominalCost {
 public:
  /// free_agents: indices of the UAVs whose actions evaluate() receives (distinct). assumed: one
  /// plan per UAV; the plans of the others are read from it (a missing step repeats the last
  /// action, an empty plan hovers), the entries of free UAVs are ignored.
  /// With a pool, the tracks' part of the preparation runs on it (from kPoolTracksFrom tracks);
  /// the result is the same bits.
  void prepare(const PlanningProblem& problem, std::span<const int> free_agents,
               std::span<const Plan> assumed, TaskPool* pool = nullptr);
  /// Tracks from which prepare() shares its tracks out: 256 tracks take about 0.4 ms on one
  /// core at 64 UAVs, against a few µs for a hand-off.
  static constexpr int kPoolTracksFrom = 32;
  static constexpr int kBlocksPerThread = 4;
  /// Whether the cost reads assumed[uav] of a UAV that is not free, i.e. whether its plan can
  /// change J: always in team scope; in reach scope when it starts within reach(f) + reach(uav)
  /// of some free UAV f, or when it is a body that may come within the separation of a free
  /// body of its class (prepare() skips the others). The planner's threads plan
  /// agents whose costs do not read each other's new plans side by side (team_planner.h).
  static bool readsPlanOf(const PlanningProblem& problem, std::span<const int> free_agents,
                          int uav);

  /// actions: a_{f,m} for each free UAV f (in prepare's order) and m = 1..H, agent-major
  /// (size = free count · H), m/s. Returns J (m², or mixed units with full_trace).
  double evaluate(std::span<const Vec2> actions);
  /// How many tracks the terminal penalty at scale has charged one at a time since prepare(),
  /// over every candidate: what its work grows with (the exact skip charges only those a
  /// candidate can change; tests read it). The paper's plain loop (a few UAVs) does not count.
  std::size_t penaltyCharges() const { return penalty_charges_; }

  /// J of many candidate plans at once: actions holds costs.size() of them, one after the other
  /// (each as evaluate() takes it). The swarm's way in: four candidates run side by side, one per
  /// lane (core/lanes.h), and each gets the bits evaluate() gives it alone.
  void evaluate(std::span<const Vec2> actions, std::span<double> costs) {
    evaluateWith(instructionSet(), actions, {}, costs);
  }
  /// The same with climb rates: climbs holds climbCount() per candidate (m/s, c_{f,m} of each
  /// free UAV whose altitude is free, in prepare's order, m = 1..H), or is empty (every altitude
  /// held).
  void evaluate(std::span<const Vec2> actions, std::span<const double> climbs,
                std::span<double> costs) {
    evaluateWith(instructionSet(), actions, climbs, costs);
  }
  /// evaluate() compiled for the given instruction set (avx2 only where instructionSet() is avx2).
  void evaluateWith(InstructionSet set, std::span<const Vec2> actions, std::span<double> costs) {
    evaluateWith(set, actions, {}, costs);
  }
  void evaluateWith(InstructionSet set, std::span<const Vec2> actions,
                    std::span<const double> climbs, std::span<double> costs);
  /// Climb rates per candidate: H for each free UAV whose altitude is free.
  int climbCount() const { return static_cast<int>(climbers_.size()) * horizon_; }

  int horizon() const { return horizon_; }
  int freeCount() const { return static_cast<int>(free_.size()); }

 private:
  static constexpr int kLanes = 4;  // candidates evaluated side by side

  struct Mover {                      // a UAV's kinematics and camera, as the cost moves it
    Vec2 position;                    // m, p_{i,0}
    double cos_yaw, sin_yaw;          // ψ now
    bool yaw_follows;                 // ψ follows the direction of a_{i,m} (kept while hovering)
    double v_max;                     // m/s
    sensing::FootprintDef footprint;  // φ relative to the UAV (m)
    sensing::Footprint at_origin;     // φ placed at the origin with ψ = 0 (its constant part)
    sensing::SensorQuality quality;   // α·S, r0 (m): R of one of an action's S samples
    bool line_of_sight;               // a map tree on the segment p → z hides z from it
    bool ground;                      // a ground robot: moves as world/unicycle.h
    double yaw;                       // rad, ψ now (the unicycle's heading)
    double turn_rate;                 // rad/s, ω_max of a ground robot
    double radius;                    // m, its body
    // Height (issue 53).
    bool camera = false;                // footprint and noise follow the altitude h
    bool climbs = false;                // its altitude is free: candidates carry climb rates
    bool volumes = false;               // occlusion model `volumes`: 3-D sight through crowns
    double z = 0.0, z_min = 0.0, z_max = 0.0;  // m, altitude now and its limits
    double climb_rate = 0.0;                   // m/s
    double camera_height = 0.0;  // m, its camera's height when it has no altitude of its own
    sensing::SensorQuality reference = {};  // α_ref·S, r0: R of one sample at h_ref (camera)
  };
  // Whether `uav` at p (its camera at height h) sees the nominal position z that its footprint
  // holds and no crown covers: under line of sight, when no tree of the map lies on the segment
  // p → z; under volumes, when no crown volume lies on the segment from (p, h) to the head.
  bool sightClear(const Mover& uav, const Vec2& p, double h, const Vec2& z) const {
    if (map_ == nullptr) return true;
    if (uav.volumes) return !map_->blocksSight(p, h, z, sensing::kTargetHeight);
    return !uav.line_of_sight || !map_->blocksSegment(p, z);
  }
  // The height of `uav`'s camera at altitude h (a ground robot's is fixed).
  static double cameraHeightAt(const Mover& uav, double h) {
    return uav.camera ? h : uav.camera_height;
  }
  // The altitudes of a camera agent at the H·S samples: its own z, or z after `climbs` (H rates,
  // or none: hold), h_t = clamp(h_{t−1} + c_m·τ, z_min, z_max).
  void heightsOf(const Mover& uav, const double* climbs, double* heights) const;
  // Moves a UAV through H actions: sink(t, p, (cos ψ, sin ψ)) at each of the H·S samples t
  // (nominal_cost_motion.h).
  template <class Sink>
  void fly(const Mover& uav, std::span<const Vec2> actions, Sink&& sink) const;
  // fly() for a ground robot: each action as the world's unicycle moves it.
  template <class Sink>
  void driveUnicycle(const Mover& robot, std::span<const Vec2> actions, Sink&& sink) const;
  // fly() of a UAV that is not a ground robot for four plans at once, lane l flying plans[l]
  // (H actions each), into poses[t] for the H·S samples t; each lane gets fly()'s bits.
  void flyLanes(const Mover& uav, const Vec2* const (&plans)[kLanes], PoseLanes* poses) const;
  // tr(P) or tr(P_pos), as full_trace_ says, or the custody loss of tr(P_pos); Cov:
  // SymmetricCov4 or CovarianceLanes.
  template <class Cov>
  [[gnu::always_inline]] auto stageTrace(const Cov& P) const {
    if (custody_r2_ > 0.0) return custodyLoss(P.positionTrace());
    return full_trace_ ? P.trace() : P.positionTrace();
  }
  // What the terminal penalty weighs a track by at m = H: tr(P_pos), or its custody loss.
  template <class Cov>
  [[gnu::always_inline]] auto penaltyWeight(const Cov& P) const {
    return custody_r2_ > 0.0 ? custodyLoss(P.positionTrace()) : P.positionTrace();
  }
  // Custody: with the position error isotropic, each axis of variance tr/2, |e| is Rayleigh and
  // P(|e| > r) = exp(−r²/tr): the chance that the track is more than r off its person.
  double custodyLoss(double trace) const { return std::exp(-custody_r2_ / trace); }
  V4 custodyLoss(const V4& trace) const {
    V4 loss;
    for (int lane = 0; lane < kLanes; ++lane) loss[lane] = std::exp(-custody_r2_ / trace[lane]);
    return loss;
  }
  // evaluate()'s body, compiled once per instruction set and per kHeight, each its own function:
  // the paper's loop is not compiled beside the height branch (TH −2.1 M Ir, bench/RESULTS.md).
  template <bool kHeight>
  void evaluateBaseline(std::span<const Vec2> actions, std::span<const double> climbs,
                        std::span<double> costs);
  template <bool kHeight>
  void evaluateAvx2(std::span<const Vec2> actions, std::span<const double> climbs,
                    std::span<double> costs);
  // kHeight: some free agent has a camera or uses `volumes`, or the team mixes models (height_);
  // without, the body is the paper's loop exactly (no per-measurement test of them).
  template <bool kHeight>
  [[gnu::always_inline]] inline void evaluateBody(std::span<const Vec2> actions,
                                                  std::span<const double> climbs,
                                                  std::span<double> costs);
  // J plus the terminal penalty of the candidate in `lane` (added to J term by term).
  double addTerminalPenalty(int lane, double J);
  // addTerminalPenalty() with many tracks or fixed UAVs (preparePenalty's penalty_merge_,
  // penalty_nearest_): the same order and charges, the same bits, with fewer instructions.
  double addTerminalPenaltyAtScale(int lane, double J);
  // Their shared parts: the uncovered tracks by decreasing trace into uncovered_ (their count),
  // and the least D_i + distance over the penalty's UAVs by index.
  struct Charge {
    std::size_t entry;
    double total, distance;  // m, D_i + |p_{i,H} − z_{j,H}| and |p_{i,H} − z_{j,H}|
  };
  int sortUncovered(int lane);
  // The exact skip (terminal_penalty_skip.cpp): with many tracks that no candidate changes,
  // prepare() charges them once to the fixed UAVs (the baseline) and a candidate charges again
  // only the tracks whose charge it can change: the ones it may leave uncovered, and those that a
  // UAV whose D_i differs from the baseline's (its free UAVs first) could take or give up. The
  // same charges as the loop; J's penalty is summed in another order (its last bits may differ).
  void prepareSkip();
  double addTerminalPenaltySkipping(int lane, double J);
  // The skip's way out to addTerminalPenaltyAtScale (its ties, or too many UAVs changed), every
  // track's nearest order sorted first.
  double wholePenalty(int lane, double J);
  // Track j's fixed entries into nearest_fixed_, the nearestSorted() nearest first.
  void sortNearest(int j);
  // D_k of the baseline before position c of penalty_fixed_order_ (fixed entry k).
  double baselineChargedBefore(int entry, int c) const;
  Charge leastChargeByIndex(const Vec2* final_position, const Vec2& z,
                            const double* fixed_distance) const;
  // prepare()'s part for the terminal penalty: the tracks it may charge, which charged UAVs are
  // free, and the fixed UAVs' distances to each track at m = H.
  void preparePenalty(const std::vector<char>& is_free);
  // Every |p_{i,H} − z_{j,H}| of a fixed entry and a track of penalty_tracks_ is finite (their
  // coordinates are finite and within ±1e150).
  bool distancesFinite() const;
  // prepare()'s part for the clearance charge: the solids near each free robot, the intended
  // positions of the fixed bodies that may touch a free one (fixed_pos: every UAV's T samples,
  // filled for the fixed agents prepare() flew: those in the cost's scope and those bodies).
  void prepareClearance(const PlanningProblem& problem, std::span<const int> free_agents,
                        const std::vector<char>& is_free, const std::vector<Vec2>& fixed_pos);
  // The clearance charge of the candidate in `lane` (free_pose_ holds its flown poses).
  double clearancePenalty(int lane) const;

  int horizon_ = 0;                    // H
  int substeps_ = 1;                   // S samples per action
  double period_ = 1.0;                // s, Δ
  bool full_trace_ = false;            // stage cost on tr(P) rather than tr(P_pos)
  double custody_r2_ = 0.0;            // m², r² of the custody cost (0: the trace)
  bool terminal_ = true;               // add the terminal penalty
  double weight_ = 0.5;                // 1/m, w
  NcvNoise Q_;                         // Q(τ) of the NCV model, τ = Δ/S
  std::vector<double> discount_;       // γ^{m−1}, m = 1..H
  const OcclusionMap* map_ = nullptr;  // the problem's map (outlives the calls that use it)
  std::vector<Mover> free_;            // the free UAVs, in prepare's order
  // Per free UAV, what evaluate() reads of its footprint and sensor in every lane (S·R and, for a
  // camera, the reference S·R_ref), set by prepare() (sensing_lanes.h).
  struct FreeSensor {
    SensorLanes quality, reference;
  };
  std::vector<FreeSensor> free_sensor_;
  void prepareSensors();  // free_sensor_ of free_
  std::vector<int> free_index_;        // UAV index of each free UAV
  std::vector<int> climbers_;          // the free UAVs (f) whose altitude is free, in order
  std::vector<int> climb_slot_;        // per free UAV: its place in climbers_, or −1
  bool heads_ = false;  // some agent uses `volumes`: occluded_ is the head-in-a-volume test
  bool height_ = false;  // heads_, or some free agent has a camera (evaluateBody<true>)
  int n_uavs_ = 0;
  // Clearance: per free agent, the map's solid parts within its reach over the horizon (empty
  // for a UAV); the fixed bodies' intended positions, T per body; and which free agents keep
  // clear. A body keeps clear of the bodies of its own class: ground robots (all of them) of
  // each other and of solids, UAVs with a radius of each other (world.cpp's collision filter).
  double clearance_ = 0.2;                                       // m, c
  std::vector<std::vector<const world::TreeDef*>> solids_near_;  // [f]
  struct Teammate {
    double radius;           // m
    bool ground;             // its class: a ground robot, or a UAV with a body
    std::vector<Vec2> path;  // m, its start, then its positions at the T samples
  };
  std::vector<Teammate> fixed_bodies_;  // the fixed agents that keep clear
  std::vector<int> free_keepers_;       // the free agents that keep clear (f)

  // Per track j and sample t = (m − 1)·S + s − 1 (s = 1..S), at [j·H·S + t].
  std::vector<Vec2> z_;                   // m, nominal position H F^m ξ_j
  std::vector<std::uint8_t> occluded_;    // z_{j,m} strictly inside a crown (hidden from all)
  std::vector<std::uint8_t> under_crown_;  // with heads_: z_{j,m} strictly inside an outline
  std::vector<std::uint8_t> fixed_seen_;  // some fixed UAV's footprint holds z_{j,m}, not hidden
  std::vector<Mat2> fixed_R_;             // m², R_fix where fixed_seen_ (else I)
  std::vector<std::uint64_t> reach_;      // bit f: free UAV f can reach a footprint over z_{j,m}
  // Per track: P after t samples with the fixed UAVs' measurements only, at [j·(H·S+1) + t].
  std::vector<SymmetricCov4> fixed_path_;

  // prepare()'s fixed UAVs by cell, one index per sample (many fixed UAVs: nearby_uavs.h), their
  // positions at the sample being indexed, and one nominal position's nearby UAVs; kept to reuse
  // their memory.
  std::vector<NearbyUavs> nearby_;
  std::vector<Vec2> nearby_positions_;
  std::vector<std::vector<int>> near_scratch_;  // per block of prepare()'s tracks

  // Per track: the recursion before the first step a free UAV could see it.
  std::vector<int> start_;           // first such sample t (H·S: none)
  std::vector<double> cost_start_;   // Σ_{m<start} γ^{m−1} tr(P_{j,m})
  std::vector<int> stage_from_;      // start_ / S: its first stage term of evaluate() (H: none)
  std::vector<int> reachable_;       // the tracks with start_ < H·S, in order
  std::vector<int> scope_tracks_;    // the tracks J sums over: all (team) or reachable_ (reach)
  double sum_prefix_ = 0.0;          // J over scope_tracks_' first sum_prefix_tracks_ tracks,
  std::size_t sum_prefix_tracks_ = 0;  // those before the first with stage terms
  std::vector<int> penalty_uavs_;    // the UAVs the terminal penalty charges, by index
  std::vector<char> penalty_free_;   // per entry of penalty_uavs_: a free UAV
  std::vector<int> penalty_tracks_;  // the tracks of scope_tracks_ not occluded at m = H
  // penalty_tracks_ split: those no free UAV can see and no fixed one holds at m = H, in the
  // penalty's order (the same in every lane), and those a candidate can change, in index order;
  // penalty_merge_: the first list's traces are finite, so a merge gives the insertion sort's
  // order.
  std::vector<int> penalty_fixed_order_, penalty_varying_;
  bool penalty_merge_ = true;
  // Entries of penalty_uavs_ that are free, and fixed; per track j the fixed entries at
  // [j·|fixed|], the first nearestSorted() of them the nearest by increasing distance to z_{j,H}
  // (ties: lower entry), the rest no nearer, in any order; penalty_nearest_: every such distance
  // is finite, so the search may stop early (addTerminalPenalty).
  // With the exact skip a track's order is sorted at its first search (nearest_sorted_).
  std::vector<int> penalty_free_entries_, penalty_fixed_entries_, nearest_fixed_;
  std::vector<char> nearest_sorted_;  // per track: nearest_fixed_ holds its order
  bool penalty_nearest_ = true;
  // How many fixed entries per track preparePenalty sorts: a full sort per track was 11 % of a
  // 256-UAV run (bench/RESULTS.md).
  static constexpr std::size_t kNearestSorted = 16;
  std::size_t nearestSorted() const {
    return std::min(penalty_fixed_entries_.size(), kNearestSorted);
  }
  // |p_{i,H} − z_{j,H}| of each fixed entry k of penalty_uavs_, at [j·|penalty_uavs_| + k]
  // (rows of the tracks a candidate may charge only: charged_tracks_, when distancesFinite()).
  std::vector<double> terminal_distance_;
  // penalty_varying_, then penalty_fixed_order_ (when distancesFinite(); else penalty_tracks_)
  std::vector<int> charged_tracks_;
  // The exact skip: on from kSkipFrom tracks in penalty_fixed_order_ (with penalty_merge_ and
  // penalty_nearest_). base_[c]: the baseline's charge of the track at position c: entry, D_i +
  // distance, distance; base_penalty_ = Σ_c w·total_c·tr_c. Per entry k (offsets at [k, k+1]):
  // its baseline charges (position, D_k after it), and the positions whose charge it could take
  // (a fixed entry: distance ≤ total_c; a free one: distance from its start ≤ total_c + the
  // distance it can fly over the horizon), both by position.
  static constexpr std::size_t kSkipFrom = 16;
  static constexpr std::size_t kSkipMaxChanged = 64;  // more UAVs changed: the whole pass
  struct BaseCharge {
    int entry;
    double total, distance;  // m
  };
  bool penalty_skip_ = false;
  std::vector<BaseCharge> base_;
  double base_penalty_ = 0.0;
  std::vector<int> win_offset_, win_position_, contest_offset_, contest_position_;
  std::vector<double> win_after_;  // m, D_k after each charge of win_position_
  // One call's UAVs whose D_i differs from the baseline's: entry, D_i, next place in its
  // contest list; changed_slot_ per entry (−1: unchanged).
  struct Changed {
    int entry;
    double charged;  // m
    int cursor;
  };
  std::vector<Changed> changed_;
  std::vector<int> changed_slot_;
  std::size_t penalty_charges_ = 0;  // tracks charged one at a time since prepare()

  // evaluate()'s per-lane values (four candidates side by side), kept to reuse their memory.
  std::vector<PoseLanes> free_pose_;  // p_{f,t} and (cos ψ, sin ψ) of φ_f, at [f·H·S + t]
  // m, h_{f,t} of a camera agent, at [f·H·S + t]; aligned to 32 bytes in every translation
  // unit as PoseLanes is (the AVX2 cost's aligned loads).
  struct alignas(32) HeightLanes {
    V4 h;
  };
  std::vector<HeightLanes> free_height_;
  std::vector<double> height_scratch_;  // m, one lane's h_{f,t}, t < H·S
  std::vector<Vec2> final_position_;  // m, p_{i,H} of every UAV, at [lane·n_uavs + i]
  std::vector<double> stage_terms_;   // m², γ^{m−1} tr(P_{j,m}), 4 lanes at [4(j·H + m − 1)]
  std::vector<double> trace_final_;   // m², tr(P_{j,H}[pos]), 4 lanes at [4j]
  std::vector<std::int64_t> in_view_final_;  // some footprint holds z_{j,H}: −1/0, 4 lanes at [4j]
  std::vector<int> uncovered_;               // terminal-penalty candidates, then their order
  std::vector<double> charged_;              // m, D_i, per entry of penalty_uavs_ (0 between calls)
  std::vector<int> charged_uavs_;            // the entry each uncovered track was charged to
};

/// The cost of a complete joint plan (one plan per UAV) — prepares and evaluates once. For tests,
/// records and reports; the planner itself reuses one NominalCost.
double nominalCost(const PlanningProblem& problem, std::span<const Plan> plans);

}  // namespace canopy::agents::planning
