/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: loops that run in SIMD lanes (the kernel sweep of pair
   cell/sph, the tension sweep of bond cell/tether).
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_SIMD_H
#define CELLMECH_CELL_SIMD_H

// A sweep over contiguous arrays whose square roots and divisions, which the pair and bond loops
// wait on, run side by side in SIMD lanes. lmp and the plugin are built for the x86-64 baseline
// (SSE2, 2 lanes), so on x86-64 Linux such a function is compiled twice, for the baseline and for
// AVX2 (4 lanes), and the loader picks what the CPU has (GCC/Clang function multi-versioning). Its
// file is compiled without errno for sqrt, without trapping math and without contraction into FMA
// (CMakeLists.txt): square roots and divisions are correctly rounded in every lane, so every
// version gives the bits of one element at a time.
#if defined(__x86_64__) && defined(__linux__) && !defined(CELLMECH_NO_SIMD_CLONES) && \
    ((defined(__clang__) && __clang_major__ >= 14) ||                                 \
     (!defined(__clang__) && defined(__GNUC__) && __GNUC__ >= 6))
#define CELLMECH_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define CELLMECH_SIMD_CLONES
#endif

#endif
