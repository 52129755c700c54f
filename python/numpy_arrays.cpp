#include "numpy_arrays.h"

#include <cmath>
#include <type_traits>

#include "base/errors.h"

namespace py = pybind11;

namespace somicage {

namespace {

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t k = 0; k < array.ndim(); ++k) text += (k ? ", " : "") + std::to_string(array.shape(k));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

// The argument as a NumPy array whose dtype is one of `kinds` (NumPy's dtype.kind letters), or InputError.
py::array arrayOf(const py::handle& object, const std::string& name, const std::string& kinds, const std::string& what,
                  const std::string& hint) {
  py::array array = py::array::ensure(object);  // np.asarray; null (error cleared) when NumPy cannot
  if (!array) throw InputError(name, -1, "is not " + what, hint);
  const char kind = array.dtype().kind();
  if (kinds.find(kind) == std::string::npos)
    throw InputError(name, -1, "is not " + what + " (dtype " + py::str(array.dtype()).cast<std::string>() + ")", hint);
  return array;
}

void requireShape(const py::array& array, const std::string& name, int columns, const std::string& expected,
                  const std::string& rowsHint) {
  const bool widthOk = columns > 0 ? array.ndim() == 2 && array.shape(1) == columns
                                   : array.ndim() == 2 && (array.shape(1) == 2 || array.shape(1) == 3);
  if (!widthOk) throw InputError(name, -1, "has shape " + shapeText(array), "pass an array of shape " + expected);
  if (array.shape(0) == 0) throw InputError(name, -1, "has shape " + shapeText(array) + ": no rows", rowsHint);
}

// The indices of a (rows, columns) integer array through a 64-bit copy of the same signedness (every integer dtype
// fits one of the two exactly); converted is kept alive while it is read.
template <typename Wide>
Eigen::MatrixXi narrowIndices(const py::array& array, const std::string& name, int numVertices) {
  const auto converted = py::array_t<Wide, py::array::forcecast>::ensure(array);
  if (!converted) throw py::error_already_set();
  const auto wide = converted.template unchecked<2>();
  Eigen::MatrixXi indices(wide.shape(0), wide.shape(1));
  for (py::ssize_t r = 0; r < wide.shape(0); ++r) {
    for (py::ssize_t c = 0; c < wide.shape(1); ++c) {
      const Wide index = wide(r, c);
      const bool negative = std::is_signed_v<Wide> && index < 0;
      if (negative || static_cast<unsigned long long>(index) >= static_cast<unsigned long long>(numVertices))
        throw InputError(name, -1, "face " + std::to_string(r) + " has index " + std::to_string(index),
                         "indices are 0-based vertex rows, in [0, " + std::to_string(numVertices) + ")");
      indices(r, c) = static_cast<int>(index);
    }
  }
  return indices;
}

}  // namespace

Eigen::MatrixXd matrixFromArray(const py::handle& object, const std::string& name, int columns) {
  const std::string expected = columns > 0 ? "(n, " + std::to_string(columns) + ")" : "(n, 3) or (n, 2)";
  const py::array array = arrayOf(object, name, "fiu", "an array of real numbers",
                                  "pass a NumPy array of shape " + expected + " (float or integer)");
  requireShape(array, name, columns, expected, "pass at least one row");
  const auto doubles = py::array_t<double, py::array::forcecast>::ensure(array);
  if (!doubles) throw py::error_already_set();
  const auto view = doubles.unchecked<2>();  // any strides; doubles owns the converted copy while it is read
  Eigen::MatrixXd matrix(view.shape(0), view.shape(1));
  for (py::ssize_t r = 0; r < view.shape(0); ++r) {
    for (py::ssize_t c = 0; c < view.shape(1); ++c) {
      if (!std::isfinite(view(r, c)))
        throw InputError(name, -1, "row " + std::to_string(r) + " is not finite", "pass finite coordinates");
      matrix(r, c) = view(r, c);
    }
  }
  return matrix;
}

Eigen::MatrixXi indicesFromArray(const py::handle& object, const std::string& name, int columns, int numVertices) {
  const std::string expected = "(m, " + std::to_string(columns) + ")";
  const py::array array = arrayOf(object, name, "iu", "an array of integers",
                                  "pass vertex indices as an integer NumPy array of shape " + expected);
  requireShape(array, name, columns, expected,
               columns == 3 ? "a 3D cage needs its triangles" : "pass edges, or faces=None for a vertex loop");
  return array.dtype().kind() == 'u' ? narrowIndices<unsigned long long>(array, name, numVertices)
                                     : narrowIndices<long long>(array, name, numVertices);
}

}  // namespace somicage
