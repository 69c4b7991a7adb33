#pragma once
// How many instructions one trial will execute, stage by stage, estimated from a scenario's
// validated fields before any of it runs (issue 48). Each stage's estimate is a count of the
// inner-loop terms its code runs (the "units" below, worked from what the code does) times a
// coefficient measured with callgrind on a grid of scenarios (bench/budget_calibration.py; the
// table in bench/RESULTS.md, "Work budget in instructions"). The estimate follows the measured
// instructions within a factor of about three on that grid; the budget (spec/budget.h) compares
// the total with a limit stated in CPU time.
#include <string>

#include "spec/scenario_spec.h"

namespace canopy::spec {

/// What the estimate reads from the scenario's layout: the typical neighbourhood of a UAV at the
/// start (each count a mean over the UAVs, from the start positions).
struct WorkGeometry {
  double steps = 0.0;            // steps recorded, k = 0 … duration/dt
  double epochs = 0.0;           // planning epochs, duration / replan_period + 1 (0: no planner)
  double reach = 0.0;            // m, R = H·Δ·v_max + footprint circumradius (largest)
  double tracks_held = 0.0;      // tracks one agent holds: the targets (within interest_range)
  double tracks_in_reach = 0.0;  // targets within R + H·Δ·(fastest target) of a UAV
  double uavs_in_reach = 0.0;    // UAVs within 2R of a UAV, itself included
  double neighbours = 0.0;       // UAVs within fusion.comm_range of a UAV, itself excluded
  double trees_known = 0.0;      // crowns one agent's map holds, on average over the run
  double seen = 0.0;         // detections of one scan: targets and crowns in a footprint, clutter
  double seen_people = 0.0;  // of which targets and clutter
  double people_within_cutoff = 0.0;  // targets within the OSPA cut-off (50 m) of a target
  double swarms = 0.0;                // swarms run in the whole trial (every agent, epoch, block)
  double evaluations = 0.0;  // cost evaluations of the whole trial (every agent, epoch, swarm)
  double free_uavs = 1.0;    // UAVs whose actions one evaluation varies
};
WorkGeometry workGeometry(const ScenarioSpec& spec);

/// The fastest any target's scripted path moves (m/s): a constant velocity, or a segment's.
double fastestTargetSpeed(const ScenarioSpec& spec);

/// The stages of one step (and the setup before the first), in estimated instructions.
struct StageWork {
  double planning_search = 0.0;   // PSO moves and the cost recursion over the tracks in reach
  double planning_penalty = 0.0;  // the terminal penalty over the tracks in scope
  double planning_prepare = 0.0;  // preparing the cost before each swarm: tracks × UAVs in scope
  double fusion = 0.0;            // association and CI consensus with the neighbours
  double tracking = 0.0;          // JPDA, track upkeep and the agent's map, per scan
  double sensing = 0.0;           // footprint queries, line of sight, noise
  double world = 0.0;             // Box2D sub-steps; truth read-out (point queries among crowns)
  double record = 0.0;            // the record, the other observers, starting the program
  double metrics = 0.0;           // the summary's per-step metrics (OSPA's assignment)
  double setup = 0.0;             // the scenario's layouts, the world's bodies

  double total() const {
    return planning_search + planning_penalty + planning_prepare + fusion + tracking + sensing +
           world + record + metrics + setup;
  }
  /// The stage with the most, by its name in stageNames order ("planning_search", …).
  std::string largest() const;
  /// "planning_search 1.2e+10 planning_penalty …" in a fixed order.
  std::string text() const;
};
StageWork estimateStageWork(const ScenarioSpec& spec);

/// Instructions per CPU-second of canopy on the machine the coefficients were measured on (a 2-vCPU
/// AMD EPYC guest: 0.93–1.1·10¹⁰, callgrind's count over user + sys time for eight files;
/// bench/RESULTS.md): the estimate in CPU time.
inline constexpr double kInstructionsPerCpuSecond = 1e10;

}  // namespace canopy::spec
