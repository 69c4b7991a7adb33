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
    if (claimed_[i].exchange(true, std::memory_order_acq_rel)) return;
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
  for (std::size_t i = 0; i < n; ++i) attempt(i);  // then whatever nobody has started
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
    std::unique_lock lock(mutex_);
    start_.wait(lock, [&] { return stop_ || generation_.load() != seen; });
    if (stop_) return;
    seen = generation_.load();
    const std::function<void(std::size_t)>* task = task_;
    const std::size_t n = n_;
    if (!task) continue;  // that call has already finished
    ++busy_;
    lock.unlock();
    drain(id, *task, n);
    lock.lock();
    --busy_;
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
  spinFor([&] { return done_.load(std::memory_order_acquire) == n; });
  std::exception_ptr error;
  {
    std::unique_lock lock(mutex_);
    finished_.wait(lock, [&] { return done_.load(std::memory_order_acquire) == n && busy_ == 0; });
    task_ = nullptr;
    error = error_;
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace canopy
