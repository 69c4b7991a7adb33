// Which UAVs' plans can interact over a planning horizon: the reach of a footprint, the bodies
// that may touch, and the UAVs whose blocks a Dec-POMDP agent's joint search optimises.
#pragma once

#include <span>
#include <vector>

#include "agents/planning/nominal_cost.h"

namespace canopy::agents::planning {

inline constexpr double kReachSlack = 1e-6;  // m, rounding margin of the reachability tests

/// reach(u) = T·v_max·τ + circumradius of u's footprint: a UAV's footprint holds only points within
/// reach(u) of its start over the horizon (speeds are clamped to v_max), T = H·S samples τ = Δ/S
/// apart. A UAV that may climb: the circumradius grown by footprintGrowth(u, T·τ).
double reachOf(const CostSettings& s, const UavState& u);

/// Whether an agent keeps clear (a body the world collides, docs/design-notes.md): every ground
/// robot (the planner keeps even one of radius 0 clear by c) and every UAV with a radius. A body
/// keeps clear of the bodies of its own class only (world.cpp's collision filter).
bool keepsClear(const UavState& u);
bool sameClass(const UavState& a, const UavState& b);

/// Whether agent i can come within r_f + r_i + c of a free agent f that keeps clear of it over the
/// horizon: each moves at most T·τ·v_max from its start, so not when
/// |p_i − p_f| > T·τ·(v_f + v_i) + r_f + r_i + c.
bool mayTouch(const PlanningProblem& problem, std::span<const int> free_agents, int i);

/// The blocks of agent `self`'s block coordinate descent (Dec-POMDP, planner.joint_blocks
/// "interacting"): the UAVs of `order`, in its order, in self's connected component of the graph
/// that links UAVs i and k when their footprints can hold the same track within the horizon,
/// |p_i − p_k| ≤ reach(i) + reach(k) + T·τ·max_j |v_j| (a track moves at most that far between
/// the two looks), or when their bodies may touch. A UAV outside the component keeps its plan.
std::vector<int> interactingBlocks(const PlanningProblem& problem, int self,
                                   std::span<const int> order);

}  // namespace canopy::agents::planning
