#include "agents/planning/nominal_cost.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "agents/tracking/motion_model.h"
#include "core/cpu.h"
#include "sensing/noise.h"
#include "world/unicycle.h"

namespace canopy::agents::planning {
namespace {

constexpr double kHoverSpeedSquared = 1e-12;  // m²/s², below this the yaw is kept (as the world)
constexpr double kReachSlack = 1e-6;          // m, rounding margin of the reachability test
constexpr int kMaxFreeAgents = 64;            // one bit per free UAV in a reach mask

// Whether the footprint at p with heading (cos ψ, sin ψ) holds z: its constant part (shape, sizes,
// the sector's cos(θ/2)) is placed at the origin once per UAV.
bool footprintHolds(const sensing::Footprint& at_origin, const Vec2& p, const Vec2& heading,
                    const Vec2& z) {
  return at_origin.containsFrom(p, heading.x(), heading.y(), z);
}

}  // namespace

CostSettings CostSettings::from(const PlannerConfig& config, double sigma_a) {
  CostSettings s;
  s.horizon = config.horizon;
  s.period = config.plan_period;
  s.discount = config.discount;
  s.full_trace = config.full_trace;
  s.terminal_penalty = config.terminal_penalty;
  s.terminal_penalty_weight = config.terminal_penalty_weight;
  s.substeps = config.cost_substeps;
  s.sigma_a = sigma_a;
  return s;
}

__attribute__((always_inline)) inline void NominalCost::fly(const Mover& uav,
                                                            std::span<const Vec2> actions,
                                                            Vec2* positions, Vec2* headings) const {
  if (uav.ground) {
    driveUnicycle(uav, actions, positions, headings);
    return;
  }
  Vec2 p = uav.position;
  double c = uav.cos_yaw, s = uav.sin_yaw;
  const double v_max_sq = uav.v_max * uav.v_max;
  const double tau = period_ / substeps_;  // s, between samples
  for (int m = 0; m < horizon_; ++m) {
    Vec2 a = actions[m];
    double speed_sq = a.squaredNorm();
    if (speed_sq > v_max_sq) {  // the world clamps |a| to v_max
      a *= uav.v_max / std::sqrt(speed_sq);
      speed_sq = v_max_sq;
    }
    if (uav.yaw_follows && speed_sq > kHoverSpeedSquared) {
      const double speed = std::sqrt(speed_sq);
      c = a.x() / speed;  // ψ = atan2(a_y, a_x), kept as (cos ψ, sin ψ)
      s = a.y() / speed;
    }
    const Vec2 step = a * tau;  // m per sample
    for (int sample = 0; sample < substeps_; ++sample) {
      p += step;  // p at t_{m−1} + s·τ; at the last sample p_{i,m} = p_{i,m−1} + a_{i,m}·Δ
      *positions++ = p;
      *headings++ = Vec2(c, s);
    }
  }
}

void NominalCost::driveUnicycle(const Mover& robot, std::span<const Vec2> actions, Vec2* positions,
                                Vec2* headings) const {
  world::Pose2 pose{robot.position, robot.yaw};
  const double tau = period_ / substeps_;  // s, between samples
  for (int m = 0; m < horizon_; ++m) {
    Vec2 a = actions[m];
    const double speed = a.norm();
    if (speed > robot.v_max) a *= robot.v_max / speed;  // the world clamps |a| to v_max
    world::Pose2 at;
    for (int sample = 1; sample <= substeps_; ++sample) {
      at = world::unicycleMove(pose, a, robot.turn_rate, sample * tau);  // the world's motion
      *positions++ = at.position;
      *headings++ = Vec2(std::cos(at.heading), std::sin(at.heading));
    }
    pose = at;
  }
}

void NominalCost::prepare(const PlanningProblem& problem, std::span<const int> free_agents,
                          std::span<const Plan> assumed) {
  const CostSettings& s = problem.settings;
  const int H = horizon_ = s.horizon;
  const int S = substeps_ = s.substeps;
  const int T = H * S;  // samples over the horizon
  const double dt = period_ = s.period;
  const double tau = dt / S;  // s, between samples
  full_trace_ = s.full_trace;
  terminal_ = s.terminal_penalty;
  weight_ = s.terminal_penalty_weight;
  const int n_uavs = static_cast<int>(problem.uavs.size());
  const int n_targets = static_cast<int>(problem.targets.size());
  if (H < 1 || S < 1 || static_cast<int>(free_agents.size()) > kMaxFreeAgents ||
      static_cast<int>(assumed.size()) != n_uavs) {
    std::fprintf(
        stderr,
        "NominalCost::prepare: H = %d, S = %d (≥ 1), %zu free UAVs (≤ %d), %zu plans for %d UAVs\n",
        H, S, free_agents.size(), kMaxFreeAgents, assumed.size(), n_uavs);
    std::abort();
  }

  Q_ = NcvNoise::of(tracking::ncvProcessNoise(tau, s.sigma_a));  // Q(τ), τ = Δ/S (paper eq. 4)
  discount_.resize(H);
  for (int m = 0; m < H; ++m) discount_[m] = std::pow(s.discount, m);  // γ^{m−1}, m = 1..H

  // R·S at each of the S samples of an action, so that a target in view throughout it gains the
  // information of one measurement of R: R is proportional to α, so α·S stands for it.
  auto sampleQuality = [S](sensing::SensorQuality quality) {
    quality.alpha *= S;
    return quality;
  };
  auto moverOf = [&](const UavState& u) {
    const bool follows = u.yaw_mode == world::YawMode::velocity;
    return Mover{u.position,
                 std::cos(u.yaw),
                 std::sin(u.yaw),
                 follows,
                 u.v_max,
                 u.footprint,
                 sensing::Footprint::place(u.footprint, Vec2::Zero(), 0.0),
                 sampleQuality(u.quality),
                 u.occlusion == sensing::OcclusionModel::line_of_sight,
                 u.kind == world::AgentKind::ground,
                 u.yaw,
                 u.turn_rate};
  };
  map_ = problem.map;
  std::vector<char> is_free(n_uavs, 0);
  free_.clear();
  free_index_.assign(free_agents.begin(), free_agents.end());
  for (const int i : free_agents) {
    is_free[i] = 1;
    free_.push_back(moverOf(problem.uavs[i]));
  }

  // The fixed UAVs' paths and footprints over the horizon.
  all_final_.assign(n_uavs, Vec2::Zero());
  std::vector<int> fixed;
  std::vector<Mover> fixed_movers(n_uavs);
  std::vector<Vec2> fixed_pos(static_cast<std::size_t>(n_uavs) * T);
  std::vector<Vec2> fixed_heading(fixed_pos.size());
  std::vector<Vec2> actions(H);
  for (int i = 0; i < n_uavs; ++i) {
    if (is_free[i]) continue;
    fixed.push_back(i);
    for (int m = 0; m < H; ++m) actions[m] = assumed[i].action(m);
    fixed_movers[i] = moverOf(problem.uavs[i]);
    fly(fixed_movers[i], actions, &fixed_pos[i * T], &fixed_heading[i * T]);
    all_final_[i] = fixed_pos[i * T + T - 1];
  }

  const std::size_t cells = static_cast<std::size_t>(n_targets) * T;
  z_.resize(cells);
  occluded_.assign(cells, 0);
  fixed_seen_.assign(cells, 0);
  fixed_R_.assign(cells, Mat2::Identity());
  reach_.assign(cells, 0);
  fixed_path_.resize(static_cast<std::size_t>(n_targets) * (T + 1));  // t = 0..T per track
  start_.assign(n_targets, T);
  cost_start_.assign(n_targets, 0.0);

  for (int j = 0; j < n_targets; ++j) {
    Vec4 x = problem.targets[j].x;
    const Mat4& P0 = problem.targets[j].P;
    // Symmetrised; the recursion keeps it exactly so and works on its unique entries.
    SymmetricCov4 P = SymmetricCov4::fromUpper(0.5 * (P0 + P0.transpose()));
    SymmetricCov4* path = &fixed_path_[static_cast<std::size_t>(j) * (T + 1)];
    path[0] = P;
    double cost = 0.0;
    bool started = false;
    for (int t = 0; t < T; ++t) {
      const int m = t / S + 1;  // the planning step this sample belongs to
      const std::size_t k = static_cast<std::size_t>(j) * T + t;
      x.head<2>() += tau * x.tail<2>();  // ξ after t + 1 samples: F(τ)^{t+1} ξ_j, no noise
      const Vec2 z = x.head<2>();
      z_[k] = z;
      occluded_[k] = problem.map != nullptr && problem.map->occludes(z);
      if (!occluded_[k]) {
        Mat2 information = Mat2::Zero();  // Σ R_i⁻¹ over the fixed UAVs that see z
        int seen = 0;
        for (const int i : fixed) {
          const std::size_t im = static_cast<std::size_t>(i) * T + t;
          if (!footprintHolds(fixed_movers[i].at_origin, fixed_pos[im], fixed_heading[im], z) ||
              !sightClear(fixed_movers[i], fixed_pos[im], z)) {
            continue;
          }
          const Mat2 R = sensing::rangeBearingCovariance(z, fixed_pos[im],
                                                         sampleQuality(problem.uavs[i].quality));
          if (seen++ == 0) fixed_R_[k] = R;
          information += R.llt().solve(Mat2::Identity());
        }
        if (seen > 1) fixed_R_[k] = information.llt().solve(Mat2::Identity());  // R_fix
        fixed_seen_[k] = seen > 0;
        for (int f = 0; f < static_cast<int>(free_.size()); ++f) {
          // |p_f − p_{f,0}| ≤ (t + 1)·v_max·τ, and a footprint holds points within its
          // circumradius.
          const double radius =
              (t + 1) * free_[f].v_max * tau + sensing::circumradius(free_[f].footprint);
          if ((z - free_[f].position).norm() <= radius + kReachSlack) reach_[k] |= 1ULL << f;
        }
      }
      if (!started && reach_[k] != 0) {
        started = true;
        start_[j] = t;
        cost_start_[j] = cost;
      }
      predictCovariance(P, tau, Q_);
      if (fixed_seen_[k]) updatePosition(P, fixed_R_[k]);
      path[t + 1] = P;
      if (started) continue;
      if ((t + 1) % S == 0) cost += discount_[m - 1] * stageTrace(P);  // at t_m
    }
    if (!started) cost_start_[j] = cost;
  }

  // The tracks a free UAV can reach, in pairs, by their first reachable sample (so that the lanes
  // of a pair start together). A lane past the last holds the slot n_targets: P = R = I (positive
  // definite, as updatePosition asks of every lane), never seen, never counted.
  std::vector<int> reachable;
  for (int j = 0; j < n_targets; ++j) {
    if (start_[j] < T) reachable.push_back(j);
  }
  std::stable_sort(reachable.begin(), reachable.end(),
                   [&](int a, int b) { return start_[a] < start_[b]; });
  const int n_pairs = static_cast<int>(reachable.size() + 1) / 2;
  pair_lane_.assign(2 * n_pairs, n_targets);
  std::copy(reachable.begin(), reachable.end(), pair_lane_.begin());
  const SymmetricCov4 unit = SymmetricCov4::fromUpper(Mat4::Identity());
  pair_samples_.resize(static_cast<std::size_t>(n_pairs) * T);
  pair_start_.resize(n_pairs);
  P_pair_start_.resize(n_pairs);
  for (int q = 0; q < n_pairs; ++q) {
    const int lanes[2] = {pair_lane_[2 * q], pair_lane_[2 * q + 1]};
    pair_start_[q] = start_[lanes[0]];       // the earlier of the two
    SymmetricCov4 before[2] = {unit, unit};  // each lane's P after pair_start_ samples
    for (int lane = 0; lane < 2; ++lane) {
      const int j = lanes[lane];
      if (j != n_targets)
        before[lane] = fixed_path_[static_cast<std::size_t>(j) * (T + 1) + pair_start_[q]];
    }
    P_pair_start_[q] = CovariancePair::of(before[0], before[1]);
    for (int t = 0; t < T; ++t) {
      PairSample& sample = pair_samples_[static_cast<std::size_t>(q) * T + t];
      Mat2 R[2] = {Mat2::Identity(), Mat2::Identity()};  // I in a lane that does not see
      sample.fixed_seen = LaneMask{0, 0};
      for (int lane = 0; lane < 2; ++lane) {
        const int j = lanes[lane];
        sample.z[lane] = Vec2::Zero();
        sample.reach[lane] = 0;
        if (j == n_targets) continue;
        const std::size_t k = static_cast<std::size_t>(j) * T + t;
        sample.z[lane] = z_[k];
        sample.reach[lane] = reach_[k];
        if (!fixed_seen_[k]) continue;
        R[lane] = fixed_R_[k];
        sample.fixed_seen[lane] = -1;
      }
      sample.fixed_R = NoisePair::of(R[0], R[1]);
    }
  }

  free_pos_.resize(free_.size() * T);
  free_heading_.resize(free_.size() * T);
  // A track no free UAV can see ends as the fixed UAVs leave it (evaluate() overwrites the others).
  // Slot n_targets: a pair's empty lane.
  trace_final_.resize(n_targets + 1);
  in_view_final_.resize(n_targets + 1);
  for (int j = 0; j < n_targets; ++j) {
    trace_final_[j] = fixed_path_[static_cast<std::size_t>(j) * (T + 1) + T].positionTrace();
    in_view_final_[j] = fixed_seen_[static_cast<std::size_t>(j) * T + T - 1];
  }
  uncovered_.assign(n_targets, 0);
  stage_terms_.resize(static_cast<std::size_t>(n_targets + 1) * H);
  charged_.assign(n_uavs, 0.0);
}

#if defined(__x86_64__)
NominalCost::InstructionSet NominalCost::instructionSet() {
  return cpuHasAvx() ? InstructionSet::avx : InstructionSet::sse2;
}

__attribute__((target("avx"))) double NominalCost::evaluateAvx(std::span<const Vec2> actions) {
  return evaluateBody(actions);
}
#else  // elsewhere the baseline build only ("sse2" names it)
NominalCost::InstructionSet NominalCost::instructionSet() {
  return InstructionSet::sse2;
}

double NominalCost::evaluateAvx(std::span<const Vec2> actions) {
  return evaluateBody(actions);
}
#endif

double NominalCost::evaluateWith(InstructionSet set, std::span<const Vec2> actions) {
  return set == InstructionSet::avx ? evaluateAvx(actions) : evaluateSse2(actions);
}

double NominalCost::evaluateSse2(std::span<const Vec2> actions) {
  return evaluateBody(actions);
}

__attribute__((always_inline)) inline double NominalCost::evaluateBody(
    std::span<const Vec2> actions) {
  const int H = horizon_, S = substeps_, T = H * S;
  for (std::size_t f = 0; f < free_.size(); ++f) {
    fly(free_[f], actions.subspan(f * H, H), &free_pos_[f * T], &free_heading_[f * T]);
    all_final_[free_index_[f]] = free_pos_[f * T + T - 1];
  }

  const double tau = period_ / S;
  double J = 0.0;
  const int n_targets = static_cast<int>(start_.size());
  const int n_pairs = static_cast<int>(pair_start_.size());
  for (int q = 0; q < n_pairs; ++q) {
    const int ja = pair_lane_[2 * q], jb = pair_lane_[2 * q + 1];  // the lanes' tracks
    const int first = pair_start_[q];
    CovariancePair P = P_pair_start_[q];
    LaneMask seen_final = {0, 0};
    int m = first / S;         // the action (0-based) of the first sample
    int left = S - first % S;  // samples of it still to come, the first included
    for (int t = first; t < T; ++t) {
      const PairSample& sample = pair_samples_[static_cast<std::size_t>(q) * T + t];
      predictCovariance(P, tau, Q_);  // P⁻ at the sample (P⁻_{j,m} when S = 1)
      // V_{j,m} = {i : z_{j,m} ∈ φ_i(p_{i,m}), z_{j,m} ∉ map, and, under line of sight, no map
      // tree on the segment p_{i,m} → z_{j,m}}; the fixed UAVs' part is fused in R_fix.
      LaneMask seen = sample.fixed_seen;
      if (anyLane(seen)) updatePosition(P, sample.fixed_R, seen);
      for (std::uint64_t bits = sample.reach[0] | sample.reach[1]; bits != 0; bits &= bits - 1) {
        const int f = std::countr_zero(bits);
        const std::size_t fq = static_cast<std::size_t>(f) * T + t;
        Mat2 R[2] = {Mat2::Identity(), Mat2::Identity()};  // I in a lane that does not see
        LaneMask sees = {0, 0};
        for (int lane = 0; lane < 2; ++lane) {
          const Vec2& z = sample.z[lane];
          if ((sample.reach[lane] >> f & 1) == 0 ||
              !footprintHolds(free_[f].at_origin, free_pos_[fq], free_heading_[fq], z) ||
              !sightClear(free_[f], free_pos_[fq], z)) {
            continue;
          }
          R[lane] = sensing::rangeBearingCovariance(z, free_pos_[fq], free_[f].quality);  // S·R
          sees[lane] = -1;
        }
        if (!anyLane(sees)) continue;
        updatePosition(P, NoisePair::of(R[0], R[1]), sees);
        seen |= sees;
      }
      if (--left == 0) {  // the plan instant t_m ends the action: γ^{m−1} tr(P_{j,m})
        const Lanes term = discount_[m] * stageTrace(P);
        stage_terms_[static_cast<std::size_t>(ja) * H + m] = term[0];
        stage_terms_[static_cast<std::size_t>(jb) * H + m] = term[1];
        ++m;
        left = S;
      }
      if (t == T - 1) seen_final = seen;
    }
    const Lanes trace = P.positionTrace();  // tr(P_{j,H}[pos])
    trace_final_[ja] = trace[0];
    trace_final_[jb] = trace[1];
    in_view_final_[ja] = seen_final[0] != 0;
    in_view_final_[jb] = seen_final[1] != 0;
  }
  // J in the order of the tracks, each its prefix from prepare() and then its own stage costs.
  for (int j = 0; j < n_targets; ++j) {
    J += cost_start_[j];
    for (int k = start_[j] / S; k < H; ++k) J += stage_terms_[static_cast<std::size_t>(j) * H + k];
  }
  if (!terminal_ || charged_.empty()) return J;

  // Terminal penalty: tracks in no footprint and not occluded at m = H, by decreasing
  // tr(P_{j,H}[pos]) (ties: lower index first; stable insertion sort).
  int count = 0;
  for (int j = 0; j < n_targets; ++j) {
    if (in_view_final_[j] || occluded_[static_cast<std::size_t>(j) * T + T - 1]) continue;
    int slot = count++;
    for (; slot > 0 && trace_final_[uncovered_[slot - 1]] < trace_final_[j]; --slot) {
      uncovered_[slot] = uncovered_[slot - 1];
    }
    uncovered_[slot] = j;
  }
  std::fill(charged_.begin(), charged_.end(), 0.0);
  for (int c = 0; c < count; ++c) {
    const int j = uncovered_[c];
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    int best = 0;
    double best_total = std::numeric_limits<double>::infinity(), best_distance = 0.0;
    for (int i = 0; i < static_cast<int>(charged_.size()); ++i) {
      const double distance = (all_final_[i] - z).norm();  // |p_{i,H} − z_{j,H}|
      if (charged_[i] + distance < best_total) {
        best = i;
        best_total = charged_[i] + distance;
        best_distance = distance;
      }
    }
    J += weight_ * best_total * trace_final_[j];  // w (D_i + |p_{i,H} − z_{j,H}|) tr(P_{j,H}[pos])
    charged_[best] += best_distance;              // D_i += |p_{i,H} − z_{j,H}|
  }
  return J;
}

double nominalCost(const PlanningProblem& problem, std::span<const Plan> plans) {
  const int H = problem.settings.horizon;
  std::vector<int> everyone(problem.uavs.size());
  std::vector<Vec2> actions;
  actions.reserve(everyone.size() * H);
  for (std::size_t i = 0; i < everyone.size(); ++i) {
    everyone[i] = static_cast<int>(i);
    for (int m = 0; m < H; ++m) actions.push_back(plans[i].action(m));
  }
  NominalCost cost;
  cost.prepare(problem, everyone, plans);
  return cost.evaluate(actions);
}

}  // namespace canopy::agents::planning
