#include "geometry/mesh_placement.h"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>

namespace somicage {

namespace {

using Box = Eigen::AlignedBox<double, Eigen::Dynamic>;

Box boundingBox(const Eigen::MatrixXd& points) {
  Box box(points.cols());
  for (Eigen::Index i = 0; i < points.rows(); ++i) box.extend(points.row(i).transpose());
  return box;
}

// "1000", "25.4", "0.001": the ratio as a person reads it.
std::string readable(double ratio) {
  std::ostringstream out;
  out.precision(ratio >= 10 ? 0 : 3);
  if (ratio >= 10) out << std::fixed;
  out << ratio;
  return out.str();
}

}  // namespace

MeshPlacement measureMeshPlacement(const Cage& cage, const Eigen::MatrixXd& points) {
  MeshPlacement placement;
  if (points.rows() == 0 || cage.numVertices() == 0) return placement;
  const Box mesh = boundingBox(points.leftCols(cage.dim())), cageBox = boundingBox(cage.vertices);
  const double meshSize = mesh.diagonal().norm(), cageSize = cageBox.diagonal().norm();
  if (!(cageSize > 0) || !std::isfinite(meshSize)) return placement;
  placement.sizeRatio = meshSize / cageSize;
  placement.disjoint = !mesh.intersects(cageBox);
  return placement;
}

std::optional<std::string> describeMeshPlacement(const MeshPlacement& placement, const std::string& meshPath,
                                                 const std::string& cagePath) {
  const std::string files = "the mesh " + meshPath + " and the cage " + cagePath;
  const std::string units =
      ": are the two files in different units (millimetres and metres, inches and centimetres)? Scale one of them "
      "to match the other";
  if (placement.sizeRatio > kMeshLargerThanCage)
    return files + " do not fit: the mesh is " + readable(placement.sizeRatio) + " times the size of the cage" + units +
           "; points outside the cage only follow its best-fit similarity";
  if (placement.sizeRatio > 0 && placement.sizeRatio < kMeshSmallerThanCage)
    return files + " do not fit: the mesh is " + readable(1 / placement.sizeRatio) + " times smaller than the cage" +
           units;
  if (placement.disjoint)
    return files +
           " do not overlap: the mesh lies beside the cage, so no point of it is deformed by the cage's "
           "coordinates; move one of them (different origins?) so that the cage encloses the mesh";
  return std::nullopt;
}

}  // namespace somicage
