// libFuzzer target: precompute + deform for every method on small random cages.
// The bytes are decoded (FuzzedDataProvider) into a perturbed octahedron or icosahedron (3D) or a jittered
// polygon (2D) at a random scale and offset, a few query points (near the centre, near a face, anywhere in the
// box), a posed cage (noisy, a similarity, collapsed to a point, or flattened) and the parameters. Cages that
// validateCage rejects are skipped, as the command line refuses them.
// Contract: no crash and no sanitizer report; either InputError (bad parameters) or an output whose rows are
// finite for every point that is inside (winding >= 1/2) and farther than 1e-6 diameters from the cage.
#include <fuzzer/FuzzedDataProvider.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "base/errors.h"
#include "cage/cage_validation.h"
#include "deform/deformer.h"
#include "geometry/cage.h"
#include "methods/method_descriptors.h"

namespace {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using somicage::Cage;

constexpr double kPi = 3.14159265358979323846;

void require(bool condition, const char* what) {
  if (condition) return;
  std::fprintf(stderr, "fuzz_precompute_deform: contract violated: %s\n", what);
  std::abort();
}

double uniform(FuzzedDataProvider& in, double lo, double hi) { return in.ConsumeFloatingPointInRange(lo, hi); }

// ---- Cages ---------------------------------------------------------------------------------------------------

Cage octahedron() {
  Cage c;
  c.vertices.resize(6, 3);
  c.vertices << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  c.faces.resize(8, 3);
  c.faces << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  return c;
}

Cage icosahedron() {
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  Cage c;
  c.vertices.resize(12, 3);
  c.vertices << -1, p, 0, 1, p, 0, -1, -p, 0, 1, -p, 0, 0, -1, p, 0, 1, p, 0, -1, -p, 0, 1, -p, p, 0, -1, p, 0, 1, -p,
      0, -1, -p, 0, 1;
  c.vertices /= std::sqrt(1.0 + p * p);
  c.faces.resize(20, 3);
  c.faces << 0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4,
      3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1;
  return c;
}

// A polygon of n vertices around the unit circle, counter-clockwise unless the jitter folds it.
Cage jitteredPolygon(FuzzedDataProvider& in) {
  const int n = in.ConsumeIntegralInRange(3, 12);
  const double angleJitter = in.ConsumeProbability<double>();
  const double radiusJitter = in.ConsumeProbability<double>();
  MatrixXd loop(n, 2);
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * kPi * (k + angleJitter * uniform(in, -1.0, 1.0)) / n;
    const double radius = 1.0 + radiusJitter * uniform(in, -0.95, 2.0);
    loop.row(k) << radius * std::cos(angle), radius * std::sin(angle);
  }
  return somicage::makePolygonCage(loop);
}

Cage fuzzedCage(FuzzedDataProvider& in, int dim) {
  Cage cage;
  if (dim == 2) {
    cage = jitteredPolygon(in);
  } else {
    cage = in.ConsumeBool() ? icosahedron() : octahedron();
    const double amplitude = in.ConsumeProbability<double>();
    for (Eigen::Index i = 0; i < cage.vertices.size(); ++i) cage.vertices(i) += amplitude * uniform(in, -1.0, 1.0);
  }
  // Scales from 1e-6 to 1e6, offsets up to 100 sizes away: the integrals must be scale- and position-faithful.
  const double scale = std::pow(10.0, in.ConsumeIntegralInRange(-6, 6));
  cage.vertices *= scale;
  for (int c = 0; c < dim; ++c) cage.vertices.col(c).array() += scale * uniform(in, -100.0, 100.0);
  return cage;
}

// ---- Query points --------------------------------------------------------------------------------------------

MatrixXd fuzzedPoints(FuzzedDataProvider& in, const Cage& cage) {
  const int dim = cage.dim();
  const Eigen::RowVectorXd centre = cage.vertices.colwise().mean();
  const Eigen::RowVectorXd lo = cage.vertices.colwise().minCoeff(), hi = cage.vertices.colwise().maxCoeff();
  const double diameter = somicage::cageDiameter(cage.vertices);
  const MatrixXd normals = somicage::faceNormals(cage, cage.vertices);
  MatrixXd points(in.ConsumeIntegralInRange(1, 8), dim);
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    switch (in.ConsumeIntegralInRange(0, 2)) {
      case 0: {  // on the segment from the centre through a vertex, up to a little beyond it
        const int v = in.ConsumeIntegralInRange(0, cage.numVertices() - 1);
        points.row(p) = centre + uniform(in, 0.0, 1.2) * (cage.vertices.row(v) - centre);
        break;
      }
      case 1: {  // a point of a face, pushed off it by 1e-12 to 1 diameters on either side
        const int f = in.ConsumeIntegralInRange(0, cage.numFaces() - 1);
        Eigen::VectorXd weights(dim);
        for (int k = 0; k < dim; ++k) weights[k] = in.ConsumeProbability<double>() + 1e-3;
        weights /= weights.sum();
        Eigen::RowVectorXd onFace = Eigen::RowVectorXd::Zero(dim);
        for (int k = 0; k < dim; ++k) onFace += weights[k] * cage.vertices.row(cage.faces(f, k));
        const double offset = std::pow(10.0, -in.ConsumeIntegralInRange(0, 12)) * diameter;
        points.row(p) = onFace + (in.ConsumeBool() ? offset : -offset) * normals.row(f);
        break;
      }
      default:  // anywhere in the box, enlarged by half its size
        for (int c = 0; c < dim; ++c) {
          const double margin = 0.5 * (hi[c] - lo[c]);
          points(p, c) = uniform(in, lo[c] - margin, hi[c] + margin);
        }
    }
  }
  return points;
}

// ---- Posed cage and parameters -------------------------------------------------------------------------------

MatrixXd fuzzedPose(FuzzedDataProvider& in, const Cage& cage) {
  const int dim = cage.dim();
  const double diameter = somicage::cageDiameter(cage.vertices);
  MatrixXd pose = cage.vertices;
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0: {  // independent noise per coordinate, up to a diameter
      const double amplitude = in.ConsumeProbability<double>() * diameter;
      for (Eigen::Index i = 0; i < pose.size(); ++i) pose(i) += amplitude * uniform(in, -1.0, 1.0);
      break;
    }
    case 1: {  // a similarity: rotation, scale 1e-3 .. 1e3, translation
      MatrixXd R(dim, dim);
      const double angle = uniform(in, -kPi, kPi);
      if (dim == 2) {
        R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
      } else {
        Vector3d axis(uniform(in, -1.0, 1.0), uniform(in, -1.0, 1.0), uniform(in, -1.0, 1.0));
        if (axis.norm() < 1e-3) axis = Vector3d::UnitZ();
        R = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
      }
      const double scale = std::pow(10.0, uniform(in, -3.0, 3.0));
      pose = scale * pose * R.transpose();
      for (int c = 0; c < dim; ++c) pose.col(c).array() += diameter * uniform(in, -10.0, 10.0);
      break;
    }
    case 2:  // every vertex at one point
      pose.rowwise() = cage.vertices.row(0);
      break;
    default:  // flattened onto a coordinate plane (3D) or axis (2D)
      pose.col(in.ConsumeIntegralInRange(0, dim - 1)).setConstant(cage.vertices(0, 0));
  }
  return pose;
}

somicage::DeformParams fuzzedParams(FuzzedDataProvider& in) {
  somicage::DeformParams params;
  params.blend = in.ConsumeProbability<double>();
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0:
      params.nu = uniform(in, -0.999, 0.499);
      break;
    case 1:
      params.nu = std::numeric_limits<double>::infinity();
      break;
    case 2:
      params.nu = -std::numeric_limits<double>::infinity();
      break;
    default:
      params.nu = in.ConsumeFloatingPoint<double>();  // mostly out of range: must be an InputError
  }
  params.gamma = uniform(in, 0.0, 5.0);
  params.tractionCorrection = in.ConsumeBool();
  return params;
}

// ---- Inside / distance (independent of the library) ----------------------------------------------------------

// Generalised winding number: solid angles (3D, Van Oosterom and Strackee) or signed angles (2D) of the faces.
double windingNumber(const Cage& cage, const Eigen::RowVectorXd& x) {
  double sum = 0.0;
  for (int f = 0; f < cage.numFaces(); ++f) {
    if (cage.dim() == 3) {
      const Vector3d a = (cage.vertices.row(cage.faces(f, 0)) - x).transpose();
      const Vector3d b = (cage.vertices.row(cage.faces(f, 1)) - x).transpose();
      const Vector3d c = (cage.vertices.row(cage.faces(f, 2)) - x).transpose();
      const double la = a.norm(), lb = b.norm(), lc = c.norm();
      sum += 2.0 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
    } else {
      const Eigen::Vector2d a = (cage.vertices.row(cage.faces(f, 0)) - x).transpose();
      const Eigen::Vector2d b = (cage.vertices.row(cage.faces(f, 1)) - x).transpose();
      sum += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  }
  return sum / (cage.dim() == 3 ? 4.0 * kPi : 2.0 * kPi);
}

// Distance from p to the triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
double triangleDistance(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  const Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * vb * denom + ac * vc * denom)).norm();
}

double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

double distanceToCage(const Cage& cage, const Eigen::RowVectorXd& x) {
  double best = std::numeric_limits<double>::infinity();
  for (int f = 0; f < cage.numFaces(); ++f) {
    if (cage.dim() == 3) {
      best = std::min(best, triangleDistance(x.transpose(), cage.vertices.row(cage.faces(f, 0)).transpose(),
                                             cage.vertices.row(cage.faces(f, 1)).transpose(),
                                             cage.vertices.row(cage.faces(f, 2)).transpose()));
    } else {
      best = std::min(best, segmentDistance(x.transpose(), cage.vertices.row(cage.faces(f, 0)).transpose(),
                                            cage.vertices.row(cage.faces(f, 1)).transpose()));
    }
  }
  return best;
}

// The decoded case, so that a finding can be turned into a regression test without replaying the decoder.
void printCase(const Cage& cage, const MatrixXd& points, const MatrixXd& pose, const somicage::DeformParams& params,
               bool floatStorage) {
  const Eigen::IOFormat full(17, 0, " ", "\n", "  ");
  std::cerr << "cage vertices:\n"
            << cage.vertices.format(full) << "\ncage faces:\n"
            << cage.faces << "\npoints:\n"
            << points.format(full) << "\npose:\n"
            << pose.format(full) << "\nblend " << params.blend << " nu " << params.nu << " gamma " << params.gamma
            << " traction fix " << params.tractionCorrection << " float storage " << floatStorage << "\n";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  const int dim = in.ConsumeBool() ? 3 : 2;
  const Cage cage = fuzzedCage(in, dim);
  if (!somicage::validateCage(cage).valid()) return 0;  // the command line refuses it

  const MatrixXd points = fuzzedPoints(in, cage);
  const MatrixXd pose = fuzzedPose(in, cage);
  const somicage::DeformParams params = fuzzedParams(in);
  somicage::PrecomputeOptions options;
  options.threads = 1;
  options.integration.threads = 1;
  options.floatStorage = in.ConsumeBool();

  const double diameter = somicage::cageDiameter(cage.vertices);
  std::vector<bool> mustBeFinite(static_cast<std::size_t>(points.rows()));
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    mustBeFinite[static_cast<std::size_t>(p)] =
        windingNumber(cage, points.row(p)) >= 0.5 && distanceToCage(cage, points.row(p)) > 1e-6 * diameter;
  }

  for (somicage::Method method : somicage::allMethods()) {
    try {
      const auto deformer = somicage::makeDeformer(method, cage, points, options);
      const MatrixXd out = deformer->deform(pose, params);
      require(out.rows() == points.rows() && out.cols() == dim, "the output has one row of d numbers per point");
      for (Eigen::Index p = 0; p < points.rows(); ++p) {
        if (mustBeFinite[static_cast<std::size_t>(p)] && !out.row(p).allFinite()) {
          std::fprintf(stderr, "method %s, point %ld\n", somicage::methodName(method).c_str(), static_cast<long>(p));
          printCase(cage, points, pose, params, options.floatStorage);
          require(false, "a point inside the cage and away from it deforms to a finite position");
        }
      }
    } catch (const somicage::InputError& e) {
      require(std::string(e.what()).size() > 0, "an InputError says what is wrong");
    }
  }
  return 0;
}
