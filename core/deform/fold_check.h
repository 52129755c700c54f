// The stable variant's fold check (docs/engine.md, "The stable variant"): the least damping of the local variant's
// non-uniform volumetric tractions that keeps det J above a margin at fixed sample points inside the rest cage.
// The samples depend on the rest cage alone, so the map stays a function of the cage, the pose and the parameters
// (not of the points being deformed).
#pragma once

#include <Eigen/Core>

#include "geometry/cage.h"

namespace somicage {

// About kFoldCheckCells grid cells fill the rest cage's volume (2D: area); the samples are the cell centres inside
// the cage at least half a cell from its boundary (where the coordinates' gradients are steep and no mesh needs a
// check that the nearest interior samples do not give). 400 cells: 186 samples in CACTUS, 200 in FIREHYDRANT.
constexpr int kFoldCheckCells = 400;
// det J must exceed this share of sigma^d (sigma the best-fit scale of the pose: similarity invariant) at every
// sample: of the margins measured (0, 0.1, 0.2; docs/engine.md), the smallest that leaves the mesh vertices between
// the samples with no more fold-overs than the damping alone (CACTUS 1 / 0 / 0 / 0 at nu = 0.3 / 0.4 / 0.45 / 0.49).
constexpr double kFoldCheckMargin = 0.2;

// The samples (#S by d) inside the rest cage, in a fixed order.
Eigen::MatrixXd foldCheckSamples(const Cage& restCage);

// Whether det J > minDet at every sample (J: #S by d*d, row-major per sample as DeformationGradients::evaluate;
// NaN rows, samples without a J of their own, skipped).
bool foldFree(const Eigen::MatrixXd& J, double minDet);

// The least s in [0, 1] with det(J0 + s (J1 - J0)) > minDet at every sample (J0, J1 as for foldFree): 0 when J0
// passes, else the first of s = 1/32, 2/32, ... that passes, refined by bisection against the one before; 1 when
// none passes. J is affine in s (the tractions are, and T(x) does not depend on them), so det J along s is a cubic
// (2D: a quadratic) per sample.
double leastFoldFreeBlend(const Eigen::MatrixXd& J0, const Eigen::MatrixXd& J1, double minDet);

}  // namespace somicage
