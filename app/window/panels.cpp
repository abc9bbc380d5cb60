#include "window/panels.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/one_line.h"
#include "window/ui.h"

namespace rm {
namespace {

constexpr float kMargin = 10.0f;
constexpr float kPanelWidth = 330.0f;
const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};
const ImVec4 kWarningColour{1.0f, 0.8f, 0.35f, 1.0f};
constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                    ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;

std::optional<double> number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

// At most kShownBytes of `text`, cut between two letters. Dear ImGui draws
// a text's letters into one list of 16-bit indices, which a text of about
// 16,000 letters overflows (an assertion: a 30 KB `#error` closed the
// window); stderr has the whole text.
constexpr size_t kShownBytes = 2000;
std::string shown(const std::string& text) { return brief(text, kShownBytes); }

std::string knob_text(const Knob& knob, float value) {
  char buf[32];
  if (knob.integer) std::snprintf(buf, sizeof buf, "%d", static_cast<int>(std::lround(value)));
  else std::snprintf(buf, sizeof buf, "%g", value);
  std::string text = buf;
  // A float knob stays a float literal in GLSL ("2" would make an int).
  if (!knob.integer && text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

// The diagnostics of a failed save over the bottom of the kept picture, and
// the warnings of the latest load below them, smaller and dismissible.
void error_overlay(Ui& ui, const UiModel& model, UiChanges* changes) {
  if (model.errors.empty() && model.warnings.empty()) return;
  const ImVec2 screen = ImGui::GetIO().DisplaySize;
  const float width = std::max(1.0f, screen.x - 2 * kMargin);
  ImGui::SetNextWindowPos(ImVec2(kMargin, screen.y - kMargin), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, std::max(40.0f, screen.y * 0.45f)));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::Begin("##diagnostics", nullptr,
               kFixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_AlwaysAutoResize);
  ui.note_window_rect();
  ImGui::PushTextWrapPos(0.0f);
  if (!model.errors.empty()) {
    ImGui::TextColored(kErrorColour, "%zu %s; %s", model.errors.size(), model.errors.size() == 1 ? "error" : "errors",
                       model.has_picture ? "showing the last good picture" : "nothing to show yet");
    for (const Diagnostic& d : model.errors) ImGui::TextColored(kErrorColour, "%s", shown(d.str()).c_str());
  }
  if (!model.warnings.empty()) {
    ImGui::PushFont(ui.small_font());
    if (ImGui::SmallButton("dismiss")) changes->dismiss_warnings = true;
    ImGui::SameLine();
    ImGui::TextColored(kWarningColour, "%zu %s", model.warnings.size(),
                       model.warnings.size() == 1 ? "warning" : "warnings");
    for (const Diagnostic& d : model.warnings) ImGui::TextColored(kWarningColour, "%s", shown(d.str()).c_str());
    ImGui::PopFont();
  }
  ImGui::PopTextWrapPos();
  ImGui::End();
}

void hud(const UiModel& model) {
  if (!model.hud) return;
  ImGui::SetNextWindowPos(ImVec2(kMargin, kMargin), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(340.0f, 0.0f), ImVec2(FLT_MAX, FLT_MAX));  // numbers change width
  ImGui::SetNextWindowBgAlpha(0.6f);
  // NoInputs: the HUD never takes a press from iMouse.
  ImGui::Begin("##hud", nullptr,
               kFixed | ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
  for (const std::string& line : hud_lines(model.figures)) ImGui::TextUnformatted(line.c_str());
  ImGui::End();
}

void time_controls(const UiModel& model, UiChanges* changes) {
  if (!ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ImGui::Button(model.paused ? "Play" : "Pause")) changes->toggle_pause = true;
  ImGui::SameLine();
  if (ImGui::Button("Restart")) changes->restart = true;
  ImGui::SameLine();
  if (ImGui::ArrowButton("##back", ImGuiDir_Left)) changes->step = -1;
  ImGui::SameLine();
  if (ImGui::ArrowButton("##forward", ImGuiDir_Right)) changes->step = 1;
  // The scrub range grows in steps of 10 s as time runs on.
  const float end = static_cast<float>(std::max(10.0, std::ceil((model.time + 1.0) / 10.0) * 10.0));
  float t = static_cast<float>(model.time);
  if (ImGui::SliderFloat("iTime", &t, 0.0f, end, "%.2f s")) changes->seek = t;
  float speed = static_cast<float>(model.speed);
  if (ImGui::SliderFloat("speed", &speed, static_cast<float>(ShaderClock::kMinSpeed),
                         static_cast<float>(ShaderClock::kMaxSpeed), "%.2fx", ImGuiSliderFlags_Logarithmic))
    changes->speed = speed;
}

// Dear ImGui's sliders assert (an abort) past half of a float's or an int's
// range: "// ui: max=3e38" closed the window. Their bounds stop there.
float slider_bound(float v) { return std::clamp(v, -FLT_MAX / 2, FLT_MAX / 2); }
int int_slider_bound(float v) { return static_cast<int>(std::clamp(double(v), double(INT_MIN / 2), double(INT_MAX / 2))); }

bool uniform_control(const UserUniform& u, UniformValue& v) {
  float f[4] = {0, 0, 0, 0};
  std::copy_n(v.value.begin(), std::min<size_t>(4, v.value.size()), f);
  const char* name = u.name.c_str();
  const float min = slider_bound(u.min), max = slider_bound(u.max);
  const float speed = u.step > 0 ? u.step : (max - min) / 200.0f;
  bool changed = false;
  switch (u.type) {
    case UserUniform::Type::Float:
      changed = ImGui::SliderFloat(name, f, min, max, "%.3f");
      if (changed && u.step > 0) f[0] = min + std::round((f[0] - min) / u.step) * u.step;
      break;
    case UserUniform::Type::Int: {
      int i = static_cast<int>(std::clamp(std::round(double(f[0])), double(INT_MIN), double(INT_MAX)));
      changed = ImGui::SliderInt(name, &i, int_slider_bound(u.min), int_slider_bound(u.max));
      f[0] = static_cast<float>(i);
      break;
    }
    case UserUniform::Type::Bool: {
      bool b = f[0] != 0.0f;
      changed = ImGui::Checkbox(name, &b);
      f[0] = b ? 1.0f : 0.0f;
      break;
    }
    case UserUniform::Type::Vec2: changed = ImGui::DragFloat2(name, f, speed, min, max); break;
    case UserUniform::Type::Vec3:
      changed = u.color ? ImGui::ColorEdit3(name, f) : ImGui::DragFloat3(name, f, speed, min, max);
      break;
    case UserUniform::Type::Vec4:
      changed = u.color ? ImGui::ColorEdit4(name, f) : ImGui::DragFloat4(name, f, speed, min, max);
      break;
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s:%d", u.path.c_str(), u.line);
  if (!changed) return false;
  v.value.assign(f, f + u.components);
  v.text = uniform_value_text(u.type, v.value);
  return true;
}

void uniform_controls(UiModel& model, UiChanges* changes) {
  if (model.uniforms.uniforms.empty() || !model.values) return;
  if (!ImGui::CollapsingHeader("Uniforms", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (const UserUniform& u : model.uniforms.uniforms) {
    auto v = std::find_if(model.values->begin(), model.values->end(),
                          [&](const UniformValue& value) { return value.name == u.name; });
    if (v != model.values->end() && uniform_control(u, *v)) changes->uniforms = true;
  }
}

// shaderlib's knobs: each change is a new -D, made when the slider is let go
// (a compile), or while it is dragged where the change is a tweak (a float
// knob once its -D's program has its twins); the frame time beside them
// shows what it cost.
void knob_controls(UiModel& model, UiChanges* changes) {
  if (model.knobs.empty()) return;
  if (!ImGui::CollapsingHeader("Accuracy knobs", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::Text("frame: CPU %.2f ms, GPU %.2f ms", model.figures.cpu_ms, model.figures.gpu_ms);
  const auto& presets = quality_presets();
  int chosen = 0;
  std::vector<const char*> items = {"scene's own"};
  for (size_t i = 0; i < presets.size(); ++i) {
    items.push_back(presets[i]);
    if (model.preset == presets[i]) chosen = static_cast<int>(i + 1);
  }
  if (ImGui::Combo("preset", &chosen, items.data(), static_cast<int>(items.size())))
    changes->preset = chosen == 0 ? "" : presets[static_cast<size_t>(chosen - 1)];
  for (KnobControl& k : model.knobs) {
    const Knob& knob = *k.value.knob;
    ImGui::PushID(knob.name);
    if (!number(k.value.value)) {
      ImGui::Text("%s = %s", knob.name, shown(k.value.value).c_str());
    } else {
      const ImGuiSliderFlags flags = knob.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
      if (knob.integer) {
        int i = static_cast<int>(std::lround(k.edit));
        ImGui::SliderInt(knob.name, &i, static_cast<int>(knob.min), static_cast<int>(knob.max), "%d", flags);
        k.edit = knob_snapped(knob, static_cast<float>(i));  // RM_NORMAL_TAPS: 4 or 6, never 5
      } else {
        ImGui::SliderFloat(knob.name, &k.edit, knob.min, knob.max, "%g", flags);
      }
      k.held = ImGui::IsItemActive();
      if (k.live ? ImGui::IsItemEdited() : ImGui::IsItemDeactivatedAfterEdit())
        changes->knob = {{knob.name, knob_text(knob, k.edit)}};
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", knob.what);
    if (k.overridden) {
      ImGui::SameLine();
      if (ImGui::SmallButton("reset")) changes->knob = {{knob.name, ""}};
    }
    ImGui::PopID();
  }
}

void controls(Ui& ui, UiModel& model, UiChanges* changes) {
  const ImVec2 screen = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(screen.x - kMargin, kMargin), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  const float width = std::clamp(screen.x - 2 * kMargin, 100.0f, kPanelWidth);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, std::max(60.0f, screen.y - 2 * kMargin)));
  if (model.open_controls) ImGui::SetNextWindowCollapsed(!*model.open_controls, ImGuiCond_Always);
  else ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);  // a title bar until opened
  model.open_controls.reset();
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("Controls", nullptr, kFixed | ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushItemWidth(-150.0f);
    time_controls(model, changes);
    uniform_controls(model, changes);
    knob_controls(model, changes);
    ImGui::PopItemWidth();
  }
  ui.note_window_rect();
  ImGui::End();
}

std::string formatted(const char* format, auto... values) {
  char line[256];
  std::snprintf(line, sizeof line, format, values...);
  return line;
}

}  // namespace

std::vector<std::string> hud_lines(const HudFigures& f) {
  std::vector<std::string> lines{
      formatted("CPU %.2f ms   GPU %.2f ms   %.1f fps", f.cpu_ms, f.gpu_ms, f.fps),
      formatted("%d x %d   iTime %.2f   iFrame %d   %s", f.resolution.x, f.resolution.y, f.time, f.frame,
                !f.animated ? "static" : f.paused ? "paused" : "running"),
      formatted("scale %.2f   %d %s   %d %s", f.scale, f.tiles, f.tiles == 1 ? "tile" : "tiles", f.samples,
                f.samples == 1 ? "sample" : "samples")};
  if (f.passes.size() > 1)
    for (const HudFigures::Pass& p : f.passes) {
      std::string name = p.name;  // whole: a name may be longer than a line of snprintf's
      if (name.size() < 20) name.resize(20, ' ');
      lines.push_back("  " + name + formatted(" %11s %6.2f ms", formatted("%dx%d", p.size.x, p.size.y).c_str(), p.gpu_ms));
    }
  return lines;
}

void want_letters(Ui& ui, const UiModel& model) {
  for (const Diagnostics* list : {&model.errors, &model.warnings})
    for (const Diagnostic& d : *list) ui.want_letters(d.str());
  for (const HudFigures::Pass& pass : model.figures.passes) ui.want_letters(pass.name);
}

UiChanges draw_panels(Ui& ui, UiModel& model) {
  UiChanges changes;
  hud(model);
  controls(ui, model, &changes);
  error_overlay(ui, model, &changes);
  return changes;
}

}  // namespace rm
