#pragma once
// One JPDAF step for the tracks and observations of one label (Stone Soup's loop order: gate,
// cluster, associate, update). Births, confirmation and deletion live in Tracker.
#include <cstdint>
#include <span>
#include <vector>

#include "agents/config.h"
#include "agents/tracking/jpda_solver.h"
#include "agents/tracking/track.h"
#include "sensing/observation.h"

namespace canopy::agents::tracking {

/// TrackingConfig::birth_gate_probability: the χ²₂ gate that keeps a measurement from starting a
/// track (γ = 18.4 at the default 0.9999). It is wider than the association gate (P_G = 0.98 by
/// default) on purpose: 1 − P_G of a tracked target's own measurements fall outside its association
/// gate, usually while the track lags the target, and a track born there shares the target's next
/// measurements and gets confirmed as a duplicate. Measured over 150 runs × 100 steps of one target
/// under the default settings: 218 births and 102 duplicates alive at the end with the association
/// gate; none with the default birth gate.

/// Owns the step's buffers, so that a step allocates nothing in steady state.
class Jpdaf {
 public:
  /// Updates tracks[track_ids[k]] (whose `prior` holds this step's prediction) with the
  /// measurements observations[obs_ids[l]], all of one label and all valid
  /// (MeasurementModel<N>::valid). Sets each track's `posterior` and `detected`; sets
  /// claimed[l] = 1 for each measurement inside some track's birth gate
  /// (config.birth_gate_probability), 0 for those that may start a track.
  ///
  /// Gating is on position for both targets and trees: d² = νᵀ S⁻¹ ν ≤ γ with ν = z − x̄_pos,
  /// S = P̄_pos + R and γ = −2 ln(1 − P_G) (χ²₂). Trees gate and weigh associations on their
  /// centre only, because the clutter density λ is a density over the plane (1/m²): a 3-D
  /// likelihood over (cx, cy, r) would need a density per m²·m that the model does not have. The
  /// radius still enters the update (H = I₃).
  ///
  /// JIPDA (agents/tracking/existence.h): the association weights use P_D · visibility · ψ with
  /// each track's `visibility` and predicted existence ψ = `existence_prior`, and each track's
  /// `existence` is updated. Each track's posterior is the mixture, conditional on existence, over
  /// its hypotheses j = 0 (miss: the prediction itself) and j ≥ 1 (Kalman update with
  /// measurement j), with β from JpdaSolver and β̃ the weights given existence:
  ///   x = Σ_j β̃_j x_j,  P = Σ_j β̃_j (P_j + (x − x_j)(x − x_j)ᵀ)  (β̃ = β when ψ = 1).
  /// Instantiated for N = 4 (targets) and N = 3 (trees).
  template <int N>
  void step(std::vector<Track<N>>& tracks, std::span<const int> track_ids,
            std::span<const sensing::Observation> observations, std::span<const int> obs_ids,
            const TrackingConfig& config, std::span<std::uint8_t> claimed,
            TrackingDiagnostics& diagnostics);

  /// After step(): Σ_j β_tj of tracks[track_ids[k]], the probability that one of this scan's
  /// measurements is its own (0 when it gated none).
  double detectionProbability(int k) const { return detection_probability_[k]; }
  /// After step(): the measurement (index into obs_ids) that is more likely than not
  /// tracks[track_ids[k]]'s own (β > ½), or −1.
  int likelyMeasurement(int k) const;
  /// After step(): the measurement (index into obs_ids) with the largest β_tj of
  /// tracks[track_ids[k]], if that β is at least `floor`; else −1. Two tracks on one target
  /// share its one measurement (their β add up to at most 1), so each names it here.
  int strongestMeasurement(int k, double floor) const;

 private:
  struct Pair {
    int track;         // index into track_ids
    int measurement;   // index into obs_ids
    double log_ratio;  // ln r_tj
  };

  void gate(const Vec2& position, const Mat2& P_pos, int track, double p_detect,
            std::span<const sensing::Observation> observations, std::span<const int> obs_ids,
            const TrackingConfig& config, std::span<std::uint8_t> claimed,
            TrackingDiagnostics& diagnostics);
  void solveClusters(int tracks, int measurements, const TrackingConfig& config,
                     TrackingDiagnostics& diagnostics);
  int find(int node);
  template <int N>
  Gaussian<N> mixture(Track<N>& owner, int track,
                      std::span<const sensing::Observation> observations,
                      std::span<const int> obs_ids, const TrackingConfig& config,
                      TrackingDiagnostics& diagnostics);

  std::vector<Pair> pairs_;      // grouped by track, in track order
  std::vector<int> pair_start_;  // pairs of track k: pairs_[pair_start_[k] .. [k + 1])
  std::vector<double> beta_;     // β of each pair
  std::vector<double> detection_probability_;  // per track: Σ_j β_tj = 1 − β_0
  std::vector<int> parent_;                    // union–find over tracks, then measurements
  std::vector<int> cluster_of_root_;
  std::vector<int> cluster_start_, cluster_tracks_, cursor_;  // tracks of each cluster (CSR)
  std::vector<int> local_measurement_, cluster_measurements_;
  std::vector<GatedPair> local_pairs_;
  std::vector<double> local_beta_;
  JpdaSolver solver_;
};

}  // namespace canopy::agents::tracking
