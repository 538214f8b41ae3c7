#include "explorer/param_panel.h"

#include "scene/scene.h"

#include <imgui.h>

#include <cmath>

namespace sl {

namespace {

std::string tooltipText(const ParamDecl& decl) {
  std::string text = decl.help.empty() ? decl.key : decl.help;
  text += "\n\nkey:   " + decl.key;
  if (!decl.unit.empty()) text += "\nunit:  " + decl.unit;
  text += "\nrange: " + describeRange(decl);
  text += "\ndefault: " + formatValue(decl, decl.defaultValue);
  return text;
}

// "%.4g" keeps both 0.0005 and 4096 readable without a per-parameter format.
constexpr const char* kFloatFormat = "%.4g";

bool drawWidget(const ParamDecl& decl, ParamSet& params, double& newValue) {
  const double current = params.get(decl.key);
  const char* label = decl.key.c_str();
  switch (decl.type) {
    case ParamType::Float: {
      float v = static_cast<float>(current);
      ImGuiSliderFlags flags = decl.logScale ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
      flags |= ImGuiSliderFlags_AlwaysClamp;  // typed-in values beyond the range would be rejected
      if (!ImGui::SliderFloat(label, &v, float(decl.min), float(decl.max), kFloatFormat, flags)) return false;
      newValue = v;
      return true;
    }
    case ParamType::Int: {
      int v = static_cast<int>(std::lround(current));
      ImGuiSliderFlags flags = decl.logScale ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
      flags |= ImGuiSliderFlags_AlwaysClamp;
      if (!ImGui::SliderInt(label, &v, int(std::lround(decl.min)), int(std::lround(decl.max)), "%d", flags))
        return false;
      newValue = v;
      return true;
    }
    case ParamType::Bool: {
      bool v = current != 0.0;
      if (!ImGui::Checkbox(label, &v)) return false;
      newValue = v ? 1.0 : 0.0;
      return true;
    }
    case ParamType::Enum: {
      int index = static_cast<int>(std::lround(current));
      const char* preview =
          (index >= 0 && index < int(decl.choices.size())) ? decl.choices[size_t(index)].c_str() : "?";
      bool changed = false;
      if (ImGui::BeginCombo(label, preview)) {
        for (int i = 0; i < int(decl.choices.size()); ++i) {
          const bool selected = i == index;
          if (ImGui::Selectable(decl.choices[size_t(i)].c_str(), selected) && !selected) {
            newValue = i;
            changed = true;
          }
          if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
      }
      return changed;
    }
  }
  return false;
}

}  // namespace

// A narrow toggle: highlighted when the parameter is linked across viewports.
void linkToggle(const std::string& key, ParamLinks& links) {
  const bool on = links.all || links.linked->count(key);
  // Orange when linked, dim when not: the same "L" keeps the widgets aligned.
  ImGui::PushStyleColor(ImGuiCol_Button, on ? ImVec4(0.85f, 0.55f, 0.15f, 1.0f) : ImVec4(0.2f, 0.2f, 0.24f, 1.0f));
  ImGui::PushStyleColor(ImGuiCol_Text, on ? ImVec4(1, 1, 1, 1) : ImVec4(0.55f, 0.55f, 0.6f, 1.0f));
  if (ImGui::SmallButton("L") && !links.all) {
    if (on)
      links.linked->erase(key);
    else
      links.linked->insert(key);
  }
  ImGui::PopStyleColor(2);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(links.all ? "linked: 'Link all viewports' is on"
                      : on      ? "linked: a change here sets %s in every viewport that has it (click to unlink)"
                                : "not linked: click so that a change here sets %s in every viewport that has it",
                      key.c_str());
  ImGui::SameLine();
}

std::set<std::string> paramsWithoutEffect(const ParamSet& params, const Scene* scene) {
  std::set<std::string> keys;
  if (scene && !scene->otherLights.empty()) return keys;
  for (const ParamDecl& decl : params.decls())
    if (decl.key.rfind("lights.", 0) == 0) keys.insert(decl.key);
  return keys;
}

bool drawParamPanel(ParamSet& params, std::string& error, ParamLinks* links, const std::set<std::string>& hidden) {
  bool changed = false;
  // Widgets take a bit over half the width; the rest shows the key, which is also the --set name.
  ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  for (const ParamDecl& decl : params.decls()) {
    if (hidden.count(decl.key)) continue;
    ImGui::PushID(decl.key.c_str());
    if (links && links->linked) linkToggle(decl.key, *links);
    double newValue = 0.0;
    const bool edited = drawWidget(decl, params, newValue);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltipText(decl).c_str());
    if (edited) {
      try {
        params.set(decl.key, newValue);
        error.clear();
        changed = true;
        if (links) links->changed.push_back(decl.key);
      } catch (const ParamError& e) {
        error = e.what();
      }
    }
    ImGui::PopID();
  }
  ImGui::PopItemWidth();
  return changed;
}

}  // namespace sl
