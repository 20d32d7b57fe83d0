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

// A reduction allowed to reassociate into vector lanes (a sum of diagnostics, never a state's
// arithmetic): the order is fixed by the code each clone was built with, so a run's bits do not
// depend on the workers.
#if defined(__GNUC__) && !defined(__clang__)
#define OB_RELAXED_SUM __attribute__((optimize("associative-math", "no-signed-zeros", "no-trapping-math")))
#else
#define OB_RELAXED_SUM
#endif
