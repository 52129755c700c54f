#include "numpy_arrays.h"

#include <limits>

#include "errors.h"

namespace py = pybind11;

namespace somicage {

namespace {

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t k = 0; k < array.ndim(); ++k) text += (k ? ", " : "") + std::to_string(array.shape(k));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

void requireShape(const py::array& array, const std::string& name, int columns, const std::string& expected) {
  const bool widthOk = columns > 0 ? array.ndim() == 2 && array.shape(1) == columns
                                   : array.ndim() == 2 && (array.shape(1) == 2 || array.shape(1) == 3);
  if (!widthOk) throw InputError(name, -1, "has shape " + shapeText(array), "pass an array of shape " + expected);
}

}  // namespace

Eigen::MatrixXd matrixFromArray(const py::handle& object, const std::string& name, int columns) {
  const std::string expected = columns > 0 ? "(n, " + std::to_string(columns) + ")" : "(n, 3) or (n, 2)";
  auto array = py::array_t<double, py::array::forcecast>::ensure(object);
  if (!array) throw InputError(name, -1, "is not an array of numbers", "pass a NumPy array of shape " + expected);
  requireShape(array, name, columns, expected);
  const py::ssize_t rows = array.shape(0), cols = array.shape(1);
  // NumPy strides are in bytes; an array_t<double> view has whole-element strides.
  using Strided = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>;
  const Strided view(
      array.data(), rows, cols,
      Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(array.strides(1) / static_cast<py::ssize_t>(sizeof(double)),
                                                    array.strides(0) / static_cast<py::ssize_t>(sizeof(double))));
  Eigen::MatrixXd matrix = view;
  for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
    if (!matrix.row(r).allFinite())
      throw InputError(name, -1, "row " + std::to_string(r) + " is not finite", "pass finite coordinates");
  }
  return matrix;
}

Eigen::MatrixXi indicesFromArray(const py::handle& object, const std::string& name) {
  const py::array array = py::array::ensure(object);
  if (!array || (array.dtype().kind() != 'i' && array.dtype().kind() != 'u'))
    throw InputError(name, -1, "is not an array of integers", "pass vertex indices as an integer NumPy array");
  if (array.ndim() != 2 || array.shape(1) < 2)
    throw InputError(name, -1, "has shape " + shapeText(array), "pass an array of shape (m, 3) (or (m, 2) in 2D)");
  const auto wide = py::array_t<long long, py::array::forcecast>::ensure(array).unchecked<2>();
  Eigen::MatrixXi indices(wide.shape(0), wide.shape(1));
  for (py::ssize_t r = 0; r < wide.shape(0); ++r) {
    for (py::ssize_t c = 0; c < wide.shape(1); ++c) {
      const long long index = wide(r, c);
      // Out of int's range cannot be a vertex; smaller bad indices are the cage validation's to report.
      if (index < std::numeric_limits<int>::min() || index > std::numeric_limits<int>::max())
        throw InputError(name, -1, "face " + std::to_string(r) + " has index " + std::to_string(index),
                         "indices are 0-based vertex rows");
      indices(r, c) = static_cast<int>(index);
    }
  }
  return indices;
}

}  // namespace somicage
