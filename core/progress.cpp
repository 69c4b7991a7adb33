#include "core/progress.h"

#include <atomic>

namespace canopy {
namespace {

std::atomic<ProgressHook> g_hook{nullptr};

}  // namespace

ProgressHook setProgressHook(ProgressHook hook) {
  return g_hook.exchange(hook);
}

void reportProgress(const char* stage, double done, double total) {
  if (const ProgressHook hook = g_hook.load(std::memory_order_relaxed)) hook(stage, done, total);
}

}  // namespace canopy
