// Issue 23: the editor's front ends read the parameter table (core/deform/parameter_schema.h) and the method registry
// at run time. A row and a method registered from test code (core/constant_method.h) are on the editor's command line
// and in its help, in --view specs, view labels and sessions, and in the measurement key; the spellings kept from
// before (--local, --traction-fix off, a session's "tractionCorrection") still read as they did.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>  // GImGui->LogBuffer: the text a frame drew

#include <cstring>

#include "base/errors.h"
#include "base/json.h"
#include "core/constant_method.h"
#include "deform/deform_choices.h"
#include "editor_options.h"
#include "engine/session.h"
#include "headless_imgui.h"
#include "jobs/measure_worker.h"
#include "methods/method_descriptors.h"
#include "model/app_state.h"
#include "ui/parameter_panel.h"

namespace somicage::editor {
namespace {

using test::ConstantMethodRegistration;

TEST(EditorParameterSchema, ARegisteredParameterAndMethodReachEveryEditorFrontEnd) {
  const ConstantMethodRegistration registration;
  // Command line and help.
  const EditorOptions o = parseEditorArgs({"--method", "constant", "--test-shift", "0.25"});
  EXPECT_EQ(*o.method, test::constantMethod());
  EXPECT_EQ(o.parameters.at("test-shift"), 0.25);
  EXPECT_THROW(parseEditorArgs({"--test-shift", "3"}), InputError);  // the row's range [-1, 1]
  EXPECT_NE(editorUsage().find("--test-shift V"), std::string::npos) << editorUsage();
  EXPECT_NE(editorUsage().find("constant"), std::string::npos) << editorUsage();

  // --view: the method and its parameter; a method that does not read it is refused.
  const ViewSpec view = parseViewSpec("constant:test-shift=-0.5", "--view");
  EXPECT_EQ(view.method, test::constantMethod());
  EXPECT_EQ(view.value("test-shift"), -0.5);
  EXPECT_EQ(view.params(DeformParams{}).extra.at("test-shift"), -0.5);
  try {
    parseViewSpec("somigliana:test-shift=0.5", "--view");
    FAIL() << "somigliana does not read test-shift";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("somigliana does not read test-shift"), std::string::npos) << e.what();
  }

  // The pane's label shows the view's own value.
  AppState state;
  state.view.compare = true;
  state.view.compareViews = {view, ViewSpec{methods::somigliana(), {}, {}}};
  EXPECT_NE(viewLabel(state, 0).find("Constant  test-shift=-0.50 (own)"), std::string::npos) << viewLabel(state, 0);

  // Sessions: the shared value under the row's session key, and the view's own, read back exactly.
  Session s;
  s.method = test::constantMethod();
  s.params.extra["test-shift"] = 0.125;
  s.compare = true;
  s.compareViews = state.view.compareViews;
  const std::string text = sessionToJson(s);
  EXPECT_NE(text.find("\"testShift\": 0.125"), std::string::npos) << text;
  const Session back = sessionFromJson(text, "s.json");
  EXPECT_EQ(back.method, test::constantMethod());
  EXPECT_TRUE(back.params == s.params);
  ASSERT_EQ(back.compareViews.size(), 2u);
  EXPECT_TRUE(back.compareViews[0] == view);

  // The measurement key sees the new parameter: a changed value makes the measurements stale.
  MeasureRequest a, b;
  a.views.resize(1);
  b.views = a.views;
  b.views[0].params.extra["test-shift"] = 0.5;
  EXPECT_TRUE(measureKey(a) != measureKey(b));
}

// The control panel's parameter widgets are one loop over the table (parameter_panel.h): a row registered here
// gets its slider, with the row's key, range and tooltip, enabled while a view of a method reading it is shown;
// drawn in a real (headless) ImGui frame, its label is among the texts the panel draws. Before, the panel's sliders
// and boxes were written by hand and a new row never showed.
TEST(EditorParameterSchema, ARegisteredParameterGetsItsWidgetInThePanel) {
  const ConstantMethodRegistration registration;
  AppState state;
  state.document.method = test::constantMethod();
  const auto width = [](const char* text) { return 7.0f * static_cast<float>(std::strlen(text)); };
  std::vector<ParameterWidget> widgets = parameterWidgets(state, 320, width);
  ASSERT_EQ(widgets.size(), parameterSchema().size());
  const auto find = [&](const char* key) -> const ParameterWidget* {
    for (const ParameterWidget& w : widgets)
      if (std::string(w.spec->key) == key) return &w;
    return nullptr;
  };
  const ParameterWidget* shift = find("test-shift");
  ASSERT_NE(shift, nullptr);
  EXPECT_EQ(shift->kind, ParameterWidgetKind::Slider);
  EXPECT_EQ(shift->label, "test-shift");
  EXPECT_EQ(shift->min, -1.0f);  // the row's closed range [-1, 1]
  EXPECT_EQ(shift->max, 1.0f);
  EXPECT_TRUE(shift->enabled);
  EXPECT_NE(shift->tooltip.find("moves the constant method's points along x"), std::string::npos) << shift->tooltip;
  EXPECT_NE(shift->tooltip.find("Read by Constant."), std::string::npos) << shift->tooltip;
  EXPECT_FALSE(find("nu")->enabled);  // the constant method reads no nu
  // The built-in rows by their type: nu's open range (-1, 0.5) inset, switches as boxes, choices listed.
  const ParameterWidget* nu = find("nu");
  EXPECT_GT(nu->min, -1.0f);
  EXPECT_LT(nu->max, 0.5f);
  EXPECT_GT(nu->max, 0.45f);
  EXPECT_EQ(find("traction-fix")->kind, ParameterWidgetKind::Checkbox);
  EXPECT_NE(find("bulging")->kind, ParameterWidgetKind::Slider);
  EXPECT_NE(find("bulging")->tooltip.find("swept-volume"), std::string::npos);

  state.document.method = methods::somigliana();
  widgets = parameterWidgets(state, 320, width);
  EXPECT_FALSE(find("test-shift")->enabled);
  EXPECT_TRUE(find("nu")->enabled);
  EXPECT_TRUE(find("blend")->enabled) << "the global variant is the paper's at blend 0";
  setVariant(state.document.params, "affine", "test");
  widgets = parameterWidgets(state, 320, width);
  EXPECT_FALSE(find("blend")->enabled) << "blend applies to the paper's variant only";
  EXPECT_FALSE(find("corotational")->enabled) << "BEM's alone";

  // gamma's tooltip names the bulging convention in force (issue 26): the first "(bulging: " in it is the active one.
  state.document.method = methods::somigliana();
  for (const ChoiceParameter& choice : choiceParameters()) {
    if (std::string(choice.name) != "bulging") continue;
    for (int value = 0; value < static_cast<int>(choice.values.size()); ++value) {
      choice.set(state.document.params, value);
      widgets = parameterWidgets(state, 320, width);
      const std::string tip = find("gamma")->tooltip;
      const std::string named = std::string("(bulging: ") + choice.values[static_cast<std::size_t>(value)].name + ")";
      EXPECT_NE(tip.find(named), std::string::npos) << named << " in " << tip;
      EXPECT_EQ(tip.find("(bulging: "), tip.find(named)) << named << " first in " << tip;
    }
  }
  state.document.params = {};

  // A real frame: the panel draws the new row's label.
  ImGuiContext* context = createHeadlessImGui(800, 600);
  ImGui::NewFrame();
  ImGui::SetNextWindowSize(ImVec2(340, 560));
  ImGui::Begin("Controls");
  state.document.method = test::constantMethod();
  ImGui::LogToBuffer();
  drawParameterWidgets(state);
  const std::string drawn = GImGui->LogBuffer.c_str();
  ImGui::LogFinish();
  ImGui::End();
  ImGui::Render();
  ImGui::DestroyContext(context);
  for (const ParameterSpec& spec : parameterSchema())
    EXPECT_NE(drawn.find(spec.type == ParameterType::Switch ? spec.label : spec.key), std::string::npos)
        << spec.key << " not drawn:\n" << drawn;
  EXPECT_NE(drawn.find("test-shift"), std::string::npos) << drawn;
}

// The measurement key held blend, nu, gamma, the two switches and the two choices but not the variant's kind, so
// switching global (blend 0) to affine (blend 0) kept the global variant's measurements.
TEST(EditorParameterSchema, TheMeasurementKeyTellsVariantsOfEqualBlendApart) {
  MeasureRequest global, affine;
  global.views.resize(1);
  affine.views = global.views;
  setVariant(affine.views[0].params, "affine", "test");
  ASSERT_EQ(affine.views[0].params.blend, global.views[0].params.blend);
  EXPECT_TRUE(measureKey(global) != measureKey(affine));
}

TEST(EditorParameterSchema, SpellingsFromBeforeTheTableStillRead) {
  const auto applied = [](const EditorOptions& o) {
    DeformParams p;
    for (const ParameterSpec& spec : parameterSchema())
      if (o.parameters.count(spec.key)) setParameter(spec, p, o.parameters.at(spec.key));
    return p;
  };
  EXPECT_EQ(variantName(applied(parseEditorArgs({"--local"}))), "local");
  EXPECT_EQ(variantName(applied(parseEditorArgs({"--variant", "stable", "--global"}))), "global");
  EXPECT_FALSE(applied(parseEditorArgs({"--traction-fix", "off"})).tractionCorrection);
  EXPECT_FALSE(applied(parseEditorArgs({"--no-traction-fix"})).tractionCorrection);
  EXPECT_TRUE(applied(parseEditorArgs({"--corotational"})).corotational);  // the editor lacked it before the table
  // --blend after --local: the variant's kind stays the paper's, at that blend.
  const DeformParams blended = applied(parseEditorArgs({"--local", "--blend", "0.25"}));
  EXPECT_EQ(blended.blend, 0.25);
  EXPECT_EQ(variantName(blended), "blend");
}

}  // namespace
}  // namespace somicage::editor
