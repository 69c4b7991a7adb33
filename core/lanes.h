#pragma once
// Four doubles side by side, for the planner's hot loops: each lane performs a scalar formula's
// IEEE operations in the same order, so a lane's bits are those of the scalar code. With AVX one
// instruction advances all four lanes; on the x86-64 baseline g++ lowers each operation to two
// SSE2 instructions with the same rounding. No FMA is ever enabled (it would round differently).
//
// The helpers take and return vectors, so they are always inlined: no call ever passes a vector,
// and the compilers' note that such a call's ABI would depend on AVX (-Wpsabi) does not apply.
#include <cstdint>
#include <cstring>

#if defined(__clang__)
#pragma clang diagnostic ignored "-Wpsabi"
#elif defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace canopy::lanes {

using V4 = double __attribute__((vector_size(32)));        // four doubles
using M4 = std::int64_t __attribute__((vector_size(32)));  // per lane: −1 true, 0 false
using I4 = std::int32_t __attribute__((vector_size(16)));  // four 32-bit integers

[[gnu::always_inline]] inline V4 load(const double* p) {
  V4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline void store(double* p, const V4& v) {
  std::memcpy(p, &v, sizeof v);
}
[[gnu::always_inline]] inline V4 broadcast(double x) {
  return V4{} + x;
}
[[gnu::always_inline]] inline bool allLanes(const M4& m) {
  return (m[0] & m[1] & m[2] & m[3]) != 0;
}
[[gnu::always_inline]] inline bool anyLane(const M4& m) {
  return (m[0] | m[1] | m[2] | m[3]) != 0;
}
/// |x| per lane: the sign bit cleared, as std::abs does.
[[gnu::always_inline]] inline V4 abs(const V4& x) {
  return (V4)((M4)x & (M4{} + INT64_MAX));
}
/// √x per lane (g++ makes one vector square root of it where errno is not asked for: the cost's
/// sources are compiled with -fno-math-errno).
[[gnu::always_inline]] inline V4 sqrt(const V4& x) {
  return V4{__builtin_sqrt(x[0]), __builtin_sqrt(x[1]), __builtin_sqrt(x[2]), __builtin_sqrt(x[3])};
}
}  // namespace canopy::lanes
