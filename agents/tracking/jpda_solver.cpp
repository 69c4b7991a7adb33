#include "agents/tracking/jpda_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace canopy::agents::tracking {
namespace {

// Enumeration keeps event weights as exp(ln w − scale); it moves the scale up once an event
// outweighs it by this much (e⁶⁴ ≈ 6·10²⁷, so sums of 10⁷ events stay far from overflow).
constexpr double kRescaleMargin = 64.0;
// Belief propagation: stop when no ln ν_{j→t} moves by more than this, or after so many
// sweeps (Williams & Lau 2014 prove convergence; these bound the work on pathological input).
constexpr double kPropagationTolerance = 1e-10;
constexpr int kPropagationSweeps = 1000;
constexpr double kMinusInfinity = -std::numeric_limits<double>::infinity();

// ln(e^a + e^b), exact when either is −∞.
double logAdd(double a, double b) {
  if (a < b) std::swap(a, b);
  if (b == kMinusInfinity) return a;
  return a + std::log1p(std::exp(b - a));
}

// CSR grouping of pair indices by a key in [0, count).
template <typename Key>
void groupBy(int count, std::span<const GatedPair> pairs, Key key, std::vector<int>& start,
             std::vector<int>& grouped) {
  start.assign(count + 1, 0);
  for (const GatedPair& pair : pairs) ++start[key(pair) + 1];
  for (int k = 0; k < count; ++k) start[k + 1] += start[k];
  grouped.resize(pairs.size());
  for (int p = 0; p < static_cast<int>(pairs.size()); ++p) grouped[start[key(pairs[p])]++] = p;
  for (int k = count; k > 0; --k) start[k] = start[k - 1];  // undo the fill's advance
  start[0] = 0;
}

}  // namespace

double gateThreshold(double gate_probability) {
  return -2.0 * std::log1p(-gate_probability);  // γ = −2 ln(1 − P_G): the χ²₂ quantile
}

double associationLogRatio(double d2, double log_det_S, double p_detect, double gate_probability,
                           double clutter_density) {
  // r = P_D N(ν; 0, S) / (λ (1 − P_D P_G)), N(ν; 0, S) = exp(−d²/2) / (2π |S|^½)
  return std::log(p_detect) - std::log(clutter_density) - std::log1p(-p_detect * gate_probability) -
         std::log(2.0 * std::numbers::pi) - 0.5 * log_det_S - 0.5 * d2;
}

bool JpdaSolver::solve(int tracks, int measurements, std::span<const GatedPair> pairs,
                       long max_hypotheses, std::span<double> beta) {
  if (pairs.empty()) return true;
  buildAdjacency(tracks, measurements, pairs);
  // Every single pair is a joint event, and so is "all missed": a cluster with more pairs than
  // the cap cannot be enumerated within it.
  if (static_cast<long>(pairs.size()) < max_hypotheses && enumerate(pairs, max_hypotheses, beta)) {
    return true;
  }
  propagate(pairs, beta);
  return false;
}

void JpdaSolver::buildAdjacency(int tracks, int measurements, std::span<const GatedPair> pairs) {
  groupBy(
      tracks, pairs, [](const GatedPair& p) { return p.track; }, track_start_, by_track_);
  groupBy(
      measurements, pairs, [](const GatedPair& p) { return p.measurement; }, measurement_start_,
      by_measurement_);
  rows_are_tracks_ = tracks <= measurements;
}

bool JpdaSolver::enumerate(std::span<const GatedPair> pairs, long max_hypotheses,
                           std::span<double> beta) {
  // Depth-first enumeration of all matchings of the gating graph, row by row over its smaller
  // side: each row takes "none" or one pair whose column is still free. The leaves are the
  // feasible joint events θ, with ln w(θ) = Σ_{(t,j) ∈ θ} ln r_tj.
  const std::vector<int>& start = rows_are_tracks_ ? track_start_ : measurement_start_;
  const std::vector<int>& grouped = rows_are_tracks_ ? by_track_ : by_measurement_;
  const int rows = static_cast<int>(start.size()) - 1;
  const int columns = rows_are_tracks_ ? static_cast<int>(measurement_start_.size()) - 1
                                       : static_cast<int>(track_start_.size()) - 1;
  auto columnOf = [&](int p) { return rows_are_tracks_ ? pairs[p].measurement : pairs[p].track; };

  option_.assign(rows, -1);
  log_weight_.assign(rows + 1, 0.0);
  column_used_.assign(columns, 0);
  chosen_.clear();
  accumulated_.assign(pairs.size(), 0.0);
  double total = 0.0;  // Σ_θ w(θ) · e^{−scale}
  double scale = 0.0;  // ln of the weights' common scale
  bool scaled = false;
  long events = 0;

  int row = 0;
  while (row >= 0) {
    if (row == rows) {  // a complete joint event
      if (++events > max_hypotheses) return false;
      const double log_w = log_weight_[rows];
      if (!scaled || log_w > scale + kRescaleMargin) {
        const double factor = scaled ? std::exp(scale - log_w) : 0.0;
        total *= factor;
        for (double& a : accumulated_) a *= factor;
        scale = log_w;
        scaled = true;
      }
      const double w = std::exp(log_w - scale);
      total += w;
      for (const int p : chosen_) accumulated_[p] += w;
      --row;
      continue;
    }
    int& option = option_[row];
    const int first = start[row];
    const int degree = start[row + 1] - first;
    if (option >= 1) {  // leave the pair taken on the previous visit
      column_used_[columnOf(grouped[first + option - 1])] = 0;
      chosen_.pop_back();
    }
    ++option;
    while (option >= 1 && option <= degree && column_used_[columnOf(grouped[first + option - 1])]) {
      ++option;
    }
    if (option > degree) {  // this row's options are exhausted: back up
      option = -1;
      --row;
      continue;
    }
    if (option == 0) {
      log_weight_[row + 1] = log_weight_[row];  // the row's track (or measurement) is unassigned
    } else {
      const int p = grouped[first + option - 1];
      column_used_[columnOf(p)] = 1;
      chosen_.push_back(p);
      log_weight_[row + 1] = log_weight_[row] + pairs[p].log_ratio;  // w(θ) ·= r_tj
    }
    ++row;
  }
  for (std::size_t p = 0; p < pairs.size(); ++p) beta[p] = accumulated_[p] / total;  // β_tj
  return true;
}

void JpdaSolver::propagate(std::span<const GatedPair> pairs, std::span<double> beta) {
  // Loopy belief propagation for the marginals of a weighted bipartite matching (Williams & Lau
  // 2014), with the miss weight 1 and pair weights r_tj:
  //   μ_{t→j} = r_tj / (1 + Σ_{j'≠j} r_tj' ν_{j'→t}),   ν_{j→t} = 1 / (1 + Σ_{t'≠t} μ_{t'→j}),
  //   β_tj = r_tj ν_{j→t} / (1 + Σ_j' r_tj' ν_{j'→t}).
  // Messages are kept as logarithms, so that any ratio (λ → 0, S → 0) stays representable, and
  // the sums "over all but one" come from prefix and suffix sums, never from a subtraction.
  const int tracks = static_cast<int>(track_start_.size()) - 1;
  const int measurements = static_cast<int>(measurement_start_.size()) - 1;
  to_measurement_.assign(pairs.size(), 0.0);  // ln μ_{t→j}
  to_track_.assign(pairs.size(), 0.0);        // ln ν_{j→t}, starting from ν = 1

  // For the group grouped[begin, end): write(p, ln(1 + Σ_{other members q} e^{term(q)})).
  auto allButOne = [this](const std::vector<int>& grouped, int begin, int end, auto&& term,
                          auto&& write) {
    scratch_.resize(end - begin);
    double run = kMinusInfinity;
    for (int k = begin; k < end; ++k) {
      scratch_[k - begin] = run;
      run = logAdd(run, term(grouped[k]));
    }
    run = kMinusInfinity;
    for (int k = end - 1; k >= begin; --k) {
      write(grouped[k], logAdd(0.0, logAdd(scratch_[k - begin], run)));
      run = logAdd(run, term(grouped[k]));
    }
  };

  for (int sweep = 0; sweep < kPropagationSweeps; ++sweep) {
    for (int t = 0; t < tracks; ++t) {
      allButOne(
          by_track_, track_start_[t], track_start_[t + 1],
          [&](int p) { return pairs[p].log_ratio + to_track_[p]; },
          [&](int p, double rest) { to_measurement_[p] = pairs[p].log_ratio - rest; });
    }
    double change = 0.0;
    for (int j = 0; j < measurements; ++j) {
      allButOne(
          by_measurement_, measurement_start_[j], measurement_start_[j + 1],
          [this](int p) { return to_measurement_[p]; },
          [this, &change](int p, double rest) {
            change = std::max(change, std::abs(-rest - to_track_[p]));
            to_track_[p] = -rest;
          });
    }
    if (!(change > kPropagationTolerance)) break;
  }

  for (int t = 0; t < tracks; ++t) {
    double log_denominator = 0.0;  // ln(1 + Σ_j r_tj ν_{j→t})
    for (int k = track_start_[t]; k < track_start_[t + 1]; ++k) {
      const int p = by_track_[k];
      log_denominator = logAdd(log_denominator, pairs[p].log_ratio + to_track_[p]);
    }
    for (int k = track_start_[t]; k < track_start_[t + 1]; ++k) {
      const int p = by_track_[k];
      beta[p] = std::exp(pairs[p].log_ratio + to_track_[p] - log_denominator);
    }
  }
}

}  // namespace canopy::agents::tracking
