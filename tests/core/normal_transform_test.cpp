// Normals carried by the deformation's gradient (core/animation/normal_transform.h) against exact cases: an affine cage
// pose A under mean value coordinates (which reproduce affine maps, so J = A) gives n' = A^-T n / |A^-T n| to 1e-9 for
// per-vertex and shared `vn`; a rotation under Somigliana coordinates keeps every angle between a normal and the
// faces around it (1e-9 rad); a vertex outside the cage, which has no J, gets the recomputed normal.
#include "animation/normal_transform.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "geometry/cage.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

// An octahedron inside the unit cube: one smooth `vn` per vertex (not the faces' normals), except that the face
// 1-2-5 has one flat `vn` (index 7) named at its three corners.
const char* const kObj =
    "v 0.5 0 0\nv 0 0.5 0\nv -0.5 0 0\nv 0 -0.5 0\nv 0 0 0.5\nv 0.1 0.1 -0.5\n"
    "vn 1 0.2 0\nvn 0.1 1 0.3\nvn -1 0 0.2\nvn 0 -1 0\nvn 0.2 0 1\nvn 0 0.1 -1\nvn 1 1 1\n"
    "f 1//7 2//7 5//7\nf 2//2 3//3 5//5\nf 3//3 4//4 5//5\nf 4//4 1//1 5//5\n"
    "f 2//2 1//1 6//6\nf 3//3 2//2 6//6\nf 4//4 3//3 6//6\nf 1//1 4//4 6//6\n";

struct Posed {
  MeshDocument document;
  Eigen::MatrixXd positions;
  TransformedNormals normals;
};

Posed deformWith(Method method, const Eigen::Matrix3d& A, const Eigen::Vector3d& t, const char* obj = kObj) {
  Posed out;
  out.document = parseObjDocument(obj, "oct.obj");
  const Cage cage = test::makeCube();
  const Eigen::MatrixXd& points = out.document.geometry.vertices;
  const std::unique_ptr<CageDeformer> deformer = makeDeformer(method, cage, points);
  const Eigen::MatrixXd posed = (cage.vertices * A.transpose()).rowwise() + t.transpose();
  const DeformParams params;
  out.positions = deformer->deform(posed, params);
  const DeformationGradients gradients(*deformer, points);
  out.normals = transformNormals(out.document, out.positions, gradients, posed, params);
  return out;
}

TEST(NormalTransform, AnAffinePoseGivesTheInverseTransposeNormal) {
  Eigen::Matrix3d A;
  A << 1.3, 0.4, -0.2, 0.1, 0.8, 0.3, -0.25, 0.2, 1.1;
  const Posed posed = deformWith(methods::mvc(), A, Eigen::Vector3d(0.1, -0.2, 0.05));
  EXPECT_EQ(posed.normals.recomputed, 0);
  const Eigen::Matrix3d inverseTranspose = A.inverse().transpose();
  double worst = 0;
  for (int n = 0; n < posed.document.normalCount; ++n) {
    const Eigen::Vector3d expected = (inverseTranspose * posed.document.normals.row(n).transpose()).normalized();
    worst = std::max(worst, (posed.normals.normals.row(n).transpose() - expected).norm());
  }
  EXPECT_LE(worst, 1e-9) << "largest |n' - A^-T n / |A^-T n||";
}

// The angle between vn and the unit normal of each face whose corner names it.
std::vector<double> normalFaceAngles(const MeshDocument& document, const Eigen::MatrixXd& positions,
                                     const Eigen::MatrixXd& normals) {
  std::vector<double> angles;
  for (size_t f = 0; f < document.geometry.faces.size(); ++f) {
    const std::vector<int>& face = document.geometry.faces[f];
    const Eigen::Vector3d a = positions.row(face[0]), b = positions.row(face[1]), c = positions.row(face[2]);
    const Eigen::Vector3d faceNormal = (b - a).cross(c - a).normalized();
    for (size_t k = 0; k < 3; ++k) {
      const Eigen::Vector3d n = normals.row(document.faceNormals[f][k]).normalized();
      angles.push_back(std::atan2(n.cross(faceNormal).norm(), n.dot(faceNormal)));
    }
  }
  return angles;
}

TEST(NormalTransform, ARotationKeepsTheAnglesBetweenNormalsAndFaces) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
  const Posed posed = deformWith(methods::somigliana(), R, Eigen::Vector3d(0.3, 0, -0.1));
  EXPECT_EQ(posed.normals.recomputed, 0);
  const std::vector<double> rest =
      normalFaceAngles(posed.document, posed.document.geometry.vertices, posed.document.normals);
  const std::vector<double> moved = normalFaceAngles(posed.document, posed.positions, posed.normals.normals);
  ASSERT_EQ(rest.size(), moved.size());
  double worst = 0;
  for (size_t i = 0; i < rest.size(); ++i) worst = std::max(worst, std::abs(rest[i] - moved[i]));
  EXPECT_LE(worst, 1e-9) << "largest change of a normal-face angle (rad)";
  EXPECT_GT(rest[3], 0.1) << "the smooth normals are not the faces' own (the test would be empty)";
}

TEST(NormalTransform, AVertexWithoutAGradientGetsTheRecomputedNormal) {
  std::string obj = kObj;
  obj.replace(obj.find("v 0.1 0.1 -0.5"), 14, "v 0.1 0.1 -1.5");  // vertex 6 leaves the cage
  Eigen::Matrix3d A = 1.2 * Eigen::Matrix3d::Identity();
  const Posed posed = deformWith(methods::somigliana(), A, Eigen::Vector3d::Zero(), obj.c_str());
  EXPECT_EQ(posed.normals.recomputed, 1) << "only vn 6, which names vertex 6 alone";
  const Eigen::MatrixXd recomputed = recomputeNormals(posed.document, posed.positions);
  EXPECT_LE((posed.normals.normals.row(5) - recomputed.row(5)).norm(), 1e-15);
  EXPECT_LE((posed.normals.normals.row(4) - posed.document.normals.row(4).normalized()).norm(), 1e-9)
      << "a uniform scale leaves the other normals' directions";
}

// A 2D cage moves x and y and keeps z: J is the 2 by 2 gradient extended by J_zz = 1. A prism's side normals
// (in the plane) become A^-T n of the planar affine map A, its top normal stays +z.
TEST(NormalTransform, ATwoDimensionalMapKeepsZ) {
  Eigen::MatrixXd square(4, 2);
  square << -1, -1, 1, -1, 1, 1, -1, 1;
  const Cage cage = makePolygonCage(square);
  const MeshDocument document = parseObjDocument(
      "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0 0.5 0\nv -0.5 -0.5 1\nv 0.5 -0.5 1\nv 0 0.5 1\n"
      "vn 0 -1 0\nvn 1 0.5 0\nvn 0 0 1\n"
      "f 1//1 2//1 5//1 4//1\nf 2//2 3//2 6//2 5//2\nf 4//3 5//3 6//3\n",
      "prism.obj");
  const Eigen::MatrixXd points = document.geometry.vertices.leftCols(2);
  const std::unique_ptr<CageDeformer> deformer = makeDeformer(methods::mvc(), cage, points);
  Eigen::Matrix2d A;
  A << 1.4, 0.3, -0.2, 0.7;
  const Eigen::MatrixXd posed = cage.vertices * A.transpose();
  const DeformationGradients gradients(*deformer, points);
  Eigen::MatrixXd positions = document.geometry.vertices;
  positions.leftCols(2) = deformer->deform(posed, DeformParams());
  const TransformedNormals out = transformNormals(document, positions, gradients, posed, DeformParams());
  EXPECT_EQ(out.recomputed, 0);
  for (int n = 0; n < 2; ++n) {
    Eigen::Vector3d expected = Eigen::Vector3d::Zero();
    expected.head<2>() = (A.inverse().transpose() * document.normals.row(n).head<2>().transpose()).normalized();
    EXPECT_LE((out.normals.row(n).transpose() - expected).norm(), 1e-9) << "side " << n;
  }
  EXPECT_LE((out.normals.row(2) - Eigen::RowVector3d(0, 0, 1)).norm(), 1e-12) << "the top stays up";
}

}  // namespace
}  // namespace somicage
