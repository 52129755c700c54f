// A throw-away method and parameter registered from test code alone, touching no other file (issue 23: docs/engine.md's
// "Adding a method" and "Adding a parameter" re-checked). The method moves every point by one vector,
// y = x + u with u = the cage's mean vertex displacement + shift e_x, where shift is the test parameter: C's row of a
// point is its tail [x | 1] and W's tail is [I; u], so the front ends' y equals the closed form x + u.
#pragma once

#include <memory>

#include "deform/deformer.h"
#include "deform/frame_evaluation.h"
#include "deform/parameter_schema.h"

namespace somicage::test {

constexpr DeformParameter kParamTestShift = static_cast<DeformParameter>(1u << 20);

inline ParameterSpec shiftParameter() {
  return {"test-shift", ParameterType::Number, {},  nullptr, "test_shift", "testShift", "test shift",
          "moves the constant method's points along x", {-1.0, 1.0}, false, false, 0.0, {}, kParamTestShift,
          LabelShow::Always, nullptr, nullptr};
}

const MethodDescriptor& constantMethod();

class ConstantDeformer : public CageDeformer {
 public:
  ConstantDeformer(const Cage& rest, const Eigen::MatrixXd& points, const PrecomputeOptions& options)
      : CageDeformer(makeFrameCoordinates(rows(points), 0, options.floatStorage), options.threads), rest_(rest) {}

  Method method() const override { return constantMethod(); }
  int dim() const override { return rest_.dim(); }

  FrameWeights frameWeights(const Eigen::MatrixXd& posed, const DeformParams& params) const override {
    validateDeformParams(params);
    const int d = rest_.dim();
    Eigen::RowVectorXd u = (posed - rest_.vertices).colwise().mean();
    u(0) += parameterValue(*findParameter("test-shift"), params);
    FrameWeights W;
    W.outputs = d;
    W.main.resize(0, d);
    W.tail.resize(d + 1, d);
    W.tail << Eigen::MatrixXd::Identity(d, d), u;
    return W;
  }

  // d(x | 1)/dx_a = (e_a | 0).
  std::vector<FrameCoordinates> coordinateGradients(const Eigen::MatrixXd& points,
                                                    const ProgressCallback&) const override {
    std::vector<FrameCoordinates> frames;
    for (int a = 0; a < rest_.dim(); ++a) {
      CoordinateMatrix<double> g = CoordinateMatrix<double>::Zero(points.rows(), rest_.dim() + 1);
      g.col(a).setOnes();
      frames.push_back(makeFrameCoordinates(std::move(g), 0, coordinates_.isFloat()));
    }
    return frames;
  }

 private:
  static CoordinateMatrix<double> rows(const Eigen::MatrixXd& points) {
    CoordinateMatrix<double> C(points.rows(), points.cols() + 1);
    C << points, Eigen::VectorXd::Ones(points.rows());
    return C;
  }
  Cage rest_;
};

inline const MethodDescriptor& constantMethod() {
  static const MethodDescriptor descriptor{
      "constant",
      "Constant",
      "test: every point moved by the cage's mean displacement",
      1000,
      kParamTestShift,
      true,
      false,
      {},
      validateDeformParams,
      [](int dim, int numVertices, int numFaces) { return CoordinateLayout{numVertices, numFaces, 0, 0, dim + 1, 0}; },
      [](const CoordinateLayout&, int, std::size_t, bool, int) { return std::size_t{0}; },
      [](const Cage& rest, const Eigen::MatrixXd& points, const PrecomputeOptions& options,
         const ProgressCallback&) -> std::unique_ptr<CageDeformer> {
        return std::make_unique<ConstantDeformer>(rest, points, options);
      }};
  return descriptor;
}

// The parameter row and the method, for the test's lifetime.
struct ConstantMethodRegistration {
  ParameterRegistration parameter{shiftParameter()};
  MethodRegistration method{constantMethod()};
};

}  // namespace somicage::test
