#pragma once
// Planning in height (issue 53): the climb rate of a UAV whose altitude is free (z_min < z_max),
// chosen by the NBO cost (nominal_cost.h) with the footprint and noise of each candidate altitude.
// Kept apart from the swarm: the particle swarm plans the horizontal actions as before, then each
// free-altitude UAV tries a few climb rates held over the horizon against that joint plan
// (docs/design-notes.md, "Height").
#include <span>

#include "agents/planning/nominal_cost.h"
#include "agents/planning/plan.h"
#include "agents/planning/uav_state.h"
#include "sensing/camera.h"

namespace canopy::agents::planning {

/// The altitude a climb rate `climb` (m/s) held from z reaches at each of the horizon's H
/// instants, clamped to [z_min, z_max], averaged: z̄ = (1/H) Σ_{m=1..H} clamp(z + climb·m·Δ).
double meanAltitude(const UavState& uav, double climb, int horizon, double period);

/// `uav` as the cost sees it at altitude `z` (m): its camera's ground footprint there
/// (sensing::groundFootprint) and its sensor quality α scaled by the slant factor straight below,
/// z / h_ref (sensing/camera.h's noise model at the footprint's centre: the cost's R stays eq. 2
/// in form, so the factor is taken at one point). A UAV without a camera is returned unchanged.
UavState atAltitude(const UavState& uav, double z);

/// The climb rates tried, in order (the first of equal costs wins): hold, then ± the climb rate
/// and ± half of it, up first.
inline constexpr double kClimbFractions[] = {0.0, 1.0, -1.0, 0.5, -0.5};

/// The climb rate (m/s) of UAV `agent` whose cost J (its own H actions `own` against the other
/// UAVs' plans in `joint`, on `problem`) is least when the UAV flies at the mean altitude of
/// that rate (meanAltitude); 0 when its altitude is not free. `cost` is scratch.
double chooseClimb(const PlanningProblem& problem, int agent, std::span<const Plan> joint,
                   const Plan& own, double period, NominalCost& cost);

}  // namespace canopy::agents::planning
