// The NBO cost's settings and NominalCost::prepare: what does not depend on the candidate plans,
// computed once per planning call (the nominal target positions, the fixed UAVs' paths and their
// fused R_fix, which free UAVs can reach each position, each track's recursion up to the first
// sample a free UAV could see it). evaluate() is nominal_cost_evaluate.cpp, the terminal penalty
// terminal_penalty.cpp.
#include "agents/planning/nominal_cost.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "agents/planning/altitude_choice.h"
#include "agents/planning/interaction.h"
#include "agents/planning/nominal_cost_motion.h"
#include "agents/tracking/motion_model.h"
#include "sensing/noise.h"

namespace canopy::agents::planning {
namespace {

// From this many fixed UAVs prepare() asks only those near each nominal position (same bits).
constexpr std::size_t kNearbyFrom = 32;

constexpr int kMaxFreeAgents = 64;  // one bit per free UAV in a reach mask

// Whether p lies within reach(f) + margin of some free UAV f.
bool nearFree(const PlanningProblem& problem, std::span<const int> free_agents, const Vec2& p,
              double margin) {
  for (const int f : free_agents) {
    if ((p - problem.uavs[f].position).norm() <=
        reachOf(problem.settings, problem.uavs[f]) + margin + kReachSlack)
      return true;
  }
  return false;
}

// Whether the information cost of the free agents reads fixed agent i's plan: always in team
// scope; in reach scope when i starts within reach(f) + reach(i) of some free agent f.
bool informs(const PlanningProblem& problem, std::span<const int> free_agents, int i) {
  return problem.settings.scope == CostScope::team ||
         nearFree(problem, free_agents, problem.uavs[i].position,
                  reachOf(problem.settings, problem.uavs[i]));
}

// Closest approach of two agents that move straight over one interval, from a relative position
// a to b: min over s ∈ [0, 1] of |a + s·(b − a)|.
double closestApproach(const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp(-a.dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + s * ab).norm();
}

}  // namespace

bool NominalCost::readsPlanOf(const PlanningProblem& problem, std::span<const int> free_agents,
                              int uav) {
  // A fixed UAV farther than reach(f) + reach(uav) from every free UAV f holds no nominal
  // position a free UAV can reach, and one that cannot come within the separation of a free
  // body charges no clearance (prepare() skips it).
  return informs(problem, free_agents, uav) || mayTouch(problem, free_agents, uav);
}

CostSettings CostSettings::from(const PlannerConfig& config, double sigma_a) {
  CostSettings s;
  s.horizon = config.horizon;
  s.period = config.plan_period;
  s.discount = config.discount;
  s.full_trace = config.full_trace;
  s.custody_radius = config.custody ? config.custody_radius : 0.0;
  s.terminal_penalty = config.terminal_penalty;
  s.terminal_penalty_weight = config.terminal_penalty_weight;
  s.substeps = config.cost_substeps;
  s.sigma_a = sigma_a;
  s.clearance = config.clearance;
  s.scope = config.cost_scope;
  return s;
}

// prepare()'s part for the free UAVs' sensing constants in every lane (sensing_lanes.h).
void NominalCost::prepareSensors() {
  free_sensor_.clear();
  for (const Mover& mover : free_) {
    free_sensor_.push_back({SensorLanes::of(mover.at_origin, mover.quality),
                            SensorLanes::of(mover.at_origin, mover.reference)});
  }
}

void NominalCost::prepare(const PlanningProblem& problem, std::span<const int> free_agents,
                          std::span<const Plan> assumed, TaskPool* pool) {
  const CostSettings& s = problem.settings;
  const int H = horizon_ = s.horizon;
  const int S = substeps_ = s.substeps;
  const int T = H * S;  // samples over the horizon
  const double dt = period_ = s.period;
  const double tau = dt / S;  // s, between samples
  full_trace_ = s.full_trace;
  custody_r2_ = s.custody_radius * s.custody_radius;
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
                 u.turn_rate,
                 u.radius};
  };
  // Height (issue 53): a camera's altitude, limits and reference noise; the occlusion model.
  auto withHeight = [&](Mover mover, const UavState& u) {
    mover.camera = u.camera.has_value();
    mover.climbs = altitudeFree(u);
    mover.volumes = u.occlusion == sensing::OcclusionModel::volumes;
    mover.z = u.z;
    mover.z_min = u.z_min;
    mover.z_max = u.z_max;
    mover.climb_rate = u.climb_rate;
    mover.camera_height = u.kind == world::AgentKind::ground ? sensing::kGroundCameraHeight : u.z;
    mover.reference = sampleQuality({u.reference_alpha, u.quality.r0});
    return mover;
  };
  map_ = problem.map;
  std::vector<char> is_free(n_uavs, 0);
  free_.clear();
  free_index_.assign(free_agents.begin(), free_agents.end());
  climbers_.clear();
  climb_slot_.assign(free_agents.size(), -1);
  for (const int i : free_agents) {
    is_free[i] = 1;
    free_.push_back(withHeight(moverOf(problem.uavs[i]), problem.uavs[i]));
    if (!free_.back().climbs) continue;
    climb_slot_[free_.size() - 1] = static_cast<int>(climbers_.size());
    climbers_.push_back(static_cast<int>(free_.size()) - 1);
  }
  prepareSensors();
  heads_ = false;
  for (const UavState& u : problem.uavs)
    heads_ = heads_ || u.occlusion == sensing::OcclusionModel::volumes;
  height_ = heads_;
  for (const Mover& mover : free_) height_ = height_ || mover.camera;

  // Cost scope "reach": a fixed UAV out of every free UAV's reach plays no part
  // (readsPlanOf), and a track whose nominal positions all lie beyond reach(f) plays no part in
  // the free UAVs' choice (its stage costs do not depend on them).
  const bool reach_scope = s.scope == CostScope::reach;

  // The fixed UAVs' paths and footprints over the horizon.
  n_uavs_ = n_uavs;
  final_position_.assign(static_cast<std::size_t>(kLanes) * n_uavs, Vec2::Zero());
  penalty_uavs_.clear();
  std::vector<int> fixed;
  std::vector<Mover> fixed_movers(n_uavs);
  std::vector<Vec2> fixed_pos(static_cast<std::size_t>(n_uavs) * T);
  std::vector<Vec2> fixed_heading(fixed_pos.size());
  std::vector<double> fixed_height(fixed_pos.size());  // m, a camera agent's altitude
  std::vector<Vec2> actions(H);
  std::vector<double> climbs(H);
  for (int i = 0; i < n_uavs; ++i) {
    if (is_free[i]) {
      penalty_uavs_.push_back(i);
      continue;
    }
    const bool in_scope = informs(problem, free_agents, i);
    if (!in_scope && !mayTouch(problem, free_agents, i)) continue;
    for (int m = 0; m < H; ++m) actions[m] = assumed[i].action(m);
    fixed_movers[i] = withHeight(moverOf(problem.uavs[i]), problem.uavs[i]);
    fly(fixed_movers[i], actions, [&](int t, const Vec2& p, const Vec2& heading) {
      fixed_pos[i * T + t] = p;
      fixed_heading[i * T + t] = heading;
    });
    if (fixed_movers[i].camera) {
      for (int m = 0; m < H; ++m) climbs[m] = assumed[i].climb(m);
      heightsOf(fixed_movers[i], assumed[i].climbs.empty() ? nullptr : climbs.data(),
                &fixed_height[static_cast<std::size_t>(i) * T]);
    }
    if (!in_scope) continue;  // flown for the clearance charge only (prepareClearance)
    penalty_uavs_.push_back(i);
    fixed.push_back(i);
    for (int lane = 0; lane < kLanes; ++lane)
      final_position_[lane * n_uavs + i] = fixed_pos[i * T + T - 1];
  }

  const std::size_t cells = static_cast<std::size_t>(n_targets) * T;
  z_.resize(cells);
  occluded_.assign(cells, 0);
  under_crown_.assign(heads_ ? cells : 0, 0);
  fixed_seen_.assign(cells, 0);
  fixed_R_.assign(cells, Mat2::Identity());
  reach_.assign(cells, 0);
  fixed_path_.resize(static_cast<std::size_t>(n_targets) * (T + 1));  // t = 0..T per track
  start_.assign(n_targets, T);
  cost_start_.assign(n_targets, 0.0);

  // Many fixed UAVs: each sample's nominal positions ask only the fixed UAVs near them
  // (nearby_uavs.h), in the same order, unless one has a camera (its footprint grows with its
  // altitude).
  bool use_nearby = fixed.size() >= kNearbyFrom;
  double footprint_reach = 0.0;  // m, the largest circumradius of a fixed UAV's footprint
  for (const int i : fixed) {
    use_nearby = use_nearby && !fixed_movers[i].camera;
    footprint_reach = std::max(footprint_reach, sensing::circumradius(fixed_movers[i].footprint));
  }
  if (use_nearby) {
    nearby_.resize(T);
    nearby_positions_.assign(n_uavs, Vec2::Zero());
  }
  for (int t = 0; t < T && use_nearby; ++t) {
    for (const int i : fixed)
      nearby_positions_[i] = fixed_pos[static_cast<std::size_t>(i) * T + t];
    use_nearby = nearby_[t].build(fixed, nearby_positions_,
                                  footprint_reach + sensing::kFootprintSlack + kReachSlack);
  }

  // Track j's nominal path, what the fixed UAVs see of it and its covariance recursion until a
  // free UAV may see it: it writes only track j's entries (`near` is the caller's scratch).
  auto prepareTrack = [&](int j, std::vector<int>& near) {
    Vec4 x = problem.targets[j].x;
    // |z_{j,t} − p_{f,0}| ≥ |ξ_j − p_{f,0}| − T·τ·|v_j|: beyond every free UAV's reach, the track
    // is out of scope (its start_ stays T, its cost 0).
    if (reach_scope && !nearFree(problem, free_agents, x.head<2>(), T * tau * x.tail<2>().norm()))
      return;
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
      if (heads_) {  // hidden from all: the head inside a crown's volume
        occluded_[k] = problem.map != nullptr && problem.map->hidesHead(z, sensing::kTargetHeight);
        under_crown_[k] = problem.map != nullptr && problem.map->occludes(z);
      } else {
        occluded_[k] = problem.map != nullptr && problem.map->occludes(z);
      }
      if (!occluded_[k]) {
        Mat2 information = Mat2::Zero();  // Σ R_i⁻¹ over the fixed UAVs that see z
        int seen = 0;
        std::span<const int> asked = fixed;
        if (use_nearby) {
          nearby_[t].near(z, near);
          asked = near;
        }
        for (const int i : asked) {
          const std::size_t im = static_cast<std::size_t>(i) * T + t;
          // The footprint's constant part (shape, sizes, a sector's cos(θ/2)) placed once per UAV.
          const Mover& mover = fixed_movers[i];
          const Vec2& heading = fixed_heading[im];
          if (heads_ && !mover.volumes && under_crown_[k]) continue;  // its model hides it
          Mat2 R;
          if (mover.camera) {  // φ(h) = φ(z)·h/z; R = (ℓ(h)/ℓ(h_ref))·R_ref (class comment)
            const double h = fixed_height[im];
            const PoseLanes pose{lanes::broadcast(fixed_pos[im].x()),
                                 lanes::broadcast(fixed_pos[im].y()),
                                 lanes::broadcast(heading.x()), lanes::broadcast(heading.y())};
            if (!footprintHoldsScaled(mover.at_origin, pose, z, lanes::broadcast(mover.z / h))[0] ||
                !sightClear(mover, fixed_pos[im], h, z)) {
              continue;
            }
            R = sensing::slantNoiseFactor(z, fixed_pos[im], h) *
                sensing::rangeBearingCovariance(z, fixed_pos[im], mover.reference);
          } else {
            if (!mover.at_origin.containsFrom(fixed_pos[im], heading.x(), heading.y(), z) ||
                !sightClear(mover, fixed_pos[im], mover.camera_height, z)) {
              continue;
            }
            R = sensing::rangeBearingCovariance(z, fixed_pos[im],
                                                sampleQuality(problem.uavs[i].quality));
          }
          if (seen++ == 0) fixed_R_[k] = R;
          information += R.llt().solve(Mat2::Identity());
        }
        if (seen > 1) fixed_R_[k] = information.llt().solve(Mat2::Identity());  // R_fix
        fixed_seen_[k] = seen > 0;
        for (int f = 0; f < static_cast<int>(free_.size()); ++f) {
          // |p_f − p_{f,0}| ≤ (t + 1)·v_max·τ, and a footprint holds points within its
          // circumradius.
          // A footprint that may grow (a climb) holds points within its grown circumradius.
          const double radius =
              (t + 1) * free_[f].v_max * tau +
              sensing::circumradius(free_[f].footprint) *
                  footprintGrowth(problem.uavs[free_agents[f]], (t + 1) * tau);
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
  };
  // The tracks in blocks, side by side on the pool when there is one (each block its own
  // scratch); the same entries either way. A few blocks per thread, since the tracks out of scope
  // cost next to nothing and the pool hands a finished thread the blocks not yet started.
  const std::size_t blocks = pool == nullptr || pool->threads() == 1 || n_targets < kPoolTracksFrom
                                 ? 1
                                 : static_cast<std::size_t>(kBlocksPerThread * pool->threads());
  near_scratch_.resize(std::max(near_scratch_.size(), blocks));
  forEachTask(pool, blocks, [&](std::size_t b) {
    const int first = static_cast<int>(b * n_targets / blocks);
    const int last = static_cast<int>((b + 1) * n_targets / blocks);
    for (int j = first; j < last; ++j) prepareTrack(j, near_scratch_[b]);
  });

  reachable_.clear();
  scope_tracks_.clear();
  stage_from_.resize(n_targets);
  for (int j = 0; j < n_targets; ++j) {
    stage_from_[j] = start_[j] / S;
    if (start_[j] < T) reachable_.push_back(j);
    if (!reach_scope || start_[j] < T) scope_tracks_.push_back(j);
  }
  // evaluate() sums J over scope_tracks_ in order. Until the first track with stage terms it adds
  // the same prefixes in every lane and for every candidate: that part of the sum is taken here,
  // once, by the same additions from 0.
  sum_prefix_ = 0.0;
  sum_prefix_tracks_ = 0;
  for (const int j : scope_tracks_) {
    if (stage_from_[j] < H) break;
    sum_prefix_ += cost_start_[j];
    ++sum_prefix_tracks_;
  }
  free_pose_.resize(free_.size() * T);
  free_height_.resize(free_.size() * T);
  height_scratch_.resize(T);
  // A track no free UAV can see ends as the fixed UAVs leave it (evaluate() overwrites the others).
  trace_final_.resize(static_cast<std::size_t>(kLanes) * n_targets);
  in_view_final_.resize(trace_final_.size());
  for (const int j : scope_tracks_) {
    for (int lane = 0; lane < kLanes; ++lane) {
      trace_final_[kLanes * j + lane] =
          penaltyWeight(fixed_path_[static_cast<std::size_t>(j) * (T + 1) + T]);
      in_view_final_[kLanes * j + lane] =
          fixed_seen_[static_cast<std::size_t>(j) * T + T - 1] ? -1 : 0;
    }
  }
  preparePenalty(is_free);
  prepareClearance(problem, free_agents, is_free, fixed_pos);
  uncovered_.assign(n_targets, 0);
  charged_uavs_.assign(n_targets, 0);
  stage_terms_.resize(static_cast<std::size_t>(kLanes) * n_targets * H);
  charged_.assign(penalty_uavs_.size(), 0.0);
  penalty_charges_ = 0;
}

void NominalCost::prepareClearance(const PlanningProblem& problem, std::span<const int> free_agents,
                                   const std::vector<char>& is_free,
                                   const std::vector<Vec2>& fixed_pos) {
  const int T = horizon_ * substeps_;
  clearance_ = problem.settings.clearance;
  free_keepers_.clear();
  fixed_bodies_.clear();
  solids_near_.assign(free_.size(), {});
  if (!problem.settings.keep_clear) return;
  for (int f = 0; f < static_cast<int>(free_.size()); ++f) {
    if (!keepsClear(problem.uavs[free_agents[f]])) continue;
    free_keepers_.push_back(f);
    const Mover& agent = free_[f];
    if (!agent.ground || problem.map == nullptr) continue;  // UAVs fly above trunks and walls
    // The solids it could come within r + c of: |p − p₀| ≤ v_max·H·Δ along the horizon.
    const double reach = agent.v_max * horizon_ * period_ + agent.radius + clearance_;
    for (const world::TreeDef& tree : problem.map->trees()) {
      if (world::solidDistance(tree, agent.position) <= reach) solids_near_[f].push_back(&tree);
    }
  }
  if (free_keepers_.empty()) return;
  for (int i = 0; i < n_uavs_; ++i) {
    // prepare() flew every fixed agent that may touch a free one; no other can be charged.
    if (is_free[i] || !mayTouch(problem, free_agents, i)) continue;
    Teammate mate{problem.uavs[i].radius,
                  problem.uavs[i].kind == world::AgentKind::ground,
                  {problem.uavs[i].position}};
    mate.path.insert(mate.path.end(), fixed_pos.begin() + static_cast<std::ptrdiff_t>(i) * T,
                     fixed_pos.begin() + static_cast<std::ptrdiff_t>(i + 1) * T);
    fixed_bodies_.push_back(std::move(mate));
  }
}

void NominalCost::heightsOf(const Mover& uav, const double* climbs, double* heights) const {
  const int T = horizon_ * substeps_;
  if (!uav.climbs || climbs == nullptr) {
    std::fill(heights, heights + T, uav.z);
    return;
  }
  const double tau = period_ / substeps_;  // s, between samples
  double z = uav.z;
  int t = 0;
  for (int m = 0; m < horizon_; ++m) {
    const double step = std::clamp(climbs[m], -uav.climb_rate, uav.climb_rate) * tau;  // m
    for (int sample = 0; sample < substeps_; ++sample) {
      z = std::clamp(z + step, uav.z_min, uav.z_max);  // h_t = clamp(h_{t−1} + c_m·τ)
      heights[t++] = z;
    }
  }
}

double NominalCost::clearancePenalty(int lane) const {
  constexpr double kForbidden = 1e6;  // m², K₀
  constexpr double kPerMetre = 1e6;   // m²/m, K₁
  const int T = horizon_ * substeps_;
  double penalty = 0.0;
  auto charge = [&](double room, double distance) {
    if (distance < room) penalty += kForbidden + kPerMetre * (room - distance);
  };
  for (std::size_t a = 0; a < free_keepers_.size(); ++a) {
    const int f = free_keepers_[a];
    const Mover& agent = free_[f];
    auto poseOf = [&](int g, int t) {  // free agent g at sample t, its start at t = −1
      if (t < 0) return free_[g].position;
      const PoseLanes& pose = free_pose_[static_cast<std::size_t>(g) * T + t];
      return Vec2(pose.x[lane], pose.y[lane]);
    };
    for (int t = 0; t < T; ++t) {
      const Vec2 from = poseOf(f, t - 1);
      const Vec2 to = poseOf(f, t);
      for (const world::TreeDef* solid : solids_near_[f])  // none for a UAV
        charge(agent.radius + clearance_, world::solidDistance(*solid, from, to));
      for (const Teammate& mate : fixed_bodies_) {
        if (mate.ground != agent.ground) continue;
        charge(agent.radius + mate.radius + clearance_,
               closestApproach(from - mate.path[t], to - mate.path[t + 1]));
      }
      for (std::size_t b = a + 1; b < free_keepers_.size(); ++b) {
        const int g = free_keepers_[b];
        if (free_[g].ground != agent.ground) continue;
        charge(agent.radius + free_[g].radius + clearance_,
               closestApproach(from - poseOf(g, t - 1), to - poseOf(g, t)));
      }
    }
  }
  return penalty;
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
  std::vector<double> climbs;  // the climbing UAVs' rates, in index order (prepare's)
  for (std::size_t i = 0; i < everyone.size(); ++i) {
    if (!altitudeFree(problem.uavs[i])) continue;
    for (int m = 0; m < H; ++m) climbs.push_back(plans[i].climb(m));
  }
  double J = 0.0;
  cost.evaluate(actions, climbs, std::span<double>(&J, 1));
  return J;
}

}  // namespace canopy::agents::planning
