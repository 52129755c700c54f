// The parameter table (core/deform/parameter_schema.h) against DeformParams' own defaults and fields, its text and JSON
// forms, the sessions that predate it, and a row and a method registered from test code (constant_method.h)
// through the engine.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "base/errors.h"
#include "base/json.h"
#include "constant_method.h"
#include "deform/parameter_json.h"
#include "engine/engine.h"
#include "engine/session.h"
#include "test_shapes.h"

namespace somicage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Each row's default is the value DeformParams' own initialisers give, and setting a row changes its field alone.
TEST(ParameterSchema, RowsAreDeformParamsFieldsWithTheirDefaults) {
  const DeformParams defaults;
  std::set<std::string> keys, flags, sessionKeys, keywords;
  for (const ParameterSpec& spec : parameterSchema()) {
    SCOPED_TRACE(spec.key);
    EXPECT_EQ(parameterValue(spec, defaults), spec.defaultValue);
    EXPECT_TRUE(keys.insert(spec.key).second);
    EXPECT_TRUE(sessionKeys.insert(spec.sessionKey).second);
    EXPECT_TRUE(keywords.insert(spec.pythonKeyword).second);
    for (const ParameterFlag& f : parameterFlags())
      if (f.spec == &spec) {
        EXPECT_TRUE(flags.insert(f.flag).second) << f.flag;
      }
  }
  DeformParams p;
  p.nu = 0.25;
  EXPECT_EQ(parameterValue(*findParameter("nu"), p), 0.25);
  setParameter(*findParameter("gamma"), p, 2.0);
  EXPECT_EQ(p.gamma, 2.0);
  setParameter(*findParameter("traction-fix"), p, 0.0);
  EXPECT_FALSE(p.tractionCorrection);
  setParameter(*findParameter("corotational"), p, 1.0);
  EXPECT_TRUE(p.corotational);
  setParameter(*findParameter("bulging"), p, parseParameter(*findParameter("bulging"), "swept-volume", "t"));
  EXPECT_EQ(p.bulging, Bulging::SweptVolume);
  setParameter(*findParameter("normals"), p, parseParameter(*findParameter("normals"), "angle", "t"));
  EXPECT_EQ(p.normals, NormalWeights::Angle);
  setParameter(*findParameter("variant"), p, parseParameter(*findParameter("variant"), "stable", "t"));
  EXPECT_EQ(p.kind, VariantKind::Stable);
  EXPECT_EQ(p.blend, 1.0);
  EXPECT_EQ(p.nu, 0.25);  // untouched by the others
}

// The ranges of deform_params.h, as the paper states them: nu in (-1, 0.5) or +-inf (section 5), gamma in [0, 10],
// blend in [0, 1]; each is refused just outside, named by its label.
TEST(ParameterSchema, TextReadsBackAndRangesHoldAtTheirEnds) {
  const ParameterSpec& nu = *findParameter("nu");
  for (const double v : {-0.999, 0.0, 0.3, 0.499, kInf, -kInf})
    EXPECT_EQ(parseParameter(nu, parameterText(nu, v), "--nu"), v) << v;
  EXPECT_EQ(parameterText(nu, 0.1 + 0.2), "0.30000000000000004");  // the shortest text that reads back exactly
  // Parsed, then checked against the range (a method checks it with its own words first: BEM's nu = 0.5).
  const auto check = [](const ParameterSpec& spec, const char* text) {
    validateParameter(spec, parseParameter(spec, text, "t"));
  };
  for (const char* bad : {"0.5", "-1", "nan", "0.7", "x"}) EXPECT_THROW(check(nu, bad), InputError) << bad;
  const ParameterSpec& gamma = *findParameter("gamma");
  EXPECT_NO_THROW(check(gamma, "10"));
  EXPECT_THROW(check(gamma, "10.000001"), InputError);
  EXPECT_THROW(check(gamma, "inf"), InputError);
  EXPECT_THROW(check(*findParameter("blend"), "-0.01"), InputError);
  EXPECT_EQ(parseParameter(*findParameter("traction-fix"), "off", "t"), 0.0);
  EXPECT_THROW(parseParameter(*findParameter("traction-fix"), "no", "t"), InputError);
  DeformParams p;
  p.gamma = 11;
  try {
    validateDeformParams(p);
    FAIL() << "gamma 11 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "gamma");
    EXPECT_EQ(e.problem(), "bulging scale 11 is out of range");
    EXPECT_EQ(e.hint(), "use a value in [0, 10]");
  }
}

// "blend" is read (sessions hold it for the paper's variant between its ends) but not offered.
TEST(ParameterSchema, TheVariantBlendIsReadButNotOffered) {
  const ParameterSpec& variant = *findParameter("variant");
  EXPECT_EQ(parameterSyntax(variant), "global, local, affine or stable");
  DeformParams p;
  p.blend = 0.5;
  EXPECT_EQ(parameterText(variant, parameterValue(variant, p)), "blend");
  setParameter(variant, p, parseParameter(variant, "blend", "t"));
  EXPECT_EQ(p.blend, 0.5);
  EXPECT_EQ(p.kind, VariantKind::Blend);
}

// A session's "params" from before the table (version 1: no variant, bulging, normals or corotational) reads with
// their defaults; one written now reads back every field exactly.
TEST(ParameterSchema, SessionParametersOldAndNew) {
  DeformParams old;
  readParameters(parseJson(R"({"blend": 1, "nu": "-inf", "gamma": 0.5, "tractionCorrection": false})", "s"), old, "s");
  EXPECT_EQ(variantName(old), "local");
  EXPECT_EQ(old.nu, -kInf);
  EXPECT_EQ(old.gamma, 0.5);
  EXPECT_FALSE(old.tractionCorrection);
  EXPECT_FALSE(old.corotational);
  EXPECT_EQ(old.bulging, Bulging::SolidAngle);
  DeformParams p;
  setVariant(p, "affine", "t");
  p.nu = 1.0 / 3.0;
  p.gamma = 0.1 + 0.2;
  p.corotational = true;
  p.normals = NormalWeights::Angle;
  JsonValue object = JsonValue::object();
  writeParameters(p, object);
  DeformParams back;
  readParameters(parseJson(object.dump(), "s"), back, "s");
  EXPECT_TRUE(back == p);
  // Every variant, bulging convention and normal weighting (issue 26) is kept by a session, each with the others
  // at a non-default value.
  for (const VariantChoice& variant : variantChoices())
    for (const ChoiceParameter& choice : choiceParameters())
      for (int value = 0; value < static_cast<int>(choice.values.size()); ++value) {
        DeformParams q;
        setVariant(q, variant.name, "t");
        for (const ChoiceParameter& other : choiceParameters()) other.set(q, 1);
        choice.set(q, value);
        JsonValue written = JsonValue::object();
        writeParameters(q, written);
        DeformParams read;
        readParameters(parseJson(written.dump(), "s"), read, "s");
        EXPECT_TRUE(read == q) << variant.name << " " << choice.name << " "
                               << choice.values[static_cast<std::size_t>(value)].name;
        EXPECT_EQ(variantName(read), variant.name);
      }
  try {
    readParameters(parseJson(R"({"nu": "x"})", "s.json"), back, "s.json");
    FAIL() << "nu \"x\" read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("s.json: \"nu\" must be a value in (-1, 0.5), or inf / -inf"), 0u)
        << e.what();
  }
}

// docs/engine.md's "Adding a method" and "Adding a parameter", re-checked from test code alone: the registered
// method is in the registry and deforms through the engine as the closed form y = x + u; the registered row is
// validated and kept in DeformParams::extra.
TEST(ParameterSchema, ARowAndAMethodRegisteredByATestWorkThroughTheEngine) {
  const std::size_t methodCount = allMethods().size(), rowCount = parameterSchema().size();
  {
    const test::ConstantMethodRegistration registration;
    EXPECT_EQ(allMethods().size(), methodCount + 1);
    EXPECT_EQ(parseMethod("constant"), test::constantMethod());
    EXPECT_EQ(allMethods().back(), test::constantMethod());  // its listOrder is the largest
    EXPECT_EQ(methodsReading(test::kParamTestShift), "constant only");
    const Cage cage = test::makeExtrudedL();
    const Eigen::MatrixXd points = test::randomBoxPoints(20, 3, 0.2, 0.8, 7);
    const std::unique_ptr<CageDeformer> deformer = precompute(test::constantMethod(), cage, points, {}, "test");
    Eigen::MatrixXd posed = cage.vertices;
    posed.col(1).array() += 0.5;
    posed(0, 2) += 1.2;  // one vertex more: the mean displacement is (0, 0.5, 1.2 / #V)
    DeformParams params;
    params.extra["test-shift"] = -0.75;
    const Eigen::RowVector3d u(-0.75, 0.5, 1.2 / cage.numVertices());
    EXPECT_LE(((points.rowwise() + u) - deformer->deform(posed, params)).cwiseAbs().maxCoeff(), 1e-14);
    params.extra["test-shift"] = 1.5;
    EXPECT_THROW(deformer->deform(posed, params), InputError);
  }
  EXPECT_EQ(allMethods().size(), methodCount);
  EXPECT_EQ(parameterSchema().size(), rowCount);
  EXPECT_FALSE(findMethod("constant").has_value());
}

}  // namespace
}  // namespace somicage
