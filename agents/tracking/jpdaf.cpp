#include "agents/tracking/jpdaf.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "agents/tracking/existence.h"
#include "agents/tracking/kalman.h"
#include "agents/tracking/measurement_model.h"

namespace canopy::agents::tracking {

template <int N>
void Jpdaf::step(std::vector<Track<N>>& tracks, std::span<const int> track_ids,
                 std::span<const sensing::Observation> observations, std::span<const int> obs_ids,
                 const TrackingConfig& config, std::span<std::uint8_t> claimed,
                 TrackingDiagnostics& diagnostics) {
  const int n_tracks = static_cast<int>(track_ids.size());
  const int n_measurements = static_cast<int>(obs_ids.size());

  std::fill(claimed.begin(), claimed.end(), std::uint8_t{0});
  pairs_.clear();
  pair_start_.resize(n_tracks + 1);
  for (int k = 0; k < n_tracks; ++k) {
    pair_start_[k] = static_cast<int>(pairs_.size());
    const Track<N>& track = tracks[track_ids[k]];
    // JIPDA: the association weights are JPDA's with P_D replaced by P_D ψ, and the P_D a track
    // expects is P_D × P(visible) (agents/tracking/existence.h).
    const double p_detect = config.p_detect * track.visibility * track.existence_prior;
    gate(track.prior.x.template head<2>(), track.prior.P.template topLeftCorner<2, 2>(), k,
         p_detect, observations, obs_ids, config, claimed, diagnostics);
  }
  pair_start_[n_tracks] = static_cast<int>(pairs_.size());

  solveClusters(n_tracks, n_measurements, config, diagnostics);

  detection_probability_.assign(n_tracks, 0.0);
  for (int k = 0; k < n_tracks; ++k) {
    Track<N>& track = tracks[track_ids[k]];
    track.detected = pair_start_[k + 1] > pair_start_[k];
    if (track.detected) {
      track.posterior = mixture<N>(track, k, observations, obs_ids, config, diagnostics);
    } else {
      track.posterior = track.prior;
      // r⁺ = ψ (1 − P_D P_G) / (1 − P_D P_G ψ): no measurement of its own (existence.h)
      track.existence = existenceAfterMiss(
          track.existence_prior, config.p_detect * track.visibility, config.gate_probability);
    }
  }
}

void Jpdaf::gate(const Vec2& position, const Mat2& P_pos, int track, double p_detect,
                 std::span<const sensing::Observation> observations, std::span<const int> obs_ids,
                 const TrackingConfig& config, std::span<std::uint8_t> claimed,
                 TrackingDiagnostics& diagnostics) {
  const double gamma = gateThreshold(config.gate_probability);
  const double gamma_birth = std::max(gamma, gateThreshold(config.birth_gate_probability));
  const double trace_P = P_pos.trace();
  for (int l = 0; l < static_cast<int>(obs_ids.size()); ++l) {
    const sensing::Observation& o = observations[obs_ids[l]];
    const Vec2 nu = o.z - position;  // ν = z − H x̄
    // νᵀ S⁻¹ ν ≥ |ν|² / λ_max(S) ≥ |ν|² / tr(S): a cheap test that rejects most pairs exactly.
    if (nu.squaredNorm() > gamma_birth * (trace_P + o.R.trace())) continue;
    const Mat2 S = P_pos + o.R;  // S = H P̄ Hᵀ + R
    const Eigen::LLT<Mat2> llt(S);
    if (llt.info() != Eigen::Success) {
      ++diagnostics.non_positive_covariances;
      continue;
    }
    const Vec2 w = llt.matrixL().solve(nu);
    const double d2 = w.squaredNorm();  // d² = νᵀ S⁻¹ ν = |L⁻¹ ν|²
    if (d2 <= gamma_birth) claimed[l] = 1;
    if (!(d2 <= gamma) || !(p_detect > 0.0)) continue;  // P_D ψ = 0: no joint event assigns it
    const double log_det = 2.0 * std::log(llt.matrixL()(0, 0) * llt.matrixL()(1, 1));  // ln|S|
    pairs_.push_back({track, l,
                      associationLogRatio(d2, log_det, p_detect, config.gate_probability,
                                          config.clutter_density)});
  }
}

int Jpdaf::find(int node) {
  while (parent_[node] != node) {
    parent_[node] = parent_[parent_[node]];  // path halving
    node = parent_[node];
  }
  return node;
}

void Jpdaf::solveClusters(int tracks, int measurements, const TrackingConfig& config,
                          TrackingDiagnostics& diagnostics) {
  // Clusters: connected components of the gating graph, by union–find over tracks
  // (0 .. tracks − 1) and measurements (tracks + l).
  parent_.resize(tracks + measurements);
  std::iota(parent_.begin(), parent_.end(), 0);
  for (const Pair& pair : pairs_) {
    const int a = find(pair.track);
    const int b = find(tracks + pair.measurement);
    if (a != b) parent_[a] = b;
  }
  cluster_of_root_.assign(tracks + measurements, -1);
  int clusters = 0;
  for (int k = 0; k < tracks; ++k) {
    if (pair_start_[k + 1] == pair_start_[k]) continue;  // gated nothing: a miss, no cluster
    int& cluster = cluster_of_root_[find(k)];
    if (cluster < 0) cluster = clusters++;
  }
  cluster_start_.assign(clusters + 1, 0);
  for (int k = 0; k < tracks; ++k) {
    if (pair_start_[k + 1] == pair_start_[k]) continue;
    ++cluster_start_[cluster_of_root_[find(k)] + 1];
  }
  for (int c = 0; c < clusters; ++c) cluster_start_[c + 1] += cluster_start_[c];
  cluster_tracks_.resize(cluster_start_[clusters]);
  local_measurement_.assign(measurements, -1);
  cursor_.assign(cluster_start_.begin(), cluster_start_.end() - 1);
  for (int k = 0; k < tracks; ++k) {  // in track order: each cluster lists its tracks ascending
    if (pair_start_[k + 1] == pair_start_[k]) continue;
    cluster_tracks_[cursor_[cluster_of_root_[find(k)]]++] = k;
  }

  beta_.resize(pairs_.size());
  for (int c = 0; c < clusters; ++c) {
    local_pairs_.clear();
    cluster_measurements_.clear();
    const int first = cluster_start_[c];
    const int count = cluster_start_[c + 1] - first;
    for (int local_track = 0; local_track < count; ++local_track) {
      const int k = cluster_tracks_[first + local_track];
      for (int p = pair_start_[k]; p < pair_start_[k + 1]; ++p) {
        int& local = local_measurement_[pairs_[p].measurement];
        if (local < 0) {
          local = static_cast<int>(cluster_measurements_.size());
          cluster_measurements_.push_back(pairs_[p].measurement);
        }
        local_pairs_.push_back({local_track, local, pairs_[p].log_ratio});
      }
    }
    local_beta_.resize(local_pairs_.size());
    if (!solver_.solve(count, static_cast<int>(cluster_measurements_.size()), local_pairs_,
                       config.max_hypotheses, local_beta_)) {
      ++diagnostics.approximated_clusters;
    }
    int index = 0;  // local pairs were listed in the same order as the tracks' pairs
    for (int local_track = 0; local_track < count; ++local_track) {
      const int k = cluster_tracks_[first + local_track];
      for (int p = pair_start_[k]; p < pair_start_[k + 1]; ++p) beta_[p] = local_beta_[index++];
    }
    for (const int l : cluster_measurements_) local_measurement_[l] = -1;
  }
}

template <int N>
Gaussian<N> Jpdaf::mixture(Track<N>& owner, int track,
                           std::span<const sensing::Observation> observations,
                           std::span<const int> obs_ids, const TrackingConfig& config,
                           TrackingDiagnostics& diagnostics) {
  const Gaussian<N>& prior = owner.prior;
  using Model = MeasurementModel<N>;
  using VecN = Eigen::Matrix<double, N, 1>;
  using MatN = Eigen::Matrix<double, N, N>;
  // With d_j = x_j − x̄ (d_0 = 0 for the miss) and d = x − x̄ = Σ β_j d_j, Σ β_j = 1:
  //   Σ_j β_j (P_j + (x − x_j)(x − x_j)ᵀ) = Σ_j β_j (P_j + d_j d_jᵀ) − d dᵀ,
  // one pass over the hypotheses, with small offsets instead of raw second moments.
  double beta_miss = 1.0;
  VecN d = VecN::Zero();
  MatN moments = MatN::Zero();
  for (int p = pair_start_[track]; p < pair_start_[track + 1]; ++p) {
    const double beta = beta_[p];
    const sensing::Observation& o = observations[obs_ids[pairs_[p].measurement]];
    const auto component = kalmanUpdate<N, Model::M>(prior, Model::z(o), Model::R(o));
    if (!component) {  // counted, and its weight left with the miss hypothesis
      ++diagnostics.non_positive_covariances;
      continue;
    }
    beta_miss -= beta;
    const VecN d_j = component->x - prior.x;
    d += beta * d_j;
    moments += beta * (component->P + d_j * d_j.transpose());
  }
  beta_miss = std::max(0.0, beta_miss);  // β_0 = 1 − Σ_j β_j
  detection_probability_[track] = 1.0 - beta_miss;
  // JIPDA (existence.h): r⁺ = Σ_{j≥1} β_j + β_0 r_miss, r_miss = P(exists | no measurement); the
  // state mixes the hypotheses conditional on existence, weights β_j / r⁺ and β_0 r_miss / r⁺.
  const double p_detect = config.p_detect * owner.visibility;
  const double r_miss =
      existenceAfterMiss(owner.existence_prior, p_detect, config.gate_probability);
  const double r = std::min(1.0, (1.0 - beta_miss) + beta_miss * r_miss);
  owner.existence = r;
  if (!(r > 0.0)) return prior;
  d /= r;
  Gaussian<N> posterior;
  posterior.x = prior.x + d;  // x = Σ_j β̃_j x_j
  const MatN P = (beta_miss * r_miss / r) * prior.P + moments / r -
                 d * d.transpose();  // P = Σ_j β̃_j (P_j + (x − x_j)(x − x_j)ᵀ)
  posterior.P = 0.5 * (P + P.transpose());
  if (Eigen::LLT<MatN>(posterior.P).info() != Eigen::Success) {
    ++diagnostics.non_positive_covariances;
    posterior.P = prior.P;  // the prediction's covariance is positive definite and conservative
  }
  if constexpr (N == 3) posterior.x(2) = std::max(posterior.x(2), config.tree_min_radius);
  return posterior;
}

template void Jpdaf::step<4>(std::vector<Track<4>>&, std::span<const int>,
                             std::span<const sensing::Observation>, std::span<const int>,
                             const TrackingConfig&, std::span<std::uint8_t>, TrackingDiagnostics&);
template void Jpdaf::step<3>(std::vector<Track<3>>&, std::span<const int>,
                             std::span<const sensing::Observation>, std::span<const int>,
                             const TrackingConfig&, std::span<std::uint8_t>, TrackingDiagnostics&);

int Jpdaf::likelyMeasurement(int k) const {
  for (int p = pair_start_[k]; p < pair_start_[k + 1]; ++p) {
    if (beta_[p] > 0.5) return pairs_[p].measurement;  // at most one β of a track exceeds ½
  }
  return -1;
}

int Jpdaf::strongestMeasurement(int k, double floor) const {
  int best = -1;
  double best_beta = floor;
  for (int p = pair_start_[k]; p < pair_start_[k + 1]; ++p) {
    if (beta_[p] >= best_beta) {
      best_beta = beta_[p];
      best = pairs_[p].measurement;
    }
  }
  return best;
}

}  // namespace canopy::agents::tracking
