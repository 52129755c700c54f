#include "cage/cage_check.h"

namespace somicage {

CageCheck checkCage(const Cage& cage) {
  CageCheck check;
  check.report = validateCage(cage);
  check.problems = describeCageProblems(check.report);
  check.repair = repairCage(cage);
  check.repairedReport = check.repair.fixes.empty() ? check.report : validateCage(check.repair.cage);
  check.warnings = describeCageWarnings(check.repairedReport);
  return check;
}

ReportFields cageCheckFields(const CageCheck& check) {
  const CageReport& r = check.report;
  const auto count = [](std::size_t n) { return ReportValue(static_cast<int>(n)); };
  const bool is3d = r.dim == 3;
  return {
      {"dim", r.dim},
      {"cage_vertices", r.numVertices},
      {"cage_faces", r.numFaces},
      {"valid", r.valid()},
      {"closed", r.closed()},
      {"manifold", r.manifold()},
      {"consistently_oriented", r.consistentlyOriented()},
      {"outward", r.outward()},
      {"simple", is3d ? ReportValue(nullptr) : ReportValue(r.simple())},  // self-intersection is a 2D problem only
      {is3d ? "signed_volume" : "signed_area", r.signedVolume},
      {"diameter", r.diameter},
      {"components", r.components},
      {"boundary_edges", count(r.boundaryRidges.size())},
      {"non_manifold_edges", count(r.nonManifoldRidges.size())},
      {"misoriented_edges", count(r.misorientedRidges.size())},
      {"degenerate_faces", count(r.degenerateFaces.size())},
      {"duplicate_vertices", count(r.duplicateVertices.size())},
      {"unreferenced_vertices", count(r.unreferencedVertices.size())},
      {"problems", check.problems},
      {"repairs", check.repair.fixes},
      {"usable", check.usable()},
      {"warnings", check.warnings},
      // Of the cage deform uses (the repaired one); 2D: a self-intersecting polygon is a problem, listed above.
      {"intersecting_face_pairs", is3d ? count(check.repairedReport.intersectingFaces.size()) : ReportValue(nullptr)},
  };
}

}  // namespace somicage
