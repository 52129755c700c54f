// NumPy arrays into the engine's Eigen matrices, with the checks of an input boundary: a wrong dtype or shape, no
// rows, a non-finite value or an index outside the cage throws somicage::InputError naming the argument, like the
// OBJ loader names the file.
//
// Any dtype that holds real numbers is taken (float16 ... float64 and longer, int8 ... uint64), in any memory order
// and with any strides (views, slices): NumPy converts it to double (or a 64-bit integer for indices) into an array
// that this code owns and keeps alive while it copies from it, once, into the column-major Eigen::MatrixXd the
// engine's API owns (core/deform/deformer.h). That is #P x d doubles at bind time (under 1% of the precompute's
// coordinate matrix, #P x 10 #V doubles) and #V x d per frame (a cage: a few kB).
#pragma once

#include <pybind11/numpy.h>

#include <Eigen/Core>
#include <string>

namespace somicage {

// An argument the binding converts itself (below): anything np.asarray takes. Shown as numpy.typing.ArrayLike in
// help() and signatures instead of pybind11's "handle".
struct ArrayArgument {
  pybind11::object object;
};

// A (rows, columns) array of real numbers, rows >= 1. columns: the required width, or 0 for 2 or 3 (a cage's
// dimension).
Eigen::MatrixXd matrixFromArray(const pybind11::handle& array, const std::string& name, int columns);

// A (rows, columns) array of integers, rows >= 1, each in [0, numVertices): vertex indices.
Eigen::MatrixXi indicesFromArray(const pybind11::handle& array, const std::string& name, int columns, int numVertices);

}  // namespace somicage

namespace pybind11::detail {
template <>
struct type_caster<somicage::ArrayArgument> {
  PYBIND11_TYPE_CASTER(somicage::ArrayArgument, const_name("numpy.typing.ArrayLike"));
  bool load(handle source, bool) {
    value.object = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const somicage::ArrayArgument& argument, return_value_policy, handle) {
    return argument.object.inc_ref();
  }
};
}  // namespace pybind11::detail
