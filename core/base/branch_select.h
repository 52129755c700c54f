// A branch that the SIMD packs (simd_pack.h) can take lane by lane: branchSelect(condition, then, else) runs one of
// two lambdas for a plain bool (double and dual-number kernels: nothing changes for them), and for a pack's mask
// runs both only where its lanes disagree and blends the results. The closed-form kernels branch on the point's
// position (triangle_integrals_kernel.h); this keeps one kernel for scalars, duals, CUDA and packs.
#pragma once

#include "base/isa_namespace.h"
#include "base/portable.h"

namespace somicage {
SOMICAGE_ISA_BEGIN

// Two numbers a branch produces; a pack's branchSelect blends both members.
template <typename Scalar>
struct ScalarPair {
  Scalar first, second;
};

template <typename Then, typename Else>
SOMICAGE_HD inline auto branchSelect(bool condition, Then then, Else otherwise) -> decltype(then()) {
  return condition ? then() : otherwise();
}

SOMICAGE_ISA_END
}  // namespace somicage
