#include "geometry/cage_proximity.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "base/errors.h"

namespace somicage {

namespace {

// Barycentric coordinates below this count as zero, so that a point on an edge or a vertex gets that feature's
// pseudo-normal, whichever face reports it first.
constexpr double kOnFeature = 1e-12;

using On = CageProximity::Closest::On;

// The closest point of the segment a -> b to x: on = Vertex (corner 0 or 1) at an end, else Edge.
Eigen::VectorXd closestOnSegment(const Eigen::VectorXd& x, const Eigen::VectorXd& a, const Eigen::VectorXd& b, On& on,
                                 int& corner) {
  const Eigen::VectorXd e = b - a;
  const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  on = On::Vertex;
  if (t <= kOnFeature) return corner = 0, a;
  if (t >= 1 - kOnFeature) return corner = 1, b;
  on = On::Edge, corner = 0;
  return a + t * e;
}

// The closest point of triangle (p0, p1, p2) to x, from its barycentric coordinates (Ericson, "Real-Time
// Collision Detection", 5.1.5): the Voronoi regions of the corners, then of the edges, then the inside.
Eigen::Vector3d closestOnTriangle(const Eigen::Vector3d& x, const Eigen::Vector3d p[3], On& on, int& corner) {
  double bary[3];
  const Eigen::Vector3d ab = p[1] - p[0], ac = p[2] - p[0];
  const Eigen::Vector3d ap = x - p[0], bp = x - p[1], cp = x - p[2];
  const double d1 = ab.dot(ap), d2 = ac.dot(ap), d3 = ab.dot(bp), d4 = ac.dot(bp), d5 = ab.dot(cp), d6 = ac.dot(cp);
  const double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
  if (d1 <= 0 && d2 <= 0) {
    bary[0] = 1, bary[1] = bary[2] = 0;
  } else if (d3 >= 0 && d4 <= d3) {
    bary[1] = 1, bary[0] = bary[2] = 0;
  } else if (d6 >= 0 && d5 <= d6) {
    bary[2] = 1, bary[0] = bary[1] = 0;
  } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    bary[1] = d1 / (d1 - d3), bary[0] = 1 - bary[1], bary[2] = 0;
  } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    bary[2] = d2 / (d2 - d6), bary[0] = 1 - bary[2], bary[1] = 0;
  } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    bary[2] = (d4 - d3) / ((d4 - d3) + (d5 - d6)), bary[1] = 1 - bary[2], bary[0] = 0;
  } else {
    const double scale = 1 / (va + vb + vc);
    bary[1] = vb * scale, bary[2] = vc * scale, bary[0] = 1 - bary[1] - bary[2];
  }
  int zeros = 0, nonZero = 0, zero = 0;
  for (int k = 0; k < 3; ++k) {
    if (bary[k] <= kOnFeature)
      bary[k] = 0, ++zeros, zero = k;
    else
      nonZero = k;
  }
  if (zeros == 2)
    on = On::Vertex, corner = nonZero;
  else if (zeros == 1)
    on = On::Edge, corner = (zero + 1) % 3;  // the edge opposite corner `zero`
  else
    on = On::Face, corner = 0;
  const double sum = bary[0] + bary[1] + bary[2];
  return (bary[0] * p[0] + bary[1] * p[1] + bary[2] * p[2]) / sum;
}

double cornerAngle(const Eigen::Vector3d& at, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - at, v = b - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

}  // namespace

CageProximity::CageProximity(const Cage& cage) : cage_(cage), skip_(cage.numFaces(), false) {
  const int d = cage.dim();
  faceNormals_ = faceNormals(cage, cage.vertices);
  vertexNormals_ = Eigen::MatrixXd::Zero(cage.numVertices(), d);
  std::map<std::pair<int, int>, Eigen::Vector3d> edgeSums;
  auto edgeKey = [&](int j, int k) {
    const int a = cage.faces(j, k), b = cage.faces(j, (k + 1) % 3);
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  for (int j = 0; j < cage.numFaces(); ++j) {
    skip_[j] = isDegenerateFace(cage, j);
    if (skip_[j]) continue;
    if (d == 2) {
      for (int k = 0; k < 2; ++k) vertexNormals_.row(cage.faces(j, k)) += faceNormals_.row(j);
      continue;
    }
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) p[k] = cage.vertices.row(cage.faces(j, k));
    const Eigen::Vector3d n = faceNormals_.row(j);
    for (int k = 0; k < 3; ++k) {
      vertexNormals_.row(cage.faces(j, k)) += cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]) * n.transpose();
      auto [it, added] = edgeSums.try_emplace(edgeKey(j, k), Eigen::Vector3d::Zero());
      it->second += n;
    }
  }
  vertexNormals_.rowwise().normalize();
  if (d == 3) {
    edgeNormals_ = Eigen::MatrixXd::Zero(3 * cage.numFaces(), 3);
    for (int j = 0; j < cage.numFaces(); ++j)
      for (int k = 0; k < 3 && !skip_[j]; ++k) edgeNormals_.row(3 * j + k) = edgeSums[edgeKey(j, k)].normalized();
  }
}

CageProximity::Closest CageProximity::closest(const Eigen::VectorXd& x) const {
  Closest best;
  best.distance = std::numeric_limits<double>::infinity();
  for (int j = 0; j < cage_.numFaces(); ++j) {
    if (skip_[j]) continue;
    Closest c;
    c.face = j;
    if (cage_.dim() == 3) {
      Eigen::Vector3d p[3];
      for (int k = 0; k < 3; ++k) p[k] = cage_.vertices.row(cage_.faces(j, k));
      c.point = closestOnTriangle(x, p, c.on, c.corner);
    } else {
      c.point = closestOnSegment(x, cage_.vertices.row(cage_.faces(j, 0)), cage_.vertices.row(cage_.faces(j, 1)), c.on,
                                 c.corner);
      if (c.on == On::Edge) c.on = On::Face;  // in 2D the faces are the edges
    }
    c.distance = (x - c.point).norm();
    if (c.distance < best.distance) best = c;
  }
  SOMICAGE_ASSERT(std::isfinite(best.distance), "the cage has a face with a normal");
  setNormal(best);
  return best;
}

bool CageProximity::coarsen(Closest& c) const {
  const Eigen::MatrixXd& V = cage_.vertices;
  auto corner = [&](int k) -> Eigen::VectorXd { return V.row(cage_.faces(c.face, k % cage_.dim())).transpose(); };
  if (c.on == On::Vertex) return false;
  if (c.on == On::Edge || cage_.dim() == 2) {  // the edge's nearer end
    const int next = c.corner + 1;
    if ((c.point - corner(next)).norm() < (c.point - corner(c.corner)).norm()) c.corner = next % cage_.dim();
    c.on = On::Vertex;
    c.point = corner(c.corner);
  } else {  // the face's nearest edge
    Closest best = c;
    double nearest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      Closest e = c;
      e.point = closestOnSegment(c.point, corner(k), corner(k + 1), e.on, e.corner);
      e.corner = e.on == On::Edge ? k : (k + e.corner) % 3;
      const double distance = (e.point - c.point).norm();
      if (distance < nearest) nearest = distance, best = e;
    }
    c = best;
  }
  setNormal(c);
  return true;
}

void CageProximity::setNormal(Closest& c) const {
  switch (c.on) {
    case On::Vertex:
      c.normal = vertexNormals_.row(cage_.faces(c.face, c.corner)).transpose();
      break;
    case On::Edge:
      c.normal = edgeNormals_.row(3 * c.face + c.corner).transpose();
      break;
    case On::Face:
      c.normal = faceNormals_.row(c.face).transpose();
      break;
  }
}

}  // namespace somicage
