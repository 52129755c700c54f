#include "generation/cage_enclosure.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <set>

#include "cage/cage_validation.h"
#include "generation/cage_geometry.h"

namespace somicage {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using FaceTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
using cage_geometry::SoupTree;
using cage_geometry::Triangles;

Point point(const Eigen::MatrixXd& vertices, int i) { return Point(vertices(i, 0), vertices(i, 1), vertices(i, 2)); }

// Face j of the result is cage face j.
Mesh toMesh(const Cage& cage) {
  Mesh mesh;
  for (int i = 0; i < cage.numVertices(); ++i) mesh.add_vertex(point(cage.vertices, i));
  for (int j = 0; j < cage.numFaces(); ++j)
    mesh.add_face(Mesh::Vertex_index(cage.faces(j, 0)), Mesh::Vertex_index(cage.faces(j, 1)),
                  Mesh::Vertex_index(cage.faces(j, 2)));
  return mesh;
}

}  // namespace

EnclosureReport checkEnclosure(const Cage& cage, const Eigen::MatrixXd& meshVertices,
                               const Eigen::MatrixXi& meshTriangles) {
  const Mesh mesh = toMesh(cage);
  EnclosureReport report;
  FaceTree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.accelerate_distance_queries();
  const CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(tree);
  for (int i = 0; i < meshVertices.rows(); ++i) {
    const Point p = point(meshVertices, i);
    if (side(p) == CGAL::ON_BOUNDED_SIDE) continue;
    report.outsideVertices.push_back(i);
    report.nearestFaces.push_back(int(tree.closest_point_and_primitive(p).second));
  }
  std::vector<std::pair<int, int>> edges;  // each mesh edge once
  for (int j = 0; j < meshTriangles.rows(); ++j)
    for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(meshTriangles(j, k), meshTriangles(j, (k + 1) % 3)));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::set<int> crossed;
  std::vector<FaceTree::Primitive_id> hits;
  for (const auto& [a, b] : edges) {
    hits.clear();
    tree.all_intersected_primitives(Kernel::Segment_3(point(meshVertices, a), point(meshVertices, b)),
                                    std::back_inserter(hits));
    for (const auto f : hits) crossed.insert(int(f));
  }
  report.crossedFaces.assign(crossed.begin(), crossed.end());
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(pairs));
  for (const auto& [f, g] : pairs)
    report.selfIntersections.push_back({std::min(int(f), int(g)), std::max(int(f), int(g))});
  return report;
}

double hausdorffCageToMesh(const Cage& cage, const Eigen::MatrixXd& meshVertices, const Eigen::MatrixXi& meshTriangles,
                           int samplesPerEdge) {
  const Triangles triangles = cage_geometry::triangleSoup(meshVertices, meshTriangles);
  SoupTree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  double worst = 0;
  const int n = std::max(1, samplesPerEdge);
  for (int j = 0; j < cage.numFaces(); ++j) {
    const Eigen::Vector3d a = cage.vertices.row(cage.faces(j, 0)), b = cage.vertices.row(cage.faces(j, 1)),
                          c = cage.vertices.row(cage.faces(j, 2));
    for (int u = 0; u <= n; ++u)
      for (int v = 0; u + v <= n; ++v) {
        const Eigen::Vector3d x = a + (b - a) * (double(u) / n) + (c - a) * (double(v) / n);
        worst = std::max(worst, tree.squared_distance(Point(x.x(), x.y(), x.z())));
      }
  }
  return std::sqrt(worst);
}

CageTightness measureTightness(const Cage& cage, const Eigen::MatrixXd& meshVertices,
                               const Eigen::MatrixXi& meshTriangles) {
  CageTightness tightness;
  tightness.hausdorff = hausdorffCageToMesh(cage, meshVertices, meshTriangles) / cageDiameter(meshVertices);
  const CageReport cageReport = validateCage(cage);
  const CageReport meshReport = validateCage(Cage{meshVertices, meshTriangles});
  const bool closedMesh = meshReport.closed() && meshReport.manifold() && meshReport.consistentlyOriented();
  tightness.volumeRatio = closedMesh && meshReport.signedVolume != 0
                              ? cageReport.signedVolume / std::abs(meshReport.signedVolume)
                              : std::numeric_limits<double>::quiet_NaN();
  return tightness;
}

}  // namespace somicage
