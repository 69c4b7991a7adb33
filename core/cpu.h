#pragma once
// What the CPU running canopy offers beyond the x86-64 baseline (SSE2), asked once. The hot
// kernels keep one body compiled twice (baseline, and with target("avx") / target("avx2")) and
// pick a copy with these; both copies perform the same IEEE operations in the same order (no FMA
// is enabled), so the choice changes the instruction count, never a bit of the result.
namespace canopy {

#if defined(__x86_64__)
inline bool cpuHasAvx() {
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx") != 0;
  }();
  return has;
}
inline bool cpuHasAvx2() {
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return has;
}
#else
inline bool cpuHasAvx() { return false; }
inline bool cpuHasAvx2() { return false; }
#endif

}  // namespace canopy
