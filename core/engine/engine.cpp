#include "engine/engine.h"

#include <sstream>

#include "base/errors.h"
#include "cage/cage_repair.h"
#include "cage/cage_validation.h"
#include "geometry/mesh_placement.h"

namespace somicage {

std::string describeNotice(const Notice& notice) {
  return std::string(notice.kind == Notice::Kind::Repair ? "note: " : "warning: ") +
         (notice.source.empty() ? "" : notice.source + ": ") + notice.text;
}

Cage prepareCage(Cage cage, const std::string& source, const NoticeSink& notices) {
  CageRepair repair = repairCage(cage);
  for (const std::string& fix : repair.fixes) notices({Notice::Kind::Repair, source, fix});
  const CageReport report = validateCage(repair.cage);
  for (const std::string& warning : describeCageWarnings(report)) notices({Notice::Kind::Warning, source, warning});
  requireValidCage(report, source);
  return std::move(repair.cage);
}

namespace {

// A cage read without welding from a format that may repeat a vertex per face corner (mesh_formats.h: weldApplies)
// and not closed: refused first with --weld as the remedy, before the warnings of prepareCage, whose "pairs of faces
// meet" would only be the unjoined corners touching.
void requireClosedUnwelded(const PolygonMesh& mesh, const Cage& cage, const std::string& path) {
  if (cage.dim() != 3) return;
  const std::size_t open = validateCage(cage).boundaryRidges.size();
  if (open == 0) return;
  const std::size_t openWelded = validateCage(cageFromMesh(weldVertices(mesh), path)).boundaryRidges.size();
  throw InputError(path, -1,
                   "the cage is not closed as read: " + std::to_string(open) +
                       " edges have only one face; this format may repeat a vertex for each face corner",
                   openWelded == 0 ? "read it with --weld, which joins vertices at equal positions: welded, the cage "
                                     "is closed"
                                   : "read it with --weld, which joins vertices at equal positions; welded, " +
                                         std::to_string(openWelded) +
                                         " edges still have only one face: fill those holes so that every edge has "
                                         "exactly two faces");
}

}  // namespace

Cage loadUsableCage(const std::string& path, const NoticeSink& notices, const ReadOptions& read) {
  const PolygonMesh mesh = loadAnyMesh(path, read);
  Cage cage = cageFromMesh(mesh, path);
  if (!read.weld && weldApplies(path)) requireClosedUnwelded(mesh, cage, path);
  return prepareCage(std::move(cage), path, notices);
}

Eigen::MatrixXd meshPointsFor(const Cage& cage, const Eigen::MatrixXd& meshVertices, const std::string& meshSource,
                              const std::string& cageSource, const NoticeSink& notices) {
  SOMICAGE_ASSERT(meshVertices.cols() >= cage.dim(), "a mesh has a coordinate per cage dimension");
  Eigen::MatrixXd points = meshVertices.leftCols(cage.dim());
  if (const auto warning = describeMeshPlacement(measureMeshPlacement(cage, points), meshSource, cageSource))
    notices({Notice::Kind::Warning, "", *warning});
  return points;
}

void prepareVolumeMesh(Method method, const Cage& restCage, PrecomputeOptions& options, const NoticeSink& notices,
                       const ProgressCallback& progress) {
  if (!method->needsVolumeMesh || options.volumeMesh) return;
  int reoriented = 0;
  options.volumeMesh = volumeMeshFor(restCage, options, &reoriented, progress);
  if (reoriented > 0) {
    const auto file = options.methodOptions.find("tets");
    notices({Notice::Kind::Repair, file != options.methodOptions.end() ? file->second : "",
             "reoriented " + std::to_string(reoriented) + " of " + std::to_string(options.volumeMesh->numSimplices()) +
                 " elements whose vertices were in negative order"});
  }
  if (!options.volumeMesh->fallback.empty())  // the mesher made another mesh than asked (a Mesh_3 fallback)
    notices({Notice::Kind::Warning, "", options.volumeMesh->fallback});
}

MemoryEstimate requirePrecomputeMemory(Method method, const Cage& cage, std::size_t points,
                                       const PrecomputeOptions& options, const std::string& source,
                                       const std::string& hint, bool withGradients) {
  const int vertices = layoutVertices(method, cage, options.volumeMesh.get());
  MemoryEstimate estimate = estimatePrecomputeMemory(method, cage.dim(), vertices, cage.numFaces(), points,
                                                     options.floatStorage, options.threads);
  if (withGradients)
    estimate.gradients =
        estimateGradientBytes(method, cage.dim(), vertices, cage.numFaces(), points, options.floatStorage);
  requireMemory(estimate, availableMemoryBytes(), source, hint);
  return estimate;
}

std::unique_ptr<CageDeformer> precompute(Method method, const Cage& restCage, const Eigen::MatrixXd& points,
                                         const PrecomputeOptions& options, const std::string& source,
                                         const ProgressCallback& progress, const MemoryCheck& memory) {
  PrecomputeOptions prepared = options;
  prepareVolumeMesh(method, restCage, prepared, ignoreNotices, progress);
  const MemoryEstimate estimate = requirePrecomputeMemory(
      method, restCage, static_cast<std::size_t>(points.rows()), prepared, source,
      memory.hint.empty() ? memoryHint(!options.floatStorage) : memory.hint, memory.withGradients);
  if (memory.fits) memory.fits(estimate);
  return makeDeformer(method, restCage, points, prepared, progress);
}

std::optional<Notice> exteriorPointsNotice(const CageDeformer& deformer, const std::string& meshSource) {
  const int exterior = deformer.diagnostics().exteriorCount();
  if (exterior == 0) return std::nullopt;
  return Notice{Notice::Kind::Warning, meshSource,
                std::to_string(exterior) + " of " + std::to_string(deformer.numPoints()) +
                    " points lie outside the cage (or on it); they follow the cage's best-fit similarity, blended "
                    "smoothly into the deformation inside (docs/engine.md, \"Points outside the cage\")"};
}

void requirePosedVertices(const Cage& restCage, const Eigen::MatrixXd& posed, const std::string& source) {
  requirePosedVertexCount(restCage, static_cast<long>(posed.rows()), source);
  if (posed.cols() != restCage.dim())
    throw InputError(source, -1,
                     "the posed cage has " + std::to_string(posed.cols()) + " coordinates per vertex, the rest cage " +
                         std::to_string(restCage.dim()),
                     "give the posed vertices as #V rows of x, y" + std::string(restCage.dim() == 3 ? ", z" : ""));
  for (Eigen::Index i = 0; i < posed.rows(); ++i)
    if (!posed.row(i).allFinite())
      throw InputError(source, -1, "posed vertex " + std::to_string(i) + " is not finite",
                       "every coordinate of a pose must be a finite number");
}

Eigen::MatrixXd deformPoints(const CageDeformer& deformer, const Cage& restCage, const Eigen::MatrixXd& posed,
                             const DeformParams& params, const std::string& posedSource,
                             const std::string& meshSource) {
  CpuFrameEvaluator cpu(deformer);
  return deformPoints(deformer, cpu, restCage, posed, params, posedSource, meshSource);
}

Eigen::MatrixXd deformPoints(const CageDeformer& deformer, FrameEvaluator& evaluator, const Cage& restCage,
                             const Eigen::MatrixXd& posed, const DeformParams& params, const std::string& posedSource,
                             const std::string& meshSource) {
  requirePosedVertices(restCage, posed, posedSource);
  deformer.method()->validateParams(params);
  Eigen::MatrixXd deformed;
  evaluator.evaluate(deformer.frameWeights(posed, params), deformed);
  Eigen::Index bad = 0, firstBad = -1;
  for (Eigen::Index p = 0; p < deformed.rows(); ++p)
    if (!deformed.row(p).allFinite()) bad += 1, firstBad = firstBad < 0 ? p : firstBad;
  if (bad > 0)
    throw InputError(meshSource, -1,
                     std::to_string(bad) + " of " + std::to_string(deformed.rows()) +
                         " points could not be deformed; the first is vertex " + std::to_string(firstBad),
                     "nothing was written; this is a bug (every point gets a finite position, docs/engine.md): "
                     "please report it with the input files");
  return deformed;
}

namespace {

// The quantiles of values by name: "min", "max", or "pNN" (the NN-th percentile).
NamedNumbers quantiles(const Eigen::VectorXd& values, const std::vector<std::string>& names) {
  NamedNumbers result;
  for (const std::string& name : names) {
    const double q = name == "min" ? 0.0 : name == "max" ? 1.0 : std::stod(name.substr(1)) / 100;
    result.emplace_back(name, quantile(values, q));
  }
  return result;
}

void requireFaceIndices(const std::vector<std::vector<int>>& faces, Eigen::Index points, const std::string& source) {
  for (std::size_t k = 0; k < faces.size(); ++k)
    for (const int i : faces[k])
      if (i < 0 || i >= points)
        throw InputError(
            source, -1,
            "face " + std::to_string(k) + " refers to vertex " + std::to_string(i) + " of " + std::to_string(points),
            "give faces over the deformer's points, 0-based");
}

}  // namespace

bool measuresSeamsByDefault(Method method) { return method->needsVolumeMesh; }

std::unique_ptr<SeamJumpEvaluator> prepareSeamJumps(const CageDeformer& deformer, const Cage& restCage,
                                                    const Eigen::MatrixXd& restPoints,
                                                    const std::vector<std::vector<int>>& faces,
                                                    const PrecomputeOptions& options, const std::string& facesSource,
                                                    const ProgressCallback& progress) {
  requireFaceIndices(faces, restPoints.rows(), facesSource);
  std::shared_ptr<const VolumeMesh> mesh = deformer.volumeMesh();
  if (!mesh) mesh = options.volumeMesh ? options.volumeMesh : volumeMeshFor(restCage, options);
  SeamCrossings crossings = findSeamCrossings(*mesh, faces, restPoints);
  PrecomputeOptions prepared = options;
  prepared.volumeMesh = mesh;
  requirePrecomputeMemory(deformer.method(), restCage, 2 * static_cast<std::size_t>(crossings.points.rows()), prepared,
                          facesSource, memoryHint(false), true);
  return std::make_unique<SeamJumpEvaluator>(deformer.method(), restCage, std::move(mesh), std::move(crossings),
                                             std::move(prepared), progress);
}

PoseAnalysis analyzePose(const CageDeformer& deformer, const DeformationGradients& gradients, const Cage& restCage,
                         const Eigen::MatrixXd& restPoints, const std::vector<std::vector<int>>& faces,
                         const Eigen::MatrixXd& posed, const DeformParams& params, const std::vector<double>& nus,
                         const std::string& posedSource, const std::string& facesSource,
                         const ProgressCallback& progress, const SeamJumpEvaluator* seams) {
  requirePosedVertices(restCage, posed, posedSource);
  deformer.method()->validateParams(params);
  requireFaceIndices(faces, restPoints.rows(), facesSource);
  PoseAnalysis a;
  a.fields = analyzeDeformation(gradients, restPoints, faces, posed, params, seams);
  if (seams) a.seamJump = quantiles(a.fields.seams.edges, {"p50", "p95", "max"});
  a.jacobianDet = quantiles(a.fields.points.detJ, {"min", "p05", "p50", "p95", "max"});
  a.conformalDistortion = quantiles(a.fields.points.distortion, {"p50", "p95", "max"});
  a.areaRatio = quantiles(a.fields.faces.areaRatio, {"p05", "p50", "p95", "max"});
  if (!nus.empty()) a.nuSweep = sweepNu(gradients, restPoints, faces, posed, params, nus, progress);
  return a;
}

}  // namespace somicage
