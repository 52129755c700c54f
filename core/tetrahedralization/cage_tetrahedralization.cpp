#include "tetrahedralization/cage_tetrahedralization.h"

// CGAL's Mesh_3: the one translation unit that includes it (it takes minutes to compile).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/make_mesh_3.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "base/errors.h"
#include "tetrahedralization/constrained_tetrahedralization.h"

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

// Mesh_3's tetrahedra at `level` (> 0), or nothing when it lost a cage vertex or `stop` was set before it was done.
std::optional<VolumeMesh> mesh3Tetrahedra(const Cage& cage, int level, const TetrahedralizationBound& bound,
                                          std::atomic<bool>& stop) {
  const auto start = std::chrono::steady_clock::now();
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
    if (f == SurfaceMesh::null_face()) return std::nullopt;  // not a manifold surface: the fallback says why
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

  namespace p = CGAL::parameters;
  const auto topology = CGAL::FACET_VERTICES_ON_SAME_SURFACE_PATCH_WITH_ADJACENCY_CHECK;
  const double h = cageDiameter(cage.vertices) * std::ldexp(1.0, -(level + 1));
  const Criteria criteria(p::edge_size = h, p::facet_size = h, p::facet_topology = topology, p::cell_size = h,
                          p::cell_radius_edge_ratio = 3);
  // No p::manifold(): on CACTUS's cage its extra refinement never ends (CGAL 5.5); checkVolumeMesh checks the
  // boundary instead. Refinement stops at `stop` or the vertex cap; exudation (sliver removal) runs after it.
  CGAL::Mesh_error_code error = CGAL::CGAL_MESH_3_NO_ERROR;
  Complex complex = CGAL::make_mesh_3<Complex>(
      domain, criteria, p::no_perturb(), p::no_exude(),
      p::mesh_3_options(p::maximal_number_of_vertices = bound.maxVertices, p::pointer_to_error_code = &error,
                        p::pointer_to_stop_atomic_boolean = &stop));
  const double left = bound.seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stop.load() || error != CGAL::CGAL_MESH_3_NO_ERROR || !(left > 0)) return std::nullopt;
  CGAL::exude_mesh_3(complex, p::time_limit = left);  // does not poll `stop`: it gets the time left instead
  if (stop.load()) return std::nullopt;

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
    if (!found[static_cast<std::size_t>(i)]) return std::nullopt;  // a cage vertex lost
  VolumeMesh mesh;
  mesh.vertices.resize(n + static_cast<int>(steiner.size()), 3);
  mesh.vertices.topRows(n) = cage.vertices;
  for (std::size_t k = 0; k < steiner.size(); ++k)
    for (int a = 0; a < 3; ++a) mesh.vertices(n + static_cast<int>(k), a) = steiner[k][static_cast<std::size_t>(a)];
  mesh.simplices.resize(static_cast<int>(tets.size()), 4);
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) mesh.simplices(static_cast<int>(t), k) = tets[t][static_cast<std::size_t>(k)];
  return mesh;
}

// Whether `mesh` is a mesh of `cage` as checkVolumeMesh sees it (reorienting its simplices).
bool meshesTheCage(VolumeMesh& mesh, const Cage& cage) {
  try {
    checkVolumeMesh(mesh, cage, {kGenerated, {}, {}});
    return true;
  } catch (const InputError&) {  // e.g. a sliver exudation left flat
    return false;
  }
}

}  // namespace

VolumeMesh tetrahedralizeCage(const Cage& cage, int level, const ProgressCallback& progress,
                              const TetrahedralizationBound& bound) {
  if (cage.dim() != 3) {
    if (std::unique_ptr<VolumeMesh> star = starVolumeMesh(cage)) return *star;
    throw InputError("--tets", -1, "the polygon is not star-shaped from its centroid, so it has no triangle fan",
                     "give a triangulation of it with --tets FILE.mesh (Dimension 2, Triangles)");
  }
  if (!progress(0.0)) throw Cancelled();
  std::string fallback;  // why Mesh_3's mesh is not used (level > 0)
  if (level > 0) {
    // Mesh_3 on a worker thread, so that this thread can call progress and stop it (CGAL polls the flag).
    std::atomic<bool> stop{false};
    std::optional<VolumeMesh> mesh;
    std::exception_ptr failure;
    std::thread worker([&] {
      try {
        mesh = mesh3Tetrahedra(cage, level, bound, stop);
      } catch (...) {
        failure = std::current_exception();
      }
      stop.store(true);  // done: tells the loop below
    });
    const auto start = std::chrono::steady_clock::now();
    bool cancelled = false;
    while (!stop.load()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      const double used = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                          bound.seconds;
      if (!progress(std::min(used, 0.99))) cancelled = true;
      if (cancelled || used >= 1) stop.store(true);
    }
    worker.join();
    if (cancelled) throw Cancelled();
    if (failure) std::rethrow_exception(failure);
    if (mesh && meshesTheCage(*mesh, cage)) {
      if (!progress(1.0)) throw Cancelled();
      return *mesh;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", bound.seconds);
    fallback = "CGAL's Mesh_3 " +
               std::string(mesh ? "made a mesh of the cage that does not keep its boundary"
                           : seconds >= bound.seconds
                               ? "did not finish within its bound of " + std::string(limit) + " s"
                               : "stopped (the cage is not a manifold surface, it reached its cap of " +
                                     std::to_string(bound.maxVertices) + " vertices, or it moved a cage vertex)") +
               " at tet level " + std::to_string(level) +
               "; TetGen's constrained tetrahedralization, refined to that level's cell size, is used instead "
               "(a different mesh: a lower --tet-level, or --tets FILE, gives one of your choice)";
  }
  // Level 0, or Mesh_3 not done within its bound: the constrained tetrahedralization, cells of the level's size.
  const double h = cageDiameter(cage.vertices) * std::ldexp(1.0, -(level + 1));
  VolumeMesh mesh = constrainedTetrahedralization(cage, level > 0 ? h * h * h / (6 * std::sqrt(2.0)) : 0.0);
  if (!meshesTheCage(mesh, cage))
    throw InputError(kGenerated, -1, "neither CGAL's Mesh_3 nor TetGen made a tetrahedral mesh of the cage",
                     "repair the cage (somicage check), or give a tetrahedral mesh with --tets");
  if (!progress(1.0)) throw Cancelled();
  mesh.fallback = fallback;
  return mesh;
}

VolumeMesh tetrahedralizeCageWithOptions(const Cage& cage, const MethodOptions& options,
                                         const ProgressCallback& progress) {
  return tetrahedralizeCage(cage, parseTetLevel(options), progress);
}

}  // namespace somicage
