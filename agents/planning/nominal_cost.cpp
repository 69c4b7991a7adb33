#include "agents/planning/nominal_cost.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

constexpr int kLanes = 4;  // candidates evaluated side by side

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

template <class Sink>
[[gnu::always_inline]] inline void NominalCost::fly(const Mover& uav, std::span<const Vec2> actions,
                                                    Sink&& sink) const {
  if (uav.ground) {
    driveUnicycle(uav, actions, sink);
    return;
  }
  Vec2 p = uav.position;
  double c = uav.cos_yaw, s = uav.sin_yaw;
  const double v_max_sq = uav.v_max * uav.v_max;
  const double tau = period_ / substeps_;  // s, between samples
  int t = 0;
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
      sink(t++, p, Vec2(c, s));
    }
  }
}

template <class Sink>
void NominalCost::driveUnicycle(const Mover& robot, std::span<const Vec2> actions,
                                Sink&& sink) const {
  world::Pose2 pose{robot.position, robot.yaw};
  const double tau = period_ / substeps_;  // s, between samples
  int t = 0;
  for (int m = 0; m < horizon_; ++m) {
    Vec2 a = actions[m];
    const double speed = a.norm();
    if (speed > robot.v_max) a *= robot.v_max / speed;  // the world clamps |a| to v_max
    world::Pose2 at;
    for (int sample = 1; sample <= substeps_; ++sample) {
      at = world::unicycleMove(pose, a, robot.turn_rate, sample * tau);  // the world's motion
      sink(t++, at.position, Vec2(std::cos(at.heading), std::sin(at.heading)));
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
  n_uavs_ = n_uavs;
  final_position_.assign(static_cast<std::size_t>(kLanes) * n_uavs, Vec2::Zero());
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
    fly(fixed_movers[i], actions, [&](int t, const Vec2& p, const Vec2& heading) {
      fixed_pos[i * T + t] = p;
      fixed_heading[i * T + t] = heading;
    });
    for (int lane = 0; lane < kLanes; ++lane)
      final_position_[lane * n_uavs + i] = fixed_pos[i * T + T - 1];
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
          // The footprint's constant part (shape, sizes, a sector's cos(θ/2)) placed once per UAV.
          const Vec2& heading = fixed_heading[im];
          if (!fixed_movers[i].at_origin.containsFrom(fixed_pos[im], heading.x(), heading.y(), z) ||
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

  reachable_.clear();
  for (int j = 0; j < n_targets; ++j) {
    if (start_[j] < T) reachable_.push_back(j);
  }
  free_pose_.resize(free_.size() * T);
  // A track no free UAV can see ends as the fixed UAVs leave it (evaluate() overwrites the others).
  trace_final_.resize(static_cast<std::size_t>(kLanes) * n_targets);
  in_view_final_.resize(trace_final_.size());
  for (int j = 0; j < n_targets; ++j) {
    for (int lane = 0; lane < kLanes; ++lane) {
      trace_final_[kLanes * j + lane] =
          fixed_path_[static_cast<std::size_t>(j) * (T + 1) + T].positionTrace();
      in_view_final_[kLanes * j + lane] =
          fixed_seen_[static_cast<std::size_t>(j) * T + T - 1] ? -1 : 0;
    }
  }
  uncovered_.assign(n_targets, 0);
  stage_terms_.resize(static_cast<std::size_t>(kLanes) * n_targets * H);
  charged_.assign(n_uavs, 0.0);
}

#if defined(__x86_64__)
[[gnu::target("avx2")]] void NominalCost::evaluateAvx2(std::span<const Vec2> actions,
                                                       std::span<double> costs) {
  evaluateBody(actions, costs);
}
#else  // elsewhere the baseline build only
void NominalCost::evaluateAvx2(std::span<const Vec2> actions, std::span<double> costs) {
  evaluateBody(actions, costs);
}
#endif

void NominalCost::evaluateBaseline(std::span<const Vec2> actions, std::span<double> costs) {
  evaluateBody(actions, costs);
}

void NominalCost::evaluateWith(InstructionSet set, std::span<const Vec2> actions,
                               std::span<double> costs) {
  set == InstructionSet::avx2 ? evaluateAvx2(actions, costs) : evaluateBaseline(actions, costs);
}

double NominalCost::evaluate(std::span<const Vec2> actions) {
  double cost = 0.0;
  evaluate(actions, std::span<double>(&cost, 1));
  return cost;
}

[[gnu::always_inline]] inline void NominalCost::evaluateBody(std::span<const Vec2> actions,
                                                             std::span<double> costs) {
  using lanes::load;
  using lanes::store;
  const int H = horizon_, S = substeps_, T = H * S;
  const std::size_t per_candidate = free_.size() * H;
  const std::size_t n_candidates = costs.size();
  const int n_targets = static_cast<int>(start_.size());
  const double tau = period_ / S;
  if (actions.size() != per_candidate * n_candidates) {
    std::fprintf(stderr, "NominalCost::evaluate: %zu actions for %zu candidates of %zu\n",
                 actions.size(), n_candidates, per_candidate);
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
      for (int lane = 0; lane < kLanes; ++lane) {
        const auto plan = actions.subspan(candidate[lane] * per_candidate + f * H, H);
        fly(free_[f], plan, [&](int t, const Vec2& p, const Vec2& heading) {
          poses[t].x[lane] = p.x();
          poses[t].y[lane] = p.y();
          poses[t].c[lane] = heading.x();
          poses[t].s[lane] = heading.y();
        });
        final_position_[lane * n_uavs_ + free_index_[f]] =
            Vec2(poses[T - 1].x[lane], poses[T - 1].y[lane]);
      }
    }

    for (const int j : reachable_) {
      const int first_sample = start_[j];
      CovarianceLanes P =
          CovarianceLanes::of(fixed_path_[static_cast<std::size_t>(j) * (T + 1) + first_sample]);
      M4 seen_final = M4{};
      int m = first_sample / S;         // the action (0-based) of the first sample
      int left = S - first_sample % S;  // samples of it still to come, the first included
      for (int t = first_sample; t < T; ++t) {
        const std::size_t k = static_cast<std::size_t>(j) * T + t;
        const Vec2& z = z_[k];
        predictCovariance(P, tau, Q_);  // P⁻ at the sample (P⁻_{j,m} when S = 1)
        // V_{j,m} = {i : z_{j,m} ∈ φ_i(p_{i,m}), z_{j,m} ∉ map, and, under line of sight, no map
        // tree on the segment p_{i,m} → z_{j,m}}; the fixed UAVs' part is fused in R_fix.
        M4 seen = M4{};
        if (fixed_seen_[k]) {
          seen = M4{} - 1;
          updatePosition(P, NoiseLanes::of(fixed_R_[k]), seen);
        }
        for (std::uint64_t bits = reach_[k]; bits != 0; bits &= bits - 1) {
          const int f = std::countr_zero(bits);
          const PoseLanes& pose = free_pose_[static_cast<std::size_t>(f) * T + t];
          M4 sees = footprintHolds(free_[f].at_origin, pose, z);
          if (free_[f].line_of_sight) {  // tested once here, not per lane in sightClear
            for (int lane = 0; lane < kLanes; ++lane) {
              if (sees[lane] != 0 && !sightClear(free_[f], Vec2(pose.x[lane], pose.y[lane]), z)) {
                sees[lane] = 0;
              }
            }
          }
          if (!lanes::anyLane(sees)) continue;
          NoiseLanes R = rangeBearingCovariance(z, pose.x, pose.y, free_[f].quality);  // S·R
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
        if (t == T - 1) seen_final = seen;
      }
      store(&trace_final_[kLanes * j], P.positionTrace());  // tr(P_{j,H}[pos])
      std::memcpy(&in_view_final_[kLanes * j], &seen_final, sizeof seen_final);
    }
    // J in the order of the tracks, each its prefix from prepare() and then its own stage costs.
    V4 J = V4{};
    for (int j = 0; j < n_targets; ++j) {
      J += cost_start_[j];
      for (int k = start_[j] / S; k < H; ++k)
        J += load(&stage_terms_[kLanes * (static_cast<std::size_t>(j) * H + k)]);
    }
    for (int lane = 0; lane < kLanes && first + lane < n_candidates; ++lane) {
      costs[first + lane] = addTerminalPenalty(lane, J[lane]);
    }
  }
}

double NominalCost::addTerminalPenalty(int lane, double J) {
  if (!terminal_ || charged_.empty()) return J;
  const int T = horizon_ * substeps_;
  const int n_targets = static_cast<int>(start_.size());
  auto traceFinal = [&](int j) { return trace_final_[kLanes * j + lane]; };
  // Tracks in no footprint and not occluded at m = H, by decreasing tr(P_{j,H}[pos]) (ties: lower
  // index first; stable insertion sort).
  int count = 0;
  for (int j = 0; j < n_targets; ++j) {
    if (in_view_final_[kLanes * j + lane] != 0 ||
        occluded_[static_cast<std::size_t>(j) * T + T - 1])
      continue;
    int slot = count++;
    for (; slot > 0 && traceFinal(uncovered_[slot - 1]) < traceFinal(j); --slot) {
      uncovered_[slot] = uncovered_[slot - 1];
    }
    uncovered_[slot] = j;
  }
  std::fill(charged_.begin(), charged_.end(), 0.0);
  const Vec2* final_position = &final_position_[static_cast<std::size_t>(lane) * n_uavs_];
  for (int c = 0; c < count; ++c) {
    const int j = uncovered_[c];
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    int best = 0;
    double best_total = std::numeric_limits<double>::infinity(), best_distance = 0.0;
    for (int i = 0; i < n_uavs_; ++i) {
      const double distance = (final_position[i] - z).norm();  // |p_{i,H} − z_{j,H}|
      if (charged_[i] + distance < best_total) {
        best = i;
        best_total = charged_[i] + distance;
        best_distance = distance;
      }
    }
    J += weight_ * best_total * traceFinal(j);  // w (D_i + |p_{i,H} − z_{j,H}|) tr(P_{j,H}[pos])
    charged_[best] += best_distance;            // D_i += |p_{i,H} − z_{j,H}|
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
