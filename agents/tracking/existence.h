#pragma once
// The probability of existence of a track, JIPDA (Mušicki & Evans 2004, "Joint integrated
// probabilistic data association: JIPDA", IEEE T-AES 40(3); Markov chain one). With r the
// existence after the last step, p_S the survival over one scan, P_D the detection probability
// the track expects this scan (agents/tracking/visibility.h: P_D × P(visible)) and P_G the gate
// probability:
//   prediction      ψ = p_S · r
//   joint events    a track assigned measurement j weighs P_D ψ N(ν_j; 0, S_j) / λ, an
//                   unassigned one (1 − P_D P_G ψ) (JPDA's weights with P_D replaced by P_D ψ)
//   update          r⁺ = Σ_{j≥1} β_j + β_0 · ψ (1 − P_D P_G) / (1 − P_D P_G ψ)
// where β_j are the marginal association probabilities (β_0 = 1 − Σ β_j, the track assigned
// nothing) and the fraction is P(exists | no measurement of its own). The state is the mixture
// conditional on existence: weights β_j / r⁺ (j ≥ 1) and β_0 · ψ (1 − P_D P_G) / (1 − P_D P_G ψ) /
// r⁺. With ψ = 1 every weight is JPDA's.
#include <algorithm>
#include <cmath>

namespace canopy::agents::tracking {

/// Survival over one scan of dt (s) from the survival over one second: p_S(dt) = p_S(1 s)^dt.
inline double scanSurvival(double survival_per_second, double dt) {
  return std::pow(survival_per_second, dt);
}

/// P(exists | the track was assigned no measurement) = ψ (1 − P_D P_G) / (1 − P_D P_G ψ), for the
/// predicted existence ψ and the P_D the track expects (already scaled by its visibility).
inline double existenceAfterMiss(double psi, double p_detect, double gate_probability) {
  const double delta = p_detect * gate_probability;         // δ = P_D P_G
  const double denominator = 1.0 - delta * psi;             // 1 − δψ
  if (!(denominator > 0.0)) return psi >= 1.0 ? 1.0 : 0.0;  // δ = ψ = 1: a miss is impossible
  return std::clamp(psi * (1.0 - delta) / denominator, 0.0, 1.0);
}

/// r⁺ = Σ_{j≥1} β_j + β_0 · P(exists | no measurement), with detected = Σ_{j≥1} β_j.
inline double existenceAfterUpdate(double detected, double psi, double p_detect,
                                   double gate_probability) {
  const double beta_0 = std::max(0.0, 1.0 - detected);
  return std::clamp(detected + beta_0 * existenceAfterMiss(psi, p_detect, gate_probability), 0.0,
                    1.0);
}

}  // namespace canopy::agents::tracking
