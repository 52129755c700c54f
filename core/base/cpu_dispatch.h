// Runtime dispatch of the hot CPU kernels: one portable binary that still runs them with AVX2 and FMA (and AVX-512)
// where the CPU has them (docs/performance.md, "One binary for every CPU of its architecture"). Two mechanisms:
//
// - Per-ISA files (the Somigliana row kernels of the precompute, coordinates/somigliana_row_kernels.h): one source
//   compiled once per instruction set with that set's -march, each copy in its own namespace (base/isa_namespace.h);
//   selectedKernelIsa() below picks one, once, from the CPU's flags. Rules for such a file: it includes only headers
//   whose functions are wrapped in SOMICAGE_ISA_BEGIN/END (no Eigen, no standard-library templates), exports plain
//   functions on plain data, and core.isa_symbols (tools/check_isa_symbols.py) checks that no copy defines a symbol
//   outside its namespace.
// - SOMICAGE_DISPATCH before a function (the per-face kernels, the frame's blocks) compiles it twice -- for the
//   architecture's baseline (x86-64: SSE2) and for x86-64-v3 (AVX2, FMA, BMI) -- and the dynamic loader binds the
//   function to the copy this CPU runs (GCC's target_clones, a glibc ifunc), once, at start-up. Such a function is
//   a plain free function holding the whole hot work of a call (its callees are inlined into each copy: `flatten`;
//   a call out of it runs baseline code), with no OpenMP region inside. Eigen's explicit intrinsics stay SSE2 in
//   the copy (its macros are the baseline's); the compiler's vectoriser and FMA contraction change. The row kernels
//   ran 1.7x slower as such a copy than compiled per ISA (docs/performance.md).
// Elsewhere (SOMICAGE_NATIVE builds, which target the build machine's CPU; clang; other architectures: arm64's baseline
// already has NEON) SOMICAGE_DISPATCH keeps only `flatten` and the row kernels have their baseline copy only.
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

// The instruction sets of the per-ISA kernels (docs/performance.md): the Somigliana row kernels are compiled once
// for each (coordinates/somigliana_row_kernels.h), and one copy is chosen at run time.
enum class KernelIsa { baseline, x86_64_v3, x86_64_v4 };

// Whether this build has a copy of the per-ISA kernels for `isa` and this CPU runs it (the baseline: always).
bool kernelIsaAvailable(KernelIsa isa);

// The copy the per-ISA kernels run with here: the highest available one (chosen once, from the CPU's flags).
KernelIsa selectedKernelIsa();

// "baseline", "x86-64-v3" or "x86-64-v4".
const char* kernelIsaName(KernelIsa isa);

// The instruction set the dispatched kernels run with here: "x86-64-v3" (the AVX2/FMA copies), "x86-64-v4" (the
// row kernels' AVX-512 copy), "baseline" (the architecture's baseline copy, or a build without dispatch) or
// "native" (the whole build targets AVX2 and FMA or newer: SOMICAGE_NATIVE). The row kernels' selectedKernelIsa().
const char* dispatchedKernelTarget();

}  // namespace somicage
