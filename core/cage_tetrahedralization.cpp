#include "cage_tetrahedralization.h"

// CGAL's Mesh_3: the one translation unit that includes it (it takes minutes to compile).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "errors.h"

namespace somicage {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<Kernel, SurfaceMesh>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex =
    CGAL::Mesh_complex_3_in_triangulation_3<Triangulation, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

const char* const kGenerated = "the generated tetrahedral mesh";

}  // namespace

VolumeMesh tetrahedralizeCage(const Cage& cage, int level) {
  if (cage.dim() != 3) {
    if (std::unique_ptr<VolumeMesh> star = starVolumeMesh(cage)) return *star;
    throw InputError("--tets", -1, "the polygon is not star-shaped from its centroid, so it has no triangle fan",
                     "give a triangulation of it with --tets FILE.mesh (Dimension 2, Triangles)");
  }
  const int n = cage.numVertices();
  // Every cage face is its own surface patch and every cage edge its own feature curve: the corners of the
  // curves (every cage vertex) are kept exactly, and a boundary facet's vertices lie on one patch, so the
  // boundary facets tile the cage's faces exactly.
  SurfaceMesh surface;
  std::vector<SurfaceMesh::Vertex_index> handles;
  for (int i = 0; i < n; ++i)
    handles.push_back(surface.add_vertex(Point(cage.vertices(i, 0), cage.vertices(i, 1), cage.vertices(i, 2))));
  auto patch = surface.add_property_map<SurfaceMesh::Face_index, int>("f:patch_id", 1).first;
  std::map<std::pair<int, int>, bool> edges;
  for (int j = 0; j < cage.numFaces(); ++j) {
    const SurfaceMesh::Face_index f =
        surface.add_face(handles[cage.faces(j, 0)], handles[cage.faces(j, 1)], handles[cage.faces(j, 2)]);
    if (f == SurfaceMesh::null_face())
      throw InputError(kGenerated, -1, "the cage is not a manifold surface CGAL can mesh (face " + std::to_string(j) + ")",
                       "repair the cage, or give a tetrahedral mesh with --tets");
    patch[f] = j + 1;
    for (int k = 0; k < 3; ++k) {
      const int a = cage.faces(j, k), b = cage.faces(j, (k + 1) % 3);
      edges[{std::min(a, b), std::max(a, b)}] = true;
    }
  }
  std::vector<std::vector<Point>> curves;
  for (const auto& edge : edges)
    curves.push_back({Point(cage.vertices(edge.first.first, 0), cage.vertices(edge.first.first, 1),
                            cage.vertices(edge.first.first, 2)),
                      Point(cage.vertices(edge.first.second, 0), cage.vertices(edge.first.second, 1),
                            cage.vertices(edge.first.second, 2))});
  Domain domain(surface);
  domain.add_features(curves.begin(), curves.end());

  const double diameter = cageDiameter(cage.vertices);
  namespace p = CGAL::parameters;
  const auto topology = CGAL::FACET_VERTICES_ON_SAME_SURFACE_PATCH_WITH_ADJACENCY_CHECK;
  const double h = diameter * std::ldexp(1.0, -(level + 1));
  const Criteria criteria = level == 0 ? Criteria(p::edge_size = diameter, p::facet_topology = topology)
                                       : Criteria(p::edge_size = h, p::facet_size = h, p::facet_topology = topology,
                                                  p::cell_size = h, p::cell_radius_edge_ratio = 3);
  const Complex complex = CGAL::make_mesh_3<Complex>(domain, criteria, p::no_perturb(), p::exude(), p::manifold());

  // The cage's vertices first, matched by their exact coordinates (corners are kept as given), then the rest.
  std::map<std::array<double, 3>, int> cageIndex;
  for (int i = 0; i < n; ++i) cageIndex[{cage.vertices(i, 0), cage.vertices(i, 1), cage.vertices(i, 2)}] = i;
  std::map<Triangulation::Vertex_handle, int> index;
  std::vector<std::array<double, 3>> steiner;
  std::vector<bool> found(static_cast<std::size_t>(n), false);
  std::vector<std::array<int, 4>> tets;
  for (auto c = complex.cells_in_complex_begin(); c != complex.cells_in_complex_end(); ++c) {
    std::array<int, 4> tet{};
    for (int k = 0; k < 4; ++k) {
      const Triangulation::Vertex_handle v = c->vertex(k);
      auto it = index.find(v);
      if (it == index.end()) {
        const Point& q = v->point().point();
        const std::array<double, 3> xyz{q.x(), q.y(), q.z()};
        const auto corner = cageIndex.find(xyz);
        int id;
        if (corner != cageIndex.end()) {
          id = corner->second;
          found[static_cast<std::size_t>(id)] = true;
        } else {
          id = n + static_cast<int>(steiner.size());
          steiner.push_back(xyz);
        }
        it = index.emplace(v, id).first;
      }
      tet[static_cast<std::size_t>(k)] = it->second;
    }
    tets.push_back(tet);
  }
  for (int i = 0; i < n; ++i)
    if (!found[static_cast<std::size_t>(i)])
      throw InputError(kGenerated, -1, "CGAL's mesher did not keep cage vertex " + std::to_string(i + 1),
                       "give a tetrahedral mesh with --tets, or try another --tet-level");
  VolumeMesh mesh;
  mesh.vertices.resize(n + static_cast<int>(steiner.size()), 3);
  mesh.vertices.topRows(n) = cage.vertices;
  for (std::size_t k = 0; k < steiner.size(); ++k)
    for (int a = 0; a < 3; ++a) mesh.vertices(n + static_cast<int>(k), a) = steiner[k][static_cast<std::size_t>(a)];
  mesh.simplices.resize(static_cast<int>(tets.size()), 4);
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) mesh.simplices(static_cast<int>(t), k) = tets[t][static_cast<std::size_t>(k)];
  for (int s = 0; s < mesh.numSimplices(); ++s)
    if (signedSimplexMeasure(mesh, s) < 0) std::swap(mesh.simplices(s, 0), mesh.simplices(s, 1));
  return mesh;
}

VolumeMesh tetrahedralizeCageWithOptions(const Cage& cage, const MethodOptions& options) {
  int level = kDefaultTetLevel;
  if (const auto it = options.find("tet-level"); it != options.end()) {
    const std::string& text = it->second;
    if (text.size() != 1 || text[0] < '0' || text[0] >= '0' + kTetLevels)
      throw InputError("--tet-level", -1, "'" + text + "' is not a tetrahedral mesh level",
                       "use a whole number from 0 (coarse) to " + std::to_string(kTetLevels - 1));
    level = text[0] - '0';
  }
  return tetrahedralizeCage(cage, level);
}

}  // namespace somicage
