#include "model/fig8_demo.h"

#include <Eigen/Geometry>
#include <memory>
#include <utility>

#include "deform/parameter_schema.h"
#include "methods/method_descriptors.h"
#include "model/scene.h"

namespace somicage::editor {

std::vector<ViewSpec> fig8Views() {
  ViewSpec coarse{methods::phong(), {}, {}};
  ViewSpec fine = coarse;
  fine.options["tet-level"] = kFig8FineTetLevel;
  const double local = parseParameter(*findParameter("variant"), "local", "the Fig. 8 demo");
  const ViewSpec somigliana{methods::somigliana(), {{"nu", 0.0}, {"variant", local}}, {}};
  return {coarse, fine, somigliana};
}

Eigen::MatrixXd fig8Pose(const Cage& restCage) {
  const double halfLength = restCage.vertices.col(0).cwiseAbs().maxCoeff();
  Eigen::MatrixXd pose = restCage.vertices;
  for (Eigen::Index v = 0; v < pose.rows(); ++v) {
    const double angle = kFig8TwistRadians * pose(v, 0) / halfLength;
    const double t = pose(v, 0) / halfLength;
    pose.row(v) = (Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()) * pose.row(v).transpose()).transpose();
    pose(v, 1) += kFig8ArchHeight * (1 - t * t);
  }
  return pose;
}

void requestFig8Demo(AppState& state, bool keepViews) {
  auto scene = std::make_shared<Scene>(makeDemoScene(3));
  scene->name = "Fig. 8 demo (3D bar)";
  if (!keepViews) {  // set before the request, which precomputes the views' deformers
    state.view.compareViews = fig8Views();
    state.view.compare = true;
    state.view.quantities.clearSweep();
  }
  PendingLoad load;
  load.pose = fig8Pose(scene->restCage);
  requestScene(state, std::move(scene), std::move(load));
}

}  // namespace somicage::editor
