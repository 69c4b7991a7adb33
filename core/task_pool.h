#pragma once
// A small pool of threads for work split into independent tasks: VectorEnv's simulations
// (python/src/bind_env.cpp) and one run's agents (`canopy run --threads N`, sim/simulation.h).
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

namespace canopy {

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

/// Runs task(i) for i in [0, n): on `pool` when there is one, else in order on this thread.
/// Tasks must write only their own outputs, so that the result does not depend on which runs
/// where.
inline void forEachTask(TaskPool* pool, std::size_t n, const std::function<void(std::size_t)>& task) {
  if (pool == nullptr || pool->threads() == 1 || n < 2) {
    for (std::size_t i = 0; i < n; ++i) task(i);
    return;
  }
  pool->run(n, task);
}

}  // namespace canopy
