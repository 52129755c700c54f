// The namespace of one instruction set's copy of the hot kernels (docs/performance.md, "One binary for every CPU").
// The kernel headers (simd packs, the closed form, the rows) wrap their functions in SOMICAGE_ISA_BEGIN/END. A file
// compiled once per instruction set (coordinates/somigliana_row_kernels_isa.cpp) is given -DSOMICAGE_ISA=isa_NAME,
// which puts every inline function it instantiates in an inline namespace of that name: the AVX2 copy of an inline
// function is then a different symbol from the baseline one, so the linker cannot keep it for the baseline code
// (an ODR violation that would crash on CPUs without AVX2). Everywhere else the macros are empty. Plain data types
// that cross between the copies (PortableTriangleFrame, PortableFace) stay outside, one type for all.
#pragma once

#ifdef SOMICAGE_ISA
#define SOMICAGE_ISA_BEGIN inline namespace SOMICAGE_ISA {
#define SOMICAGE_ISA_END }
#else
#define SOMICAGE_ISA_BEGIN
#define SOMICAGE_ISA_END
#endif
