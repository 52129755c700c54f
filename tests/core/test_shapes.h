// Small cages and point sets that the engine tests build for themselves.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "geometry/cage.h"

namespace somicage::test {

// Icosphere of radius 1 (subdivided `levels` times), outward counter-clockwise faces.
inline Cage makeIcosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> V = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::Vector3i> F = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                    {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& v : V) v.normalize();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      V.push_back((V[a] + V[b]).normalized());
      return midpoints[key] = static_cast<int>(V.size()) - 1;
    };
    std::vector<Eigen::Vector3i> next;
    for (const auto& f : F) {
      const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      next.insert(next.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
    }
    F = next;
  }
  Cage cage;
  cage.vertices.resize(V.size(), 3);
  cage.faces.resize(F.size(), 3);
  for (size_t i = 0; i < V.size(); ++i) cage.vertices.row(i) = V[i];
  for (size_t j = 0; j < F.size(); ++j) cage.faces.row(j) = F[j];
  return cage;
}

// A non-convex, star-shaped "bumpy" sphere: radius 1 + 0.25 sin(3x) cos(2y) sin(2z) along each icosphere direction.
inline Cage makeBumpySphere(int levels) {
  Cage cage = makeIcosphere(levels);
  for (int i = 0; i < cage.numVertices(); ++i) {
    const Eigen::Vector3d u = cage.vertices.row(i);
    cage.vertices.row(i) = (1 + 0.25 * std::sin(3 * u.x()) * std::cos(2 * u.y()) * std::sin(2 * u.z() + 1)) * u;
  }
  return cage;
}

// The cube [-1, 1]^3, each face split into two triangles, outward counter-clockwise.
inline Cage makeCube() {
  Cage cage;
  cage.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i) cage.vertices.row(i) << (i & 1 ? 1 : -1), (i & 2 ? 1 : -1), (i & 4 ? 1 : -1);
  cage.faces.resize(12, 3);
  cage.faces << 0, 2, 3, 0, 3, 1,  // z = -1
      4, 5, 7, 4, 7, 6,            // z = +1
      0, 1, 5, 0, 5, 4,            // y = -1
      2, 6, 7, 2, 7, 3,            // y = +1
      0, 4, 6, 0, 6, 2,            // x = -1
      1, 3, 7, 1, 7, 5;            // x = +1
  return cage;
}

// The L-shaped hexagon {x <= 1 or y <= 1} in [0, 2]^2, counter-clockwise (non-convex, reflex corner at (1, 1)).
inline Eigen::MatrixXd lLoop() {
  Eigen::MatrixXd loop(6, 2);
  loop << 0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2;
  return loop;
}

// The L extruded over z in [0, 1]: a non-convex 3D cage whose inner side planes x = 1 and y = 1 cross its inside.
inline Cage makeExtrudedL() {
  const Eigen::MatrixXd loop = lLoop();
  Cage cage;
  cage.vertices.resize(12, 3);
  for (int k = 0; k < 6; ++k) {
    cage.vertices.row(k) << loop(k, 0), loop(k, 1), 0;
    cage.vertices.row(k + 6) << loop(k, 0), loop(k, 1), 1;
  }
  std::vector<Eigen::Vector3i> faces;
  for (int k = 0; k < 6; ++k) {  // sides: quad (k, k+1, k+1+6, k+6), outward for a counter-clockwise loop
    const int k1 = (k + 1) % 6;
    faces.push_back({k, k1, k1 + 6});
    faces.push_back({k, k1 + 6, k + 6});
  }
  // Caps: a fan from corner 0, which sees the whole L; bottom faces down, top faces up.
  for (int k = 1; k < 5; ++k) faces.push_back({0, k + 1, k}), faces.push_back({6, k + 6, k + 7});
  cage.faces.resize(faces.size(), 3);
  for (size_t j = 0; j < faces.size(); ++j) cage.faces.row(j) = faces[j];
  return cage;
}

// Random points of the extruded L (or of the flat L when dim = 2) at least `margin` inside.
inline Eigen::MatrixXd randomLPoints(int count, int dim, double margin, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  Eigen::MatrixXd P(count, dim);
  for (int p = 0; p < count;) {
    const double x = margin + (2 - 2 * margin) * uniform(rng), y = margin + (2 - 2 * margin) * uniform(rng);
    if (x > 1 - margin && y > 1 - margin) continue;
    P(p, 0) = x, P(p, 1) = y;
    if (dim == 3) P(p, 2) = margin + (1 - 2 * margin) * uniform(rng);
    ++p;
  }
  return P;
}

// Random points of the box [lo, hi]^dim, drawn row by row, coordinate by coordinate.
inline Eigen::MatrixXd randomBoxPoints(int count, int dim, double lo, double hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(lo, hi);
  Eigen::MatrixXd P(count, dim);
  for (int p = 0; p < count; ++p)
    for (int a = 0; a < dim; ++a) P(p, a) = uniform(rng);
  return P;
}

// Random points at radius <= maxRadius around the origin (inside the icosphere for maxRadius < ~0.79).
inline Eigen::MatrixXd randomBallPoints(int count, double maxRadius, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0, 1);
  Eigen::MatrixXd P(count, 3);
  for (int p = 0; p < count; ++p) {
    const Eigen::Vector3d dir = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    P.row(p) = maxRadius * std::cbrt(uniform(rng)) * dir;
  }
  return P;
}

// The unit square [0, 1]^2, counter-clockwise from the origin.
inline Cage makeUnitSquare() {
  Eigen::MatrixXd loop(4, 2);
  loop << 0, 0, 1, 0, 1, 1, 0, 1;
  return makePolygonCage(loop);
}

// A non-convex counter-clockwise star polygon with `spikes` spikes (radii 1 and 0.5), slightly irregular.
inline Cage makeStarPolygon(int spikes) {
  Eigen::MatrixXd loop(2 * spikes, 2);
  for (int k = 0; k < 2 * spikes; ++k) {
    const double angle = M_PI * k / spikes + 0.05 * std::sin(3.0 * k);
    const double radius = (k % 2 == 0 ? 1.0 : 0.5) * (1 + 0.05 * std::cos(5.0 * k));
    loop.row(k) << radius * std::cos(angle), radius * std::sin(angle);
  }
  return makePolygonCage(loop);
}

// Random points inside the disc of radius maxRadius (inside the star for maxRadius < ~0.45).
inline Eigen::MatrixXd randomDiscPoints(int count, double maxRadius, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  Eigen::MatrixXd P(count, 2);
  for (int p = 0; p < count; ++p) {
    const double angle = 2 * M_PI * uniform(rng), radius = maxRadius * std::sqrt(uniform(rng));
    P.row(p) << radius * std::cos(angle), radius * std::sin(angle);
  }
  return P;
}

// Points at distance `offset` inside the cage from random points of random faces (3D and 2D).
inline Eigen::MatrixXd pointsNearFaces(const Cage& cage, int count, double offset, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::uniform_int_distribution<int> face(0, cage.numFaces() - 1);
  const Eigen::MatrixXd N = faceNormals(cage, cage.vertices);
  Eigen::MatrixXd P(count, cage.dim());
  for (int p = 0; p < count; ++p) {
    const int j = face(rng);
    Eigen::VectorXd y;
    if (cage.dim() == 3) {
      double a = uniform(rng), b = uniform(rng);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      y = (1 - a - b) * cage.vertices.row(cage.faces(j, 0)) + a * cage.vertices.row(cage.faces(j, 1)) +
          b * cage.vertices.row(cage.faces(j, 2));
    } else {
      const double a = 0.1 + 0.8 * uniform(rng);
      y = (1 - a) * cage.vertices.row(cage.faces(j, 0)) + a * cage.vertices.row(cage.faces(j, 1));
    }
    P.row(p) = y.transpose() - offset * N.row(j);
  }
  return P;
}

// A random similarity: rotation (random axis, angle), scale and translation, applied to the rows of V.
struct TestSimilarity {
  Eigen::MatrixXd rotation;
  double scale;
  Eigen::RowVectorXd translation;
  Eigen::MatrixXd apply(const Eigen::MatrixXd& V) const {
    return (scale * V * rotation.transpose()).rowwise() + translation;
  }
};

inline TestSimilarity randomSimilarity(int dim, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  TestSimilarity s;
  if (dim == 3) {
    const Eigen::Vector3d axis = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized();
    s.rotation = Eigen::AngleAxisd(M_PI * uniform(rng), axis).toRotationMatrix();
  } else {
    s.rotation = Eigen::Rotation2Dd(M_PI * uniform(rng)).toRotationMatrix();
  }
  s.scale = std::exp(uniform(rng));
  s.translation = Eigen::RowVectorXd::Zero(dim);
  for (int a = 0; a < dim; ++a) s.translation(a) = 3 * uniform(rng);
  return s;
}

// A non-trivial pose: each vertex moved by a smooth field plus a little noise.
inline Eigen::MatrixXd bendPose(const Eigen::MatrixXd& V, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::MatrixXd P = V;
  for (int i = 0; i < V.rows(); ++i) {
    const double x = V(i, 0), y = V(i, 1);
    P(i, 1) += amount * x * x;
    P(i, 0) += amount * 0.5 * std::sin(2 * y);
    for (int a = 0; a < V.cols(); ++a) P(i, a) += 0.05 * amount * uniform(rng);
  }
  return P;
}

}  // namespace somicage::test
