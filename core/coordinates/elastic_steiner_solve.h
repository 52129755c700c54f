// Where a volume mesh's interior Steiner vertices go when its other vertices move (issue 25, item 2): they
// minimise the linear-elastic energy
//   E = sum_t V_t (mu |eps_t|^2 + lambda/2 tr(eps_t)^2),   eps_t = (F_t + F_t^T)/2 - I,   F_t = D_s D_m^-1,
// with mu = 1 and lambda = 2 nu / (1 - 2 nu), the other vertices fixed. E = 1/2 u^T K u in the displacements u
// (K = K_mu + lambda K_lambda, assembled once), so the free displacements solve K_ff u_f = -K_fk u_k: a sparse
// SPD system, factored once per nu (Eigen's SimplicialLDLT) and solved per frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <limits>
#include <memory>
#include <vector>

#include "geometry/volume_mesh.h"

namespace somicage {

// lambda(nu) = 2 nu / (1 - 2 nu) (mu = 1). The energy is positive definite where the bulk modulus
// mu + d lambda / 2 ... (3D: 2 mu + 3 lambda > 0, i.e. -1 < nu < 1/2; 2D: mu + lambda > 0, i.e. nu < 1/2).
double lameLambda(double nu);
// Whether E is positive definite at nu in dimension d (the range above; never at nu = +-inf).
bool elasticEnergyPositiveDefinite(double nu, int dim);

// The vertices the solver solves for: the Steiner vertices (index >= cageVertices) on no boundary face. Those on
// the boundary lie on the cage's faces and follow them.
std::vector<bool> interiorSteinerVertices(const VolumeMesh& mesh, int cageVertices);

class ElasticSteinerSolver {
 public:
  // free[v]: vertex v's position is solved for; the others are given each frame.
  ElasticSteinerSolver(const VolumeMesh& rest, const std::vector<bool>& free);

  int freeCount() const { return static_cast<int>(freeVertices_.size()); }

  // Factors K_ff at nu unless it is factored at that nu already. Throws InputError("nu", ...) outside the
  // positive-definite range, or when the factorisation fails.
  void factor(double nu);
  double factoredNu() const { return nu_; }

  // positions (#N by d): the free rows are replaced by the minimiser, given the other rows. Needs factor(). The
  // last solve is kept: the same known rows at the same nu are not solved again. Not thread-safe (nor is factor).
  void solve(Eigen::MatrixXd& positions) const;
  // How many times solve() ran the factor's solve (not counting repeats it answered from the last solve).
  int solveCount() const { return solves_; }

  // K at nu over all vertices (d #N square, vertex-major: row v d + a), for tests against a dense solve.
  Eigen::SparseMatrix<double> stiffness(double nu) const;

 private:
  Eigen::MatrixXd rest_;
  std::vector<int> freeVertices_, knownVertices_;
  Eigen::SparseMatrix<double> kMu_, kLambda_;  // all vertices, vertex-major
  Eigen::SparseMatrix<double> freeFreeMu_, freeFreeLambda_, freeKnownMu_, freeKnownLambda_;
  Eigen::SparseMatrix<double> freeKnown_;  // at the factored nu
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> factor_;
  double nu_ = 0;
  bool factored_ = false;
  // The last solve: the known displacements and nu it was for (NaN: none yet), and the free displacements.
  mutable Eigen::VectorXd lastKnown_, lastU_;
  mutable double lastNu_ = std::numeric_limits<double>::quiet_NaN();
  mutable int solves_ = 0;
};

}  // namespace somicage
