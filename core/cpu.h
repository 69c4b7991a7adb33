#pragma once
// Which compiled copy of a hot kernel runs. The kernels keep one body compiled twice: for the
// x86-64 baseline (SSE2) and with target("avx2"). Both copies perform the same IEEE operations in
// the same order (no FMA is enabled), so the choice changes the instruction count, never a bit of
// the result; tests run both where the CPU has AVX2.
namespace canopy {

enum class InstructionSet { baseline, avx2 };

/// avx2 where this CPU has it, else baseline; asked once.
inline InstructionSet instructionSet() {
#if defined(__x86_64__)
  static const InstructionSet set = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") ? InstructionSet::avx2 : InstructionSet::baseline;
  }();
  return set;
#else
  return InstructionSet::baseline;
#endif
}

}  // namespace canopy
