// The method registry (core/deform/method.h): every method is listed once, in order, by name; each method's layout is
// the shape of the matrix C its deformer stores; nothing outside a descriptor knows a method by heart.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "base/errors.h"
#include "deform/deformer.h"
#include "deform/method.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

TEST(MethodRegistry, ListsEveryMethodOnceInListOrder) {
  const std::vector<Method>& all = allMethods();
  ASSERT_GE(all.size(), 3u);
  std::set<std::string> names;
  for (std::size_t k = 0; k < all.size(); ++k) {
    EXPECT_TRUE(names.insert(all[k]->name).second) << all[k]->name << " twice";
    EXPECT_FALSE(std::string(all[k]->displayName).empty());
    EXPECT_FALSE(std::string(all[k]->description).empty());
    if (k > 0) {
      EXPECT_LT(all[k - 1]->listOrder, all[k]->listOrder);
    }
  }
  EXPECT_TRUE(names.count("somigliana") && names.count("green") && names.count("mvc"));
  EXPECT_EQ(Method(), methods::somigliana()) << "the default method is the paper's";
  // The registry is generated from the method files (core/CMakeLists.txt): it names exactly the NAME of each
  // core/methods/NAME_method.cpp, read here from the source folder itself.
  std::set<std::string> files;
  const std::filesystem::path folder = std::filesystem::path(SOMICAGE_TEST_DATA_DIR) / ".." / ".." / "core" / "methods";
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string file = entry.path().filename().string();
    const std::string suffix = "_method.cpp";
    if (file.size() > suffix.size() && file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0)
      files.insert(file.substr(0, file.size() - suffix.size()));
  }
  EXPECT_EQ(names, files);
}

TEST(MethodRegistry, NamesRoundTripAndUnknownNamesAreRefusedWithTheList) {
  for (Method m : allMethods()) {
    EXPECT_EQ(parseMethod(methodName(m)), m);
  }
  EXPECT_FALSE(findMethod("harmonic").has_value());
  try {
    parseMethod("harmonic");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "--method");
    EXPECT_EQ(e.problem(), "unknown method 'harmonic'");
    for (Method m : allMethods()) EXPECT_NE(e.hint().find(m->name), std::string::npos) << e.hint();
  }
  EXPECT_EQ(methodNameList().find("somigliana, green"), 0u) << methodNameList();
}

// The layout's column counts are what the deformer stores (points strictly inside: no exterior rows), and its
// vertex, face and tail columns cover [0, columns) exactly once.
TEST(MethodRegistry, EachLayoutIsTheShapeOfTheStoredCoordinates) {
  const Cage cages[] = {test::makeExtrudedL(), makePolygonCage(test::lLoop())};
  for (const Cage& cage : cages) {
    const Eigen::MatrixXd points = test::randomBoxPoints(11, cage.dim(), 0.2, 0.8, 3);
    for (Method method : allMethods()) {
      SCOPED_TRACE(methodName(method) + " " + std::to_string(cage.dim()) + "D");
      // A volume method's vertices are its volume mesh's: here the cage's star (no mesher given).
      const CoordinateLayout layout =
          coordinateLayout(method, cage, method->needsVolumeMesh ? cage.numVertices() + 1 : -1);
      const std::unique_ptr<CageDeformer> deformer = makeDeformer(method, cage, points);
      EXPECT_EQ(deformer->method(), method);
      EXPECT_EQ(deformer->frameCoordinates().mainColumns, layout.mainColumns());
      EXPECT_EQ(deformer->frameCoordinates().columns(), layout.columns());
      EXPECT_EQ(deformer->frameCoordinates().bytes(), layout.bytes(points.rows(), false));
      std::vector<int> hits(layout.columns(), 0);
      for (int i = 0; i < layout.numVertices; ++i)
        for (int k = 0; k < layout.vertexTerms; ++k) ++hits[layout.vertexColumn(i, k)];
      for (int j = 0; j < layout.numFaces; ++j)
        for (int k = 0; k < layout.faceTerms; ++k) ++hits[layout.faceColumn(j, k)];
      for (int k = 0; k < layout.tailColumns; ++k) ++hits[layout.tailColumn(k)];
      EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), layout.columns());
      // The frame finishes as the descriptor states (frame_finish.h), and every method reproduces the rest pose:
      // the identity is in the span of each method's coordinates (x = sum of the rest vertices' weights).
      const FrameWeights W = deformer->frameWeights(cage.vertices, DeformParams{});
      EXPECT_EQ(W.finish, method->finish);
      EXPECT_EQ(W.outputs, frameOutputs(method->finish, cage.dim()));
      EXPECT_LE((deformer->deform(cage.vertices, DeformParams{}) - points).cwiseAbs().maxCoeff(), 1e-8);
    }
  }
}

}  // namespace
}  // namespace somicage
