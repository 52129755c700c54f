#include "generation/cage_simplification.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "base/errors.h"
#include "generation/cage_geometry.h"

namespace somicage {

namespace {

using cage_geometry::minAngle;
using cage_geometry::trianglesCross;
namespace SMS = CGAL::Surface_mesh_simplification;
namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Face = Mesh::Face_index;
using Vertex = Mesh::Vertex_index;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
using Profile = SMS::Edge_profile<Mesh>;
using cage_geometry::SoupTree;
using cage_geometry::Triangles;

// A closed oriented polygon soup as a halfedge mesh; vertices where marching cubes made a pinch are duplicated.
Mesh toMesh(const Cage& cage) {
  std::vector<Point> points(cage.numVertices());
  for (int i = 0; i < cage.numVertices(); ++i)
    points[i] = Point(cage.vertices(i, 0), cage.vertices(i, 1), cage.vertices(i, 2));
  std::vector<std::array<std::size_t, 3>> faces(cage.numFaces());
  for (int j = 0; j < cage.numFaces(); ++j)
    faces[j] = {std::size_t(cage.faces(j, 0)), std::size_t(cage.faces(j, 1)), std::size_t(cage.faces(j, 2))};
  PMP::orient_polygon_soup(points, faces);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, faces, mesh);
  return mesh;
}

Cage toCage(const Mesh& mesh) {
  Cage cage;
  cage.vertices.resize(mesh.number_of_vertices(), 3);
  cage.faces.resize(mesh.number_of_faces(), 3);
  std::vector<int> index(mesh.num_vertices(), -1);
  int i = 0;
  for (Vertex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    cage.vertices.row(i) << p.x(), p.y(), p.z();
    index[v] = i++;
  }
  int j = 0;
  for (Face f : mesh.faces()) {
    int k = 0;
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) cage.faces(j, k++) = index[v];
    ++j;
  }
  return cage;
}

// The current triangles of the surface in a uniform grid of cells over its bounding box. A triangle is (re)entered
// in the cells of its bounding box when it is made; a cell may keep triangles that have since moved or gone, which
// a query skips or tests against their current corners (their current cells are always listed).
class TriangleGrid {
 public:
  TriangleGrid(const Mesh& mesh, int resolution) : mesh_(mesh), resolution_(resolution) {
    box_ = CGAL::Polygon_mesh_processing::bbox(mesh);
    const double margin =
        1e-3 * std::max({box_.xmax() - box_.xmin(), box_.ymax() - box_.ymin(), box_.zmax() - box_.zmin()});
    box_ = CGAL::Bbox_3(box_.xmin() - margin, box_.ymin() - margin, box_.zmin() - margin, box_.xmax() + margin,
                        box_.ymax() + margin, box_.zmax() + margin);
    cells_.resize(std::size_t(resolution) * resolution * resolution);
    for (Face f : mesh.faces()) insert(f);
  }

  void insert(Face f) {
    forCells(faceBox(f), [&](std::vector<Face>& cell) { cell.push_back(f); });
  }

  // Whether triangle (a, b, c) crosses a current triangle of the surface, other than those in `replaced` (the faces
  // the collapse removes or remakes) and other than at the corners they share.
  bool crosses(const Point& a, const Point& b, const Point& c, const std::vector<Face>& replaced) {
    ++stamp_;
    if (seen_.size() < mesh_.num_faces()) seen_.resize(mesh_.num_faces(), 0);
    for (Face f : replaced) seen_[f] = stamp_;
    const Kernel::Triangle_3 t(a, b, c);
    bool hit = false;
    forCells(a.bbox() + b.bbox() + c.bbox(), [&](std::vector<Face>& cell) {
      for (Face f : cell) {
        if (hit || seen_[f] == stamp_ || mesh_.is_removed(f)) continue;
        seen_[f] = stamp_;
        hit = crossesFace(t, f);
      }
    });
    return hit;
  }

 private:
  CGAL::Bbox_3 faceBox(Face f) const {
    CGAL::Bbox_3 box;
    for (Vertex v : CGAL::vertices_around_face(mesh_.halfedge(f), mesh_)) box += mesh_.point(v).bbox();
    return box;
  }

  template <typename Visit>
  void forCells(const CGAL::Bbox_3& b, Visit visit) {
    const auto cell = [&](double x, int axis) {
      const double t = (x - box_.min(axis)) / (box_.max(axis) - box_.min(axis));
      return std::clamp(static_cast<int>(t * resolution_), 0, resolution_ - 1);
    };
    const int x0 = cell(b.xmin(), 0), x1 = cell(b.xmax(), 0), y0 = cell(b.ymin(), 1), y1 = cell(b.ymax(), 1);
    const int z0 = cell(b.zmin(), 2), z1 = cell(b.zmax(), 2);
    for (int x = x0; x <= x1; ++x)
      for (int y = y0; y <= y1; ++y)
        for (int z = z0; z <= z1; ++z) visit(cells_[(std::size_t(x) * resolution_ + y) * resolution_ + z]);
  }

  bool crossesFace(const Kernel::Triangle_3& t, Face f) const {
    std::array<Point, 3> q;
    int k = 0;
    for (Vertex v : CGAL::vertices_around_face(mesh_.halfedge(f), mesh_)) q[k++] = mesh_.point(v);
    return trianglesCross(t, q);
  }

  const Mesh& mesh_;
  int resolution_;
  CGAL::Bbox_3 box_;
  std::vector<std::vector<Face>> cells_;
  std::vector<unsigned> seen_;
  unsigned stamp_ = 0;
};

// Refuses collapses whose new triangles would fold, be needles, cross the barrier or cross the surface.
class EnclosureFilter {
 public:
  EnclosureFilter(const Tree& barrier, const SoupTree& mesh, TriangleGrid& grid, double minAngle)
      : barrier_(barrier), mesh_(mesh), grid_(grid), minAngle_(minAngle) {}

  boost::optional<Point> operator()(const Profile& profile, boost::optional<Point> placement) const {
    if (!placement) return placement;
    const Point& p = *placement;
    const Mesh& mesh = profile.surface_mesh();
    // The faces around both ends of the edge: removed or remade by the collapse.
    std::vector<Face> replaced;
    for (Vertex end : {profile.v0(), profile.v1()})
      for (Face f : CGAL::faces_around_target(mesh.halfedge(end), mesh))
        if (f != Mesh::null_face()) replaced.push_back(f);
    const Profile::Triangle_vector& triangles = profile.triangles();
    // A collapse may make an angle below the bound when it improves on the worst one it replaces: otherwise the
    // slivers that marching cubes makes could never be collapsed away.
    double bound = minAngle_;
    for (const Profile::Triangle& t : triangles)
      bound = std::min(bound, minAngle(mesh.point(t.v0), mesh.point(t.v1), mesh.point(t.v2)));
    auto it = triangles.begin();
    if (profile.left_face_exists()) ++it;
    if (profile.right_face_exists()) ++it;
    std::vector<std::array<Point, 3>> remade;
    for (; it != triangles.end(); ++it) {  // the triangles that remain, with p in place of their second corner
      const Point& a = mesh.point(it->v0);
      const Point& b = mesh.point(it->v1);
      const Point& c = mesh.point(it->v2);
      const Kernel::Vector_3 before = CGAL::cross_product(b - a, c - a), after = CGAL::cross_product(p - a, c - a);
      if (!(before * after > 0)) return boost::none;
      if (minAngle(a, p, c) < bound) return boost::none;
      const Kernel::Triangle_3 made(a, p, c);
      if (barrier_.do_intersect(made) || mesh_.do_intersect(made)) return boost::none;
      if (grid_.crosses(a, p, c, replaced)) return boost::none;
      for (const std::array<Point, 3>& other : remade)
        if (trianglesCross(made, other)) return boost::none;
      remade.push_back({a, p, c});
    }
    // The surface sweeps through the tetrahedra between p and the faces it replaces: no part of the mesh may lie
    // there, or the collapse would jump over it (a thin part, a boundary) without any new face crossing it.
    for (Face f : replaced) {
      std::array<Point, 3> q;
      int k = 0;
      for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) q[k++] = mesh.point(v);
      if (CGAL::orientation(q[0], q[1], q[2], p) == CGAL::COPLANAR) continue;  // no volume to sweep
      if (mesh_.do_intersect(Kernel::Tetrahedron_3(q[0], q[1], q[2], p))) return boost::none;
    }
    return placement;
  }

 private:
  const Tree& barrier_;
  const SoupTree& mesh_;
  TriangleGrid& grid_;
  double minAngle_;
};

// Enters remade triangles in the grid and reports progress (from the calling thread: CGAL's loop is serial).
struct Visitor : SMS::Edge_collapse_visitor_base<Mesh> {
  Visitor(TriangleGrid& grid, const ProgressCallback& progress, std::size_t start, std::size_t goal)
      : grid(&grid), progress(&progress), start(start), goal(goal) {}
  void OnCollapsed(const Profile& profile, Vertex v) {
    const Mesh& mesh = profile.surface_mesh();
    for (Face f : CGAL::faces_around_target(mesh.halfedge(v), mesh))
      if (f != Mesh::null_face()) grid->insert(f);
  }
  void OnSelected(const Profile&, boost::optional<double>, std::size_t, std::size_t current) {
    if (++steps % 256 != 0 || start <= goal) return;
    const double done = double(start - std::min(start, current)) / double(start - goal);
    if (!(*progress)(std::clamp(done, 0.0, 1.0))) *cancelled = true;
  }
  TriangleGrid* grid;
  const ProgressCallback* progress;
  std::size_t start, goal, steps = 0;
  std::shared_ptr<bool> cancelled = std::make_shared<bool>(false);
};

// Stops at the face budget (a closed triangle mesh has 3F/2 edges), or when cancelled.
struct BudgetStop {
  std::size_t maxEdges;
  std::shared_ptr<bool> cancelled;
  bool operator()(double, const Profile&, std::size_t, std::size_t edges) const {
    return edges <= maxEdges || *cancelled;
  }
};

}  // namespace

SimplificationResult simplifyOutsideBarrier(const Cage& surface, const Cage& barrier,
                                            const Eigen::MatrixXd& meshVertices, const Eigen::MatrixXi& meshTriangles,
                                            const SimplificationOptions& options, const ProgressCallback& progress) {
  Mesh mesh = toMesh(surface);
  const Mesh barrierMesh = toMesh(barrier);
  Tree barrierTree(faces(barrierMesh).first, faces(barrierMesh).second, barrierMesh);
  barrierTree.accelerate_distance_queries();
  const Triangles meshSoup = cage_geometry::triangleSoup(meshVertices, meshTriangles);
  const SoupTree meshTree(meshSoup.begin(), meshSoup.end());
  TriangleGrid grid(mesh, 32);
  const double minAngleRadians = options.minAngleDegrees * M_PI / 180.0;
  const EnclosureFilter filter(barrierTree, meshTree, grid, minAngleRadians);
  const std::size_t maxEdges = std::size_t(options.maxFaces) * 3 / 2;
  Visitor visitor(grid, progress, mesh.number_of_edges(), maxEdges);
  const BudgetStop stop{maxEdges, visitor.cancelled};
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(SMS::LindstromTurk_cost<Mesh>())
                         .get_placement(SMS::LindstromTurk_placement<Mesh>())
                         .filter(filter)
                         .visitor(visitor));
  if (*visitor.cancelled) throw Cancelled();
  mesh.collect_garbage();
  SimplificationResult result;
  result.budgetMet = int(mesh.number_of_faces()) <= options.maxFaces;
  result.surface = toCage(mesh);
  return result;
}

}  // namespace somicage
