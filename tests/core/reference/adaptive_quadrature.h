// Test-only quadrature for the reference evaluation of Somigliana coordinates (reference/somigliana_reference.h):
// Gauss-Legendre rules of any order, applied to a triangle (3D, through the collapsed-square map) or a segment (2D)
// that is subdivided until every piece is small against its distance to the query point. Independent of core's
// integrals: it only needs a point-to-piece distance, which it computes itself.
//
// Why it converges: a piece of diameter h at distance >= h / ratio from x sees an integrand analytic in a region
// whose size relative to the piece grows with 1 / ratio, so an n-point Gauss-Legendre rule's error falls like
// rho^(-2n) with rho about 4 / ratio + 1 (the Bernstein ellipse); refining the pieces costs only log(h / dist)
// levels next to x. The tests measure the rate (SomiglianaReference.QuadratureConverges).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

namespace somicage::reference {

struct QuadratureOptions {
  int order = 10;      // Gauss-Legendre points per direction (n^2 per triangle piece, n per segment piece)
  double ratio = 0.5;  // a piece is split until its diameter <= ratio * its distance to the query point
  int maxDepth = 40;   // a guard: pieces are not split beyond this depth (reached only within ~1e-12 of the cage)
};

// The n-point Gauss-Legendre rule on [0, 1]: Newton's method on P_n from the Chebyshev guesses.
struct GaussRule {
  std::vector<double> nodes, weights;
};

inline GaussRule gaussLegendre(int n) {
  auto legendre = [n](double x, double& value, double& derivative) {  // P_n(x) and P_n'(x)
    double previous = 1;
    value = x;
    for (int m = 2; m <= n; ++m) {
      const double next = ((2 * m - 1) * x * value - (m - 1) * previous) / m;
      previous = value, value = next;
    }
    derivative = n * (x * value - previous) / (x * x - 1);
  };
  GaussRule rule;
  for (int k = 0; k < n; ++k) {
    double x = std::cos(M_PI * (k + 0.75) / (n + 0.5)), value, derivative;
    for (int iteration = 0; iteration < 100; ++iteration) {
      legendre(x, value, derivative);
      const double step = value / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    legendre(x, value, derivative);
    rule.nodes.push_back(0.5 * (1 - x));
    rule.weights.push_back(1 / ((1 - x * x) * derivative * derivative));  // 2 / ((1-x^2) P'^2), halved for [0, 1]
  }
  return rule;
}

// Distance from x to the segment a b (any dimension).
template <class Vector>
double segmentDistance(const Vector& x, const Vector& a, const Vector& b) {
  const Vector e = b - a;
  const double t = std::clamp(e.dot(x - a) / e.squaredNorm(), 0.0, 1.0);
  return (a + t * e - x).norm();
}

// Distance from x to the triangle p0 p1 p2: the plane distance when x projects inside, else the nearest edge.
inline double triangleDistance(const Eigen::Vector3d& x, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                               const Eigen::Vector3d& p2) {
  const Eigen::Vector3d normal = (p1 - p0).cross(p2 - p0);
  const double twiceArea2 = normal.squaredNorm();
  const Eigen::Vector3d d = x - p0;
  const double b1 = (d.cross(p2 - p0)).dot(normal) / twiceArea2, b2 = ((p1 - p0).cross(d)).dot(normal) / twiceArea2;
  if (b1 >= 0 && b2 >= 0 && b1 + b2 <= 1) return std::abs(d.dot(normal)) / std::sqrt(twiceArea2);
  return std::min({segmentDistance(x, p0, p1), segmentDistance(x, p1, p2), segmentDistance(x, p2, p0)});
}

// Calls node(y, phi, weight) for the quadrature nodes of the triangle p0 p1 p2 (y a node, phi its three barycentric
// coordinates = the hat functions of the corners, weight its area weight), refined around x.
template <class Node>
void forEachTriangleNode(const Eigen::Vector3d p[3], const Eigen::Vector3d& x, const QuadratureOptions& options,
                         const GaussRule& rule, Node&& node) {
  // A piece is three corners given by their barycentric coordinates in the triangle.
  struct Piece {
    Eigen::Vector3d corner[3];
    int depth;
  };
  auto position = [&](const Eigen::Vector3d& b) -> Eigen::Vector3d { return b[0] * p[0] + b[1] * p[1] + b[2] * p[2]; };
  std::vector<Piece> stack{{{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()}, 0}};
  while (!stack.empty()) {
    const Piece piece = stack.back();
    stack.pop_back();
    const Eigen::Vector3d q0 = position(piece.corner[0]), q1 = position(piece.corner[1]),
                          q2 = position(piece.corner[2]);
    const double diameter = std::max({(q1 - q0).norm(), (q2 - q1).norm(), (q0 - q2).norm()});
    if (piece.depth < options.maxDepth && diameter > options.ratio * triangleDistance(x, q0, q1, q2)) {
      const Eigen::Vector3d* c = piece.corner;
      const Eigen::Vector3d m01 = (c[0] + c[1]) / 2, m12 = (c[1] + c[2]) / 2, m20 = (c[2] + c[0]) / 2;
      const int depth = piece.depth + 1;
      stack.push_back({{c[0], m01, m20}, depth});
      stack.push_back({{m01, c[1], m12}, depth});
      stack.push_back({{m20, m12, c[2]}, depth});
      stack.push_back({{m01, m12, m20}, depth});
      continue;
    }
    // Collapsed square: b(s, t) = c0 + s (c1 - c0) + s t (c2 - c1), |dy/ds x dy/dt| = s * 2 * area.
    const double twiceArea = (q1 - q0).cross(q2 - q0).norm();
    for (size_t i = 0; i < rule.nodes.size(); ++i)
      for (size_t j = 0; j < rule.nodes.size(); ++j) {
        const double s = rule.nodes[i], t = rule.nodes[j];
        const Eigen::Vector3d b =
            piece.corner[0] + s * (piece.corner[1] - piece.corner[0]) + s * t * (piece.corner[2] - piece.corner[1]);
        node(position(b), b, rule.weights[i] * rule.weights[j] * s * twiceArea);
      }
  }
}

// Calls node(y, phi, weight) for the quadrature nodes of the segment p0 p1 (phi: the hat functions of its two
// ends), refined around x.
template <class Node>
void forEachSegmentNode(const Eigen::Vector2d p[2], const Eigen::Vector2d& x, const QuadratureOptions& options,
                        const GaussRule& rule, Node&& node) {
  struct Piece {
    double t0, t1;
    int depth;
  };
  const double length = (p[1] - p[0]).norm();
  std::vector<Piece> stack{{0.0, 1.0, 0}};
  while (!stack.empty()) {
    const Piece piece = stack.back();
    stack.pop_back();
    const Eigen::Vector2d a = p[0] + piece.t0 * (p[1] - p[0]), b = p[0] + piece.t1 * (p[1] - p[0]);
    if (piece.depth < options.maxDepth && (piece.t1 - piece.t0) * length > options.ratio * segmentDistance(x, a, b)) {
      const double middle = (piece.t0 + piece.t1) / 2;
      stack.push_back({piece.t0, middle, piece.depth + 1});
      stack.push_back({middle, piece.t1, piece.depth + 1});
      continue;
    }
    for (size_t i = 0; i < rule.nodes.size(); ++i) {
      const double t = piece.t0 + (piece.t1 - piece.t0) * rule.nodes[i];
      node(Eigen::Vector2d(p[0] + t * (p[1] - p[0])), Eigen::Vector2d(1 - t, t),
           rule.weights[i] * (piece.t1 - piece.t0) * length);
    }
  }
}

}  // namespace somicage::reference
