#include "core/task_pool.h"

namespace canopy {

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

}  // namespace canopy
