#include "generation/offset_surface.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <vector>

#include "base/errors.h"
#include "geometry/cage.h"

namespace somicage {

namespace {

struct VdbMesh {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
};

// The isosurface as triangles (each quad split along its shorter diagonal), wound so that the normals point to
// larger values. OpenVDB winds the surfaces of level sets the other way (they come out with negative volume), and
// those of other grids (an unsigned distance) this way.
VdbMesh isosurface(const openvdb::FloatGrid& grid, double isovalue) {
  VdbMesh mesh;
  std::vector<openvdb::Vec3I> triangles;
  openvdb::tools::volumeToMesh(grid, mesh.points, triangles, mesh.quads, isovalue, 0.0);
  const bool reverse = grid.getGridClass() == openvdb::GRID_LEVEL_SET;
  const auto add = [&](unsigned a, unsigned b, unsigned c) {
    mesh.triangles.push_back(reverse ? openvdb::Vec3I(a, c, b) : openvdb::Vec3I(a, b, c));
  };
  for (const openvdb::Vec3I& t : triangles) add(t[0], t[1], t[2]);
  for (const openvdb::Vec4I& q : mesh.quads) {
    if ((mesh.points[q[0]] - mesh.points[q[2]]).lengthSqr() <= (mesh.points[q[1]] - mesh.points[q[3]]).lengthSqr()) {
      add(q[0], q[1], q[2]);
      add(q[0], q[2], q[3]);
    } else {
      add(q[0], q[1], q[3]);
      add(q[1], q[2], q[3]);
    }
  }
  mesh.quads.clear();
  return mesh;
}

// Connected components of the triangles (through shared vertices), as component index per triangle.
std::vector<int> triangleComponents(const VdbMesh& mesh, int& count) {
  std::vector<int> parent(mesh.points.size());
  for (size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  const auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const openvdb::Vec3I& t : mesh.triangles) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::vector<int> label(mesh.points.size(), -1), component(mesh.triangles.size());
  count = 0;
  for (size_t j = 0; j < mesh.triangles.size(); ++j) {
    const int root = find(mesh.triangles[j][0]);
    if (label[root] < 0) label[root] = count++;
    component[j] = label[root];
  }
  return component;
}

double signedVolumeTerm(const VdbMesh& mesh, const openvdb::Vec3I& t) {
  const auto corner = [&](int k) {
    const openvdb::Vec3d p = mesh.points[t[k]];
    return Eigen::Vector3d(p.x(), p.y(), p.z());
  };
  return signedTetrahedronVolume(Eigen::Vector3d::Zero(), corner(0), corner(1), corner(2));
}

// OpenVDB orients the surface of {distance <= offset} with normals pointing to larger distances: the outer shell of
// each piece then has a positive volume, the walls of cavities a negative one. Keeps the positive shells, largest
// first, that do not lie inside an already kept one (tested at one vertex by ray parity on the kept shells' volume
// sign: a shell inside another is inside its bounding box and has a smaller volume; see the note below).
VdbMesh outerShells(const VdbMesh& mesh) {
  int count = 0;
  const std::vector<int> component = triangleComponents(mesh, count);
  std::vector<double> volume(count, 0.0);
  std::vector<openvdb::BBoxd> box(count);
  for (size_t j = 0; j < mesh.triangles.size(); ++j) {
    volume[component[j]] += signedVolumeTerm(mesh, mesh.triangles[j]);
    for (int k = 0; k < 3; ++k) box[component[j]].expand(openvdb::Vec3d(mesh.points[mesh.triangles[j][k]]));
  }
  std::vector<int> order(count);
  for (int i = 0; i < count; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return volume[a] > volume[b]; });
  // A positive shell inside another positive shell lies inside that one's cavity (the surfaces of a distance field
  // never cross), so the bounding box test is exact here: nested shells' boxes nest, separate shells' boxes may
  // overlap but then neither contains the other entirely, except in contrived cases the final enclosure check
  // (cage_enclosure.h) still catches.
  std::vector<char> keep(count, 0);
  for (int i : order) {
    if (volume[i] <= 0) break;
    bool nested = false;
    for (int k = 0; k < count && !nested; ++k)
      nested = keep[k] && box[k].isInside(box[i].min()) && box[k].isInside(box[i].max());
    keep[i] = !nested;
  }
  VdbMesh kept;
  kept.points = mesh.points;
  for (size_t j = 0; j < mesh.triangles.size(); ++j)
    if (keep[component[j]]) kept.triangles.push_back(mesh.triangles[j]);
  return kept;
}

// The used vertices and the triangles, compacted.
Cage toCage(const VdbMesh& surface) {
  std::vector<int> index(surface.points.size(), -1);
  int used = 0;
  for (const openvdb::Vec3I& t : surface.triangles)
    for (int k = 0; k < 3; ++k)
      if (index[t[k]] < 0) index[t[k]] = used++;
  Cage result;
  result.vertices.resize(used, 3);
  result.faces.resize(static_cast<Eigen::Index>(surface.triangles.size()), 3);
  for (size_t i = 0; i < surface.points.size(); ++i)
    if (index[i] >= 0)
      result.vertices.row(index[i]) << surface.points[i].x(), surface.points[i].y(), surface.points[i].z();
  for (size_t j = 0; j < surface.triangles.size(); ++j)
    for (int k = 0; k < 3; ++k) result.faces(static_cast<Eigen::Index>(j), k) = index[surface.triangles[j][k]];
  return result;
}

}  // namespace

OffsetSurfaces offsetSurfaces(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles,
                              const OffsetSurfaceOptions& options) {
  SOMICAGE_ASSERT(options.voxelSize > 0 && options.offset > options.voxelSize && options.closing >= 0 &&
                      options.barrier > 0 && options.barrier < options.offset,
                  "offset surface: the offset must exceed the voxel size");
  openvdb::initialize();
  const openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(options.voxelSize);
  std::vector<openvdb::Vec3s> points(vertices.rows());
  for (Eigen::Index i = 0; i < vertices.rows(); ++i)
    points[i] = openvdb::Vec3s(float(vertices(i, 0)), float(vertices(i, 1)), float(vertices(i, 2)));
  std::vector<openvdb::Vec3I> faces(triangles.rows());
  for (Eigen::Index j = 0; j < triangles.rows(); ++j)
    faces[j] = openvdb::Vec3I(triangles(j, 0), triangles(j, 1), triangles(j, 2));

  // Dilation: the level set {distance = offset + closing} of the unsigned distance (the band must reach it).
  const double dilation = options.offset + options.closing;
  const float band = static_cast<float>(dilation / options.voxelSize + 2.0);
  const openvdb::FloatGrid::Ptr distance =
      openvdb::tools::meshToUnsignedDistanceField<openvdb::FloatGrid>(*transform, points, faces, {}, band);
  VdbMesh surface = outerShells(isosurface(*distance, dilation));

  if (options.closing > 0) {
    // Erosion: the level set {signed distance = -closing} of the dilated solid.
    const float inside = static_cast<float>(options.closing / options.voxelSize + 2.0);
    const openvdb::FloatGrid::Ptr solid = openvdb::tools::meshToSignedDistanceField<openvdb::FloatGrid>(
        *transform, surface.points, surface.triangles, {}, 2.0f, inside);
    surface = outerShells(isosurface(*solid, -options.closing));
  }

  return {toCage(surface), toCage(outerShells(isosurface(*distance, options.barrier)))};
}

}  // namespace somicage
