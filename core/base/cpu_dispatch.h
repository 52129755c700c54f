// Runtime dispatch of the hot CPU kernels: one portable binary that still runs them with AVX2 and FMA where the CPU
// has them (docs/performance.md). SOMICAGE_DISPATCH before a function compiles it twice -- for the architecture's
// baseline (x86-64: SSE2) and for x86-64-v3 (AVX2, FMA, BMI) -- and the dynamic loader binds the function to the
// copy this CPU runs (GCC's target_clones, a glibc ifunc), once, at start-up.
//
// Rules for a dispatched function (how to add one: docs/performance.md):
// - A plain free function (not a template or member, so that the mechanism could move to clang or Highway later):
//   wrap a template kernel in one such function per instantiation. Only its definition carries the macro.
// - It should hold the whole hot work of one call (a point's row, a block of rows): its callees are inlined into
//   each copy (`flatten`), so Eigen and the inline kernels are compiled for each target; a call out of it runs the
//   baseline code. Eigen chooses its own packet math by the baseline's macros (SSE2), so its explicit intrinsics do
//   not change; the compiler's vectoriser and FMA contraction do.
// - No OpenMP region inside: its outlined body would not be cloned. Call the function from inside the loop.
// Elsewhere (SOMICAGE_NATIVE builds, which target the build machine's CPU; clang; other architectures: arm64's baseline
// already has NEON) the macro keeps only `flatten`, so every build inlines the kernels the same way.
#pragma once

#include <cstdlib>  // glibc's <features.h>, for __GLIBC__

// GCC only: clang 14 (Debian 12's; the fuzz builds) refuses target_clones with flatten, needs it on every
// declaration, and in a two-file test called the clones with garbage arguments. Clang builds run the baseline.
// A build whose own target has AVX2 and FMA (SOMICAGE_NATIVE on such a CPU) has nothing to dispatch. Nor does an
// unoptimised (Debug) build: without inlining, `flatten` leaves the SIMD packs' helpers out of line, compiled for the
// baseline, and the AVX2 copy calls them with its own convention for 32-byte vectors (returned in a register, not in
// memory), so they ran on shifted arguments and crashed.
#if defined(__x86_64__) && !(defined(__AVX2__) && defined(__FMA__)) && defined(__linux__) && defined(__GLIBC__) && \
    !defined(__clang__) && __GNUC__ >= 11 && defined(__OPTIMIZE__)
#define SOMICAGE_DISPATCH_CLONES 1
#define SOMICAGE_DISPATCH __attribute__((target_clones("default", "arch=x86-64-v3"), flatten))
#else
#define SOMICAGE_DISPATCH_CLONES 0
#define SOMICAGE_DISPATCH __attribute__((flatten))
#endif

namespace somicage {

// The instruction set the dispatched kernels run with here: "x86-64-v3" (the AVX2/FMA copy), "baseline" (the
// architecture's baseline copy, or a build without dispatch) or "native" (the whole build targets AVX2 and FMA or
// newer: SOMICAGE_NATIVE). Observed, not predicted: it asks a dispatched function whether it fused a multiply-add.
const char* dispatchedKernelTarget();

}  // namespace somicage
