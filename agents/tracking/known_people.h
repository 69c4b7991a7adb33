#pragma once
// Known people: the tracks the scenario pre-seeds (key origin kKnownOrigin) are people the team
// is told exist. Such a track is never deleted and its existence stays 1 (p_S = 1: a known person
// does not leave). Unseen for long it becomes *lost* — tr(P_pos) > delete_trace, where an unknown
// track would be deleted — and its Gaussian is kept within what can be true of a walking person
// in the area (a track that is seen follows its measurements: the mean is bounded once lost):
//   velocity   σ_v² ≤ walk_speed² per axis, and once lost |v̂| ≤ walk_speed;
//   position   σ_p² ≤ W²/12 per axis (a uniform spread over the area's width W, resp. height),
//              and once lost the mean inside the area.
// The bound scales P's rows and columns, P ← D P D with D = diag(min(1, σ_max,i / σ_i)), so the
// bounded P stays positive semi-definite with the same correlations. The planner's cost counts a
// lost track like any other: in team scope its large tr(P) pulls the team back toward it
// (docs/design-notes.md, "Search and track at scale").
#include "agents/config.h"
#include "agents/tracking/track.h"

namespace canopy::agents::tracking {

inline bool isKnown(const TrackKey& key) {
  return key.origin == kKnownOrigin;
}

/// A known track whose tr(P_pos) exceeds delete_trace: lost, and searched for.
inline bool isLost(const TargetGaussian& g, double delete_trace) {
  return g.P(0, 0) + g.P(1, 1) > delete_trace;
}

/// Keeps a known person's Gaussian within the bounds above (the mean's only when `lost`).
void boundKnownPerson(TargetGaussian& g, const Aabb& area, double walk_speed, bool lost);

}  // namespace canopy::agents::tracking
