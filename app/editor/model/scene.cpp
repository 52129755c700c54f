#include "model/scene.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "generation/cage_generation.h"
#include "io/mesh_formats.h"
#include "io/obj_io.h"

namespace somicage::editor {

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- 3D demo: capped cylinder along x inside a segmented box ----
Scene demo3D() {
  const int around = 48, along = 96;
  const double halfLength = 2.0, radius = 0.5;
  const int ringCount = along + 1;
  Eigen::MatrixXd v(ringCount * around + 2, 3);
  for (int i = 0; i < ringCount; ++i) {
    const double x = -halfLength + 2.0 * halfLength * i / along;
    for (int j = 0; j < around; ++j) {
      const double t = 2.0 * kPi * j / around;
      v.row(i * around + j) << x, radius * std::cos(t), radius * std::sin(t);
    }
  }
  const int capLeft = ringCount * around, capRight = capLeft + 1;
  v.row(capLeft) << -halfLength, 0, 0;
  v.row(capRight) << halfLength, 0, 0;
  std::vector<Eigen::Vector3i> tris;
  for (int i = 0; i < along; ++i) {
    for (int j = 0; j < around; ++j) {
      const int a = i * around + j, b = i * around + (j + 1) % around;
      const int c = a + around, d = b + around;
      tris.emplace_back(a, d, c);
      tris.emplace_back(a, b, d);
    }
  }
  for (int j = 0; j < around; ++j) {
    const int jn = (j + 1) % around;
    tris.emplace_back(capLeft, jn, j);
    tris.emplace_back(capRight, along * around + j, along * around + jn);
  }
  Scene s;
  s.name = "demo (3D bar)";
  s.meshVertices = v;
  s.meshTriangles.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (std::size_t f = 0; f < tris.size(); ++f) s.meshTriangles.row(static_cast<Eigen::Index>(f)) = tris[f].transpose();

  // Cage: square rings of 4 corners at 5 stations along x.
  const int stations = 5;
  const double cx = 2.35, cy = 0.75;
  Eigen::MatrixXd cv(stations * 4, 3);
  const double corners[4][2] = {{-cy, -cy}, {cy, -cy}, {cy, cy}, {-cy, cy}};
  for (int k = 0; k < stations; ++k) {
    const double x = -cx + 2.0 * cx * k / (stations - 1);
    for (int c = 0; c < 4; ++c) cv.row(k * 4 + c) << x, corners[c][0], corners[c][1];
  }
  std::vector<Eigen::Vector3i> cf;
  for (int k = 0; k + 1 < stations; ++k) {
    for (int c = 0; c < 4; ++c) {
      const int a = k * 4 + c, b = k * 4 + (c + 1) % 4, e = a + 4, d = b + 4;
      cf.emplace_back(a, b, d);
      cf.emplace_back(a, d, e);
    }
  }
  const int last = (stations - 1) * 4;
  cf.emplace_back(0, 2, 1);
  cf.emplace_back(0, 3, 2);
  cf.emplace_back(last + 0, last + 1, last + 2);
  cf.emplace_back(last + 0, last + 2, last + 3);
  s.restCage.vertices = cv;
  s.restCage.faces.resize(static_cast<Eigen::Index>(cf.size()), 3);
  for (std::size_t f = 0; f < cf.size(); ++f) s.restCage.faces.row(static_cast<Eigen::Index>(f)) = cf[f].transpose();
  return s;
}

// ---- 2D demo: a dense strip inside a polygon ----
Scene demo2D() {
  const int nx = 96, ny = 24;
  const double hx = 2.0, hy = 0.5;
  Eigen::MatrixXd v((nx + 1) * (ny + 1), 2);
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) v.row(j * (nx + 1) + i) << -hx + 2 * hx * i / nx, -hy + 2 * hy * j / ny;
  }
  Eigen::MatrixXi f(2 * nx * ny, 3);
  int k = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      f.row(k++) << a, b, d;
      f.row(k++) << a, d, c;
    }
  }
  Scene s;
  s.name = "demo (2D strip)";
  s.meshVertices = v;
  s.meshTriangles = f;
  const int perSide = 5;
  const double cx = 2.3, cy = 0.8;
  Eigen::MatrixXd loop(2 * perSide, 2);
  for (int i = 0; i < perSide; ++i) {
    const double x = -cx + 2 * cx * i / (perSide - 1);
    loop.row(i) << x, -cy;                   // bottom, left to right
    loop.row(2 * perSide - 1 - i) << x, cy;  // top, right to left
  }
  s.restCage = makePolygonCage(loop);
  return s;
}

}  // namespace

Scene makeDemoScene(int dim) { return dim == 2 ? demo2D() : demo3D(); }

// A mesh opened without a cage gets a generated one (core/generation/cage_generation.h, the defaults of 'somicage
// cage').
Cage generatedCage(const PolygonMesh& mesh, const std::string& meshPath, std::vector<std::string>& notices) {
  const GeneratedCage generated =
      generateCage(mesh.vertices, triangulatePolygons(mesh.vertices, mesh.faces), CageGenerationOptions{}, meshPath);
  notices.push_back("cage generated: " + std::to_string(generated.cage.numFaces()) +
                    " faces around the mesh (write it to a file with 'somicage cage --mesh MESH --out CAGE.obj')");
  return generated.cage;
}

namespace {

// MESH around the cage makeCage gives for it (called with the mesh and the notice sink, after the mesh loaded and
// before its points are placed), in the engine's one order (engine.h); the notices go to the status bar.
Scene meshScene(const std::string& meshPath, const std::string& cageSource,
                const std::function<Cage(const PolygonMesh&, Scene&, const NoticeSink&)>& makeCage) {
  Scene s;
  auto document = std::make_shared<const MeshDocument>(loadMeshDocument(meshPath));
  const PolygonMesh& mesh = document->geometry;
  const NoticeSink notice = [&](const Notice& n) { s.notices.push_back(sceneNotice(n)); };
  s.restCage = makeCage(mesh, s, notice);
  s.meshTriangles = mesh.faces.empty() ? Eigen::MatrixXi(0, 3) : triangulatePolygons(mesh.vertices, mesh.faces);
  if (mesh.faces.empty())  // a point set, or a file cut short inside its vertices: no surface to draw either way
    s.notices.push_back("mesh warning: " + meshPath + " has " + std::to_string(mesh.vertices.rows()) +
                        " vertices but no faces: a point set, deformed as points with no surface drawn; if it "
                        "should have faces, the file is probably cut short (compare it with the original)");
  s.meshVertices = meshPointsFor(s.restCage, mesh.vertices, meshPath, cageSource, notice);
  s.document = std::move(document);
  s.meshPath = meshPath;
  const std::size_t slash = meshPath.find_last_of('/');
  s.name = slash == std::string::npos ? meshPath : meshPath.substr(slash + 1);
  return s;
}

}  // namespace

std::string sceneNotice(const Notice& n) {
  return std::string(n.source.empty() ? "mesh " : "cage ") +
         (n.kind == Notice::Kind::Repair ? "repaired: " : "warning: ") + n.text;
}

Scene loadScene(const std::string& meshPath, const std::string& cagePath) {
  Scene s = meshScene(meshPath, cagePath, [&](const PolygonMesh& mesh, Scene& scene, const NoticeSink& notice) {
    return cagePath.empty() ? prepareCage(generatedCage(mesh, meshPath, scene.notices), meshPath, notice)
                            : loadUsableCage(cagePath, notice);
  });
  s.cagePath = cagePath;
  return s;
}

Scene loadSceneWithCage(const std::string& meshPath, const Cage& cage, const std::string& cageSource) {
  if (meshPath.empty()) {
    Scene demo = makeDemoScene(cage.dim());
    demo.restCage = cage;
    return demo;
  }
  return meshScene(meshPath, cageSource, [&](const PolygonMesh&, Scene&, const NoticeSink&) { return cage; });
}

void bounds3(const Eigen::MatrixXd& points, Eigen::Vector3d& lo, Eigen::Vector3d& hi) {
  lo.setZero();
  hi.setZero();
  if (points.rows() == 0) return;
  for (Eigen::Index c = 0; c < std::min<Eigen::Index>(points.cols(), 3); ++c) {
    lo[c] = points.col(c).minCoeff();
    hi[c] = points.col(c).maxCoeff();
  }
}

}  // namespace somicage::editor
