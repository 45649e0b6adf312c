// Loops over arrays that the compiler turns into vector code: marked functions are also
// compiled for AVX-512 (eight doubles a vector) and AVX2 (four), and the processor's best is
// chosen when the program starts. Without fused multiply-adds (-ffp-contract=off: AVX-512 has
// them): the same operations, so the same results, as the baseline build.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__linux__)
#define NCURVE_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define NCURVE_VECTOR_CLONES
#endif
