#pragma once
// The per-step work of canopy.TrackingEnv and canopy.VectorEnv in C++ (issue 30): an agent's
// observation vector and reward from a StepRecord, and a pool of threads that steps many
// simulations at once. Nothing here touches a Python object, so it all runs without the GIL.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "sim/step_record.h"
#include "spec/scenario_spec.h"

namespace canopy::python {

/// The observation layout of python/canopy/env.py (its docstring is the reference), with finite
/// bounds: every entry is clipped into [low, high] so that it lies inside its space.
struct EnvLayout {
  static constexpr int kTrack = 7;  // px, py, vx, vy, P_xx, P_yy, valid
  static constexpr int kTree = 4;   // dx, dy, r, valid

  int max_tracks = 8;
  int max_trees = 8;
  double map_radius = 30.0;  // m
  bool full_trace = false;   // reward: tr(P) over the whole 4 × 4 block, else the position block
  float position = 0.0F;     // m, |x| and |y| of positions are clipped to this
  float speed = 0.0F;        // m/s, |vx| and |vy| of velocities are clipped to this
  std::vector<float> low, high;

  int size() const { return 3 + kTrack * max_tracks + kTree * max_trees; }
};

/// The layout and its bounds for `spec`: positions within the AOI and every UAV start grown by
/// the distance the fastest UAV flies in the episode; yaw in [−π, π]; track velocities within
/// max(50, 5 · the fastest v_max) m/s; variances in [0, 10⁴] m²; tree offsets and radii within
/// map_radius. Throws std::invalid_argument for negative sizes or a non-positive map_radius.
EnvLayout makeLayout(const spec::ScenarioSpec& spec, int max_tracks, int max_trees,
                     double map_radius, bool full_trace);

/// Agent `agent`'s observation at `record` into out[0 .. layout.size()).
void observe(const sim::StepRecord& record, int agent, const EnvLayout& layout, float* out);

/// Minus the NBO stage cost of the agent's fused belief: −Σ_j tr(P_j) (position block, or all).
double stageReward(const sim::StepRecord& record, int agent, bool full_trace);

/// A fixed set of worker threads that runs `task(i)` for i in [0, n) and waits for all of them;
/// the calling thread works too. Participant k of T (the caller is 0) first runs the tasks of
/// its block [k·n/T, (k+1)·n/T), so that task i keeps running on the same thread from call to
/// call (its data stays in that core's caches and that thread's malloc arena, and the threads'
/// output rows share one cache line), then takes any task not yet started (a late or
/// descheduled thread's). Waiting threads spin for up to kSpin, yielding the CPU at each turn,
/// before they sleep on a condition variable: a VectorEnv step is a few hundred µs of work, and
/// a futex sleep and wake-up on every step cost the two threads more than they gained (perf: 17 %
/// of the time in the kernel's scheduler). The first exception a task throws is rethrown by run().
class TaskPool {
 public:
  explicit TaskPool(int threads);  // threads ≥ 1 in all, the caller included
  ~TaskPool();
  TaskPool(const TaskPool&) = delete;
  TaskPool& operator=(const TaskPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }
  void run(std::size_t n, const std::function<void(std::size_t)>& task);

  static constexpr std::chrono::microseconds kSpin{200};

 private:
  void work(int id);
  void drain(int id, const std::function<void(std::size_t)>& task, std::size_t n);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_, finished_;
  std::atomic<std::uint64_t> generation_{0};
  bool stop_ = false;
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t n_ = 0;
  std::vector<std::atomic<bool>> claimed_;  // per task of this call: started by someone
  std::atomic<std::size_t> done_{0};
  std::atomic<int> busy_{0};  // workers inside drain()
  std::exception_ptr error_;
};

}  // namespace canopy::python
