#include "coordinates/bem_layer_integrals.h"

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "base/errors.h"
#include "base/point_blocks.h"
#include "geometry/edge_integrals.h"
#include "geometry/triangle_integrals.h"

namespace somicage {

Eigen::MatrixXd assembleFaceKelvinlet(const double* t, int dim, double nu) {
  const NuCoefficients c = nuCoefficients(dim, nu);
  Eigen::MatrixXd M(dim, dim);
  if (dim == 3)
    M << t[1], t[4], t[5], t[4], t[2], t[6], t[5], t[6], t[3];
  else
    M << t[1], t[3], t[3], t[2];
  return c.k1 * t[0] * Eigen::MatrixXd::Identity(dim, dim) + c.k2 * M;
}

CoordinateLayout bemLayerLayout(int dim, int numVertices, int numFaces) {
  return {numVertices, numFaces, vertexTermCount(dim), bemFaceTermCount(dim), 0};
}

Eigen::MatrixXd BemLayerIntegrals::vertexCoordinate(int p, int i, double nu) const {
  double terms[vertexTermCount(3)];
  gatherVertexTerms(layout, values.row(p).data(), i, terms);
  return assembleVertexCoordinate(terms, dim, nu);
}

Eigen::MatrixXd BemLayerIntegrals::faceKelvinlet(int p, int j, double nu) const {
  return assembleFaceKelvinlet(values.row(p).data() + layout.faceColumn(j, 0), dim, nu);
}

namespace {

// Adds one triangle's integrals to a row (vertex terms as in somigliana_coordinates.h, face terms S, M).
void accumulateTriangle(const TriangleIntegrals& I, const Eigen::Vector3d& n, const int corners[3],
                        const CoordinateLayout& layout, double* face, double* row) {
  addVertexTerms(I, n, corners, layout, row);
  const Eigen::Matrix3d& M = I.M;
  face[0] = I.S;
  face[1] = M(0, 0), face[2] = M(1, 1), face[3] = M(2, 2), face[4] = M(0, 1), face[5] = M(0, 2), face[6] = M(1, 2);
}

void accumulateEdge(const EdgeIntegrals& I, const int ends[2], const CoordinateLayout& layout, double* face,
                    double* row) {
  addVertexTerms(I, ends, layout, row);
  face[0] = I.S, face[1] = I.M(0, 0), face[2] = I.M(1, 1), face[3] = I.M(0, 1);
}

}  // namespace

BemLayerIntegrals integrateBemLayers(const Cage& cage, const Eigen::MatrixXd& points, const std::vector<int>& onFace,
                                     int threads, const ProgressCallback& progress) {
  const int dim = cage.dim(), numPoints = static_cast<int>(points.rows());
  assertCageAndPoints(cage, points);
  SOMICAGE_ASSERT(onFace.empty() || static_cast<int>(onFace.size()) == numPoints, "one face index per point");

  BemLayerIntegrals out;
  out.dim = dim;
  out.layout = bemLayerLayout(dim, cage.numVertices(), cage.numFaces());
  out.values = RowMatrixXd::Zero(numPoints, out.layout.mainColumns());
  out.winding.resize(numPoints);
  std::vector<TriangleFrame> frames;
  if (dim == 3)
    for (int j = 0; j < cage.numFaces(); ++j)
      frames.push_back(makeTriangleFrame(cage.vertices.row(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 1)),
                                         cage.vertices.row(cage.faces(j, 2))));
  forEachPointInBlocks(
      numPoints, cage.numFaces(), threads, progress, [] { return 0; },
      [&](int, int p) {
        double* row = out.values.row(p).data();
        const int own = onFace.empty() ? -1 : onFace[static_cast<std::size_t>(p)];
        double angleSum = 0;
        for (int j = 0; j < cage.numFaces(); ++j) {
          double* face = row + out.layout.faceColumn(j, 0);
          if (dim == 3) {
            if (frames[j].degenerate) continue;
            const int corners[3] = {cage.faces(j, 0), cage.faces(j, 1), cage.faces(j, 2)};
            TriangleIntegrals I;
            if (j == own)
              integrateTriangleInteriorLimit(frames[j], points.row(p).transpose(), I);
            else
              integrateTriangle(frames[j], points.row(p).transpose(), I);
            accumulateTriangle(I, frames[j].n, corners, out.layout, face, row);
            angleSum += I.solidAngle;
          } else {
            const int ends[2] = {cage.faces(j, 0), cage.faces(j, 1)};
            const Eigen::Vector2d p0 = cage.vertices.row(ends[0]), p1 = cage.vertices.row(ends[1]);
            if (isDegenerateFace(cage, j)) continue;  // zero-length edges contribute nothing
            EdgeIntegrals I;
            if (j == own)
              integrateEdgeInteriorLimit(p0, p1, points.row(p).transpose(), I);
            else
              integrateEdge(p0, p1, points.row(p).transpose(), I);
            accumulateEdge(I, ends, out.layout, face, row);
            angleSum += I.angle;
          }
        }
        out.winding(p) = -angleSum / (dim == 3 ? 4 * M_PI : 2 * M_PI);
      });
  return out;
}

}  // namespace somicage
