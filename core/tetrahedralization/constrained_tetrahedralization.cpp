#include "tetrahedralization/constrained_tetrahedralization.h"

#define TETLIBRARY  // Debian's libtet is built as a library: TetGen throws its exit code instead of exiting
#include <tetgen.h>

#include <cstdio>
#include <string>
#include <utility>

#include "base/errors.h"

namespace somicage {

namespace {

const char* const kGenerated = "the generated tetrahedral mesh";

// TetGen's exit codes (terminatetetgen in tetgen.h), for the error.
std::string tetgenProblem(int code) {
  switch (code) {
    case 1:
      return "TetGen ran out of memory";
    case 3:
      return "the cage intersects itself";
    case 4:
    case 5:
      return "the cage has features too small or faces too close for TetGen";
    default:
      return "TetGen failed on the cage (code " + std::to_string(code) + ")";
  }
}

}  // namespace

VolumeMesh constrainedTetrahedralization(const Cage& cage, double maxVolume) {
  SOMICAGE_ASSERT(cage.dim() == 3 && cage.faces.cols() == 3, "a 3D triangle cage");
  const int n = cage.numVertices();
  tetgenio in, out;  // their destructors free what TetGen and we allocate with new[]
  in.firstnumber = 0;
  in.numberofpoints = n;
  in.pointlist = new REAL[3 * static_cast<std::size_t>(n)];
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) in.pointlist[3 * i + a] = cage.vertices(i, a);
  in.numberoffacets = cage.numFaces();
  in.facetlist = new tetgenio::facet[static_cast<std::size_t>(cage.numFaces())];
  for (int j = 0; j < cage.numFaces(); ++j) {
    tetgenio::facet& facet = in.facetlist[j];
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    facet.numberofholes = 0;
    facet.holelist = nullptr;
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) facet.polygonlist[0].vertexlist[k] = cage.faces(j, k);
  }
  // p: a piecewise linear complex (the cage), Q: quiet, M: no merging of nearly coplanar faces (Steiner vertices
  // on a merged face can lie 1e-7 diameters off the cage's); Y: the faces kept unsplit, or q, a: quality and
  // volume bounds (with Y TetGen refines nothing near the boundary, so the bounds split the faces too).
  std::string switches = "pQMY";
  if (maxVolume > 0) {
    char bound[48];
    std::snprintf(bound, sizeof bound, "pQMq2a%.17g", maxVolume);
    switches = bound;
  }
  try {
    tetrahedralize(&switches[0], &in, &out);
  } catch (int code) {
    throw InputError(kGenerated, -1, tetgenProblem(code),
                     "repair the cage (somicage check), or give a tetrahedral mesh with --tets");
  }
  if (out.numberofpoints < n || out.numberoftetrahedra <= 0 || out.numberofcorners != 4)
    throw InputError(kGenerated, -1, "TetGen returned no tetrahedra for the cage",
                     "repair the cage (somicage check), or give a tetrahedral mesh with --tets");
  VolumeMesh mesh;
  mesh.vertices.resize(out.numberofpoints, 3);
  for (int i = 0; i < out.numberofpoints; ++i)
    for (int a = 0; a < 3; ++a) mesh.vertices(i, a) = out.pointlist[3 * i + a];
  // TetGen keeps the input points first, in order, unless it merged duplicates: then the cage is not welded.
  if (mesh.vertices.topRows(n) != cage.vertices)
    throw InputError(kGenerated, -1, "TetGen merged cage vertices at equal positions",
                     "weld the cage's coincident vertices (--weld), or give a tetrahedral mesh with --tets");
  mesh.simplices.resize(out.numberoftetrahedra, 4);
  for (int t = 0; t < out.numberoftetrahedra; ++t)
    for (int k = 0; k < 4; ++k) mesh.simplices(t, k) = out.tetrahedronlist[4 * t + k];
  for (int s = 0; s < mesh.numSimplices(); ++s)
    if (signedSimplexMeasure(mesh, s) < 0) std::swap(mesh.simplices(s, 0), mesh.simplices(s, 1));
  return mesh;
}

}  // namespace somicage
