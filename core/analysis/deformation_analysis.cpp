#include "analysis/deformation_analysis.h"

#include <string>

#include "base/errors.h"

namespace somicage {

DeformationAnalysis analyzeDeformation(const DeformationGradients& gradients, const Eigen::MatrixXd& restPoints,
                                       const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& posedVertices,
                                       const DeformParams& params, const SeamJumpEvaluator* seams) {
  DeformationAnalysis a;
  gradients.evaluate(posedVertices, params, a.positions, a.jacobians);
  a.points = pointQuantities(a.jacobians, gradients.dim());
  a.faces = faceQuantities(faces, restPoints, a.positions);
  a.volume = enclosedMeasure(faces, restPoints, a.positions);
  if (seams) a.seams = seams->evaluate(posedVertices, params);
  return a;
}

std::vector<double> nuSweepValues(double from, double to, int count) {
  auto inRange = [](double nu) { return nu > -1 && nu < 0.5; };
  if (!inRange(from) || !inRange(to) || !(count >= 2))
    throw InputError(
        "--nu-sweep", -1,
        "the sweep " + std::to_string(from) + ":" + std::to_string(to) + ":" + std::to_string(count) + " is not usable",
        "give FROM:TO:N with -1 < FROM, TO < 0.5 and N >= 2, e.g. -0.9:0.49:30");
  std::vector<double> nus(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) nus[static_cast<std::size_t>(k)] = from + k * (to - from) / (count - 1);
  return nus;
}

std::vector<NuSweepEntry> sweepNu(const DeformationGradients& gradients, const Eigen::MatrixXd& restPoints,
                                  const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& posedVertices,
                                  DeformParams params, const std::vector<double>& nus,
                                  const ProgressCallback& progress) {
  std::vector<NuSweepEntry> sweep;
  for (std::size_t k = 0; k < nus.size(); ++k) {
    if (!progress(static_cast<double>(k) / static_cast<double>(nus.size()))) throw Cancelled();
    params.nu = nus[k];
    Eigen::MatrixXd positions, jacobians;
    gradients.evaluate(posedVertices, params, positions, jacobians);
    sweep.push_back({params.nu, enclosedMeasure(faces, restPoints, positions).change(),
                     pointQuantities(jacobians, gradients.dim()).foldovers});
  }
  progress(1.0);
  return sweep;
}

}  // namespace somicage
