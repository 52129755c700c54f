#include "deform/deformer.h"

#include <string>

#include "base/errors.h"
#include "deform/jacobian.h"
#include "geometry/medit_io.h"

namespace somicage {

Eigen::MatrixXd CageDeformer::posedVolumeMesh(const Eigen::MatrixXd&, const DeformParams&) const {
  return Eigen::MatrixXd(0, dim());
}

void CageDeformer::deform(const Eigen::MatrixXd& posedVertices, const DeformParams& params,
                          Eigen::MatrixXd& out) const {
  evaluateFrame(coordinates_, frameWeights(posedVertices, params), dim(), threads_, out);
}

std::shared_ptr<const DeformationGradients> CageDeformer::gradients(const Eigen::MatrixXd& points,
                                                                    const ProgressCallback& progress) const {
  if (std::shared_ptr<const DeformationGradients> kept = keptGradients()) return kept;
  const std::lock_guard<std::mutex> integrating(gradientCache_.integrating);
  std::uint64_t releases = 0;
  {
    const std::lock_guard<std::mutex> slot(gradientCache_.slot);
    if (gradientCache_.kept) return gradientCache_.kept;  // integrated by the caller this one waited for
    releases = gradientCache_.releases;
  }
  auto made = std::make_shared<const DeformationGradients>(*this, points, progress);
  const std::lock_guard<std::mutex> slot(gradientCache_.slot);
  gradientCache_.integrations += 1;
  if (gradientCache_.releases == releases) gradientCache_.kept = made;
  return made;
}

std::shared_ptr<const DeformationGradients> CageDeformer::keptGradients() const {
  const std::lock_guard<std::mutex> slot(gradientCache_.slot);
  return gradientCache_.kept;
}

void CageDeformer::releaseGradients() const {
  const std::lock_guard<std::mutex> slot(gradientCache_.slot);
  gradientCache_.kept.reset();
  gradientCache_.releases += 1;
}

int CageDeformer::gradientIntegrations() const {
  const std::lock_guard<std::mutex> slot(gradientCache_.slot);
  return gradientCache_.integrations;
}

std::shared_ptr<const VolumeMesh> volumeMeshFor(const Cage& restCage, const PrecomputeOptions& options,
                                                int* reoriented, const ProgressCallback& progress) {
  if (options.volumeMesh) return options.volumeMesh;
  int flipped = 0;
  std::shared_ptr<VolumeMesh> mesh;
  if (const auto file = options.methodOptions.find("tets"); file != options.methodOptions.end()) {
    MeditMesh read = readMedit(file->second);
    flipped = checkVolumeMesh(read.mesh, restCage, read.source);
    mesh = std::make_shared<VolumeMesh>(std::move(read.mesh));
  } else if (std::unique_ptr<VolumeMesh> star =
                 options.methodOptions.count("tet-level") == 0 ? starVolumeMesh(restCage) : nullptr) {
    mesh = std::move(star);  // the coarsest mesh there is, the same in every front end
  } else if (options.volumeMesher) {
    mesh = std::make_shared<VolumeMesh>(options.volumeMesher(restCage, options.methodOptions, progress));
    try {
      flipped = checkVolumeMesh(*mesh, restCage, {"the generated tetrahedral mesh", {}, {}});
    } catch (const InputError& e) {  // e.g. a sliver CGAL left flat: the user can only change the level
      throw InputError("--tet-level", -1, "the generated tetrahedral mesh is unusable: " + e.problem(),
                       "try another --tet-level, or give a tetrahedral mesh with --tets");
    }
  } else {
    throw InputError("--tets", -1, "the cage needs a tetrahedral mesh, and it is not star-shaped from its centroid",
                     "give one with --tets FILE.mesh (Python: tets=), or use a front end that tetrahedralizes cages "
                     "(the somicage command, the editor)");
  }
  if (reoriented) *reoriented = flipped;
  return mesh;
}

std::unique_ptr<CageDeformer> makeDeformer(Method method, const Cage& restCage, const Eigen::MatrixXd& points,
                                           const PrecomputeOptions& options, const ProgressCallback& progress) {
  return method->precompute(restCage, points, options, progress);
}

}  // namespace somicage
