// Dual numbers (dual_number.h) as an Eigen scalar, so that Eigen-based closed forms (mean_value_coordinates.cpp)
// can be templated on the scalar and differentiated; products with double matrices give duals.
#pragma once

#include <Eigen/Core>

#include "base/dual_number.h"

namespace Eigen {

template <int N>
struct NumTraits<somicage::dual::Dual<N>> : GenericNumTraits<double> {
  using Real = somicage::dual::Dual<N>;
  using NonInteger = Real;
  using Nested = Real;
  using Literal = Real;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = N + 1,
    AddCost = N + 1,
    MulCost = 2 * N + 1
  };
};

template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<somicage::dual::Dual<N>, double, BinaryOp> {
  using ReturnType = somicage::dual::Dual<N>;
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<double, somicage::dual::Dual<N>, BinaryOp> {
  using ReturnType = somicage::dual::Dual<N>;
};

}  // namespace Eigen
