// The run-time parameters of a deformation (DeformParams), their ranges and their validation: what a frame reads
// besides the posed cage, apart from the deformer that reads it, so that what only carries parameters (boundary
// conditions, poses and keys, sessions) does not include the deformer.
#pragma once

#include <map>
#include <string>

#include "deform/deform_choices.h"

namespace somicage {

// Which boundary conditions the Somigliana deformer builds (docs/engine.md, "Variants beyond the paper").
enum class VariantKind {
  Blend,   // the paper's: rotations blended from the global (blend 0) to the local (blend 1) variant (Fig. 4)
  Affine,  // the global variant with the best-fit affine map A = R S: tractions R sigma(S) n_j (blend ignored)
  Stable,  // the local variant without its fold-overs at high nu (blend ignored)
};

// Run-time parameters. Green and mean value coordinates ignore all but the posed cage.
struct DeformParams {
  double blend = 0.0;              // t in [0, 1]: 0 = global variant, 1 = local variant (Fig. 4)
  double nu = 0.0;                 // Poisson ratio in (-1, 0.5), or +-infinity
  double gamma = 0.0;              // bulging scale >= 0 (section 4.4)
  bool tractionCorrection = true;  // Eq. 15
  bool corotational = false;       // BEM only: remove the best-fit rotation before the linear solve (bem_method.cpp)
  Bulging bulging = Bulging::SolidAngle;        // how eta grows with gamma (deform_choices.h)
  NormalWeights normals = NormalWeights::Area;  // vertex normals' and vertex rotations' face weights
  VariantKind kind = VariantKind::Blend;        // set with blend by the variant's name (deform_choices.h)
  // The values of parameters registered outside core (parameter_schema.h: ParameterRegistration), by key.
  std::map<std::string, double> extra{};
};

// Every field equal (numbers exactly).
bool operator==(const DeformParams& a, const DeformParams& b);
inline bool operator!=(const DeformParams& a, const DeformParams& b) { return !(a == b); }
// The ranges validateDeformParams accepts: the one list every front end shows or checks (the CLI's help, the
// editor's options and sliders, Python's somicage.parameter_ranges(), the Blender add-on through it).
struct ParameterRange {
  double min, max;
};
// nu: the open interval (min, max), or +-infinity (the limits of section 5).
constexpr ParameterRange kNuRange{-1.0, 0.5};
// gamma: [min, max]. The normal stretch is eta_j = lambda_j exp(gamma beta_j / (2^(d-1) pi)) (section 4.4) with
// |beta_j| < 2^d pi (3D: a difference of two solid angles in (-2 pi, 2 pi]; 2D: wrapped to (-pi, pi]), so
// exp(-gamma) < eta_j / lambda_j < exp(gamma). At 10 (five times the paper's largest gamma, twice the editor's
// slider) that bound is 2.2e4 and every result stays finite; beyond it one face's stretch can reach 1e248
// (gamma 1e4) and overflow (1e6) without any pose being wrong.
constexpr ParameterRange kGammaRange{0.0, 10.0};
// blend: [min, max], 0 = global variant, 1 = local variant.
constexpr ParameterRange kBlendRange{0.0, 1.0};

// A range as help texts and messages show it: "[0, 10]", or "(-1, 0.5)" when open.
std::string rangeText(const ParameterRange& range, bool open = false);

// Throws InputError naming the parameter when a value is out of range or NaN (every row of parameter_schema.h).
void validateDeformParams(const DeformParams& params);

// The thread counts every front end takes (--threads, Python's threads=): 0 (all cores) to kMaxThreads.
constexpr int kMaxThreads = 4096;

}  // namespace somicage
