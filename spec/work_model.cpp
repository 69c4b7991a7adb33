#include "spec/work_model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <unordered_map>
#include <utility>
#include <vector>

#include "sensing/footprint.h"
#include "sensing/sensor.h"
#include "world/substeps.h"

namespace canopy::spec {
namespace {

// Instructions per unit of each stage's term, measured by bench/budget_calibration.py
// (bench/RESULTS.md, "Work budget in instructions"): the geometric mean of measured / units over
// the grid's rows in which the stage holds at least 1 % of the run.
// Planning's search: one track-sample of the recursion, or one move of H variables.
constexpr double kPerSearchUnit = 68.0;
// The terminal penalty: one track in scope, per evaluation.
constexpr double kPerPenaltyUnit = 38.0;
// The penalty's exact skip: one track in reach (plus one), per evaluation (bench/RESULTS.md, "The
// terminal penalty's exact skip": 72, 131 and 126 at 64 × 256 × 10⁵, 16 × 64 × 10⁴ and
// 16 × 256 × 10⁴; their geometric mean).
constexpr double kPerSkipUnit = 106.0;
// The skip starts from 16 tracks that no candidate changes (NominalCost::kSkipFrom).
constexpr double kSkipFromTracks = 16.0;
// Preparing the cost: one (track, UAV) pair in scope, per swarm. 508 until the penalty's part
// measured only the tracks a candidate may charge (issue 48): × 0.777, the change in the
// estimate / measured ratio of 16 × 64 × 10⁴ and 64 × 256 × 10⁵ (bench/RESULTS.md).
constexpr double kPerPrepareUnit = 395.0;
// Fusion: one track or crown held, per step (copied, associated, fused; pair by pair, each
// neighbour adds 0.7 of that; consensus in rounds, each neighbour and round 1/31).
constexpr double kPerFusionUnit = 1950.0;
// Tracking: one track or crown held or detection, per scan (and the JPDA term of its people).
constexpr double kPerTrackingUnit = 1070.0;
// Sensing: one detection, per scan.
constexpr double kPerSensingUnit = 2800.0;
// World: one body per sub-step, or one truth read-out.
constexpr double kPerWorldUnit = 2300.0;
// Record: one track, crown or detection written, per step.
constexpr double kPerRecordUnit = 5000.0;
// Metrics: one person an agent's OSPA is computed against, per step. 281 until the cut-off
// assignment's parts were found by one search per column of cells and a counting sort (issue
// 48): × 0.707, the fit on 16 × 64 × 10⁴ and 64 × 256 × 10⁵ (bench/RESULTS.md).
constexpr double kPerMetricsUnit = 199.0;
// Setup: one crown, UAV or target built.
constexpr double kPerSetupUnit = 5670.0;
// Starting the program (dynamic linking, the command line, the built-in scenarios' index): the
// instructions of a run too small to measure anything else (bench/RESULTS.md).
constexpr double kProgramStart = 1.5e7;
// The summary's OSPA cut-off (m; sim/summary.h).
constexpr double kOspaCutoff = 50.0;

// Planning: the iterations a swarm runs. The stall rule stops it after stall_iterations without a
// relative gain of ftol, which took 1.1–2.7 × stall_iterations on average in every measured run
// (bench/RESULTS.md, "Swarms with the defaults, second step" and "Work budget in instructions");
// max_iterations bounds them.
constexpr double kIterationsPerStallWindow = 2.0;

std::vector<Vec2> uavStarts(const ScenarioSpec& spec) {
  std::vector<Vec2> starts;
  starts.reserve(spec.uavs.size());
  for (const UavSpec& uav : spec.uavs) starts.push_back(uav.body.start);
  return starts;
}

std::vector<Vec2> targetStarts(const ScenarioSpec& spec) {
  std::vector<Vec2> starts;
  starts.reserve(spec.targets.size());
  for (const TargetSpec& target : spec.targets) starts.push_back(target.path.positionAt(0.0));
  return starts;
}

/// The mean over `centres` of how many `points` lie within `radius` of each (a grid of cells of
/// side `radius`: each centre looks at its 3 × 3 block). An infinite radius counts them all. Past
/// kCentresCounted centres, an evenly strided sample of them (10⁵ people packed a metre apart
/// took 18 s counted in full).
double meanWithin(const std::vector<Vec2>& centres, const std::vector<Vec2>& points,
                  double radius) {
  if (centres.empty() || points.empty() || !(radius >= 0.0)) return 0.0;
  if (!std::isfinite(radius)) return static_cast<double>(points.size());
  const double cell = std::max(radius, 1e-3);
  auto key = [](long long i, long long j) {
    return (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint32_t>(j);
  };
  auto cellOf = [&](const Vec2& p) {
    return std::pair(static_cast<long long>(std::floor(p.x() / cell)),
                     static_cast<long long>(std::floor(p.y() / cell)));
  };
  std::unordered_map<std::uint64_t, std::vector<Vec2>> cells;
  cells.reserve(points.size());
  for (const Vec2& p : points) {
    const auto [i, j] = cellOf(p);
    cells[key(i, j)].push_back(p);
  }
  constexpr std::size_t kCentresCounted = 1000;
  const std::size_t stride = std::max<std::size_t>(1, centres.size() / kCentresCounted);
  double count = 0.0, counted = 0.0;
  for (std::size_t k = 0; k < centres.size(); k += stride) {
    const Vec2& c = centres[k];
    counted += 1.0;
    const auto [i, j] = cellOf(c);
    for (long long di = -1; di <= 1; ++di)
      for (long long dj = -1; dj <= 1; ++dj)
        if (const auto it = cells.find(key(i + di, j + dj)); it != cells.end())
          for (const Vec2& p : it->second) count += (p - c).norm() <= radius ? 1.0 : 0.0;
  }
  return count / counted;
}

}  // namespace

double fastestTargetSpeed(const ScenarioSpec& spec) {
  double fastest = 0.0;  // m/s
  for (const TargetSpec& target : spec.targets) {
    const world::Path& path = target.path;
    if (path.isConstantVelocity()) {
      fastest = std::max(fastest, path.velocity().norm());
      continue;
    }
    const std::vector<world::TimedPoint>& p = path.points();
    for (std::size_t i = 1; i < p.size(); ++i)
      fastest = std::max(fastest, (p[i].p - p[i - 1].p).norm() / (p[i].t - p[i - 1].t));
  }
  return fastest;
}

WorkGeometry workGeometry(const ScenarioSpec& spec) {
  WorkGeometry g;
  g.steps = spec.steps() + 1.0;
  const double uavs = static_cast<double>(spec.uavs.size());
  const double targets = static_cast<double>(spec.targets.size());
  if (spec.uavs.empty()) return g;
  const std::vector<Vec2> uav_starts = uavStarts(spec);
  const std::vector<Vec2> target_starts = targetStarts(spec);
  const agents::PlannerConfig& p = spec.planner;
  const bool plans = p.algorithm != agents::PlannerAlgorithm::none;

  // The footprint: the largest circumradius and the mean area (each UAV at its highest).
  double circumradius = 0.0, footprint_area = 0.0, v_max = 0.0;
  for (const UavSpec& uav : spec.uavs) {
    const sensing::FootprintDef def = sensing::footprintAt(uav.sensor, uav.body.z_max);
    circumradius = std::max(circumradius, sensing::circumradius(def));
    footprint_area += sensing::Footprint::place(def, Vec2::Zero(), 0.0).area() / uavs;
    v_max = std::max(v_max, uav.body.v_max);
  }
  const double horizon_time = p.horizon * p.plan_period;  // H·Δ (s)
  g.reach = horizon_time * v_max + circumradius;

  // Tracks: every agent ends up with every target the team holds (preseeded, or shared at full
  // communication); a finite interest_range keeps those within it.
  g.tracks_held =
      std::min(targets, meanWithin(uav_starts, target_starts, spec.fusion.interest_range));
  g.tracks_in_reach = std::min(
      g.tracks_held,
      meanWithin(uav_starts, target_starts, g.reach + horizon_time * fastestTargetSpeed(spec)));
  g.uavs_in_reach = std::max(1.0, meanWithin(uav_starts, uav_starts, 2.0 * g.reach));
  g.neighbours = std::max(0.0, meanWithin(uav_starts, uav_starts, spec.fusion.comm_range) - 1.0);

  // Crowns an agent knows: those under the ground its neighbourhood's footprints swept by mid-run,
  // each footprint moving at about the people's pace (UAVs follow them; at least 1 m/s), at the
  // forest's mean density, within interest_range.
  const double area = std::max(1.0, spec.aoi.width() * spec.aoi.height());
  const double density = static_cast<double>(spec.trees.size()) / area;  // crowns per m²
  const double pace = std::min(v_max, std::max(1.0, fastestTargetSpeed(spec)));
  const double swept_one = footprint_area + std::sqrt(footprint_area) * pace * 0.5 * spec.duration;
  double swept = std::min(area, (g.neighbours + 1.0) * swept_one);
  if (std::isfinite(spec.fusion.interest_range))
    swept =
        std::min(swept, std::numbers::pi * spec.fusion.interest_range * spec.fusion.interest_range);
  g.trees_known = density * swept;
  // One scan: the targets within a disc of the footprint's area around a UAV, clutter, crowns.
  g.seen_people =
      meanWithin(uav_starts, target_starts, std::sqrt(footprint_area / std::numbers::pi)) +
      spec.sensing.clutter_rate;
  g.seen = g.seen_people + density * footprint_area;
  g.people_within_cutoff = meanWithin(target_starts, target_starts, kOspaCutoff);

  if (!plans) return g;
  g.epochs = spec.duration / p.replan_period + 1.0;
  if (p.algorithm == agents::PlannerAlgorithm::learned) {
    g.evaluations = g.epochs * uavs;  // one network pass per agent and epoch
    return g;
  }
  const double particles = static_cast<double>(p.pso.particles_per_step) * p.horizon;
  const bool blocks = p.algorithm != agents::PlannerAlgorithm::sma &&
                      p.joint_search == agents::JointSearch::block_coordinate;
  // Block coordinate descent: one swarm per block per round; a Dec-POMDP agent's blocks are the
  // UAVs whose plans can interact with its own (planner.joint_blocks "interacting"), those
  // within 2R (agents/planning/interaction.h).
  const bool interacting_blocks = p.algorithm == agents::PlannerAlgorithm::dec_pomdp &&
                                  p.joint_blocks == agents::JointBlocks::interacting;
  const double swarms_per_call =
      blocks ? p.joint_rounds * (interacting_blocks ? g.uavs_in_reach : uavs) : 1.0;
  // Centralised planning is one call for the team; the others one per agent.
  const double calls = p.algorithm == agents::PlannerAlgorithm::centralized ? 1.0 : uavs;
  const double iterations = std::min(static_cast<double>(p.pso.max_iterations),
                                     kIterationsPerStallWindow * p.pso.stall_iterations);
  g.swarms = g.epochs * calls * swarms_per_call;
  g.evaluations = g.swarms * particles * iterations;
  g.free_uavs = p.algorithm != agents::PlannerAlgorithm::sma && !blocks ? uavs : 1.0;
  return g;
}

StageWork estimateStageWork(const ScenarioSpec& spec) {
  StageWork w;
  const WorkGeometry g = workGeometry(spec);
  const double uavs = static_cast<double>(spec.uavs.size());
  const double targets = static_cast<double>(spec.targets.size());
  const agents::PlannerConfig& p = spec.planner;
  if (p.algorithm == agents::PlannerAlgorithm::learned) {
    // A network pass over the agent's tracks and teammates.
    w.planning_search = kPerSearchUnit * g.evaluations * (g.tracks_held + uavs);
  } else if (g.evaluations > 0.0) {
    // Each evaluation moves the swarm's 2·H·free variables and runs the covariance recursion of
    // every track a free UAV can reach over H·S samples (nominal_cost.h: the others start at T).
    w.planning_search = kPerSearchUnit * g.evaluations * p.horizon * g.free_uavs *
                        (1.0 + g.tracks_in_reach * p.cost_substeps);
    // The terminal penalty charges every track in scope (all held in team scope, those in reach
    // in reach scope) to its nearest pursuer: a few entries searched with one free UAV, every UAV
    // in scope when all are free.
    const double scope_tracks =
        p.cost_scope == agents::CostScope::reach ? g.tracks_in_reach : g.tracks_held;
    const double searched =
        g.free_uavs > 1.0 ? (p.cost_scope == agents::CostScope::reach ? g.uavs_in_reach : uavs)
                          : 1.0;
    // With one free UAV and at least 16 tracks out of its reach, a candidate charges again only
    // the tracks it can change (agents/planning/terminal_penalty_skip.cpp): those in its reach
    // and the few the UAVs it displaces could take.
    const bool skips = g.free_uavs <= 1.0 && scope_tracks - g.tracks_in_reach >= kSkipFromTracks;
    if (p.terminal_penalty) {
      w.planning_penalty = skips ? kPerSkipUnit * g.evaluations * (1.0 + g.tracks_in_reach)
                                 : kPerPenaltyUnit * g.evaluations * scope_tracks * searched;
    }
    // Before each swarm, the cost is prepared (nominal_cost.h): every track in scope against
    // every UAV in scope (the fixed UAVs' paths, footprints and distances at m = H).
    const double scope_uavs = p.cost_scope == agents::CostScope::reach ? g.uavs_in_reach : uavs;
    w.planning_prepare = kPerPrepareUnit * g.swarms * scope_tracks * scope_uavs;
  }
  // Fusion, every step (agents/fusion/team_fusion.h): each agent's tracks and crowns are copied,
  // associated with its neighbours' and fused. The association goes by key from 8 UAVs on (each
  // copy sorted and bounded once) and pair by pair with each neighbour below; the consensus is
  // one closed form on a complete graph without losses (clusters of 16 or more), else `rounds`
  // rounds over each neighbour's copy. Measured per held track and step (bench/RESULTS.md, "The
  // association by key"): 1896–1953 instructions at 16 × 64 × 10⁴ to 64 × 256 × 10⁵ (complete),
  // 3039 in city_swarm (3.5 neighbours, 5 rounds), 3689 in trajectory_handover (one neighbour).
  const double held = g.tracks_held + g.trees_known;
  // From TrackAssociation::kGroupedFrom UAVs; InformationConsensus::kClosedFormFrom members.
  const bool by_key = uavs >= 8.0;
  const bool closed_form = uavs >= 16.0 && !std::isfinite(spec.fusion.comm_range) &&
                           spec.fusion.comm_drop <= 0.0;
  const double per_held = 1.0 + (by_key ? 0.0 : 0.7 * g.neighbours) +
                          (closed_form ? 0.0 : g.neighbours * spec.fusion.rounds / 31.0);
  w.fusion = kPerFusionUnit * g.steps * uavs * held * per_held;
  // Tracking, every scan: predict and keep every track and crown held, gate each detection; the
  // people's detections (and clutter) and the tracks near them form clusters whose joint events
  // (JPDA) number up to max_hypotheses, each as deep as the cluster: pairs m² times a depth of
  // min(m, 64), as in the worst-case bound of spec/budget.cpp (crowns stand apart: few pairs).
  w.tracking =
      kPerTrackingUnit * g.steps * uavs *
      (held + g.seen + g.seen_people * g.seen_people * std::clamp(g.seen_people, 1.0, 64.0));
  // Sensing, every scan: the footprint's query among the bodies, then each detection's line of
  // sight and noise.
  w.sensing = kPerSensingUnit * g.steps * uavs * (1.0 + g.seen);
  // World: Box2D moves every body in each sub-step; each target's truth is read out with a point
  // query among the crowns.
  std::vector<world::UavDef> bodies;
  bodies.reserve(spec.uavs.size());
  for (const UavSpec& uav : spec.uavs) bodies.push_back(uav.body);
  const double substeps = world::substepBound(bodies, spec.dt, fastestTargetSpeed(spec));
  w.world = kPerWorldUnit * g.steps * (substeps * (uavs + targets) + targets);
  // The record: every agent's tracks, map and scan, every step; and starting the program.
  w.record = kPerRecordUnit * g.steps * uavs * (1.0 + held + g.seen) + kProgramStart;
  // The summary's metrics: each agent's estimates against every person (OSPA's cut-off
  // assignment), every step.
  // Per solve (metrics/ospa.h, solved by parts): a pass over the people (1 unit each) and over
  // the tracks (11.5 units each), and each part's assignment, about the cube of the people within
  // the 50 m cut-off of one another (0.1 unit per track and such pair); fitted on 16 × 64,
  // 16 × 256 and 64 × 256 scale points and city_swarm. An agent holding the positions of the last
  // agent solved, bit for bit, takes its figures (sim/summary.cpp): with the closed form above
  // every agent holds the team's one set, so a step is one solve; elsewhere one per agent. Every
  // agent's tracks still pass once through that comparison and the team's figures: 0.75 units
  // each (1.1, 0.53 and 3.0 measured at 16 × 64 × 10⁴, 64 × 256 × 10⁵ and 16 × 256 × 10⁴ after
  // one solve's estimate; bench/RESULTS.md, ninth session).
  const double group = std::min(g.tracks_held, g.people_within_cutoff);
  const double solves = closed_form ? 1.0 : uavs;
  w.metrics = kPerMetricsUnit * g.steps *
              (solves * (targets + 11.5 * g.tracks_held + 0.1 * g.tracks_held * group * group) +
               0.75 * uavs * g.tracks_held);
  // Setup: the layouts' crowns, Box2D's bodies.
  w.setup = kPerSetupUnit * (static_cast<double>(spec.trees.size()) + uavs + targets);
  return w;
}

namespace {
constexpr const char* kStageNames[] = {
    "planning_search", "planning_penalty", "planning_prepare", "fusion", "tracking", "sensing",
    "world",           "record",           "metrics",          "setup"};
}  // namespace

std::string StageWork::largest() const {
  const double values[] = {
      planning_search, planning_penalty, planning_prepare, fusion, tracking, sensing,
      world,           record,           metrics,          setup};
  std::size_t best = 0;
  for (std::size_t i = 1; i < std::size(values); ++i)
    if (values[i] > values[best]) best = i;
  return kStageNames[best];
}

std::string StageWork::text() const {
  const double values[] = {
      planning_search, planning_penalty, planning_prepare, fusion, tracking, sensing,
      world,           record,           metrics,          setup};
  std::string out;
  for (std::size_t i = 0; i < std::size(values); ++i) {
    char number[32];
    std::snprintf(number, sizeof number, "%.2e", values[i]);
    out += (i ? " " : "") + std::string(kStageNames[i]) + " " + number;
  }
  return out;
}

}  // namespace canopy::spec
