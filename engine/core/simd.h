// Hot loops compiled for AVX2 and the baseline, picked at load time (ifunc). Both clones do the
// same IEEE operations in the same order (no FMA contraction), so results are bit-identical.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(OB_NO_SIMD_CLONES)
#define OB_VECTOR_KERNEL __attribute__((target_clones("avx2", "default")))
#elif defined(__GNUC__)
#define OB_VECTOR_KERNEL __attribute__((noinline))  // keeps the __restrict of its parameters
#else
#define OB_VECTOR_KERNEL
#endif
