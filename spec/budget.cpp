#include "spec/budget.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <unordered_map>
#include <utility>
#include <vector>

#include "agents/tracking/existence.h"
#include "sensing/footprint.h"
#include "spec/error.h"
#include "world/substeps.h"

namespace canopy::spec {
namespace {

std::string roughly(double x) {
  char text[32];
  std::snprintf(text, sizeof text, x < 1e6 ? "%.6g" : "%.1e", x);
  return text;
}

void require(const ScenarioSpec& spec, const std::string& field, double amount, double limit,
             const std::string& what) {
  if (amount > limit)
    throw ScenarioError(spec.file.string(), field, budgetMessage(amount, limit, what));
}

}  // namespace

WorkLimits workLimits(double scale) {
  WorkLimits limits;
  for (double* limit :
       {&limits.trees, &limits.world_units, &limits.world_substeps, &limits.record_bytes,
        &limits.tracking_units, &limits.tracking_step_units, &limits.cpu_seconds,
        &limits.sweep_configurations, &limits.sweep_trials, &limits.sweep_bytes}) {
    *limit *= scale;
  }
  return limits;
}

std::string budgetMessage(double amount, double limit, const std::string& what) {
  return "expected at most " + roughly(limit) + " " + what + ", this file asks for about " +
         roughly(amount) + " (--budget K raises every work limit K-fold)";
}

namespace {

double footprintReach(const ScenarioSpec& spec) {
  double reach = 0.0;  // the largest footprint's circumradius
  for (const UavSpec& uav : spec.uavs) {
    // A UAV at an altitude (issue 53) reaches farthest at its highest.
    reach =
        std::max(reach, sensing::circumradius(sensing::footprintAt(uav.sensor, uav.body.z_max)));
  }
  return reach;
}

/// The most of `points` one window of circumradius `reach` can hold, bounded from above: a window
/// lies in a square of side 2·reach, which meets at most 3 × 3 half-open cells of side `reach`,
/// so the busiest 3 × 3 block of such cells bounds it.
double busiestWindow(const std::vector<Vec2>& points, double reach) {
  const double cell = std::max(reach, 1e-3);
  std::unordered_map<std::uint64_t, double> counts;
  counts.reserve(points.size());
  auto key = [](long long i, long long j) {
    return (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint32_t>(j);
  };
  auto cellOf = [&](const Vec2& p) {
    return std::pair(static_cast<long long>(std::floor(p.x() / cell)),
                     static_cast<long long>(std::floor(p.y() / cell)));
  };
  for (const Vec2& p : points) {
    const auto [i, j] = cellOf(p);
    counts[key(i, j)] += 1.0;
  }
  double busiest = 0.0;
  for (const Vec2& p : points) {
    const auto [i, j] = cellOf(p);
    double block = 0.0;
    for (long long di = -1; di <= 1; ++di)
      for (long long dj = -1; dj <= 1; ++dj)
        if (const auto it = counts.find(key(i + di, j + dj)); it != counts.end())
          block += it->second;
    busiest = std::max(busiest, block);
    if (busiest >= static_cast<double>(points.size())) break;
  }
  return std::min(busiest, static_cast<double>(points.size()));
}

}  // namespace

double visibleTreesBound(const ScenarioSpec& spec) {
  if (spec.trees.empty() || spec.uavs.empty()) return 0.0;
  // A crown is seen when it meets the footprint: its centre lies within reach + crown.
  double crown = 0.0;
  for (const world::TreeDef& tree : spec.trees) crown = std::max(crown, tree.radius);
  std::vector<Vec2> centres;
  centres.reserve(spec.trees.size());
  for (const world::TreeDef& tree : spec.trees) centres.push_back(tree.centre);
  return busiestWindow(centres, footprintReach(spec) + crown);
}

double visibleTargetsBound(const ScenarioSpec& spec) {
  const double targets = static_cast<double>(spec.targets.size());
  if (spec.targets.empty() || spec.uavs.empty()) return 0.0;
  // Targets are sensed at the steps only: the busiest footprint window over every step's
  // positions. Past kSamples positions in all, every target counts (the cheap bound).
  constexpr double kSamples = 2e6;
  const double steps = spec.steps() + 1.0;
  if (steps * targets > kSamples) return targets;
  const double reach = footprintReach(spec);
  double busiest = 0.0;
  std::vector<Vec2> positions(spec.targets.size());
  for (int k = 0; k < static_cast<int>(steps); ++k) {
    const double t = k * spec.dt;
    for (std::size_t i = 0; i < spec.targets.size(); ++i)
      positions[i] = spec.targets[i].path.positionAt(t);
    busiest = std::max(busiest, busiestWindow(positions, reach));
    if (busiest >= targets) break;
  }
  return busiest;
}

namespace {

double substepsBound(const ScenarioSpec& spec) {
  std::vector<world::UavDef> bodies;
  bodies.reserve(spec.uavs.size());
  for (const UavSpec& uav : spec.uavs) bodies.push_back(uav.body);
  return world::substepBound(bodies, spec.dt, fastestTargetSpeed(spec));
}

}  // namespace

double clutterTrackScans(const ScenarioSpec& spec) {
  const agents::TrackingConfig& t = spec.tracking;
  const double steps = spec.steps() + 1.0;
  if (t.confirmation == agents::TrackConfirmation::m_of_n)
    return std::min(steps, static_cast<double>(t.confirm_window));
  const double p_s = agents::tracking::scanSurvival(t.survival_probability, spec.dt);
  double r = t.birth_existence;
  double scans = 0.0;
  while (r >= t.delete_existence && scans < steps) {  // each miss lowers r (δ > 0, ψ ≤ r)
    r = agents::tracking::existenceAfterMiss(p_s * r, t.p_detect, t.gate_probability);
    scans += 1.0;
    if (!(r < 1.0)) return steps;  // δ = 0 or p_S = 1 with r = 1: it never falls
  }
  return scans;
}

WorkEstimate estimateWork(const ScenarioSpec& spec) {
  const double steps = spec.steps() + 1.0;
  const double uavs = static_cast<double>(spec.uavs.size());
  const double targets = static_cast<double>(spec.targets.size());
  const double clutter = spec.sensing.clutter_rate;
  WorkEstimate work;
  work.visible_trees = visibleTreesBound(spec);
  work.visible_targets = visibleTargetsBound(spec);
  // detections per scan, at most
  const double seen = work.visible_targets + clutter + work.visible_trees;
  // Sensing: every UAV looks at every target, its clutter and the trees in its footprint; the
  // world moves every body in each of its Box2D sub-steps (world/substeps.h: v_max 10⁹ m/s made
  // 2·10⁸ sub-steps a step, a run that never ended).
  work.substeps = substepsBound(spec);
  work.world_units = steps * (work.substeps * (uavs + targets) + uavs * seen);
  // record.jsonl: per step and UAV a fixed part (pose, plan, intentions) and a part per track
  // held (targets, clutter-born tentatives); set above the sizes measured on the library
  // scenarios (tests/spec/budget_test.cpp); a polygonal crown or wall in an agent's map
  // also carries its outline, about 45 bytes a vertex.
  double polygon_vertices = 0.0;
  for (const world::TreeDef& tree : spec.trees)
    polygon_vertices += static_cast<double>(tree.vertices.size());
  work.record_bytes =
      steps * uavs * (1000.0 + 600.0 * (targets + clutter) + 45.0 * polygon_vertices);
  work.record_written_bytes = work.record_bytes > kCompactRecordAbove
                                  ? work.record_bytes / kCompactRecordRatio
                                  : work.record_bytes;
  // JPDA: gating is tracks × measurements (trees seen are measurements and tracks too); a
  // cluster enumerates at most max_hypotheses events, each as deep as the cluster's smaller side
  // (counted up to 64: larger clusters exceed any max_hypotheses at once), and a cluster with
  // more events is solved by belief propagation, at most kPropagationSweeps sweeps over its
  // gated pairs (at most tracks × measurements).
  const double measurements = seen;
  const double depth = std::min(measurements, 64.0);
  constexpr double kPropagationSweeps = 1000.0;  // agents/tracking/jpda_solver.cpp
  work.tracking_units =
      steps * uavs *
      (measurements * measurements * (1.0 + (measurements > 1.0 ? kPropagationSweeps : 0.0)) +
       (measurements > 1.0 ? spec.tracking.max_hypotheses * std::max(1.0, depth) : 0.0));
  // One step, every UAV (the trial's total can hide a step of many seconds): the joint events one
  // scan may enumerate, max_hypotheses × min(m, 64) as above, and the cluster clutter makes of
  // itself: every clutter-born track still held (clutter × clutterTrackScans) gated with every
  // clutter measurement, through up to kPropagationSweeps sweeps of belief propagation.
  // Measured (bench/RESULTS.md, "Work budget per step"): max_hypotheses 10⁷ with 60 clutter
  // and 200 clutter with birth_existence 0.999 took seconds per step.
  work.clutter_track_scans = clutterTrackScans(spec);
  work.tracking_step_units =
      uavs * ((measurements > 1.0 ? spec.tracking.max_hypotheses * std::max(1.0, depth) : 0.0) +
              clutter * work.clutter_track_scans * clutter * kPropagationSweeps);
  // Every stage's instructions (spec/work_model.h).
  work.stages = estimateStageWork(spec);
  work.instructions = work.stages.total();
  return work;
}

namespace {

// The field that makes the sub-steps many: the radius is at least world::kMinAgentRadius, so
// only a speed is unbounded: the fastest agent's v_max, or the targets' paths.
std::string fastestField(const ScenarioSpec& spec) {
  std::size_t fastest = 0;
  for (std::size_t i = 0; i < spec.uavs.size(); ++i)
    if (spec.uavs[i].body.v_max > spec.uavs[fastest].body.v_max) fastest = i;
  if (spec.uavs.empty() || fastestTargetSpeed(spec) > spec.uavs[fastest].body.v_max)
    return "targets";
  return "uavs[" + std::to_string(fastest) + "].v_max";
}

// What to change when a stage's work is the largest: the field named and the words.
struct StageAdvice {
  std::string field, what, change;
};
StageAdvice adviceFor(const std::string& stage) {
  if (stage == "planning_search")
    return {"planner.pso", "planning's search (particles × iterations × tracks in reach)",
            "fewer planner.pso.particles_per_step or stall_iterations, a shorter planner.horizon "
            "or clock.duration"};
  if (stage == "planning_penalty")
    return {"planner.cost_scope",
            "planning's terminal penalty (particles × iterations × tracks in scope)",
            "planner.cost_scope \"reach\", fewer planner.pso.particles_per_step or a shorter "
            "clock.duration"};
  if (stage == "planning_prepare")
    return {"planner.cost_scope", "planning's preparation (swarms × tracks × UAVs in scope)",
            "planner.cost_scope \"reach\" or a shorter clock.duration"};
  if (stage == "fusion")
    return {"fusion.comm_range", "fusion (rounds × UAVs × neighbours × tracks and crowns known)",
            "a finite fusion.comm_range or interest_range, fewer fusion.rounds or a shorter "
            "clock.duration"};
  if (stage == "tracking")
    return {"fusion.interest_range", "tracking (UAVs × tracks and crowns each agent holds)",
            "a finite fusion.interest_range or a shorter clock.duration"};
  if (stage == "setup") return {"occluders", "building the layouts", "fewer trees"};
  return {"clock.duration", stage + " (steps × UAVs and targets)", "a shorter clock.duration"};
}

// "42 CPU-seconds", "12 CPU-minutes", "2.1 CPU-hours".
std::string cpuTime(double seconds) {
  char text[48];
  if (seconds < 120.0)
    std::snprintf(text, sizeof text, "%.3g CPU-seconds", seconds);
  else if (seconds < 7200.0)
    std::snprintf(text, sizeof text, "%.3g CPU-minutes", seconds / 60.0);
  else
    std::snprintf(text, sizeof text, "%.3g CPU-hours", seconds / 3600.0);
  return text;
}

}  // namespace

void checkWork(const ScenarioSpec& spec, double budget_scale) {
  const WorkLimits limits = workLimits(budget_scale);
  const WorkEstimate work = estimateWork(spec);
  require(spec, "occluders", static_cast<double>(spec.trees.size()), limits.trees,
          "trees in all (every layout and include together)");
  // Sub-steps drive the estimate when the bodies' share outweighs the sensing's.
  const double bodies = static_cast<double>(spec.uavs.size() + spec.targets.size());
  const double sensing = static_cast<double>(spec.uavs.size()) *
                         (work.visible_targets + spec.sensing.clutter_rate + work.visible_trees);
  const bool substepping = work.substeps > 1.0 && work.substeps * bodies > sensing;
  require(spec,
          substepping                                                     ? fastestField(spec)
          : work.visible_trees > static_cast<double>(spec.targets.size()) ? "occluders"
                                                                          : "clock.duration",
          work.world_units, limits.world_units,
          "world units per trial (steps × (Box2D sub-steps × (UAVs + targets) + UAVs × "
          "(clutter_rate + targets and trees one footprint can hold)))");
  require(spec, "clock.duration", work.record_written_bytes, limits.record_bytes,
          "bytes of record (record.jsonl: steps × UAVs × (1000 + 600 × (targets + clutter_rate) + "
          "45 × polygon vertices); past 6.4e+07 the compact record.jsonl.zst, a 20th of that)");
  // Box2D steps the whole world once per sub-step: a step of v_max·dt = 2·10⁸ m was 2·10⁸
  // sub-steps, a run that never ended.
  require(spec, work.substeps > 1.0 ? fastestField(spec) : std::string("clock.duration"),
          (spec.steps() + 1.0) * work.substeps, limits.world_substeps,
          "Box2D sub-steps per trial (steps × the most sub-steps of one step: every body moves at "
          "most 1 m and two bodies close by at most half the smaller radius per sub-step)");
  // The field named is the one that drives the estimate most.
  const double m = work.visible_targets + spec.sensing.clutter_rate + work.visible_trees;
  const double enumeration = spec.tracking.max_hypotheses * std::min(std::max(m, 1.0), 64.0);
  const std::string tracking_field = enumeration > 1001.0 * m * m ? "tracking.max_hypotheses"
                                     : work.visible_trees > m - work.visible_trees ? "occluders"
                                                                                   : "targets";
  require(spec, tracking_field, work.tracking_units, limits.tracking_units,
          "tracking units per trial (steps × UAVs × (1001 m² + max_hypotheses × min(m, 64)), m = "
          "targets and trees one footprint can hold + sensing.clutter_rate)");
  // Per step: the field named is the one whose term is larger.
  const double enumeration_step = static_cast<double>(spec.uavs.size()) *
                                  spec.tracking.max_hypotheses * std::min(std::max(m, 1.0), 64.0);
  require(spec,
          enumeration_step >= work.tracking_step_units - enumeration_step
              ? "tracking.max_hypotheses"
              : "sensing.clutter_rate",
          work.tracking_step_units, limits.tracking_step_units,
          "tracking units in one step (UAVs × (max_hypotheses × min(m, 64) + clutter_rate² × "
          "scans a clutter-born track lives × 1000 propagation sweeps))");
  // The whole run in CPU time, named by its largest stage.
  const double instruction_limit = limits.cpu_seconds * kInstructionsPerCpuSecond;
  if (work.instructions > instruction_limit) {
    const StageAdvice advice = adviceFor(work.stages.largest());
    throw ScenarioError(
        spec.file.string(), advice.field,
        "expected at most about " + cpuTime(limits.cpu_seconds) + " of work (" +
            roughly(instruction_limit) + " instructions at " + roughly(kInstructionsPerCpuSecond) +
            " a CPU-second, the machine the estimate was measured on), this file "
            "asks for about " +
            cpuTime(work.cpuSeconds()) + " (" + roughly(work.instructions) +
            "; by stage: " + work.stages.text() + "); the largest part is " + advice.what + ": " +
            advice.change + " (--budget K raises every work limit K-fold)");
  }
}

}  // namespace canopy::spec
