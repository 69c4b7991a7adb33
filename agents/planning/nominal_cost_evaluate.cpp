// NominalCost::evaluate: the free UAVs' candidate plans, four side by side (one per lane of
// core/lanes.h), flown, then each reachable track's recursion run from where prepare() left it;
// compiled once for the x86-64 baseline and once for AVX2, chosen by the CPU (core/cpu.h).
#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "agents/planning/nominal_cost.h"
#include "agents/planning/nominal_cost_motion.h"
#include "core/cpu.h"

namespace canopy::agents::planning {

#if defined(__x86_64__)
template <bool kHeight>
[[gnu::target("avx2")]] void NominalCost::evaluateAvx2(std::span<const Vec2> actions,
                                                       std::span<const double> climbs,
                                                       std::span<double> costs) {
  evaluateBody<kHeight>(actions, climbs, costs);
}
#else  // elsewhere the baseline build only
template <bool kHeight>
void NominalCost::evaluateAvx2(std::span<const Vec2> actions, std::span<const double> climbs,
                               std::span<double> costs) {
  evaluateBody<kHeight>(actions, climbs, costs);
}
#endif

template <bool kHeight>
void NominalCost::evaluateBaseline(std::span<const Vec2> actions, std::span<const double> climbs,
                                   std::span<double> costs) {
  evaluateBody<kHeight>(actions, climbs, costs);
}

void NominalCost::evaluateWith(InstructionSet set, std::span<const Vec2> actions,
                               std::span<const double> climbs, std::span<double> costs) {
  if (set == InstructionSet::avx2) {
    height_ ? evaluateAvx2<true>(actions, climbs, costs)
            : evaluateAvx2<false>(actions, climbs, costs);
  } else {
    height_ ? evaluateBaseline<true>(actions, climbs, costs)
            : evaluateBaseline<false>(actions, climbs, costs);
  }
}

double NominalCost::evaluate(std::span<const Vec2> actions) {
  double cost = 0.0;
  evaluate(actions, std::span<double>(&cost, 1));
  return cost;
}

template <bool kHeight>
[[gnu::always_inline]] inline void NominalCost::evaluateBody(std::span<const Vec2> actions,
                                                             std::span<const double> climbs,
                                                             std::span<double> costs) {
  using lanes::load;
  using lanes::store;
  const int H = horizon_, S = substeps_, T = H * S;
  const std::size_t per_candidate = free_.size() * H;
  const std::size_t n_candidates = costs.size();
  const double tau = period_ / S;
  if (actions.size() != per_candidate * n_candidates) {
    std::fprintf(stderr, "NominalCost::evaluate: %zu actions for %zu candidates of %zu\n",
                 actions.size(), n_candidates, per_candidate);
    std::abort();
  }
  const std::size_t per_climbs = static_cast<std::size_t>(climbCount());
  if (!climbs.empty() && climbs.size() != per_climbs * n_candidates) {
    std::fprintf(stderr, "NominalCost::evaluate: %zu climb rates for %zu candidates of %zu\n",
                 climbs.size(), n_candidates, per_climbs);
    std::abort();
  }
  for (std::size_t first = 0; first < n_candidates; first += kLanes) {
    // Lane l runs candidate first + l; past the last candidate a lane repeats it (and is dropped).
    std::size_t candidate[kLanes];
    for (int lane = 0; lane < kLanes; ++lane) {
      candidate[lane] = std::min(first + lane, n_candidates - 1);
    }
    for (std::size_t f = 0; f < free_.size(); ++f) {
      PoseLanes* poses = &free_pose_[f * T];
      const Vec2* plans[kLanes];
      for (int lane = 0; lane < kLanes; ++lane) {
        plans[lane] = actions.data() + candidate[lane] * per_candidate + f * H;
      }
      if (free_[f].ground) {  // the unicycle, one lane after another
        for (int lane = 0; lane < kLanes; ++lane) {
          fly(free_[f], {plans[lane], static_cast<std::size_t>(H)},
              [&](int t, const Vec2& p, const Vec2& heading) {
                poses[t].x[lane] = p.x();
                poses[t].y[lane] = p.y();
                poses[t].c[lane] = heading.x();
                poses[t].s[lane] = heading.y();
              });
        }
      } else {
        flyLanes(free_[f], plans, poses);
      }
      for (int lane = 0; lane < kLanes; ++lane) {
        final_position_[lane * n_uavs_ + free_index_[f]] =
            Vec2(poses[T - 1].x[lane], poses[T - 1].y[lane]);
      }
      if (kHeight && free_[f].camera) {  // h_{f,t} per lane, heightsOf's operations
        HeightLanes* heights = &free_height_[f * T];
        const int slot = climb_slot_[f];
        double* h = height_scratch_.data();
        for (int lane = 0; lane < kLanes; ++lane) {
          const std::size_t offset =
              candidate[lane] * per_climbs + static_cast<std::size_t>(slot < 0 ? 0 : slot) * H;
          const double* rates = slot < 0 || climbs.empty() ? nullptr : climbs.data() + offset;
          heightsOf(free_[f], rates, h);
          for (int t = 0; t < T; ++t) heights[t].h[lane] = h[t];
        }
      }
    }

    for (const int j : reachable_) {
      const int first_sample = start_[j];
      CovarianceLanes P =
          CovarianceLanes::of(fixed_path_[static_cast<std::size_t>(j) * (T + 1) + first_sample]);
      // Whose footprints hold z_{j,t} at the sample being run; after the loop, at t = H·S − 1
      // (it runs at least once: start_[j] < H·S for a reachable track).
      M4 seen = M4{};
      int m = first_sample / S;         // the action (0-based) of the first sample
      int left = S - first_sample % S;  // samples of it still to come, the first included
      for (int t = first_sample; t < T; ++t) {
        const std::size_t k = static_cast<std::size_t>(j) * T + t;
        const Vec2& z = z_[k];
        predictCovariance(P, tau, Q_);  // P⁻ at the sample (P⁻_{j,m} when S = 1)
        // V_{j,m} = {i : z_{j,m} ∈ φ_i(p_{i,m}), z_{j,m} ∉ map, and, under line of sight, no map
        // tree on the segment p_{i,m} → z_{j,m}}; the fixed UAVs' part is fused in R_fix.
        seen = M4{};
        if (fixed_seen_[k]) {
          seen = M4{} - 1;
          updatePosition(P, NoiseLanes::of(fixed_R_[k]), seen);
        }
        for (std::uint64_t bits = reach_[k]; bits != 0; bits &= bits - 1) {
          const int f = std::countr_zero(bits);
          const PoseLanes& pose = free_pose_[static_cast<std::size_t>(f) * T + t];
          const Mover& uav = free_[f];
          const FreeSensor& sensor = free_sensor_[f];
          const bool camera = kHeight && uav.camera;
          if (kHeight && heads_ && !uav.volumes && under_crown_[k]) continue;  // its model hides it
          const V4 h = camera ? free_height_[static_cast<std::size_t>(f) * T + t].h : V4{};
          // φ(h) = φ(z)·h/z (class comment)
          M4 sees = camera ? footprintHoldsScaled(uav.at_origin, sensor.quality, pose, z, uav.z / h)
                           : footprintHolds(uav.at_origin, sensor.quality, pose, z);
          if (uav.line_of_sight || (kHeight && uav.volumes)) {  // once here, not per lane
            for (int lane = 0; lane < kLanes; ++lane) {
              if (sees[lane] != 0 &&
                  !sightClear(uav, Vec2(pose.x[lane], pose.y[lane]),
                              cameraHeightAt(uav, h[lane]), z)) {
                sees[lane] = 0;
              }
            }
          }
          if (!lanes::anyLane(sees)) continue;
          NoiseLanes R;
          if (camera) {  // (ℓ(h)/ℓ(h_ref))·R_ref, the sensor's model
            R = rangeBearingCovariance(z, pose.x, pose.y, sensor.reference);
            const V4 factor = slantFactor(z, pose.x, pose.y, h);
            R.r00 *= factor;
            R.r01 *= factor;
            R.r10 *= factor;
            R.r11 *= factor;
          } else {
            R = rangeBearingCovariance(z, pose.x, pose.y, sensor.quality);  // S·R
          }
          R.r00 = sees ? R.r00 : lanes::broadcast(1.0);  // I in a lane that does not see
          R.r01 = sees ? R.r01 : V4{};
          R.r10 = sees ? R.r10 : V4{};
          R.r11 = sees ? R.r11 : lanes::broadcast(1.0);
          updatePosition(P, R, sees);
          seen |= sees;
        }
        if (--left == 0) {  // the plan instant t_m ends the action: γ^{m−1} tr(P_{j,m})
          store(&stage_terms_[kLanes * (static_cast<std::size_t>(j) * H + m)],
                discount_[m] * stageTrace(P));
          ++m;
          left = S;
        }
      }
      store(&trace_final_[kLanes * j], penaltyWeight(P));  // tr(P_{j,H}[pos]) or its custody loss
      std::memcpy(&in_view_final_[kLanes * j], &seen, sizeof seen);
    }
    // J in the order of scope_tracks_ (all of them in team scope), each its prefix from
    // prepare() and then its own stage costs; the leading tracks without stage costs were summed
    // by prepare(). (A division per track and candidate group here, for the first stage, was
    // half of this function at 1024 tracks: stage_from_.)
    V4 J = lanes::broadcast(sum_prefix_);
    for (std::size_t i = sum_prefix_tracks_; i < scope_tracks_.size(); ++i) {
      const int j = scope_tracks_[i];
      J += cost_start_[j];
      for (int k = stage_from_[j]; k < H; ++k)
        J += load(&stage_terms_[kLanes * (static_cast<std::size_t>(j) * H + k)]);
    }
    for (int lane = 0; lane < kLanes && first + lane < n_candidates; ++lane) {
      costs[first + lane] = addTerminalPenalty(lane, J[lane]);
      if (!free_keepers_.empty()) costs[first + lane] += clearancePenalty(lane);
    }
  }
}

}  // namespace canopy::agents::planning
