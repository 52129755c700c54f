#include "generation/cage_generation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "base/errors.h"
#include "cage/cage_validation.h"
#include "generation/cage_enclosure.h"
#include "generation/cage_shrink.h"
#include "generation/cage_simplification.h"
#include "generation/offset_surface.h"

namespace somicage {

namespace {

constexpr int kMaxAttempts = 4;
constexpr int kMaxRepairRounds = 8;
constexpr double kMarginGrowth = 1.5;  // per rejected attempt
constexpr double kClearance = 0.5;     // the shrink step keeps vertices this many voxels from the mesh
constexpr double kShrinkFrom = 0.9;    // of the progress bar: the tries before, the shrink step after

// Voxels per diagonal: enough to resolve what maxFaces faces can show (edges of about 1/sqrt(maxFaces) diagonals)
// several times over, bounded so that large budgets stay fast.
double voxelSizeFor(int maxFaces) { return 1.0 / std::clamp(5.0 * std::sqrt(double(maxFaces)), 48.0, 128.0); }

// Area-weighted outward vertex normals.
Eigen::MatrixXd vertexNormals(const Cage& cage) {
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(cage.numVertices(), 3);
  for (int j = 0; j < cage.numFaces(); ++j) {
    const Eigen::Vector3d a = cage.vertices.row(cage.faces(j, 0)), b = cage.vertices.row(cage.faces(j, 1)),
                          c = cage.vertices.row(cage.faces(j, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) normals.row(cage.faces(j, k)) += n.transpose();
  }
  for (int i = 0; i < cage.numVertices(); ++i)
    if (normals.row(i).norm() > 0) normals.row(i).normalize();
  return normals;
}

// Moves the corners of the given faces outward by `step`.
void pushOutward(Cage& cage, const std::set<int>& faces, double step) {
  const Eigen::MatrixXd normals = vertexNormals(cage);
  std::set<int> corners;
  for (int f : faces)
    for (int k = 0; k < 3; ++k) corners.insert(cage.faces(f, k));
  for (int v : corners) cage.vertices.row(v) += step * normals.row(v);
}

struct Attempt {
  Cage cage;
  std::string failure;  // empty: a valid cage
  int repairRounds = 0;
};

// One try at a given margin: offset, simplify, scale back, check and repair.
Attempt attempt(const Eigen::MatrixXd& unitVertices, const Eigen::MatrixXi& triangles, const Eigen::RowVector3d& center,
                double diagonal, const Eigen::MatrixXd& vertices, const CageGenerationOptions& options, double margin,
                double voxel, const ProgressCallback& progress) {
  Attempt result;
  OffsetSurfaceOptions offset;
  offset.voxelSize = voxel;
  offset.offset = margin;
  // A quarter of the margin leaves the coarse cages room to move; at least a voxel, or marching cubes may leave holes
  // in a barrier that close to the mesh.
  offset.barrier = std::max(0.25 * margin, voxel);
  offset.closing = std::max(2.0 * voxel, 0.5 / std::sqrt(double(options.maxFaces)));
  const OffsetSurfaces surfaces = offsetSurfaces(unitVertices, triangles, offset);
  if (!progress(0.15)) throw Cancelled();

  SimplificationOptions simplification;
  simplification.maxFaces = options.maxFaces;
  simplification.minAngleDegrees = options.minAngleDegrees;
  const SimplificationResult simplified =
      simplifyOutsideBarrier(surfaces.surface, surfaces.barrier, unitVertices, triangles, simplification,
                             [&](double done) { return progress(0.15 + 0.75 * done); });
  if (!simplified.budgetMet) {
    std::ostringstream why;
    why << "the simplification stopped at " << simplified.surface.numFaces() << " faces";
    result.failure = why.str();
    return result;
  }
  result.cage = simplified.surface;
  result.cage.vertices = (result.cage.vertices * diagonal).rowwise() + center;

  for (;; ++result.repairRounds) {
    if (!progress(0.9 + 0.1 * result.repairRounds / (kMaxRepairRounds + 1))) throw Cancelled();
    const CageReport report = validateCage(result.cage);
    if (!report.closed() || !report.manifold() || !report.outward()) {
      result.failure = describeCageProblems(report).front();
      return result;
    }
    const EnclosureReport enclosure = checkEnclosure(result.cage, vertices, triangles);
    if (!enclosure.selfIntersections.empty()) {
      result.failure = "the cage intersects itself";
      return result;
    }
    if (enclosure.encloses()) return result;
    if (result.repairRounds == kMaxRepairRounds) {
      std::ostringstream why;
      why << enclosure.outsideVertices.size() << " mesh vertices stayed outside and " << enclosure.crossedFaces.size()
          << " cage faces crossed by mesh edges after " << kMaxRepairRounds << " rounds of pushing the cage outward";
      result.failure = why.str();
      return result;
    }
    std::set<int> faces(enclosure.crossedFaces.begin(), enclosure.crossedFaces.end());
    faces.insert(enclosure.nearestFaces.begin(), enclosure.nearestFaces.end());
    pushOutward(result.cage, faces, voxel * diagonal * std::ldexp(0.25, result.repairRounds));
  }
}

// The box [lower - pad, upper + pad] as 12 outward triangles.
Cage boundingBoxCage(const Eigen::RowVector3d& lower, const Eigen::RowVector3d& upper, double pad) {
  Cage box;
  box.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i)
    for (int axis = 0; axis < 3; ++axis)
      box.vertices(i, axis) = (i >> axis) & 1 ? upper(axis) + pad : lower(axis) - pad;
  box.faces.resize(12, 3);
  box.faces << 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7,
      5;
  return box;
}

// A valid cage within the budget that the exact check finds enclosing the mesh.
bool provenCage(const Cage& cage, const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles,
                const CageGenerationOptions& options) {
  return cage.numFaces() <= options.maxFaces && validateCage(cage).valid() &&
         checkEnclosure(cage, vertices, triangles).encloses();
}

}  // namespace

double minimumAngleDegrees(const Cage& cage) {
  double smallest = 180.0;
  for (int j = 0; j < cage.numFaces(); ++j)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d o = cage.vertices.row(cage.faces(j, k));
      const Eigen::Vector3d u = Eigen::Vector3d(cage.vertices.row(cage.faces(j, (k + 1) % 3))) - o;
      const Eigen::Vector3d v = Eigen::Vector3d(cage.vertices.row(cage.faces(j, (k + 2) % 3))) - o;
      smallest = std::min(smallest, std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / M_PI);
    }
  return smallest;
}

GeneratedCage generateCage(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles,
                           const CageGenerationOptions& options, const std::string& source,
                           const ProgressCallback& progress) {
  if (options.maxFaces < CageGenerationOptions::kMinFaces)
    throw InputError(source, -1, "a cage needs at least " + std::to_string(CageGenerationOptions::kMinFaces) + " faces",
                     "ask for more faces");
  if (!(options.margin >= 0 && options.margin < 1))
    throw InputError(source, -1, "the margin must be in [0, 1) bounding-box diagonals",
                     "give a margin like 0.02, or none for an automatic one");
  if (triangles.rows() == 0 || vertices.rows() == 0)
    throw InputError(source, -1, "the mesh has no faces to make a cage around", "give a mesh with faces");
  if (!vertices.allFinite())
    throw InputError(source, -1, "the mesh has a coordinate that is not finite", "fix the file");
  const Eigen::RowVector3d lower = vertices.colwise().minCoeff(), upper = vertices.colwise().maxCoeff();
  const double diagonal = (upper - lower).norm();
  if (!(diagonal > 0))
    throw InputError(source, -1, "the mesh has no extent (all vertices at one point)", "fix the file");
  const Eigen::RowVector3d center = 0.5 * (lower + upper);
  const Eigen::MatrixXd unitVertices = (vertices.rowwise() - center) / diagonal;

  const double voxel = voxelSizeFor(options.maxFaces);
  GeneratedCage generated;
  generated.voxelSize = voxel;
  generated.margin = options.margin > 0 ? std::max(options.margin, 1.5 * voxel) : 2.0 * voxel;
  std::string failures;
  for (generated.attempts = 1; generated.attempts <= kMaxAttempts; ++generated.attempts) {
    // The first try takes 70% of the bar, each retry 70% of what is left.
    const double from = 1.0 - std::pow(0.3, generated.attempts - 1), span = 0.7 * (1.0 - from);
    Attempt tried = attempt(unitVertices, triangles, center, diagonal, vertices, options, generated.margin, voxel,
                            [&](double done) { return progress(kShrinkFrom * (from + span * done)); });
    if (tried.failure.empty()) {
      generated.cage = std::move(tried.cage);
      ShrinkOptions shrink;
      shrink.clearance = kClearance * voxel * diagonal;
      shrink.minAngleDegrees = options.minAngleDegrees;
      Cage shrunk = generated.cage;
      shrinkTowardMesh(shrunk, vertices, triangles, shrink,
                       [&](double done) { return progress(kShrinkFrom + (1 - kShrinkFrom) * done); });
      // Every move was proven safe; the exact check still has the last word.
      if (provenCage(shrunk, vertices, triangles, options)) generated.cage = std::move(shrunk);
      // On box-like shapes the bounding box, tightened the same way, fits better than any offset surface.
      Cage box = boundingBoxCage(lower, upper, shrink.clearance);
      shrinkTowardMesh(box, vertices, triangles, shrink);
      if (minimumAngleDegrees(box) >= options.minAngleDegrees && provenCage(box, vertices, triangles, options) &&
          hausdorffCageToMesh(box, vertices, triangles) < hausdorffCageToMesh(generated.cage, vertices, triangles))
        generated.cage = std::move(box);
      generated.repairRounds = tried.repairRounds;
      generated.minAngleDegrees = minimumAngleDegrees(generated.cage);
      generated.tightness = measureTightness(generated.cage, vertices, triangles);
      progress(1.0);
      return generated;
    }
    std::ostringstream line;
    line << (failures.empty() ? "" : "; ") << "margin " << generated.margin << ": " << tried.failure;
    failures += line.str();
    generated.margin *= kMarginGrowth;
  }
  throw InputError(source, -1,
                   "no valid cage with at most " + std::to_string(options.maxFaces) + " faces (" + failures + ")",
                   "ask for more faces, or a larger margin");
}

}  // namespace somicage
