#pragma once
// Planning in height (issue 53): what the planner needs of a UAV whose camera follows its
// altitude. The particle swarm searches the climb rates of every UAV whose altitude is free
// (plan_optimizer.h) and the NBO cost evaluates each candidate's footprint and noise at the
// altitude it reaches (nominal_cost.h; docs/design-notes.md, "Height").
#include "agents/planning/uav_state.h"
#include "sensing/camera.h"

namespace canopy::agents::planning {

/// `uav` as its sensor is at altitude `z` (m): its camera's ground footprint there
/// (sensing::groundFootprint) and α scaled by the slant factor straight below, z / h_ref (what
/// the record and tools show; the NBO cost takes the slant factor at each measured point). A UAV
/// without a camera is returned unchanged.
UavState atAltitude(const UavState& uav, double z);

/// Whether the planner chooses `uav`'s altitude: a camera, z_min < z_max and a climb rate > 0.
bool altitudeFree(const UavState& uav);

/// The largest factor by which `uav`'s footprint can grow within `seconds` (≥ 1): a pinhole
/// camera's ground footprint is proportional to the altitude, so min(z_max, z + ż_max·t) / z
/// for a UAV whose altitude is free, 1 for any other.
double footprintGrowth(const UavState& uav, double seconds);

}  // namespace canopy::agents::planning
