#include "ui/parameter_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "deform/deform_choices.h"
#include "deform/deform_params.h"
#include "deform/method.h"
#include "engine/view_spec.h"
#include "model/app_state.h"
#include "ui/panels.h"  // tooltip

namespace somicage::editor {

namespace {

// The editor's longer help for some rows (the equations behind them), after the table's one line. A row without
// any needs nothing here.
std::string detail(const std::string& key, const DeformParams& p) {
  if (key == "variant")
    return "global: one similarity (R, s) fitted to the whole cage (Umeyama); R_j = R, lambda_j = s.\n"
           "local: each face's own polar rotation R_j and stretch lambda_j (Eqs. 12-14).\n"
           "affine: the global variant with the best-fit affine map A = R S; any affine pose moves the mesh exactly.\n"
           "stable: the local variant without the fold-overs it makes at high nu (docs/engine.md).";
  if (key == "blend")
    return "t in [0, 1] between the global (0) and the local (1) variant (Fig. 4):\n"
           "R_j(t) = R exp(t log(R^T R_j)), lambda_j(t) = t lambda_j + (1 - t) s.";
  if (key == "nu")
    return "It sets the traction scale s_j = 2[eta_j + nu/(1-2nu) (eta_j + (d-1) lambda_j)] (Eqs. 12-14).\n"
           "The limit nu -> infinity: the Laplace layers of Green coordinates plus an antisymmetric part\n"
           "(in 2D with gamma = 0 exactly Green coordinates, paper section 5).";
  if (key == "gamma") {
    switch (p.bulging) {
      case Bulging::Reference:
        return "The authors' code's convention (bulging: reference): eta_j = lambda_j exp(gamma^2 dOmega_j / 4 pi),\n"
               "dOmega_j the change of the unsigned solid angle of the face's vertex normals (2D: signed angle /\n"
               "2 pi). gamma here = gamma in the paper's figures. 0: none.";
      case Bulging::SweptVolume:
        return "Swept volume (bulging: swept-volume): eta_j = lambda_j exp(gamma^2 V_j / V), V_j the volume face j\n"
               "swept from the best-fit similarity of its rest place, V that cage's volume. 0: no bulging.";
      case Bulging::Polygon:
        return "The paper's solid angle per flat polygon (bulging: polygon): as solid-angle, but coplanar\n"
               "neighbouring faces share one eta from their summed beta. 0: no bulging.";
      case Bulging::SolidAngle:
        break;
    }
    return "Section 4.4, the paper's text (bulging: solid-angle): eta_j = lambda_j exp(gamma beta_j / (2^(d-1) pi)),\n"
           "beta_j the change of the face's signed solid angle of vertex normals. The paper's figures used gamma^2\n"
           "(bulging: reference). 0: no bulging.";
  }
  if (key == "traction-fix") return "s'_j = s_j - lambda . w_j, so that a similarity pose moves the mesh as a similarity.";
  if (key == "corotational")
    return "The best-fit rotation (Umeyama) is applied after the solve, so large rotations do not shear the mesh.";
  return "";
}

// Rows that apply only for some values of another: blend is the paper's variant's (a chosen variant sets it).
bool applies(const ParameterSpec& spec, const DeformParams& p) {
  return std::string(spec.key) != "blend" || p.kind == VariantKind::Blend;
}

std::string methodList(DeformParameter parameter) {
  std::string list;
  for (Method m : allMethods())
    if (readsParameter(m, parameter)) list += (list.empty() ? "" : ", ") + std::string(m->displayName);
  return list.empty() ? "no method" : list;
}

// The values a choice offers (the table keeps some only to read, e.g. the variant "blend").
std::vector<int> offered(const ParameterSpec& spec) {
  std::vector<int> values;
  for (std::size_t k = 0; k < spec.values.size(); ++k)
    if (spec.values[k].description) values.push_back(static_cast<int>(k));
  return values;
}

float imguiTextWidth(const char* text) { return ImGui::CalcTextSize(text).x; }

}  // namespace

void sliderSpan(const ParameterSpec& spec, float& min, float& max) {
  const double inset = spec.openRange ? std::min(0.01, 0.01 * (spec.range.max - spec.range.min)) : 0.0;
  min = static_cast<float>(spec.range.min + inset);
  max = static_cast<float>(spec.range.max - inset);
}

std::vector<ParameterWidget> parameterWidgets(const AppState& state, float panelWidth,
                                              float (*textWidth)(const char* text)) {
  unsigned shownParameters = 0;  // the parameters some shown view's method reads
  for (const DeformerKey& key : state.deformerKeys()) shownParameters |= key.method->parameters;
  std::vector<ParameterWidget> widgets;
  for (const ParameterSpec& spec : parameterSchema()) {
    ParameterWidget w;
    w.spec = &spec;
    w.enabled = (shownParameters & spec.parameter) != 0 && applies(spec, state.document.params);
    const std::string more = detail(spec.key, state.document.params);
    w.tooltip = std::string(spec.label) + ": " + spec.tooltip + (more.empty() ? "" : "\n" + more) +
                "\nRead by " + methodList(spec.parameter) + ".";
    switch (spec.type) {
      case ParameterType::Number: {
        w.kind = ParameterWidgetKind::Slider;
        w.label = spec.key;
        sliderSpan(spec, w.min, w.max);
        w.infinite = spec.infinities && std::isinf(parameterValue(spec, state.document.params));
        w.tooltip += " Ctrl+click to type a value.";
        break;
      }
      case ParameterType::Switch:
        w.kind = ParameterWidgetKind::Checkbox;
        w.label = spec.label;
        break;
      case ParameterType::Choice: {
        w.label = spec.key;
        float width = textWidth(spec.key);  // the label after the buttons
        for (int k : offered(spec)) width += textWidth(spec.values[static_cast<std::size_t>(k)].name) + 32;
        w.kind = panelWidth > 0 && width <= panelWidth ? ParameterWidgetKind::Radio : ParameterWidgetKind::Combo;
        for (int k : offered(spec))
          w.tooltip += std::string("\n  ") + spec.values[static_cast<std::size_t>(k)].name + ": " +
                       spec.values[static_cast<std::size_t>(k)].description;
        break;
      }
    }
    widgets.push_back(std::move(w));
  }
  return widgets;
}

void drawParameterWidgets(AppState& state) {
  DeformParams p = state.document.params;
  std::string step;       // an edit complete at once (a box, a button): its undo step's name
  std::string sliderDone;  // a slider released after a drag
  for (const ParameterWidget& w :
       parameterWidgets(state, ImGui::GetContentRegionAvail().x, imguiTextWidth)) {
    const ParameterSpec& spec = *w.spec;
    const double value = parameterValue(spec, p);
    ImGui::PushID(spec.key);
    ImGui::BeginDisabled(!w.enabled);
    switch (w.kind) {
      case ParameterWidgetKind::Slider: {
        if (spec.infinities) {
          bool infinite = w.infinite;
          const std::string box = std::string(spec.key) + " = infinity";
          if (ImGui::Checkbox(box.c_str(), &infinite)) {
            const double finite = std::isfinite(spec.defaultValue) ? spec.defaultValue : 0.5 * (w.min + w.max);
            setParameter(spec, p, infinite ? std::numeric_limits<double>::infinity() : finite);
            step = spec.label;
          }
          tooltip(w.tooltip.c_str());
        }
        if (w.infinite) {
          ImGui::TextDisabled("%s = inf (the limit)", spec.key);
          break;
        }
        float v = static_cast<float>(value);
        // Typed values (Ctrl+click) are clamped too: the range's ends or +-inf only through the box.
        if (ImGui::SliderFloat(w.label.c_str(), &v, w.min, w.max, "%.3f", ImGuiSliderFlags_AlwaysClamp))
          setParameter(spec, p, v);
        if (ImGui::IsItemDeactivatedAfterEdit()) sliderDone = spec.key;
        tooltip(w.tooltip.c_str());
        break;
      }
      case ParameterWidgetKind::Checkbox: {
        bool on = value != 0;
        if (ImGui::Checkbox(w.label.c_str(), &on)) {
          setParameter(spec, p, on ? 1.0 : 0.0);
          step = spec.label;
        }
        tooltip(w.tooltip.c_str());
        break;
      }
      case ParameterWidgetKind::Radio: {
        for (int k : offered(spec)) {
          const ChoiceValue& c = spec.values[static_cast<std::size_t>(k)];
          if (ImGui::RadioButton(c.name, static_cast<int>(value) == k) && static_cast<int>(value) != k) {
            setParameter(spec, p, k);
            step = std::string(c.name) + " " + spec.key;
          }
          tooltip((std::string(c.name) + ": " + c.description + "\n\n" + w.tooltip).c_str());
          ImGui::SameLine();
        }
        ImGui::TextUnformatted(w.label.c_str());
        tooltip(w.tooltip.c_str());
        break;
      }
      case ParameterWidgetKind::Combo: {
        const std::size_t current = static_cast<std::size_t>(value);
        if (ImGui::BeginCombo(w.label.c_str(), current < spec.values.size() ? spec.values[current].name : "")) {
          for (int k : offered(spec)) {
            const ChoiceValue& c = spec.values[static_cast<std::size_t>(k)];
            if (ImGui::Selectable(c.name, static_cast<std::size_t>(k) == current) &&
                static_cast<std::size_t>(k) != current) {
              setParameter(spec, p, k);
              step = spec.label;
            }
            tooltip(c.description);
          }
          ImGui::EndCombo();
        }
        tooltip(w.tooltip.c_str());
        break;
      }
    }
    ImGui::EndDisabled();
    ImGui::PopID();
  }
  if (p != state.document.params) setParams(state, p);
  if (!step.empty()) commitEdit(state, step);
  if (!sliderDone.empty()) commitEdit(state, sliderDone);
}

}  // namespace somicage::editor
