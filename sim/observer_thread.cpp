#include "sim/observer_thread.h"

#include <algorithm>
#include <utility>

namespace canopy::sim {

ObserverThread::ObserverThread(std::vector<StepObserver*> observers, std::size_t slots)
    : observers_(std::move(observers)),
      slots_(std::max<std::size_t>(slots, 1)),
      thread_([this] { work(); }) {}

ObserverThread::~ObserverThread() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void ObserverThread::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return (pending_ > 0 && !error_) || stop_; });
    if (stop_) return;
    const StepRecord& record = slots_[first_];
    lock.unlock();
    std::exception_ptr error;
    try {
      for (StepObserver* observer : observers_) observer->onStep(record);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error) {
      // The caller stops at its next onStep() or finish(): no step after the one that failed is
      // observed.
      error_ = error;
      pending_ = 0;
    } else {
      first_ = (first_ + 1) % slots_.size();
      --pending_;
    }
    changed_.notify_all();
  }
}

void ObserverThread::onStep(const StepRecord& record) {
  std::size_t slot = 0;
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return error_ || pending_ < slots_.size(); });
    if (error_) std::rethrow_exception(error_);
    slot = (first_ + pending_) % slots_.size();
  }
  // Not pending, so the thread does not read it: copied without the lock. Vectors keep their
  // capacity, so a slot allocates nothing once it has held the largest step.
  slots_[slot] = record;
  {
    const std::lock_guard lock(mutex_);
    ++pending_;
  }
  changed_.notify_all();
}

void ObserverThread::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return error_ || pending_ == 0; });
  if (error_) std::rethrow_exception(error_);
}

}  // namespace canopy::sim
