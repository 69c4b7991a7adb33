#pragma once
// How finely World::step() cuts one step into Box2D sub-steps, and the most sub-steps a step of a
// world can take, known before the world is built (the work budget, spec/budget.cpp).
#include <numbers>
#include <vector>

#include "world/defs.h"

namespace canopy::world {

// Each Box2D sub-step stays well inside its per-step motion limits (b2_maxTranslation = 2 m,
// b2_maxRotation = π/2, beyond which Box2D silently scales velocities down); world.cpp checks
// these against Box2D's own constants.
inline constexpr double kMaxSubstepTranslation = 1.0;                   // m, ½ b2_maxTranslation
inline constexpr double kMaxSubstepRotation = 0.25 * std::numbers::pi;  // rad, ½ b2_maxRotation
// A colliding body moves at most this fraction of its radius per sub-step: it meets whatever it
// runs into before passing through it, and sinks into it by less than that before the solver
// pushes it out.
inline constexpr double kMaxSubstepRadii = 0.5;

/// The most sub-steps World::step(dt) takes for these agents when no target moves faster than
/// `target_speed` (m/s), by step()'s rules: n ≥ v·dt / kMaxSubstepTranslation for every body
/// (agents at v_max), n ≥ θ / kMaxSubstepRotation for the largest turn θ (a ground robot's
/// turn_rate·dt, at most π: headings are wrapped), and, when two agents of one kind both have
/// bodies, n ≥ (2 v_max dt) / (kMaxSubstepRadii · r_min), their closing distance over half the
/// smaller radius. At least 1.
double substepBound(const std::vector<UavDef>& agents, double dt, double target_speed);

}  // namespace canopy::world
