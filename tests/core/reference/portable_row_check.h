// Checks one point's row of 3D Somigliana terms, as the CUDA precompute writes it
// (core/coordinates/somigliana_row_portable.h in the layout of core/deform/coordinate_layout.h: 10 terms per cage
// vertex, D, omega, B (xx, yy, zz, xy, xz, yz), then 4 per face, S, q = Q n), against the
// reference quadrature (somigliana_reference.h): the row is turned back into T_i(x) and K_j(x) n_j with Eqs. 3-4's
// own scalars, T_i = (a - 2b)(D_i I + A_i) + 6b B_i (A_i w = omega_i x w) and K_j n_j = (a - b) S_j n_j + b q_j,
// and compared at two Poisson ratios, so that a term written to the wrong column, with the wrong sign or the wrong
// factor shows up however the kernel computes it. The 18 affine terms after them (the affine variant's tail,
// core/geometry/affine_terms.h) are turned back into sum_j K_j sigma n_j for each of the six symmetric basis stresses
// sigma (xx, yy, zz, xy, xz, yz) and compared with the reference's full K_j: K_j sigma n_j = (a - b) S_j sigma n_j +
// b M_j sigma n_j, whose second part is the affine terms' column of that sigma.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "deform/coordinate_layout.h"
#include "somigliana_reference.h"

namespace somicage::reference {

// Largest difference between the row (column c at row[c * stride]) and the reference, relative to the largest
// entry of the reference's T_i and K_j n_j; `winding` is compared with the reference winding number (absolute).
struct RowComparison {
  double coordinates = 0, winding = 0;
  double affine = 0;  // the affine terms' sum_j K_j sigma n_j, relative to its largest reference entry
};

inline RowComparison compareRowWithReference(const Cage& cage, const Eigen::Vector3d& x, const double* row, long stride,
                                             double winding) {
  const std::vector<double> nus = {0.0, 0.3};
  const std::vector<Coordinates> expected = integrateCoordinates(cage, x, nus, {12, 0.5, 40});
  RowComparison out;
  out.winding = std::abs(winding - windingNumber(cage, x));
  const CoordinateLayout layout{cage.numVertices(), cage.numFaces(), 10, 4, 0};
  const auto vertexTerm = [&](int i, int k) { return row[static_cast<long>(layout.vertexColumn(i, k)) * stride]; };
  const auto faceTerm = [&](int j, int k) { return row[static_cast<long>(layout.faceColumn(j, k)) * stride]; };
  for (size_t k = 0; k < nus.size(); ++k) {
    const KernelScalars s = kernelScalars(3, nus[k]);
    double scale = 0, error = 0;
    for (int i = 0; i < cage.numVertices(); ++i) {
      const auto t = [&](int m) { return vertexTerm(i, m); };
      Eigen::Matrix3d A, B;
      A << 0, -t(3), t(2), t(3), 0, -t(1), -t(2), t(1), 0;
      B << t(4), t(7), t(8), t(7), t(5), t(9), t(8), t(9), t(6);
      const Eigen::Matrix3d T = (s.a - 2 * s.b) * (t(0) * Eigen::Matrix3d::Identity() + A) + 6 * s.b * B;
      scale = std::max(scale, expected[k].T[i].cwiseAbs().maxCoeff());
      error = std::max(error, (T - expected[k].T[i]).cwiseAbs().maxCoeff());
    }
    for (int j = 0; j < cage.numFaces(); ++j) {
      Eigen::VectorXd n;
      double area;
      faceGeometry(cage, cage.vertices, j, n, area);
      const Eigen::Vector3d Kn =
          (s.a - s.b) * faceTerm(j, 0) * n + s.b * Eigen::Vector3d(faceTerm(j, 1), faceTerm(j, 2), faceTerm(j, 3));
      const Eigen::Vector3d expectedKn = expected[k].K[j] * n;
      scale = std::max(scale, expectedKn.cwiseAbs().maxCoeff());
      error = std::max(error, (Kn - expectedKn).cwiseAbs().maxCoeff());
    }
    out.coordinates = std::max(out.coordinates, error / scale);

    const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};  // affine_terms.h's order
    const long affineColumn = layout.mainColumns();
    double affineScale = 0, affineError = 0;
    for (int q = 0; q < 6; ++q) {
      Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
      sigma(pairs[q][0], pairs[q][1]) = sigma(pairs[q][1], pairs[q][0]) = 1;
      Eigen::Vector3d expectedSum = Eigen::Vector3d::Zero(), sum = Eigen::Vector3d::Zero();
      for (int j = 0; j < cage.numFaces(); ++j) {
        Eigen::VectorXd n;
        double area;
        faceGeometry(cage, cage.vertices, j, n, area);
        expectedSum += expected[k].K[j] * sigma * n;
        sum += (s.a - s.b) * faceTerm(j, 0) * sigma * n;
      }
      for (int a = 0; a < 3; ++a) sum[a] += s.b * row[(affineColumn + a * 6 + q) * stride];
      affineScale = std::max(affineScale, expectedSum.cwiseAbs().maxCoeff());
      affineError = std::max(affineError, (sum - expectedSum).cwiseAbs().maxCoeff());
    }
    out.affine = std::max(out.affine, affineScale > 0 ? affineError / affineScale : 0.0);
  }
  return out;
}

}  // namespace somicage::reference
