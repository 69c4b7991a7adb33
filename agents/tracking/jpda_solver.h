#pragma once
// Marginal association probabilities of one JPDA cluster (Fortmann, Bar-Shalom & Scheffe 1983;
// Bar-Shalom, Willett & Tian 2011). A joint event assigns each track at most one gated
// measurement and each measurement at most one track (a matching of the gating graph). Its
// probability in the parametric JPDA, with P_D the detection and P_G the gate probability and
// λ the clutter density (1/m²), is
//   P(θ | Z) ∝ Π_{(t,j) ∈ θ} P_D N(z_j; ẑ_t, S_tj) / λ · Π_{t missed in θ} (1 − P_D P_G).
// Dividing by the constant Π_t (1 − P_D P_G) leaves P(θ | Z) ∝ Π_{(t,j) ∈ θ} r_tj with the
// likelihood ratio r_tj = P_D N(ν_tj; 0, S_tj) / (λ (1 − P_D P_G)).
// The marginal β_tj = Σ_{θ ∋ (t,j)} P(θ | Z); the miss probability is β_t0 = 1 − Σ_j β_tj.
#include <span>
#include <vector>

namespace canopy::agents::tracking {

/// One gated track–measurement pair of a cluster, with indices local to the cluster.
struct GatedPair {
  int track = 0;           // 0 .. tracks − 1
  int measurement = 0;     // 0 .. measurements − 1
  double log_ratio = 0.0;  // ln r_tj (dimensionless); −∞ when P_D = 0
};

/// χ²₂ gate threshold γ with P(χ²₂ ≤ γ) = P_G: γ = −2 ln(1 − P_G) (7.824 at P_G = 0.98).
double gateThreshold(double gate_probability);

/// ln r = ln P_D − ln λ − ln(1 − P_D P_G) − ln 2π − ½ ln|S| − ½ d², for a 2-D innovation with
/// Mahalanobis distance d² = νᵀ S⁻¹ ν and log_det_S = ln|S| (S in m²).
double associationLogRatio(double d2, double log_det_S, double p_detect, double gate_probability,
                           double clutter_density);

/// Solves clusters; keeps its buffers between calls so that steady state allocates nothing.
class JpdaSolver {
 public:
  /// Writes β_tj of pairs[k] into beta[k]. Enumerates the joint events exactly when there are at
  /// most max_hypotheses of them and returns true. Otherwise returns false and approximates the
  /// marginals by loopy belief propagation on the gating graph (Williams & Lau 2014), which is
  /// exact when the cluster's gating graph has no cycle.
  bool solve(int tracks, int measurements, std::span<const GatedPair> pairs, long max_hypotheses,
             std::span<double> beta);

 private:
  void buildAdjacency(int tracks, int measurements, std::span<const GatedPair> pairs);
  bool enumerate(std::span<const GatedPair> pairs, long max_hypotheses, std::span<double> beta);
  void propagate(std::span<const GatedPair> pairs, std::span<double> beta);

  // Pairs grouped by track and by measurement (CSR: pairs of track t are
  // by_track_[track_start_[t] .. track_start_[t + 1])).
  std::vector<int> track_start_, by_track_, measurement_start_, by_measurement_;
  // Enumeration: rows are the smaller side of the bipartite gating graph.
  bool rows_are_tracks_ = true;
  std::vector<int> option_;         // per row: −1 not entered, 0 none, k ≥ 1 its k-th pair
  std::vector<double> log_weight_;  // ln of the event weight accumulated down to each row
  std::vector<char> column_used_;
  std::vector<int> chosen_;          // pairs in the current partial event
  std::vector<double> accumulated_;  // Σ of event weights per pair (scaled)
  // Belief propagation: ln μ_{t→j} and ln ν_{j→t} per pair, and a prefix-sum buffer.
  std::vector<double> to_measurement_, to_track_, scratch_;
};

}  // namespace canopy::agents::tracking
