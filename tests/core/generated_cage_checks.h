// What every generated cage must satisfy (core/generation/cage_generation.h), checked independently of CGAL: the
// project's own validator (closed, manifold, outward, no self-intersection), the generalised winding number of every
// mesh vertex summed from solid angles (Van Oosterom and Strackee 1983), a brute-force segment-triangle test for every
// mesh edge, the face budget, and the Somigliana precompute on the cage (partition of unity, Eq. 9; identity at rest).
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "cage/cage_validation.h"
#include "coordinates/somigliana_coordinates.h"
#include "deform/deformer.h"
#include "geometry/cage.h"
#include "methods/method_descriptors.h"

namespace somicage::test {

// Winding number of the closed triangle mesh around x: the sum of the signed solid angles of its faces / 4 pi.
inline double windingNumber(const Cage& cage, const Eigen::Vector3d& x) {
  double sum = 0;
  for (int j = 0; j < cage.numFaces(); ++j) {
    const Eigen::Vector3d a = Eigen::Vector3d(cage.vertices.row(cage.faces(j, 0))) - x;
    const Eigen::Vector3d b = Eigen::Vector3d(cage.vertices.row(cage.faces(j, 1))) - x;
    const Eigen::Vector3d c = Eigen::Vector3d(cage.vertices.row(cage.faces(j, 2))) - x;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    sum += 2 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return sum / (4 * M_PI);
}

// Whether segment pq meets triangle abc (closed sets; Moller-Trumbore with a relative tolerance that errs on the
// side of "meets").
inline bool segmentMeetsTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d d = q - p, e1 = b - a, e2 = c - a, h = d.cross(e2);
  const double det = e1.dot(h), scale = d.norm() * e1.norm() * e2.norm();
  if (std::abs(det) <= 1e-12 * scale) return false;  // parallel: the winding-number test covers the endpoints
  const Eigen::Vector3d s = p - a, qv = s.cross(e1);
  const double u = s.dot(h) / det, v = d.dot(qv) / det, t = e2.dot(qv) / det, eps = 1e-9;
  return u >= -eps && v >= -eps && u + v <= 1 + eps && t >= -eps && t <= 1 + eps;
}

// Mesh edges that meet a cage face (each edge once), found by testing every pair whose boxes overlap.
inline int meshEdgesCrossingCage(const Cage& cage, const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles) {
  std::set<std::pair<int, int>> edges;
  for (int j = 0; j < triangles.rows(); ++j)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(triangles(j, k), triangles(j, (k + 1) % 3)));
  std::vector<Eigen::AlignedBox3d> boxes(cage.numFaces());
  for (int j = 0; j < cage.numFaces(); ++j)
    for (int k = 0; k < 3; ++k) boxes[j].extend(Eigen::Vector3d(cage.vertices.row(cage.faces(j, k))));
  int crossing = 0;
  for (const auto& [i, k] : edges) {
    const Eigen::Vector3d p = vertices.row(i), q = vertices.row(k);
    Eigen::AlignedBox3d box(p.cwiseMin(q), p.cwiseMax(q));
    for (int j = 0; j < cage.numFaces(); ++j) {
      if (!box.intersects(boxes[j])) continue;
      if (segmentMeetsTriangle(p, q, cage.vertices.row(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 1)),
                               cage.vertices.row(cage.faces(j, 2)))) {
        ++crossing;
        break;
      }
    }
  }
  return crossing;
}

// Every `stride`-th row (at most about maxRows of them).
inline Eigen::MatrixXd subsample(const Eigen::MatrixXd& rows, int maxRows) {
  const Eigen::Index stride = std::max<Eigen::Index>(1, (rows.rows() + maxRows - 1) / maxRows);
  Eigen::MatrixXd picked(rows.rows() / stride, rows.cols());
  for (Eigen::Index p = 0; p < picked.rows(); ++p) picked.row(p) = rows.row(p * stride);
  return picked;
}

// The properties of the issue, for a cage generated around (vertices, triangles) with a budget of maxFaces.
inline void expectGeneratedCageValid(const Cage& cage, const Eigen::MatrixXd& vertices,
                                     const Eigen::MatrixXi& triangles, int maxFaces, int precomputePoints) {
  EXPECT_LE(cage.numFaces(), maxFaces);
  const CageReport report = validateCage(cage);
  EXPECT_TRUE(report.valid()) << describeCageProblems(report).front();
  EXPECT_TRUE(report.intersectingFaces.empty()) << report.intersectingFaces.size() << " face pairs intersect";

  int outside = 0;
  double worst = 0;
  for (Eigen::Index i = 0; i < vertices.rows(); ++i) {
    const double w = windingNumber(cage, vertices.row(i));
    worst = std::max(worst, std::abs(w - 1));
    outside += std::abs(w - 1) > 1e-6;
  }
  EXPECT_EQ(outside, 0) << "mesh vertices with winding number != 1 (worst |w - 1| = " << worst << ")";
  EXPECT_EQ(meshEdgesCrossingCage(cage, vertices, triangles), 0);

  // Somigliana coordinates on the new cage: partition of unity (Eq. 9) and the identity at rest.
  const Eigen::MatrixXd points = subsample(vertices, precomputePoints);
  const SomiglianaCoordinates coords = computeSomiglianaCoordinates(cage, points);
  EXPECT_LE(partitionOfUnityResidual(coords).maxCoeff(), 1e-9);
  const auto deformer = makeDeformer(methods::somigliana(), cage, points);
  const double rest = (deformer->deform(cage.vertices, {}) - points).rowwise().norm().maxCoeff();
  EXPECT_LE(rest, 1e-9 * cageDiameter(cage.vertices));
}

}  // namespace somicage::test
