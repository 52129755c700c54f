// NumPy arrays into the engine's Eigen matrices, with the checks of an input boundary: a wrong shape, a non-finite
// value or a float index throws somicage::InputError naming the argument, like the OBJ loader names the file.
//
// The copy: the engine's API takes column-major Eigen::MatrixXd that it owns (core/deformer.h), so each array is
// copied once, straight from NumPy's buffer with its strides (C or Fortran order, any view), into that storage.
// That is #P x d doubles at bind time (under 1% of the precompute's coordinate matrix, #P x 10 #V doubles) and
// #V x d per frame (a cage: a few kB). Arrays of another dtype are converted by NumPy first.
#pragma once

#include <pybind11/numpy.h>

#include <Eigen/Core>
#include <string>

namespace somicage {

// A (rows, columns) float array. columns: the required width, or 0 for 2 or 3 (a cage's dimension).
Eigen::MatrixXd matrixFromArray(const pybind11::handle& array, const std::string& name, int columns);

// A (rows, k) integer array (k >= 2) of vertex indices; range is checked by the cage validation.
Eigen::MatrixXi indicesFromArray(const pybind11::handle& array, const std::string& name);

}  // namespace somicage
