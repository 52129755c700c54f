// The boundary element solution of linear elasticity (mu = 1, Poisson ratio nu, no body force) inside a rest cage
// whose boundary is displaced by u: u_i at the cage vertices, linear over each face. Unknowns: one traction t_j per
// face (piecewise constant), found by collocating the boundary integral equation -- the Somigliana identity (paper
// Eq. 2) in its limit from the inside -- at the face centroids x_c:
//
//   u(x_c) = sum_i T_i(x_c-) u_i + sum_j K_j(x_c) t_j + omega        (d F equations)
//   sum_j A_j t_j = 0                                                  (d equations: the tractions balance)
//
// with the same kernels and coordinates T_i, K_j as the Somigliana deformer (bem_layer_integrals.h). T_i(x_c-) is
// the closed form in the limit from inside, which holds the jump term (sum_i T_i(x_c-) = I). omega (d numbers) is
// the constant of the Hsiao-MacCamy formulation: with the balance equations it makes the system uniquely solvable
// at every cage size (the 2D logarithmic single layer is singular at "degenerate scales") and gives tractions in
// equilibrium; it vanishes for exact data, e.g. for every affine displacement, which the scheme reproduces exactly
// (t_j = sigma n_j). docs/engine.md ("Boundary element reference") says why collocation at centroids.
//
// The boundary matrix depends on the rest cage and nu only: BemFactorization is assembled and LU-factored once per
// (cage, nu) from nu-independent integrals; a solve is then one triangular solve with a (dF + d) vector. The system
// keeps the factorizations of the values of nu used last (factorization(nu)), so views at different nu and a nu sweep
// that comes back do not re-factor every frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <cstddef>
#include <memory>

#include "base/progress.h"
#include "coordinates/bem_layer_integrals.h"
#include "geometry/cage.h"

namespace somicage {

// Throws InputError unless nu is in (-1, 1/2) or +-infinity (the limit of docs/method.md: vector Laplace). nu = 1/2
// is refused: incompressible, the single layer of the normal vanishes inside, so the boundary matrix is singular
// (the pressure is undetermined) and a pose that changes the volume has no solution.
void validateBemPoissonRatio(double nu);

struct BemFactorization {
  double nu = 0;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;  // of the (dF + d) square boundary matrix
  Eigen::MatrixXd dataOperator;             // (dF + d) by dV: the right-hand side from u (vertex-major, u_i blocks)
};

struct BemSolution {
  Eigen::MatrixXd tractions;  // t_j, #F by d
  Eigen::VectorXd omega;      // d
};

class BemSystem {
 public:
  // Integrates the collocation rows of the rest cage (its face centroids; F^2 (point, face) pairs).
  explicit BemSystem(const Cage& restCage, int threads = 0, const ProgressCallback& progress = noProgress);

  const Cage& restCage() const { return rest_; }
  const Eigen::MatrixXd& collocationPoints() const { return centroids_; }  // #F by d

  // Assembles and factors the boundary matrix at nu (validated as above).
  std::shared_ptr<const BemFactorization> factor(double nu) const;

  // factor(nu) through a least-recently-used cache of the last kCachedFactorizations values of nu (fewer when one
  // factorization is large: at most kCacheBytes in all, at least one kept). Thread-safe; the factoring runs under
  // the cache's lock, so two threads asking for one nu factor it once.
  std::shared_ptr<const BemFactorization> factorization(double nu) const;
  // How many factorizations factorization() has made (cache misses), for tests and benchmarks.
  std::size_t factorizationsMade() const;
  static constexpr std::size_t kCachedFactorizations = 8;
  static constexpr std::size_t kCacheBytes = std::size_t(256) << 20;

  // The tractions for the displacement u (#V by d, rest cage order).
  BemSolution solve(const BemFactorization& factorization, const Eigen::MatrixXd& displacement) const;

 private:
  Cage rest_;
  Eigen::MatrixXd centroids_;
  Eigen::VectorXd areas_;        // A_j (2D: edge lengths)
  double lengthScale_ = 1;       // the cage diameter: scales the balance rows and omega's column like K
  BemLayerIntegrals integrals_;  // at the centroids, in the limit from inside on each one's own face
  struct FactorizationCache;
  std::shared_ptr<FactorizationCache> cache_;  // shared by copies of the system (it depends on nothing they change)
};

}  // namespace somicage
