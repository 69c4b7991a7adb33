#include "python/src/env_core.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace canopy::python {

EnvLayout makeLayout(const spec::ScenarioSpec& spec, int max_tracks, int max_trees,
                     double map_radius, bool full_trace) {
  if (max_tracks < 0 || max_trees < 0)
    throw std::invalid_argument("expected max_tracks ≥ 0 and max_trees ≥ 0");
  if (!(map_radius > 0.0) || !std::isfinite(map_radius))
    throw std::invalid_argument("map_radius: expected a finite length > 0 (m)");
  EnvLayout layout;
  layout.max_tracks = max_tracks;
  layout.max_trees = max_trees;
  layout.map_radius = map_radius;
  layout.full_trace = full_trace;

  double reach = std::max({std::abs(spec.aoi.lo.x()), std::abs(spec.aoi.lo.y()),
                           std::abs(spec.aoi.hi.x()), std::abs(spec.aoi.hi.y())});
  double v_max = 0.0;
  for (const spec::UavSpec& u : spec.uavs) {
    reach = std::max({reach, std::abs(u.body.start.x()), std::abs(u.body.start.y())});
    v_max = std::max(v_max, u.body.v_max);
  }
  const auto position = static_cast<float>(std::ceil(reach + v_max * spec.duration));
  const auto speed = static_cast<float>(std::max(50.0, 5.0 * v_max));
  layout.position = position;
  layout.speed = speed;
  const float variance = 1.0e4F;  // m²
  const auto pi = static_cast<float>(std::numbers::pi);
  const auto radius = static_cast<float>(map_radius);

  auto add = [&](float lo, float hi) {
    layout.low.push_back(lo);
    layout.high.push_back(hi);
  };
  add(-position, position);
  add(-position, position);
  add(-pi, pi);
  for (int j = 0; j < max_tracks; ++j) {
    add(-position, position);
    add(-position, position);
    add(-speed, speed);
    add(-speed, speed);
    add(0.0F, variance);
    add(0.0F, variance);
    add(0.0F, 1.0F);
  }
  for (int j = 0; j < max_trees; ++j) {
    add(-radius, radius);
    add(-radius, radius);
    add(0.0F, radius);
    add(0.0F, 1.0F);
  }
  return layout;
}

void observe(const sim::StepRecord& record, int agent, const EnvLayout& layout, float* out) {
  const auto size = static_cast<std::size_t>(layout.size());
  std::fill(out, out + size, 0.0F);
  const auto i = static_cast<std::size_t>(agent);
  const sim::UavRecord& uav = record.uavs[i];
  out[0] = static_cast<float>(uav.position.x());
  out[1] = static_cast<float>(uav.position.y());
  out[2] = static_cast<float>(uav.yaw);

  const auto& tracks = record.beliefs[i].tracks;
  float* row = out + 3;
  const std::size_t m = std::min(tracks.size(), static_cast<std::size_t>(layout.max_tracks));
  for (std::size_t j = 0; j < m; ++j, row += EnvLayout::kTrack) {
    const auto& b = tracks[j].belief;
    for (int a = 0; a < 4; ++a) row[a] = static_cast<float>(b.x(a));
    row[4] = static_cast<float>(b.P(0, 0));
    row[5] = static_cast<float>(b.P(1, 1));
    row[6] = 1.0F;
  }

  // The discs nearest to the agent within map_radius, nearest first (ties in map order).
  const auto& trees = record.beliefs[i].trees;
  struct Near {
    double distance;
    std::size_t index;
  };
  std::vector<Near> near;
  near.reserve(trees.size());
  for (std::size_t t = 0; t < trees.size(); ++t) {
    const double dx = trees[t].belief.x(0) - uav.position.x();
    const double dy = trees[t].belief.x(1) - uav.position.y();
    const double d = std::hypot(dx, dy);
    if (d <= layout.map_radius) near.push_back({d, t});
  }
  std::stable_sort(near.begin(), near.end(),
                   [](const Near& a, const Near& b) { return a.distance < b.distance; });
  row = out + 3 + EnvLayout::kTrack * layout.max_tracks;
  const std::size_t k = std::min(near.size(), static_cast<std::size_t>(layout.max_trees));
  for (std::size_t j = 0; j < k; ++j, row += EnvLayout::kTree) {
    const auto& x = trees[near[j].index].belief.x;
    row[0] = static_cast<float>(x(0) - uav.position.x());
    row[1] = static_cast<float>(x(1) - uav.position.y());
    row[2] = static_cast<float>(x(2));
    row[3] = 1.0F;
  }
  for (std::size_t e = 0; e < size; ++e) out[e] = std::clamp(out[e], layout.low[e], layout.high[e]);
}

double stageReward(const sim::StepRecord& record, int agent, bool full_trace) {
  double cost = 0.0;
  const int n = full_trace ? 4 : 2;
  for (const auto& track : record.beliefs[static_cast<std::size_t>(agent)].tracks) {
    double trace = 0.0;
    for (int a = 0; a < n; ++a) trace += track.belief.P(a, a);
    cost += trace;
  }
  return -cost;
}

TaskPool::TaskPool(int threads) {
  for (int t = 1; t < threads; ++t) workers_.emplace_back([this, t] { work(t); });
}

TaskPool::~TaskPool() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void TaskPool::drain(int id, const std::function<void(std::size_t)>& task, std::size_t n) {
  const auto parts = static_cast<std::size_t>(threads());
  const auto k = static_cast<std::size_t>(id);
  auto attempt = [&](std::size_t i) {
    // A load first: the flags share a cache line, which a failed exchange would take from the
    // other core every time.
    if (claimed_[i].load(std::memory_order_relaxed) ||
        claimed_[i].exchange(true, std::memory_order_acq_rel))
      return;
    try {
      task(i);
    } catch (...) {
      const std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
    done_.fetch_add(1, std::memory_order_acq_rel);
  };
  // Mine: a contiguous block, so that the threads' outputs (rows of the batch arrays) meet at
  // one cache line only.
  for (std::size_t i = k * n / parts; i < (k + 1) * n / parts; ++i) attempt(i);
  // Then whatever nobody has started, from the end: the other blocks' last tasks, so that the
  // tasks a slower thread is about to run stay on it.
  for (std::size_t i = n; i-- > 0;) attempt(i);
}

namespace {

/// Spins until `ready()` or kSpin has passed; returns ready().
template <typename Ready>
bool spinFor(Ready ready) {
  const auto until = std::chrono::steady_clock::now() + TaskPool::kSpin;
  for (int k = 0;; ++k) {
    if (ready()) return true;
    if (k % 16 == 15 && std::chrono::steady_clock::now() > until) return ready();
    std::this_thread::yield();  // on a busy machine, lets the thread that has work run
  }
}

}  // namespace

void TaskPool::work(int id) {
  std::uint64_t seen = 0;
  for (;;) {
    spinFor([&] { return generation_.load(std::memory_order_acquire) != seen; });
    const std::function<void(std::size_t)>* task = nullptr;
    std::size_t n = 0;
    {
      std::unique_lock lock(mutex_);
      start_.wait(lock, [&] { return stop_ || generation_.load() != seen; });
      if (stop_) return;
      seen = generation_.load();
      task = task_;
      n = n_;
      if (!task) continue;  // that call has already finished
      // Counted under the lock: run() clears task_ under it, once busy_ is 0.
      busy_.fetch_add(1, std::memory_order_relaxed);
    }
    drain(id, *task, n);
    // Out without the lock, so that run() can see it while spinning; then the lock taken and
    // dropped before the notification, so that a run() between its check and its sleep is woken.
    busy_.fetch_sub(1, std::memory_order_acq_rel);
    { const std::lock_guard lock(mutex_); }
    finished_.notify_all();
  }
}

void TaskPool::run(std::size_t n, const std::function<void(std::size_t)>& task) {
  {
    const std::lock_guard lock(mutex_);
    if (claimed_.size() < n) claimed_ = std::vector<std::atomic<bool>>(n);
    for (std::size_t i = 0; i < n; ++i) claimed_[i].store(false, std::memory_order_relaxed);
    task_ = &task;
    n_ = n;
    done_.store(0, std::memory_order_relaxed);
    error_ = nullptr;
    generation_.fetch_add(1, std::memory_order_acq_rel);
  }
  if (!workers_.empty() && n > 1) start_.notify_all();
  drain(0, task, n);
  // Every task done and every worker out of drain(): spun for first, as a worker leaves drain()
  // a few hundred ns after its last task, and sleeping on finished_ then costs a futex wake-up.
  auto finished = [&] {
    return done_.load(std::memory_order_acquire) == n && busy_.load(std::memory_order_acquire) == 0;
  };
  spinFor(finished);
  std::exception_ptr error;
  {
    std::unique_lock lock(mutex_);
    finished_.wait(lock, finished);
    task_ = nullptr;
    error = error_;
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace canopy::python
