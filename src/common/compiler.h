/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Compiler hints for the hot paths: forced inlining (so that a body written
 * once for a runtime degree is specialised for constant degrees), no
 * inlining (to keep large stack frames out of the callers), loop
 * unrolling, and clones of
 * the hot kernels per instruction set. Each falls back to nothing on
 * compilers without it.
 */
#ifndef PC_COMMON_COMPILER_H
#define PC_COMMON_COMPILER_H

#if defined(__GNUC__)
#define PC_ALWAYS_INLINE inline __attribute__((always_inline))
#define PC_NOINLINE __attribute__((noinline))
#else
#define PC_ALWAYS_INLINE inline
#define PC_NOINLINE
#endif

/* Full unrolling of the short loops of constant trip count (GCC; clang
 * unrolls them unasked). */
#if defined(__GNUC__) && !defined(__clang__)
#define PC_UNROLL _Pragma("GCC unroll 8")
#else
#define PC_UNROLL
#endif

/* The hot numeric kernels are compiled twice, for baseline x86-64 and with
 * FMA (which implies AVX: one 4-wide multiply-add per homogeneous point
 * instead of four SSE2 operations), the loader picking the clone the CPU
 * runs (GNU ifunc, dispatched on the CPU's feature bits). Other targets and
 * compilers get one version, and so does a build with PC_NO_CLONES (CMake
 * PROJCURVE_CLONES=OFF, forced by PROJCURVE_SANITIZE_THREAD: the ifunc
 * resolvers run before ThreadSanitizer's runtime is ready). */
#if defined(__x86_64__) && defined(__ELF__) && defined(__has_attribute) && !defined(PC_NO_CLONES)
#if __has_attribute(target_clones)
#define PC_HOT_CLONES __attribute__((target_clones("fma", "default")))
#endif
#endif
#ifndef PC_HOT_CLONES
#define PC_HOT_CLONES
#endif

#endif /* PC_COMMON_COMPILER_H */
